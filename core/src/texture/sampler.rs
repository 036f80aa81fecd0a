//! Texture filters (nearest, bilinear) and wrap modes (repeat, clamp), as types for compile-time selection and as
//! enums for run-time selection.

use super::Texture;
use crate::math::{Vec2, Vec3, float};

/// How coordinates outside `[0, 1]` map onto the texture.
///
/// Both modes first bring the coordinate into `[0, 1]` in floating point and then index integer texels: NaN (and
/// so also an infinite coordinate under [`Repeat`]) becomes 0; the texel index is always in range.
pub trait Wrap {
    /// A coordinate in texture units (`[0, 1]` spans the image once) reduced to `[0, 1]`.
    fn reduce(t: f32) -> f32;
    /// An integer texel index, possibly one outside `0..size`, brought back into range.
    fn index(i: i32, size: i32) -> i32;
}

/// Tile the texture: `u` and `u + 1` sample the same texel.
#[derive(Clone, Copy, Debug, Default)]
pub struct Repeat;

impl Wrap for Repeat {
    #[inline(always)]
    fn reduce(t: f32) -> f32 {
        // The fractional part; `clamp` maps NaN (from NaN or infinite t) to 0 and a rounded-up 1.0 stays in range.
        float::clamp(t - float::floor(t), 0.0, 1.0)
    }
    #[inline(always)]
    fn index(i: i32, size: i32) -> i32 {
        i.rem_euclid(size)
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
    /// Samples `texture` at `uv` with wrap mode `W`.
    fn sample<W: Wrap>(texture: &Texture<'_>, uv: Vec2) -> Vec3;
}

/// The texel containing the sample point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Nearest;

impl Filter for Nearest {
    #[inline(always)]
    fn sample<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> Vec3 {
        let (w, h) = (t.width, t.height);
        let x = float::floor_to_i32(W::reduce(uv.x) * w as f32);
        let y = float::floor_to_i32((1.0 - W::reduce(uv.y)) * h as f32);
        t.texel(W::index(x, w), W::index(y, h))
    }
}

/// The four texels around the sample point, weighted by distance (texel centres at half-integers).
#[derive(Clone, Copy, Debug, Default)]
pub struct Bilinear;

impl Filter for Bilinear {
    #[inline(always)]
    fn sample<W: Wrap>(t: &Texture<'_>, uv: Vec2) -> Vec3 {
        let (w, h) = (t.width, t.height);
        let fx = W::reduce(uv.x) * w as f32 - 0.5;
        let fy = (1.0 - W::reduce(uv.y)) * h as f32 - 0.5;
        let (x0, y0) = (float::floor_to_i32(fx), float::floor_to_i32(fy));
        let (ax, ay) = (fx - x0 as f32, fy - y0 as f32);
        let (xa, xb) = (W::index(x0, w), W::index(x0 + 1, w));
        let (ya, yb) = (W::index(y0, h), W::index(y0 + 1, h));
        let top = t.texel(xa, ya).lerp(t.texel(xb, ya), ax);
        let bottom = t.texel(xa, yb).lerp(t.texel(xb, yb), ax);
        top.lerp(bottom, ay)
    }
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
