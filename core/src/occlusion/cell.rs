//! One cell of the occlusion grid: the occlusion the horizon search found at a pixel, and that pixel's depth.

use crate::math::float;

/// One cell: the occlusion found at its pixel and that pixel's view-space depth coordinate.
#[derive(Clone, Copy)]
pub(super) struct Cell {
    /// In `[0, 1]`, or [`Cell::UNKNOWN`].
    pub(super) occlusion: f32,
    /// NaN where there is no surface (background, behind the camera, outside the stored rows or the frame).
    pub(super) z: f32,
}

impl Cell {
    /// The occlusion of a cell without one: no surface, or a surface of unknown orientation.
    pub(super) const UNKNOWN: f32 = -1.0;

    /// A cell without a surface.
    pub(super) const NONE: Self = Self { occlusion: Self::UNKNOWN, z: f32::NAN };

    /// The 1-2-1 mean of `self` and its two neighbours `sides`, over those whose occlusion is known and whose
    /// surface lies within `tolerance` of its own in depth; unknown if none is.
    #[inline(always)]
    pub(super) fn filtered(self, sides: [Cell; 2], tolerance: f32) -> Self {
        let (mut sum, mut weight) = if self.occlusion >= 0.0 { (2.0 * self.occlusion, 2) } else { (0.0, 0) };
        for side in sides {
            if side.occlusion >= 0.0 && float::abs(side.z - self.z) <= tolerance {
                sum += side.occlusion;
                weight += 1;
            }
        }
        let occlusion = if weight == 0 { Self::UNKNOWN } else { sum * [0.0, 1.0, 0.5, 1.0 / 3.0, 0.25][weight] };
        Self { occlusion, z: self.z }
    }
}
