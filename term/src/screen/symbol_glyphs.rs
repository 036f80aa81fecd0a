//! The character sets that split a cell into a grid of sub-pixels: quadrants (2x2), sextants (2x3), octants (2x4)
//! and Braille dots (2x4), and the character for each pattern of lit sub-pixels.
//!
//! A pattern is a bit mask over the cell's sub-pixels in row-major order: bit `row * 2 + col` is the sub-pixel in
//! column `col` (0 left, 1 right) of row `row` (0 at the top). A set bit is drawn in the foreground colour, a clear
//! one in the background colour. Code points: The Unicode Standard, charts "Block Elements" (U+2580-U+259F),
//! "Symbols for Legacy Computing" (U+1FB00-U+1FBFF), "Symbols for Legacy Computing Supplement" (Unicode 16:
//! U+1CC00-U+1CEBF, the octants U+1CD00-U+1CDE5) and "Braille Patterns" (U+2800-U+28FF).

/// A set of characters that draws every pattern of a cell's sub-pixels in two colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymbolSet {
    /// 2x2 sub-pixels: the quadrant blocks with the half and full blocks (all in Block Elements).
    Quadrant,
    /// 2x3 sub-pixels: Unicode 13's sextants with the left, right and full blocks.
    Sextant,
    /// 2x4 sub-pixels: Unicode 16's octants with the block, quadrant and quarter-block characters that draw the
    /// other 26 patterns. Few fonts have octants yet.
    Octant,
    /// 2x4 sub-pixels: the 256 Braille patterns, a dot per sub-pixel.
    Braille,
}

/// Every set, in order of fineness.
pub const SYMBOL_SETS: [SymbolSet; 4] =
    [SymbolSet::Quadrant, SymbolSet::Sextant, SymbolSet::Octant, SymbolSet::Braille];

/// Quadrant characters by pattern: bit 0 upper left, 1 upper right, 2 lower left, 3 lower right.
const QUADRANT_GLYPHS: [char; 16] = [' ', '▘', '▝', '▀', '▖', '▌', '▞', '▛', '▗', '▚', '▐', '▜', '▄', '▙', '▟', '█'];

/// The sextant pattern drawn by `▌` (U+258C) rather than a sextant character: the left column.
const SEXTANT_LEFT_HALF: u8 = 0b01_0101;
/// The sextant pattern drawn by `▐` (U+2590): the right column.
const SEXTANT_RIGHT_HALF: u8 = 0b10_1010;

impl SymbolSet {
    /// Sub-pixel columns of a cell (2 in every set).
    pub const fn columns(self) -> usize {
        2
    }

    /// Sub-pixel rows of a cell.
    pub const fn rows(self) -> usize {
        match self {
            SymbolSet::Quadrant => 2,
            SymbolSet::Sextant => 3,
            SymbolSet::Octant | SymbolSet::Braille => 4,
        }
    }

    /// Sub-pixels of a cell.
    pub const fn sub_pixels(self) -> usize {
        self.columns() * self.rows()
    }

    /// The character that shows `pattern` (a mask over [`SymbolSet::sub_pixels`] bits; higher bits are ignored).
    ///
    /// The empty pattern is a space in every set, so a cell of one colour is a space on that background.
    pub const fn glyph(self, pattern: u8) -> char {
        match self {
            SymbolSet::Quadrant => QUADRANT_GLYPHS[(pattern & 0xF) as usize],
            SymbolSet::Sextant => sextant_glyph(pattern & 0x3F),
            SymbolSet::Octant => octant_glyph(pattern),
            SymbolSet::Braille => braille_glyph(pattern),
        }
    }
}

/// The sextants U+1FB00..=U+1FB3B hold the 64 patterns but four, in pattern order: the empty and full cells and
/// the two half blocks come from the older Block Elements.
const fn sextant_glyph(pattern: u8) -> char {
    match pattern {
        0 => ' ',
        0x3F => '█',
        SEXTANT_LEFT_HALF => '▌',
        SEXTANT_RIGHT_HALF => '▐',
        _ => {
            let skipped = (pattern > SEXTANT_LEFT_HALF) as u32 + (pattern > SEXTANT_RIGHT_HALF) as u32;
            match char::from_u32(0x1FB00 + pattern as u32 - 1 - skipped) {
                Some(ch) => ch,
                None => ' ',
            }
        }
    }
}

