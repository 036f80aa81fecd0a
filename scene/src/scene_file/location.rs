//! Byte offsets of the scene file's text turned into line and column numbers.

use std::fmt;
use std::ops::Range;

/// A place in the scene file: 1-based line and column, the column counted in characters (not bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Location {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column, in characters from the start of the line.
    pub column: usize,
}

impl Location {
    /// The start of the file, where problems with the document as a whole (a missing top-level key) are reported.
    pub const START: Self = Self { line: 1, column: 1 };

    /// The location of byte `offset` of `text`. An offset past the end is the end of the text; one inside a
    /// multi-byte character is that character.
    pub(crate) fn of_offset(text: &str, offset: usize) -> Self {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let before = &text[..offset];
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        Self { line: before.matches('\n').count() + 1, column: before[line_start..].chars().count() + 1 }
    }

    /// The location of the start of `span`.
    pub(crate) fn of_span(text: &str, span: &Range<usize>) -> Self {
        Self::of_offset(text, span.start)
    }
}

impl fmt::Display for Location {
    /// `LINE:COLUMN`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_columns_are_one_based() {
        let text = "a = 1\nbb = 2\n";
        assert_eq!(Location::of_offset(text, 0), Location::START);
        assert_eq!(Location::of_offset(text, 4), Location { line: 1, column: 5 });
        assert_eq!(Location::of_offset(text, 6), Location { line: 2, column: 1 });
        assert_eq!(Location::of_offset(text, 11), Location { line: 2, column: 6 });
        assert_eq!(Location::of_offset(text, 1000), Location { line: 3, column: 1 });
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let text = "name = \"é\" # ü\nx";
        // The `#` is byte 12 (after the two bytes of `é`) but the 12th character.
        assert_eq!(Location::of_offset(text, 12), Location { line: 1, column: 12 });
        // Inside the two bytes of `ü`: that character.
        assert_eq!(Location::of_offset(text, 15), Location { line: 1, column: 14 });
        assert_eq!(Location { line: 4, column: 2 }.to_string(), "4:2");
    }
}
