//! `rastty render`: a model to a PNG file, without a terminal.

use std::fmt;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use rastty_core::math::Vec3;
use rastty_core::pipeline::DrawStats;
use rastty_core::target::{MAX_DIMENSION, Rgb888, Target, downsample_rgb888};

use crate::builtin::{BUILTIN_NAME, builtin_model};
use crate::model::{LoadError, TextureImage, load_obj};
use crate::png_file::{PngError, write_png};
use crate::scene::{Appearance, OrbitCamera, RenderError, Scene};

/// Which model to load.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ModelSource {
    /// The model compiled into the binary.
    BuiltIn,
    /// An OBJ file.
    File(PathBuf),
}

/// Where textures come from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TextureChoice {
    /// The model's own materials.
    FromModel,
    /// This image, for every part of the model (useful for OBJ files without a material library).
    File(PathBuf),
}

/// A loaded scene and the warnings met while loading it.
#[derive(Debug)]
pub struct LoadedScene {
    /// The scene.
    pub scene: Scene,
    /// A name for the model in messages (raw: sanitise before showing it in a terminal).
    pub name: String,
    /// Non-fatal problems, one line each.
    pub warnings: Vec<String>,
}

/// Loads the model and applies the texture choice. A texture that cannot be loaded is a warning, and the model
/// is drawn untextured.
///
/// # Errors
/// [`LoadError`] when the model itself cannot be loaded.
pub fn load_scene(source: &ModelSource, texture: &TextureChoice) -> Result<LoadedScene, LoadError> {
    let (mut model, name) = match source {
        ModelSource::BuiltIn => (builtin_model()?, BUILTIN_NAME.to_string()),
        ModelSource::File(path) => (load_obj(path)?, path.display().to_string()),
    };
    let mut warnings = std::mem::take(&mut model.warnings);
    match texture {
        TextureChoice::FromModel => {}
        TextureChoice::File(path) => match TextureImage::load(path) {
            Ok(image) if model.uvs.is_some() => model.set_texture(image),
            Ok(_) => warnings.push(format!("{name} has no texture coordinates; the texture is not used")),
            Err(e) => {
                warnings.push(format!("{}; rendering untextured", e.to_string().trim_end_matches('.')));
                model.materials.iter_mut().for_each(|m| m.texture = None);
            }
        },
    }
    Ok(LoadedScene { scene: Scene::new(model), name, warnings })
}

/// Parses an image size written `WIDTHxHEIGHT`, each side from 1 to [`MAX_DIMENSION`].
///
/// # Errors
/// A message naming the text and the limits.
pub fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("{text:?} is not a size WIDTHxHEIGHT with sides from 1 to {MAX_DIMENSION}");
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h) = (w.trim().parse::<u32>().map_err(|_| bad())?, h.trim().parse::<u32>().map_err(|_| bad())?);
    if !(1..=MAX_DIMENSION).contains(&w) || !(1..=MAX_DIMENSION).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

/// An image rendered in memory.
#[derive(Debug, Clone)]
pub struct RenderedImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `0x00RRGGBB` pixels, top row first.
    pub pixels: Vec<u32>,
    /// What the core did.
    pub stats: DrawStats,
    /// Time spent drawing and resolving supersamples (not clearing, not writing the file).
    pub render_time: Duration,
}

/// Renders a scene to pixels with square pixels, anti-aliased with `supersample x supersample` samples per pixel
/// when `supersample > 1` (rendered that much larger and averaged with
/// [`rastty_core::target::downsample_rgb888`]).
///
/// # Errors
/// [`HeadlessError::Render`] for a degenerate camera; [`HeadlessError::Size`] when the (supersampled) size is
/// outside `1..=MAX_DIMENSION`.
pub fn render_image(
    scene: &Scene,
    (width, height): (u32, u32),
    supersample: u32,
    camera: &OrbitCamera,
    appearance: &Appearance,
) -> Result<RenderedImage, HeadlessError> {
    let frame =
        render_supersampled((width, height), supersample, appearance.background, HeadlessError::Size, |target| {
            Ok(scene.draw(target, camera, appearance, width as f32 / height as f32)?)
        })?;
    let SampledFrame { pixels, value: stats, render_time } = frame;
    Ok(RenderedImage { width, height, pixels, stats, render_time })
}

/// A frame drawn at `k x k` times its size and averaged, with what the drawing returned.
#[derive(Clone, Debug)]
pub struct SampledFrame<T> {
    /// `0x00RRGGBB` pixels of the final size, top row first.
    pub pixels: Vec<u32>,
    /// What `draw` returned.
    pub value: T,
    /// Time spent drawing and averaging (not allocating or clearing the buffers).
    pub render_time: Duration,
}

