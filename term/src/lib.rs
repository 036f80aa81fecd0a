//! rasterm: load models, render them with `rasterm-core`, and show them in a terminal or write PNG files.

pub mod model;
pub mod screen;
