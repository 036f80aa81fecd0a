//! The Oklab perceptual colour space, used to measure how far apart two colours look.
//!
//! Source of the matrices: Björn Ottosson, "A perceptual color space for image processing" (2020),
//! <https://bottosson.github.io/posts/oklab/>.

/// A colour in Oklab: `l` is perceived lightness (0..=1 for sRGB colours), `a` and `b` the opponent axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Oklab {
    /// Perceived lightness.
    pub l: f32,
    /// Green (negative) to red (positive).
    pub a: f32,
    /// Blue (negative) to yellow (positive).
    pub b: f32,
}

impl Oklab {
    /// Converts an sRGB colour with 8-bit channels.
    pub fn from_srgb8(r: u8, g: u8, b: u8) -> Self {
        Self::from_srgb(f32::from(r) / 255.0, f32::from(g) / 255.0, f32::from(b) / 255.0)
    }

    /// Converts an sRGB colour with channels in `0.0..=1.0` (gamma-encoded, as stored in images).
    pub fn from_srgb(r: f32, g: f32, b: f32) -> Self {
        Self::from_linear_srgb(srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b))
    }

    /// Converts a linear-light sRGB colour.
    pub fn from_linear_srgb(r: f32, g: f32, b: f32) -> Self {
        let l = 0.412_221_46 * r + 0.536_332_55 * g + 0.051_445_995 * b;
        let m = 0.211_903_5 * r + 0.680_699_5 * g + 0.107_396_96 * b;
        let s = 0.088_302_46 * r + 0.281_718_85 * g + 0.629_978_7 * b;
        let (l, m, s) = (l.cbrt(), m.cbrt(), s.cbrt());
        Oklab {
            l: 0.210_454_26 * l + 0.793_617_8 * m - 0.004_072_047 * s,
            a: 1.977_998_5 * l - 2.428_592_2 * m + 0.450_593_7 * s,
            b: 0.025_904_037 * l + 0.782_771_77 * m - 0.808_675_77 * s,
        }
    }

    /// The linear-light sRGB colour of this Oklab colour (the inverse of [`Oklab::from_linear_srgb`]); colours
    /// outside the sRGB gamut give channels outside `0.0..=1.0`.
    pub fn to_linear_srgb(self) -> [f32; 3] {
        let l = self.l + 0.396_337_78 * self.a + 0.215_803_76 * self.b;
        let m = self.l - 0.105_561_346 * self.a - 0.063_854_17 * self.b;
        let s = self.l - 0.089_484_18 * self.a - 1.291_485_5 * self.b;
        let (l, m, s) = (l * l * l, m * m * m, s * s * s);
        [
            4.076_741_7 * l - 3.307_711_6 * m + 0.230_969_94 * s,
            -1.268_438 * l + 2.609_757_4 * m - 0.341_319_4 * s,
            -0.004_196_086_3 * l - 0.703_418_6 * m + 1.707_614_7 * s,
        ]
    }

    /// The nearest 8-bit sRGB colour, `0x00RRGGBB`, channels clamped to the gamut.
    pub fn to_srgb8(self) -> u32 {
        let [r, g, b] = self.to_linear_srgb();
        let channel = |c: f32| (linear_to_srgb(c.clamp(0.0, 1.0)) * 255.0).round() as u32;
        channel(r) << 16 | channel(g) << 8 | channel(b)
    }

    /// Squared Euclidean distance (ΔE² in Oklab); monotonic in the perceptual difference.
    #[inline]
    pub fn distance_squared(self, other: Oklab) -> f32 {
        let (dl, da, db) = (self.l - other.l, self.a - other.a, self.b - other.b);
        dl * dl + da * da + db * db
    }
}

/// The sRGB transfer function, decoded: gamma-encoded `0..=1` to linear light `0..=1`.
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.040_45 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// The sRGB transfer function: linear light `0..=1` to gamma-encoded `0..=1`.
pub fn linear_to_srgb(c: f32) -> f32 {
    if c <= 0.003_130_8 { c * 12.92 } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn white_and_black_sit_at_the_ends_of_the_lightness_axis() {
        let white = Oklab::from_srgb8(255, 255, 255);
        assert!((white.l - 1.0).abs() < 1e-3 && white.a.abs() < 1e-3 && white.b.abs() < 1e-3, "{white:?}");
        let black = Oklab::from_srgb8(0, 0, 0);
        assert!(black.l.abs() < 1e-6 && black.a.abs() < 1e-6 && black.b.abs() < 1e-6, "{black:?}");
    }

    #[test]
    fn reference_values_from_the_oklab_post() {
        // Ottosson's table: linear sRGB red ~ (0.628, 0.225, 0.126), blue ~ (0.452, -0.032, -0.312).
        let red = Oklab::from_linear_srgb(1.0, 0.0, 0.0);
        assert!((red.l - 0.628).abs() < 2e-3 && (red.a - 0.225).abs() < 2e-3 && (red.b - 0.126).abs() < 2e-3);
        let blue = Oklab::from_linear_srgb(0.0, 0.0, 1.0);
        assert!((blue.l - 0.452).abs() < 2e-3 && (blue.a + 0.032).abs() < 2e-3 && (blue.b + 0.312).abs() < 2e-3);
    }

    #[test]
    fn every_8_bit_colour_survives_the_round_trip() {
        for v in (0..0x0100_0000u32).step_by(4099).chain([0, 0xFFFFFF, 0xFF0000, 0x00FF00, 0x0000FF]) {
            let [_, r, g, b] = v.to_be_bytes();
            assert_eq!(Oklab::from_srgb8(r, g, b).to_srgb8(), v, "{v:06x}");
        }
    }

    #[test]
    fn transfer_function_is_continuous_and_monotonic() {
        let mut last = -1.0;
        for i in 0..=255 {
            let v = srgb_to_linear(i as f32 / 255.0);
            assert!(v > last);
            last = v;
        }
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
    }
}
