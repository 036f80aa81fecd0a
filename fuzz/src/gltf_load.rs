//! The `gltf_load` target: arbitrary bytes as a glTF file (JSON or binary), through the model type detection
//! (`rastty_scene::model::ModelFormat::detect`) and `rastty_scene::model::load_gltf_bytes`, with no files beside it (a URI
//! that is not a `data:` URI is missing); a model that loads is checked and rendered once
//! ([`crate::model_checks`]).
//!
//! Input layout: `[config: u8] [glTF bytes: the rest]`; the config is [`render_once`]'s.

use std::path::Path;

use rastty_scene::model::{ModelFormat, NoFiles, load_gltf_bytes};

use crate::model_checks::{check_load_error, check_model, render_once};

/// Loads, checks and renders one input (a failure is a panic). Returns whether the model loaded.
pub fn run(data: &[u8]) -> bool {
    let Some((&config, gltf)) = data.split_first() else { return false };
    let name = Path::new("fuzz.glb");
    let _ = ModelFormat::detect(name, gltf);
    match load_gltf_bytes(name, gltf, &NoFiles) {
        Ok(model) => {
            check_model(&model);
            render_once(model, config, "fuzz.glb");
            true
        }
        Err(e) => {
            check_load_error(&e);
            false
        }
    }
}

/// An input in the layout [`run`] reads.
pub fn encode(config: u8, gltf: &[u8]) -> Vec<u8> {
    let mut out = vec![config];
    out.extend_from_slice(gltf);
    out
}
