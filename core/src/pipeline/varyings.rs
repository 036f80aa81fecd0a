//! Values that the rasterizer interpolates between a triangle's vertices.

use crate::math::{Vec2, Vec3, Vec4};

/// Per-vertex values interpolated across a triangle (colours, normals, texture coordinates...).
///
/// Every component is interpolated independently with the same weights, so a shader that carries more values
/// still computes bit-identical results for the ones it shares with a leaner shader. `()` carries nothing: a
/// shader whose varyings are `()` interpolates nothing at all.
///
/// Implemented for `()`, `f32`, [`Vec2`], [`Vec3`], [`Vec4`], arrays of varyings, and tuples of up to four.
pub trait Varyings: Copy {
    /// `self + (other - self) * t`: a point on the segment, used when clipping cuts an edge.
    fn lerp(&self, other: &Self, t: f32) -> Self;
    /// `self - other`, component-wise: a triangle's per-edge differences, computed once per triangle.
    fn sub(&self, other: &Self) -> Self;
    /// `self + d1 * w1 + d2 * w2`: the value at barycentric weights `(1 - w1 - w2, w1, w2)` given the vertex-0
    /// value `self` and the differences `d1 = v1 - v0`, `d2 = v2 - v0`.
    ///
    /// This form reproduces a constant attribute exactly, whatever rounding the weights carry.
    fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self;
    /// True when every component is finite; a vertex whose varyings are not is skipped with its triangle.
    fn is_finite(&self) -> bool;
}

impl Varyings for () {
    #[inline(always)]
    fn lerp(&self, _: &Self, _: f32) -> Self {}
    #[inline(always)]
    fn sub(&self, _: &Self) -> Self {}
    #[inline(always)]
    fn interpolate(&self, _: &Self, _: f32, _: &Self, _: f32) -> Self {}
    #[inline(always)]
    fn is_finite(&self) -> bool {
        true
    }
}

impl Varyings for f32 {
    #[inline(always)]
    fn lerp(&self, o: &Self, t: f32) -> Self {
        self + (o - self) * t
    }
    #[inline(always)]
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    #[inline(always)]
    fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
        self + d1 * w1 + d2 * w2
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        f32::is_finite(*self)
    }
}

/// Implements [`Varyings`](crate::pipeline::Varyings) for a struct whose fields all implement it, field by
/// field.
///
/// # Examples
/// ```
/// use rastty_core::{impl_varyings, math::{Vec2, Vec3}};
/// #[derive(Clone, Copy)]
/// struct MyVaryings {
///     normal: Vec3,
///     uv: Vec2,
/// }
/// impl_varyings!(MyVaryings { normal, uv });
/// ```
#[macro_export]
macro_rules! impl_varyings {
    ($t:ident { $($f:ident),+ $(,)? }) => {
        impl $crate::pipeline::Varyings for $t {
            #[inline(always)]
            fn lerp(&self, o: &Self, t: f32) -> Self {
                $t { $($f: $crate::pipeline::Varyings::lerp(&self.$f, &o.$f, t)),+ }
            }
            #[inline(always)]
            fn sub(&self, o: &Self) -> Self {
                $t { $($f: $crate::pipeline::Varyings::sub(&self.$f, &o.$f)),+ }
            }
            #[inline(always)]
            fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
                $t { $($f: $crate::pipeline::Varyings::interpolate(&self.$f, &d1.$f, w1, &d2.$f, w2)),+ }
            }
            #[inline(always)]
            fn is_finite(&self) -> bool {
                true $(&& $crate::pipeline::Varyings::is_finite(&self.$f))+
            }
        }
    };
}

crate::impl_varyings!(Vec2 { x, y });
crate::impl_varyings!(Vec3 { x, y, z });
crate::impl_varyings!(Vec4 { x, y, z, w });

impl<V: Varyings, const N: usize> Varyings for [V; N] {
    #[inline(always)]
    fn lerp(&self, o: &Self, t: f32) -> Self {
        core::array::from_fn(|i| self[i].lerp(&o[i], t))
    }
    #[inline(always)]
    fn sub(&self, o: &Self) -> Self {
        core::array::from_fn(|i| self[i].sub(&o[i]))
    }
    #[inline(always)]
    fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
        core::array::from_fn(|i| self[i].interpolate(&d1[i], w1, &d2[i], w2))
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.iter().all(Varyings::is_finite)
    }
}

/// Implements [`Varyings`] for a tuple, element by element.
macro_rules! varyings_tuple {
    ($($t:ident $i:tt),+) => {
        impl<$($t: Varyings),+> Varyings for ($($t,)+) {
            #[inline(always)]
            fn lerp(&self, o: &Self, t: f32) -> Self {
                ($(self.$i.lerp(&o.$i, t),)+)
            }
            #[inline(always)]
            fn sub(&self, o: &Self) -> Self {
                ($(self.$i.sub(&o.$i),)+)
            }
            #[inline(always)]
            fn interpolate(&self, d1: &Self, w1: f32, d2: &Self, w2: f32) -> Self {
                ($(self.$i.interpolate(&d1.$i, w1, &d2.$i, w2),)+)
            }
            #[inline(always)]
            fn is_finite(&self) -> bool {
                true $(&& self.$i.is_finite())+
            }
        }
    };
}

varyings_tuple!(A 0);
varyings_tuple!(A 0, B 1);
varyings_tuple!(A 0, B 1, C 2);
varyings_tuple!(A 0, B 1, C 2, D 3);
