//! rastty-scene: models and scene files rendered with `rastty-core`, on threads, into frames or PNG files.
//!
//! The road from a file to a frame, the same for a model and a scene file:
//!
//! | step | module | what happens |
//! |---|---|---|
//! | file | [`model`], [`scene_file`] | a model (OBJ with its MTL and textures, STL or glTF) or a TOML scene file, read by [`input_file`], checked and loaded; [`scene_file::open`] takes either |
//! | scene | [`scene_file`], [`scene_render`] | a [`scene_file::SceneData`] (a model alone is one fitted object under the viewer's camera and lights), prepared once ([`scene_render::PreparedScene`]) |
//! | frame | [`scene_render`] | a plan of passes (shadow maps, forward draws, ambient occlusion) for a camera ([`scene_render::Orbit`]) and the look asked for ([`scene_render::ScenePlan`]), run in bands of rows on threads ([`scene_render::SceneRenderer`]); or at once, supersampled, into an image ([`scene_render::render_scene_image`]) |
//! | file out | [`png_file`] | the frame as a PNG file, written atomically |
//!
//! Beside them: [`builtin`] (the model compiled in, `builtin:spot`), [`input_file`] (the one reader of every file
//! given: regular files only, size-capped) and [`escaped`] (text from input files made safe to print: every error
//! and label that quotes a file's text goes through it).
//!
//! ```
//! use rastty_scene::model::ModelOptions;
//! use rastty_scene::scene_file::open;
//! use rastty_scene::scene_render::{PlanOptions, PreparedScene, render_scene_image};
//!
//! // The built-in model (a path instead: a model or a scene file).
//! let opened = open(None, &ModelOptions::default())?;
//! let scene = PreparedScene::new(opened.data)?;
//! let image = render_scene_image(&scene, &scene.camera(), (64, 48), 1, &PlanOptions::default())?;
//! assert_eq!(image.pixels.len(), 64 * 48);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod builtin;
pub mod environment;
pub mod escaped;
pub mod input_file;
pub mod model;
pub mod png_file;
pub mod scene_file;
pub mod scene_render;
