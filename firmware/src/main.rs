//! rastty-core on a Cortex-M4: renders the shared scene (`rastty-firmware-scene`: Spot the cow, Phong-lit,
//! plain or textured, 320x240 RGB565, `u16` depth) in bands, its triangles binned once a frame, in each memory
//! layout (16, 32 and 64 KiB for the band buffers and the bins together), folds every band into an FNV-1a
//! checksum, and prints, through semihosting, one line per frame and layout that the host must reproduce exactly
//! (`check.sh` compares them), then the instructions each took (a frame, a pixel, a triangle of the model and a
//! shaded fragment) and each layout's peak stack, the frame memory's RAM and the peak stack of the whole run. Each frame is drawn twice: timed, as a product would draw it into its display; then untimed,
//! its depths folded into a second checksum.
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
use rastty_firmware_scene::{ChecksumDisplay, checksum_frame, render_frame, spot};
use rastty_firmware_scene::{FRAME_MEMORY_BYTES, FRAMES, FrameMemory, HEIGHT, LAYOUTS, Look, VIEWS, WIDTH};

/// The band buffers and the bins, in `.bss`: the only frame memory.
static mut MEMORY: FrameMemory = FrameMemory::new();

#[entry]
fn main() -> ! {
    let mut out = hio::hstdout().unwrap_or_else(|()| fail());
    let memory = &raw mut MEMORY;
    // SAFETY: `main` runs once and is the only place that touches `MEMORY`.
    let memory: &'static mut FrameMemory = unsafe { &mut *memory };
    timer::start();

    let _ = writeln!(
        out,
        "rastty-core on a Cortex-M4: Spot ({} vertices, {} triangles; textured, {} vertices and {s}x{s} texels), \
         {WIDTH}x{HEIGHT} RGB565 + u16 depth",
        spot::VERTEX_COUNT,
        spot::TRIANGLE_COUNT,
        spot::textured::VERTEX_COUNT,
        s = spot::textured::TEXTURE_SIZE,
    );
    // Each frame's instructions and shaded fragments in each layout.
    let mut instructions = [[(0u64, 0u64); FRAMES]; LAYOUTS.len()];
    let mut stacks = [0usize; LAYOUTS.len()];
    let start_up = stack::peak_bytes();
    for ((layout, counts), stack) in LAYOUTS.iter().zip(&mut instructions).zip(&mut stacks) {
        stack::repaint();
        for (frame, count) in counts.iter_mut().enumerate() {
            // Timed: the frame as a product would draw it, into its display.
            let mut display = ChecksumDisplay::new();
            let t0 = timer::now();
            let (_, stats) = render_frame(frame, *layout, memory, &mut display, None)
                .unwrap_or_else(|e| panic!("frame {frame}: {e}"));
            *count = (timer::instructions_since(t0), stats.fragments);
            // Checked, untimed: the same frame again, its depths folded too.
            let report = checksum_frame(frame, *layout, memory).unwrap_or_else(|e| panic!("frame {frame}: {e}"));
            assert_eq!(display.checksum(), report.checksum, "frame {frame}: the same pixels twice");
            let _ = writeln!(out, "{report}");
        }
        // Its frames' deepest, printing their lines included.
        *stack = stack::peak_bytes();
    }

    for ((layout, counts), stack) in LAYOUTS.iter().zip(&instructions).zip(stacks) {
        let _ = writeln!(
            out,
            "layout {} KiB: bands of {} rows, {} bytes of buffers, peak stack {stack} bytes",
            layout.budget_kib,
            layout.band_rows,
            layout.bytes()
        );
        for (frame, &(count, fragments)) in counts.iter().enumerate() {
            let per_pixel = count / u64::from(WIDTH * HEIGHT);
            let triangles = spot::TRIANGLE_COUNT as u64;
            let look = match VIEWS[frame].look {
                Look::Plain => "plain",
                Look::Textured => "textured",
            };
            let _ = writeln!(
                out,
                "frame {frame} in {} KiB: {count} instructions, {per_pixel} per pixel, {} per triangle, {} per shaded \
                 fragment ({look}: {fragments} fragments)",
                layout.budget_kib,
                count / triangles,
                count / fragments.max(1),
            );
        }
    }
    let t0 = timer::now();
    timer::two_million_instructions();
    let _ = writeln!(out, "timer check: a 2000000-instruction loop measures {}", timer::instructions_since(t0));
    let _ = writeln!(out, "frame memory: {FRAME_MEMORY_BYTES} bytes of RAM (the largest layout's)");
    // The deepest of start-up, every layout's frames, and the last layout's with the printing since.
    let stack = stacks.into_iter().chain([start_up, stack::peak_bytes()]).max().unwrap_or(0);
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
