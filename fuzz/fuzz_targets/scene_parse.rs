//! `cargo +nightly fuzz run scene_parse`: see `src/scene_parse.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    rastty_fuzz::scene_parse::run(data);
});
