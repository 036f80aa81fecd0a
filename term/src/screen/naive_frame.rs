//! The naive way to send a frame, kept as the baseline that the encoder's byte counts are compared with.

use super::cell_grid::CellGrid;
use super::cursor_move::CursorMove;
use super::sgr::{Pen, SGR_RESET, write_full_sgr};

/// Every cell of `grid` with an SGR naming both its colours, and an absolute cursor position at the start
/// of each row; then an attribute reset. No clear, no synchronized-output brackets, no `\n`.
pub fn naive_full_frame(grid: &CellGrid) -> Vec<u8> {
    let mut out = Vec::with_capacity(grid.cells.len() * 24);
    for (row, cells) in grid.rows().enumerate() {
        CursorMove::Position { row, col: 0 }.write(&mut out);
        for cell in cells {
            write_full_sgr(&mut out, Pen::of(cell));
            let mut utf8 = [0u8; 4];
            out.extend_from_slice(cell.safe_ch().encode_utf8(&mut utf8).as_bytes());
        }
    }
    out.extend_from_slice(SGR_RESET);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::screen::cell::Cell;
    use crate::screen::color::Color;

    #[test]
    fn every_cell_carries_both_colours() {
        let grid = CellGrid::filled(2, 2, Cell::new('▀', Color::Indexed(3), Color::Default));
        let expected = "\x1b[H\x1b[33;49m▀\x1b[33;49m▀\x1b[2H\x1b[33;49m▀\x1b[33;49m▀\x1b[0m";
        assert_eq!(String::from_utf8(naive_full_frame(&grid)).unwrap(), expected);
    }
}
