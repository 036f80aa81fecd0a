//! `rastty-bench peers`: the core against published Rust software rasterizers, side by side in one run.
//!
//! Six pictures ([`scenes`]) drawn by euc 0.5.3, retrofire-core 0.4.0 and the core, single thread, the same
//! work per frame for each: clear colour and depth, draw the whole mesh with a z-buffer, back faces culled, the
//! vertex normal interpolated perspective-correctly, and per pixel `albedo * (0.1 + 0.9 * max(0, n.l))` with `n`
//! the normalised interpolated normal. The renderers take turns frame by frame (the first of each round rotating),
//! so that a noisy moment of the machine falls on all of them alike. The report gives each renderer's median and
//! minimum time per frame, the core's ratio to the best peer, and how many pixels of each peer's picture differ
//! from the core's by more than [`DIFFERENCE`] levels in a channel (the peers' edge rules and depth precision
//! differ from the core's exact ones, so a few edge pixels do).
//!
//! A second table draws the same scenes through the program's threaded frame ([`threaded_renderer`]) on one
//! thread and on each count up to [`PeersReport::threads`], taking turns frame by frame, and gives the speed-up
//! beside the machine's own ceiling for the frame ([`ceiling`]).

pub mod ceiling;
pub mod core_renderer;
pub mod euc_renderer;
pub mod retrofire_renderer;
pub mod scenes;
pub mod threaded_renderer;

use std::fmt::Write as _;
use std::io::Write;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use rastty_core::math::Vec3;

use self::ceiling::Ceiling;
use self::core_renderer::CoreRenderer;
use self::euc_renderer::EucRenderer;
use self::retrofire_renderer::RetrofireRenderer;
use self::scenes::{PeerScene, PeerSceneError};
use self::threaded_renderer::ThreadedRenderer;
use super::median;

/// Measured frames per renderer and scene by default.
pub const DEFAULT_FRAMES: usize = 20;
/// Measured frames with `--quick`.
pub const QUICK_FRAMES: usize = 2;
/// A pixel differs when a channel differs by more than this many levels.
pub const DIFFERENCE: u32 = 8;
/// The scenes' names, in the report's order.
pub const SCENES: [&str; 6] = ["head", "head-tex", "bunny", "sphere100k", "sphere1m", "large"];

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct PeersReport {
    /// The shared models folder.
    pub models: PathBuf,
    /// Measured frames per renderer and scene.
    pub frames: usize,
    /// Smaller spheres and [`QUICK_FRAMES`] frames, for CI: proves the command works.
    pub quick: bool,
    /// The scenes to draw (names from [`SCENES`]); empty for all.
    pub only: Vec<String>,
    /// The most threads of the threaded frame: it is drawn on 1 and on each count from 2 to this.
    pub threads: usize,
}

/// The three renderers, in the report's column order.
const RENDERERS: [&str; 3] = ["euc 0.5.3", "retrofire-core 0.4.0", "rastty-core"];

/// One scene's renderers, each with its buffers.
struct Contenders {
    euc: EucRenderer,
    retrofire: RetrofireRenderer,
    core: CoreRenderer,
}

impl Contenders {
    fn new(scene: &PeerScene) -> Self {
        Self { euc: EucRenderer::new(scene), retrofire: RetrofireRenderer::new(scene), core: CoreRenderer::new(scene) }
    }

    /// Draws a frame with renderer `which` (an index into [`RENDERERS`]) and returns how long it took.
    fn time(&mut self, which: usize, scene: &PeerScene) -> Duration {
        let start = Instant::now();
        match which {
            0 => self.euc.render(scene),
            1 => self.retrofire.render(scene),
            _ => self.core.render(scene),
        }
        start.elapsed()
    }

    fn pixels(&self, which: usize) -> &[u32] {
        match which {
            0 => self.euc.pixels(),
            1 => self.retrofire.pixels(),
            _ => self.core.pixels(),
        }
    }
}

