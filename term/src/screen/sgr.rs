//! SGR (Select Graphic Rendition) sequences that set the foreground and background colours, and their
//! byte lengths, so the encoder can price a colour change before it writes one.

use super::cell::Cell;
use super::color::Color;
use super::decimal::{decimal_len, write_u8_decimal};

/// The colours the terminal is currently drawing with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Pen {
    /// Foreground.
    pub fg: Color,
    /// Background.
    pub bg: Color,
}

impl Pen {
    /// The state after `ESC[0m`.
    pub const DEFAULT: Pen = Pen { fg: Color::Default, bg: Color::Default };

    /// The pen that draws `cell`.
    #[inline]
    pub const fn of(cell: &Cell) -> Pen {
        Pen { fg: cell.fg, bg: cell.bg }
    }
}

/// `ESC[0m`: every attribute back to the default.
pub(crate) const SGR_RESET: &[u8] = b"\x1b[0m";

#[derive(Clone, Copy)]
enum Layer {
    Fg,
    Bg,
}

/// Length of the SGR parameter(s) for `color` on `layer` (without separators around them).
#[inline]
fn param_len(color: Color, layer: Layer) -> usize {
    match color {
        Color::Default => 2,
        Color::Indexed(n) if n < 8 => 2,
        Color::Indexed(n) if n < 16 => match layer {
            Layer::Fg => 2,
            Layer::Bg => 3,
        },
        Color::Indexed(n) => 5 + decimal_len(u32::from(n)),
        Color::Rgb(r, g, b) => 7 + decimal_len(u32::from(r)) + decimal_len(u32::from(g)) + decimal_len(u32::from(b)),
    }
}

#[inline]
fn write_param(out: &mut Vec<u8>, color: Color, layer: Layer) {
    let (digit, bright) = match layer {
        Layer::Fg => (b'3', &b"9"[..]),
        Layer::Bg => (b'4', &b"10"[..]),
    };
    match color {
        Color::Default => {
            out.push(digit);
            out.push(b'9');
        }
        Color::Indexed(n) if n < 8 => {
            out.push(digit);
            out.push(b'0' + n);
        }
        Color::Indexed(n) if n < 16 => {
            for &b in bright {
                out.push(b);
            }
            out.push(b'0' + n - 8);
        }
        Color::Indexed(n) => {
            for b in [digit, b'8', b';', b'5', b';'] {
                out.push(b);
            }
            write_u8_decimal(out, n);
        }
        Color::Rgb(r, g, b) => {
            for byte in [digit, b'8', b';', b'2', b';'] {
                out.push(byte);
            }
            write_u8_decimal(out, r);
            out.push(b';');
            write_u8_decimal(out, g);
            out.push(b';');
            write_u8_decimal(out, b);
        }
    }
}

/// Bytes [`write_sgr_change`] appends to go from `from` to `to`.
#[inline]
pub(crate) fn sgr_change_len(from: Pen, to: Pen) -> usize {
    if from == to {
        return 0;
    }
    if to == Pen::DEFAULT {
        return SGR_RESET.len();
    }
    let fg = if from.fg == to.fg { 0 } else { param_len(to.fg, Layer::Fg) };
    let bg = if from.bg == to.bg { 0 } else { param_len(to.bg, Layer::Bg) };
    let separator = usize::from(fg > 0 && bg > 0);
    3 + fg + separator + bg
}

/// The longest SGR [`write_sgr_change`] or [`write_full_sgr`] writes: `ESC[38;2;255;255;255;48;2;255;255;255m`.
pub(crate) const MAX_SGR_LEN: usize = 36;

/// Appends one SGR sequence that changes the pen from `from` to `to`, naming only the colours that differ
/// (`ESC[0m` when `to` is all defaults); nothing when they are equal.
#[inline]
pub(crate) fn write_sgr_change(out: &mut Vec<u8>, from: Pen, to: Pen) {
    if from == to {
        return;
    }
    if to == Pen::DEFAULT {
        out.extend_from_slice(SGR_RESET);
        return;
    }
    out.push(0x1b);
    out.push(b'[');
    let fg_changed = from.fg != to.fg;
    if fg_changed {
        write_param(out, to.fg, Layer::Fg);
    }
    if from.bg != to.bg {
        if fg_changed {
            out.push(b';');
        }
        write_param(out, to.bg, Layer::Bg);
    }
    out.push(b'm');
}

/// Appends one SGR sequence naming both colours of `pen`, whatever the terminal had before.
pub(crate) fn write_full_sgr(out: &mut Vec<u8>, pen: Pen) {
    out.extend_from_slice(b"\x1b[");
    write_param(out, pen.fg, Layer::Fg);
    out.push(b';');
    write_param(out, pen.bg, Layer::Bg);
    out.push(b'm');
}

#[cfg(test)]
mod tests {
    use super::*;

    fn change(from: Pen, to: Pen) -> String {
        let mut out = Vec::new();
        write_sgr_change(&mut out, from, to);
        assert_eq!(out.len(), sgr_change_len(from, to));
        String::from_utf8(out).unwrap()
    }

    fn pen(fg: Color, bg: Color) -> Pen {
        Pen { fg, bg }
    }

    #[test]
    fn only_changed_colours_are_named() {
        let a = pen(Color::Rgb(1, 22, 255), Color::Indexed(17));
        assert_eq!(change(a, a), "");
        assert_eq!(change(Pen::DEFAULT, a), "\x1b[38;2;1;22;255;48;5;17m");
        assert_eq!(change(a, pen(Color::Rgb(1, 22, 255), Color::Indexed(3))), "\x1b[43m");
        assert_eq!(change(a, pen(Color::Indexed(12), Color::Indexed(17))), "\x1b[94m");
        assert_eq!(change(a, pen(Color::Default, Color::Indexed(9))), "\x1b[39;101m");
        assert_eq!(change(a, Pen::DEFAULT), "\x1b[0m");
    }

    #[test]
    fn lengths_match_for_every_colour() {
        let mut colors = vec![Color::Default, Color::Rgb(0, 0, 0), Color::Rgb(255, 100, 9), Color::Rgb(10, 200, 99)];
        colors.extend((0..=255).map(Color::Indexed));
        for &fg in &colors {
            for &bg in &colors[..20] {
                change(Pen::DEFAULT, pen(fg, bg));
                change(pen(bg, fg), pen(fg, bg));
                change(pen(fg, Color::Default), pen(fg, bg));
            }
        }
    }

    #[test]
    fn longest_sequence_fits_the_bound() {
        let white = Color::Rgb(255, 255, 255);
        let mut out = Vec::new();
        write_full_sgr(&mut out, pen(white, white));
        assert_eq!(out.len(), MAX_SGR_LEN);
        assert_eq!(sgr_change_len(Pen::DEFAULT, pen(white, white)), MAX_SGR_LEN);
    }

    #[test]
    fn full_sgr_names_both() {
        let mut out = Vec::new();
        write_full_sgr(&mut out, Pen::DEFAULT);
        assert_eq!(out, b"\x1b[39;49m");
    }
}
