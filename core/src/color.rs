//! Colours: `f32` RGB for shading, packed integers for storage.
//!
//! Shading works on [`Vec3`] colours with channels nominally in `[0, 1]` (values above 1, from specular
//! highlights, saturate when packed). No gamma curve is applied in shading: colours are stored and shaded in the
//! same (sRGB-encoded) space, as most small renderers do. The sRGB transfer functions ([`srgb_to_linear`],
//! [`SrgbEncoder`]) serve where averaging must be in linear light: the mipmap chains of colour maps
//! ([`crate::texture::build_mip_levels`]).
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

/// The sRGB decoding of an encoded channel `c` in `[0, 1]` to linear light (IEC 61966-2-1, the piecewise curve
/// with exponent 2.4).
///
/// # Examples
/// ```
/// use rastty_core::color::srgb_to_linear;
/// assert_eq!((srgb_to_linear(0.0), srgb_to_linear(1.0)), (0.0, 1.0));
/// assert!((srgb_to_linear(0.5) - 0.214).abs() < 1e-3);
/// ```
#[must_use]
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 { c / 12.92 } else { float::pow((c + 0.055) / 1.055, 2.4) }
}

/// Linear light to 8-bit sRGB codes, by table: the boundaries between neighbouring codes (the midpoints of the
/// encoded scale) decoded to linear light once, and each value's code the number of boundaries at or below it. So
/// a value gets the code nearest its encoding with 8 comparisons instead of a power, the same on every target.
#[derive(Clone, Debug)]
pub struct SrgbEncoder {
    boundaries: [f32; 255],
}

impl SrgbEncoder {
    /// The table: 255 decodings.
    #[must_use]
    pub fn new() -> Self {
        Self { boundaries: core::array::from_fn(|c| srgb_to_linear((c as f32 + 0.5) / 255.0)) }
    }

    /// The sRGB code, `0..=255`, of the linear value `l` (0 below the range and for NaN, 255 above).
    ///
    /// # Examples
    /// ```
    /// use rastty_core::color::{SrgbEncoder, srgb_to_linear};
    /// let encoder = SrgbEncoder::new();
    /// assert_eq!((encoder.code(0.0), encoder.code(0.5), encoder.code(1.0)), (0, 188, 255));
    /// assert_eq!(encoder.code(srgb_to_linear(100.0 / 255.0)), 100);
    /// ```
    #[must_use]
    pub fn code(&self, l: f32) -> u32 {
        self.boundaries.partition_point(|&b| b <= l) as u32
    }
}

impl Default for SrgbEncoder {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table gives the code nearest each value's encoding, computed here in `f64` from the standard's formula
    /// (values within 10^-4 of a code's edge, where `f32` decoding could tip them, are left out).
    #[test]
    fn the_encoder_gives_the_nearest_code() {
        let encoder = SrgbEncoder::new();
        let encode = |l: f64| if l <= 0.003_130_8 { l * 12.92 } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
        for i in 0..=20_000 {
            let l = f64::from(i) / 20_000.0;
            let scaled = encode(l) * 255.0;
            if (scaled - scaled.floor() - 0.5).abs() < 1e-4 {
                continue;
            }
            assert_eq!(encoder.code(l as f32), scaled.round() as u32, "linear {l}");
        }
    }
}
