//! `cargo +nightly fuzz run gltf_animation`: see `src/gltf_animation.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    rastty_fuzz::gltf_animation::run(data);
});
