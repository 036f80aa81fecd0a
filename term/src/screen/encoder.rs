//! The frame encoder: the bytes that turn what the terminal shows into the next cell grid, sending only
//! the cells that changed.

use super::cell::Cell;
use super::cell_grid::CellGrid;
use super::cursor_move::CursorMove;
use super::image_placeholder::{self, PLACEHOLDER};
use super::sgr::{MAX_SGR_LEN, Pen, SGR_RESET, sgr_change_len, write_sgr_change};
use super::tolerance::Tolerance;

/// Begin synchronized output (DEC private mode 2026): the terminal holds the screen until [`SYNC_END`].
pub const SYNC_BEGIN: &[u8] = b"\x1b[?2026h";
/// End synchronized output.
pub const SYNC_END: &[u8] = b"\x1b[?2026l";
/// Erase the whole screen (ED 2), in the current background colour, hence sent after an attribute reset.
pub const CLEAR_SCREEN: &[u8] = b"\x1b[2J";

/// Turns a sequence of cell grids into terminal output, each frame as a delta against the one before.
///
/// The encoder remembers the grid it last sent. [`Encoder::encode`] then compares the next grid cell by
/// cell and writes only the changed cells, moving the cursor across unchanged stretches by the cheapest
/// of absolute CUP, column CHA, cursor-forward CUF, or re-sending the skipped cells. Colours go out as one
/// SGR per change that names only the colours that differ from the last SGR sent.
///
/// Assumptions about the terminal between frames: the encoder leaves SGR attributes reset after every
/// frame and expects them still reset at the start of the next; it never assumes where the cursor is at
/// the start of a frame. Output that breaks the first assumption, or that scrolls or overwrites the
/// screen, must be followed by [`Encoder::invalidate`].
#[derive(Clone, Debug, Default)]
pub struct Encoder {
    /// What the terminal shows, when `valid`.
    shown: CellGrid,
    valid: bool,
}

impl Encoder {
    /// An encoder whose first frame is a full redraw.
    pub fn new() -> Self {
        Self::default()
    }

    /// Forgets what the terminal shows, so the next frame is a full redraw (clear + every cell).
    pub fn invalidate(&mut self) {
        self.valid = false;
    }

    /// Records that the terminal shows a `width` x `height` grid of blank cells, as after an image was drawn over
    /// all of it: the next frame draws its cells that are not blank, and neither clears the screen nor blanks a
    /// cell (which would erase the image).
    pub fn assume_blank(&mut self, width: usize, height: usize) {
        self.shown.reset(width, height, Cell::BLANK);
        self.valid = true;
    }

    /// The grid the terminal shows as far as the encoder knows, or `None` before the first frame and after
    /// [`Encoder::invalidate`].
    pub fn shown(&self) -> Option<&CellGrid> {
        self.valid.then_some(&self.shown)
    }

    /// Appends to `out` the bytes that change the terminal from the last encoded frame to `next`.
    ///
    /// The first frame, a frame whose size differs from the last one, and the first frame after
    /// [`Encoder::invalidate`] are full redraws: reset attributes, clear the screen, draw every cell that is
    /// not [`Cell::BLANK`]. Any non-empty output is bracketed by [`SYNC_BEGIN`] / [`SYNC_END`] and leaves the
    /// attributes reset. When nothing changed, nothing at all is appended. Never writes `\n` or `\r`; a cell
    /// character that is not [`Cell::is_safe_char`] is sent as [`super::cell::REPLACEMENT_CHAR`].
    ///
    /// # Panics
    /// If `next.cells.len() != next.width * next.height`.
    pub fn encode(&mut self, next: &CellGrid, out: &mut Vec<u8>) {
        self.encode_within(next, Tolerance::EXACT, out);
    }

    /// As [`Encoder::encode`], but a shown cell that `tolerance` accepts for the wanted one is left as it is, and
    /// a cell that is sent goes out as [`Tolerance::cheaper`] makes it; the encoder remembers what was shown, so a
    /// later exact frame sends the difference.
    ///
    /// # Panics
    /// If `next.cells.len() != next.width * next.height`.
    pub fn encode_within(&mut self, next: &CellGrid, tolerance: Tolerance, out: &mut Vec<u8>) {
        self.encode_frame(next, tolerance, usize::MAX, out);
    }

