//! rastty-core's integration tests: one binary, one module per subject (listed below).
//!
//! One test binary per crate links once instead of once per file (`autotests = false` in Cargo.toml: a new
//! file here is a module declared below). Run one subject with `cargo test -p rastty-core --test integration MODULE::`.

mod ambient_occlusion;
mod bands;
mod bins;
mod clipping;
mod common;
mod cutout;
mod depth;
mod effects;
mod environment;
mod fill_rule;
mod inverse_sqrt;
mod math;
mod metallic_roughness;
mod mipmaps;
mod multisample;
mod robustness;
mod shadows;
mod specialisation;
mod stability;
mod supersample;
mod tangents;
mod texture;
mod two_sided;
mod vertex_cache;
mod vertex_memory;
mod wireframe;
