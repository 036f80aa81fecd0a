//! How the viewer sends its picture: as cells, or as one image in a pixel graphics protocol.

use std::fmt;
use std::io::Write;
use std::str::FromStr;

use super::frame_palette::{Dither, Learning, reduce};
use super::passthrough::Passthrough;
use super::{iterm2, kitty, sixel};
use crate::screen::PixelFrame;

/// The image id the viewer shows its frames under (kitty), unless they are shown by placeholders
/// ([`Passthrough::TmuxPlaceholders`], which names its own).
pub const IMAGE_ID: u32 = 1;

/// The way the picture reaches the terminal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GraphicsProtocol {
    /// Character cells ([`crate::screen::CellMode`]): every terminal.
    #[default]
    Cells,
    /// The kitty graphics protocol (kitty, WezTerm, Ghostty, Konsole).
    Kitty,
    /// Sixel (xterm -ti vt340, foot, mlterm, WezTerm, Windows Terminal).
    Sixel,
    /// iTerm2's inline images (iTerm2, WezTerm).
    Iterm2,
}

/// A frame to send as an image, the cells it covers from the top-left cell, and the way it goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FrameImage {
    /// `0x00RRGGBB`, row-major.
    pub pixels: Vec<u32>,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Columns covered.
    pub columns: u16,
    /// Rows covered.
    pub rows: u16,
    /// Directly to the terminal, or through tmux (kitty and iTerm2 only: tmux draws Sixel itself, when it can; by
    /// placeholders, kitty only).
    pub passthrough: Passthrough,
}

impl GraphicsProtocol {
    /// Every protocol.
    pub const ALL: [GraphicsProtocol; 4] =
        [GraphicsProtocol::Cells, GraphicsProtocol::Kitty, GraphicsProtocol::Sixel, GraphicsProtocol::Iterm2];

    /// The name accepted by [`GraphicsProtocol::from_str`].
    pub const fn name(self) -> &'static str {
        match self {
            GraphicsProtocol::Cells => "cells",
            GraphicsProtocol::Kitty => "kitty",
            GraphicsProtocol::Sixel => "sixel",
            GraphicsProtocol::Iterm2 => "iterm2",
        }
    }

    /// The rows of a `rows`-row terminal an image may cover. Sixel and iTerm2 move the cursor below the image, so
    /// an image reaching the last row would scroll the screen: they leave it free. kitty keeps the cursor (`C=1`).
    pub const fn image_rows(self, rows: u16) -> u16 {
        match self {
            GraphicsProtocol::Sixel | GraphicsProtocol::Iterm2 => rows.saturating_sub(1),
            GraphicsProtocol::Cells | GraphicsProtocol::Kitty => rows,
        }
    }

    /// Whether an image replaces the cells under it (Sixel, iTerm2): text drawn there before is gone, and text to
    /// show over the image must be drawn after it. A kitty image lies under the text.
    pub const fn covers_text(self) -> bool {
        matches!(self, GraphicsProtocol::Sixel | GraphicsProtocol::Iterm2)
    }

    /// Whether the terminal scales an image to the cells it covers (kitty, iTerm2), so that a smaller image shows
    /// the same picture, coarser; a Sixel image is shown at its own size.
    pub const fn scaled_by_terminal(self) -> bool {
        matches!(self, GraphicsProtocol::Kitty | GraphicsProtocol::Iterm2)
    }

    /// The pixel rows an image's height must be a whole number of (Sixel draws bands of six; a last, partial band
    /// would leave its rows to the terminal).
    pub const fn row_multiple(self) -> usize {
        match self {
            GraphicsProtocol::Sixel => 6,
            _ => 1,
        }
    }

    /// Appends the bytes that show `image` from the top-left cell (nothing for [`GraphicsProtocol::Cells`]);
    /// `dither` is how a Sixel frame maps to its palette. A kitty image shown by placeholders is sent without a
    /// place: the grid's [placeholder cells](crate::screen::image_placeholder) show it.
    pub fn write_image(self, out: &mut Vec<u8>, image: &FrameImage, dither: Dither) {
        let frame = PixelFrame::new(&image.pixels, image.width, image.height);
        let (column, row) = image.passthrough.origin().unwrap_or((0, 0));
        image.passthrough.write_with(out, |bytes| match (self, image.passthrough) {
            (GraphicsProtocol::Cells, _) => {}
            (GraphicsProtocol::Kitty, Passthrough::TmuxPlaceholders { image_id }) => {
                kitty::write_virtual_frame(bytes, frame, image_id.into(), image.columns, image.rows);
            }
            (GraphicsProtocol::Kitty, _) => {
                let placement =
                    kitty::KittyPlacement { image_id: IMAGE_ID, column, row, columns: image.columns, rows: image.rows };
                kitty::write_frame(bytes, frame, &placement);
            }
            (GraphicsProtocol::Sixel, _) => {
                write_cursor_move(bytes, column, row);
                sixel::write_image(bytes, &reduce(frame, 256, dither, Learning::Quick));
            }
            (GraphicsProtocol::Iterm2, _) => {
                write_cursor_move(bytes, column, row);
                iterm2::write_image(bytes, frame, image.columns, image.rows);
            }
        });
    }

    /// Whether the terminal keeps an image it was sent, so that the same picture can be shown again by placing it
    /// ([`Self::write_placement`]) rather than sending it: kitty only.
    pub const fn keeps_images(self) -> bool {
        matches!(self, GraphicsProtocol::Kitty)
    }

    /// Appends the bytes that show again, from the top-left cell, the image last sent with [`Self::write_image`]
    /// (kitty: a placement of the image the terminal holds); nothing for a protocol that does not
    /// [keep images](Self::keeps_images), nor for an image shown by placeholders, which show it again themselves.
    pub fn write_placement(self, out: &mut Vec<u8>, image: &FrameImage) {
        let Some((column, row)) = image.passthrough.origin().filter(|_| self.keeps_images()) else { return };
        image.passthrough.write_with(out, |bytes| {
            let placement =
                kitty::KittyPlacement { image_id: IMAGE_ID, column, row, columns: image.columns, rows: image.rows };
            kitty::write_placement(bytes, &placement);
        });
    }

    /// Appends what frees the terminal's memory of the viewer's image when the viewer ends (kitty: the image is
    /// deleted; the others keep nothing once the screen is cleared), through `passthrough`.
    pub fn write_end(self, out: &mut Vec<u8>, passthrough: Passthrough) {
        if self == GraphicsProtocol::Kitty {
            let image_id = match passthrough {
                Passthrough::TmuxPlaceholders { image_id } => image_id.into(),
                Passthrough::Direct | Passthrough::Tmux { .. } => IMAGE_ID,
            };
            passthrough.write_with(out, |bytes| kitty::write_delete(bytes, image_id));
        }
    }
}

