//! Colour storage the caller owns: where shaded fragments end up.

use crate::color::{pack_rgb565, pack_rgb888};
use crate::math::Vec3;

/// Somewhere to put shaded pixels: one value per pixel, row-major, `width` values per row.
///
/// Implement it to render into your own format. Writes always come with an index below the length the target
/// was checked against, so an implementation may index directly.
pub trait ColorBuffer {
    /// Number of pixels stored, or `None` for a buffer that stores nothing (and fits any size).
    fn pixel_count(&self) -> Option<usize>;
    /// Stores the shaded colour of pixel `index`.
    fn write(&mut self, index: usize, color: Vec3);
    /// Sets every pixel to `color`.
    fn fill(&mut self, color: Vec3);
}

/// `0x00RRGGBB` pixels in `u32`s (see [`crate::color`]).
#[derive(Debug)]
pub struct Rgb888<'a>(pub &'a mut [u32]);

impl ColorBuffer for Rgb888<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    #[inline(always)]
    fn write(&mut self, index: usize, color: Vec3) {
        if let Some(p) = self.0.get_mut(index) {
            *p = pack_rgb888(color);
        }
    }
    fn fill(&mut self, color: Vec3) {
        self.0.fill(pack_rgb888(color));
    }
}

/// RGB565 pixels in `u16`s, the native format of most small SPI displays (see [`crate::color`]).
#[derive(Debug)]
pub struct Rgb565<'a>(pub &'a mut [u16]);

impl ColorBuffer for Rgb565<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    #[inline(always)]
    fn write(&mut self, index: usize, color: Vec3) {
        if let Some(p) = self.0.get_mut(index) {
            *p = pack_rgb565(color);
        }
    }
    fn fill(&mut self, color: Vec3) {
        self.0.fill(pack_rgb565(color));
    }
}

/// No colour at all: for depth-only passes.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoColor;

impl ColorBuffer for NoColor {
    fn pixel_count(&self) -> Option<usize> {
        None
    }
    #[inline(always)]
    fn write(&mut self, _: usize, _: Vec3) {}
    fn fill(&mut self, _: Vec3) {}
}
