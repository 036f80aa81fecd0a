//! `rastty-bench effects`: what each effect of a scene file costs per frame.
//!
//! One scene ([`DEFAULT_SCENE`] unless another is given), its own camera, rendered by a [`SceneRenderer`] at each
//! size of [`EffectsReport::sizes`] in every [`configuration`](configurations): no effect, each effect alone, and
//! every effect. Shadows are measured twice, alone and with the rest:
//!
//! - **map drawn every frame** ([`ShadowMaps::Drawn`]): a fresh [`SceneRenderer`] for every frame, as
//!   `rastty render` makes one per image, so the map's buffer is allocated and the map drawn each time;
//! - **map kept** ([`ShadowMaps::Kept`]): one renderer for all frames, as the viewer keeps one while only the camera
//!   moves: the warm-up frame draws the map and every measured frame reuses it.
//!
//! The report checks that this happened (every measured frame's shadow passes all drawn, or all reused) and fails
//! rather than print figures under the wrong label.
//!
//! Every configuration gets one warm-up frame, then [`EffectsReport::frames`] measured frames. The configurations
//! take turns frame by frame (each round starting one configuration later than the one before), so a noisy moment
//! of the machine falls on all of them alike; every size has one colour and one depth buffer, which all of its
//! frames share. A frame's time is the wall time of [`SceneRenderer::render`]; the passes' times are the
//! [`FrameReport`]'s. Every figure is a median over the measured frames.

use std::fmt::Write as _;
use std::io::Write;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use rastty_core::target::{Rgb888, Target};

use super::error::ReportError;
use super::median;
use rastty_scene::escaped::path_text;
use rastty_scene::scene_render::{
    BAND_PIXELS, BANDS_PER_THREAD, EffectToggles, FrameReport, PlanOptions, PreparedScene, SceneEffect, ScenePlan,
    SceneRenderError, SceneRenderer,
};

/// The scene measured when none is given, relative to the current directory: it uses every effect.
pub const DEFAULT_SCENE: &str = "assets/scenes/spot_lamp.toml";
/// Frame sizes measured, in pixels: a large window, and a large terminal's half-block pixels (200x60 cells).
pub const SIZES: [(u32, u32); 2] = [(800, 800), (200, 120)];
/// Measured frames per configuration and size by default.
pub const DEFAULT_FRAMES: usize = 30;
/// Measured frames per configuration and size with `--quick`.
pub const QUICK_FRAMES: usize = 5;

/// How a configuration with shadows gets its shadow maps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowMaps {
    /// A fresh [`SceneRenderer`] for every frame: the maps are drawn every frame.
    Drawn,
    /// One [`SceneRenderer`] for all frames: the maps drawn in the warm-up frame are reused.
    Kept,
}

/// One row of the report: the effects allowed and how shadow maps are had.
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    /// The row's label.
    pub label: String,
    /// The effects allowed (the scene's own materials and lights decide where they apply).
    pub effects: EffectToggles,
    /// Fresh renderers or one kept renderer (only matters with shadows on).
    pub maps: ShadowMaps,
}

