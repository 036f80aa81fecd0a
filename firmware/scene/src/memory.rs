//! The frame memory: one band's colour and depth, and the triangle bins; and the layouts that share it out.

#[cfg(doc)]
use rastty_core::pipeline::BIN_BLOCK;
use rastty_core::pipeline::BinnedTriangle;

use crate::frame::WIDTH;

/// Entries the bins hold: Spot's kept triangles (those facing the camera that cover a pixel centre: 2,158 and
/// 2,142 in the two frames) and one entry for each [`BIN_BLOCK`] of them, with 26% to spare. Triangles beyond it
/// would be drawn in every band, and without room for the blocks each band would scan every entry (slower, the
/// same pixels).
pub const BIN_ENTRIES: usize = 2_816;

/// How the frame memory is shared out: rows per band, within a budget of RAM for every buffer together.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryLayout {
    /// The budget in KiB: colour, depth and bins together fit in it.
    pub budget_kib: usize,
    /// Rows per band (the last band is shorter when this does not divide the height).
    pub band_rows: u32,
}

impl MemoryLayout {
    /// The most rows per band that fit `budget_kib` KiB with the bins.
    #[must_use]
    pub const fn for_budget(budget_kib: usize) -> Self {
        let band_bytes = budget_kib * 1024 - BIN_ENTRIES * size_of::<BinnedTriangle>();
        Self { budget_kib, band_rows: (band_bytes / (2 * 2 * WIDTH as usize)) as u32 }
    }

    /// Pixels of one band.
    #[must_use]
    pub const fn band_pixels(&self) -> usize {
        (WIDTH * self.band_rows) as usize
    }

    /// Bytes the layout uses: RGB565 colour and `u16` depth for one band, and [`BIN_ENTRIES`] bins.
    #[must_use]
    pub const fn bytes(&self) -> usize {
        2 * 2 * self.band_pixels() + BIN_ENTRIES * size_of::<BinnedTriangle>()
    }
}

/// The layouts measured, smallest first, each with the most rows per band that fit its budget. The firmware's
/// frames are checked in every one.
pub const LAYOUTS: [MemoryLayout; 3] =
    [MemoryLayout::for_budget(16), MemoryLayout::for_budget(32), MemoryLayout::for_budget(64)];

/// Pixels of the largest layout's band: what [`FrameMemory`] holds.
pub const MAX_BAND_PIXELS: usize = LAYOUTS[LAYOUTS.len() - 1].band_pixels();

/// Bytes of RAM [`FrameMemory`] takes: the largest layout's buffers, which every smaller one uses the start of.
pub const FRAME_MEMORY_BYTES: usize = size_of::<FrameMemory>();
const _: () = assert!(FRAME_MEMORY_BYTES <= 64 * 1024, "the frame memory fits 64 KiB");

/// RGB565 colour and `u16` depth for one band, and the bins: reused for every band of every frame in every
/// layout (a layout of fewer rows uses the start of the band buffers).
#[derive(Clone, Debug)]
pub struct FrameMemory {
    /// RGB565 colour, row-major.
    pub color: [u16; MAX_BAND_PIXELS],
    /// Depth, row-major.
    pub depth: [u16; MAX_BAND_PIXELS],
    /// The triangles binned by band.
    pub bins: [BinnedTriangle; BIN_ENTRIES],
}

impl FrameMemory {
    /// Zeroed buffers (a `const fn`, so that a firmware can keep them in a `static`, in `.bss`).
    #[must_use]
    pub const fn new() -> Self {
        Self { color: [0; MAX_BAND_PIXELS], depth: [0; MAX_BAND_PIXELS], bins: [BinnedTriangle::UNSET; BIN_ENTRIES] }
    }
}

impl Default for FrameMemory {
    fn default() -> Self {
        Self::new()
    }
}
