//! Four `f32` lanes that the compiler keeps in one SIMD register, and exact rounding to whole numbers for them.

use crate::math::float;

/// Lanes in an [`F4`]: the width of an SSE or NEON register of `f32`.
pub(super) const LANES: usize = 4;

/// Four `f32` lanes: element-wise arithmetic the compiler maps onto one SIMD register (SSE, NEON), each lane
/// rounded exactly as the scalar operation would be, so results do not depend on whether it does.
#[derive(Clone, Copy)]
#[repr(align(16))]
pub(super) struct F4(pub(super) [f32; LANES]);

impl F4 {
    /// 0 in every lane.
    pub(super) const ZERO: Self = Self([0.0; LANES]);

    /// `v` in every lane.
    #[inline(always)]
    pub(super) fn splat(v: f32) -> Self {
        Self([v; LANES])
    }

    /// Lane `k` set to `f(k)`.
    #[inline(always)]
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self {
        Self(core::array::from_fn(f))
    }

    /// Each lane (below 2^22 in magnitude) rounded to a whole number, ties to even.
    #[inline(always)]
    pub(super) fn round_small(self) -> Self {
        Self::from_fn(|k| (self.0[k] + ROUNDER) - ROUNDER)
    }

    /// Each lane, a whole number below 2^22 in magnitude, as an integer: read from the bits of the lane plus
    /// [`ROUNDER`], with no conversion instruction, so it stays in the register.
    #[inline(always)]
    pub(super) fn small_to_i32(self) -> [i32; LANES] {
        core::array::from_fn(|k| (self.0[k] + ROUNDER).to_bits() as i32 - ROUNDER.to_bits() as i32)
    }

    /// Each lane limited to `[low, high]`.
    #[inline(always)]
    pub(super) fn clamp(self, low: f32, high: f32) -> Self {
        Self::from_fn(|k| float::clamp(self.0[k], low, high))
    }

    /// The larger of each pair of lanes; `self`'s where `o`'s is NaN.
    #[inline(always)]
    pub(super) fn max(self, o: Self) -> Self {
        Self::from_fn(|k| float::max(o.0[k], self.0[k]))
    }

    /// Each lane kept where `low < high` in that lane, 0 elsewhere (and where either is NaN): a select, not a
    /// branch.
    #[inline(always)]
    pub(super) fn where_less(self, low: Self, high: Self) -> Self {
        Self::from_fn(|k| if low.0[k] < high.0[k] { self.0[k] } else { 0.0 })
    }

    /// 1 in each lane where `self` equals `o`, 0 elsewhere.
    #[inline(always)]
    pub(super) fn equal(self, o: Self) -> Self {
        Self::from_fn(|k| if self.0[k] == o.0[k] { 1.0 } else { 0.0 })
    }
}

impl core::ops::Add for F4 {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::from_fn(|k| self.0[k] + o.0[k])
    }
}

impl core::ops::Sub for F4 {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::from_fn(|k| self.0[k] - o.0[k])
    }
}

impl core::ops::Mul for F4 {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Self::from_fn(|k| self.0[k] * o.0[k])
    }
}

impl core::ops::Div for F4 {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        Self::from_fn(|k| self.0[k] / o.0[k])
    }
}

/// 1.5 * 2^23: adding it to an `f32` below 2^22 in magnitude leaves that value rounded to a whole number (ties to
/// even) in the low mantissa bits, in one exact IEEE operation.
const ROUNDER: f32 = 12_582_912.0;
