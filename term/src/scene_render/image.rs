//! A scene rendered to pixels in memory, for `rastty render SCENE.toml` and tests.

use std::time::Duration;

use super::{FrameReport, PlanOptions, PreparedScene, ScenePlan, SceneRenderError, SceneRenderer};
use crate::headless::{SampledFrame, render_supersampled};
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
    let frame = render_supersampled(
        (width, height),
        supersample,
        scene.data().background,
        SceneRenderError::Target,
        |target| {
            let plan = ScenePlan::new(scene, camera, (target.width(), target.height()), options)?;
            let report = SceneRenderer::new().render(scene, &plan, target)?;
            Ok((plan, report))
        },
    )?;
    let SampledFrame { pixels, value: (plan, report), render_time } = frame;
    Ok(SceneImage { width, height, pixels, plan, report, render_time })
}