/// Allocates a `width x height` frame `supersample` times larger on each side, clears it to `background` (before
/// the clock starts, which also maps the fresh pages, so the time measured is rendering), runs `draw` on it, and
/// averages it down with [`downsample_rgb888`] when `supersample > 1`.
///
/// # Errors
/// `size_error` with a message naming the sizes when the supersampled frame is outside `1..=MAX_DIMENSION`;
/// whatever `draw` returns.
pub fn render_supersampled<T, E>(
    (width, height): (u32, u32),
    supersample: u32,
    background: Vec3,
    size_error: impl Fn(String) -> E,
    draw: impl FnOnce(&mut Target<Rgb888<'_>, &mut [f32]>) -> Result<T, E>,
) -> Result<SampledFrame<T>, E> {
    let k = supersample.max(1);
    let too_large = || {
        size_error(format!(
            "{width}x{height} with {k}x{k} samples per pixel is more than {MAX_DIMENSION} pixels a side"
        ))
    };
    let sw = width.checked_mul(k).filter(|&s| s <= MAX_DIMENSION).ok_or_else(too_large)?;
    let sh = height.checked_mul(k).filter(|&s| s <= MAX_DIMENSION).ok_or_else(too_large)?;
    let n = sw as usize * sh as usize;
    let mut samples = vec![0u32; n];
    let mut depth = vec![0f32; n];
    let mut target =
        Target::new(Rgb888(&mut samples), &mut depth[..], sw, sh).map_err(|e| size_error(e.to_string()))?;
    target.clear(background);
    let start = Instant::now();
    let value = draw(&mut target)?;
    let pixels = if k > 1 {
        let mut pixels = vec![0u32; width as usize * height as usize];
        downsample_rgb888(&samples, sw, k, &mut pixels).map_err(|e| size_error(e.to_string()))?;
        pixels
    } else {
        samples
    };
    Ok(SampledFrame { pixels, value, render_time: start.elapsed() })
}

/// What `rastty render` needs.
#[derive(Clone, Debug)]
pub struct RenderRequest {
    /// The model.
    pub model: ModelSource,
    /// The textures.
    pub texture: TextureChoice,
    /// Image size in pixels.
    pub size: (u32, u32),
    /// Samples per pixel along each axis (1: no anti-aliasing).
    pub supersample: u32,
    /// The camera.
    pub camera: OrbitCamera,
    /// The look.
    pub appearance: Appearance,
    /// The PNG file to write.
    pub output: PathBuf,
}

/// What `rastty render` did.
#[derive(Debug)]
pub struct RenderReport {
    /// The model's name.
    pub name: String,
    /// Loading warnings.
    pub warnings: Vec<String>,
    /// The image (already written).
    pub image: RenderedImage,
    /// What the draws compiled to.
    pub variants: Vec<String>,
}

/// Why `rastty render` failed.
#[derive(Debug)]
pub enum HeadlessError {
    /// The model could not be loaded.
    Load(LoadError),
    /// The frame could not be drawn.
    Render(RenderError),
    /// The image size is not usable.
    Size(String),
    /// The PNG could not be written.
    Write(PngError),
}

impl fmt::Display for HeadlessError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Load(e) => e.fmt(f),
            Self::Render(e) => e.fmt(f),
            Self::Size(e) => write!(f, "bad image size: {e}"),
            Self::Write(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for HeadlessError {}

impl From<RenderError> for HeadlessError {
    fn from(e: RenderError) -> Self {
        Self::Render(e)
    }
}

/// Loads, renders and writes the PNG.
///
/// # Errors
/// [`HeadlessError`]; the output file is then not created (or left as it was).
pub fn render_to_png(request: &RenderRequest) -> Result<RenderReport, HeadlessError> {
    let loaded = load_scene(&request.model, &request.texture).map_err(HeadlessError::Load)?;
    let aspect = request.size.0 as f32 / request.size.1 as f32;
    let variants = loaded.scene.explain(&request.camera, &request.appearance, aspect)?;
    let image = render_image(&loaded.scene, request.size, request.supersample, &request.camera, &request.appearance)?;
    write_png(&request.output, image.width, image.height, &image.pixels).map_err(HeadlessError::Write)?;
    Ok(RenderReport { name: loaded.name, warnings: loaded.warnings, image, variants })
}
