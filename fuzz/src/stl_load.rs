//! The `stl_load` target: arbitrary bytes as an STL file, through the model type detection
//! (`rastty_scene::model::ModelFormat::detect`) and `rastty_scene::model::load_stl_bytes`; a model that loads is checked and
//! rendered once ([`crate::model_checks`]).
//!
//! Input layout: `[config: u8] [STL bytes: the rest]`. The config's top bit asks for smooth normals, at an angle of
//! `(config & 0x7f) * 180 / 127` degrees; its low bits are [`render_once`]'s.

use std::path::Path;

use rastty_scene::model::{ModelFormat, load_stl_bytes};

use crate::model_checks::{check_load_error, check_model, render_once};

/// Loads, checks and renders one input (a failure is a panic). Returns whether the model loaded.
pub fn run(data: &[u8]) -> bool {
    let Some((&config, stl)) = data.split_first() else { return false };
    let name = Path::new("fuzz.stl");
    // Recognising the type reads the bytes too; any answer is fine, a panic is not.
    let _ = ModelFormat::detect(name, stl);
    let smooth_angle = (config & 0x80 != 0).then(|| f32::from(config & 0x7f) * (180.0 / 127.0));
    match load_stl_bytes(name, stl, smooth_angle) {
        Ok(model) => {
            check_model(&model);
            assert!(model.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-3), "a normal that is not unit length");
            assert!(model.parts.len() == 1 && model.uvs.is_none() && model.materials.is_empty());
            render_once(model, config, "fuzz.stl");
            true
        }
        Err(e) => {
            check_load_error(&e);
            false
        }
    }
}

/// An input in the layout [`run`] reads.
pub fn encode(config: u8, stl: &[u8]) -> Vec<u8> {
    let mut out = vec![config];
    out.extend_from_slice(stl);
    out
}