/// The rows of the report, in order: no effect (`none`, the base every other row is compared with), each effect
/// alone (shadows twice: map drawn every frame, map kept), then every effect (map drawn every frame, map kept).
pub fn configurations() -> Vec<Configuration> {
    let none = EffectToggles::all_but(&SceneEffect::ALL);
    let alone = |effect: SceneEffect| {
        let mut effects = none;
        effects.set(effect, true);
        effects
    };
    let row = |label: String, effects, maps| Configuration { label, effects, maps };
    let mut rows = vec![row("none".into(), none, ShadowMaps::Kept)];
    for effect in SceneEffect::ALL {
        if effect == SceneEffect::Shadows {
            rows.push(row(format!("{}, map drawn every frame", effect.name()), alone(effect), ShadowMaps::Drawn));
            rows.push(row(format!("{}, map kept", effect.name()), alone(effect), ShadowMaps::Kept));
        } else {
            rows.push(row(effect.name().into(), alone(effect), ShadowMaps::Kept));
        }
    }
    rows.push(row("all, map drawn every frame".into(), EffectToggles::ALL_ON, ShadowMaps::Drawn));
    rows.push(row("all, map kept".into(), EffectToggles::ALL_ON, ShadowMaps::Kept));
    rows
}

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct EffectsReport {
    /// The scene file (shown in the report; the caller loads it).
    pub scene_path: PathBuf,
    /// True when the scene was named on the command line (only for the command line shown).
    pub scene_given: bool,
    /// Measured frames per configuration and size (at least 1), after one warm-up frame each.
    pub frames: usize,
    /// Threads per frame, or `None` for as many as this machine runs at once.
    pub threads: Option<usize>,
    /// Frame sizes in pixels.
    pub sizes: Vec<(u32, u32)>,
    /// True when `--quick` chose the frame count (only for the command line shown).
    pub quick: bool,
}

impl EffectsReport {
    /// The standard report: `scene` (default [`DEFAULT_SCENE`]) at [`SIZES`], `frames` frames per configuration.
    pub fn new(scene: Option<PathBuf>, frames: usize, threads: Option<usize>) -> Self {
        Self {
            scene_given: scene.is_some(),
            scene_path: scene.unwrap_or_else(|| DEFAULT_SCENE.into()),
            frames,
            threads,
            sizes: SIZES.to_vec(),
            quick: false,
        }
    }

    /// The standard report with [`QUICK_FRAMES`] frames, for CI.
    pub fn quick(scene: Option<PathBuf>, threads: Option<usize>) -> Self {
        Self { quick: true, ..Self::new(scene, QUICK_FRAMES, threads) }
    }

    /// The threads each frame is drawn on: [`Self::threads`], else this machine's logical CPUs (at least 1).
    pub fn thread_count(&self) -> usize {
        super::thread_count(self.threads)
    }

    /// The command that prints this report.
    pub fn command_line(&self) -> String {
        let mut line = "rastty-bench effects".to_owned();
        if self.scene_given {
            line.push(' ');
            line.push_str(&path_text(&self.scene_path));
        }
        if self.quick {
            line.push_str(" --quick");
        } else {
            let _ = write!(line, " --frames {}", self.frames);
        }
        if let Some(threads) = self.threads {
            let _ = write!(line, " --threads {threads}");
        }
        line
    }
}

/// The measured frames of one configuration at one size, one sample per frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConfigurationTimes {
    /// Wall time of [`SceneRenderer::render`].
    pub frame: Vec<Duration>,
    /// [`FrameReport::shadow_time`].
    pub shadow: Vec<Duration>,
    /// [`FrameReport::forward_time`].
    pub forward: Vec<Duration>,
    /// [`FrameReport::occlusion_time`].
    pub occlusion: Vec<Duration>,
    /// Shadow passes in the plan.
    pub shadow_passes: usize,
    /// Whether the plan has the ambient occlusion step.
    pub occlusion_step: bool,
    /// Fragments the forward pass shaded in the last measured frame ([`FrameReport::forward`]).
    pub fragments: u64,
}

impl ConfigurationTimes {
    /// No samples yet, for `plan`.
    pub(super) fn for_plan(plan: &ScenePlan) -> Self {
        Self {
            shadow_passes: plan.shadow_passes.len(),
            occlusion_step: plan.ambient_occlusion.is_some(),
            ..Self::default()
        }
    }

    /// Adds one measured frame.
    pub(super) fn push(&mut self, frame: Duration, report: &FrameReport) {
        self.frame.push(frame);
        self.shadow.push(report.shadow_time);
        self.forward.push(report.forward_time);
        self.occlusion.push(report.occlusion_time);
        self.fragments = report.forward.fragments;
    }
}

