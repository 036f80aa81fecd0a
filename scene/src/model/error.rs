//! Why a model or a texture could not be loaded.

use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

use crate::escaped::{Escaped, path_text};

/// The largest magnitude accepted for any number of a `v`, `vt` or `vn` statement.
///
/// It keeps every quantity the loader and the renderer derive from coordinates (extents, squared lengths, cross
/// products) finite in `f32`: `(2e15)^2 * 3` is about `1.2e31`, far below `f32::MAX` (about `3.4e38`).
pub const COORDINATE_LIMIT: f32 = 1e15;

/// A model or texture that could not be loaded: the file and what went wrong.
///
/// [`Display`](fmt::Display) gives one line that names the file (and the line of the file, when there is one).
/// Control characters from file names and file text are escaped in that line.
#[derive(Debug)]
pub struct LoadError {
    /// The file the problem is in: the OBJ file (as given, or the name given for in-memory data) or the image.
    pub path: PathBuf,
    /// What went wrong.
    pub kind: LoadErrorKind,
}

/// What went wrong while loading.
#[derive(Debug)]
#[non_exhaustive]
pub enum LoadErrorKind {
    /// The file could not be opened or read; holds the operating system's reason.
    Io(io::Error),
    /// A statement of the OBJ file could not be parsed.
    Syntax {
        /// 1-based line number.
        line: usize,
        /// What is wrong with the statement (raw text: may quote the file's tokens).
        problem: String,
    },
    /// A face refers to a vertex, texture coordinate or normal that is not defined before it.
    IndexOutOfRange {
        /// 1-based line number of the face.
        line: usize,
        /// What the index refers to.
        element: Element,
        /// The index as written (1-based; negative for relative indices; 0 is always invalid).
        index: i64,
        /// How many elements of that kind were defined before the face.
        defined: usize,
    },
    /// A number of a `v`, `vt` or `vn` statement is NaN, infinite, or beyond [`COORDINATE_LIMIT`] in magnitude
    /// (for `v x y z w`, after the division by `w`).
    BadCoordinate {
        /// 1-based line number.
        line: usize,
        /// The offending value.
        value: f32,
    },
    /// The file has no triangles to draw (no faces, or only points and lines).
    NoTriangles,
    /// The model has more vertices than 32-bit indices can address.
    TooManyVertices,
    /// An image could not be decoded (the reason given by the decoder).
    Image(String),
    /// The OBJ parser rejected the file for a reason the loader's own line check did not find. Should not happen;
    /// kept so that such a file is an error rather than a surprise.
    Parser(String),
    /// A coordinate of a triangle of a binary file (STL) is NaN, infinite, or beyond [`COORDINATE_LIMIT`].
    BadTriangle {
        /// 1-based triangle number.
        triangle: usize,
        /// The offending value.
        value: f32,
    },
    /// The file is not laid out as its format says (a binary STL shorter than its triangle count): what is wrong.
    Format(String),
    /// The file is not of a type the loader reads: what it looks like, and the types that are read.
    UnknownFormat(String),
}

/// The kind of element a face index refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Element {
    /// A position (`v`).
    Vertex,
    /// A texture coordinate (`vt`).
    TextureCoordinate,
    /// A normal (`vn`).
    Normal,
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Vertex => "vertex",
            Self::TextureCoordinate => "texture coordinate",
            Self::Normal => "normal",
        })
    }
}

impl LoadError {
    /// An error of `kind` in the file at `path`.
    pub fn new(path: impl Into<PathBuf>, kind: LoadErrorKind) -> Self {
        Self { path: path.into(), kind }
    }

    /// The 1-based line of the file the problem is on, when it is about one line.
    pub fn line(&self) -> Option<usize> {
        match self.kind {
            LoadErrorKind::Syntax { line, .. }
            | LoadErrorKind::IndexOutOfRange { line, .. }
            | LoadErrorKind::BadCoordinate { line, .. } => Some(line),
            _ => None,
        }
    }

