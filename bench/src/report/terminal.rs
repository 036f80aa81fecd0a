//! `rastty-bench terminal`: what the viewer's frames cost, for a turntable of the built-in model.
//!
//! For each terminal size and colour mode, the built-in model is turned once around (the viewer's camera for a
//! model, [`FramedCamera::DEFAULT`], turned with [`Orbit::rotate`](rastty_scene::scene_render::Orbit::rotate) in equal steps about the scene's vertical axis)
//! and every frame goes through the viewer's pipeline: a [`ScenePlan`](rastty_scene::scene_render::ScenePlan) for the terminal's physical aspect and a
//! [`SceneRenderer`] (as the viewer keeps one) into a pixel buffer of the terminal's pixel size, half-block cells
//! ([`CellMode::HalfBlock`]), then the [`Encoder`] (a delta against the frame before) and, for comparison,
//! [`naive_full_frame`].
//!
//! The first frame is the encoder's full redraw (clear, then every cell that is not blank). It is reported in a
//! column of its own and left out of every mean and median: those are over the `frames` frames after it, which
//! together make the full turn (the last one shows the model as the first did).

use std::io::Write;
use std::time::{Duration, Instant};

use super::error::ReportError;
use super::median;
use super::turntable::{CELL_ASPECT, Turntable, TurntableFrame, builtin_scene, mean};
use rastty::screen::{CellMode, ColorMode, Encoder, naive_full_frame};
use rastty_scene::builtin::BUILTIN_NAME;
use rastty_scene::scene_file::{FramedCamera, SceneProjection};
use rastty_scene::scene_render::{PreparedScene, SceneRenderer};

/// Terminal sizes measured, in cells (columns, rows).
pub const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (200, 60)];
/// Colour modes measured.
pub const COLOR_MODES: [ColorMode; 2] = [ColorMode::TrueColor, ColorMode::Ansi256];
/// Frames per turn by default.
pub const DEFAULT_FRAMES: usize = 120;
/// Frames per turn with `--quick`.
pub const QUICK_FRAMES: usize = 12;
/// The goal for bytes: the mean delta frame at most this share of the mean naive frame.
pub const GOAL_DELTA_SHARE: f64 = 0.35;
/// The goal for encoding: the median encode time under this...
pub const GOAL_ENCODE_TIME: Duration = Duration::from_micros(500);
/// ...at this terminal size.
pub const GOAL_ENCODE_SIZE: (u16, u16) = (200, 60);

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct TerminalReport {
    /// Frames per full turn (at least 1); the first, full-redraw frame comes on top.
    pub frames: usize,
    /// Terminal sizes in cells.
    pub sizes: Vec<(u16, u16)>,
    /// Colour modes.
    pub colors: Vec<ColorMode>,
    /// True when `--quick` chose the frame count (only for the command line shown in the report).
    pub quick: bool,
}

impl TerminalReport {
    /// The standard report: [`SIZES`] x [`COLOR_MODES`], `frames` frames per turn.
    pub fn new(frames: usize) -> Self {
        Self { frames, sizes: SIZES.to_vec(), colors: COLOR_MODES.to_vec(), quick: false }
    }

    /// The standard report with [`QUICK_FRAMES`] frames, for CI.
    pub fn quick() -> Self {
        Self { quick: true, ..Self::new(QUICK_FRAMES) }
    }

    /// The command that prints this report.
    pub fn command_line(&self) -> String {
        if self.quick {
            "rastty-bench terminal --quick".to_owned()
        } else {
            format!("rastty-bench terminal --frames {}", self.frames)
        }
    }
}

/// The figures of one terminal size and colour mode.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// Terminal columns.
    pub cols: u16,
    /// Terminal rows.
    pub rows: u16,
    /// Colour mode.
    pub colors: ColorMode,
    /// Bytes of the first frame, the encoder's full redraw (not in any mean).
    pub first_frame_bytes: usize,
    /// Encoder bytes of each frame after the first (a delta against the frame before).
    pub delta_bytes: Vec<usize>,
    /// [`naive_full_frame`] bytes of the same frames.
    pub naive_bytes: Vec<usize>,
    /// Render time (the [`ScenePlan`](rastty_scene::scene_render::ScenePlan) and [`SceneRenderer::render`], clearing included) of the same frames.
    pub render_times: Vec<Duration>,
    /// Encode time ([`Encoder::encode`]) of the same frames.
    pub encode_times: Vec<Duration>,
}

