//! Which key of the document a byte span belongs to, written as a dotted path (`objects[1].material.diffuse`).
//!
//! `toml`'s errors carry the span of the offending key or value but not the key's path, so the path is found by
//! walking the document's spanned tree: the deepest key whose name or value contains the span's start wins.
//! Array elements are indexed only when they are tables (`objects[1]`); a bad element of an array of numbers is
//! reported under the array's key.

use std::ops::Range;

use toml::Spanned;
use toml::de::{DeString, DeTable, DeValue};

/// One step of a key path: a key of a table or an index into an array of tables.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Step {
    Key(String),
    Index(usize),
}

/// Dotted path text of `steps`: keys that are not bare TOML keys are quoted.
fn render(steps: &[Step]) -> String {
    let mut out = String::new();
    for step in steps {
        match step {
            Step::Key(k) => {
                if !out.is_empty() {
                    out.push('.');
                }
                let bare = !k.is_empty() && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
                if bare {
                    out.push_str(k);
                } else {
                    out.push_str(&format!("{k:?}"));
                }
            }
            Step::Index(i) => out.push_str(&format!("[{i}]")),
        }
    }
    out
}

/// Joins a parent path (possibly empty) and a key, quoting the key when it is not bare.
pub(crate) fn child(parent: &str, key: &str) -> String {
    let key = render(&[Step::Key(key.to_string())]);
    if parent.is_empty() { key } else { format!("{parent}.{key}") }
}

/// The path of the deepest key whose name or value contains byte `pos`; failing that, the last key on the same
/// line of `text` that starts before `pos` (the key being written when a syntax error cut its value short).
pub(crate) fn key_at(text: &str, table: &DeTable<'_>, pos: usize) -> Option<String> {
    let mut best = Best::default();
    walk(table, pos, &mut Vec::new(), &mut best);
    let line_start = text.get(..pos).and_then(|t| t.rfind('\n')).map_or(0, |i| i + 1);
    best.containing
        .or_else(|| best.before.filter(|(start, _)| *start >= line_start).map(|(_, steps)| steps))
        .map(|steps| render(&steps))
}

#[derive(Default)]
struct Best {
    /// The deepest match whose key or value contains the position.
    containing: Option<Vec<Step>>,
    /// The key starting last before the position, with its start.
    before: Option<(usize, Vec<Step>)>,
}

fn contains(span: &Range<usize>, pos: usize) -> bool {
    span.contains(&pos) || (span.is_empty() && span.start == pos)
}

fn walk(table: &DeTable<'_>, pos: usize, path: &mut Vec<Step>, best: &mut Best) {
    for (key, value) in table.iter() {
        path.push(Step::Key(key.get_ref().to_string()));
        visit(key, value, pos, path, best);
        path.pop();
    }
}

fn visit(key: &Spanned<DeString<'_>>, value: &Spanned<DeValue<'_>>, pos: usize, path: &mut Vec<Step>, best: &mut Best) {
    let here = contains(&key.span(), pos) || contains(&value.span(), pos);
    if here && best.containing.as_ref().is_none_or(|b| b.len() <= path.len()) {
        best.containing = Some(path.clone());
    }
    let start = key.span().start;
    if start <= pos && best.before.as_ref().is_none_or(|(s, _)| *s <= start) {
        best.before = Some((start, path.clone()));
    }
    match value.get_ref() {
        DeValue::Table(t) => walk(t, pos, path, best),
        DeValue::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                if let DeValue::Table(t) = item.get_ref() {
                    path.push(Step::Index(i));
                    if contains(&item.span(), pos) && best.containing.as_ref().is_none_or(|b| b.len() <= path.len()) {
                        best.containing = Some(path.clone());
                    }
                    walk(t, pos, path, best);
                    path.pop();
                }
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn path(text: &str, needle: &str) -> Option<String> {
        let tree = DeTable::parse(text).unwrap();
        key_at(text, tree.get_ref(), text.find(needle).unwrap())
    }

    #[test]
    fn keys_values_and_tables_of_arrays() {
        let text = "a = 1\n[camera]\nfov = 200\n[[objects]]\nmesh = 'x'\n[[objects]]\nmesh = 'y'\n\
                    [objects.material]\ncolor = [1, 2, 'z']\n";
        assert_eq!(path(text, "1").as_deref(), Some("a"));
        assert_eq!(path(text, "200").as_deref(), Some("camera.fov"));
        assert_eq!(path(text, "[camera]").as_deref(), Some("camera"));
        assert_eq!(path(text, "'y'").as_deref(), Some("objects[1].mesh"));
        assert_eq!(path(text, "[objects.material]").as_deref(), Some("objects[1].material"));
        assert_eq!(path(text, "'z'").as_deref(), Some("objects[1].material.color"));
    }

    #[test]
    fn inline_tables_and_quoted_keys() {
        let text = "[[objects]]\nmaterial = { color = [1, 1, 1], \"odd key\" = 3 }\n";
        assert_eq!(path(text, "[1, 1").as_deref(), Some("objects[0].material.color"));
        assert_eq!(path(text, "\"odd").as_deref(), Some("objects[0].material.\"odd key\""));
        assert_eq!(child("camera", "fov"), "camera.fov");
        assert_eq!(child("", "a.b"), "\"a.b\"");
    }

    #[test]
    fn a_position_after_a_key_on_its_line_names_that_key() {
        let text = "[camera]\nfov = 1\n";
        let tree = DeTable::parse(text).unwrap();
        // Just past the value, as a syntax error there would be.
        assert_eq!(key_at(text, tree.get_ref(), text.len() - 1).as_deref(), Some("camera.fov"));
        // Nothing on the line: no key.
        let text = "[camera]\nfov = 1\n\n";
        let tree = DeTable::parse(text).unwrap();
        assert_eq!(key_at(text, tree.get_ref(), text.len()), None);
    }
}
