//! The built-in model: Spot the cow by Keenan Crane (public domain; see `assets/spot/NOTICE.md`), compiled into
//! the binary so that `rastty` with no arguments has something to show.

use std::path::Path;

use crate::model::{LoadError, Model, NoFiles, TextureImage, load_obj_bytes};

const SPOT_OBJ: &[u8] = include_bytes!("../../assets/spot/spot.obj");
const SPOT_TEXTURE: &[u8] = include_bytes!("../../assets/spot/spot_texture.png");

/// The name the built-in model goes by in messages.
pub const BUILTIN_NAME: &str = "built-in Spot";

/// Loads the built-in model with its texture, turned to face `+z` (the camera) — Spot's file has her facing
/// `-z`.
///
/// # Errors
/// Only if the embedded files were damaged at build time.
pub fn builtin_model() -> Result<Model, LoadError> {
    let mut model = load_obj_bytes(BUILTIN_NAME, SPOT_OBJ, &NoFiles)?;
    model.set_texture(TextureImage::decode(Path::new("spot_texture.png"), SPOT_TEXTURE)?);
    // Half a turn about the vertical axis: a rotation, so windings and normals stay consistent.
    for v in model.positions.iter_mut().chain(model.normals.iter_mut()) {
        (v.x, v.z) = (-v.x, -v.z);
    }
    Ok(model)
}
