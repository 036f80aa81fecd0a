//! `rastty-bench frames`: the time per frame of one scene file, the same frame drawn again and again.
//!
//! [`effects`](super::effects) lets its configurations take turns frame by frame, so that a noisy moment of the
//! machine falls on all of them alike; each of its frames therefore starts with caches full of another
//! configuration's data. This report measures a scene the way a viewer shows it while the camera orbits, or a
//! benchmark loop repeats one frame: in blocks of [`BLOCK`] frames of one configuration, each block after a
//! warm-up frame of its own, the configurations taking turns block by block. Its rows are the scene with every
//! effect its file asks for, with the shadow maps kept (one [`SceneRenderer`] for every frame) and drawn every
//! frame (a fresh renderer per frame, as `rastty render` makes one per image), and the scene without shadows;
//! a scene without a shadow-casting light has the one row. The first row is drawn again with every surface lit by
//! glTF's metallic-roughness model instead of Blinn-Phong (`--shading metallic-roughness`), and a last row draws it
//! with four samples per pixel (`--msaa`).

use std::fmt::Write as _;
use std::io::Write;
use std::path::PathBuf;
use std::time::Duration;

use super::effects::{ConfigurationTimes, ShadowMaps, TimedFrames, check_maps, plan};
use super::error::ReportError;
use super::median;
use rastty_scene::escaped::path_text;
use rastty_scene::scene_render::{
    EffectToggles, PlanOptions, PreparedScene, SceneEffect, ScenePlan, SceneRenderError, SceneRenderer, ShadingMode,
};

/// Frame size measured unless another is given: the tinyrenderer comparison's.
pub const DEFAULT_SIZE: (u32, u32) = (800, 800);
/// Measured frames per row by default.
pub const DEFAULT_FRAMES: usize = 30;
/// Measured frames per row with `--quick`.
pub const QUICK_FRAMES: usize = 5;
/// Measured frames in a row's block, after its warm-up frame.
pub const BLOCK: usize = 10;

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct FramesReport {
    /// The scene file (shown in the report; the caller loads it).
    pub scene_path: PathBuf,
    /// Measured frames per row (at least 1).
    pub frames: usize,
    /// Threads per frame, or `None` for as many as this machine runs at once.
    pub threads: Option<usize>,
    /// Frame size in pixels.
    pub size: (u32, u32),
    /// True when `--quick` chose the frame count (only for the command line shown).
    pub quick: bool,
}

impl FramesReport {
    /// `frames` frames per row of `scene` at `size` on `threads` threads (default: every logical CPU).
    pub fn new(scene: PathBuf, frames: usize, threads: Option<usize>, size: (u32, u32)) -> Self {
        Self { scene_path: scene, frames, threads, size, quick: false }
    }

    /// The report with [`QUICK_FRAMES`] frames, for CI.
    pub fn quick(scene: PathBuf, threads: Option<usize>, size: (u32, u32)) -> Self {
        Self { quick: true, ..Self::new(scene, QUICK_FRAMES, threads, size) }
    }

    /// The threads each frame is drawn on: [`Self::threads`], else this machine's logical CPUs (at least 1).
    pub fn thread_count(&self) -> usize {
        super::thread_count(self.threads)
    }

