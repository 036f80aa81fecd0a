//! `cargo +nightly fuzz run obj_load`: see `src/obj_load.rs` and docs/fuzzing.md.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    rastty_fuzz::obj_load::run(data);
});
