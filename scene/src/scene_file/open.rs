//! What the command line names, loaded as a scene: a scene file, a model file, or the built-in model.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::{BUILTIN_PREFIX, CameraPlacement, SceneData, SceneFileError, SceneObject};
use crate::builtin::{BUILTIN_NAME, builtin_model};
use crate::escaped::{Escaped, not_among, path_text};
use crate::model::{LoadError, ModelCamera, ModelOptions, TextureImage, load_model};

/// A scene file: a path ending in `.toml` (any case). Everything else is read as a model.
pub fn is_scene_file(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("toml"))
}

/// Why what the command line names could not be loaded.
#[derive(Debug)]
pub enum OpenError {
    /// The scene file could not be read, checked or loaded.
    SceneFile(SceneFileError),
    /// The model (or the `--texture` image) could not be loaded.
    Model(LoadError),
}

impl fmt::Display for OpenError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::SceneFile(e) => e.fmt(f),
            Self::Model(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for OpenError {}

/// A loaded scene, with a name for it in messages.
#[derive(Debug)]
pub struct OpenedScene {
    /// The scene.
    pub data: SceneData,
    /// The file as given, or the built-in model's name (raw: escape before printing).
    pub name: String,
}

impl OpenedScene {
    /// Every warning of the scene and of its meshes, one line each, raw (escape before printing).
    pub fn warnings(&self) -> impl Iterator<Item = &String> {
        let meshes = self.data.objects.iter().flat_map(|o| o.model.warnings.iter());
        self.data.warnings.iter().chain(meshes)
    }
}

/// Loads `path` as a scene: a scene file ([`is_scene_file`]) with [`super::load`], any other file as a model
/// ([`load_model`] with `options`, then [`SceneData::from_model`]); the built-in model when `path` is `None`.
///
/// # Errors
/// [`OpenError`] naming the file and what is wrong.
pub fn open(path: Option<&Path>, options: &ModelOptions) -> Result<OpenedScene, OpenError> {
    match path {
        Some(path) if is_scene_file(path) => {
            let data = super::load(path).map_err(OpenError::SceneFile)?;
            Ok(OpenedScene { data, name: path.to_string_lossy().into_owned() })
        }
        Some(path) => {
            let model = load_model(path, options).map_err(OpenError::Model)?;
            let name = path.to_string_lossy().into_owned();
            Ok(OpenedScene { data: SceneData::from_model(model, path.to_path_buf()), name })
        }
        None => {
            let model = builtin_model().map_err(OpenError::Model)?;
            let data = SceneData::from_model(model, PathBuf::from(format!("{BUILTIN_PREFIX}spot")));
            Ok(OpenedScene { data, name: BUILTIN_NAME.into() })
        }
    }
}

impl SceneData {
    /// Views the scene through a camera its models give (glTF cameras, `--camera`): the first named `name`, else
    /// the one numbered `name` among every object's cameras in order (from 0), placed as its object is.
    ///
    /// # Errors
    /// A message naming the camera asked for and listing those there are (escaped), when none has that name or
    /// number, or it cannot be placed.
    pub fn use_file_camera(&mut self, name: &str) -> Result<(), String> {
        let all: Vec<(&SceneObject, usize, &ModelCamera)> =
            self.objects.iter().flat_map(|o| o.model.cameras.iter().enumerate().map(move |(k, c)| (o, k, c))).collect();
        let found = all
            .iter()
            .position(|(_, _, c)| c.name.as_deref() == Some(name))
            .or_else(|| name.parse::<usize>().ok().filter(|&i| i < all.len()));
        let Some(i) = found else {
            let labels = all.iter().map(|(_, k, c)| c.label(*k));
            return Err(not_among("camera", name, labels, "the models give none"));
        };
        let (object, _, camera) = all[i];
        let placed = camera
            .scene_camera(&object.transform)
            .ok_or_else(|| format!("camera {} cannot be placed: its transform has no direction", Escaped(name)))?;
        self.camera = CameraPlacement::Placed(placed);
        Ok(())
    }

    /// Uses the image at `path` as the diffuse texture of every object (`--texture`), over their own; an object
    /// without texture coordinates gets a warning, as the image cannot show on it.
    ///
    /// # Errors
    /// [`OpenError::Model`] when the image cannot be loaded.
    pub fn use_texture(&mut self, path: &Path) -> Result<(), OpenError> {
        let image = Arc::new(TextureImage::load(path).map_err(OpenError::Model)?);
        for (i, object) in self.objects.iter_mut().enumerate() {
            if object.model.uvs.is_none() {
                self.warnings.push(format!(
                    "object {} ({}) has no texture coordinates, so {} does not show on it",
                    i + 1,
                    Escaped(&object.mesh_path.to_string_lossy()),
                    path_text(path)
                ));
            }
            object.material.diffuse = Some(Arc::clone(&image));
        }
        self.images.push((path.to_path_buf(), image));
        Ok(())
    }
}
