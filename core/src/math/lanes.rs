//! The core's one lane type: `N` values side by side, computed element by element in loops of a constant count,
//! which the compiler turns into SIMD instructions where the target has them (SSE or AVX on x86-64, NEON on
//! AArch64) and runs one lane at a time where it has not.
//!
//! A fragment batch's columns ([`crate::pipeline::Column`]: one `f32` per fragment), the occlusion kernel's four
//! directions and the depth-only fill's [`crate::target::DEPTH_LANES`] pixels of a row are all `Lanes`. Each lane is
//! computed exactly as the scalar operation computes it (IEEE arithmetic, nothing fused or reordered), so results
//! do not depend on whether, or how wide, the compiler makes a loop.

use core::ops::{Add, Deref, DerefMut, Div, Mul, Sub};

use super::float;

/// `N` values of `T`, read and written as the array they are (through [`Deref`]), with element-wise arithmetic.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes<T, const N: usize>(pub [T; N]);

impl<T: Copy, const N: usize> Lanes<T, N> {
    /// `v` in every lane.
    #[inline(always)]
    pub const fn splat(v: T) -> Self {
        Self([v; N])
    }

    /// Lane `k` set to `f(k)`.
    #[inline(always)]
    pub fn from_fn(f: impl FnMut(usize) -> T) -> Self {
        Self(core::array::from_fn(f))
    }

    /// `f` of each lane.
    #[inline(always)]
    pub fn map<U>(self, f: impl FnMut(T) -> U) -> Lanes<U, N> {
        Lanes(self.0.map(f))
    }
}

impl<const N: usize> Lanes<f32, N> {
    /// 0 in every lane.
    pub const ZERO: Self = Self([0.0; N]);

    /// Each lane (below 2^22 in magnitude) rounded to a whole number, ties to even.
    #[inline(always)]
    #[must_use]
    pub fn round_small(self) -> Self {
        Self::from_fn(|k| (self[k] + ROUNDER) - ROUNDER)
    }

    /// Each lane, a whole number below 2^22 in magnitude, as an integer: read from the bits of the lane plus
    /// 1.5 * 2^23, with no conversion instruction, so it stays in the register.
    #[inline(always)]
    #[must_use]
    pub fn small_to_i32(self) -> Lanes<i32, N> {
        Lanes::from_fn(|k| (self[k] + ROUNDER).to_bits() as i32 - ROUNDER.to_bits() as i32)
    }

    /// Each lane limited to `[low, high]` ([`float::clamp`]).
    #[inline(always)]
    #[must_use]
    pub fn clamp(self, low: f32, high: f32) -> Self {
        Self::from_fn(|k| float::clamp(self[k], low, high))
    }

    /// The larger of each pair of lanes; `self`'s where `o`'s is NaN.
    #[inline(always)]
    #[must_use]
    pub fn max(self, o: Self) -> Self {
        Self::from_fn(|k| float::max(o[k], self[k]))
    }

    /// Each lane kept where `low < high` in that lane, 0 elsewhere (and where either is NaN): a select, not a
    /// branch.
    #[inline(always)]
    #[must_use]
    pub fn where_less(self, low: Self, high: Self) -> Self {
        Self::from_fn(|k| if low[k] < high[k] { self[k] } else { 0.0 })
    }

    /// 1 in each lane where `self` equals `o`, 0 elsewhere.
    #[inline(always)]
    #[must_use]
    pub fn equal(self, o: Self) -> Self {
        Self::from_fn(|k| if self[k] == o[k] { 1.0 } else { 0.0 })
    }
}

impl<T, const N: usize> Deref for Lanes<T, N> {
    type Target = [T; N];
    #[inline(always)]
    fn deref(&self) -> &[T; N] {
        &self.0
    }
}

impl<T, const N: usize> DerefMut for Lanes<T, N> {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [T; N] {
        &mut self.0
    }
}

/// The element-wise `f32` operators.
macro_rules! lane_operator {
    ($($trait:ident $method:ident $op:tt),*) => {$(
        impl<const N: usize> $trait for Lanes<f32, N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Self::from_fn(|k| self[k] $op o[k])
            }
        }
    )*};
}

lane_operator!(Add add +, Sub sub -, Mul mul *, Div div /);

/// 1.5 * 2^23: adding it to an `f32` below 2^22 in magnitude leaves that value rounded to a whole number (ties to
/// even) in the low mantissa bits, in one exact IEEE operation.
const ROUNDER: f32 = 12_582_912.0;

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding and conversion: ties to even, negative values, and the integer read from the bits equals the cast.
    #[test]
    fn small_values_round_to_even_and_convert_exactly() {
        let v = Lanes([0.5, 1.5, -2.5, 1_000_000.4]);
        assert_eq!(v.round_small(), Lanes([0.0, 2.0, -2.0, 1_000_000.0]));
        assert_eq!(v.round_small().small_to_i32(), Lanes([0, 2, -2, 1_000_000]));
    }

    /// Selections: NaN in either compared lane keeps nothing; `max` keeps `self` against a NaN.
    #[test]
    fn selections_treat_nan_as_failing() {
        let x = Lanes([1.0, 2.0, 3.0, 4.0]);
        let low = Lanes([0.0, f32::NAN, 1.0, 5.0]);
        let high = Lanes([1.0, 1.0, f32::NAN, 6.0]);
        assert_eq!(x.where_less(low, high), Lanes([1.0, 0.0, 0.0, 4.0]));
        assert_eq!(x.max(Lanes([0.5, f32::NAN, 3.5, 4.0])), Lanes([1.0, 2.0, 3.5, 4.0]));
        assert_eq!(x.equal(Lanes([1.0, 0.0, 3.0, f32::NAN])), Lanes([1.0, 0.0, 1.0, 0.0]));
    }
}