/// Appends the cursor move (CUP, 1-based) to `column`, `row` (from 0).
fn write_cursor_move(out: &mut Vec<u8>, column: u16, row: u16) {
    let _ = write!(out, "\x1b[{};{}H", u32::from(row) + 1, u32::from(column) + 1);
}

impl fmt::Display for GraphicsProtocol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The error of parsing an unknown protocol name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownGraphicsProtocol(pub String);

impl fmt::Display for UnknownGraphicsProtocol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown graphics protocol {:?} (expected cells, kitty, sixel or iterm2)", self.0)
    }
}

impl std::error::Error for UnknownGraphicsProtocol {}

impl FromStr for GraphicsProtocol {
    type Err = UnknownGraphicsProtocol;

    /// Accepts the names of [`GraphicsProtocol::name`] (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let lower = s.to_ascii_lowercase();
        Self::ALL.into_iter().find(|p| p.name() == lower).ok_or_else(|| UnknownGraphicsProtocol(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for protocol in GraphicsProtocol::ALL {
            assert_eq!(protocol.name().parse::<GraphicsProtocol>(), Ok(protocol));
        }
        assert!("png".parse::<GraphicsProtocol>().is_err());
    }

    #[test]
    fn images_start_at_the_top_left_cell() {
        let mut image = FrameImage {
            pixels: vec![0xFF0000; 12],
            width: 4,
            height: 3,
            columns: 2,
            rows: 1,
            passthrough: Passthrough::Direct,
        };
        for protocol in [GraphicsProtocol::Kitty, GraphicsProtocol::Sixel, GraphicsProtocol::Iterm2] {
            let mut out = Vec::new();
            protocol.write_image(&mut out, &image, Dither::None);
            assert!(out.starts_with(b"\x1b[1;1H"), "{protocol}");
        }
        let mut out = Vec::new();
        GraphicsProtocol::Cells.write_image(&mut out, &image, Dither::FloydSteinberg);
        GraphicsProtocol::Sixel.write_end(&mut out, Passthrough::Direct);
        assert!(out.is_empty());
        GraphicsProtocol::Kitty.write_end(&mut out, Passthrough::Direct);
        assert_eq!(out, b"\x1b_Ga=d,d=I,i=1,q=2\x1b\\");
        // Through tmux: wrapped, from the pane's top-left cell on the terminal.
        image.passthrough = Passthrough::Tmux { column: 40, row: 1 };
        out.clear();
        GraphicsProtocol::Kitty.write_image(&mut out, &image, Dither::None);
        assert!(out.starts_with(b"\x1bPtmux;\x1b\x1b[2;41H\x1b\x1b_Ga=T,"));
    }

    #[test]
    fn a_kitty_image_by_placeholders_has_no_place_and_its_own_id() {
        let image = FrameImage {
            pixels: vec![0x00FF00; 12],
            width: 4,
            height: 3,
            columns: 2,
            rows: 1,
            passthrough: Passthrough::TmuxPlaceholders { image_id: 42 },
        };
        let mut out = Vec::new();
        GraphicsProtocol::Kitty.write_image(&mut out, &image, Dither::None);
        assert!(out.starts_with(b"\x1bPtmux;\x1b\x1b_Ga=T,U=1,f=24,o=z,s=4,v=3,i=42,c=2,r=1,q=2,m=0;"), "{out:?}");
        out.clear();
        GraphicsProtocol::Kitty.write_placement(&mut out, &image);
        assert!(out.is_empty(), "the placeholders show the held image again");
        GraphicsProtocol::Kitty.write_end(&mut out, image.passthrough);
        assert_eq!(out, b"\x1bPtmux;\x1b\x1b_Ga=d,d=I,i=42,q=2\x1b\x1b\\\x1b\\");
    }
}
