//! `rastty-bench accuracy`: what each quality knob costs in time and buys in accuracy.
//!
//! Five scenes ([`scenes`]) are rendered by the reference renderer ([`crate::reference`]: `f64` throughout, 16x16
//! samples per pixel) and by rastty with the default settings and with each knob turned alone
//! ([`settings`]). For every scene and setting the report gives the median frame time, the time relative to the
//! default, the PSNR against the reference, the largest error in 8-bit steps, and the pixels with wrong coverage;
//! then which settings lie on the speed/quality frontier. It writes `accuracy.md` and the chart `accuracy.png`.

mod chart;
mod core_render;
mod metrics;
pub mod scenes;
pub mod settings;

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::time::Duration;

pub use core_render::{CoreRenderError, CoreScene, Frames, Rendered};
pub use metrics::{Score, score};

use crate::reference;
use rastty_core::target::Samples;
use rastty_scene::escaped::path_text;
use rastty_scene::png_file::{write_atomically, write_png};

/// What to measure and where to write.
#[derive(Clone, Debug)]
pub struct AccuracyOptions {
    /// Image size.
    pub size: (u32, u32),
    /// Frames timed per setting (the median is reported).
    pub repeats: usize,
    /// Directory for `accuracy.md` and `accuracy.png`.
    pub output: PathBuf,
    /// A few repeats at a small size: proves the command works, in CI.
    pub quick: bool,
}

impl AccuracyOptions {
    /// The full report: 320x240, 51 repeats.
    pub fn full(output: PathBuf) -> Self {
        Self { size: (320, 240), repeats: 51, output, quick: false }
    }

    /// The quick report: 96x72, 2 repeats.
    pub fn quick(output: PathBuf) -> Self {
        Self { size: (96, 72), repeats: 2, output, quick: true }
    }
}

/// One measured setting.
pub struct AccuracyRow {
    /// The setting.
    pub setting: settings::Setting,
    /// Median frame time.
    pub time: Duration,
    /// Time relative to the default.
    pub relative: f64,
    /// The score against the reference.
    pub score: Score,
    /// The setting gives exactly the default's pixels here (its knob has nothing to act on in this scene).
    pub same_as_default: bool,
}

/// Differences smaller than these are noise, not one setting beating another: 5% of frame time (this machine is
/// shared and timings vary by that much), 0.05 dB of PSNR.
const TIME_NOISE: f64 = 0.05;
const PSNR_NOISE: f64 = 0.05;

/// One scene's results.
pub struct SceneResult {
    /// The scene's name.
    pub name: &'static str,
    /// What it stresses.
    pub purpose: &'static str,
    /// One row per setting, the default first.
    pub rows: Vec<AccuracyRow>,
    /// Time the reference took.
    pub reference_time: Duration,
    /// For a scene with an environment: each prefiltering the settings name and the time making the environment
    /// ready with it took, on one thread (a cost paid once per scene, not per frame).
    pub preparations: Vec<(rastty_core::environment::Prefiltering, Duration)>,
}

impl SceneResult {
    /// The settings on the frontier: no other setting is at least as fast and at least as accurate (PSNR) and
    /// clearly better in one of the two (beyond the noise margins). Settings that give the default's very pixels
    /// are left out: they are the default under another name.
    pub fn frontier(&self) -> Vec<&AccuracyRow> {
        let candidates: Vec<&AccuracyRow> = self.rows.iter().filter(|r| !r.same_as_default).collect();
        let beats = |o: &AccuracyRow, r: &AccuracyRow| {
            let (to, tr) = (o.time.as_secs_f64(), r.time.as_secs_f64());
            let (po, pr) = (o.score.psnr, r.score.psnr);
            let no_worse = to <= tr * (1.0 + TIME_NOISE) && po >= pr - PSNR_NOISE;
            let better = to < tr * (1.0 - TIME_NOISE) || po > pr + PSNR_NOISE;
            no_worse && better
        };
        candidates.iter().copied().filter(|r| !candidates.iter().any(|o| beats(o, r))).collect()
    }
}

/// Everything the report measured.
pub struct AccuracyReport {
    /// The options it ran with.
    pub options: AccuracyOptions,
    /// Per scene.
    pub scenes: Vec<SceneResult>,
}

