//! Colours: `f32` RGB for shading, packed integers for storage.
//!
//! Shading works on [`Vec3`] colours with channels nominally in `[0, 1]` (values above 1, from specular
//! highlights, saturate when packed). Stored colours (texels, pixels) are sRGB-encoded 8-bit codes; a draw lights
//! them in linear light or as they are stored, as its [`ShadingSpace`] says. The sRGB transfer functions
//! ([`SRGB_DECODE`], [`linear_to_srgb8`]) are tables the compiler computes, so every target decodes and encodes
//! the same bits; they also average colour maps' levels in linear light ([`crate::texture::build_mip_levels`]).
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

/// How a draw combines colours with light.
///
/// In [`ShadingSpace::Linear`] (the sRGB-correct way) the 8-bit codes of colour maps are decoded to linear light
/// ([`SRGB_DECODE`]), light is added up and multiplied in linear light, and each pixel's result is encoded to the
/// nearest sRGB code ([`linear_to_srgb8`]); the colours given as numbers (material, vertex and light colours, the
/// ambient light) are taken to be linear already, as glTF defines its factors and vertex colours. In
/// [`ShadingSpace::Encoded`] every value is used as stored, so light falls off too darkly and adds up too brightly,
/// as in most small renderers: kept to compare with them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ShadingSpace {
    /// Decode, light in linear light, encode.
    #[default]
    Linear,
    /// Light the stored (sRGB-encoded) values as they are.
    Encoded,
}

impl ShadingSpace {
    /// A colour lit in this space as a frame stores it: encoded from linear light to sRGB ([`encode_srgb`]), or as
    /// it is.
    #[inline(always)]
    pub fn stored(self, color: Vec3) -> Vec3 {
        match self {
            Self::Linear => encode_srgb(color),
            Self::Encoded => color,
        }
    }
}

/// The sRGB decoding of an encoded channel `c` to linear light (IEC 61966-2-1, the piecewise curve with exponent
/// 2.4), computed in `f64` and rounded once: the same bits on every target, and at compile time for tables.
/// Values above 1 follow the curve; values at or below 0 stay linear.
///
/// # Examples
/// ```
/// use rastty_core::color::srgb_to_linear;
/// assert_eq!((srgb_to_linear(0.0), srgb_to_linear(1.0)), (0.0, 1.0));
/// assert!((srgb_to_linear(0.5) - 0.214).abs() < 1e-3);
/// ```
#[must_use]
pub const fn srgb_to_linear(c: f32) -> f32 {
    srgb_to_linear_f64(c as f64) as f32
}

/// The sRGB encoding of linear light `l` (IEC 61966-2-1's inverse), in `f64` and rounded once, for colours a
/// loader receives in linear light and stores as encoded values (glTF's factors); [`linear_to_srgb8`] gives the
/// nearest 8-bit code. Values at or below 0 stay linear.
///
/// # Examples
/// ```
/// use rastty_core::color::{linear_to_srgb, srgb_to_linear};
/// assert_eq!((linear_to_srgb(0.0), linear_to_srgb(1.0)), (0.0, 1.0));
/// assert!((linear_to_srgb(0.5) - 0.7354).abs() < 1e-4);
/// assert!((srgb_to_linear(linear_to_srgb(0.3)) - 0.3).abs() < 1e-6);
/// ```
#[must_use]
pub const fn linear_to_srgb(l: f32) -> f32 {
    let l = l as f64;
    (if l <= 0.003_130_8 { l * 12.92 } else { 1.055 * float::pow_f64(l, 1.0 / 2.4) - 0.055 }) as f32
}

const fn srgb_to_linear_f64(c: f64) -> f64 {
    if c <= 0.04045 { c / 12.92 } else { float::pow_f64((c + 0.055) / 1.055, 2.4) }
}

/// Each 8-bit sRGB code decoded to linear light: `SRGB_DECODE[c]` is `c / 255` decoded ([`srgb_to_linear`]),
/// computed by the compiler.
pub const SRGB_DECODE: [f32; 256] = {
    let mut table = [0.0; 256];
    let mut code = 0;
    while code < 256 {
        table[code] = srgb_to_linear_f64(code as f64 / 255.0) as f32;
        code += 1;
    }
    table
};

/// The boundaries between neighbouring codes in linear light: code `c` and `c + 1` meet at the encoded value
/// `(c + 0.5) / 255` decoded. A value's nearest code is the number of boundaries at or below it; the last entry,
/// infinite, stands for no boundary above code 255.
const SRGB_BOUNDARIES: [f32; 256] = {
    let mut table = [f32::INFINITY; 256];
    let mut code = 0;
    while code < 255 {
        table[code] = srgb_to_linear_f64((code as f64 + 0.5) / 255.0) as f32;
        code += 1;
    }
    table
};

/// The bits above which [`linear_to_srgb8`] looks a value up: `2^-13`, below the first boundary (`1.5 * 10^-4`).
const BUCKETS_START: u32 = 0x3900_0000;
/// Buckets from `2^-13` to 1: 128 per octave (the top 7 bits of the mantissa), narrow enough that at most one
/// boundary falls in each (tested below), since the codes are at most 78 to an octave.
const BUCKETS: usize = ((0x3F80_0000 - BUCKETS_START) >> 16) as usize;

