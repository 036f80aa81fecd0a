//! `cargo +nightly fuzz run raster`: see `src/raster.rs` and docs/fuzzing.md. With `RASTTY_FUZZ_SEEDS` set it writes
//! the seed corpora instead (`src/seeds.rs`).

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(init: rastty_fuzz::seeds::write_if_asked(), |input: rastty_fuzz::raster::Input| {
    rastty_fuzz::raster::run(input);
});
