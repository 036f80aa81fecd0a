//! rastty-bench: what rastty's figures are measured with, kept out of the installed program.
//!
//! | module | holds |
//! |---|---|
//! | [`animated_tube`] | a skinned, morphed, animated model made in memory, for the animation benchmark and report |
//! | [`reference`](mod@reference) | a slow `f64` reference renderer (16x16 samples per pixel, coverage and shading in `f64`): the truth to measure against |
//! | [`report`] | `rastty-bench`: measured figures as Markdown (terminal frame bytes and times; every quality knob's time and error; the cost of each effect) |
//!
//! The benchmarks (`cargo bench -p rastty-bench`) live in `benches/`: the core's pipelines and ambient
//! occlusion (`render`, `occlusion`), posing a model that moves (`animation`) and the terminal encoder (`screen_encode`).

pub mod animated_tube;
pub mod reference;
pub mod report;
