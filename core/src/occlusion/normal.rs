//! Surface normals from the depth buffer, taken on the side of a pixel that continues its surface (Wu, "Accurate
//! normal reconstruction from depth buffer", 2021), so creases and silhouettes do not bend them.

use super::around::Around;
use super::frame::DepthFrame;
use crate::math::{Vec3, float};

impl DepthFrame<'_> {
    /// A normal of the surface at pixel `(x, y)`, seen through `around`, facing the camera, its largest component
    /// `±1`: the cross product of a horizontal and a vertical difference to a neighbour. Each is taken on a side
    /// whose next two pixels continue in a straight line through the pixel (NDC depth is affine across a plane),
    /// the straighter if both do. `None` when no side across, or none up and down, continues the surface (the
    /// pixel is a tip or a line one or two pixels thin, and its orientation is unknown), or when the product is
    /// zero or not finite.
    pub(super) fn normal(&self, x: i32, y: i32, around: &Around) -> Option<Vec3> {
        let (across, [above2, above1, d, below1, below2]) = self.lines_through(x, y);
        let across = around.offset(1.0, 0.0, slope(across)?);
        let up = around.offset(0.0, -1.0, slope([below2, below1, d, above1, above2])?);
        let n = across.cross(up);
        // Scaled to a length from 1 to the square root of 3, whatever the pixel's size in units of the radius.
        let largest = float::max(float::max(float::abs(n.x), float::abs(n.y)), float::abs(n.z));
        let n = n * (1.0 / largest);
        (largest > 0.0 && n.dot(n).is_finite()).then_some(n)
    }
}

/// How much the depth changes one pixel along a line of five depths through a pixel (the middle one): towards
/// the neighbour ahead or from the one behind, whichever side continues the surface better; `None` if neither
/// does.
#[inline(always)]
fn slope([b2, b1, d, a1, a2]: [f32; 5]) -> Option<f32> {
    match (side(d, a1, a2), side(d, b1, b2)) {
        (Some(ahead), Some(behind)) if behind < ahead => Some(d - b1),
        (Some(_), _) => Some(a1 - d),
        (None, Some(_)) => Some(d - b1),
        (None, None) => None,
    }
}

/// How far extrapolating the neighbour `d1` and the next one `d2` misses depth `d`; `None` unless both are drawn
/// and the miss is within half their own difference (and a rounding slack): otherwise they lie on another
/// surface.
#[inline(always)]
fn side(d: f32, d1: f32, d2: f32) -> Option<f32> {
    let miss = float::abs(2.0 * d1 - d2 - d);
    ((d1 < 1.0) & (d2 < 1.0) & (miss <= 0.5 * float::abs(d1 - d2) + DEPTH_SLACK)).then_some(miss)
}

/// Depth rounding that a surface's depths may show and still count as one plane: a few units in the last place
/// of depths near 1, where they are coarsest.
const DEPTH_SLACK: f32 = 8.0 * f32::EPSILON;
