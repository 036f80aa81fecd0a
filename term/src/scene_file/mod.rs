//! Scene files: a camera, lights and any number of placed, textured meshes, written in TOML.
//!
//! [`load`] reads a scene file, checks it, and loads every mesh and image it names, giving a [`SceneData`] of
//! owned data. [`parse`] only parses and checks text (no file is touched), giving a [`SceneFile`] whose
//! [`SceneFile::load`] does the rest. Every problem is one [`SceneFileError`] naming the file, the line and column,
//! and the key: `scene.toml:7:7: camera.fov: must be between 0 and 180 degrees, got 200`.
//!
//! # The format
//!
//! ```toml
//! background = "20242c"          # optional, RRGGBB
//! ambient = [0.1, 0.1, 0.12]     # optional ambient light colour
//! ambient_occlusion = true       # optional, default false
//!
//! [camera]
//! position = [2.5, 1.8, 3.5]
//! target = [0, 0.6, 0]
//! up = [0, 1, 0]                 # default [0, 1, 0]
//! fov = 40                       # vertical, degrees; or `orthographic = HEIGHT`, not both
//! near = 0.1                     # optional, 0 < near < far
//! far = 50                       # optional
//!
//! [[lights]]
//! type = "directional"
//! direction = [-1, -2, -1]       # the way the light travels: from the light toward the scene
//! color = [1, 0.95, 0.9]         # default [1, 1, 1]
//! intensity = 1.2                # default 1
//! shadows = true                 # default false
//!
//! [[lights]]
//! type = "point"
//! position = [0, 3, 2]
//!
//! [[objects]]
//! mesh = "../spot/spot.obj"      # relative to this file; or "builtin:spot"
//! translate = [0, 0.74, 0]       # default [0, 0, 0]
//! rotate = [0, 180, 0]           # degrees about X, then Y, then Z; default [0, 0, 0]
//! scale = 1                      # or [x, y, z]; default 1
//!
//! [objects.material]             # every key optional
//! color = [1, 1, 1]              # overrides the MTL's Kd
//! diffuse = "../spot/spot_texture.png"   # overrides the MTL's map_Kd
//! normal_map = "bumps.png"
//! normal_space = "tangent"       # or "object"; needs normal_map
//! specular = 0.3                 # or [r, g, b]
//! shininess = 32
//! specular_map = "shine.png"
//! glow_map = "glow.png"
//! filter = "bilinear"            # or "nearest"
//! wrap = "repeat"                # or "clamp"
//! ```
//!
//! | key | value | default | rule |
//! |---|---|---|---|
//! | `background` | `"RRGGBB"` | `16191f` | six hex digits, `#` allowed |
//! | `ambient` | `[r, g, b]` | [`crate::scene::AMBIENT`] | finite, not negative |
//! | `ambient_occlusion` | bool | `false` | |
//! | `camera.position`, `camera.target` | `[x, y, z]` | required | finite, not the same point |
//! | `camera.up` | `[x, y, z]` | `[0, 1, 0]` | not zero |
//! | `camera.fov` | degrees | | `0 < fov < 180`; exactly one of `fov` and `orthographic` |
//! | `camera.orthographic` | world units | | the view's height, positive |
//! | `camera.near`, `camera.far` | distance | renderer's | positive, `near < far` |
//! | `lights[].type` | `"directional"`, `"point"` | required | |
//! | `lights[].direction` | `[x, y, z]` | | directional only, required there; the direction of travel; not zero |
//! | `lights[].position` | `[x, y, z]` | | point only, required there |
//! | `lights[].color` | `[r, g, b]` | `[1, 1, 1]` | finite, not negative |
//! | `lights[].intensity` | number | `1` | finite, not negative |
//! | `lights[].shadows` | bool | `false` | |
//! | `objects[].mesh` | path or `"builtin:spot"` | required | relative to the scene file |
//! | `objects[].translate` | `[x, y, z]` | `[0, 0, 0]` | finite |
//! | `objects[].rotate` | degrees `[x, y, z]` | `[0, 0, 0]` | applied about X, then Y, then Z |
//! | `objects[].scale` | number or `[x, y, z]` | `1` | positive |
//! | `objects[].material.color` | `[r, g, b]` | the MTL's `Kd` | 0 to 1 |
//! | `objects[].material.diffuse` | image path | the MTL's `map_Kd` | |
//! | `objects[].material.normal_map` | image path | none | |
//! | `objects[].material.normal_space` | `"tangent"`, `"object"` | `"tangent"` | only with `normal_map` |
//! | `objects[].material.specular` | number or `[r, g, b]` | renderer's | 0 to 1 |
//! | `objects[].material.shininess` | number | renderer's | positive |
//! | `objects[].material.specular_map`, `glow_map` | image path | none | |
//! | `objects[].material.filter` | `"nearest"`, `"bilinear"` | `"bilinear"` | |
//! | `objects[].material.wrap` | `"repeat"`, `"clamp"` | `"repeat"` | |
//!
//! The types of [`schema`] document every key. Unknown keys are errors. Paths are relative to the scene file's
//! directory. A mesh is placed by `translate * rotate_z * rotate_y * rotate_x * scale` ([`object_transform`]) in its
//! own coordinates, without the viewer's fitting. Each mesh file and each image file the scene names is loaded once,
//! however many objects or keys name it (files are told apart by their canonical paths); textures named by a
//! mesh's own MTL file are decoded by the OBJ loader, separately. Normal, specular and glow maps are loaded as
//! images ([`crate::model::TextureImage`], RGB).
//!
//! This module is the format and the loader; [`crate::scene_render`] draws a loaded scene
//! (`rastty render SCENE.toml -o OUT.png`, `rastty render SCENE.toml --explain`, `rastty SCENE.toml`).
//!
//! # Example
//! ```
//! use rastty::scene_file::{LightKind, Projection, parse};
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
//! assert_eq!(scene.camera.projection, Projection::Perspective { fov_degrees: 40.0 });
//! assert!(matches!(scene.lights[0].kind, LightKind::Directional { .. }));
//! assert!(scene.lights[0].shadows);
//! assert!(scene.objects[0].model.triangle_count() > 0);
//!
//! let bad = text.replace("fov = 40", "fov = 200");
//! let error = parse(bad, "bad.toml").unwrap_err();
//! assert_eq!(error.to_string(), "bad.toml:5:7: camera.fov: must be between 0 and 180 degrees, got 200");
//! ```