impl Measurement {
    /// Frames measured (the first, full-redraw frame not counted).
    pub fn frames(&self) -> usize {
        self.delta_bytes.len()
    }

    /// Mean encoder bytes per frame.
    pub fn mean_delta_bytes(&self) -> f64 {
        mean(&self.delta_bytes)
    }

    /// Mean naive bytes per frame.
    pub fn mean_naive_bytes(&self) -> f64 {
        mean(&self.naive_bytes)
    }

    /// Mean delta bytes over mean naive bytes (0 when there is nothing to compare).
    pub fn delta_share(&self) -> f64 {
        let naive = self.mean_naive_bytes();
        if naive > 0.0 { self.mean_delta_bytes() / naive } else { 0.0 }
    }

    /// Median render time.
    pub fn median_render(&self) -> Duration {
        median(&self.render_times)
    }

    /// Median encode time.
    pub fn median_encode(&self) -> Duration {
        median(&self.encode_times)
    }

    /// True when the mean delta frame is at most [`GOAL_DELTA_SHARE`] of the naive frame.
    pub fn meets_byte_goal(&self) -> bool {
        self.delta_share() <= GOAL_DELTA_SHARE
    }

    /// Whether the median encode time is under [`GOAL_ENCODE_TIME`]; `None` except at [`GOAL_ENCODE_SIZE`].
    pub fn meets_encode_goal(&self) -> Option<bool> {
        ((self.cols, self.rows) == GOAL_ENCODE_SIZE).then(|| self.median_encode() < GOAL_ENCODE_TIME)
    }
}

/// Measures one terminal size and colour mode: a first (full-redraw) frame, then `frames` frames making one turn.
///
/// # Errors
/// [`ReportError::Setup`] for zero frames or a size the renderer does not take; [`ReportError::Render`].
pub fn measure(
    scene: &PreparedScene,
    size: (u16, u16),
    colors: ColorMode,
    frames: usize,
) -> Result<Measurement, ReportError> {
    if frames == 0 {
        return Err(ReportError::Setup("the turntable needs at least one frame".into()));
    }
    let mut turntable = Turntable::new(scene, size, CellMode::HalfBlock, colors, frames);
    let mut encoder = Encoder::new();
    let mut bytes = Vec::new();
    let first = turntable.next_frame()?.grid;
    encoder.encode(&first, &mut bytes);
    let mut m = Measurement {
        cols: size.0,
        rows: size.1,
        colors,
        first_frame_bytes: bytes.len(),
        delta_bytes: Vec::with_capacity(frames),
        naive_bytes: Vec::with_capacity(frames),
        render_times: Vec::with_capacity(frames),
        encode_times: Vec::with_capacity(frames),
    };
    for _ in 0..frames {
        let TurntableFrame { grid, render: render_time, .. } = turntable.next_frame()?;
        // The buffer keeps the capacity of the full redraw, so encoding never waits for an allocation.
        bytes.clear();
        let start = Instant::now();
        encoder.encode(&grid, &mut bytes);
        m.encode_times.push(start.elapsed());
        m.render_times.push(render_time);
        m.delta_bytes.push(bytes.len());
        m.naive_bytes.push(naive_full_frame(&grid).len());
    }
    Ok(m)
}

