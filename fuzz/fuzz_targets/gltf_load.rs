//! `cargo +nightly fuzz run gltf_load`: see `src/gltf_load.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    rastty_fuzz::gltf_load::run(data);
});