    /// As [`Encoder::encode`], but stops drawing cells once `out` has grown by `limit` bytes (it may go over by
    /// one cell and the frame's closing bytes, and always draws at least one changed cell); the cells not drawn
    /// stay as they were, and a later frame draws them. Returns true when every changed cell was drawn.
    ///
    /// # Panics
    /// If `next.cells.len() != next.width * next.height`.
    pub fn encode_limited(&mut self, next: &CellGrid, limit: usize, out: &mut Vec<u8>) -> bool {
        self.encode_frame(next, Tolerance::EXACT, limit, out)
    }

    fn encode_frame(&mut self, next: &CellGrid, tolerance: Tolerance, limit: usize, out: &mut Vec<u8>) -> bool {
        assert_eq!(next.cells.len(), next.width * next.height, "malformed {}x{} grid", next.width, next.height);
        let end = out.len().saturating_add(limit);
        let mut frame =
            FrameWriter { out, pen: Pen::DEFAULT, cursor: None, started: false, width: next.width, end, drawn: false };
        if !self.valid || !self.shown.same_size(next) {
            frame.begin();
            frame.out.extend_from_slice(SGR_RESET);
            frame.out.extend_from_slice(CLEAR_SCREEN);
            self.shown.reset(next.width, next.height, Cell::BLANK);
        }
        let mut complete = true;
        if next.width > 0 {
            let rows = self.shown.cells.chunks_exact_mut(next.width).zip(next.rows());
            for (row, (shown, wanted)) in rows.enumerate() {
                if shown != wanted && !frame.draw_row_changes(row, shown, wanted, tolerance) {
                    complete = false;
                    break;
                }
            }
        }
        frame.finish();
        self.valid = true;
        complete
    }
}

/// The state of one frame being written: what the terminal's pen and cursor are after the bytes so far.
struct FrameWriter<'a> {
    out: &'a mut Vec<u8>,
    pen: Pen,
    /// `None` when unknown, including after the last column (where terminals differ about pending wraps).
    cursor: Option<(usize, usize)>,
    started: bool,
    width: usize,
    /// No cell is started once `out` is this long and one cell was drawn (so every frame makes progress).
    end: usize,
    drawn: bool,
}