/// The plan of `scene`'s frame at `size` with its own camera ([`PreparedScene::camera`]) and `effects` allowed.
pub(super) fn plan(
    scene: &PreparedScene,
    size: (u32, u32),
    effects: EffectToggles,
) -> Result<ScenePlan, SceneRenderError> {
    ScenePlan::new(scene, &scene.camera(), size, &PlanOptions { effects, ..PlanOptions::default() })
}

/// Frames of one scene at one size, drawn into one colour and one depth buffer and timed: what the timing reports
/// run.
pub(super) struct TimedFrames<'s> {
    scene: &'s PreparedScene,
    size: (u32, u32),
    threads: usize,
    pixels: Vec<u32>,
    depth: Vec<f32>,
}

impl<'s> TimedFrames<'s> {
    /// Buffers for `scene`'s frames at `size`, drawn on `threads` threads.
    pub(super) fn new(scene: &'s PreparedScene, size: (u32, u32), threads: usize) -> Self {
        let pixel_count = size.0 as usize * size.1 as usize;
        Self { scene, size, threads, pixels: vec![0; pixel_count], depth: vec![0.0; pixel_count] }
    }

    /// Renders `plan` with `renderer`, which is made afresh first for [`ShadowMaps::Drawn`]; the wall time of
    /// [`SceneRenderer::render`] and its report.
    pub(super) fn render(
        &mut self,
        renderer: &mut SceneRenderer,
        maps: ShadowMaps,
        plan: &ScenePlan,
    ) -> Result<(Duration, FrameReport), ReportError> {
        if maps == ShadowMaps::Drawn {
            *renderer = SceneRenderer::with_threads(self.threads);
        }
        let (width, height) = self.size;
        let mut target = Target::new(Rgb888(&mut self.pixels), &mut self.depth[..], width, height)
            .map_err(SceneRenderError::from)?;
        let start = Instant::now();
        let report = renderer.render(self.scene, plan, &mut target)?;
        Ok((start.elapsed(), report))
    }
}

/// An error unless the measured frame `report` of row `label` drew (for [`ShadowMaps::Drawn`]) or reused (for
/// [`ShadowMaps::Kept`]) every shadow map: the report would otherwise print figures under the wrong label.
pub(super) fn check_maps(label: &str, maps: ShadowMaps, report: &FrameReport) -> Result<(), ReportError> {
    let want_reused = maps == ShadowMaps::Kept;
    match report.shadow_passes.iter().find(|p| p.reused != want_reused) {
        Some(pass) => {
            let did = if pass.reused { "reused" } else { "drew" };
            Err(ReportError::Setup(format!(
                "{label}: the renderer {did} the shadow map of light {} (a bug in the report)",
                pass.light
            )))
        }
        None => Ok(()),
    }
}

/// Everything measured: `samples[configuration][size]`.
#[derive(Clone, Debug, PartialEq)]
pub struct EffectsResults {
    /// The rows, as [`configurations`] gives them.
    pub configurations: Vec<Configuration>,
    /// The frame sizes, in pixels.
    pub sizes: Vec<(u32, u32)>,
    /// The threads each frame was drawn on.
    pub threads: usize,
    /// The samples of each configuration (outer) at each size (inner).
    pub samples: Vec<Vec<ConfigurationTimes>>,
}

impl EffectsResults {
    /// The median frame time of row `configuration` at size `size` (indices).
    pub fn median_frame(&self, configuration: usize, size: usize) -> Duration {
        median(&self.samples[configuration][size].frame)
    }
}

