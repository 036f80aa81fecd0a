//! A vertex after the position stage: its outcode and snapped screen position, all that a triangle needs that is
//! not clipped.

use super::clip::{CLIP_MASK, ClipVolume};
use super::raster::{Rasterizer, Snapped};
use super::{Cull, Winding};
use crate::math::Vec4;
use crate::target::Samples;

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

    /// The vertex's screen row in pixels (y down, before snapping, within twice the guard band), when it has a
    /// screen position: finite, in front of the eye, inside the near and far planes and the guard band.
    pub fn screen_row(&self) -> Option<f32> {
        (self.code & (CLIP_MASK | NOT_FINITE | NO_SCREEN) == 0).then(|| self.screen.row())
    }

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

/// The position pass: [`ScreenVertex::new`] of the vertices `first..first + out.len()`, whose clip-space
/// positions `position` gives by index, into `out` (one per vertex).
///
/// [`LANES`] vertices at a time: their clip-space positions one by one (a shader's position stage is the caller's
/// code), then outcodes and screen positions as loops over the lanes, with no branch, which the compiler widens
/// to SIMD; each lane computes what [`ScreenVertex::new`] computes, with the same operations.
#[inline(always)]
pub(crate) fn screen_vertices(
    position: impl Fn(usize) -> Vec4,
    first: usize,
    volume: &ClipVolume,
    raster: &Rasterizer,
    out: &mut [ScreenVertex],
) {
    for (chunk, start) in out.chunks_mut(LANES).zip((first..).step_by(LANES)) {
        let mut pos = [Vec4::ZERO; LANES];
        for (j, p) in pos.iter_mut().enumerate().take(chunk.len()) {
            *p = position(start + j);
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

/// [`screen_vertices`] for a whole `width x height` frame drawn with `subpixel_bits`: outcodes against the
/// frame's planes and rows, snapped positions on its grid ([`crate::target::SharedScreenVertices`]).
pub(crate) fn frame_screen_vertices(
    position: impl Fn(usize) -> Vec4,
    (width, height): (u32, u32),
    subpixel_bits: u8,
    first: usize,
    out: &mut [ScreenVertex],
) {
    let volume = ClipVolume::new(width, height, 0, height);
    // Culling, winding and the samples per pixel do not enter the position stage.
    let raster =
        Rasterizer::for_frame(width, height, 0..height, Samples::One, subpixel_bits, Cull::None, Winding::default());
    screen_vertices(position, first, &volume, &raster, out);
}
