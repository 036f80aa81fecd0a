//! The varyings of a draw: each slot carried only when the draw's variant uses it.

use crate::math::{Vec2, Vec3, Vec4};
use crate::pipeline::Varyings;

/// A varying that a draw carries (the value's own type) or not ([`Absent`]), decided at compile time.
pub trait Slot<T: Copy>: Varyings {
    /// True when carried.
    const PRESENT: bool;
    /// The slot's per-vertex value (`f` runs only when carried).
    fn capture(f: impl FnOnce() -> T) -> Self;
    /// The interpolated value, when carried.
    fn get(&self) -> Option<T>;
}

/// A varying not carried: nothing stored, nothing interpolated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Absent;

impl Varyings for Absent {
    #[inline(always)]
    fn lerp(&self, _: &Self, _: f32) -> Self {
        Absent
    }
    #[inline(always)]
    fn sub(&self, _: &Self) -> Self {
        Absent
    }
    #[inline(always)]
    fn interpolate(&self, _: &Self, _: f32, _: &Self, _: f32) -> Self {
        Absent
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        true
    }
}

impl<T: Copy> Slot<T> for Absent {
    const PRESENT: bool = false;
    #[inline(always)]
    fn capture(_: impl FnOnce() -> T) -> Self {
        Absent
    }
    #[inline(always)]
    fn get(&self) -> Option<T> {
        None
    }
}

/// Implements [`Slot`] for a varying type carried as itself.
macro_rules! carried {
    ($($t:ty),+) => {$(
        impl Slot<$t> for $t {
            const PRESENT: bool = true;
            #[inline(always)]
            fn capture(f: impl FnOnce() -> $t) -> Self {
                f()
            }
            #[inline(always)]
            fn get(&self) -> Option<$t> {
                Some(*self)
            }
        }
    )+};
}

carried!(Vec2, Vec3, Vec4);

/// What a draw interpolates, in five slots, each carried or [`Absent`] as its variant's layout says. The first
/// two `Vec3` slots hold what the shading model reads per vertex ([`super::Layout`]): the world normal and the
/// world position (per-pixel lighting), the diffuse and specular light (Gouraud), the world normal (the normals
/// view). Each component is interpolated on its own with the same weights, so what a slot means changes no value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceVaryings<A, B, U, T, C = Absent> {
    /// The first `Vec3` slot.
    pub first: A,
    /// The second `Vec3` slot.
    pub second: B,
    /// Texture coordinates.
    pub uv: U,
    /// World-space tangent in `xyz`, handedness in `w`.
    pub tangent: T,
    /// The vertex colour (part of the albedo of every model that colours).
    pub color: C,
}

impl<A: Varyings, B: Varyings, U: Varyings, T: Varyings, C: Varyings> Varyings for SurfaceVaryings<A, B, U, T, C> {
    #[inline(always)]
    fn lerp(&self, o: &Self, t: f32) -> Self {
        Self {
            first: self.first.lerp(&o.first, t),
            second: self.second.lerp(&o.second, t),
            uv: self.uv.lerp(&o.uv, t),
            tangent: self.tangent.lerp(&o.tangent, t),
            color: self.color.lerp(&o.color, t),
        }
    }
    #[inline(always)]
    fn sub(&self, o: &Self) -> Self {
        Self {
            first: self.first.sub(&o.first),
            second: self.second.sub(&o.second),
            uv: self.uv.sub(&o.uv),
            tangent: self.tangent.sub(&o.tangent),
            color: self.color.sub(&o.color),
        }
    }
    #[inline(always)]
    fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
        Self {
            first: self.first.interpolate(&d1.first, w1, &d2.first, w2),
            second: self.second.interpolate(&d1.second, w1, &d2.second, w2),
            uv: self.uv.interpolate(&d1.uv, w1, &d2.uv, w2),
            tangent: self.tangent.interpolate(&d1.tangent, w1, &d2.tangent, w2),
            color: self.color.interpolate(&d1.color, w1, &d2.color, w2),
        }
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.first.is_finite()
            && self.second.is_finite()
            && self.uv.is_finite()
            && self.tangent.is_finite()
            && self.color.is_finite()
    }
}
