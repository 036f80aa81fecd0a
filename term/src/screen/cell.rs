//! One terminal cell: a character and its foreground and background colours.

use super::color::Color;
use super::image_placeholder;

/// The character the encoder sends in place of a cell character that is not [`Cell::is_safe_char`].
pub const REPLACEMENT_CHAR: char = '?';

/// One character cell of the terminal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Cell {
    /// The character shown; see [`Cell::is_safe_char`] for the ones that are sent as they are.
    pub ch: char,
    /// Foreground (glyph) colour.
    pub fg: Color,
    /// Background colour.
    pub bg: Color,
}

impl Cell {
    /// A space in the terminal's default colours: what a cleared terminal shows.
    pub const BLANK: Cell = Cell { ch: ' ', fg: Color::Default, bg: Color::Default };

    /// A cell from its parts.
    pub const fn new(ch: char, fg: Color, bg: Color) -> Self {
        Cell { ch, fg, bg }
    }

    /// A placeholder cell of kitty image `image_id` ([`image_placeholder`]): a 256-colour index; 16 to 255 pass
    /// every multiplexer unchanged.
    pub const fn image_placeholder(image_id: u8) -> Self {
        Cell { ch: image_placeholder::PLACEHOLDER, fg: Color::Indexed(image_id), bg: Color::Default }
    }

    /// Whether `ch` is sent to the terminal as it is: printable ASCII (space to `~`), box drawing and block
    /// elements (U+2500..=U+259F, which hold `▀` and the quadrants), Braille patterns (U+2800..=U+28FF), the
    /// sextants (U+1FB00..=U+1FB3B), the other legacy-computing blocks an octant cell draws (U+1FB82, U+1FB85,
    /// U+1FBE6, U+1FBE7), the octants (U+1CD00..=U+1CDE5), the quarter blocks beside them (U+1CEA0..=U+1CEAB), and
    /// kitty's image placeholder (U+10EEEE, which the encoder follows with the marks that place it).
    ///
    /// All of these are one column wide, so the encoder can track the cursor. Control characters, which
    /// could inject escape sequences, and zero-width or double-width characters, which would desynchronise
    /// the cursor, are not.
    #[inline]
    pub const fn is_safe_char(ch: char) -> bool {
        matches!(
            ch,
            ' '..='~'
                | '\u{2500}'..='\u{259F}'
                | '\u{2800}'..='\u{28FF}'
                | '\u{1FB00}'..='\u{1FB3B}'
                | '\u{1FB82}'
                | '\u{1FB85}'
                | '\u{1FBE6}'
                | '\u{1FBE7}'
                | '\u{1CD00}'..='\u{1CDE5}'
                | '\u{1CEA0}'..='\u{1CEAB}'
                | image_placeholder::PLACEHOLDER
        )
    }

    /// The character actually sent for this cell: `ch` when [`Cell::is_safe_char`], else [`REPLACEMENT_CHAR`].
    #[inline]
    pub const fn safe_ch(&self) -> char {
        if Self::is_safe_char(self.ch) { self.ch } else { REPLACEMENT_CHAR }
    }
}

impl Default for Cell {
    fn default() -> Self {
        Cell::BLANK
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_and_wide_characters_are_replaced() {
        for ch in ['\x1b', '\n', '\r', '\x07', '\x7f', '\u{9b}', '\u{0301}', '中', '\u{1F600}', '\u{200B}', '\u{1FB3C}']
        {
            assert_eq!(Cell::new(ch, Color::Default, Color::Default).safe_ch(), REPLACEMENT_CHAR, "{ch:?}");
        }
    }

    #[test]
    fn drawing_characters_pass() {
        for ch in [' ', '@', '~', '▀', '▄', '█', '─', '⣿', '▚', '\u{1FB00}', '\u{1FB3B}'] {
            assert_eq!(Cell::new(ch, Color::Default, Color::Default).safe_ch(), ch);
        }
    }
}
