//! Scene files: a camera, lights and any number of placed, textured meshes, written in TOML; and a model file
//! loaded as the scene of that one model ([`SceneData::from_model`]), so that one renderer draws both ([`open`]).
//!
//! [`load`] reads a scene file, checks it, and loads every mesh and image it names, giving a [`SceneData`] of
//! owned data. [`parse`] only parses and checks text (no file is touched), giving a [`SceneFile`] whose
//! [`SceneFile::load`] does the rest. Every problem is one [`SceneFileError`] naming the file, the line and column,
//! and the key: `scene.toml:7:7: camera.fov: must be between 0 and 180 degrees, got 200`.
//!
//! The format, every key with its default and rule, is in `docs/scene-format.md`.
//!
//! This module is the format and the loader; [`crate::scene_render`] draws a loaded scene
//! (`rastty render SCENE.toml -o OUT.png`, `rastty render SCENE.toml --explain`, `rastty SCENE.toml`).
//!
//! # Example
//! ```
//! use rastty_scene::scene_file::{CameraPlacement, SceneLightKind, SceneProjection, parse};
//!
//! let text = r#"
//! [camera]
//! position = [0, 1, 4]
//! target = [0, 0, 0]
//! fov = 40
//!
//! [[lights]]
//! type = "directional"
//! direction = [0, -1, 0]
//! shadows = true
//!
//! [[objects]]
//! mesh = "builtin:spot"
//! scale = 2
//! "#;
//! let scene = parse(text, "example.toml").unwrap().load().unwrap();
//! let CameraPlacement::Placed(camera) = scene.camera else { panic!("a placed camera") };
//! assert_eq!(camera.projection, SceneProjection::Perspective { fov_degrees: 40.0 });
//! assert!(matches!(scene.lights[0].kind, SceneLightKind::Directional { .. }));
//! assert!(scene.lights[0].shadows);
//! assert!(scene.objects[0].model.triangle_count() > 0);
//!
//! let bad = text.replace("fov = 40", "fov = 200");
//! let error = parse(bad, "bad.toml").unwrap_err();
//! assert_eq!(error.to_string(), "bad.toml:5:7: camera.fov: must be between 0 and 180 degrees, got 200");
//! ```

pub mod defaults;
mod error;
mod hex_color;
mod key_path;
mod load;
mod loaded;
mod location;
mod model_scene;
mod open;
pub mod schema;
mod transform;
mod validate;

pub use error::{SceneFileError, SceneFileErrorKind};
pub use hex_color::parse_hex_color;
pub use loaded::{
    CameraPlacement, FramedCamera, LightFalloff, ObjectAnimation, ObjectMaterial, ObjectNormalMap, SceneCamera,
    SceneData, SceneLight, SceneLightKind, SceneObject, SceneProjection,
};
pub use location::Location;
pub use open::{OpenError, OpenedScene, is_scene_file, open};
pub use schema::{LightSpace, NameOrIndex, NormalSpaceSpec, SceneSpec};
pub use transform::object_transform;
pub(crate) use validate::BUILTIN_PREFIX;

use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::de::{DeTable, Deserializer};

use crate::input_file::read_input_file;
use key_path::{child, key_at};
use validate::{Checker, validate};

/// A parsed and checked scene file: its schema values, and its text for placing later errors (a file that cannot
/// be loaded is reported at the key that names it).
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// Where the text came from: paths in it are relative to this file's directory.
    pub origin: PathBuf,
    /// The values, as written, with their places in the text.
    pub spec: SceneSpec,
    text: String,
}

impl SceneFile {
    /// The text the file was parsed from.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Loads every mesh and image the file names, relative to the directory of [`Self::origin`].
    ///
    /// # Errors
    /// [`SceneFileErrorKind::Mesh`] or [`SceneFileErrorKind::Image`], at the key that names the file, when a file
    /// is missing or cannot be loaded.
    pub fn load(&self) -> Result<SceneData, SceneFileError> {
        load::load_scene_file(self)
    }
}

