//! `cargo +nightly fuzz run stl_load`: see `src/stl_load.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    rastty_fuzz::stl_load::run(data);
});
