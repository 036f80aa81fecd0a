//! Depth storage the caller owns: the z-buffer.
//!
//! Depth is NDC depth in `[0, 1]`, 0 at the near plane (see [`crate::camera`]). The comparison is **less**: a
//! fragment is kept when its depth is strictly smaller than the stored one, so of two surfaces at exactly the same
//! depth, the one drawn first stays. Clearing sets every value to the far plane (1.0).

use crate::math::float;

/// Consecutive pixels of a row that [`DepthBuffer::test_and_set_lanes`] tests at once: eight `f32`s, one AVX
/// register (two SSE ones).
pub const DEPTH_LANES: usize = 8;

/// A depth buffer: one value per pixel, row-major, `width` values per row.
pub trait DepthBuffer {
    /// Number of pixels stored, or `None` for a buffer that stores nothing.
    fn pixel_count(&self) -> Option<usize>;
    /// If `z` is nearer than the stored depth of pixel `index` (`z < stored`), stores it and returns true.
    fn test_and_set(&mut self, index: usize, z: f32) -> bool;
    /// [`Self::test_and_set`] for pixel `start + i` with depth `z[i]`, for each `i` where `covered[i]`; returns how
    /// many passed. The pixels need not be in one row (the depth-only pass lets a group reach past a row's end,
    /// uncovered).
    #[inline(always)]
    fn test_and_set_lanes(&mut self, start: usize, z: &[f32; DEPTH_LANES], covered: &[bool; DEPTH_LANES]) -> u32 {
        one_by_one(self, start, z, covered)
    }
    /// Resets every value to the far plane.
    fn clear(&mut self);
}

/// `f32` depth: NDC depth as interpolated, clamped below at 0.
///
/// Interpolated depth can round a hair past its vertices' range (-9.4e-38 between vertices at 0 and 1e-30);
/// like Direct3D, which clamps depth to the viewport's depth range, a negative depth is stored as 0. A depth above
/// 1 needs no clamp: it never passes against a buffer cleared to 1. NaN fails the test.
impl DepthBuffer for &mut [f32] {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.len())
    }
    #[inline(always)]
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        match self.get_mut(index) {
            Some(d) if z < *d => {
                *d = clamped(z);
                true
            }
            _ => false,
        }
    }
    /// Branch-free over a group whose stored depths are all non-negative numbers (sign bit clear, not NaN), as
    /// every depth this library stores is, so that it widens to SIMD; any other group goes pixel by pixel.
    ///
    /// The new depths are the minimum of the stored ones and, per lane, the passing depth or `+inf`: over such
    /// depths that is exactly the test's result, and it compiles to plain stores. (Choosing between the new and the
    /// stored value compiled to masked stores, slow on some x86 processors.)
    #[inline(always)]
    fn test_and_set_lanes(&mut self, start: usize, z: &[f32; DEPTH_LANES], covered: &[bool; DEPTH_LANES]) -> u32 {
        let group = self.get_mut(start..start + DEPTH_LANES).and_then(|s| <&mut [f32; DEPTH_LANES]>::try_from(s).ok());
        let ordinary =
            |g: &[f32; DEPTH_LANES]| g.iter().fold(true, |a, d| a & (d.to_bits() <= f32::INFINITY.to_bits()));
        let Some(stored) = group.filter(|g| ordinary(g)) else {
            return one_by_one(self, start, z, covered);
        };
        let mut candidate = [0.0; DEPTH_LANES];
        let mut passed = 0;
        for i in 0..DEPTH_LANES {
            let pass = covered[i] & (z[i] < stored[i]);
            // Clamped before the choice, not inside it: inside, the loop compiled 3.6 times slower (caster pass).
            let value = clamped(z[i]);
            candidate[i] = if pass { value } else { f32::INFINITY };
            passed += u32::from(pass);
        }
        for i in 0..DEPTH_LANES {
            stored[i] = float::min_num(stored[i], candidate[i]);
        }
        passed
    }
    fn clear(&mut self) {
        self.fill(1.0);
    }
}

/// The `f32` depth stored for a passing `z`: a negative one as 0.
#[inline(always)]
fn clamped(z: f32) -> f32 {
    if z < 0.0 { 0.0 } else { z }
}

/// [`DepthBuffer::test_and_set_lanes`] as a loop of [`DepthBuffer::test_and_set`].
#[inline(always)]
fn one_by_one<D: DepthBuffer + ?Sized>(
    depth: &mut D,
    start: usize,
    z: &[f32; DEPTH_LANES],
    covered: &[bool; DEPTH_LANES],
) -> u32 {
    let mut passed = 0;
    for i in 0..DEPTH_LANES {
        if covered[i] && depth.test_and_set(start + i, z[i]) {
            passed += 1;
        }
    }
    passed
}

/// Quantizes NDC depth in `[0, 1]` to 16 bits, rounding to nearest (values outside saturate, NaN gives 0).
#[inline(always)]
pub fn depth_to_u16(z: f32) -> u16 {
    crate::math::float::quantize_unit(z, 65535.0) as u16
}

/// `u16` depth: NDC depth quantized to 65536 levels (see [`depth_to_u16`]); half the memory of `f32`.
impl DepthBuffer for &mut [u16] {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.len())
    }
    #[inline(always)]
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        let q = depth_to_u16(z);
        match self.get_mut(index) {
            Some(d) if q < *d => {
                *d = q;
                true
            }
            _ => false,
        }
    }
    fn clear(&mut self) {
        self.fill(u16::MAX);
    }
}

/// No depth buffer: every fragment passes.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoDepth;

impl DepthBuffer for NoDepth {
    fn pixel_count(&self) -> Option<usize> {
        None
    }
    #[inline(always)]
    fn test_and_set(&mut self, _: usize, _: f32) -> bool {
        true
    }
    fn clear(&mut self) {}
}