/// Measures every scene with every setting.
///
/// # Errors
/// A message when a scene cannot be built or rendered.
pub fn measure(options: &AccuracyOptions) -> Result<AccuracyReport, String> {
    let (w, h) = options.size;
    let mut results = Vec::new();
    for scene in scenes::all(w, h)? {
        let start = std::time::Instant::now();
        let truth = reference::render(&scene.scene).map_err(|e| format!("{}: reference: {e}", scene.name))?;
        let reference_time = start.elapsed();
        let core = CoreScene::new(&scene.scene).map_err(|e| format!("{}: {e}", scene.name))?;
        let preparations = core.environments.iter().map(|p| (p.prefiltering, p.time)).collect();
        let failed = |e: CoreRenderError| format!("{}: {e}", scene.name);
        // Settings take turns, a frame each per round: load on the machine then slows them alike.
        let mut frames: Vec<Frames<'_>> = settings::ALL.iter().map(|setting| Frames::new(&core, setting)).collect();
        for _ in 0..options.repeats {
            for f in &mut frames {
                f.time_one(&core).map_err(failed)?;
            }
        }
        let mut rows = Vec::new();
        let mut default_pixels = Vec::new();
        for (setting, f) in settings::ALL.into_iter().zip(frames) {
            let rendered = f.finish(&core).map_err(failed)?;
            let sampled = setting.supersample > 1 || setting.multisample != Samples::One;
            let score = score(&truth, &rendered, sampled);
            let same_as_default = if setting.is_default() {
                default_pixels.clone_from(&rendered.pixels);
                false
            } else {
                rendered.pixels == default_pixels
            };
            rows.push(AccuracyRow { setting, time: rendered.median, relative: 0.0, score, same_as_default });
        }
        let base = rows[0].time.as_secs_f64().max(1e-9);
        for row in &mut rows {
            row.relative = row.time.as_secs_f64() / base;
        }
        results.push(SceneResult { name: scene.name, purpose: scene.purpose, rows, reference_time, preparations });
    }
    Ok(AccuracyReport { options: options.clone(), scenes: results })
}

/// The marker after which `accuracy.md` holds hand-written analysis, kept when the report is regenerated.
pub const ANALYSIS_MARKER: &str =
    "<!-- Hand-written analysis below this line is kept when the report is regenerated. -->";

impl AccuracyReport {
    /// The command line that reproduces the report.
    pub fn command_line(&self) -> String {
        if self.options.quick { "rastty-bench accuracy --quick".into() } else { "rastty-bench accuracy".into() }
    }

    /// The Markdown report (without any hand-written analysis).
    pub fn markdown(&self) -> String {
        let (w, h) = self.options.size;
        let n = reference::SAMPLES_PER_AXIS;
        let mut md = String::new();
        let _ = writeln!(md, "# What accuracy costs: every quality knob, timed and scored\n");
        let _ = writeln!(
            md,
            "Generated by `{}` ({}) on {}, single thread: {w}x{h} pixels, the median of {} frames per setting, the \
             settings taking turns. Each scene is also rendered by the reference renderer (`f64` throughout, \
             {n}x{n} samples per pixel each tested against the triangles' edges in `f64`, perspective-correct, \
             bilinear, per-pixel lighting (metallic-roughness surfaces: glTF's BRDF with a multiple-scattering lobe, \
             the environment integrated over it by 64 importance-sampled directions a sample), in linear light: \
             texels decoded from sRGB before they are blended, each \
             sample's light averaged and the mean encoded); PSNR and errors are against it. Every setting changes \
             one knob from rastty's default (8 sub-pixel bits, fixed-point edges, perspective-correct, bilinear, \
             trilinear mipmaps, per-pixel lighting, linear light, one sample per pixel, `f32` depth). The setting \
             that lights sRGB codes takes every colour the scene gives in linear light encoded, as a renderer that \
             lights the stored values would be given it. There is \
             no maths knob: normalising uses a Newton-Raphson inverse square root within one unit in the last \
             place of the exact value for every input (`float::inv_sqrt`, tested over all of them), and every \
             other function goes through `libm`, so that host and microcontroller compute the same pixels.\n",
            self.command_line(),
            super::build_description(),
            super::machine_description(),
            self.options.repeats
        );
        let _ = writeln!(
            md,
            "Columns: median frame time; time relative to the default; PSNR against the reference (higher is \
             better); the same over the pixels no edge crosses (the reference covers all or none of their \
             samples), the error of shading and texturing alone; the largest error of any channel in 8-bit steps; pixels whose coverage differs from the \
             reference's (one sample per pixel: the pixel centre against the exact centre test; supersampling: \
             the majority of samples against the reference's coverage of at least half). The chart is \
             [accuracy.png](accuracy.png).\n"
        );
        for scene in &self.scenes {
            let _ = writeln!(
                md,
                "## {}\n\n{}. Reference: {:.2} s.\n",
                scene.name,
                capitalise(scene.purpose),
                scene.reference_time.as_secs_f64()
            );
            if !scene.preparations.is_empty() {
                let made: Vec<String> = scene
                    .preparations
                    .iter()
                    .map(|(p, time)| {
                        let ms = time.as_secs_f64() * 1e3;
                        format!("{}x{}, {} levels, {} samples: {ms:.1} ms", 2 * p.height, p.height, p.levels, p.samples)
                    })
                    .collect();
                let _ = writeln!(
                    md,
                    "The environment made ready once per scene, on one thread, for each prefiltering below (its \
                     frames' times do not include it): {}.\n",
                    made.join("; ")
                );
            }
            let _ = writeln!(
                md,
                "| setting | knob | time (ms) | x default | PSNR (dB) | inside (dB) | max error | coverage errors |"
            );
            let _ = writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|");
            for row in &scene.rows {
                let name = if row.setting.is_default() {
                    format!("**{}**", row.setting.name)
                } else {
                    row.setting.name.to_string()
                };
                let decibels = |psnr: f64| if psnr.is_finite() { format!("{psnr:.2}") } else { "exact".into() };
                let (psnr, inside) = if row.same_as_default {
                    ("same pixels as default".into(), String::new())
                } else {
                    (decibels(row.score.psnr), decibels(row.score.inside_psnr))
                };
                let _ = writeln!(
                    md,
                    "| {name} | {} | {:.3} | {:.2} | {psnr} | {inside} | {} | {} |",
                    row.setting.knob,
                    row.time.as_secs_f64() * 1e3,
                    row.relative,
                    row.score.max_error,
                    row.score.coverage_errors
                );
            }
            md.push('\n');
        }
        let _ = writeln!(md, "## The speed/quality frontier\n");
        let _ = writeln!(
            md,
            "Settings that no other setting beats on both time and PSNR, computed from the tables above (time \
             differences under 5% and PSNR differences under 0.05 dB count as ties; settings that give the default's \
             very pixels are left out):\n"
        );
        for scene in &self.scenes {
            let frontier = scene.frontier();
            let names: Vec<String> = frontier.iter().map(|r| r.setting.name.to_string()).collect();
            let default_on = frontier.iter().any(|r| r.setting.is_default());
            let _ = writeln!(
                md,
                "- {}: {} (the default is {}on it)",
                scene.name,
                names.join(", "),
                if default_on { "" } else { "not " }
            );
        }
        md.push('\n');
        md
    }

