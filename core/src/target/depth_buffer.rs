//! Depth storage the caller owns: the z-buffer.
//!
//! Depth is NDC depth in `[0, 1]`, 0 at the near plane (see [`crate::camera`]). The comparison is **less**: a
//! fragment is kept when its depth is strictly smaller than the stored one, so of two surfaces at exactly the same
//! depth, the one drawn first stays. Clearing sets every value to the far plane (1.0).

/// A depth buffer: one value per pixel, row-major, `width` values per row.
pub trait DepthBuffer {
    /// Number of pixels stored, or `None` for a buffer that stores nothing.
    fn pixel_count(&self) -> Option<usize>;
    /// If `z` is nearer than the stored depth of pixel `index` (`z < stored`), stores it and returns true.
    fn test_and_set(&mut self, index: usize, z: f32) -> bool;
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
                *d = if z < 0.0 { 0.0 } else { z };
                true
            }
            _ => false,
        }
    }
    fn clear(&mut self) {
        self.fill(1.0);
    }
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
