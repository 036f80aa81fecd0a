//! A vertex after the position stage: its outcode and snapped screen position, all that a triangle needs that is
//! not clipped.

use super::Shader;
use super::clip::{CLIP_MASK, ClipVolume};
use super::raster::{Rasterizer, Snapped};
use crate::math::Vec4;
use crate::mesh::Mesh;

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
    /// reads), and the value of a vertex whose position is not finite.
    pub const UNSET: Self = Self { code: NOT_FINITE, screen: Snapped::ZERO };

    /// The vertex of clip-space position `pos` in `volume`, snapped by `raster`.
    #[inline(always)]
    pub(crate) fn new(pos: Vec4, volume: &ClipVolume, raster: &Rasterizer) -> Self {
        Self::classify(pos, || volume.outcode(pos), || raster.snap_any(pos))
    }

    /// The vertex of clip-space position `pos` whose outcode is `code()` and whose screen position, if it has one,
    /// is `snapped()` ([`Rasterizer::snap_any`]); each is asked for only when it is kept. One vertex at a time
    /// they are computed here, only when needed; the position pass computes them for eight vertices beforehand.
    #[inline(always)]
    fn classify(pos: Vec4, code: impl FnOnce() -> u16, snapped: impl FnOnce() -> Snapped) -> Self {
        if !pos.is_finite() {
            return Self::UNSET;
        }
        let code = code();
        if code & CLIP_MASK != 0 {
            Self { code, screen: Snapped::ZERO }
        } else if pos.w > 0.0 {
            Self { code, screen: snapped() }
        } else {
            Self { code: code | NO_SCREEN, screen: Snapped::ZERO }
        }
    }
}

/// Vertices the position pass works on at once.
const LANES: usize = 8;

/// The position pass: [`ScreenVertex::new`] of every vertex of `mesh`, in order, into `out` (one per vertex).
///
/// [`LANES`] vertices at a time: their clip-space positions one by one ([`Shader::position`] is the caller's
/// code), then outcodes and screen positions as loops over the lanes, with no branch, which the compiler widens
/// to SIMD; each lane computes what [`ScreenVertex::new`] computes, with the same operations.
#[inline(always)]
pub(crate) fn screen_vertices<S: Shader>(
    shader: &S,
    mesh: &Mesh<'_>,
    volume: &ClipVolume,
    raster: &Rasterizer,
    out: &mut [ScreenVertex],
) {
    for (chunk, first) in out.chunks_mut(LANES).zip((0..).step_by(LANES)) {
        let mut pos = [Vec4::ZERO; LANES];
        for (j, p) in pos.iter_mut().enumerate().take(chunk.len()) {
            *p = shader.position(mesh, first + j);
        }
        let mut code = [0u16; LANES];
        let mut snapped = [Snapped::ZERO; LANES];
        for j in 0..LANES {
            code[j] = volume.outcode(pos[j]);
            snapped[j] = raster.snap_any(pos[j]);
        }
        for (j, v) in chunk.iter_mut().enumerate() {
            *v = ScreenVertex::classify(pos[j], || code[j], || snapped[j]);
        }
    }
}
