//! A scene rendered to pixels in memory, anti-aliased by supersampling, for `rastty render` and tests.

use std::time::{Duration, Instant};

use rastty_core::color::ShadingSpace;
use rastty_core::math::Vec3;
use rastty_core::target::{MAX_DIMENSION, Rgb888, Target, downsample_rgb888};

use super::{FrameReport, PlanOptions, PreparedScene, ScenePlan, SceneRenderError, SceneRenderer};
use crate::scene_file::SceneCamera;

/// A frame of a scene.
#[derive(Clone, Debug)]
pub struct SceneImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `0x00RRGGBB` pixels, top row first.
    pub pixels: Vec<u32>,
    /// What the frame ran, for the rendered size.
    pub plan: ScenePlan,
    /// What each pass did.
    pub report: FrameReport,
    /// Time spent planning, drawing and resolving supersamples (not allocating the buffers).
    pub render_time: Duration,
}

/// Renders `scene` seen by `camera` at `width x height`, anti-aliased with `supersample x supersample` samples per
/// pixel when `supersample > 1` (planned and drawn that much larger, shadow map size included, then averaged).
///
/// # Errors
/// [`SceneRenderError::Target`] when the (supersampled) size is outside `1..=MAX_DIMENSION`, and what
/// [`ScenePlan::new`] and [`SceneRenderer::render`] report.
pub fn render_scene_image(
    scene: &PreparedScene,
    camera: &SceneCamera,
    size: (u32, u32),
    supersample: u32,
    options: &PlanOptions,
) -> Result<SceneImage, SceneRenderError> {
    render_scene_image_with(&mut SceneRenderer::new(), scene, camera, size, supersample, options)
}

/// [`render_scene_image`] drawn by `renderer`, which keeps its threads and its shadow maps from one image to the
/// next: a series of images of one scene (a turntable) starts no thread after the first and draws a shadow map
/// again only when its light's view changed. The pixels are those of [`render_scene_image`].
///
/// # Errors
/// Those of [`render_scene_image`].
pub fn render_scene_image_with(
    renderer: &mut SceneRenderer,
    scene: &PreparedScene,
    camera: &SceneCamera,
    (width, height): (u32, u32),
    supersample: u32,
    options: &PlanOptions,
) -> Result<SceneImage, SceneRenderError> {
    let frame = render_supersampled(
        (width, height),
        supersample,
        scene.data().background,
        scene.data().space,
        SceneRenderError::Target,
        |target| {
            let plan = ScenePlan::new(scene, camera, (target.width(), target.height()), options)?;
            let report = renderer.render(scene, &plan, target)?;
            Ok((plan, report))
        },
    )?;
    let SampledFrame { pixels, value: (plan, report), render_time } = frame;
    Ok(SceneImage { width, height, pixels, plan, report, render_time })
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

/// A frame drawn at `k x k` times its size and averaged, with what the drawing returned.
#[derive(Clone, Debug)]
pub(crate) struct SampledFrame<T> {
    /// `0x00RRGGBB` pixels of the final size, top row first.
    pub pixels: Vec<u32>,
    /// What `draw` returned.
    pub value: T,
    /// Time spent drawing and averaging (not allocating or clearing the buffers).
    pub render_time: Duration,
}

/// Allocates a `width x height` frame `supersample` times larger on each side, clears it to `background` (before
/// the clock starts, which also maps the fresh pages, so the time measured is rendering), runs `draw` on it, and
/// averages it down in `space` with [`downsample_rgb888`] when `supersample > 1`.
///
/// # Errors
/// `size_error` with a message naming the sizes when the supersampled frame is outside `1..=MAX_DIMENSION`;
/// whatever `draw` returns.
pub(crate) fn render_supersampled<T, E>(
    (width, height): (u32, u32),
    supersample: u32,
    background: Vec3,
    space: ShadingSpace,
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
        downsample_rgb888(&samples, sw, k, space, &mut pixels).map_err(|e| size_error(e.to_string()))?;
        pixels
    } else {
        samples
    };
    Ok(SampledFrame { pixels, value, render_time: start.elapsed() })
}