/// The lines above the table: what was measured, where, and how to read it.
pub fn header(report: &TerminalReport, machine: &str) -> String {
    let build = super::build_description();
    let frames = report.frames;
    let degrees = 360.0 / frames.max(1) as f64;
    let encode_goal = GOAL_ENCODE_TIME.as_secs_f64() * 1e3;
    let (goal_cols, goal_rows) = GOAL_ENCODE_SIZE;
    let camera = FramedCamera::DEFAULT;
    [
        "### Terminal frames: a turntable of the built-in model".to_owned(),
        String::new(),
        format!("- command: `{}` ({build})", report.command_line()),
        format!("- machine: {machine}"),
        format!(
            "- scene: {BUILTIN_NAME} as the viewer shows it, its camera (yaw {}°, pitch {}°, {} radii away, {}) \
             turned {frames} times by {degrees:.3}° about the vertical axis (`Orbit::rotate`, one full turn); \
             default look (Phong, textured, the viewer's lights); half-block cells, cell aspect {CELL_ASPECT}; drawn \
             by one `SceneRenderer` on {} threads",
            camera.yaw_degrees,
            camera.pitch_degrees,
            camera.distance,
            match camera.projection {
                SceneProjection::Perspective { fov_degrees } => format!("{fov_degrees}° lens"),
                SceneProjection::Orthographic { height } => format!("orthographic, {height} radii high"),
            },
            SceneRenderer::new().threads(),
        ),
        format!(
            "- first frame: the encoder's full redraw (clear + every non-blank cell), in its own column and in no \
             mean or median; means (bytes) and medians (times, one sample per frame) are over the {frames} frames \
             after it"
        ),
        "- naive: `naive_full_frame`, every cell with an SGR naming both colours; delta: `Encoder::encode` against \
         the frame before"
            .to_owned(),
        format!(
            "- goals: mean delta ≤ {:.0}% of mean naive; median encode < {encode_goal} ms at {goal_cols}x{goal_rows}",
            GOAL_DELTA_SHARE * 100.0
        ),
        String::new(),
        "| size | colours | frames | first frame B | mean delta B | mean naive B | delta/naive | render ms | \
         encode ms | bytes goal | encode goal |"
            .to_owned(),
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|".to_owned(),
    ]
    .join("\n")
}

/// One table row.
pub fn table_row(m: &Measurement) -> String {
    let yes_no = |ok: bool| if ok { "yes" } else { "**no**" };
    format!(
        "| {}x{} | {} | {} | {} | {:.0} | {:.0} | {:.1}% | {:.3} | {:.3} | {} | {} |",
        m.cols,
        m.rows,
        m.colors.name(),
        m.frames(),
        m.first_frame_bytes,
        m.mean_delta_bytes(),
        m.mean_naive_bytes(),
        m.delta_share() * 100.0,
        m.median_render().as_secs_f64() * 1e3,
        m.median_encode().as_secs_f64() * 1e3,
        yes_no(m.meets_byte_goal()),
        m.meets_encode_goal().map_or("–", yes_no),
    )
}