    pub(crate) fn syntax(path: &Path, line: usize, problem: impl Into<String>) -> Self {
        Self::new(path, LoadErrorKind::Syntax { line, problem: problem.into() })
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path = path_text(&self.path);
        match &self.kind {
            LoadErrorKind::Io(e) => write!(f, "{path}: cannot read the file: {}", Escaped(&e.to_string())),
            LoadErrorKind::Syntax { line, problem } => write!(f, "{path}, line {line}: {}", Escaped(problem)),
            LoadErrorKind::IndexOutOfRange { line, element, index: 0, .. } => {
                write!(f, "{path}, line {line}: {element} index 0 is invalid (OBJ indices start at 1)")
            }
            LoadErrorKind::IndexOutOfRange { line, element, index, defined } => {
                write!(f, "{path}, line {line}: {element} index {index} is out of range ({defined} defined before it)")
            }
            LoadErrorKind::BadCoordinate { line, value } if !value.is_finite() => {
                write!(f, "{path}, line {line}: coordinate {value} is not a finite number")
            }
            LoadErrorKind::BadCoordinate { line, value } => {
                write!(f, "{path}, line {line}: coordinate {value:e} is beyond the limit of ±{COORDINATE_LIMIT:e}")
            }
            LoadErrorKind::NoTriangles => write!(f, "{path}: the model has no triangles"),
            LoadErrorKind::TooManyVertices => {
                write!(f, "{path}: the model has more than {} vertices", u32::MAX)
            }
            LoadErrorKind::Image(reason) => write!(f, "{path}: cannot decode the image: {}", Escaped(reason)),
            LoadErrorKind::Parser(reason) => write!(f, "{path}: the OBJ parser failed: {}", Escaped(reason)),
            LoadErrorKind::BadTriangle { triangle, value } if !value.is_finite() => {
                write!(f, "{path}, triangle {triangle}: coordinate {value} is not a finite number")
            }
            LoadErrorKind::BadTriangle { triangle, value } => {
                write!(
                    f,
                    "{path}, triangle {triangle}: coordinate {value:e} is beyond the limit of ±{COORDINATE_LIMIT:e}"
                )
            }
            LoadErrorKind::Format(problem) => write!(f, "{path}: {}", Escaped(problem)),
            LoadErrorKind::UnknownFormat(problem) => write!(f, "{path}: {}", Escaped(problem)),
        }
    }
}

impl std::error::Error for LoadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            LoadErrorKind::Io(e) => Some(e),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(kind: LoadErrorKind) -> String {
        LoadError::new("models/a.obj", kind).to_string()
    }

    #[test]
    fn every_kind_is_one_line_naming_the_file() {
        let kinds = [
            LoadErrorKind::Io(io::Error::new(io::ErrorKind::NotFound, "gone\nreally")),
            LoadErrorKind::Syntax { line: 3, problem: "bad \u{1b}[2J token".into() },
            LoadErrorKind::IndexOutOfRange { line: 4, element: Element::Normal, index: -7, defined: 2 },
            LoadErrorKind::IndexOutOfRange { line: 4, element: Element::Vertex, index: 0, defined: 2 },
            LoadErrorKind::BadCoordinate { line: 5, value: f32::NAN },
            LoadErrorKind::BadCoordinate { line: 5, value: 2e16 },
            LoadErrorKind::NoTriangles,
            LoadErrorKind::TooManyVertices,
            LoadErrorKind::Image("truncated".into()),
            LoadErrorKind::Parser("face parse error".into()),
        ];
        for kind in kinds {
            let t = text(kind);
            assert!(t.starts_with("models/a.obj"), "{t}");
            assert!(!t.chars().any(char::is_control), "{t:?}");
        }
    }

    #[test]
    fn messages_say_what_and_where() {
        assert_eq!(
            text(LoadErrorKind::IndexOutOfRange { line: 4, element: Element::TextureCoordinate, index: 9, defined: 2 }),
            "models/a.obj, line 4: texture coordinate index 9 is out of range (2 defined before it)"
        );
        assert_eq!(
            text(LoadErrorKind::BadCoordinate { line: 7, value: 2e16 }),
            "models/a.obj, line 7: coordinate 2e16 is beyond the limit of ±1e15"
        );
        assert_eq!(
            text(LoadErrorKind::BadCoordinate { line: 7, value: f32::INFINITY }),
            "models/a.obj, line 7: coordinate inf is not a finite number"
        );
        assert_eq!(text(LoadErrorKind::NoTriangles), "models/a.obj: the model has no triangles");
    }

    #[test]
    fn line_is_reported_for_line_errors_only() {
        assert_eq!(LoadError::syntax(Path::new("a.obj"), 12, "x").line(), Some(12));
        assert_eq!(LoadError::new("a.obj", LoadErrorKind::NoTriangles).line(), None);
    }
}