/// The 26 octant patterns that older characters draw, in pattern order, with their characters. Unicode numbers
/// octant parts 1 to 8 row by row, as the pattern's bits are: part `k` is bit `k - 1`.
const OCTANTS_ELSEWHERE: [(u8, char); 26] = [
    (0b0000_0000, ' '),
    (0b0000_0001, '\u{1CEA8}'), // LEFT HALF UPPER ONE QUARTER BLOCK
    (0b0000_0010, '\u{1CEAB}'), // RIGHT HALF UPPER ONE QUARTER BLOCK
    (0b0000_0011, '\u{1FB82}'), // UPPER ONE QUARTER BLOCK
    (0b0000_0101, '▘'),
    (0b0000_1010, '▝'),
    (0b0000_1111, '▀'),
    (0b0001_0100, '\u{1FBE6}'), // MIDDLE LEFT ONE QUARTER BLOCK
    (0b0010_1000, '\u{1FBE7}'), // MIDDLE RIGHT ONE QUARTER BLOCK
    (0b0011_1111, '\u{1FB85}'), // UPPER THREE QUARTERS BLOCK
    (0b0100_0000, '\u{1CEA3}'), // LEFT HALF LOWER ONE QUARTER BLOCK
    (0b0101_0000, '▖'),
    (0b0101_0101, '▌'),
    (0b0101_1010, '▞'),
    (0b0101_1111, '▛'),
    (0b1000_0000, '\u{1CEA0}'), // RIGHT HALF LOWER ONE QUARTER BLOCK
    (0b1010_0000, '▗'),
    (0b1010_0101, '▚'),
    (0b1010_1010, '▐'),
    (0b1010_1111, '▜'),
    (0b1100_0000, '▂'),
    (0b1111_0000, '▄'),
    (0b1111_0101, '▙'),
    (0b1111_1010, '▟'),
    (0b1111_1100, '▆'),
    (0b1111_1111, '█'),
];

/// The octants U+1CD00..=U+1CDE5 hold the 256 patterns but [`OCTANTS_ELSEWHERE`], in pattern order.
const fn octant_glyph(pattern: u8) -> char {
    let mut skipped = 0;
    let mut k = 0;
    while k < OCTANTS_ELSEWHERE.len() {
        let (other, ch) = OCTANTS_ELSEWHERE[k];
        if other == pattern {
            return ch;
        }
        skipped += (other < pattern) as u32;
        k += 1;
    }
    match char::from_u32(0x1CD00 + pattern as u32 - skipped) {
        Some(ch) => ch,
        None => ' ',
    }
}

/// Braille numbers its dots 1-2-3 down the left column, 4-5-6 down the right, then 7 and 8 below them; dot `k`
/// is bit `k - 1` of the code point's offset from U+2800.
const fn braille_glyph(pattern: u8) -> char {
    if pattern == 0 {
        return ' ';
    }
    // Bit `row * 2 + col` of the pattern is this dot's bit of the code point.
    const DOT_BIT: [u8; 8] = [0, 3, 1, 4, 2, 5, 6, 7];
    let mut offset = 0u32;
    let mut bit = 0;
    while bit < 8 {
        if pattern & (1 << bit) != 0 {
            offset |= 1 << DOT_BIT[bit];
        }
        bit += 1;
    }
    match char::from_u32(0x2800 + offset) {
        Some(ch) => ch,
        None => ' ',
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pattern_has_its_own_glyph() {
        for set in SYMBOL_SETS {
            let patterns = 1u16 << set.sub_pixels();
            let glyphs: std::collections::HashSet<char> = (0..patterns).map(|p| set.glyph(p as u8)).collect();
            assert_eq!(glyphs.len(), usize::from(patterns), "{set:?}");
        }
    }

    #[test]
    fn sextants_fill_their_block() {
        let sextants: Vec<char> =
            (0u8..64).map(|p| SymbolSet::Sextant.glyph(p)).filter(|c| *c as u32 >= 0x1FB00).collect();
        assert_eq!(sextants.len(), 60);
        assert_eq!(*sextants.first().unwrap() as u32, 0x1FB00);
        assert_eq!(*sextants.last().unwrap() as u32, 0x1FB3B);
    }

    #[test]
    fn octants_fill_their_block() {
        let octants: Vec<char> = (0u8..=255)
            .map(|p| SymbolSet::Octant.glyph(p))
            .filter(|c| (0x1CD00..=0x1CDE5).contains(&(*c as u32)))
            .collect();
        assert_eq!(octants.len(), 230);
        assert_eq!(*octants.first().unwrap() as u32, 0x1CD00);
        assert_eq!(*octants.last().unwrap() as u32, 0x1CDE5);
    }

    #[test]
    fn braille_dots_follow_the_cell_grid() {
        assert_eq!(SymbolSet::Braille.glyph(0b0000_0001), '⠁'); // dot 1, upper left
        assert_eq!(SymbolSet::Braille.glyph(0b0000_0010), '⠈'); // dot 4, upper right
        assert_eq!(SymbolSet::Braille.glyph(0b0100_0000), '⡀'); // dot 7, lower left
        assert_eq!(SymbolSet::Braille.glyph(0xFF), '⣿');
    }
}
