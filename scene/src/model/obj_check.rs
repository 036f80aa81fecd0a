//! A line-by-line check of OBJ text before it reaches `tobj`.
//!
//! `tobj` reports errors without a line number, and with indices far out of range it can overflow (a panic in
//! debug builds) or read the wrong element (release builds). So every statement `tobj` parses is checked here first,
//! with the same tokenisation (`split_whitespace`, `f32`/`isize` parsing), and the first bad one is reported with
//! its line. What passes is safe for `tobj`, which then parses it again into meshes.
//!
//! Rules, stricter than `tobj` where it is lax:
//! - `v x y z [w]` or `v x y z r g b`; `vt u [v]` (more numbers ignored); `vn x y z`. Every number must be finite and
//!   within [`COORDINATE_LIMIT`] in magnitude (positions after the division by `w`, which must not be 0).
//! - `f` (and `l`, which `tobj` treats as a face) tokens are `v`, `v/vt`, `v//vn` or `v/vt/vn`. An index refers to
//!   an element defined *before* the face (`tobj` would accept later ones of the same object); `-1` is the last one
//!   defined; `0` is invalid.
//! - `usemtl` needs a name. `mtllib` without a file name is dropped with a warning.
//!
//! The text handed to `tobj` is rewritten a little, line for line: leading whitespace removed (`tobj` would take the
//! `g` of ` g name` into the name), vertex colours dropped (the renderer does not use them, and `tobj` fails on a
//! file where only some vertices have colours), `l` lines dropped (a polyline is not a face), and the separator
//! after `usemtl`/`mtllib` made a space (`tobj` splits there on a space only), and `vt u` completed to `vt u 0`. Invalid UTF-8 is replaced by U+FFFD
//! (with a warning).

use std::path::Path;

use super::error::{COORDINATE_LIMIT, Element, LoadError, LoadErrorKind};
use crate::escaped::path_text;

/// OBJ text that passed the check.
pub(crate) struct CheckedObj {
    /// The text for `tobj`, with the same line numbers as the file.
    pub(crate) text: String,
    /// The material names given to `usemtl`, each with the first line it is used on.
    pub(crate) material_uses: Vec<(usize, String)>,
    /// Warnings about the text (invalid UTF-8, faces with fewer than three vertices, empty `mtllib`).
    pub(crate) warnings: Vec<String>,
}

/// Checks OBJ `bytes`; `path` names the file in errors and warnings.
///
/// # Errors
/// The first statement that does not pass, with its line.
pub(crate) fn check_obj(path: &Path, bytes: &[u8]) -> Result<CheckedObj, LoadError> {
    let mut checker = Checker { path, counts: [0; 3], material_uses: Vec::new() };
    let mut text = String::with_capacity(bytes.len() + 16);
    let mut warnings = Vec::new();
    let mut bad_utf8 = Tally::default();
    let mut short_faces = Tally::default();
    for (index, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let number = index + 1;
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let line = String::from_utf8_lossy(raw);
        if matches!(line, std::borrow::Cow::Owned(_)) {
            bad_utf8.add(number);
        }
        match checker.statement(number, line.trim_start())? {
            Output::Keep(l) => text.push_str(l),
            Output::Replace(l) => text.push_str(&l),
            Output::Drop => {}
            Output::DropShortFace => short_faces.add(number),
            Output::DropEmptyMtllib => {
                warnings.push(format!("{}, line {number}: mtllib without a file name", path_text(path)));
            }
        }
        text.push('\n');
    }
    let file = path_text(path);
    if let Some((first, count)) = bad_utf8.summary() {
        warnings.push(format!(
            "{file}: {count} line(s) are not valid UTF-8, the first at line {first}; invalid bytes replaced"
        ));
    }
    if let Some((first, count)) = short_faces.summary() {
        warnings.push(format!("{file}: {count} face(s) with fewer than 3 vertices ignored, the first at line {first}"));
    }
    Ok(CheckedObj { text, material_uses: checker.material_uses, warnings })
}