impl FrameWriter<'_> {
    fn begin(&mut self) {
        if !self.started {
            self.out.extend_from_slice(SYNC_BEGIN);
            self.started = true;
        }
    }

    fn finish(&mut self) {
        if self.started {
            write_sgr_change(self.out, self.pen, Pen::DEFAULT);
            self.out.extend_from_slice(SYNC_END);
        }
    }

    /// Draws the cells of `wanted` that `tolerance` does not accept from `shown` (one row), updating `shown` to
    /// what the row then shows.
    /// Returns false if it stopped at the byte limit before the end of the row.
    fn draw_row_changes(&mut self, row: usize, shown: &mut [Cell], wanted: &[Cell], tolerance: Tolerance) -> bool {
        self.begin();
        for col in 0..wanted.len() {
            if !tolerance.accepts(&shown[col], &wanted[col]) {
                if self.drawn && self.out.len() >= self.end {
                    return false;
                }
                let cell = tolerance.cheaper(&wanted[col]);
                self.go_to(row, col, shown, wanted);
                self.put(&cell, row, col);
                shown[col] = cell;
            }
        }
        true
    }

    /// Puts the cursor on `(row, col)` by the cheapest means. Cells left of `col` may be re-sent on the way
    /// (from `wanted`, which `shown` then records).
    #[inline]
    fn go_to(&mut self, row: usize, col: usize, shown: &mut [Cell], wanted: &[Cell]) {
        let Some((at_row, at_col)) = self.cursor else {
            CursorMove::Position { row, col }.write(self.out);
            self.cursor = Some((row, col));
            return;
        };
        if (at_row, at_col) == (row, col) {
            return;
        }
        let jump = CursorMove::cheapest(self.cursor, row, col);
        if at_row == row && at_col < col {
            let target = Pen::of(&wanted[col]);
            let budget = jump.len() + sgr_change_len(self.pen, target);
            if resend_cost(&wanted[at_col..col], self.pen, target, budget).is_some() {
                for (at, (shown, cell)) in shown[at_col..col].iter_mut().zip(&wanted[at_col..col]).enumerate() {
                    self.put(cell, row, at_col + at);
                    *shown = *cell;
                }
                return;
            }
        }
        jump.write(self.out);
        self.cursor = Some((row, col));
    }

    /// Writes one cell at the cursor, which is at `row`, `col`, and advances it. An image placeholder is followed by
    /// the marks of its place ([`image_placeholder::write_marks`]), which is its place on the grid: the image starts
    /// at the top-left cell.
    #[inline]
    fn put(&mut self, cell: &Cell, row: usize, col: usize) {
        // One reservation per cell keeps the pushes below free of reallocation.
        self.out.reserve(MAX_SGR_LEN + 4 + image_placeholder::MAX_MARKS_LEN);
        self.drawn = true;
        let pen = Pen::of(cell);
        write_sgr_change(self.out, self.pen, pen);
        self.pen = pen;
        let ch = cell.safe_ch();
        if ch.is_ascii() {
            self.out.push(ch as u8);
        } else {
            let mut utf8 = [0u8; 4];
            for &b in ch.encode_utf8(&mut utf8).as_bytes() {
                self.out.push(b);
            }
            if ch == PLACEHOLDER {
                image_placeholder::write_marks(self.out, row, col, self.width);
            }
        }
        self.cursor = match self.cursor {
            Some((row, col)) if col + 1 < self.width => Some((row, col + 1)),
            _ => None,
        };
    }
}

/// What re-sending `cells` from pen `pen` and then switching to `target` costs, if less than `budget`.
#[inline]
fn resend_cost(cells: &[Cell], mut pen: Pen, target: Pen, budget: usize) -> Option<usize> {
    let mut cost = 0;
    for cell in cells {
        let next = Pen::of(cell);
        cost += sgr_change_len(pen, next) + sent_len(cell);
        pen = next;
        if cost >= budget {
            return None;
        }
    }
    cost += sgr_change_len(pen, target);
    (cost < budget).then_some(cost)
}

