//! The varyings of a mapped draw: the normal always, the world position, texture coordinates and tangent only
//! when the draw uses them.

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

/// What a mapped draw interpolates: the world normal, and in the other slots the world position (`W`), texture
/// coordinates (`U`) and the world tangent with its handedness (`T`), each either carried or [`Absent`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceVaryings<W, U, T> {
    /// World-space normal (unit at the vertices).
    pub normal: Vec3,
    /// World-space position.
    pub world: W,
    /// Texture coordinates.
    pub uv: U,
    /// World-space tangent in `xyz`, handedness in `w`.
    pub tangent: T,
}

impl<W: Varyings, U: Varyings, T: Varyings> Varyings for SurfaceVaryings<W, U, T> {
    #[inline(always)]
    fn lerp(&self, o: &Self, t: f32) -> Self {
        Self {
            normal: Varyings::lerp(&self.normal, &o.normal, t),
            world: self.world.lerp(&o.world, t),
            uv: self.uv.lerp(&o.uv, t),
            tangent: self.tangent.lerp(&o.tangent, t),
        }
    }
    #[inline(always)]
    fn sub(&self, o: &Self) -> Self {
        Self {
            normal: Varyings::sub(&self.normal, &o.normal),
            world: self.world.sub(&o.world),
            uv: self.uv.sub(&o.uv),
            tangent: self.tangent.sub(&o.tangent),
        }
    }
    #[inline(always)]
    fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
        Self {
            normal: self.normal.interpolate(&d1.normal, w1, &d2.normal, w2),
            world: self.world.interpolate(&d1.world, w1, &d2.world, w2),
            uv: self.uv.interpolate(&d1.uv, w1, &d2.uv, w2),
            tangent: self.tangent.interpolate(&d1.tangent, w1, &d2.tangent, w2),
        }
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        Varyings::is_finite(&self.normal) && self.world.is_finite() && self.uv.is_finite() && self.tangent.is_finite()
    }
}
