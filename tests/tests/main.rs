//! The workspace's cross-crate tests: one binary, one module per subject (listed below).
//!
//! One test binary per crate links once instead of once per file (`autotests = false` in Cargo.toml: a new
//! file here is a module declared below). Run one subject with `cargo test -p rastty-tests --test integration MODULE::`.

mod effect_snapshots;
mod embedded_graphics;
mod firmware_checksum;
mod snapshot;
mod snapshots;
mod stability;
