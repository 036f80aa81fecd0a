//! Texture filters (nearest, bilinear) and wrap modes (repeat, clamp), as types for compile-time selection and as
//! enums for run-time selection.

use super::Texture;
use crate::color::{decode_srgb888, unpack_rgb888};
use crate::math::{Vec2, Vec3, float};

/// How coordinates outside `[0, 1]` map onto the texture.
///
/// Both modes first bring the coordinate into `[0, 1]` in floating point and then index integer texels: NaN (and
/// so also an infinite coordinate under [`Repeat`]) becomes 0; the texel index is always in range.
pub trait Wrap {
    /// A coordinate in texture units (`[0, 1]` spans the image once) reduced to `[0, 1]`.
    fn reduce(t: f32) -> f32;
    /// A texel index in `-1..=size` (one step outside at most, as filters produce from a reduced coordinate)
    /// brought into `0..size`.
    fn index(i: i32, size: i32) -> i32;
}

/// Tile the texture: `u` and `u + 1` sample the same texel.
#[derive(Clone, Copy, Debug, Default)]
pub struct Repeat;

impl Wrap for Repeat {
    #[inline(always)]
    fn reduce(t: f32) -> f32 {
        // The fractional part: exact for every finite t (from 2^23 up, floor(t) = t and the fraction is 0). NaN and
        // infinities give NaN here, which `clamp` turns into 0; it also keeps a rounded-up 1.0 in range.
        float::clamp(t - float::floor(t), 0.0, 1.0)
    }
    #[inline(always)]
    fn index(i: i32, size: i32) -> i32 {
        if i < 0 {
            i + size
        } else if i >= size {
            i - size
        } else {
            i
        }
    }
}

/// Extend the edge texels outward.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clamp;

impl Wrap for Clamp {
    #[inline(always)]
    fn reduce(t: f32) -> f32 {
        float::clamp(t, 0.0, 1.0)
    }
    #[inline(always)]
    fn index(i: i32, size: i32) -> i32 {
        i.clamp(0, size - 1)
    }
}

/// How a texel colour is reconstructed from the texels around a sample point.
pub trait Filter {
    /// Where a batch of `N` samples reads a texture: it depends on the texture's size, not on its texels, so
    /// textures of one size sampled at the same coordinates (a material's maps, usually) share it.
    type Addresses<const N: usize>: Copy;

