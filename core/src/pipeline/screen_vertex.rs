//! A vertex after the position stage: its outcode and snapped screen position, all that a triangle needs that is
//! not clipped.

use super::clip::{CLIP_MASK, ClipVolume};
use super::raster::{Rasterizer, Snapped};
use crate::math::Vec4;

/// Outcode bit of a position that is not finite (NaN or infinite): its triangles are skipped.
pub(crate) const NOT_FINITE: u16 = 1 << 15;
/// Outcode bit of a position inside every clipping plane that still has no screen position: `w <= 0`, which only
/// the all-zero point can be there. Its unclipped triangles cover nothing.
pub(crate) const NO_SCREEN: u16 = 1 << 14;

/// A vertex's outcode and snapped screen position, as a draw computes them from [`super::Shader::position`]:
/// kept by the vertex cache, or in a caller's memory ([`crate::target::Target::with_vertex_memory`]). Clipping
/// computes the clip-space position again (the position stage is a function of the index), so that the common
/// case stores and copies only this.
#[derive(Clone, Copy, Debug)]
pub struct ScreenVertex {
    /// Outcode against the draw's [`ClipVolume`], with [`NOT_FINITE`] and [`NO_SCREEN`].
    pub(crate) code: u16,
    /// Snapped screen position, when the code has none of [`CLIP_MASK`], [`NOT_FINITE`] and [`NO_SCREEN`].
    pub(crate) screen: Snapped,
}

impl ScreenVertex {
    /// A value to fill a caller's buffer with before its first draw (any value will do: a draw overwrites what it
    /// reads).
    pub const UNSET: Self = Self { code: NOT_FINITE, screen: Snapped::ZERO };

    /// The vertex of clip-space position `pos` in `volume`, snapped by `raster`.
    #[inline(always)]
    pub(crate) fn new(pos: Vec4, volume: &ClipVolume, raster: &Rasterizer) -> Self {
        if !pos.is_finite() {
            return Self { code: NOT_FINITE, screen: Snapped::ZERO };
        }
        let code = volume.outcode(pos);
        if code & CLIP_MASK != 0 {
            return Self { code, screen: Snapped::ZERO };
        }
        match raster.snap(pos) {
            Some(screen) => Self { code, screen },
            None => Self { code: code | NO_SCREEN, screen: Snapped::ZERO },
        }
    }
}

impl Default for ScreenVertex {
    fn default() -> Self {
        Self::UNSET
    }
}