    /// The command that prints this report.
    pub fn command_line(&self) -> String {
        let mut line = format!("rastty-bench frames {}", path_text(&self.scene_path));
        if self.size != DEFAULT_SIZE {
            let _ = write!(line, " --size {}x{}", self.size.0, self.size.1);
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

/// One row: the effects allowed and how the shadow maps are had.
#[derive(Clone, Debug, PartialEq)]
pub struct FramesRow {
    /// The row's label.
    pub label: &'static str,
    /// The effects allowed (the scene's own materials and lights decide where they apply).
    pub effects: EffectToggles,
    /// One renderer for every frame, or a fresh one per frame.
    pub maps: ShadowMaps,
    /// Four samples per pixel ([`PlanOptions::multisample`]).
    pub multisample: bool,
    /// The shading mode of every surface.
    pub shading: ShadingMode,
}

impl FramesRow {
    /// The row's plan of `scene`'s frame at `size` with its own camera.
    fn plan(&self, scene: &PreparedScene, size: (u32, u32)) -> Result<ScenePlan, SceneRenderError> {
        let options = PlanOptions {
            effects: self.effects,
            multisample: self.multisample,
            shading: self.shading,
            ..PlanOptions::default()
        };
        ScenePlan::new(scene, &scene.camera(), size, &options)
    }
}

/// The rows for a scene: with shadow passes, every effect with the maps kept and drawn every frame and every
/// effect but shadows; without, every effect alone; then the first row again lit by the metallic-roughness model,
/// and with four samples per pixel.
pub fn rows(has_shadows: bool) -> Vec<FramesRow> {
    let all = EffectToggles::ALL_ON;
    let phong = ShadingMode::Phong;
    let row = |label, effects, maps| FramesRow { label, effects, maps, multisample: false, shading: phong };
    let pbr = |label| FramesRow { shading: ShadingMode::MetallicRoughness, ..row(label, all, ShadowMaps::Kept) };
    let msaa = |label| FramesRow { multisample: true, ..row(label, all, ShadowMaps::Kept) };
    if !has_shadows {
        return vec![
            row("every effect", all, ShadowMaps::Kept),
            pbr("every effect, metallic-roughness"),
            msaa("every effect, 4x MSAA"),
        ];
    }
    let mut no_shadows = all;
    no_shadows.set(SceneEffect::Shadows, false);
    vec![
        row("every effect, shadow maps kept", all, ShadowMaps::Kept),
        pbr("every effect, metallic-roughness, shadow maps kept"),
        row("every effect, shadow maps drawn every frame", all, ShadowMaps::Drawn),
        row("every effect but shadows", no_shadows, ShadowMaps::Kept),
        msaa("every effect, 4x MSAA, shadow maps kept"),
    ]
}

/// Everything measured.
#[derive(Clone, Debug, PartialEq)]
pub struct FramesResults {
    /// The rows, as [`rows`] gives them for the scene.
    pub rows: Vec<FramesRow>,
    /// The threads each frame was drawn on.
    pub threads: usize,
    /// Each row's samples.
    pub samples: Vec<ConfigurationTimes>,
}

/// Measures every row of `report` on `scene`.
///
/// # Errors
/// [`ReportError::Setup`] for zero frames, or shadow maps not drawn or reused as the row needs;
/// [`ReportError::Render`].
pub fn measure(scene: &PreparedScene, report: &FramesReport) -> Result<FramesResults, ReportError> {
    if report.frames == 0 {
        return Err(ReportError::Setup("the report needs at least one frame per row".into()));
    }
    let has_shadows = !plan(scene, report.size, EffectToggles::ALL_ON)?.shadow_passes.is_empty();
    let rows = rows(has_shadows);
    let plans = rows.iter().map(|row| row.plan(scene, report.size)).collect::<Result<Vec<_>, _>>()?;
    let threads = report.thread_count();
    let mut renderers: Vec<SceneRenderer> = rows.iter().map(|_| SceneRenderer::with_threads(threads)).collect();
    let mut samples: Vec<ConfigurationTimes> = plans.iter().map(ConfigurationTimes::for_plan).collect();
    let mut frames = TimedFrames::new(scene, report.size, threads);
    // Two frames first: a kept map is drawn in the first and its filter windows' ranges worked out in the second.
    for (r, row) in rows.iter().enumerate() {
        for _ in 0..2 {
            frames.render(&mut renderers[r], row.maps, &plans[r])?;
        }
    }
    while samples.iter().any(|s| s.frame.len() < report.frames) {
        for (r, row) in rows.iter().enumerate() {
            let block = BLOCK.min(report.frames - samples[r].frame.len());
            if block == 0 {
                continue;
            }
            frames.render(&mut renderers[r], row.maps, &plans[r])?;
            for _ in 0..block {
                let (elapsed, frame_report) = frames.render(&mut renderers[r], row.maps, &plans[r])?;
                check_maps(row.label, row.maps, &frame_report)?;
                samples[r].push(elapsed, &frame_report);
            }
        }
    }
    Ok(FramesResults { rows, threads, samples })
}

/// The lines above the table: what was measured, where, and how to read it.
pub fn header(report: &FramesReport, plan: &ScenePlan, threads: usize, machine: &str) -> String {
    let (w, h) = report.size;
    let plural = |n: usize, word: &str| if n == 1 { format!("1 {word}") } else { format!("{n} {word}s") };
    let maps: Vec<String> = plan.shadow_passes.iter().map(|p| p.texels()).collect();
    let maps = if maps.is_empty() { "no shadow map".to_owned() } else { format!("shadow maps {}", maps.join(", ")) };
    let occlusion = if plan.ambient_occlusion.is_some() { "ambient occlusion" } else { "no ambient occlusion" };
    [
        format!("### Time per frame: `{}` at {w}x{h}", path_text(&report.scene_path)),
        String::new(),
        format!("- command: `{}` ({})", report.command_line(), super::build_description()),
        format!("- machine: {machine}"),
        format!("- threads: {threads}"),
        format!(
            "- scene: the file's camera and effects; {}, {}, {maps}, {occlusion}",
            plural(plan.draws.len(), "forward draw"),
            plural(plan.lights.len(), "light")
        ),
        format!(
            "- frames: every row renders 2 frames first, then {} measured frames in blocks of up to {BLOCK}, each \
             block after a warm-up frame, the rows taking turns block by block; every figure is the median of the \
             measured frames, but `min`",
            report.frames
        ),
        "- ms: wall time of `SceneRenderer::render`; shadow, forward, occlusion: the passes' times from its \
         `FrameReport`, in ms (– where the plan has no such pass); fragments: shaded by the forward pass in a frame; \
         ns/fragment: the forward pass's median wall time over those fragments (all threads' together)"
            .to_owned(),
        "- metallic-roughness: every surface lit by glTF's metallic-roughness model instead of Blinn-Phong \
         (`--shading metallic-roughness`), the same fragments"
            .to_owned(),
        "- shadow maps kept: one renderer for every frame (as the viewer while only the camera moves); drawn every \
         frame: a fresh renderer for every frame (as `rastty render` makes one per image), its map's buffer \
         allocated and the map drawn each time"
            .to_owned(),
    ]
    .join("\n")
}

/// The table: one line per row.
pub fn table(results: &FramesResults) -> String {
    let ms = |d: Duration| format!("{:.2}", d.as_secs_f64() * 1e3);
    let mut lines = vec![
        "| configuration | ms | min ms | shadow | forward | occlusion | fragments | ns/fragment |".to_owned(),
        "|---|---:|---:|---:|---:|---:|---:|---:|".to_owned(),
    ];
    for (row, s) in results.rows.iter().zip(&results.samples) {
        let pass = |present: bool, values: &[Duration]| if present { ms(median(values)) } else { "–".to_owned() };
        let min = s.frame.iter().min().copied().unwrap_or_default();
        let per_fragment = median(&s.forward).as_secs_f64() * 1e9 / s.fragments.max(1) as f64;
        lines.push(format!(
            "| {} | {} | {} | {} | {} | {} | {} | {per_fragment:.1} |",
            row.label,
            ms(median(&s.frame)),
            ms(min),
            pass(s.shadow_passes > 0, &s.shadow),
            ms(median(&s.forward)),
            pass(s.occlusion_step, &s.occlusion),
            s.fragments
        ));
    }
    lines.join("\n")
}

/// Measures everything `report` asks for on `scene` (loaded from [`FramesReport::scene_path`]) and writes the
/// Markdown report to `out`: the header first, the table when every row is measured. Returns the measurements.
///
/// # Errors
/// [`ReportError`].
pub fn run(report: &FramesReport, scene: &PreparedScene, out: &mut dyn Write) -> Result<FramesResults, ReportError> {
    // Plan first: a scene that cannot be planned fails before anything is printed.
    let plan = plan(scene, report.size, EffectToggles::ALL_ON)?;
    let threads = report.thread_count();
    writeln!(out, "{}", header(report, &plan, threads, &super::machine_description()))?;
    writeln!(out)?;
    out.flush()?;
    let results = measure(scene, report)?;
    writeln!(out, "{}", table(&results))?;
    out.flush()?;
    Ok(results)
}
