//! The scene library's integration tests, one binary (each file here is a module declared below). Run one subject
//! with `cargo test -p rastty-scene --test integration MODULE::`.

mod common;
mod model_loading;
mod scene_file;
mod scene_render;
