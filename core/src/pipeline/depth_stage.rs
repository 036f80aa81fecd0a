//! The depth test as a stage chosen once per draw.

use super::DepthTest;
use crate::target::{DEPTH_LANES, DepthBuffer};

/// Decides whether a fragment survives, updating the depth buffer.
pub(crate) trait DepthStage: Copy {
    /// True when the fragment at `index` with depth `z` is to be shaded.
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool;
    /// [`Self::test`] for the covered ones of [`DEPTH_LANES`] consecutive pixels from `start`: how many survive.
    fn test_lanes<D: DepthBuffer>(
        &self,
        depth: &mut D,
        start: usize,
        z: &[f32; DEPTH_LANES],
        covered: &[bool; DEPTH_LANES],
    ) -> u32;
}

/// [`DepthTest::Less`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthLess;

impl DepthStage for DepthLess {
    #[inline(always)]
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool {
        depth.test_and_set(index, z)
    }
    #[inline(always)]
    fn test_lanes<D: DepthBuffer>(
        &self,
        depth: &mut D,
        start: usize,
        z: &[f32; DEPTH_LANES],
        covered: &[bool; DEPTH_LANES],
    ) -> u32 {
        depth.test_and_set_lanes(start, z, covered)
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
    #[inline(always)]
    fn test_lanes<D: DepthBuffer>(
        &self,
        _: &mut D,
        _: usize,
        _: &[f32; DEPTH_LANES],
        covered: &[bool; DEPTH_LANES],
    ) -> u32 {
        covered.iter().map(|&c| u32::from(c)).sum()
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
    #[inline(always)]
    fn test_lanes<D: DepthBuffer>(
        &self,
        depth: &mut D,
        start: usize,
        z: &[f32; DEPTH_LANES],
        covered: &[bool; DEPTH_LANES],
    ) -> u32 {
        match self.0 {
            DepthTest::Less => DepthLess.test_lanes(depth, start, z, covered),
            DepthTest::Off => DepthOff.test_lanes(depth, start, z, covered),
        }
    }
}
