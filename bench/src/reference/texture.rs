//! Bilinear texture sampling in `f64`, with the core's conventions but exact weights.

use rastty_core::color::ShadingSpace;
use rastty_core::texture::WrapMode;

use super::math::V3;
use super::srgb;
use rastty_scene::model::TextureImage;

/// A texel's channels in `[0, 1]` (`0x00RRGGBB`, the top byte ignored), decoded to linear light in
/// [`ShadingSpace::Linear`].
fn unpack(p: u32, space: ShadingSpace) -> V3 {
    let c = |shift: u32| {
        let c = f64::from((p >> shift) & 0xFF) / 255.0;
        if space == ShadingSpace::Linear { srgb::decode(c) } else { c }
    };
    V3::new(c(16), c(8), c(0))
}

/// Reduces a coordinate to `[0, 1]` as the core's wrap modes do; NaN and infinities give 0.
fn reduce(t: f64, wrap: WrapMode) -> f64 {
    if !t.is_finite() {
        return 0.0;
    }
    match wrap {
        WrapMode::Repeat => (t - t.floor()).clamp(0.0, 1.0),
        WrapMode::Clamp => t.clamp(0.0, 1.0),
    }
}

/// A texel index one step outside `0..size` at most, brought inside.
fn index(i: i64, size: i64, wrap: WrapMode) -> usize {
    let i = match wrap {
        WrapMode::Repeat => i.rem_euclid(size),
        WrapMode::Clamp => i.clamp(0, size - 1),
    };
    i as usize
}

/// Samples `texture` at `(u, v)` with a bilinear filter: `u` left to right, `v` bottom to top, row 0 of the
/// image at the top, texel centres at half-integers (texel `(x, y)` is centred on
/// `u = (x + 0.5) / width`, `v = 1 - (y + 0.5) / height`). The four texels are blended with exact `f64` weights,
/// so a texel centre returns the texel and a point half-way between two texels their exact mean: in linear light
/// in [`ShadingSpace::Linear`] (each texel decoded first), else of the stored values.
///
/// An empty or inconsistent image (fewer texels than `width * height`) samples black.
pub fn sample_bilinear(texture: &TextureImage, wrap: WrapMode, space: ShadingSpace, [u, v]: [f64; 2]) -> [f64; 3] {
    let (w, h) = (i64::from(texture.width), i64::from(texture.height));
    if w == 0 || h == 0 || texture.texels.len() < (w * h) as usize {
        return [0.0; 3];
    }
    let x = reduce(u, wrap) * w as f64 - 0.5;
    let y = (1.0 - reduce(v, wrap)) * h as f64 - 0.5;
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let (x0, y0) = (x0 as i64, y0 as i64);
    let (xa, xb) = (index(x0, w, wrap), index(x0 + 1, w, wrap));
    let (ya, yb) = (index(y0, h, wrap), index(y0 + 1, h, wrap));
    let texel = |x: usize, y: usize| unpack(texture.texels[y * w as usize + x], space);
    // `a (1 - f) + b f`: exactly `a` at `f = 0` and `b` at `f = 1`.
    let lerp = |a: V3, b: V3, f: f64| a * (1.0 - f) + b * f;
    let top = lerp(texel(xa, ya), texel(xb, ya), fx);
    let bottom = lerp(texel(xa, yb), texel(xb, yb), fx);
    lerp(top, bottom, fy).to_array()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(width: u32, height: u32, texels: Vec<u32>) -> TextureImage {
        TextureImage::new(width, height, texels)
    }

    #[test]
    fn texel_centres_give_the_texel_exactly() {
        // 3x2: row 0 (top) then row 1.
        let t = image(3, 2, vec![0x010203, 0x0A0B0C, 0xFF8001, 0x7F7F7F, 0x000000, 0xFFFFFF]);
        for y in 0..2u32 {
            for x in 0..3u32 {
                let uv = [(f64::from(x) + 0.5) / 3.0, 1.0 - (f64::from(y) + 0.5) / 2.0];
                let want = unpack(t.texels[(y * 3 + x) as usize], ShadingSpace::Encoded).to_array();
                for wrap in [WrapMode::Repeat, WrapMode::Clamp] {
                    assert_eq!(sample_bilinear(&t, wrap, ShadingSpace::Encoded, uv), want, "texel ({x}, {y}) {wrap:?}");
                }
            }
        }
    }

    #[test]
    fn half_way_gives_the_exact_mean_without_8_bit_rounding() {
        // Blue 1 and 2 (out of 255): the mean 1.5/255 has no 8-bit representation.
        let t = image(2, 1, vec![0x000001, 0x000002]);
        let s = sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Encoded, [0.5, 0.5]);
        assert_eq!(s, [0.0, 0.0, 1.5 / 255.0]);
        // A quarter of the way: weights 3/4 and 1/4.
        let s = sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Encoded, [0.375, 0.5]);
        assert!((s[2] - 1.25 / 255.0).abs() < 1e-17);
        // Vertically: 2x2 with the top row 0 and the bottom row 255 gives 127.5 / 255 half-way.
        let t = image(1, 2, vec![0x000000, 0xFFFFFF]);
        assert_eq!(sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Encoded, [0.5, 0.5]), [0.5; 3]);
        // The top row is at v near 1.
        assert_eq!(sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Encoded, [0.5, 0.75]), [0.0; 3]);
        // In linear light half-way between black and white is half of white's light, and code 0x80 is 0.2159.
        assert_eq!(sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Linear, [0.5, 0.5]), [0.5; 3]);
        let grey = sample_bilinear(&image(1, 1, vec![0x808080]), WrapMode::Clamp, ShadingSpace::Linear, [0.5, 0.5]);
        assert!((grey[0] - 0.215_861).abs() < 1e-6, "{grey:?}");
    }

    #[test]
    fn repeat_wraps_across_the_edge_and_clamp_does_not() {
        let t = image(2, 1, vec![0x000000, 0x0000FF]);
        // u = 0: half-way between the last texel (wrapped) and the first.
        assert_eq!(sample_bilinear(&t, WrapMode::Repeat, ShadingSpace::Encoded, [0.0, 0.5]), [0.0, 0.0, 0.5]);
        assert_eq!(sample_bilinear(&t, WrapMode::Repeat, ShadingSpace::Encoded, [3.0, 0.5]), [0.0, 0.0, 0.5]);
        assert_eq!(sample_bilinear(&t, WrapMode::Clamp, ShadingSpace::Encoded, [0.0, 0.5]), [0.0; 3]);
        assert_eq!(sample_bilinear(&t, WrapMode::Repeat, ShadingSpace::Encoded, [f64::NAN, 0.5]), [0.0, 0.0, 0.5]);
    }
}
