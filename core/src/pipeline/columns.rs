//! A batch's lanes: how many fragments a batch holds ([`BATCH_SIZE`]), which lanes a lane-wise loop runs over
//! ([`lanes`]), one value per fragment ([`Column`]), per-fragment vectors as two or three columns (all x, all y,
//! all z), and the lane-wise operations the fragment stages share.
//!
//! The arithmetic loops run over [`lanes`]`(len)` lanes: on a target with SIMD registers every lane of a batch, a
//! constant count with no branch, so the compiler turns them into SIMD instructions (SSE or AVX on x86-64, four or
//! eight lanes at a time; lanes past a batch's length hold values nobody reads); elsewhere only the filled ones.
//! Normalising needs no square root ([`float::inv_sqrt`] is plain arithmetic), so it widens too; the one square
//! root left, a length, runs in a scalar pass of its own: `libm`'s square root is one instruction the compiler
//! cannot widen, and inside a loop it would keep the rest of the loop scalar too. Every lane computes exactly what
//! the scalar [`Vec3`] operations compute, in the same order, so the pixels do not change with the layout.

// Lane loops index every column they touch by the same lane, which iterators would hide.
#![allow(clippy::needless_range_loop)]

use crate::math::float::{self, Exponent, SIMD};
use crate::math::{Lanes, Vec2, Vec3};

/// The most fragments a [`FragmentBatch`](super::FragmentBatch) holds: 32 where the target has SIMD registers, 1 elsewhere.
///
/// A target without SIMD (a Cortex-M4) computes one lane at a time, so a larger batch saves no instruction per
/// fragment and costs stack and code: on the firmware's frame (`firmware/measure.sh`, 2026-11-26), batches of
/// 8 took 40,652 bytes of the core's code and 91.7 million instructions, batches of 1 25,084 bytes and 88.6
/// million: the lane loops compile to the code of one fragment.
pub const BATCH_SIZE: usize = if SIMD { 32 } else { 1 };

/// The lanes a lane-wise loop over a batch of `len` fragments runs over: all [`BATCH_SIZE`] where the target has
/// SIMD registers (a constant count, which the compiler widens; the lanes past `len` hold finite values nobody
/// reads), the first `len` elsewhere. Either way lane `i < len` computes the same value.
#[must_use]
#[inline(always)]
pub const fn lanes(len: usize) -> usize {
    if SIMD || len > BATCH_SIZE { BATCH_SIZE } else { len }
}

/// One `f32` per fragment of a batch: lanes past the batch's length hold finite values nobody should read.
pub type Column = Lanes<f32, BATCH_SIZE>;

/// `lane(i)` in lane `i` of a batch of `len`: a column of one value of each fragment (zero past `len`).
#[inline(always)]
pub(crate) fn gather(len: usize, lane: impl Fn(usize) -> f32) -> Column {
    let mut out = Column::ZERO;
    for i in 0..len.min(BATCH_SIZE) {
        out[i] = lane(i);
    }
    out
}

/// One [`Vec2`] per fragment of a batch, as two columns.
#[derive(Clone, Copy)]
pub(crate) struct Column2 {
    pub x: Column,
    pub y: Column,
}

impl Column2 {
    /// Every lane `(0, 0)`.
    pub const ZERO: Self = Self { x: Column::ZERO, y: Column::ZERO };

    /// `lane(i)` in lane `i` of a batch of `len` (zero past `len`).
    #[inline(always)]
    pub fn gather(len: usize, lane: impl Fn(usize) -> Vec2) -> Self {
        let mut out = Self::ZERO;
        for i in 0..len.min(BATCH_SIZE) {
            let v = lane(i);
            (out.x[i], out.y[i]) = (v.x, v.y);
        }
        out
    }
}

/// One [`Vec3`] per fragment of a batch, as three columns.
#[derive(Clone, Copy)]
pub(crate) struct Column3 {
    pub x: Column,
    pub y: Column,
    pub z: Column,
}

impl Column3 {
    /// Every lane `(0, 0, 0)`.
    pub const ZERO: Self = Self::splat(Vec3::ZERO);

    /// Every lane `v`.
    #[inline(always)]
    pub const fn splat(v: Vec3) -> Self {
        Self { x: Column::splat(v.x), y: Column::splat(v.y), z: Column::splat(v.z) }
    }

    /// `lane(i)` in lane `i` of a batch of `len` (zero past `len`).
    #[inline(always)]
    pub fn gather(len: usize, lane: impl Fn(usize) -> Vec3) -> Self {
        let mut out = Self::ZERO;
        for i in 0..len.min(BATCH_SIZE) {
            out.set(i, lane(i));
        }
        out
    }

    /// `to - from[i]` in the lanes of a batch of `len`: the vectors from the lanes' points to one point.
    #[inline(always)]
    pub fn toward(to: Vec3, from: &Self, len: usize) -> Self {
        let mut d = Self::ZERO;
        for i in 0..lanes(len) {
            d.x[i] = to.x - from.x[i];
            d.y[i] = to.y - from.y[i];
            d.z[i] = to.z - from.z[i];
        }
        d
    }

    /// Lane `i`.
    #[inline(always)]
    pub fn get(&self, i: usize) -> Vec3 {
        Vec3::new(self.x[i], self.y[i], self.z[i])
    }

