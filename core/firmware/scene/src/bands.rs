//! The band buffers: all the frame memory the renderer needs.

use crate::frame::{BAND_ROWS, WIDTH};

/// Pixels in one band buffer: one strip of [`BAND_ROWS`] rows.
pub const BAND_PIXELS: usize = (WIDTH * BAND_ROWS) as usize;

/// Bytes of RAM the band buffers take: RGB565 colour and `u16` depth for one strip.
pub const BAND_BUFFER_BYTES: usize = core::mem::size_of::<BandBuffers>();
const _: () = assert!(BAND_BUFFER_BYTES <= 16 * 1024, "the band buffers must fit 16 KiB");

/// RGB565 colour and `u16` depth for one strip of [`BAND_ROWS`] rows, reused for every strip of every frame.
#[derive(Clone, Debug)]
pub struct BandBuffers {
    /// RGB565 colour, row-major.
    pub color: [u16; BAND_PIXELS],
    /// Depth, row-major.
    pub depth: [u16; BAND_PIXELS],
}

impl BandBuffers {
    /// Zeroed buffers (a `const fn`, so that a firmware can keep them in a `static`, in `.bss`).
    pub const fn new() -> Self {
        Self { color: [0; BAND_PIXELS], depth: [0; BAND_PIXELS] }
    }
}

impl Default for BandBuffers {
    fn default() -> Self {
        Self::new()
    }
}
