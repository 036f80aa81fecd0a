//! How many colours the terminal can show, detected from its environment, and pixel quantisation to that mode.

use std::fmt;
use std::str::FromStr;

use super::color::Color;
use super::palette_lut::{nearest_ansi16, nearest_xterm256};

/// How cell colours are sent to the terminal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ColorMode {
    /// 24-bit colour (`38;2;r;g;b`).
    TrueColor,
    /// The xterm 256-colour palette (`38;5;n`); pixels map to the 6x6x6 cube and the grey ramp.
    Ansi256,
    /// The 16 ANSI colours (`30-37`, `90-97`).
    Ansi16,
    /// No colour escape codes at all (`NO_COLOR`, `TERM=dumb`).
    None,
}

/// The environment values colour detection looks at, passed in explicitly so detection is testable.
///
/// Each is `None` when the variable is unset.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TermEnv<'a> {
    /// `COLORTERM`.
    pub colorterm: Option<&'a str>,
    /// `TERM`.
    pub term: Option<&'a str>,
    /// `NO_COLOR` (see <https://no-color.org>): set and non-empty turns colour off.
    pub no_color: Option<&'a str>,
}

impl ColorMode {
    /// Picks the colour mode for a terminal environment.
    ///
    /// In order: `NO_COLOR` set and non-empty, or `TERM=dumb`, give [`ColorMode::None`]; `COLORTERM` equal to
    /// `truecolor` or `24bit`, or `TERM` ending in `-direct`, give [`ColorMode::TrueColor`]; anything else gives
    /// [`ColorMode::Ansi256`]. [`ColorMode::Ansi16`] is never detected, only asked for.
    pub fn detect(env: TermEnv<'_>) -> ColorMode {
        if env.no_color.is_some_and(|v| !v.is_empty()) || env.term == Some("dumb") {
            return ColorMode::None;
        }
        if matches!(env.colorterm, Some("truecolor" | "24bit")) || env.term.is_some_and(|t| t.ends_with("-direct")) {
            return ColorMode::TrueColor;
        }
        ColorMode::Ansi256
    }

    /// [`ColorMode::detect`] on this process's `COLORTERM`, `TERM` and `NO_COLOR`.
    ///
    /// A value that is not valid Unicode is read lossily, so a non-empty one still turns `NO_COLOR` on.
    pub fn from_process_env() -> ColorMode {
        let read = |name: &str| std::env::var_os(name).map(|v| v.to_string_lossy().into_owned());
        let (colorterm, term, no_color) = (read("COLORTERM"), read("TERM"), read("NO_COLOR"));
        ColorMode::detect(TermEnv {
            colorterm: colorterm.as_deref(),
            term: term.as_deref(),
            no_color: no_color.as_deref(),
        })
    }

    /// The cell colour for a pixel `0x00RRGGBB` in this mode: the exact RGB, the nearest palette entry
    /// (through the lookup tables of [`super::palette_lut`]), or [`Color::Default`] when colour is off.
    #[inline]
    pub fn quantize(self, pixel: u32) -> Color {
        let [_, r, g, b] = pixel.to_be_bytes();
        match self {
            ColorMode::TrueColor => Color::Rgb(r, g, b),
            ColorMode::Ansi256 => Color::Indexed(nearest_xterm256(r, g, b)),
            ColorMode::Ansi16 => Color::Indexed(nearest_ansi16(r, g, b)),
            ColorMode::None => Color::Default,
        }
    }

    /// The name accepted by [`ColorMode::from_str`].
    pub const fn name(self) -> &'static str {
        match self {
            ColorMode::TrueColor => "truecolor",
            ColorMode::Ansi256 => "256",
            ColorMode::Ansi16 => "16",
            ColorMode::None => "none",
        }
    }
}

impl fmt::Display for ColorMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The error of parsing an unknown colour-mode name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownColorMode(pub String);

impl fmt::Display for UnknownColorMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown colour mode {:?} (expected truecolor, 256, 16 or none)", self.0)
    }
}

impl std::error::Error for UnknownColorMode {}

impl FromStr for ColorMode {
    type Err = UnknownColorMode;

    /// Accepts `truecolor`/`24bit`, `256`, `16` and `none` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "truecolor" | "24bit" => Ok(ColorMode::TrueColor),
            "256" => Ok(ColorMode::Ansi256),
            "16" => Ok(ColorMode::Ansi16),
            "none" => Ok(ColorMode::None),
            _ => Err(UnknownColorMode(s.to_owned())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn detect(colorterm: Option<&str>, term: Option<&str>, no_color: Option<&str>) -> ColorMode {
        ColorMode::detect(TermEnv { colorterm, term, no_color })
    }

    #[test]
    fn truecolor_from_colorterm_or_direct_terminfo() {
        assert_eq!(detect(Some("truecolor"), Some("xterm-256color"), None), ColorMode::TrueColor);
        assert_eq!(detect(Some("24bit"), None, None), ColorMode::TrueColor);
        assert_eq!(detect(None, Some("xterm-direct"), None), ColorMode::TrueColor);
        assert_eq!(detect(Some("yes"), Some("xterm-direct"), Some("")), ColorMode::TrueColor);
    }

    #[test]
    fn everything_else_is_256_colours() {
        assert_eq!(detect(None, None, None), ColorMode::Ansi256);
        assert_eq!(detect(None, Some("xterm-256color"), None), ColorMode::Ansi256);
        assert_eq!(detect(Some("TRUECOLOR"), Some("linux"), None), ColorMode::Ansi256);
        assert_eq!(detect(Some(""), Some("direct"), None), ColorMode::Ansi256);
    }

    #[test]
    fn no_color_and_dumb_turn_colour_off() {
        assert_eq!(detect(Some("truecolor"), Some("xterm"), Some("1")), ColorMode::None);
        assert_eq!(detect(Some("truecolor"), Some("dumb"), None), ColorMode::None);
        // An empty NO_COLOR does not count.
        assert_eq!(detect(None, Some("xterm"), Some("")), ColorMode::Ansi256);
    }

    #[test]
    fn names_round_trip() {
        for mode in [ColorMode::TrueColor, ColorMode::Ansi256, ColorMode::Ansi16, ColorMode::None] {
            assert_eq!(mode.name().parse::<ColorMode>(), Ok(mode));
        }
        assert!("rainbow".parse::<ColorMode>().is_err());
    }

    #[test]
    fn quantize_per_mode() {
        assert_eq!(ColorMode::TrueColor.quantize(0x0012_3456), Color::Rgb(0x12, 0x34, 0x56));
        assert_eq!(ColorMode::Ansi256.quantize(0x00FF_0000), Color::Indexed(196));
        assert_eq!(ColorMode::Ansi16.quantize(0x00FF_0000), Color::Indexed(9));
        assert_eq!(ColorMode::None.quantize(0x00FF_0000), Color::Default);
    }
}
