//! The depth test as a stage chosen once per draw.

use super::DepthTest;
use crate::target::DepthBuffer;

/// Decides whether a fragment survives, updating the depth buffer.
pub(crate) trait DepthStage: Copy {
    /// True when the fragment at `index` with depth `z` is to be shaded.
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool;
}

/// [`DepthTest::Less`], with depth clamped below at 0.
///
/// Interpolated depth can round a hair past its vertices' range (-1e-37 between vertices at 0 and 1e-30); like
/// Direct3D, which clamps depth to the viewport's depth range before the test, a negative depth is stored as 0.
/// A depth above 1 needs no clamp: it never passes against a buffer cleared to 1. NaN stays NaN and fails.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthLess;

impl DepthStage for DepthLess {
    #[inline(always)]
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool {
        depth.test_and_set(index, if z < 0.0 { 0.0 } else { z })
    }
}

/// [`DepthTest::Off`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthOff;

impl DepthStage for DepthOff {
    #[inline(always)]
    fn test<D: DepthBuffer>(&self, _: &mut D, _: usize, _: f32) -> bool {
        true
    }
}

/// Either, decided per pixel: the general path.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DynamicDepth(pub DepthTest);

impl DepthStage for DynamicDepth {
    #[inline(always)]
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool {
        match self.0 {
            DepthTest::Less => DepthLess.test(depth, index, z),
            DepthTest::Off => DepthOff.test(depth, index, z),
        }
    }
}
