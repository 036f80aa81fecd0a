//! Images through a terminal multiplexer: tmux keeps its own screen and drops the escape strings it does not know
//! (kitty's APC, iTerm2's OSC 1337), unless they come wrapped for pass-through and the pane allows it
//! (`set -g allow-passthrough on`, tmux 3.3 and later; <https://github.com/tmux/tmux/wiki/FAQ>).
//!
//! A wrapped string is `ESC P tmux ; S ESC \`, where `S` is the string with each ESC doubled. tmux writes `S` to
//! the terminal as it is, wherever the terminal's cursor then happens to be (not at the pane's cursor: its own
//! drawing of cells is deferred), and afterwards forgets where the cursor is. So the image's position goes inside
//! the first wrapped string as an absolute cursor move to the pane's top-left cell on the terminal. Each string is
//! wrapped on its own, so that no wrapped string outgrows tmux's input buffer, however large the image.
//!
//! kitty's images can also be shown by text instead ([`Passthrough::TmuxPlaceholders`]): the image goes through
//! the pass-through with a virtual placement and no position, and the pane's cells hold kitty's Unicode
//! placeholders ([`crate::screen::image_placeholder`]), which tmux keeps with the pane's text. So the image follows
//! the pane when it moves, goes when another window is shown and comes back with it, and is clipped with the pane;
//! an image placed by position stays where it was put until the viewer draws again.
//!
//! Sixel is not wrapped: tmux 3.4 and later, built with Sixel, draw it themselves into the pane, and say so in their
//! device attributes; other builds answer without Sixel, so the viewer does not send it.

use std::io::Write;

/// The terminal the viewer's image strings go to: directly, or through tmux.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Passthrough {
    /// Straight to the terminal; the image starts at the top-left cell of the screen.
    #[default]
    Direct,
    /// Through tmux's pass-through, to the terminal tmux runs in; the pane's top-left cell is at `column`, `row`
    /// (from 0) of that terminal.
    Tmux {
        /// The pane's first column on the terminal.
        column: u16,
        /// The pane's first row on the terminal.
        row: u16,
    },
    /// Through tmux's pass-through, a kitty image shown by Unicode placeholders in the pane's cells, whose
    /// foreground colour names the image: image `image_id` (a 256-colour index from 16 to 255, so that tmux passes
    /// it on unchanged). Its place is the pane's, wherever tmux shows it.
    TmuxPlaceholders {
        /// The image's id, the placeholders' foreground colour.
        image_id: u8,
    },
}

impl Passthrough {
    /// Where the image's top-left cell is on the terminal that draws it (column, row, from 0); `None` for an image
    /// placed by placeholders, whose place is the placeholders'.
    pub const fn origin(self) -> Option<(u16, u16)> {
        match self {
            Passthrough::Direct => Some((0, 0)),
            Passthrough::Tmux { column, row } => Some((column, row)),
            Passthrough::TmuxPlaceholders { .. } => None,
        }
    }

    /// Appends what `write` writes so that it reaches the terminal: straight into `out`, or (through tmux) into a
    /// buffer of its own first, then wrapped ([`Self::write`]).
    pub fn write_with(self, out: &mut Vec<u8>, write: impl FnOnce(&mut Vec<u8>)) {
        if self == Passthrough::Direct {
            write(out);
            return;
        }
        let mut bytes = Vec::new();
        write(&mut bytes);
        self.write(out, &bytes);
    }

    /// Appends `bytes` (escape strings, each ended by ST or BEL, and cursor moves before them) so that they
    /// reach the terminal: as they are, or each string wrapped for tmux with what precedes it.
    pub fn write(self, out: &mut Vec<u8>, bytes: &[u8]) {
        if self == Passthrough::Direct {
            out.extend_from_slice(bytes);
            return;
        }
        let mut rest = bytes;
        while !rest.is_empty() {
            let end = string_end(rest).unwrap_or(rest.len());
            let _ = write!(out, "\x1bPtmux;");
            for &byte in &rest[..end] {
                if byte == 0x1b {
                    out.push(0x1b);
                }
                out.push(byte);
            }
            out.extend_from_slice(b"\x1b\\");
            rest = &rest[end..];
        }
    }
}

/// The length of `bytes` up to and with the first string terminator: ST (`ESC \`) or BEL.
fn string_end(bytes: &[u8]) -> Option<usize> {
    bytes.iter().enumerate().find_map(|(i, &byte)| match byte {
        0x07 => Some(i + 1),
        b'\\' if i > 0 && bytes[i - 1] == 0x1b => Some(i + 1),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direct_bytes_are_unchanged() {
        let mut out = Vec::new();
        Passthrough::Direct.write(&mut out, b"\x1b[1;1H\x1b_Ga=T;AAAA\x1b\\");
        assert_eq!(out, b"\x1b[1;1H\x1b_Ga=T;AAAA\x1b\\");
        assert_eq!(Passthrough::Direct.origin(), Some((0, 0)));
    }

    #[test]
    fn each_string_is_wrapped_with_its_escapes_doubled() {
        let mut out = Vec::new();
        let tmux = Passthrough::Tmux { column: 40, row: 2 };
        tmux.write(&mut out, b"\x1b[3;41H\x1b_Gm=1;AA\x1b\\\x1b_Gm=0;BB\x1b\\\x1b]1337;File=:CC\x07");
        let expected: &[u8] = b"\x1bPtmux;\x1b\x1b[3;41H\x1b\x1b_Gm=1;AA\x1b\x1b\\\x1b\\\
            \x1bPtmux;\x1b\x1b_Gm=0;BB\x1b\x1b\\\x1b\\\
            \x1bPtmux;\x1b\x1b]1337;File=:CC\x07\x1b\\";
        assert_eq!(out, expected, "{}", String::from_utf8_lossy(&out).escape_debug());
        assert_eq!(tmux.origin(), Some((40, 2)));
        // Placeholders: the same wrapping, no position.
        let placeholders = Passthrough::TmuxPlaceholders { image_id: 42 };
        let mut wrapped = Vec::new();
        placeholders.write(&mut wrapped, b"\x1b_Gm=0;BB\x1b\\");
        assert_eq!(wrapped, b"\x1bPtmux;\x1b\x1b_Gm=0;BB\x1b\x1b\\\x1b\\");
        assert_eq!(placeholders.origin(), None);
    }
}
