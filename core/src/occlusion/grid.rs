//! The occlusion on a grid of cells, one per 2x2 block of pixels, filtered across neighbouring cells and
//! interpolated back to every pixel, a strip of columns at a time.
//!
//! Cell `(i, j)` is pixel `(2i, 2j)`: its occlusion is searched there ([`Kernel::cell`]), each of the four cells
//! of a 2x2 block of cells looking along directions turned a different way. A 1-2-1 tent across and then down
//! (joint bilateral: only neighbours on the same surface count) averages the four turns, and each pixel takes the
//! mean of the filtered cells at or next to it (itself, two or four of them, as bilinear interpolation at its
//! position weights them), again only those on its own surface. A pixel with none on its surface searches for
//! itself. Everything a cell or a pixel computes depends on frame coordinates and depths only.

use super::cell::Cell;
use super::frame::DepthFrame;
use super::horizon::Kernel;
use super::{AmbientOcclusion, darken};
use crate::color::ShadingSpace;
use crate::math::float;

/// Cells across one strip of the frame: bounds the rows of cells [`Grid`] holds to a few kilobytes of stack.
const STRIP: usize = 64;

/// Cells in a row of a strip: the strip's, the one after it (its last pixels interpolate towards it), and one
/// more on each side for the filter across.
const ROW: usize = STRIP + 3;

/// Cell rows above and below a pixel's that its value depends on: the one it interpolates towards, and one more
/// on each side for the filter down. Each is two pixel rows, and the pixel may be the second of its own.
pub(super) const ROWS_AROUND: u32 = 3;

/// A row of cells of one strip, from the cell before the strip's first.
type Row = [Cell; ROW];

/// The cells of one strip of columns, computed a row at a time as the pixel rows going down need them.
pub(super) struct Grid<'a> {
    /// The search at one pixel.
    kernel: &'a Kernel,
    /// The depth it searches.
    frame: &'a DepthFrame<'a>,
    /// How far apart in view-space depth two points may be and still count as one surface: the radius.
    tolerance: f32,
    /// How much of the occlusion darkens a pixel ([`AmbientOcclusion::strength`]).
    strength: f32,
    /// Where it darkens ([`AmbientOcclusion::space`]).
    space: ShadingSpace,
    /// The strip's first cell column.
    first: i32,
    /// Rows filtered across, by cell row modulo 3.
    across: [Row; 3],
    /// The cell row each of `across` holds, if any.
    across_rows: [Option<i32>; 3],
    /// Rows filtered across and down, by cell row modulo 2.
    filtered: [Row; 2],
    /// The cell row each of `filtered` holds, if any.
    filtered_rows: [Option<i32>; 2],
}

impl<'a> Grid<'a> {
    /// An empty grid for searching `frame` with `kernel`, darkening as `settings` say; [`Grid::strip`] starts
    /// each strip.
    pub(super) fn new(kernel: &'a Kernel, frame: &'a DepthFrame<'a>, settings: &AmbientOcclusion) -> Self {
        Self {
            kernel,
            frame,
            tolerance: settings.radius,
            strength: settings.strength,
            space: settings.space,
            first: 0,
            across: [[Cell::NONE; ROW]; 3],
            across_rows: [None; 3],
            filtered: [[Cell::NONE; ROW]; 2],
            filtered_rows: [None; 2],
        }
    }

    /// Starts the strip of [`STRIP`] cell columns from `first`, pixel columns `2 * first` on.
    pub(super) fn strip(&mut self, first: u32) {
        self.first = first as i32;
        self.across_rows = [None; 3];
        self.filtered_rows = [None; 2];
    }

    /// The strip's first cell columns, one strip after another across a frame `width` pixels wide.
    pub(super) fn strips(width: u32) -> impl Iterator<Item = u32> {
        (0..width.div_ceil(2)).step_by(STRIP)
    }