/// Pixels where `a` and `b` differ by more than [`DIFFERENCE`] in some channel.
pub fn differing_pixels(a: &[u32], b: &[u32]) -> usize {
    let channel = |p: u32, shift: u32| (p >> shift) & 0xFF;
    a.iter()
        .zip(b)
        .filter(|&(&p, &q)| [16, 8, 0].iter().any(|&s| channel(p, s).abs_diff(channel(q, s)) > DIFFERENCE))
        .count()
}

/// `color` as `0x00RRGGBB`, each channel rounded to nearest and limited to `[0, 255]`: the peers' last step.
pub fn pack(color: Vec3) -> u32 {
    u32::from(channel(color.x)) << 16 | u32::from(channel(color.y)) << 8 | u32::from(channel(color.z))
}

/// One channel of [`pack`]: `c * 255` rounded to nearest, through the saturating conversion `as u8` (values past
/// 255 give 255, negative values and NaN give 0), so no clamp is needed: the bits of a clamp and a rounding, in
/// fewer operations, as a careful user writes it.
#[inline(always)]
pub fn channel(c: f32) -> u8 {
    (c * 255.0 + 0.5) as u8
}

/// The comparison's light factor from an interpolated normal `n` (not unit length) as `n.l` (`l`: the unit vector
/// to the light) and `|n|`: `AMBIENT + DIFFUSE * max(0, n.l / |n|)`, one square root and one division where
/// normalising `n` first takes three more.
#[inline(always)]
pub fn light_factor(n_dot_l: f32, n_length: f32) -> f32 {
    scenes::AMBIENT + scenes::DIFFUSE * (n_dot_l / n_length).max(0.0)
}

/// Runs the report and writes it to `out` as Markdown.
///
/// # Errors
/// When a model cannot be read, a scene name is unknown, or `out` cannot be written.
pub fn run(report: &PeersReport, out: &mut dyn Write) -> Result<(), Box<dyn std::error::Error>> {
    if let Some(unknown) = report.only.iter().find(|name| !SCENES.contains(&name.as_str())) {
        return Err(PeerSceneError(format!("no scene named {unknown:?}: the scenes are {}", SCENES.join(", "))).into());
    }
    let scenes = scenes::scenes(&report.models, report.quick, &report.only)?;
    let mut text = String::new();
    let command = if report.quick { "--quick".to_owned() } else { format!("--frames {}", report.frames) };
    writeln!(text, "### The core and its peers, one thread")?;
    writeln!(text)?;
    writeln!(text, "- command: `rastty-bench peers {command}` ({})", super::build_description())?;
    writeln!(text, "- machine: {}", super::machine_description())?;
    writeln!(
        text,
        "- frames: one warm-up frame each, then {} measured frames per renderer and scene, the renderers taking \
         turns frame by frame; ms: median (minimum) wall time of a frame: clear, draw the mesh",
        report.frames
    )?;
    writeln!(
        text,
        "- differing: pixels of the peer's picture more than {DIFFERENCE} levels from the core's in a channel"
    )?;
    for scene in &scenes {
        writeln!(text, "- {}: {}", scene.name, scene.description)?;
    }
    writeln!(text)?;
    writeln!(
        text,
        "| scene | {} | {} | {} | core / best peer | differing from euc | differing from retrofire |",
        RENDERERS[0], RENDERERS[1], RENDERERS[2]
    )?;
    writeln!(text, "|---|---:|---:|---:|---:|---:|---:|")?;
    for scene in &scenes {
        let mut contenders = Contenders::new(scene);
        let mut times: [Vec<Duration>; 3] = Default::default();
        for which in 0..RENDERERS.len() {
            contenders.time(which, scene);
        }
        for round in 0..report.frames {
            for k in 0..RENDERERS.len() {
                let which = (round + k) % RENDERERS.len();
                times[which].push(contenders.time(which, scene));
            }
        }
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        let medians = times.each_ref().map(|t| ms(median(t)));
        let cell = |which: usize| {
            let min = times[which].iter().min().copied().unwrap_or_default();
            format!("{:.2} ({:.2})", medians[which], ms(min))
        };
        let best_peer = medians[0].min(medians[1]);
        let core = contenders.pixels(2);
        writeln!(
            text,
            "| {} | {} | {} | {} | {:.2} | {} | {} |",
            scene.name,
            cell(0),
            cell(1),
            cell(2),
            medians[2] / best_peer,
            differing_pixels(contenders.pixels(0), core),
            differing_pixels(contenders.pixels(1), core),
        )?;
    }
    threaded_table(report, &scenes, &mut text)?;
    out.write_all(text.as_bytes())?;
    Ok(())
}

