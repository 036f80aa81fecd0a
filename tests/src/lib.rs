//! Integration tests of the rastty workspace live in `tests/tests/`: `snapshots.rs` compares rendered frames of
//! the built-in model with the golden PNG files in `tests/snapshots/`; `effect_snapshots.rs` does the same for the
//! scene files' effects (`spot_lamp` with every effect, none, and each one left out; `spot_sun`'s shadow), with
//! goldens in `tests/snapshots/effects/`, and checks that leaving out any effect changes the frame. Both share the
//! harness in `tests/tests/snapshot/`; re-bless their goldens with `UPDATE_SNAPSHOTS=1 cargo test -p rastty-tests`.
//! `stability.rs` holds the hard cases that need the program crate; `firmware_checksum.rs` computes the checksums
//! the firmware must match under QEMU.

/// The README's Rust code, compiled and run as a doctest (`cargo test --doc -p rastty-tests`), so that the
/// example of using the core cannot drift from the core's interface.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeExamples;
