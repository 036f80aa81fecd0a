//! The turntable the terminal reports measure: the built-in model turned once around in equal steps, each frame
//! made as the viewer makes it (a [`ScenePlan`] for the terminal's physical aspect and a kept [`SceneRenderer`]
//! into a pixel buffer, then cells or an image).

use std::time::{Duration, Instant};

use rastty_core::target::{Rgb888, Target};

use rastty::graphics::{FrameImage, GraphicsProtocol, Passthrough};
use rastty::graphics::{MAX_IMAGE_PIXELS, image_size};
use rastty::screen::{CellGrid, CellMode, ColorMode, PixelFrame};
use rastty_scene::scene_file::open;
use rastty_scene::scene_render::{Orbit, PlanOptions, PreparedScene, ScenePlan, SceneRenderer};

use super::error::ReportError;

/// Cell height over cell width (the viewer's default).
pub const CELL_ASPECT: f32 = 2.0;

/// The mean of `values` (0 for none).
pub(crate) fn mean(values: &[usize]) -> f64 {
    if values.is_empty() { 0.0 } else { values.iter().sum::<usize>() as f64 / values.len() as f64 }
}

/// One turntable frame: its cells, and what making them took.
pub(crate) struct TurntableFrame {
    /// The cells.
    pub grid: CellGrid,
    /// The [`ScenePlan`] and [`SceneRenderer::render`], clearing included.
    pub render: Duration,
    /// Pixels to cells ([`CellMode::to_cells`]; zero for an image frame).
    pub cells: Duration,
    /// The picture as an image, when the turntable sends images.
    pub image: Option<FrameImage>,
}

/// The turntable frames of one terminal size, cell mode and colour mode, as the viewer would make them.
pub(crate) struct Turntable<'a> {
    scene: &'a PreparedScene,
    orbit: Orbit,
    options: PlanOptions,
    /// Kept from frame to frame, as the viewer keeps its renderer.
    renderer: SceneRenderer,
    /// Radians turned between two frames.
    step: f32,
    cell_mode: CellMode,
    colors: ColorMode,
    /// Cells, or the protocol of the images it makes.
    graphics: GraphicsProtocol,
    /// The terminal's size in cells.
    size: (u16, u16),
    width: usize,
    height: usize,
    aspect: f32,
    pixels: Vec<u32>,
    depth: Vec<f32>,
}

impl<'a> Turntable<'a> {
    /// `frames` frames per turn at `cols` x `rows` cells.
    pub(super) fn new(
        scene: &'a PreparedScene,
        size: (u16, u16),
        cell_mode: CellMode,
        colors: ColorMode,
        frames: usize,
    ) -> Self {
        Self::with_step(scene, size, cell_mode, colors, std::f32::consts::TAU / frames.max(1) as f32)
    }

    /// Frames `step` radians apart at `cols` x `rows` cells.
    pub(super) fn with_step(
        scene: &'a PreparedScene,
        (cols, rows): (u16, u16),
        cell_mode: CellMode,
        colors: ColorMode,
        step: f32,
    ) -> Self {
        let (width, height) = cell_mode.pixel_size(usize::from(cols), usize::from(rows));
        Self {
            scene,
            orbit: Orbit::new(scene.camera()),
            options: PlanOptions::default(),
            renderer: SceneRenderer::new(),
            step,
            cell_mode,
            colors,
            graphics: GraphicsProtocol::Cells,
            size: (cols, rows),
            width,
            height,
            // As in the viewer: the physical aspect, a cell being CELL_ASPECT times taller than wide.
            aspect: f32::from(cols) / (f32::from(rows) * CELL_ASPECT),
            pixels: vec![0; width * height],
            depth: vec![0.0; width * height],
        }
    }

    /// `frames` frames per turn at `cols` x `rows` cells as images in `protocol`, sized as the viewer sizes them
    /// for a terminal that does not give its size in pixels ([`image_size`]).
    pub(super) fn images(
        scene: &'a PreparedScene,
        size: (u16, u16),
        protocol: GraphicsProtocol,
        frames: usize,
    ) -> Self {
        let (width, height) = image_size(protocol, size, None, CELL_ASPECT, MAX_IMAGE_PIXELS);
        let mut turntable = Self::new(scene, size, CellMode::HalfBlock, ColorMode::TrueColor, frames);
        turntable.graphics = protocol;
        (turntable.width, turntable.height, turntable.aspect) = (width, height, width as f32 / height as f32);
        (turntable.pixels, turntable.depth) = (vec![0; width * height], vec![0.0; width * height]);
        turntable
    }

    /// The pixel size of the frames.
    pub(super) fn pixel_size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// Renders the current view into cells, then turns the camera one step.
    pub(super) fn next_frame(&mut self) -> Result<TurntableFrame, ReportError> {
        let too_big = |e: rastty_core::target::TargetError| ReportError::Setup(e.to_string());
        let mut target =
            Target::new(Rgb888(&mut self.pixels), &mut self.depth[..], self.width as u32, self.height as u32)
                .map_err(too_big)?;
        let size = (self.width as u32, self.height as u32);
        let start = Instant::now();
        let plan = ScenePlan::with_aspect(self.scene, &self.orbit.camera, size, self.aspect, &self.options)
            .map_err(ReportError::Render)?;
        self.renderer.render(self.scene, &plan, &mut target).map_err(ReportError::Render)?;
        let render = start.elapsed();
        self.orbit.rotate(self.step, 0.0);
        if self.graphics != GraphicsProtocol::Cells {
            let (columns, rows) = self.size;
            let image = FrameImage {
                pixels: self.pixels.clone(),
                width: self.width,
                height: self.height,
                columns,
                rows: self.graphics.image_rows(rows),
                passthrough: Passthrough::Direct,
            };
            return Ok(TurntableFrame { grid: CellGrid::default(), render, cells: Duration::ZERO, image: Some(image) });
        }
        let background = rastty_core::color::pack_rgb888(plan.background);
        let frame = PixelFrame::new(&self.pixels, self.width, self.height);
        let start = Instant::now();
        let grid = self.cell_mode.to_cells(frame, self.colors, background);
        let cells = start.elapsed();
        Ok(TurntableFrame { grid, render, cells, image: None })
    }
}

/// The built-in model as the viewer shows it without a scene file ([`open`]`(None)`).
///
/// # Errors
/// [`ReportError::Load`], [`ReportError::Render`] (a model without a finite vertex).
pub fn builtin_scene() -> Result<PreparedScene, ReportError> {
    let opened = open(None, &rastty_scene::model::ModelOptions::default()).map_err(ReportError::Load)?;
    PreparedScene::new(opened.data).map_err(ReportError::Render)
}
