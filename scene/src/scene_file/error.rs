//! Why a scene file could not be read, parsed, validated or loaded: one line naming the file, the line and column,
//! and the key.

use std::fmt;
use std::io;
use std::path::PathBuf;

use super::location::Location;
use crate::escaped::{Escaped, path_text};
use crate::model::LoadError;

/// A scene file that could not be used.
///
/// [`Display`](fmt::Display) gives one line, `FILE:LINE:COLUMN: KEY: message`, for example
/// `scene.toml:7:7: camera.fov: must be between 0 and 180 degrees, got 200`. The location is left out only when
/// the scene file itself cannot be read, and the key when the problem is not about one key (most syntax errors).
/// Control characters from file names, keys and quoted file text are escaped, so the line is safe to print on a
/// terminal.
#[derive(Debug)]
pub struct SceneFileError {
    /// The scene file (as given to [`super::load`], or the origin given to [`super::parse`]).
    pub file: PathBuf,
    /// Where in the scene file: the offending key or value, or the header of the table that lacks a key; the start
    /// of the file for a missing top-level key.
    pub location: Option<Location>,
    /// The dotted path of the key concerned (`camera.fov`, `objects[1].material.diffuse`), raw: it may hold any
    /// character the file's quoted keys hold.
    pub key: Option<String>,
    /// What went wrong.
    pub kind: SceneFileErrorKind,
}

/// What went wrong with a scene file.
#[derive(Debug)]
#[non_exhaustive]
pub enum SceneFileErrorKind {
    /// The scene file could not be read; holds the operating system's reason.
    Io(io::Error),
    /// The text is not valid TOML (or not UTF-8); holds the parser's message.
    Syntax(String),
    /// The TOML does not fit the scene schema: an unknown key, a value of the wrong type, a missing key, an
    /// unknown name (`type = "spot"`). Holds the message.
    Schema(String),
    /// A value of the right type that the scene cannot use (out of range, not finite, contradicting another key).
    Invalid(String),
    /// A mesh named by the scene could not be loaded.
    Mesh {
        /// The mesh file as resolved against the scene file's directory (`builtin:spot` for the built-in model).
        path: PathBuf,
        /// The loader's error, which names the file (and the line of the OBJ file, when there is one).
        error: Box<LoadError>,
    },
    /// An image (texture or map) named by the scene could not be loaded.
    Image {
        /// The image file as resolved against the scene file's directory.
        path: PathBuf,
        /// The loader's error, which names the file.
        error: Box<LoadError>,
    },
}

impl SceneFileError {
    /// An error of `kind` at `location` and `key` of `file`.
    pub fn new(
        file: impl Into<PathBuf>,
        location: Option<Location>,
        key: Option<String>,
        kind: SceneFileErrorKind,
    ) -> Self {
        Self { file: file.into(), location, key, kind }
    }

    /// The message alone, without file, location and key (control characters not yet escaped).
    pub fn message(&self) -> String {
        match &self.kind {
            SceneFileErrorKind::Io(e) => format!("cannot read the scene file: {e}"),
            SceneFileErrorKind::Syntax(m) => format!("TOML syntax error: {m}"),
            SceneFileErrorKind::Schema(m) | SceneFileErrorKind::Invalid(m) => m.clone(),
            SceneFileErrorKind::Mesh { error, .. } => format!("cannot load the mesh: {error}"),
            SceneFileErrorKind::Image { error, .. } => format!("cannot load the image: {error}"),
        }
    }
}

impl fmt::Display for SceneFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", path_text(&self.file))?;
        if let Some(location) = self.location {
            write!(f, ":{location}")?;
        }
        if let Some(key) = &self.key {
            write!(f, ": {}", Escaped(key))?;
        }
        write!(f, ": {}", Escaped(&self.message()))
    }
}

impl std::error::Error for SceneFileError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            SceneFileErrorKind::Io(e) => Some(e),
            SceneFileErrorKind::Mesh { error, .. } | SceneFileErrorKind::Image { error, .. } => Some(&**error),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::LoadErrorKind;

    #[test]
    fn one_line_with_file_location_and_key() {
        let e = SceneFileError::new(
            "scenes/a.toml",
            Some(Location { line: 7, column: 7 }),
            Some("camera.fov".into()),
            SceneFileErrorKind::Invalid("must be between 0 and 180 degrees, got 200".into()),
        );
        assert_eq!(e.to_string(), "scenes/a.toml:7:7: camera.fov: must be between 0 and 180 degrees, got 200");
    }

    #[test]
    fn control_characters_are_escaped_everywhere() {
        let e = SceneFileError::new(
            "a\nb.toml",
            Some(Location::START),
            Some("x\u{1b}[2J".into()),
            SceneFileErrorKind::Schema("unknown key \"\u{7}\"".into()),
        );
        let text = e.to_string();
        assert!(!text.chars().any(char::is_control), "{text:?}");
        assert_eq!(text, "a\\nb.toml:1:1: x\\u{1b}[2J: unknown key \"\\u{7}\"");
    }

    #[test]
    fn loader_errors_are_the_source() {
        let error = LoadError::new("m/x.obj", LoadErrorKind::NoTriangles);
        let e = SceneFileError::new(
            "s.toml",
            Some(Location { line: 3, column: 8 }),
            Some("objects[0].mesh".into()),
            SceneFileErrorKind::Mesh { path: "m/x.obj".into(), error: Box::new(error) },
        );
        assert_eq!(
            e.to_string(),
            "s.toml:3:8: objects[0].mesh: cannot load the mesh: m/x.obj: the model has no triangles"
        );
        assert!(std::error::Error::source(&e).is_some());
    }
}
