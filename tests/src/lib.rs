//! Integration tests of the rasterm workspace live in `tests/tests/`: `snapshots.rs` compares rendered frames of
//! the built-in model with the golden PNG files in `tests/snapshots/` (re-bless them with
//! `UPDATE_SNAPSHOTS=1 cargo test -p rasterm-tests`); `stability.rs` holds the hard cases that need the program
//! crate; `firmware_checksum.rs` computes the checksums the firmware must match under QEMU.
