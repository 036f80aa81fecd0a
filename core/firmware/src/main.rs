//! rastty-core on a Cortex-M4: renders the shared scene (`rastty-firmware-scene`: Spot the cow, Phong-lit,
//! 320x240 RGB565, `u16` depth) in 12-row strips through 15,360 bytes of band buffers, folds every strip into an
//! FNV-1a checksum, and prints, through semihosting, one line per frame that the host must reproduce exactly
//! (`check.sh` compares them), then the instructions each frame took, the band buffers' RAM and the peak stack.
//! It exits through semihosting: status 0, or 1 after a panic or a hard fault.
//!
//! Built for QEMU's `mps2-an386` machine (`memory.x`); `cargo run --release` runs it there (`.cargo/config.toml`),
//! with `-icount shift=0`, without which the instruction counts would be host time ([`timer`]). The peak stack
//! comes from stack painting ([`stack`]).

#![no_std]
#![no_main]

mod stack;
mod timer;

use core::fmt::Write;
use core::panic::PanicInfo;

use cortex_m_rt::{ExceptionFrame, entry, exception};
use cortex_m_semihosting::{debug, hio};
use rastty_firmware_scene::{BAND_BUFFER_BYTES, BAND_ROWS, BandBuffers, FRAMES, HEIGHT, STRIPS, WIDTH};
use rastty_firmware_scene::{checksum_frame, spot};

/// The band buffers, in `.bss`: the only frame memory.
static mut BANDS: BandBuffers = BandBuffers::new();

#[entry]
fn main() -> ! {
    let mut out = hio::hstdout().unwrap_or_else(|()| fail());
    let bands = &raw mut BANDS;
    // SAFETY: `main` runs once and is the only place that touches `BANDS`.
    let bands: &'static mut BandBuffers = unsafe { &mut *bands };
    timer::start();

    let _ = writeln!(
        out,
        "rastty-core on a Cortex-M4: Spot ({} vertices, {} triangles), {WIDTH}x{HEIGHT} RGB565 + u16 depth, \
         {STRIPS} strips of {BAND_ROWS} rows",
        spot::VERTEX_COUNT,
        spot::TRIANGLE_COUNT,
    );
    let mut instructions = [0u64; FRAMES];
    for (frame, count) in instructions.iter_mut().enumerate() {
        let t0 = timer::now();
        let report = checksum_frame(frame, bands).unwrap_or_else(|e| panic!("frame {frame}: {e}"));
        *count = timer::instructions_since(t0);
        let _ = writeln!(out, "{report}");
    }
    let stack = stack::peak_bytes();

    for (frame, &count) in instructions.iter().enumerate() {
        let per_pixel = count / u64::from(WIDTH * HEIGHT);
        let _ = writeln!(out, "frame {frame}: {count} instructions, {per_pixel} per pixel (under -icount shift=0)");
    }
    let t0 = timer::now();
    timer::two_million_instructions();
    let _ = writeln!(out, "timer check: a 2000000-instruction loop measures {}", timer::instructions_since(t0));
    let _ = writeln!(out, "band buffers: {BAND_BUFFER_BYTES} bytes of RAM");
    let _ = writeln!(out, "peak stack: {stack} bytes");
    debug::exit(debug::EXIT_SUCCESS);
    fail()
}

/// Exits with a failure status (and spins, should the debugger let the program go on).
fn fail() -> ! {
    loop {
        debug::exit(debug::EXIT_FAILURE);
    }
}

#[panic_handler]
fn panic(info: &PanicInfo<'_>) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "panic: {info}");
    }
    fail()
}

#[exception]
unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "hard fault: {frame:?}");
    }
    fail()
}