mod error;
mod key_path;
mod load;
mod loaded;
mod location;
pub mod schema;
mod transform;
mod validate;

pub use error::{SceneFileError, SceneFileErrorKind};
pub use loaded::{LightKind, NormalMap, ObjectMaterial, Projection, SceneCamera, SceneData, SceneLight, SceneObject};
pub use location::Location;
pub use schema::{NormalSpace, SceneSpec};
pub use transform::object_transform;
pub use validate::{BUILTIN_MODELS, BUILTIN_PREFIX};

use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::de::{DeTable, Deserializer};

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
    let bytes = std::fs::read(path).map_err(|e| SceneFileError::new(path, None, None, SceneFileErrorKind::Io(e)))?;
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
    fn the_format_shown_in_the_module_docs_is_a_valid_scene() {
        let source = include_str!("mod.rs");
        let lines: Vec<&str> = source.lines().map_while(|l| l.strip_prefix("//!")).collect();
        let start = lines.iter().position(|l| l.trim() == "```toml").unwrap() + 1;
        let end = start + lines[start..].iter().position(|l| l.trim() == "```").unwrap();
        let text: Vec<&str> = lines[start..end].iter().map(|l| l.strip_prefix(' ').unwrap_or(l)).collect();
        let file = parse(text.join("\n"), "docs.toml").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(file.spec.lights.len(), 2);
        assert!(file.spec.objects.get_ref()[0].get_ref().material.glow_map.is_some());
    }

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
