//! The depth test as a stage chosen once per draw.

use super::DepthTest;
use crate::target::{DEPTH_LANES, DepthBuffer};

/// Decides whether a fragment survives, updating the depth buffer.
pub(crate) trait DepthStage: Copy {
    /// True when the fragment at `index` with depth `z` is to be shaded.
    fn test<D: DepthBuffer>(&self, depth: &mut D, index: usize, z: f32) -> bool;
    /// [`Self::test`] without writing: false only when the fragment would fail it, now and after any later write
    /// (stored depths only decrease). For fragments that may yet be discarded.
    fn nearer<D: DepthBuffer>(&self, depth: &D, index: usize, z: f32) -> bool;
    /// [`Self::test`] for the covered ones of [`DEPTH_LANES`] consecutive pixels from `start`: how many survive.
    /// By default pixel by pixel.
    #[inline(always)]
    fn test_lanes<D: DepthBuffer>(
        &self,
        depth: &mut D,
        start: usize,
        z: &[f32; DEPTH_LANES],
        covered: &[bool; DEPTH_LANES],
    ) -> u32 {
        let mut passed = 0;
        for i in 0..DEPTH_LANES {
            if covered[i] && self.test(depth, start + i, z[i]) {
                passed += 1;
            }
        }
        passed
    }
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
    fn nearer<D: DepthBuffer>(&self, depth: &D, index: usize, z: f32) -> bool {
        depth.nearer(index, z)
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
    fn nearer<D: DepthBuffer>(&self, _: &D, _: usize, _: f32) -> bool {
        true
    }
}

/// Either, decided per pixel (its lanes too, by [`DepthStage::test_lanes`]'s default): the general path.
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
    fn nearer<D: DepthBuffer>(&self, depth: &D, index: usize, z: f32) -> bool {
        match self.0 {
            DepthTest::Less => DepthLess.nearer(depth, index, z),
            DepthTest::Off => DepthOff.nearer(depth, index, z),
        }
    }
}
