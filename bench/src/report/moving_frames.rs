//! `rastty-bench terminal`, second table: what each tolerance of the viewer's frame writer saves on a moving
//! picture, and what it costs in accuracy.
//!
//! On a slow link the writer sends a moving frame with the smallest tolerance of [`TOLERANCES`] whose bytes fit
//! the link (`viewer/frame_writer.rs`). For each tolerance, the built-in model's frames at [`SIZE`] (truecolor
//! half-blocks) go through one encoder with that tolerance, as the writer would send them if it kept to it: a
//! full redraw, then each frame with [`Encoder::encode_within`]. The error is the Oklab distance (ΔE) between
//! the colour the screen then shows and the exact one, over both sides of every cell. Two motions: the turntable
//! (the report's step) and key presses (10° each, as the arrow keys turn).

use std::io::Write;

use super::error::ReportError;
use super::turntable::Turntable;
use rastty::screen::TOLERANCES;
use rastty::screen::tolerance::color_distance;
use rastty::screen::{CellGrid, CellMode, ColorMode, Encoder, Tolerance};
use rastty_scene::scene_render::PreparedScene;

/// The terminal size measured: the SSH test's (docs/terminal.md).
pub const SIZE: (u16, u16) = (120, 40);
/// Degrees an arrow key turns the model.
pub const KEY_STEP_DEGREES: f32 = 10.0;

/// One motion at one tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moving {
    /// Mean bytes per frame after the first.
    pub mean_bytes: f64,
    /// Mean ΔE between what the screen shows and the exact frame, over every frame after the first.
    pub mean_error: f64,
    /// The largest ΔE of any cell side in any frame.
    pub max_error: f32,
}

/// One table row: a tolerance, on the turntable and on key presses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ToleranceRow {
    /// The tolerance (Oklab ΔE; 0 is exact).
    pub delta_e: f32,
    /// Turntable frames.
    pub turntable: Moving,
    /// Key-press frames.
    pub keys: Moving,
}

/// Renders `frames` frames, turning the built-in model by `step` radians each (the first unturned).
fn frames(scene: &PreparedScene, frames: usize, step: f32) -> Result<Vec<CellGrid>, ReportError> {
    let mut turntable = Turntable::with_step(scene, SIZE, CellMode::HalfBlock, ColorMode::TrueColor, step);
    (0..=frames).map(|_| turntable.next_frame().map(|frame| frame.grid)).collect()
}

/// `grids` through one encoder with `tolerance` after an exact first frame.
fn moving(grids: &[CellGrid], tolerance: Tolerance) -> Moving {
    let mut encoder = Encoder::new();
    let mut bytes = Vec::new();
    let (mut total_bytes, mut total_error, mut max_error) = (0usize, 0.0f64, 0.0f32);
    let mut first = true;
    for grid in grids {
        bytes.clear();
        encoder.encode_within(grid, if first { Tolerance::EXACT } else { tolerance }, &mut bytes);
        if std::mem::take(&mut first) {
            continue;
        }
        total_bytes += bytes.len();
        let shown = encoder.shown().map_or(&[][..], |g| &g.cells[..]);
        let mut error = 0.0f64;
        for (s, w) in shown.iter().zip(&grid.cells) {
            for (a, b) in [(s.fg, w.fg), (s.bg, w.bg)] {
                // A terminal default against a colour: unknown, counted as the largest error (never in truecolor).
                let e = color_distance(a, b).unwrap_or(1.0);
                error += f64::from(e);
                max_error = max_error.max(e);
            }
        }
        total_error += error / (2 * grid.cells.len()).max(1) as f64;
    }
    let n = grids.len().saturating_sub(1).max(1) as f64;
    Moving { mean_bytes: total_bytes as f64 / n, mean_error: total_error / n, max_error }
}

