//! The `rastty` program's integration tests: one binary, one module per subject (listed below).
//!
//! One test binary per crate links once instead of once per file (`autotests = false` in Cargo.toml: a new
//! file here is a module declared below). Run one subject with `cargo test -p rastty --test integration MODULE::`.

mod cli;
mod common;
mod environment;
mod gltf_animation;
mod gltf_lights;
mod gltf_models;
mod graphics_decoders;
mod readme_picture;
mod scene_cli;
mod screen_cells;
mod screen_encoder;
mod screen_palette;
mod snapshot;
mod stl_models;
mod turntable_export;
mod viewer_graphics;
mod viewer_lifecycle;
mod viewer_ssh;
mod viewer_tmux;
