//! `cargo +nightly fuzz run raster`: see `src/raster.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: rastty_fuzz::raster::Input| {
    rastty_fuzz::raster::run(input);
});