/// Measures every configuration at every size of `report` on `scene`.
///
/// # Errors
/// [`ReportError::Setup`] for zero frames or shadow maps not drawn or reused as the configuration needs;
/// [`ReportError::Render`].
pub fn measure(scene: &PreparedScene, report: &EffectsReport) -> Result<EffectsResults, ReportError> {
    if report.frames == 0 {
        return Err(ReportError::Setup("the report needs at least one frame per configuration".into()));
    }
    let configurations = configurations();
    let threads = report.thread_count();
    let mut samples = vec![Vec::with_capacity(report.sizes.len()); configurations.len()];
    for &size in &report.sizes {
        for (row, measured) in
            measure_size(scene, &configurations, size, threads, report.frames)?.into_iter().enumerate()
        {
            samples[row].push(measured);
        }
    }
    Ok(EffectsResults { configurations, sizes: report.sizes.clone(), threads, samples })
}

/// Every configuration at one size: a warm-up frame each, then `frames` rounds of one frame each.
fn measure_size(
    scene: &PreparedScene,
    configurations: &[Configuration],
    (width, height): (u32, u32),
    threads: usize,
    frames: usize,
) -> Result<Vec<ConfigurationTimes>, ReportError> {
    let plans =
        configurations.iter().map(|c| plan(scene, (width, height), c.effects)).collect::<Result<Vec<_>, _>>()?;
    let mut renderers: Vec<SceneRenderer> =
        configurations.iter().map(|_| SceneRenderer::with_threads(threads)).collect();
    let mut samples: Vec<ConfigurationTimes> = plans.iter().map(ConfigurationTimes::for_plan).collect();
    let mut frames_drawn = TimedFrames::new(scene, (width, height), threads);
    let mut frame = |row: usize, warm_up: bool| -> Result<(), ReportError> {
        let configuration = &configurations[row];
        let (elapsed, report) = frames_drawn.render(&mut renderers[row], configuration.maps, &plans[row])?;
        if !warm_up {
            check_maps(&format!("{} at {width}x{height}", configuration.label), configuration.maps, &report)?;
            samples[row].push(elapsed, &report);
        }
        Ok(())
    };
    let count = configurations.len();
    for row in 0..count {
        frame(row, true)?;
    }
    for round in 0..frames {
        for k in 0..count {
            frame((round + k) % count, false)?;
        }
    }
    Ok(samples)
}

/// The lines above the table: what was measured, where, and how to read it. `plans` are the scene's plans with
/// every effect on, one per size of `report`.
pub fn header(report: &EffectsReport, plans: &[ScenePlan], threads: usize, machine: &str) -> String {
    let build = super::build_description();
    let frames = report.frames;
    let plural = |n: usize, word: &str| if n == 1 { format!("1 {word}") } else { format!("{n} {word}s") };
    let sizes: Vec<String> = report.sizes.iter().map(|(w, h)| format!("{w}x{h}")).collect();
    let maps: Vec<String> = plans
        .iter()
        .map(|plan| {
            let (w, h) = plan.size;
            match plan.shadow_passes.iter().map(|p| p.texels()).collect::<Vec<_>>() {
                maps if maps.is_empty() => format!("no shadow map at {w}x{h}"),
                maps => format!("shadow maps of {} at {w}x{h}", maps.join(", ")),
            }
        })
        .collect();
    let scene = plans.first().map_or_else(String::new, |plan| {
        let occlusion = if plan.ambient_occlusion.is_some() { "ambient occlusion" } else { "no ambient occlusion" };
        format!("{}, {}, {occlusion}; ", plural(plan.draws.len(), "forward draw"), plural(plan.lights.len(), "light"),)
    });
    [
        format!("### What each effect costs: `{}`", path_text(&report.scene_path)),
        String::new(),
        format!("- command: `{}` ({build})", report.command_line()),
        format!("- machine: {machine}"),
        if threads == 1 {
            format!(
                "- threads: 1 (shadow maps drawn whole; frames in one band per {} pixels, 1 to {} bands, drawn one \
                 after another)",
                BAND_PIXELS, BANDS_PER_THREAD
            )
        } else {
            format!(
                "- threads: {threads} (shadow maps drawn in {threads} bands of rows; frames in one band per {} \
                 pixels, {threads} to {} bands, taken in turn by the threads, the most triangles first)",
                BAND_PIXELS,
                threads * BANDS_PER_THREAD
            )
        },
        format!("- scene, every effect on: the file's camera; {scene}{}", maps.join(", ")),
        format!(
            "- frames: at {}, each configuration renders 1 warm-up frame, then {frames} measured frames, the \
             configurations taking turns frame by frame, into the same buffers; every figure is the median of the \
             {frames}",
            sizes.join(" and ")
        ),
        "- ms: wall time of `SceneRenderer::render`; +ms and ratio: against `none` (medians); shadow, forward, \
         occlusion: the passes' times from its `FrameReport`, in ms (– where the plan has no such pass)"
            .to_owned(),
        "- map drawn every frame: a fresh `SceneRenderer` for every frame (as `rastty render` makes one per image), \
         so the map's buffer is allocated and the map drawn every frame; map kept: one renderer for every frame (as \
         the viewer while only the camera moves), the map drawn in the warm-up frame and reused by every measured \
         frame (the first of them works out its filter windows' depth ranges, once)"
            .to_owned(),
    ]
    .join("\n")
}

