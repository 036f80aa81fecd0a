//! rastty: load models, render them with `rastty-core`, and show them in a terminal or write PNG files.
//!
//! | module | holds |
//! |---|---|
//! | [`model`] | OBJ/MTL/texture loading into a [`model::Model`] |
//! | [`builtin`] | the model compiled into the binary |
//! | [`escaped`] | text from input files made safe for a terminal |
//! | [`scene`] | camera, lights and shading choices; drawing a model into a core target |
//! | [`scene_file`] | TOML scene files: camera, lights, placed and textured meshes; parsed, checked and loaded |
//! | [`scene_render`] | drawing scene files: a plan of passes (shadow maps, forward draws, ambient occlusion), explained and run |
//! | [`headless`] | `rastty render`: a scene to a PNG file |
//! | [`png_file`] | writing PNG files safely |
//! | [`screen`] | terminal cells, colour modes and the frame-diff encoder |
//! | [`viewer`] | the interactive terminal viewer |

pub mod builtin;
pub mod escaped;
pub mod headless;
pub mod model;
pub mod png_file;
pub mod scene;
pub mod scene_file;
pub mod scene_render;
pub mod screen;
pub mod viewer;
