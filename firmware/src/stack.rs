//! The deepest the stack has gone, from the paint `cortex-m-rt` put down.
//!
//! Its `paint-stack` feature fills all RAM between the statics and the top of the stack with
//! [`STACK_PAINT_VALUE`] before `main`; the lowest word that no longer holds it is the deepest the stack went.
//! [`repaint`] paints again what lies below the stack pointer, so that each part of the program gets its own
//! figure.

use core::ptr::{addr_of, read_volatile, write_volatile};

use cortex_m_rt::STACK_PAINT_VALUE;

unsafe extern "C" {
    /// Top of the stack (the initial stack pointer), from `cortex-m-rt`'s linker script.
    static _stack_start: u32;
    /// Bottom of the stack area: the end of the statics.
    static _stack_end: u32;
}

/// Paints every free word of the stack area again: from its bottom to 64 bytes below the stack pointer (the
/// caller's frame and this function's stay as they are). The deepest the stack goes from here on is then
/// [`peak_bytes`].
#[inline(never)]
pub fn repaint() {
    let bottom = addr_of!(_stack_end) as usize;
    let below = (cortex_m::register::msp::read() as usize).saturating_sub(64) & !3;
    let mut word = bottom;
    while word < below {
        // SAFETY: `_stack_end..msp - 64` is RAM below the live stack, word-aligned, that nothing else uses (no
        // interrupt is enabled), so it may be overwritten.
        unsafe { write_volatile(word as *mut u32, STACK_PAINT_VALUE) };
        word += 4;
    }
}

/// Bytes between the top of the stack and the lowest word that no longer holds the paint.
pub fn peak_bytes() -> usize {
    let top = addr_of!(_stack_start) as usize;
    let mut word = addr_of!(_stack_end) as usize;
    // SAFETY: every word in `_stack_end.._stack_start` is RAM, and word-aligned (`cortex-m-rt` asserts both ends).
    while word < top && unsafe { read_volatile(word as *const u32) } == STACK_PAINT_VALUE {
        word += 4;
    }
    top - word
}
