//! How different a cell on the screen may look from the wanted one and still be left as it is: the knob that lets
//! the viewer send fewer bytes while the picture moves over a slow link.
//!
//! The difference is the Oklab distance (ΔE, the perceptual difference; Ottosson 2020, see [`super::oklab`]) of
//! each side's colour. A cell is left only when its character is the same and both colours are within the
//! tolerance; [`Tolerance::EXACT`] leaves only identical cells. A cell that is sent may go out with a 256-colour
//! palette index instead of its 24-bit colour where the two are within the tolerance (`38;5;n` is about half as
//! long as `38;2;r;g;b`).

use super::cell::Cell;
use super::color::Color;
use super::oklab::Oklab;
use super::palette::xterm256_rgb;
use super::palette_lut::nearest_xterm256;

/// The tolerances (Oklab ΔE) a moving frame may be sent with, tried in order until one fits the budget; the
/// bytes each gives on a turntable are in docs/terminal.md.
pub const TOLERANCES: [f32; 10] = [0.0, 0.01, 0.02, 0.035, 0.05, 0.08, 0.12, 0.2, 0.3, 0.5];

/// The largest Oklab distance (ΔE) at which a shown colour may stand for the wanted one.
#[derive(Clone, Copy, Debug, Default, PartialEq, PartialOrd)]
pub struct Tolerance(f32);

impl Tolerance {
    /// Only identical cells are alike.
    pub const EXACT: Tolerance = Tolerance(0.0);

    /// A tolerance of `delta_e` (Oklab distance; white to black is 1, one 8-bit step of a mid grey about
    /// 0.0035). Negative or NaN is [`Self::EXACT`].
    pub fn new(delta_e: f32) -> Self {
        if delta_e > 0.0 { Self(delta_e) } else { Self::EXACT }
    }

    /// The distance.
    pub fn delta_e(self) -> f32 {
        self.0
    }

    /// True when `shown` may stay on the screen where `wanted` should be.
    #[inline]
    pub fn accepts(self, shown: &Cell, wanted: &Cell) -> bool {
        if shown == wanted {
            return true;
        }
        if self.0 == 0.0 || shown.ch != wanted.ch {
            return false;
        }
        let limit = self.0 * self.0;
        colors_within(shown.fg, wanted.fg, limit) && colors_within(shown.bg, wanted.bg, limit)
    }

    /// The cell to send for `wanted`: each 24-bit colour replaced by its nearest 256-colour palette entry when
    /// that is within the tolerance (never with [`Self::EXACT`]).
    #[inline]
    pub fn cheaper(self, wanted: &Cell) -> Cell {
        if self.0 == 0.0 {
            return *wanted;
        }
        let limit = self.0 * self.0;
        Cell { ch: wanted.ch, fg: cheaper_color(wanted.fg, limit), bg: cheaper_color(wanted.bg, limit) }
    }
}

#[inline]
fn cheaper_color(color: Color, limit_squared: f32) -> Color {
    let Color::Rgb(r, g, b) = color else { return color };
    let index = Color::Indexed(nearest_xterm256(r, g, b));
    if colors_within(index, color, limit_squared) { index } else { color }
}

/// The Oklab distance between two cells' colours on one side, for reports; `None` when either is the terminal's
/// default (which has no known colour) and they differ.
pub fn color_distance(a: Color, b: Color) -> Option<f32> {
    if a == b {
        return Some(0.0);
    }
    Some(oklab(a)?.distance_squared(oklab(b)?).sqrt())
}

#[inline]
fn colors_within(a: Color, b: Color, limit_squared: f32) -> bool {
    a == b || matches!((oklab(a), oklab(b)), (Some(a), Some(b)) if a.distance_squared(b) <= limit_squared)
}

/// The colour's Oklab coordinates; `None` for the terminal's default colour.
fn oklab(color: Color) -> Option<Oklab> {
    let (r, g, b) = match color {
        Color::Rgb(r, g, b) => (r, g, b),
        Color::Indexed(n) => xterm256_rgb(n),
        Color::Default => return None,
    };
    Some(Oklab::from_srgb8(r, g, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    const UPPER: char = '▀';

    fn cell(fg: (u8, u8, u8), bg: (u8, u8, u8)) -> Cell {
        Cell::new(UPPER, Color::Rgb(fg.0, fg.1, fg.2), Color::Rgb(bg.0, bg.1, bg.2))
    }

    #[test]
    fn exact_accepts_only_identical_cells() {
        let a = cell((100, 100, 100), (0, 0, 0));
        assert!(Tolerance::EXACT.accepts(&a, &a));
        assert!(!Tolerance::EXACT.accepts(&a, &cell((101, 100, 100), (0, 0, 0))));
        assert_eq!(Tolerance::new(-1.0), Tolerance::EXACT);
        assert_eq!(Tolerance::new(f32::NAN), Tolerance::EXACT);
    }

    #[test]
    fn both_colours_and_the_character_must_be_within() {
        let shown = cell((100, 100, 100), (20, 20, 20));
        // One 8-bit step of grey is about 0.003 in Oklab lightness near the middle.
        let near = cell((101, 101, 101), (21, 21, 21));
        let far_fg = cell((160, 100, 100), (20, 20, 20));
        let far_bg = cell((100, 100, 100), (20, 90, 20));
        let t = Tolerance::new(0.02);
        assert!(t.accepts(&shown, &near));
        assert!(!t.accepts(&shown, &far_fg));
        assert!(!t.accepts(&shown, &far_bg));
        assert!(!t.accepts(&shown, &Cell { ch: ' ', ..near }));
        let default = Cell::new(UPPER, Color::Default, Color::Rgb(20, 20, 20));
        assert!(!Tolerance::new(10.0).accepts(&default, &shown), "the default colour is unknown, never near");
    }

    #[test]
    fn a_palette_colour_within_the_tolerance_is_sent_instead() {
        // 95 is a level of the palette's colour cube: (95, 95, 95) is index 59.
        let wanted = cell((95, 95, 96), (200, 10, 10));
        let sent = Tolerance::new(0.02).cheaper(&wanted);
        assert_eq!(sent.fg, Color::Indexed(59));
        assert_eq!(sent.bg, wanted.bg, "no palette entry is within 0.02 of (200, 10, 10)");
        assert!(Tolerance::new(0.02).accepts(&sent, &wanted));
        assert_eq!(Tolerance::EXACT.cheaper(&wanted), wanted);
    }

    #[test]
    fn the_distance_is_oklabs() {
        let d = color_distance(Color::Rgb(255, 255, 255), Color::Rgb(0, 0, 0)).unwrap();
        assert!((d - 1.0).abs() < 1e-3, "white to black is 1 in Oklab lightness, got {d}");
        // Palette index 231 is the cube's white, 16 its black.
        assert_eq!(color_distance(Color::Indexed(231), Color::Rgb(255, 255, 255)), Some(0.0));
        let d = color_distance(Color::Indexed(16), Color::Rgb(255, 255, 255)).unwrap();
        assert!((d - 1.0).abs() < 1e-3);
        assert_eq!(color_distance(Color::Default, Color::Rgb(0, 0, 0)), None);
    }
}
