//! rastty-bench's tests: the reference renderer against closed-form answers, and the reports' shapes and errors.
//!
//! One test binary per crate links once instead of once per file (`autotests = false` in Cargo.toml: a new
//! file here is a module declared below). Run one subject with `cargo test -p rastty-bench --test integration MODULE::`.

mod common;
mod reference;
mod report_animation;
mod report_effects;
mod report_frames;
mod report_peers;
