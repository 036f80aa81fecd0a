//! Colours: `f32` RGB for shading, packed integers for storage.
//!
//! Shading works on [`Vec3`] colours with channels nominally in `[0, 1]` (values above 1, from specular
//! highlights, saturate when packed). No gamma curve is applied anywhere: colours are stored and shaded in the same
//! (sRGB-encoded) space, as most small renderers do.
//!
//! Packed formats:
//! - **RGB888 in a `u32`**: `0x00RRGGBB` — red in bits 16..24, green in 8..16, blue in 0..8, top byte zero. This
//!   is the layout of `softbuffer`/`minifb` frame buffers. [`crate::texture::Texture`] texels use the top byte
//!   for transparency (`255 - alpha`, see [`texel_alpha`]), so a plain `0x00RRGGBB` texel is opaque.
//! - **RGB565 in a `u16`**: red in bits 11..16, green in 5..11, blue in 0..5, the usual layout of SPI displays.

use crate::math::{Vec3, float};

/// Packs a colour as `0x00RRGGBB`.
///
/// # Examples
/// ```
/// use rastty_core::{color::pack_rgb888, math::Vec3};
/// assert_eq!(pack_rgb888(Vec3::new(1.0, 0.5, 0.0)), 0x00FF8000);
/// ```
#[inline(always)]
pub fn pack_rgb888(c: Vec3) -> u32 {
    (float::quantize_unit(c.x, 255.0) << 16)
        | (float::quantize_unit(c.y, 255.0) << 8)
        | float::quantize_unit(c.z, 255.0)
}

/// Unpacks `0x00RRGGBB` to channels in `[0, 1]`; the top byte is ignored.
#[inline(always)]
pub fn unpack_rgb888(p: u32) -> Vec3 {
    const S: f32 = 1.0 / 255.0;
    Vec3::new(((p >> 16) & 0xFF) as f32 * S, ((p >> 8) & 0xFF) as f32 * S, (p & 0xFF) as f32 * S)
}

/// The alpha of a texture texel `0xTTRRGGBB`, `0..=255`: its top byte holds the transparency `255 - alpha`, so
/// that texels written as `0x00RRGGBB` are opaque.
///
/// # Examples
/// ```
/// use rastty_core::color::texel_alpha;
/// assert_eq!(texel_alpha(0x00FF8000), 255);
/// assert_eq!(texel_alpha(0xFF123456), 0);
/// ```
#[must_use]
#[inline(always)]
pub const fn texel_alpha(p: u32) -> u32 {
    255 - (p >> 24)
}

/// Packs a colour as RGB565.
///
/// # Examples
/// ```
/// use rastty_core::{color::pack_rgb565, math::Vec3};
/// assert_eq!(pack_rgb565(Vec3::new(1.0, 0.0, 1.0)), 0xF81F);
/// ```
#[inline(always)]
pub fn pack_rgb565(c: Vec3) -> u16 {
    ((float::quantize_unit(c.x, 31.0) << 11) | (float::quantize_unit(c.y, 63.0) << 5) | float::quantize_unit(c.z, 31.0))
        as u16
}

/// Unpacks RGB565 to channels in `[0, 1]`.
#[inline(always)]
pub fn unpack_rgb565(p: u16) -> Vec3 {
    let p = u32::from(p);
    Vec3::new(((p >> 11) & 31) as f32 / 31.0, ((p >> 5) & 63) as f32 / 63.0, (p & 31) as f32 / 31.0)
}

/// Converts RGB565 to `0x00RRGGBB`, replicating the high bits into the low ones (exact for 0 and full scale).
#[inline]
pub fn rgb565_to_rgb888(p: u16) -> u32 {
    let p = u32::from(p);
    let (r, g, b) = ((p >> 11) & 31, (p >> 5) & 63, p & 31);
    (((r << 3) | (r >> 2)) << 16) | (((g << 2) | (g >> 4)) << 8) | ((b << 3) | (b >> 2))
}
