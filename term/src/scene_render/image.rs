//! A scene rendered to pixels in memory, for `rasterm render SCENE.toml` and tests.

use std::time::{Duration, Instant};

use rasterm_core::target::{MAX_DIMENSION, Rgb888, Target, downsample_rgb888};

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
    (width, height): (u32, u32),
    supersample: u32,
    options: &PlanOptions,
) -> Result<SceneImage, SceneRenderError> {
    let k = supersample.max(1);
    let too_large = || {
        SceneRenderError::Target(format!(
            "{width}x{height} with {k}x{k} samples per pixel is more than {MAX_DIMENSION} pixels a side"
        ))
    };
    let sw = width.checked_mul(k).filter(|&s| s <= MAX_DIMENSION).ok_or_else(too_large)?;
    let sh = height.checked_mul(k).filter(|&s| s <= MAX_DIMENSION).ok_or_else(too_large)?;
    let n = sw as usize * sh as usize;
    let mut samples = vec![0u32; n];
    let mut depth = vec![0f32; n];
    let mut target = Target::new(Rgb888(&mut samples), &mut depth[..], sw, sh)?;
    // Touch the buffers before the clock starts, so the time measured is rendering, not page faults.
    target.clear(scene.data().background);
    let start = Instant::now();
    let plan = ScenePlan::new(scene, camera, (sw, sh), options)?;
    let report = SceneRenderer::new().render(scene, &plan, &mut target)?;
    let pixels = if k > 1 {
        let mut pixels = vec![0u32; width as usize * height as usize];
        downsample_rgb888(&samples, sw, k, &mut pixels).map_err(|e| SceneRenderError::Target(e.to_string()))?;
        pixels
    } else {
        samples
    };
    let render_time = start.elapsed();
    Ok(SceneImage { width, height, pixels, plan, report, render_time })
}