    /// Samples `texture` at `uv` with wrap mode `W`, as a packed `0xTTRRGGBB` value (every channel, transparency
    /// too, filtered alike).
    fn sample_packed<W: Wrap>(texture: &Texture<'_>, uv: Vec2) -> u32;

    /// The addresses of the samples at each `(u[i], v[i])` in a `width x height` texture (as
    /// [`Texture::new`] accepts it). Filters whose addresses are plain arithmetic compute them for all lanes in one
    /// loop the compiler can widen.
    fn addresses<W: Wrap, const N: usize>(width: u32, height: u32, u: &[f32; N], v: &[f32; N]) -> Self::Addresses<N>;

    /// The samples of `texture` at `addresses` (made for its size), into `out[i]`: what
    /// [`Filter::sample_packed`] gives at each lane's coordinates. Addresses made for another size read other
    /// texels (0 past the end), never panic.
    fn read<W: Wrap, const N: usize>(texture: &Texture<'_>, addresses: &Self::Addresses<N>, out: &mut [u32; N]);

    /// [`Filter::sample_light`] at the lanes' `addresses` (made for `texture`'s size), into `out[i]`.
    fn read_light<W: Wrap, const N: usize>(texture: &Texture<'_>, addresses: &Self::Addresses<N>, out: &mut [Vec3; N]);

    /// [`Filter::sample_packed`] at each `(u[i], v[i])`, into `out[i]`: a batch of samples at once.
    #[inline(always)]
    fn sample_packed_lanes<W: Wrap, const N: usize>(
        texture: &Texture<'_>,
        u: &[f32; N],
        v: &[f32; N],
        out: &mut [u32; N],
    ) {
        let addresses = Self::addresses::<W, N>(texture.width(), texture.height(), u, v);
        Self::read::<W, N>(texture, &addresses, out);
    }

    /// Samples `texture` at `uv` with wrap mode `W`, channels in `[0, 1]`.
    #[inline(always)]
    fn sample<W: Wrap>(texture: &Texture<'_>, uv: Vec2) -> Vec3 {
        unpack_rgb888(Self::sample_packed::<W>(texture, uv))
    }

    /// Samples the sRGB-encoded colour texture `texture` at `uv` with wrap mode `W` in linear light: each texel's
    /// codes decoded ([`crate::color::SRGB_DECODE`]) before the texels are blended, so that half-way between black
    /// and white is half of white's light (code 188), not the codes' mean (128) decoded (0.22 of white's light).
    fn sample_light<W: Wrap>(texture: &Texture<'_>, uv: Vec2) -> Vec3;
}

/// The texel containing the sample point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Nearest;

impl Filter for Nearest {
    /// The position of each lane's texel in the texture's row-major texels.
    type Addresses<const N: usize> = [u32; N];

    #[inline(always)]
    fn sample_packed<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> u32 {
        let (x, y) = Self::texel::<W>(t.width, t.height, uv);
        t.packed(x, y)
    }

    #[inline(always)]
    fn sample_light<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> Vec3 {
        decode_srgb888(Self::sample_packed::<W>(t, uv))
    }

    #[inline(always)]
    fn addresses<W: Wrap, const N: usize>(width: u32, height: u32, u: &[f32; N], v: &[f32; N]) -> [u32; N] {
        let (w, h) = (width as i32, height as i32);
        let mut index = [0u32; N];
        for i in 0..N {
            let (x, y) = Self::texel::<W>(w, h, Vec2::new(u[i], v[i]));
            index[i] = Texture::index_in(w, x, y);
        }
        index
    }

    #[inline(always)]
    fn read<W: Wrap, const N: usize>(t: &Texture<'_>, index: &[u32; N], out: &mut [u32; N]) {
        for (o, &i) in out.iter_mut().zip(index) {
            *o = t.at(i);
        }
    }

    #[inline(always)]
    fn read_light<W: Wrap, const N: usize>(t: &Texture<'_>, index: &[u32; N], out: &mut [Vec3; N]) {
        for (o, &i) in out.iter_mut().zip(index) {
            *o = decode_srgb888(t.at(i));
        }
    }
}

impl Nearest {
    /// The column and row of the texel containing `uv` in a `w x h` texture.
    #[inline(always)]
    fn texel<W: Wrap>(w: i32, h: i32, uv: Vec2) -> (i32, i32) {
        // In [0, size]: floor is exact, and the integer conversion needs no saturation.
        let x = float::round_small_to_u32(float::floor(W::reduce(uv.x) * w as f32)) as i32;
        let y = float::round_small_to_u32(float::floor((1.0 - W::reduce(uv.y)) * h as f32)) as i32;
        (W::index(x, w), W::index(y, h))
    }
}

/// The four texels around the sample point, weighted by distance (texel centres at half-integers).
///
/// The sample point is snapped to 1/256 of a texel (8 bits of sub-texel precision is what Direct3D 11 requires,
/// functional specification 7.18.16.1). As stored ([`Filter::sample_packed`]) the texels are blended in integer
/// arithmetic on the packed channels, as texture units do; in light ([`Filter::sample_light`]) in `f32` with
/// those weights.
#[derive(Clone, Copy, Debug, Default)]
pub struct Bilinear;

impl Filter for Bilinear {
    /// The lanes' coordinates: the four texels and their weights are worked out per sample, in
    /// [`Filter::read`].
    type Addresses<const N: usize> = ([f32; N], [f32; N]);

    #[inline(always)]
    fn addresses<W: Wrap, const N: usize>(_: u32, _: u32, u: &[f32; N], v: &[f32; N]) -> Self::Addresses<N> {
        (*u, *v)
    }

    #[inline(always)]
    fn read<W: Wrap, const N: usize>(t: &Texture<'_>, (u, v): &Self::Addresses<N>, out: &mut [u32; N]) {
        for ((o, &u), &v) in out.iter_mut().zip(u).zip(v) {
            *o = Self::sample_packed::<W>(t, Vec2::new(u, v));
        }
    }

    #[inline(always)]
    fn read_light<W: Wrap, const N: usize>(t: &Texture<'_>, (u, v): &Self::Addresses<N>, out: &mut [Vec3; N]) {
        for ((o, &u), &v) in out.iter_mut().zip(u).zip(v) {
            *o = Self::sample_light::<W>(t, Vec2::new(u, v));
        }
    }

    #[inline(always)]
    fn sample_packed<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> u32 {
        let ([top_left, top_right, bottom_left, bottom_right], (ax, ay)) = Self::taps::<W>(t, uv);
        blend(blend(top_left, top_right, ax), blend(bottom_left, bottom_right, ax), ay)
    }

    #[inline(always)]
    fn sample_light<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> Vec3 {
        let (texels, (ax, ay)) = Self::taps::<W>(t, uv);
        let [top_left, top_right, bottom_left, bottom_right] = texels.map(decode_srgb888);
        // Exact: an 8-bit weight over 256.
        let (wx, wy) = (ax as f32 * (1.0 / 256.0), ay as f32 * (1.0 / 256.0));
        top_left.lerp(top_right, wx).lerp(bottom_left.lerp(bottom_right, wx), wy)
    }
}

impl Bilinear {
    /// The four texels around `uv` (top left, top right, bottom left, bottom right) and the weights of the right
    /// and the bottom ones, in 256ths.
    #[inline(always)]
    fn taps<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> ([u32; 4], (u32, u32)) {
        let (w, h) = (t.width, t.height);
        // Fixed point with 8 fractional bits, offset by one texel (+256 - 128 for the half-texel centre shift) so
        // that it is never negative: the integer part is the left/top texel + 1, the fraction its neighbour's
        // weight.
        let fixed = |r: f32, size: i32| float::round_small_to_u32(r * (size * 256) as f32 + 128.0);
        let (fx, fy) = (fixed(W::reduce(uv.x), w), fixed(1.0 - W::reduce(uv.y), h));
        let (x0, y0) = ((fx >> 8) as i32 - 1, (fy >> 8) as i32 - 1);
        let (xa, xb) = (W::index(x0, w), W::index(x0 + 1, w));
        let (ya, yb) = (W::index(y0, h), W::index(y0 + 1, h));
        ([t.packed(xa, ya), t.packed(xb, ya), t.packed(xa, yb), t.packed(xb, yb)], (fx & 0xFF, fy & 0xFF))
    }
}

/// `p + (q - p) * w / 256` on each channel of two `0xTTRRGGBB` texels, rounded, for `w` in `0..256`.
///
/// Two channels 16 bits apart are blended in one multiply (they cannot carry into each other): red with blue,
/// then transparency with green, shifted down first so that the products fit 32 bits. Green alone gives what it
/// gave before the transparency byte was blended: `((g p + g q + 128) >> 8) << 8` either way.
#[inline(always)]
pub(super) fn blend(p: u32, q: u32, w: u32) -> u32 {
    let v = 256 - w;
    let rb = (((p & 0xFF00FF) * v + (q & 0xFF00FF) * w + 0x80_0080) >> 8) & 0xFF00FF;
    let tg = ((((p >> 8) & 0xFF00FF) * v + ((q >> 8) & 0xFF00FF) * w + 0x80_0080) >> 8) & 0xFF00FF;
    rb | (tg << 8)
}

/// A filter chosen at run time.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FilterMode {
    /// [`Nearest`].
    Nearest,
    /// [`Bilinear`].
    #[default]
    Bilinear,
}

/// A wrap mode chosen at run time.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WrapMode {
    /// [`Repeat`].
    #[default]
    Repeat,
    /// [`Clamp`].
    Clamp,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A batch of samples gives what one sample at a time gives, for both filters and wrap modes, at coordinates
    /// inside, outside and on the edges of the texture, and at NaN and infinities.
    #[test]
    fn lanes_sample_what_single_samples_do() {
        let texels: [u32; 15] = core::array::from_fn(|i| i as u32 * 0x1110_2030);
        let texture = Texture::new(&texels, 5, 3).unwrap();
        let special = [0.0, 1.0, -0.0, 0.5, -1.25, 2.75, 1e-9, -1e-9, 1e9, f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
        let uv: [Vec2; 64] = core::array::from_fn(|i| {
            let u = if i < special.len() { special[i] } else { i as f32 * 0.173 - 3.0 };
            Vec2::new(u, special[(i * 5) % special.len()] + i as f32 * 0.031)
        });
        fn check<F: Filter, W: Wrap>(texture: &Texture<'_>, uv: &[Vec2; 64]) {
            let mut lanes = [0; 64];
            let (u, v) = (uv.map(|uv| uv.x), uv.map(|uv| uv.y));
            F::sample_packed_lanes::<W, 64>(texture, &u, &v, &mut lanes);
            for (i, (&lane, &uv)) in lanes.iter().zip(uv).enumerate() {
                assert_eq!(lane, F::sample_packed::<W>(texture, uv), "lane {i} at {uv:?}");
            }
        }
        check::<Nearest, Repeat>(&texture, &uv);
        check::<Nearest, Clamp>(&texture, &uv);
        check::<Bilinear, Repeat>(&texture, &uv);
        check::<Bilinear, Clamp>(&texture, &uv);
    }

    /// The transparency byte is blended like the colour channels, and the colour channels of texels with an
    /// opaque top byte are what they were before it was blended (the old green formula, kept here).
    #[test]
    fn blend_filters_transparency_and_keeps_colours() {
        assert_eq!(blend(0xFF00_0000, 0, 128), 0x8000_0000);
        assert_eq!(blend(0xFF00_0000, 0x00FF_FFFF, 64) >> 24, (255 * 192 + 128) >> 8);
        let old_green = |p: u32, q: u32, w: u32| (((p & 0xFF00) * (256 - w) + (q & 0xFF00) * w + 0x8000) >> 8) & 0xFF00;
        let mut x = 0x1234_5678u32;
        for _ in 0..10_000 {
            // xorshift32 (Marsaglia 2003).
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            let (p, q, w) = (x & 0xFF_FFFF, x.rotate_left(11) & 0xFF_FFFF, x >> 24);
            assert_eq!(blend(p, q, w) & 0xFF00, old_green(p, q, w), "{p:06x} {q:06x} {w}");
            assert_eq!(blend(p, q, w) >> 24, 0);
        }
    }
}
