//! A borrowed frame of renderer pixels, as it arrives from the rasteriser.

/// `width` x `height` pixels `0x00RRGGBB`, row-major, row 0 at the top.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelFrame<'a> {
    pixels: &'a [u32],
    width: usize,
    height: usize,
}

impl<'a> PixelFrame<'a> {
    /// Wraps a pixel buffer.
    ///
    /// # Panics
    /// If `pixels.len() != width * height`.
    pub fn new(pixels: &'a [u32], width: usize, height: usize) -> Self {
        assert_eq!(pixels.len(), width * height, "{width}x{height} frame needs {} pixels", width * height);
        PixelFrame { pixels, width, height }
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// All pixels, row-major.
    pub fn pixels(&self) -> &'a [u32] {
        self.pixels
    }

    /// The pixels of row `y`.
    ///
    /// # Panics
    /// If `y >= height`.
    pub fn row(&self, y: usize) -> &'a [u32] {
        &self.pixels[y * self.width..(y + 1) * self.width]
    }
}
