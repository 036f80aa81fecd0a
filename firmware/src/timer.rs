//! Counting instructions with the CMSDK APB timer 0 of the MPS2 board.
//!
//! QEMU has no cycle counter. Run with `-icount shift=0`, virtual time advances exactly 1 ns per instruction, so
//! the timer, clocked at the board's 25 MHz, counts one tick per 40 instructions, deterministically. Without
//! `-icount` the figures are host time, not instructions.

use core::arch::asm;
use core::ptr::{read_volatile, write_volatile};

/// The timer's registers on `mps2-an386`.
const BASE: usize = 0x4000_0000;
const CTRL: *mut u32 = BASE as *mut u32;
const VALUE: *mut u32 = (BASE + 0x4) as *mut u32;
const RELOAD: *mut u32 = (BASE + 0x8) as *mut u32;
/// Instructions per tick of the 25 MHz timer, at 1 ns of virtual time per instruction.
const INSTRUCTIONS_PER_TICK: u64 = 1_000_000_000 / 25_000_000;

/// Starts the timer counting down from `u32::MAX`: 171 s of virtual time before it wraps.
pub fn start() {
    // SAFETY: the timer's registers on mps2-an386; nothing else uses them.
    unsafe {
        write_volatile(CTRL, 0);
        write_volatile(RELOAD, u32::MAX);
        write_volatile(VALUE, u32::MAX);
        write_volatile(CTRL, 1);
    }
}

/// The counter now.
pub fn now() -> u32 {
    // SAFETY: as in `start`.
    unsafe { read_volatile(VALUE) }
}

/// Instructions executed since the counter read `t0` (with `-icount shift=0`; a multiple of 40).
pub fn instructions_since(t0: u32) -> u64 {
    u64::from(t0.wrapping_sub(now())) * INSTRUCTIONS_PER_TICK
}

/// Runs exactly 2,000,000 instructions, 1,000,000 turns of `subs` + `bne`: a check of the counting.
pub fn two_million_instructions() {
    // SAFETY: touches one register and the flags only.
    unsafe {
        asm!("2:", "subs {n}, #1", "bne 2b", n = inout(reg) 1_000_000u32 => _, options(nomem, nostack));
    }
}