/// The second table: each scene through the threaded frame on one thread and on each count from 2 to
/// `report.threads`, the two taking turns frame by frame, with the machine's ceiling for that frame ([`Ceiling`])
/// timed the same way beside it, and the pixels that differ from the core's own draw (none, when the frame is
/// right).
fn threaded_table(
    report: &PeersReport,
    scenes: &[PeerScene],
    text: &mut String,
) -> Result<(), Box<dyn std::error::Error>> {
    let most = report.threads.max(2);
    writeln!(text)?;
    writeln!(text, "### The same scenes through the threaded frame, on 1 to {most} threads")?;
    writeln!(text)?;
    writeln!(
        text,
        "- a scene of one object, planned once and drawn by one `SceneRenderer` per column, the columns taking \
         turns frame by frame; ms: median (minimum) wall time of a frame; differing: pixels more than \
         {DIFFERENCE} levels from the core's single draw above"
    )?;
    writeln!(
        text,
        "- ceiling: the speed-up of a plain parallel loop writing the frame's colour and depth, at least {} pixels \
         a time (passes over the frame), in one band of rows per thread of a pool started once, timed on 1 and n \
         threads in the same turns; of the ceiling: the frame's speed-up over the loop's",
        ceiling::MIN_WRITES
    )?;
    writeln!(text)?;
    writeln!(
        text,
        "| scene | n | 1 thread | n threads | speed-up | ceiling speed-up | of the ceiling | differing from the \
         core's draw |"
    )?;
    writeln!(text, "|---|---:|---:|---:|---:|---:|---:|---:|")?;
    for scene in scenes {
        let mut single = CoreRenderer::new(scene);
        single.render(scene);
        for threads in 2..=most {
            let mut renderers = [ThreadedRenderer::new(scene, 1)?, ThreadedRenderer::new(scene, threads)?];
            let mut ceilings =
                [Ceiling::new(scene.width, scene.height, 1)?, Ceiling::new(scene.width, scene.height, threads)?];
            let mut times: [Vec<Duration>; 4] = Default::default();
            for (renderer, ceiling) in renderers.iter_mut().zip(&mut ceilings) {
                renderer.render()?;
                ceiling.fill();
            }
            for round in 0..report.frames {
                for k in 0..2 {
                    let which = (round + k) % 2;
                    let start = Instant::now();
                    renderers[which].render()?;
                    times[which].push(start.elapsed());
                    let start = Instant::now();
                    ceilings[which].fill();
                    times[2 + which].push(start.elapsed());
                }
            }
            let ms = |d: Duration| d.as_secs_f64() * 1e3;
            let medians = times.each_ref().map(|t| ms(median(t)));
            let cell = |which: usize| {
                let min = times[which].iter().min().copied().unwrap_or_default();
                format!("{:.2} ({:.2})", medians[which], ms(min))
            };
            let (speed_up, ceiling) = (medians[0] / medians[1], medians[2] / medians[3]);
            let differing = renderers.iter().map(|r| differing_pixels(r.pixels(), single.pixels())).max().unwrap_or(0);
            writeln!(
                text,
                "| {} | {threads} | {} | {} | {speed_up:.2} | {ceiling:.2} | {:.2} | {differing} |",
                scene.name,
                cell(0),
                cell(1),
                speed_up / ceiling,
            )?;
        }
    }
    Ok(())
}