    /// Darkens the strip's pixels of row `y`, `line` being the whole row.
    pub(super) fn darken_row(&mut self, line: &mut [u32], y: i32) {
        let j = y >> 1;
        let odd_row = y & 1 == 1;
        let top = self.filtered_row(j);
        let bottom = if odd_row { self.filtered_row(j + 1) } else { top };
        let (top, bottom) = (&self.filtered[top], &self.filtered[bottom]);
        let frame = self.frame;
        let row = frame.row_z_w(y);
        let depth = frame.row(y);
        let start = 2 * self.first;
        let end = (start + 2 * STRIP as i32).min(frame.width);
        for x in start..end {
            let Some(d) = Some(depth[x as usize]).filter(|&d| d < 1.0) else {
                continue;
            };
            // The cell at or before the pixel, in the row's indices.
            let i = ((x >> 1) - self.first + 1) as usize;
            let occlusion = match (x & 1 == 1, odd_row) {
                // The cell's own pixel.
                (false, false) => top[i].occlusion,
                (true, false) => self.interpolated(x, y, d, row, &[top[i], top[i + 1]]),
                (false, true) => self.interpolated(x, y, d, row, &[top[i], bottom[i]]),
                (true, true) => self.interpolated(x, y, d, row, &[top[i], top[i + 1], bottom[i], bottom[i + 1]]),
            };
            if occlusion > 0.0 {
                let factor = float::clamp(1.0 - self.strength * occlusion, 0.0, 1.0);
                let pixel = &mut line[x as usize];
                *pixel = darken(*pixel, factor, self.space);
            }
        }
    }

    /// The occlusion at pixel `(x, y)` (depth `d`, row terms `row`) that is not a cell's own: the mean of `cells`,
    /// those around it, over the ones on its surface; its own search if none is; negative behind the camera.
    #[inline(always)]
    fn interpolated<const N: usize>(&self, x: i32, y: i32, d: f32, row: (f32, f32), cells: &[Cell; N]) -> f32 {
        let (zw, w) = self.frame.z_w(row, x, d);
        if w.is_nan() || w <= 0.0 {
            return Cell::UNKNOWN;
        }
        // |z_cell - z| <= radius, multiplied through by w > 0.
        let tolerance = self.tolerance * w;
        let (mut sum, mut count) = (0.0, 0.0);
        for cell in cells {
            let on = (cell.occlusion >= 0.0) & (float::abs(cell.z * w - zw) <= tolerance);
            let weight = if on { 1.0 } else { 0.0 };
            sum += weight * cell.occlusion;
            count += weight;
        }
        if count == 0.0 { self.kernel.cell(self.frame, x, y).occlusion } else { sum / count }
    }

    /// Which of `filtered` holds cell row `j`, filtering it first unless it is held.
    fn filtered_row(&mut self, j: i32) -> usize {
        let slot = j.rem_euclid(2) as usize;
        if self.filtered_rows[slot] != Some(j) {
            let [above, at, below] = [j - 1, j, j + 1].map(|j| self.across_row(j));
            for i in 1..ROW - 1 {
                let sides = [self.across[above][i], self.across[below][i]];
                self.filtered[slot][i] = self.across[at][i].filtered(sides, self.tolerance);
            }
            self.filtered_rows[slot] = Some(j);
        }
        slot
    }

    /// Which of `across` holds cell row `j`, searching and filtering it first unless it is held.
    fn across_row(&mut self, j: i32) -> usize {
        let slot = j.rem_euclid(3) as usize;
        if self.across_rows[slot] != Some(j) {
            let raw: Row =
                core::array::from_fn(|i| self.kernel.cell(self.frame, 2 * (self.first + i as i32 - 1), 2 * j));
            for i in 1..ROW - 1 {
                self.across[slot][i] = raw[i].filtered([raw[i - 1], raw[i + 1]], self.tolerance);
            }
            self.across_rows[slot] = Some(j);
        }
        slot
    }
}