    /// The chart as `0x00RRGGBB` pixels.
    ///
    /// # Errors
    /// A message when the font cannot be registered or plotters fails.
    pub fn chart(&self, width: u32, height: u32) -> Result<Vec<u32>, String> {
        let panels: Vec<(&str, Vec<chart::Mark<'_>>)> = self
            .scenes
            .iter()
            .map(|s| {
                let marks = s
                    .rows
                    .iter()
                    .filter(|r| !r.same_as_default)
                    .map(|r| chart::Mark {
                        label: r.setting.name,
                        relative_time: r.relative,
                        psnr: r.score.psnr,
                        highlighted: r.setting.is_default(),
                    })
                    .collect();
                (s.name, marks)
            })
            .collect();
        chart::draw(&panels, width, height)
    }

    /// Writes `accuracy.md` (keeping any hand-written analysis after [`ANALYSIS_MARKER`]) and `accuracy.png` into
    /// the output directory.
    ///
    /// # Errors
    /// A message naming the file that could not be written.
    pub fn write(&self) -> Result<Written, String> {
        let dir = &self.options.output;
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", path_text(dir)))?;
        let markdown_path = dir.join("accuracy.md");
        let kept = std::fs::read_to_string(&markdown_path)
            .ok()
            .and_then(|old| old.find(ANALYSIS_MARKER).map(|i| old[i..].to_string()))
            .unwrap_or_else(|| format!("{ANALYSIS_MARKER}\n"));
        let markdown = self.markdown();
        write_atomically(&markdown_path, |out| write!(out, "{markdown}{kept}"))
            .map_err(|e| format!("cannot write {}: {e}", path_text(&markdown_path)))?;
        let chart_path = dir.join("accuracy.png");
        let (cw, ch) = (1400, 1000);
        let pixels = self.chart(cw, ch)?;
        write_png(&chart_path, cw, ch, &pixels).map_err(|e| e.to_string())?;
        Ok(Written { markdown, markdown_path, chart_path })
    }
}

/// What [`AccuracyReport::write`] wrote.
pub struct Written {
    /// The generated Markdown (without the kept analysis).
    pub markdown: String,
    /// Where it was written.
    pub markdown_path: PathBuf,
    /// Where the chart was written.
    pub chart_path: PathBuf,
}

fn capitalise(s: &str) -> String {
    let mut c = s.chars();
    c.next().map_or_else(String::new, |f| f.to_uppercase().collect::<String>() + c.as_str())
}
