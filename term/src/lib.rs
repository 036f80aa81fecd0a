//! rastty: load models and scene files, render them with `rastty-core`, and show them in a terminal or write PNG
//! files.
//!
//! One road from a file to the terminal, the same for a model and a scene file:
//!
//! | step | module | what happens |
//! |---|---|---|
//! | file | [`model`], [`scene_file`] | a model (OBJ with its MTL and textures, STL or glTF) or a TOML scene file, read by [`input_file`], checked and loaded; [`scene_file::open`] takes either |
//! | scene | [`scene_file`], [`scene_render`] | a [`scene_file::SceneData`] (a model alone is one fitted object under the viewer's camera and lights), prepared once ([`scene_render::PreparedScene`]) |
//! | frame | [`scene_render`] | a plan of passes (shadow maps, forward draws, ambient occlusion) for a camera ([`scene_render::Orbit`]) and the look asked for, run in bands of rows on threads |
//! | cells | [`screen`], [`viewer`] | the frame as terminal cells, diffed against the last one and written; or a PNG file ([`png_file`]) |
//! | files | [`png_file`], [`turntable_export`], [`render_stats`] | `rastty render`: the frame as a PNG file, or a turn of frames ([`turntable_export::Turntable`]) as an animated GIF, an APNG or numbered PNG files, written as they are rendered; `--stats`, the counts and times |
//!
//! Beside them: [`builtin`] (the model compiled into the binary), [`input_file`] (the one reader of every file the
//! program is given: regular files only, size-capped), [`escaped`] (text from input files made safe for a
//! terminal) and [`graphics`] (the frame as one image in the kitty, Sixel or iTerm2 protocol instead of
//! cells, for terminals that show pixels).

pub mod builtin;
pub mod escaped;
pub mod graphics;
pub mod input_file;
pub mod model;
pub mod png_file;
pub mod render_stats;
pub mod scene_file;
pub mod scene_render;
pub mod screen;
pub mod turntable_export;
pub mod viewer;
