//! A model file of any type the program reads: its type recognised from its contents first and its extension
//! second, then loaded by the loader for that type.

use std::fmt;
use std::path::Path;

use super::error::{LoadError, LoadErrorKind};
use super::gltf_loader::load_gltf_bytes;
use super::loaded_model::Model;
use super::obj_loader::load_obj_bytes;
use super::resolver::Directory;
use super::stl_loader::{is_ascii_stl, is_binary_stl, load_stl_bytes};
use crate::input_file::read_input_file;

/// The model types read, for messages.
pub const SUPPORTED_MODELS: &str = "OBJ (.obj), STL (.stl, binary or ASCII) and glTF 2.0 (.gltf, .glb)";

/// The statements an OBJ file may start with (after comments and blank lines).
const OBJ_KEYWORDS: [&str; 14] =
    ["v", "vt", "vn", "vp", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl", "usemap", "maplib"];

/// A type of model file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelFormat {
    /// Wavefront OBJ, with MTL libraries and textures beside it.
    Obj,
    /// STL, binary or ASCII.
    Stl,
    /// glTF 2.0: JSON (`.gltf`) or binary (`.glb`).
    Gltf,
}

impl fmt::Display for ModelFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ModelFormat::Obj => "OBJ",
            ModelFormat::Stl => "STL",
            ModelFormat::Gltf => "glTF",
        })
    }
}

impl ModelFormat {
    /// The type of the file `path` holding `bytes`: from the contents (GLB's magic, a binary STL's length for its
    /// count, JSON's brace, ASCII STL's `solid`, an OBJ statement at the start), else from the extension; `None`
    /// when neither says.
    pub fn detect(path: &Path, bytes: &[u8]) -> Option<Self> {
        let text = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes).trim_ascii_start();
        if bytes.starts_with(b"glTF") || text.starts_with(b"{") {
            return Some(ModelFormat::Gltf);
        }
        if is_binary_stl(bytes) || is_ascii_stl(bytes) {
            return Some(ModelFormat::Stl);
        }
        if starts_like_obj(text) {
            return Some(ModelFormat::Obj);
        }
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "obj" => Some(ModelFormat::Obj),
            "stl" => Some(ModelFormat::Stl),
            "gltf" | "glb" => Some(ModelFormat::Gltf),
            _ => None,
        }
    }
}

/// Whether the first statement of `text` (comments and blank lines skipped) is an OBJ statement.
fn starts_like_obj(text: &[u8]) -> bool {
    let statement =
        text.split(|&b| b == b'\n').map(<[u8]>::trim_ascii).find(|line| !line.is_empty() && !line.starts_with(b"#"));
    let Some(first) = statement.and_then(|line| line.split(u8::is_ascii_whitespace).next()) else { return false };
    OBJ_KEYWORDS.iter().any(|keyword| keyword.as_bytes() == first)
}

/// How models are loaded, where their types leave a choice.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ModelOptions {
    /// STL: `None` for flat faces, else the largest angle in degrees between faces whose shared corners get one
    /// normal.
    pub smooth_angle: Option<f32>,
}

/// Loads the model file at `path`, of any type in [`SUPPORTED_MODELS`], read with
/// [`read_input_file`]; the files an OBJ or glTF file names (MTL libraries, textures, buffers, images) are read
/// from its folder, under the rule of [`Directory`].
///
/// # Errors
/// [`LoadErrorKind::Io`] when the file cannot be read (or is not a regular file, or is too large),
/// [`LoadErrorKind::UnknownFormat`] when it is of no type read here, and the errors of the type's loader.
pub fn load_model(path: impl AsRef<Path>, options: &ModelOptions) -> Result<Model, LoadError> {
    let path = path.as_ref();
    let bytes = read_input_file(path).map_err(|e| LoadError::new(path, LoadErrorKind::Io(e)))?;
    match ModelFormat::detect(path, &bytes) {
        Some(ModelFormat::Obj) => load_obj_bytes(path, &bytes, &Directory::new(model_folder(path))),
        Some(ModelFormat::Stl) => load_stl_bytes(path, &bytes, options.smooth_angle),
        Some(ModelFormat::Gltf) => load_gltf_bytes(path, &bytes, &Directory::new(model_folder(path))),
        None => {
            let problem = format!("not a model file this program reads ({SUPPORTED_MODELS})");
            Err(LoadError::new(path, LoadErrorKind::UnknownFormat(problem)))
        }
    }
}

/// The folder of the model file at `path`, which the files it names are read from.
fn model_folder(path: &Path) -> &Path {
    path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn types_come_from_the_contents_before_the_extension() {
        let detect = |name: &str, bytes: &[u8]| ModelFormat::detect(Path::new(name), bytes);
        let mut binary_stl = vec![0u8; 84 + 50];
        binary_stl[80] = 1;
        assert_eq!(detect("part.bin", &binary_stl), Some(ModelFormat::Stl));
        assert_eq!(detect("part.obj", b"solid cube\nfacet normal 0 0 1\n"), Some(ModelFormat::Stl));
        assert_eq!(detect("spot.txt", b"# exported\n\nv 0 0 0\n"), Some(ModelFormat::Obj));
        assert_eq!(detect("spot.obj", b"mtllib spot.mtl\n"), Some(ModelFormat::Obj));
        assert_eq!(detect("scene.data", b"glTF\x02\0\0\0"), Some(ModelFormat::Gltf));
        assert_eq!(detect("scene", b"\xef\xbb\xbf  {\"asset\": {}}"), Some(ModelFormat::Gltf));
        // Contents that say nothing: the extension, in any case.
        assert_eq!(detect("empty.OBJ", b""), Some(ModelFormat::Obj));
        assert_eq!(detect("broken.Stl", &[1, 2, 3]), Some(ModelFormat::Stl));
        assert_eq!(detect("photo.png", b"\x89PNG\r\n"), None);
        assert_eq!(detect("notes", b"hello\n"), None);
    }
}