/// The bytes of a cell's character as [`FrameWriter::put`] sends it, at most (a placeholder's marks vary with its
/// place).
#[inline]
fn sent_len(cell: &Cell) -> usize {
    match cell.safe_ch() {
        PLACEHOLDER => PLACEHOLDER.len_utf8() + image_placeholder::MAX_MARKS_LEN,
        ch => ch.len_utf8(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::screen::color::Color;

    fn encode(encoder: &mut Encoder, grid: &CellGrid) -> String {
        let mut out = Vec::new();
        encoder.encode(grid, &mut out);
        String::from_utf8(out).unwrap()
    }

    const RED: Color = Color::Rgb(255, 0, 0);
    const BLUE: Color = Color::Indexed(21);

    #[test]
    fn first_frame_clears_and_skips_blank_cells() {
        let mut grid = CellGrid::blank(3, 2);
        *grid.get_mut(1, 2) = Cell::new('▀', RED, BLUE);
        let bytes = encode(&mut Encoder::new(), &grid);
        assert_eq!(bytes, "\x1b[?2026h\x1b[0m\x1b[2J\x1b[2;3H\x1b[38;2;255;0;0;48;5;21m▀\x1b[0m\x1b[?2026l");
    }

    #[test]
    fn unchanged_frame_is_empty() {
        let mut encoder = Encoder::new();
        let grid = CellGrid::filled(4, 3, Cell::new('▀', RED, BLUE));
        assert!(!encode(&mut encoder, &grid).is_empty());
        assert_eq!(encode(&mut encoder, &grid), "");
        encoder.invalidate();
        assert!(encode(&mut encoder, &grid).contains("\x1b[2J"));
    }

    #[test]
    fn single_skipped_cell_is_resent_when_cheaper() {
        let base = CellGrid::filled(8, 1, Cell::new('#', RED, Color::Default));
        let mut encoder = Encoder::new();
        encode(&mut encoder, &base);
        let mut next = base.clone();
        next.get_mut(0, 2).ch = '@';
        next.get_mut(0, 4).ch = '@';
        // Re-sending the '#' between (1 byte) beats ESC[C (3 bytes).
        assert_eq!(encode(&mut encoder, &next), "\x1b[?2026h\x1b[1;3H\x1b[38;2;255;0;0m@#@\x1b[0m\x1b[?2026l");
    }

    #[test]
    fn longer_gaps_use_cursor_forward_and_rows_use_cup() {
        let base = CellGrid::filled(30, 2, Cell::new('▀', RED, BLUE));
        let mut encoder = Encoder::new();
        encode(&mut encoder, &base);
        let mut next = base.clone();
        next.get_mut(0, 1).ch = ' ';
        next.get_mut(0, 5).ch = ' ';
        next.get_mut(1, 0).ch = ' ';
        let expected = "\x1b[?2026h\x1b[1;2H\x1b[38;2;255;0;0;48;5;21m \x1b[3C \x1b[2H \x1b[0m\x1b[?2026l";
        assert_eq!(encode(&mut encoder, &next), expected);
    }

    #[test]
    fn resend_is_priced_with_its_colour_changes() {
        // The skipped cell has another colour, so re-sending it costs an SGR each way: CUF wins.
        let mut base = CellGrid::filled(6, 1, Cell::new('#', RED, Color::Default));
        base.get_mut(0, 2).fg = BLUE;
        let mut encoder = Encoder::new();
        encode(&mut encoder, &base);
        let mut next = base.clone();
        next.get_mut(0, 1).ch = '@';
        next.get_mut(0, 3).ch = '@';
        assert_eq!(encode(&mut encoder, &next), "\x1b[?2026h\x1b[1;2H\x1b[38;2;255;0;0m@\x1b[C@\x1b[0m\x1b[?2026l");
    }

    #[test]
    fn control_characters_never_reach_the_terminal() {
        let mut grid = CellGrid::blank(3, 1);
        grid.get_mut(0, 0).ch = '\x1b';
        grid.get_mut(0, 1).ch = '\n';
        let bytes = encode(&mut Encoder::new(), &grid);
        assert!(bytes.ends_with("\x1b[H??\x1b[?2026l"), "{bytes:?}");
    }

    #[test]
    fn image_placeholders_carry_their_row_and_column() {
        let mut grid = CellGrid::blank(4, 2);
        for (row, col) in [(0, 0), (0, 1), (1, 1), (1, 2), (1, 3)] {
            *grid.get_mut(row, col) = Cell::image_placeholder(42);
        }
        let mut encoder = Encoder::new();
        let bytes = encode(&mut encoder, &grid);
        let p = "\u{10EEEE}";
        let (m0, m1, m2) = ("\u{0305}", "\u{030D}", "\u{030E}");
        // The last column's placeholder goes without marks (the piece after its neighbour's).
        let expected = format!(
            "\x1b[?2026h\x1b[0m\x1b[2J\x1b[H\x1b[38;5;42m{p}{m0}{m0}{p}{m0}{m1}\x1b[2;2H{p}{m1}{m1}{p}{m1}{m2}{p}\x1b[0m\x1b[?2026l"
        );
        assert_eq!(bytes, expected);
        // A placeholder between two changed cells costs more to re-send than a cursor move over it.
        let mut next = grid.clone();
        next.get_mut(0, 0).ch = 'x';
        next.get_mut(0, 2).ch = 'y';
        let bytes = encode(&mut encoder, &next);
        assert_eq!(bytes, "\x1b[?2026h\x1b[H\x1b[38;5;42mx\x1b[C\x1b[0my\x1b[?2026l");
    }
}