    /// Sets lane `i` to `v`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Vec3) {
        self.x[i] = v.x;
        self.y[i] = v.y;
        self.z[i] = v.z;
    }

    /// Lane-wise [`Vec3::dot`], over the lanes of a batch of `len`.
    #[inline(always)]
    pub fn dot(&self, o: &Self, out: &mut Column, len: usize) {
        for i in 0..lanes(len) {
            out[i] = self.x[i] * o.x[i] + self.y[i] * o.y[i] + self.z[i] * o.z[i];
        }
    }

    /// `self += color * k` lane by lane over a batch of `len`, where `k[i]` multiplies each channel of `color`
    /// (`Vec3 * f32`).
    #[inline(always)]
    pub fn add_scaled(&mut self, color: Vec3, k: &Column, len: usize) {
        for i in 0..lanes(len) {
            self.x[i] += color.x * k[i];
            self.y[i] += color.y * k[i];
            self.z[i] += color.z * k[i];
        }
    }

    /// Lane-wise [`Vec3::normalize_or_zero`], in place. Only the first `len` lanes are normalised; the others are
    /// set to zero.
    #[inline(always)]
    pub fn normalize(&mut self, len: usize) {
        let mut squared = Column::ZERO;
        self.dot(&*self, &mut squared, len);
        for i in 0..lanes(len) {
            let d = squared[i];
            // `0 < d < inf`, as `Vec3::try_normalize` asks (NaN fails both); lanes past `len` fail. Non-short-circuit
            // `&` and products computed before the choice: written with `&&` and the products inside it, the loop
            // compiled to a branch per lane instead of SIMD.
            let usable = (i < len) & (d > 0.0) & (d < f32::INFINITY);
            let inv = float::inv_sqrt(d);
            let (x, y, z) = (self.x[i] * inv, self.y[i] * inv, self.z[i] * inv);
            self.x[i] = if usable { x } else { 0.0 };
            self.y[i] = if usable { y } else { 0.0 };
            self.z[i] = if usable { z } else { 0.0 };
        }
    }
}

/// The square root of each of the first `len` lanes, in place (a scalar pass: see the module docs).
#[inline(always)]
pub(crate) fn sqrt_lanes(v: &mut Column, len: usize) {
    for x in &mut v[..len] {
        *x = float::sqrt(*x);
    }
}

/// `x[i]` raised to `y`, lane by lane, as [`float::pow`] computes it: for a whole exponent up to 256 the same
/// multiplications as [`float::powi`] in the same order, run across the lanes; otherwise `powf` on the first
/// `len` lanes.
#[inline(always)]
pub(crate) fn pow_lanes(x: &mut Column, y: Exponent, len: usize) {
    if let Exponent::Whole(mut n) = y {
        let mut result = Column::splat(1.0);
        while n > 0 {
            if n & 1 == 1 {
                for i in 0..lanes(len) {
                    result[i] *= x[i];
                }
            }
            for v in &mut x[..lanes(len)] {
                *v *= *v;
            }
            n >>= 1;
        }
        *x = result;
    } else {
        raise_lanes_out_of_line(x, y, len);
    }
}

/// The lanes of [`pow_lanes`] raised by `powf`, out of line: inlined, the compiler hoisted the parts of `powf` that
/// depend on the exponent alone out of the lane loop, before the test for a whole exponent, so every batch paid for
/// them (on the firmware, about 23 instructions a fragment: shading 9.96 against 9.52 million a frame).
#[cold]
#[inline(never)]
fn raise_lanes_out_of_line(x: &mut Column, y: Exponent, len: usize) {
    for v in &mut x[..len] {
        *v = y.raise(*v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lane-wise operations give bit for bit what the scalar ones give, zero and non-finite vectors and
    /// fractional exponents included.
    #[test]
    fn lanes_compute_what_scalars_compute() {
        let samples = [
            Vec3::new(0.3, -0.4, 0.5),
            Vec3::ZERO,
            Vec3::new(f32::NAN, 1.0, 0.0),
            Vec3::new(f32::INFINITY, 0.0, 0.0),
            Vec3::new(1e-30, 2e-30, -1e-30),
            Vec3::new(3e30, -2e30, 1e30),
            Vec3::new(-0.0, 0.0, 7.25),
        ];
        let mut c = Column3::ZERO;
        for i in 0..BATCH_SIZE {
            c.set(i, samples[i % samples.len()] * (1.0 + i as f32 * 0.37));
        }
        let mut out = c;
        out.normalize(BATCH_SIZE);
        let mut d = Column::ZERO;
        let l = Vec3::new(0.25, -0.5, 0.75);
        c.dot(&Column3::splat(l), &mut d, BATCH_SIZE);
        let bits = |v: Vec3| [v.x, v.y, v.z].map(f32::to_bits);
        for i in 0..BATCH_SIZE {
            let v = c.get(i);
            assert_eq!(bits(out.get(i)), bits(v.normalize_or_zero()));
            assert_eq!(d[i].to_bits(), v.dot(l).to_bits());
        }
        for y in [0.0, 1.0, 7.0, 32.0, 256.0, 12.5, 300.0] {
            let mut x = Column::from_fn(|i| i as f32 / 31.0);
            let expected = x.map(|v| float::pow(v, y));
            pow_lanes(&mut x, Exponent::new(y), BATCH_SIZE);
            assert_eq!(x.map(f32::to_bits), expected.map(f32::to_bits), "exponent {y}");
        }
    }
}