/// Measures every tolerance of [`TOLERANCES`]: the turntable in `turntable_frames` steps per turn, and
/// `key_presses` presses of [`KEY_STEP_DEGREES`].
///
/// # Errors
/// [`ReportError`] when a frame cannot be drawn.
pub fn measure(
    scene: &PreparedScene,
    turntable_frames: usize,
    key_presses: usize,
) -> Result<Vec<ToleranceRow>, ReportError> {
    let step = std::f32::consts::TAU / turntable_frames.max(1) as f32;
    let turntable = frames(scene, turntable_frames, step)?;
    let keys = frames(scene, key_presses, KEY_STEP_DEGREES.to_radians())?;
    Ok(TOLERANCES
        .iter()
        .map(|&delta_e| {
            let tolerance = Tolerance::new(delta_e);
            ToleranceRow { delta_e, turntable: moving(&turntable, tolerance), keys: moving(&keys, tolerance) }
        })
        .collect())
}

/// Writes the table for `rows` (turntable of `turntable_frames` frames, `key_presses` presses).
///
/// # Errors
/// The writer's.
pub fn write_table(
    out: &mut dyn Write,
    rows: &[ToleranceRow],
    turntable_frames: usize,
    key_presses: usize,
) -> std::io::Result<()> {
    let (cols, lines) = SIZE;
    let degrees = 360.0 / turntable_frames.max(1) as f64;
    writeln!(out)?;
    writeln!(out, "### Moving frames within a tolerance, {cols}x{lines} truecolor")?;
    writeln!(out)?;
    writeln!(
        out,
        "Each tolerance (Oklab ΔE) through its own encoder: cells within it of what the screen shows are left, and a \
         sent colour goes out as a 256-colour index where that is within it. Turntable: {turntable_frames} frames of \
         {degrees:.1}°; keys: {key_presses} presses of {KEY_STEP_DEGREES}°. Error: ΔE between the screen and the \
         exact frame, mean over every cell side of every frame, and the largest."
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "| ΔE | turntable B/frame | vs exact | mean error | max error | key B/frame | vs exact | mean error | max error |"
    )?;
    writeln!(out, "|---:|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    let exact = rows.first().map_or((1.0, 1.0), |r| (r.turntable.mean_bytes, r.keys.mean_bytes));
    let share = |bytes: f64, of: f64| if of > 0.0 { bytes / of * 100.0 } else { 0.0 };
    for row in rows {
        writeln!(
            out,
            "| {:.3} | {:.0} | {:.0}% | {:.4} | {:.3} | {:.0} | {:.0}% | {:.4} | {:.3} |",
            row.delta_e,
            row.turntable.mean_bytes,
            share(row.turntable.mean_bytes, exact.0),
            row.turntable.mean_error,
            row.turntable.max_error,
            row.keys.mean_bytes,
            share(row.keys.mean_bytes, exact.1),
            row.keys.mean_error,
            row.keys.max_error,
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::turntable::builtin_scene;

    /// Exact is exact and costs the most; every error stays within its tolerance; more tolerance never costs
    /// more bytes on these frames.
    #[test]
    fn tolerances_trade_bytes_for_bounded_error() {
        let scene = builtin_scene().expect("built-in model");
        let rows = measure(&scene, 12, 3).expect("measured");
        assert_eq!(rows.len(), TOLERANCES.len());
        assert_eq!(rows[0].delta_e, 0.0);
        assert_eq!((rows[0].turntable.mean_error, rows[0].turntable.max_error), (0.0, 0.0));
        for row in &rows {
            for m in [row.turntable, row.keys] {
                assert!(m.max_error <= row.delta_e + 1e-6, "{row:?}");
                assert!(m.mean_error <= f64::from(m.max_error), "{row:?}");
                assert!(m.mean_bytes > 0.0, "{row:?}");
            }
        }
        for pair in rows.windows(2) {
            assert!(pair[1].turntable.mean_bytes <= pair[0].turntable.mean_bytes, "{pair:?}");
            assert!(pair[1].keys.mean_bytes <= pair[0].keys.mean_bytes, "{pair:?}");
        }
        let mut table = Vec::new();
        write_table(&mut table, &rows, 12, 3).expect("written");
        let table = String::from_utf8(table).expect("UTF-8");
        assert_eq!(table.lines().filter(|l| l.starts_with("| 0.")).count(), TOLERANCES.len(), "{table}");
    }
}