/// The table: one row per configuration, and for each size its frame time, its cost over `none` and its passes.
pub fn table(results: &EffectsResults) -> String {
    let mut head = "| configuration |".to_owned();
    let mut rule = "|---|".to_owned();
    for (w, h) in &results.sizes {
        let _ = write!(head, " {w}x{h} ms | +ms | ratio | shadow | forward | occlusion |");
        rule.push_str("---:|---:|---:|---:|---:|---:|");
    }
    let mut lines = vec![head, rule];
    let ms = |d: Duration| format!("{:.2}", d.as_secs_f64() * 1e3);
    for (row, configuration) in results.configurations.iter().enumerate() {
        let mut line = format!("| {} |", configuration.label);
        for size in 0..results.sizes.len() {
            let s = &results.samples[row][size];
            let time = results.median_frame(row, size);
            let base = results.median_frame(0, size);
            let (over, ratio) = if row == 0 {
                ("–".to_owned(), "–".to_owned())
            } else {
                let over = (time.as_secs_f64() - base.as_secs_f64()) * 1e3;
                let ratio = if base.is_zero() {
                    "–".to_owned()
                } else {
                    format!("{:.2}x", time.as_secs_f64() / base.as_secs_f64())
                };
                (format!("{over:+.2}"), ratio)
            };
            let pass = |present: bool, values: &[Duration]| if present { ms(median(values)) } else { "–".to_owned() };
            let _ = write!(
                line,
                " {} | {over} | {ratio} | {} | {} | {} |",
                ms(time),
                pass(s.shadow_passes > 0, &s.shadow),
                ms(median(&s.forward)),
                pass(s.occlusion_step, &s.occlusion),
            );
        }
        lines.push(line);
    }
    lines.join("\n")
}

/// Measures everything `report` asks for on `scene` (loaded from [`EffectsReport::scene_path`]) and writes the
/// Markdown report to `out`: the header first, the table when every row is measured. Returns the measurements.
///
/// # Errors
/// [`ReportError`].
pub fn run(report: &EffectsReport, scene: &PreparedScene, out: &mut dyn Write) -> Result<EffectsResults, ReportError> {
    // Plan first: a scene that cannot be planned fails before anything is printed.
    let plans = report
        .sizes
        .iter()
        .map(|&size| ScenePlan::new(scene, &scene.camera(), size, &PlanOptions::default()))
        .collect::<Result<Vec<_>, _>>()?;
    let threads = report.thread_count();
    writeln!(out, "{}", header(report, &plans, threads, &super::machine_description()))?;
    writeln!(out)?;
    out.flush()?;
    let results = measure(scene, report)?;
    writeln!(out, "{}", table(&results))?;
    out.flush()?;
    Ok(results)
}
