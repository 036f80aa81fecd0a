//! Control-character escaping for any text from input files that may reach a terminal.
//!
//! File names, tokens and material names come from files and can hold any character. Messages built from them must
//! stay on one line and must not carry terminal escape sequences, so every control character is written as a Rust
//! escape (`\n`, `\u{1b}`). The data itself (part and material names) is kept raw.

use std::fmt;

/// Displays a string with its control characters escaped.
pub struct Escaped<'a>(pub &'a str);

impl fmt::Display for Escaped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in self.0.chars() {
            if c.is_control() {
                write!(f, "{}", c.escape_default())?;
            } else {
                fmt::Write::write_char(f, c)?;
            }
        }
        Ok(())
    }
}

/// The message for a `what` named `asked` that is not among `labels` (raw names, numbered from 0 in the message):
/// "there is no WHAT ASKED (there are 0: a, 1: b)", or "there is no WHAT ASKED: NONE" when there are none. Every
/// name escaped.
pub fn not_among(what: &str, asked: &str, labels: impl IntoIterator<Item = String>, none: &str) -> String {
    let there: Vec<String> = labels.into_iter().enumerate().map(|(k, l)| format!("{k}: {}", Escaped(&l))).collect();
    if there.is_empty() {
        format!("there is no {what} {}: {none}", Escaped(asked))
    } else {
        format!("there is no {what} {} (there are {})", Escaped(asked), there.join(", "))
    }
}

/// `path` as text for a message: lossy UTF-8, control characters escaped.
pub fn path_text(path: &std::path::Path) -> String {
    Escaped(&path.to_string_lossy()).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_the_rest_kept() {
        assert_eq!(Escaped("a\nb\x1b[31mc\u{9b}é").to_string(), "a\\nb\\u{1b}[31mc\\u{9b}é");
        assert_eq!(Escaped("plain name.obj").to_string(), "plain name.obj");
    }

    #[test]
    fn paths_become_one_line() {
        let text = path_text(std::path::Path::new("dir/evil\r\nname.obj"));
        assert_eq!(text, "dir/evil\\r\\nname.obj");
    }
}
