//! The firmware's display: an `embedded-graphics` draw target that folds the pixels it is sent into a checksum.

use core::convert::Infallible;

use embedded_graphics_core::Pixel;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::{IntoStorage, Rgb565};
use embedded_graphics_core::primitives::Rectangle;

use crate::{Fnv1a, HEIGHT, WIDTH};

/// A [`WIDTH`]x[`HEIGHT`] RGB565 display that keeps no pixels: it folds each one it is sent, in the order sent,
/// into an [`Fnv1a`] checksum ([`Fnv1a::write_words`]). Sent a frame's bands top to bottom, as
/// [`rastty_embedded_graphics::draw_frame`] sends them, it holds the checksum of the frame.
#[derive(Clone, Copy, Debug, Default)]
pub struct ChecksumDisplay {
    checksum: Fnv1a,
    pixels: u64,
}

impl ChecksumDisplay {
    /// A display sent nothing yet.
    #[must_use]
    pub const fn new() -> Self {
        Self { checksum: Fnv1a::new(), pixels: 0 }
    }

    /// The checksum of the pixels sent so far.
    #[must_use]
    pub const fn checksum(&self) -> u32 {
        self.checksum.finish()
    }

    /// The number of pixels sent so far.
    #[must_use]
    pub const fn pixels(&self) -> u64 {
        self.pixels
    }

    fn write(&mut self, color: Rgb565) {
        self.checksum.write_words(&[color.into_storage()]);
        self.pixels += 1;
    }
}

impl OriginDimensions for ChecksumDisplay {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl DrawTarget for ChecksumDisplay {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(_, color) in pixels {
            self.write(color);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(&mut self, _: &Rectangle, colors: I) -> Result<(), Infallible> {
        for color in colors {
            self.write(color);
        }
        Ok(())
    }
}
