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
    /// Stores `color` at index `first + s` for every bit `s` set in `mask`: the samples of one pixel of a
    /// multisampled target that a triangle reached (see [`super::Samples`]). By default one [`Self::write`] each;
    /// a format that converts the colour can convert it once.
    #[inline(always)]
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        for_each_sample(mask, |s| self.write(first + s, color));
    }
    /// Stores `colors[i]` at index `indices[i]` for each `i`, in order (a later write to an index wins): a batch
    /// of shaded fragments, handed over once. By default one [`Self::write`] each.
    #[inline(always)]
    fn write_batch(&mut self, indices: &[usize], colors: &[Vec3]) {
        for (&index, &color) in indices.iter().zip(colors) {
            self.write(index, color);
        }
    }
    /// The buffer as the pipeline writes it: by default [`ColorView::Other`], written through this trait's
    /// methods (a call per batch of fragments). A type that holds one of the library's formats (an enum over
    /// buffers, say) may hand that over instead, to have it written directly.
    #[inline(always)]
    fn view(&mut self) -> ColorView<'_>
    where
        Self: Sized,
    {
        ColorView::Other(self)
    }
}

/// A colour buffer as the pipeline writes it: one of the library's packed formats, stored into directly, or any
/// other [`ColorBuffer`], through its methods.
///
/// The pipeline draws into this one type whatever buffer the caller gave ([`ColorBuffer::view`]), so that its
/// loops are compiled once, not once for every colour buffer type a program draws into: the format is one branch
/// per batch of shaded fragments.
pub enum ColorView<'a> {
    /// `0x00RRGGBB` pixels ([`Rgb888`]).
    Rgb888(&'a mut [u32]),
    /// RGB565 pixels ([`Rgb565`]).
    Rgb565(&'a mut [u16]),
    /// Any other colour buffer.
    Other(&'a mut dyn ColorBuffer),
}

impl core::fmt::Debug for ColorView<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Rgb888(p) => write!(f, "Rgb888({} pixels)", p.len()),
            Self::Rgb565(p) => write!(f, "Rgb565({} pixels)", p.len()),
            Self::Other(c) => write!(f, "Other({:?} pixels)", c.pixel_count()),
        }
    }
}

impl ColorBuffer for ColorView<'_> {
    fn pixel_count(&self) -> Option<usize> {
        match self {
            Self::Rgb888(p) => Some(p.len()),
            Self::Rgb565(p) => Some(p.len()),
            Self::Other(c) => c.pixel_count(),
        }
    }
    #[inline(always)]
    fn write(&mut self, index: usize, color: Vec3) {
        match self {
            Self::Rgb888(p) => Rgb888(p).write(index, color),
            Self::Rgb565(p) => Rgb565(p).write(index, color),
            Self::Other(c) => c.write(index, color),
        }
    }
    fn fill(&mut self, color: Vec3) {
        match self {
            Self::Rgb888(p) => Rgb888(p).fill(color),
            Self::Rgb565(p) => Rgb565(p).fill(color),
            Self::Other(c) => c.fill(color),
        }
    }
    #[inline(always)]
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        match self {
            Self::Rgb888(p) => Rgb888(p).write_samples(first, mask, color),
            Self::Rgb565(p) => Rgb565(p).write_samples(first, mask, color),
            Self::Other(c) => c.write_samples(first, mask, color),
        }
    }
    #[inline(always)]
    fn write_batch(&mut self, indices: &[usize], colors: &[Vec3]) {
        match self {
            Self::Rgb888(p) => Rgb888(p).write_batch(indices, colors),
            Self::Rgb565(p) => Rgb565(p).write_batch(indices, colors),
            Self::Other(c) => c.write_batch(indices, colors),
        }
    }
    #[inline(always)]
    fn view(&mut self) -> ColorView<'_> {
        match self {
            Self::Rgb888(p) => ColorView::Rgb888(p),
            Self::Rgb565(p) => ColorView::Rgb565(p),
            Self::Other(c) => ColorView::Other(&mut **c),
        }
    }
}

/// Calls `f` with the index of every bit set in `mask`, lowest first.
#[inline(always)]
fn for_each_sample(mask: u8, mut f: impl FnMut(usize)) {
    let mut rest = mask;
    while rest != 0 {
        f(rest.trailing_zeros() as usize);
        rest &= rest - 1;
    }
}

/// Stores the packed value `packed` at index `first + s` of `buffer` for every bit `s` set in `mask`.
#[inline(always)]
fn store_samples<T: Copy>(buffer: &mut [T], first: usize, mask: u8, packed: T) {
    for_each_sample(mask, |s| {
        if let Some(p) = buffer.get_mut(first + s) {
            *p = packed;
        }
    });
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
    #[inline(always)]
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        store_samples(self.0, first, mask, pack_rgb888(color));
    }
    #[inline(always)]
    fn view(&mut self) -> ColorView<'_> {
        ColorView::Rgb888(self.0)
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
    #[inline(always)]
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        store_samples(self.0, first, mask, pack_rgb565(color));
    }
    #[inline(always)]
    fn view(&mut self) -> ColorView<'_> {
        ColorView::Rgb565(self.0)
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
    #[inline(always)]
    fn write_samples(&mut self, _: usize, _: u8, _: Vec3) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The packed formats' one conversion stores what a [`ColorBuffer::write`] per sample stores, for every mask,
    /// including samples past the buffer's end (ignored, as `write` ignores them).
    #[test]
    fn write_samples_equals_a_write_per_sample() {
        let color = Vec3::new(0.8, 0.25, 0.6);
        for first in [0, 3, 6] {
            for mask in 0..=u8::MAX {
                let (mut one, mut each) = ([7u32; 10], [7u32; 10]);
                Rgb888(&mut one).write_samples(first, mask, color);
                for s in (0..8).filter(|s| mask >> s & 1 == 1) {
                    Rgb888(&mut each).write(first + s, color);
                }
                assert_eq!(one, each, "Rgb888, first {first}, mask {mask:#010b}");
                let (mut one, mut each) = ([7u16; 10], [7u16; 10]);
                Rgb565(&mut one).write_samples(first, mask, color);
                for s in (0..8).filter(|s| mask >> s & 1 == 1) {
                    Rgb565(&mut each).write(first + s, color);
                }
                assert_eq!(one, each, "Rgb565, first {first}, mask {mask:#010b}");
            }
        }
        // A mask that sets every second sample writes exactly those.
        let mut buffer = [0u32; 8];
        Rgb888(&mut buffer).write_samples(0, 0b0101_0101, color);
        let packed = pack_rgb888(color);
        assert_eq!(buffer, [packed, 0, packed, 0, packed, 0, packed, 0]);
    }
}