/// Measures everything `report` asks for and writes the Markdown report to `out`, a row as soon as it is
/// measured; returns the measurements.
///
/// # Errors
/// [`ReportError`].
pub fn run(report: &TerminalReport, out: &mut dyn Write) -> Result<Vec<Measurement>, ReportError> {
    let scene = builtin_scene()?;
    writeln!(out, "{}", header(report, &super::machine_description()))?;
    out.flush()?;
    let mut results = Vec::new();
    for &size in &report.sizes {
        for &colors in &report.colors {
            let m = measure(&scene, size, colors, report.frames)?;
            writeln!(out, "{}", table_row(&m))?;
            out.flush()?;
            results.push(m);
        }
    }
    let bytes_met = results.iter().filter(|m| m.meets_byte_goal()).count();
    let encode: Vec<bool> = results.iter().filter_map(Measurement::meets_encode_goal).collect();
    writeln!(out)?;
    writeln!(
        out,
        "Bytes goal met in {bytes_met} of {} rows; encode goal met in {} of {} rows.",
        results.len(),
        encode.iter().filter(|&&ok| ok).count(),
        encode.len()
    )?;
    let modes = super::cell_modes::measure(&scene, report.frames)?;
    super::cell_modes::write_table(out, &modes, report.frames)?;
    let key_presses = if report.quick { 6 } else { 36 };
    let rows = super::moving_frames::measure(&scene, report.frames, key_presses)?;
    super::moving_frames::write_table(out, &rows, report.frames, key_presses)?;
    Ok(results)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> PreparedScene {
        builtin_scene().expect("built-in model")
    }

    /// The byte figures are the encoder's and `naive_full_frame`'s own lengths for the same frames, and the
    /// means and shares follow from them; times are only counted, never compared.
    #[test]
    fn byte_accounting_is_consistent() {
        let scene = scene();
        for colors in COLOR_MODES {
            let m = measure(&scene, (20, 8), colors, 3).unwrap();
            assert_eq!((m.cols, m.rows, m.colors, m.frames()), (20, 8, colors, 3));
            assert_eq!((m.naive_bytes.len(), m.render_times.len(), m.encode_times.len()), (3, 3, 3));

            // The same frames again, encoded independently.
            let mut turntable = Turntable::new(&scene, (20, 8), CellMode::HalfBlock, colors, 3);
            let mut encoder = Encoder::new();
            let first = turntable.next_frame().unwrap().grid;
            assert_eq!((first.width, first.height), (20, 8));
            let mut bytes = Vec::new();
            encoder.encode(&first, &mut bytes);
            assert!(bytes.windows(4).any(|w| w == b"\x1b[2J"), "the first frame is a full redraw");
            assert_eq!(m.first_frame_bytes, bytes.len());
            let (mut delta_total, mut naive_total) = (0, 0);
            for i in 0..3 {
                let grid = turntable.next_frame().unwrap().grid;
                let mut delta = Vec::new();
                encoder.encode(&grid, &mut delta);
                let naive = naive_full_frame(&grid).len();
                assert_eq!(m.delta_bytes[i], delta.len(), "frame {i}");
                assert_eq!(m.naive_bytes[i], naive, "frame {i}");
                assert!(!delta.is_empty() && delta.len() < naive, "frame {i}: a 120° turn changes the picture");
                delta_total += delta.len();
                naive_total += naive;
            }
            assert_eq!(m.delta_bytes.iter().sum::<usize>(), delta_total);
            assert_eq!(m.naive_bytes.iter().sum::<usize>(), naive_total);
            assert!((m.mean_delta_bytes() - delta_total as f64 / 3.0).abs() < 1e-9);
            assert!((m.mean_naive_bytes() - naive_total as f64 / 3.0).abs() < 1e-9);
            assert!((m.delta_share() - delta_total as f64 / naive_total as f64).abs() < 1e-12);
            assert_eq!(m.meets_byte_goal(), m.delta_share() <= GOAL_DELTA_SHARE);
            assert_eq!(m.meets_encode_goal(), None, "the encode goal is for 200x60 only");

            let row = table_row(&m);
            assert!(row.starts_with(&format!("| 20x8 | {} | 3 | {} |", colors.name(), m.first_frame_bytes)), "{row}");
            assert_eq!(row.matches('|').count(), 12, "{row}");
        }
    }

    #[test]
    fn medians_and_means() {
        let ms = |v: &[u64]| v.iter().map(|&x| Duration::from_millis(x)).collect::<Vec<_>>();
        assert_eq!(median(&ms(&[5, 1, 3])), Duration::from_millis(3));
        assert_eq!(median(&ms(&[4, 1, 3, 2])), Duration::from_micros(2500));
        assert_eq!(median(&[]), Duration::ZERO);
        assert_eq!(mean(&[1, 2, 6]), 3.0);
        assert_eq!(mean(&[]), 0.0);
        assert!(measure(&scene(), (20, 8), ColorMode::TrueColor, 0).is_err());
    }

    #[test]
    fn header_names_the_command_and_the_columns() {
        let header = header(&TerminalReport::quick(), "Test CPU, 2 logical CPUs");
        assert!(header.contains("`rastty-bench terminal --quick`"), "{header}");
        assert!(header.contains("Test CPU, 2 logical CPUs"));
        let columns = header.lines().rev().nth(1).unwrap();
        assert_eq!(columns.matches('|').count(), 12, "{columns}");
        assert!(TerminalReport::new(120).command_line().ends_with("--frames 120"));
    }
}
