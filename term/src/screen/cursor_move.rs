//! Cursor-movement sequences (absolute CUP, column-absolute CHA, cursor-forward CUF), their byte lengths,
//! and the cheapest of them for a given jump.
//!
//! Positions here are 0-based; the sequences carry them 1-based. No movement ever uses `\n` or `\r`.

use super::decimal::{decimal_len, write_decimal};

/// A way to move the cursor to a target cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum CursorMove {
    /// `ESC[row;colH` (shortened to `ESC[rowH` in column 0 and `ESC[H` at the origin).
    Position { row: usize, col: usize },
    /// `ESC[colG` on the current row (`ESC[G` for column 0).
    Column { col: usize },
    /// `ESC[nC` (`ESC[C` for one column).
    Forward { by: usize },
}

impl CursorMove {
    /// The cheapest sequence that takes the cursor from `from` (`None`: unknown) to `(row, col)`.
    #[inline]
    pub fn cheapest(from: Option<(usize, usize)>, row: usize, col: usize) -> CursorMove {
        let position = CursorMove::Position { row, col };
        let Some((from_row, from_col)) = from else {
            return position;
        };
        if from_row != row {
            return position;
        }
        let column = CursorMove::Column { col };
        let mut best = if column.len() < position.len() { column } else { position };
        if from_col < col {
            let forward = CursorMove::Forward { by: col - from_col };
            if forward.len() <= best.len() {
                best = forward;
            }
        }
        best
    }

    /// Bytes [`CursorMove::write`] appends.
    #[inline]
    pub fn len(self) -> usize {
        match self {
            CursorMove::Position { row: 0, col: 0 } => 3,
            CursorMove::Position { row, col: 0 } => 3 + decimal_len(row as u32 + 1),
            CursorMove::Position { row, col } => 4 + decimal_len(row as u32 + 1) + decimal_len(col as u32 + 1),
            CursorMove::Column { col: 0 } => 3,
            CursorMove::Column { col } => 3 + decimal_len(col as u32 + 1),
            CursorMove::Forward { by: 1 } => 3,
            CursorMove::Forward { by } => 3 + decimal_len(by as u32),
        }
    }

    /// Appends the escape sequence.
    #[inline]
    pub fn write(self, out: &mut Vec<u8>) {
        out.extend_from_slice(b"\x1b[");
        match self {
            CursorMove::Position { row, col } => {
                if row > 0 || col > 0 {
                    write_decimal(out, row as u32 + 1);
                }
                if col > 0 {
                    out.push(b';');
                    write_decimal(out, col as u32 + 1);
                }
                out.push(b'H');
            }
            CursorMove::Column { col } => {
                if col > 0 {
                    write_decimal(out, col as u32 + 1);
                }
                out.push(b'G');
            }
            CursorMove::Forward { by } => {
                if by > 1 {
                    write_decimal(out, by as u32);
                }
                out.push(b'C');
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes(m: CursorMove) -> String {
        let mut out = Vec::new();
        m.write(&mut out);
        assert_eq!(out.len(), m.len(), "{m:?}");
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn sequences_are_one_based_and_shortened() {
        assert_eq!(bytes(CursorMove::Position { row: 0, col: 0 }), "\x1b[H");
        assert_eq!(bytes(CursorMove::Position { row: 4, col: 0 }), "\x1b[5H");
        assert_eq!(bytes(CursorMove::Position { row: 0, col: 9 }), "\x1b[1;10H");
        assert_eq!(bytes(CursorMove::Position { row: 59, col: 199 }), "\x1b[60;200H");
        assert_eq!(bytes(CursorMove::Column { col: 0 }), "\x1b[G");
        assert_eq!(bytes(CursorMove::Column { col: 99 }), "\x1b[100G");
        assert_eq!(bytes(CursorMove::Forward { by: 1 }), "\x1b[C");
        assert_eq!(bytes(CursorMove::Forward { by: 12 }), "\x1b[12C");
    }

    #[test]
    fn cheapest_prefers_relative_moves_on_the_same_row() {
        assert_eq!(CursorMove::cheapest(None, 3, 4), CursorMove::Position { row: 3, col: 4 });
        assert_eq!(CursorMove::cheapest(Some((2, 4)), 3, 4), CursorMove::Position { row: 3, col: 4 });
        assert_eq!(CursorMove::cheapest(Some((3, 1)), 3, 4), CursorMove::Forward { by: 3 });
        assert_eq!(CursorMove::cheapest(Some((30, 90)), 30, 105), CursorMove::Forward { by: 15 });
        // 150 forward costs as much as going to column 161, which is cheaper than CUP; ties go to CUF.
        assert_eq!(CursorMove::cheapest(Some((30, 10)), 30, 160), CursorMove::Forward { by: 150 });
        // CHA only ever wins going backwards.
        assert_eq!(CursorMove::cheapest(Some((30, 150)), 30, 0), CursorMove::Column { col: 0 });
        assert_eq!(CursorMove::cheapest(Some((30, 90)), 30, 5), CursorMove::Column { col: 5 });
    }
}