/// Counts occurrences and remembers the first line.
#[derive(Default)]
struct Tally {
    first: usize,
    count: usize,
}

impl Tally {
    fn add(&mut self, line: usize) {
        if self.count == 0 {
            self.first = line;
        }
        self.count += 1;
    }

    fn summary(&self) -> Option<(usize, usize)> {
        (self.count > 0).then_some((self.first, self.count))
    }
}

enum Output<'l> {
    Keep(&'l str),
    Replace(String),
    Drop,
    DropShortFace,
    DropEmptyMtllib,
}

struct Checker<'p> {
    path: &'p Path,
    /// Positions, texture coordinates and normals defined so far.
    counts: [usize; 3],
    material_uses: Vec<(usize, String)>,
}

const ELEMENTS: [Element; 3] = [Element::Vertex, Element::TextureCoordinate, Element::Normal];

impl Checker<'_> {
    fn statement<'l>(&mut self, line: usize, text: &'l str) -> Result<Output<'l>, LoadError> {
        let mut words = text.split_whitespace();
        let Some(keyword) = words.next() else { return Ok(Output::Keep(text)) };
        let rest = text[keyword.len()..].trim();
        match keyword {
            "v" => self.vertex(line, text, words),
            "vt" => {
                // `vt u` is short for `vt u 0`; `tobj` needs both numbers.
                let expected = "texture coordinates (vt) need 1 or 2 numbers";
                let (u, v) = (words.next().unwrap_or_default(), words.next());
                self.check_range(line, self.number(line, expected, u)?)?;
                if let Some(v) = v {
                    self.check_range(line, self.number(line, expected, v)?)?;
                }
                self.counts[1] += 1;
                Ok(if v.is_some() { Output::Keep(text) } else { Output::Replace(format!("vt {u} 0")) })
            }
            "vn" => {
                self.numbers::<3>(line, "a normal (vn) needs 3 numbers", words)?;
                self.counts[2] += 1;
                Ok(Output::Keep(text))
            }
            "f" => match self.face(line, words)? {
                0..=2 => Ok(Output::DropShortFace),
                _ => Ok(Output::Keep(text)),
            },
            "l" => Ok(Output::Drop),
            "usemtl" if rest.is_empty() => Err(LoadError::syntax(self.path, line, "usemtl without a material name")),
            "usemtl" => {
                if !self.material_uses.iter().any(|(_, name)| name == rest) {
                    self.material_uses.push((line, rest.to_owned()));
                }
                Ok(Output::Replace(format!("usemtl {rest}")))
            }
            "mtllib" if rest.is_empty() => Ok(Output::DropEmptyMtllib),
            "mtllib" => Ok(Output::Replace(format!("mtllib {rest}"))),
            _ => Ok(Output::Keep(text)),
        }
    }

    fn vertex<'l>(
        &mut self,
        line: usize,
        text: &'l str,
        mut words: std::str::SplitWhitespace<'l>,
    ) -> Result<Output<'l>, LoadError> {
        let xyz = [(); 3].map(|()| words.next().unwrap_or_default());
        let mut p = [0f32; 3];
        for (value, word) in p.iter_mut().zip(xyz) {
            *value = self.number(line, "a vertex (v) needs 3 numbers", word)?;
        }
        let extra: Vec<&str> = words.collect();
        let output = match extra.len() {
            0 => Output::Keep(text),
            1 => {
                let w = self.number(line, "the w of a vertex (v) must be a number", extra[0])?;
                if w == 0.0 {
                    return Err(LoadError::syntax(self.path, line, "the w of a vertex (v) is zero"));
                }
                for c in &mut p {
                    *c /= w;
                }
                Output::Keep(text)
            }
            3 => Output::Replace(format!("v {} {} {}", xyz[0], xyz[1], xyz[2])),
            n => {
                return Err(LoadError::syntax(
                    self.path,
                    line,
                    format!("a vertex (v) has x y z, then w or r g b, or nothing; found {} numbers", 3 + n),
                ));
            }
        };
        for c in p {
            self.check_range(line, c)?;
        }
        self.counts[0] += 1;
        Ok(output)
    }

    /// Parses the first `N` words as numbers in range (further words are ignored, as `tobj` does).
    fn numbers<const N: usize>(
        &self,
        line: usize,
        expected: &str,
        mut words: std::str::SplitWhitespace<'_>,
    ) -> Result<(), LoadError> {
        for _ in 0..N {
            let value = self.number(line, expected, words.next().unwrap_or_default())?;
            self.check_range(line, value)?;
        }
        Ok(())
    }

    fn number(&self, line: usize, expected: &str, word: &str) -> Result<f32, LoadError> {
        if word.is_empty() {
            return Err(LoadError::syntax(self.path, line, format!("{expected}, found fewer")));
        }
        word.parse::<f32>()
            .map_err(|_| LoadError::syntax(self.path, line, format!("{expected}; {word:?} is not a number")))
    }

    fn check_range(&self, line: usize, value: f32) -> Result<(), LoadError> {
        if value.is_finite() && value.abs() <= COORDINATE_LIMIT {
            Ok(())
        } else {
            Err(LoadError::new(self.path, LoadErrorKind::BadCoordinate { line, value }))
        }
    }

    /// Checks the vertices of a face; returns how many there are.
    fn face(&self, line: usize, words: std::str::SplitWhitespace<'_>) -> Result<usize, LoadError> {
        let mut vertices = 0;
        for word in words {
            vertices += 1;
            for (slot, part) in word.split('/').enumerate() {
                if part.is_empty() {
                    if slot == 0 {
                        return Err(LoadError::syntax(
                            self.path,
                            line,
                            format!("face vertex {word:?} has no position index"),
                        ));
                    }
                    continue;
                }
                if slot >= 3 {
                    return Err(LoadError::syntax(
                        self.path,
                        line,
                        format!("face vertex {word:?} has more than 3 indices (v/vt/vn)"),
                    ));
                }
                let Ok(index) = part.parse::<isize>() else {
                    return Err(LoadError::syntax(
                        self.path,
                        line,
                        format!("face vertex {word:?}: {part:?} is not an index"),
                    ));
                };
                let defined = self.counts[slot];
                if index == 0 || index.unsigned_abs() > defined {
                    return Err(LoadError::new(
                        self.path,
                        LoadErrorKind::IndexOutOfRange { line, element: ELEMENTS[slot], index: index as i64, defined },
                    ));
                }
            }
        }
        if vertices == 0 {
            return Err(LoadError::syntax(self.path, line, "a face (f) without vertices"));
        }
        Ok(vertices)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str) -> Result<CheckedObj, LoadError> {
        check_obj(Path::new("m.obj"), text.as_bytes())
    }

    fn error(text: &str) -> (Option<usize>, String) {
        let e = check(text).err().expect("an error");
        (e.line(), e.to_string())
    }

    #[test]
    fn valid_statements_pass_and_keep_their_line_numbers() {
        let c = check(
            "# c\n  v 0 0 0\r\nv 1 0 0 1 0 0\nv 0 1 0 2\nvt 0 0 0\nvt 1\nvn 0 0 1\nl 1 2\nf 1/2/1 2/1/1 -1/-1/-1\n",
        )
        .unwrap();
        assert_eq!(
            c.text,
            "# c\nv 0 0 0\nv 1 0 0\nv 0 1 0 2\nvt 0 0 0\nvt 1 0\nvn 0 0 1\n\nf 1/2/1 2/1/1 -1/-1/-1\n\n"
        );
        assert!(c.warnings.is_empty());
    }

    #[test]
    fn bad_numbers_are_reported_on_their_line() {
        assert_eq!(error("v 0 0 0\nv 1 x 0\n").0, Some(2));
        assert_eq!(error("v 0 0\n").0, Some(1));
        assert_eq!(error("vt 0 0\nvt 0.5 y\n").0, Some(2));
        assert_eq!(error("vt 0 0\nvt\n").0, Some(2));
        assert_eq!(error("vn 0 0 1\n\nvn 0 0 NaN-ish\n").0, Some(3));
        assert_eq!(error("v 0 0 0 0\n").1, "m.obj, line 1: the w of a vertex (v) is zero");
        assert_eq!(error("v 0 0 0 1 1\n").0, Some(1));
    }

    #[test]
    fn non_finite_and_huge_coordinates_are_reported_with_value_and_line() {
        assert_eq!(error("v 0 0 0\nv nan 0 0\n").1, "m.obj, line 2: coordinate NaN is not a finite number");
        assert_eq!(error("v 1e39 0 0\n").1, "m.obj, line 1: coordinate inf is not a finite number");
        assert_eq!(error("\nv 0 -2e15 0\n").1, "m.obj, line 2: coordinate -2e15 is beyond the limit of ±1e15");
        assert_eq!(error("v 1 1 1 1e-20\n").1, "m.obj, line 1: coordinate 1e20 is beyond the limit of ±1e15");
        assert_eq!(error("vt inf 0\n").0, Some(1));
        assert!(check("v 1e15 -1e15 0\n").is_ok());
    }

    #[test]
    fn face_indices_must_refer_to_earlier_elements() {
        let (line, text) = error("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n");
        assert_eq!(line, Some(3));
        assert_eq!(text, "m.obj, line 3: vertex index 3 is out of range (2 defined before it)");
        assert_eq!(error("v 0 0 0\nf 1 1 -2\n").0, Some(2));
        assert!(error("v 0 0 0\nf 0 1 1\n").1.contains("index 0 is invalid"));
        assert!(error("v 0 0 0\nvt 0 0\nf 1/1 1/2 1/1\n").1.contains("texture coordinate index 2"));
        assert!(error("v 0 0 0\nf 1//1 1//1 1//1\n").1.contains("normal index 1 is out of range (0 defined"));
        assert!(error("v 0 0 0\nf 1 1 -9223372036854775808\n").1.contains("index -9223372036854775808"));
    }

    #[test]
    fn malformed_faces_are_syntax_errors_on_their_line() {
        assert_eq!(error("v 0 0 0\nf\n").0, Some(2));
        assert_eq!(error("v 0 0 0\nf a 1 1\n").0, Some(2));
        assert_eq!(error("v 0 0 0\nf 1/1/1/1 1 1\n").0, Some(2));
        assert_eq!(error("v 0 0 0\nf /1 1 1\n").0, Some(2));
        assert_eq!(error("v 0 0 0\nf 99999999999999999999 1 1\n").0, Some(2));
        assert_eq!(error("usemtl\n").0, Some(1));
    }

    #[test]
    fn short_faces_empty_mtllib_and_bad_utf8_are_warnings() {
        let c = check("v 0 0 0\nf 1 1\nf 1\nmtllib \n# \u{0}\n").unwrap();
        assert_eq!(c.warnings.len(), 2, "{:?}", c.warnings);
        let c = check_obj(Path::new("m.obj"), b"# caf\xe9\nv 0 0 0\n").unwrap();
        assert_eq!(c.warnings, ["m.obj: 1 line(s) are not valid UTF-8, the first at line 1; invalid bytes replaced"]);
    }

    #[test]
    fn usemtl_and_mtllib_are_normalised_and_names_recorded_once() {
        let c = check("mtllib\tm.mtl\nusemtl\tred\nusemtl red\nusemtl blue \n").unwrap();
        assert_eq!(c.text, "mtllib m.mtl\nusemtl red\nusemtl red\nusemtl blue\n\n");
        assert_eq!(c.material_uses, [(2, "red".to_owned()), (4, "blue".to_owned())]);
    }
}