/// For each bucket, the code of its lowest value: the number of boundaries at or below it.
const BUCKET_CODES: [u8; BUCKETS] = {
    let mut table = [0; BUCKETS];
    let (mut bucket, mut code) = (0, 0);
    while bucket < BUCKETS {
        let lowest = f32::from_bits(BUCKETS_START + ((bucket as u32) << 16));
        while SRGB_BOUNDARIES[code] <= lowest {
            code += 1;
        }
        table[bucket] = code as u8;
        bucket += 1;
    }
    table
};

/// The 8-bit sRGB code nearest the encoding of the linear value `l` (0 at or below 0 and for NaN, 255 from 1 up):
/// the code of `l`'s bucket (from its float bits), plus one if `l` is past the one boundary the bucket may hold.
/// Exact, a table read and a comparison, the same on every target.
///
/// # Examples
/// ```
/// use rastty_core::color::{SRGB_DECODE, linear_to_srgb8};
/// assert_eq!((linear_to_srgb8(0.0), linear_to_srgb8(0.5), linear_to_srgb8(1.0)), (0, 188, 255));
/// assert_eq!(linear_to_srgb8(SRGB_DECODE[100]), 100);
/// ```
#[must_use]
#[inline(always)]
pub fn linear_to_srgb8(l: f32) -> u32 {
    if l.is_nan() || l < f32::from_bits(BUCKETS_START) {
        return 0;
    }
    if l >= 1.0 {
        return 255;
    }
    let bucket = ((l.to_bits() - BUCKETS_START) >> 16) as usize;
    let code = BUCKET_CODES[bucket.min(BUCKETS - 1)];
    u32::from(code) + u32::from(l >= SRGB_BOUNDARIES[usize::from(code)])
}

/// The colour of a packed texel `0x..RRGGBB` as linear light: each code decoded through [`SRGB_DECODE`].
#[inline(always)]
pub fn decode_srgb888(p: u32) -> Vec3 {
    let channel = |shift: u32| SRGB_DECODE[((p >> shift) & 0xFF) as usize];
    Vec3::new(channel(16), channel(8), channel(0))
}

/// The linear colour `c` encoded: each channel its nearest sRGB code ([`linear_to_srgb8`]) over 255, so that
/// packing it ([`pack_rgb888`]) stores that code.
#[inline(always)]
pub fn encode_srgb(c: Vec3) -> Vec3 {
    const S: f32 = 1.0 / 255.0;
    Vec3::new(linear_to_srgb8(c.x) as f32 * S, linear_to_srgb8(c.y) as f32 * S, linear_to_srgb8(c.z) as f32 * S)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The standard's curve in `f64` from the platform's `powf`.
    fn decode(c: f64) -> f64 {
        if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
    }

    /// The compiler's table holds every code's decoding rounded once to `f32`.
    #[test]
    fn the_decoding_table_is_the_standard_curve() {
        for code in 0..=255u8 {
            assert_eq!(SRGB_DECODE[usize::from(code)], decode(f64::from(code) / 255.0) as f32, "code {code}");
        }
        assert_eq!(srgb_to_linear(2.0), decode(2.0) as f32);
        assert_eq!(srgb_to_linear(-0.5), -0.5 / 12.92);
    }

    /// Each bucket holds at most one boundary, so one comparison finds the code.
    #[test]
    fn no_bucket_holds_two_boundaries() {
        for bucket in 0..BUCKETS as u32 {
            let (low, high) =
                (f32::from_bits(BUCKETS_START + (bucket << 16)), f32::from_bits(BUCKETS_START + ((bucket + 1) << 16)));
            let inside = SRGB_BOUNDARIES.iter().filter(|&&b| low < b && b < high).count();
            assert!(inside <= 1, "bucket {bucket} [{low}, {high}) holds {inside} boundaries");
        }
    }

    /// The encoder gives the code nearest each value's encoding, computed here in `f64` from the standard's formula
    /// (values within 10^-4 of a code's edge, where rounding the boundary to `f32` could tip them, are left out),
    /// and the number of boundaries at or below every value, at a quarter of a million values across the buckets.
    #[test]
    fn the_encoder_gives_the_nearest_code() {
        let encode = |l: f64| if l <= 0.003_130_8 { l * 12.92 } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
        for i in 0..=20_000 {
            let l = f64::from(i) / 20_000.0;
            let scaled = encode(l) * 255.0;
            if (scaled - scaled.floor() - 0.5).abs() < 1e-4 {
                continue;
            }
            assert_eq!(linear_to_srgb8(l as f32), scaled.round() as u32, "linear {l}");
        }
        for bits in (0x3800_0000..0x3F90_0000u32).step_by(509) {
            let l = f32::from_bits(bits);
            assert_eq!(linear_to_srgb8(l), SRGB_BOUNDARIES[..255].partition_point(|&b| b <= l) as u32, "{l}");
        }
        for (l, code) in [(-1.0, 0), (f32::NAN, 0), (f32::INFINITY, 255), (1.0, 255), (7.5, 255), (0.0, 0)] {
            assert_eq!(linear_to_srgb8(l), code, "{l}");
        }
    }

    /// Every code survives decoding and encoding: the boundaries fall between the codes' decodings.
    #[test]
    fn every_code_comes_back() {
        for code in 0..=255u32 {
            assert_eq!(linear_to_srgb8(SRGB_DECODE[code as usize]), code);
            let packed = (code << 16) | ((255 - code) << 8) | (code / 2);
            assert_eq!(pack_rgb888(encode_srgb(decode_srgb888(packed))), packed);
        }
    }
}
