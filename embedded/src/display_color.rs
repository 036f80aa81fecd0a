//! The display colour types the core writes directly.

use embedded_graphics_core::pixelcolor::raw::RawU16;
use embedded_graphics_core::pixelcolor::{PixelColor, Rgb565, Rgb888};
use rastty_core::target::ColorBuffer;

/// A display's colour type that the core renders to: what one pixel of a band is stored as, the core's colour
/// buffer over such pixels, and the display's colour of a stored pixel.
pub trait DisplayColor: PixelColor {
    /// One stored pixel.
    type Stored: Copy + Default;
    /// The core's colour buffer over a band of stored pixels.
    type Buffer<'a>: ColorBuffer;

    /// The core's colour buffer over `pixels`.
    fn buffer(pixels: &mut [Self::Stored]) -> Self::Buffer<'_>;

    /// The display's colour of a stored pixel.
    fn from_stored(pixel: Self::Stored) -> Self;
}

/// Stored as the core's [`rastty_core::target::Rgb565`] stores it: `rrrrrggggggbbbbb` in a `u16`, the raw value of
/// `embedded-graphics`' `Rgb565`.
impl DisplayColor for Rgb565 {
    type Stored = u16;
    type Buffer<'a> = rastty_core::target::Rgb565<'a>;

    fn buffer(pixels: &mut [u16]) -> rastty_core::target::Rgb565<'_> {
        rastty_core::target::Rgb565(pixels)
    }

    #[inline]
    fn from_stored(pixel: u16) -> Self {
        Self::from(RawU16::new(pixel))
    }
}

/// Stored as the core's [`rastty_core::target::Rgb888`] stores it: `0x00RRGGBB` in a `u32`.
impl DisplayColor for Rgb888 {
    type Stored = u32;
    type Buffer<'a> = rastty_core::target::Rgb888<'a>;

    fn buffer(pixels: &mut [u32]) -> rastty_core::target::Rgb888<'_> {
        rastty_core::target::Rgb888(pixels)
    }

    #[inline]
    fn from_stored(pixel: u32) -> Self {
        let [_, r, g, b] = pixel.to_be_bytes();
        Self::new(r, g, b)
    }
}