/// Reads, checks and loads the scene file at `path`.
///
/// # Errors
/// [`SceneFileErrorKind::Io`] when the file cannot be read, and everything [`parse`] and [`SceneFile::load`]
/// report.
pub fn load(path: impl AsRef<Path>) -> Result<SceneData, SceneFileError> {
    let path = path.as_ref();
    let bytes = read_input_file(path).map_err(|e| SceneFileError::new(path, None, None, SceneFileErrorKind::Io(e)))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let location = Location::of_offset(&String::from_utf8_lossy(valid), valid.len());
        SceneFileError::new(path, Some(location), None, SceneFileErrorKind::Syntax("the file is not UTF-8 text".into()))
    })?;
    parse(text, path)?.load()
}

/// Parses and checks scene text without touching the file system. `origin` names the file in errors and is the
/// base of the relative paths when the result is loaded.
///
/// # Errors
/// [`SceneFileErrorKind::Syntax`] for text that is not TOML, [`SceneFileErrorKind::Schema`] for unknown keys,
/// wrong types and missing keys, [`SceneFileErrorKind::Invalid`] for values out of range or contradicting each
/// other; each with the line, column and key.
pub fn parse(text: impl Into<String>, origin: impl AsRef<Path>) -> Result<SceneFile, SceneFileError> {
    let text = text.into();
    let origin = origin.as_ref().to_path_buf();
    let spec = deserialize(&text, &origin)?;
    validate(&Checker { file: &origin, text: &text }, &spec)?;
    Ok(SceneFile { origin, spec, text })
}

/// TOML text to the schema, with syntax and schema errors placed and keyed.
fn deserialize(text: &str, origin: &Path) -> Result<SceneSpec, SceneFileError> {
    let (tree, syntax) = DeTable::parse_recoverable(text);
    if let Some(e) = syntax.first() {
        let pos = e.span().map_or(0, |s| s.start);
        let key = key_at(text, tree.get_ref(), pos);
        let kind = SceneFileErrorKind::Syntax(e.message().to_string());
        return Err(SceneFileError::new(origin, Some(Location::of_offset(text, pos)), key, kind));
    }
    SceneSpec::deserialize(Deserializer::from(tree)).map_err(|e| {
        let span = e.span();
        let pos = span.as_ref().map_or(0, |s| s.start);
        // The tree was consumed; parse again (the text is valid TOML) to find the key.
        // An empty span is the document itself (a missing top-level key): no key to find.
        let key = span
            .as_ref()
            .filter(|s| !s.is_empty())
            .and_then(|_| DeTable::parse(text).ok())
            .and_then(|tree| key_at(text, tree.get_ref(), pos));
        let (key, message) = schema_message(e.message(), key);
        let location = span.map_or(Location::START, |s| Location::of_span(text, &s));
        SceneFileError::new(origin, Some(location), key, SceneFileErrorKind::Schema(message))
    })
}

/// `serde`'s message reworded for a scene file's author, and the key it is about: a missing key is named as the
/// table's path plus the key (its location is the table's header); "field" becomes "key"; Rust type names become
/// TOML's.
fn schema_message(message: &str, key: Option<String>) -> (Option<String>, String) {
    if let Some(name) = message.strip_prefix("missing field `").and_then(|m| m.strip_suffix('`')) {
        let path = child(key.as_deref().unwrap_or(""), name);
        return (Some(path), "required, but missing".to_string());
    }
    let mut message = message.to_string();
    if let Some(rest) = message.strip_prefix("unknown field `") {
        // "unknown field `x`, expected one of `a`, `b`": the key is in the path already.
        message = match rest.split_once("`, ") {
            Some((_, expected)) => format!("unknown key, {expected}"),
            None => "unknown key".to_string(),
        };
    }
    let words = [
        ("expected f32", "expected a number"),
        ("expected a sequence", "expected an array"),
        ("invalid type: map", "invalid type: table"),
        ("invalid type: sequence", "invalid type: array"),
    ];
    for (rust, toml) in words {
        message = message.replace(rust, toml);
    }
    (key, message)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_messages_are_reworded() {
        assert_eq!(
            schema_message("missing field `target`", Some("camera".into())),
            (Some("camera.target".into()), "required, but missing".into())
        );
        assert_eq!(
            schema_message("missing field `camera`", None),
            (Some("camera".into()), "required, but missing".into())
        );
        assert_eq!(
            schema_message("unknown field `fovv`, expected one of `position`, `fov`", Some("camera.fovv".into())).1,
            "unknown key, expected one of `position`, `fov`"
        );
        assert_eq!(
            schema_message("invalid type: string \"x\", expected f32", None).1,
            "invalid type: string \"x\", expected a number"
        );
    }
}
