//! The working set of one batch of fragments, as a structure of arrays: each stage reads and writes whole
//! columns.

use crate::math::Vec2;
use crate::pipeline::columns::{Column, Column2, Column3};
use crate::pipeline::{BATCH_SIZE, Slopes};

/// Per-fragment values of one batch. Only the first `len` lanes of each column are meaningful, and a column is
/// filled only by a draw that uses it; the others hold finite values nobody reads (lane-wise loops run over every
/// lane, see [`crate::pipeline::columns`]).
///
/// Every stage writes the columns it produces before any stage reads them, so one set can serve a draw's batches
/// in turn without clearing: where batches have 32 lanes the draw's shader keeps one (`KEPT_SCRATCH` in
/// [`super::shader`] says why and where).
#[derive(Clone)]
pub(crate) struct Scratch {
    pub len: usize,
    /// Interpolated world normal (not normalised).
    pub normal: Column3,
    /// Unit geometric normal: the interpolated one, normalised (for shadow offsets).
    pub geometric: Column3,
    /// Unit shading normal: the geometric one, or the normal map's.
    pub shading: Column3,
    pub world: Column3,
    /// Texture coordinates (and their slopes, in a draw that mipmaps).
    pub at: Coordinates,
    /// World tangent.
    pub tangent: Column3,
    /// The tangent frame's handedness: the sign of the bitangent.
    pub handedness: Column,
    /// 1 for a front-facing fragment, -1 for a back-facing one (two-sided lighting only).
    pub facing: Column,
    /// Unit vector from the surface toward the eye (for highlights).
    pub view: Column3,
    /// Albedo: material colour, times the vertex colours, times the diffuse map.
    pub albedo: Column3,
    /// Ambient light scaled by the occlusion map.
    pub ambient: Column3,
    /// Light arriving: ambient plus diffuse.
    pub diffuse: Column3,
    /// Specular light arriving.
    pub specular: Column3,
    /// Specular colour: the material's, times the specular map.
    pub specular_color: Column3,
    /// Emitted light (glow map).
    pub emission: Column3,
}

impl Scratch {
    /// Every column zero, no lanes filled.
    pub fn new() -> Self {
        let v3 = Column3::ZERO;
        Self {
            len: 0,
            normal: v3,
            geometric: v3,
            shading: v3,
            world: v3,
            at: Coordinates::ZERO,
            tangent: v3,
            handedness: Column::ZERO,
            facing: Column::splat(1.0),
            view: v3,
            albedo: v3,
            ambient: v3,
            diffuse: v3,
            specular: v3,
            specular_color: v3,
            emission: v3,
        }
    }
}

/// A batch's texture coordinates and, in a draw that mipmaps, their screen-space slopes.
#[derive(Clone, Copy)]
pub(crate) struct Coordinates {
    pub uv: Column2,
    /// `None` in a draw that does not mipmap (so that its batches do not clear four more columns).
    pub slopes: Option<Slopes<Column2>>,
}

impl Coordinates {
    /// Every lane at `(0, 0)`, no slopes.
    pub const ZERO: Self = Self { uv: Column2::ZERO, slopes: None };

    /// The coordinates `uv(i)` of the lanes of a batch of `len` and, when `slopes` is set, their slopes
    /// `slopes_of(i)`.
    #[inline(always)]
    pub fn gather(
        len: usize,
        uv: impl Fn(usize) -> Vec2,
        slopes: bool,
        slopes_of: impl Fn(usize) -> Slopes<Vec2>,
    ) -> Self {
        let uv = Column2::gather(len, uv);
        if !slopes {
            return Self { uv, slopes: None };
        }
        let mut columns = Slopes { dx: Column2::ZERO, dy: Column2::ZERO };
        for i in 0..len.min(BATCH_SIZE) {
            let s = slopes_of(i);
            (columns.dx.x[i], columns.dx.y[i]) = (s.dx.x, s.dx.y);
            (columns.dy.x[i], columns.dy.y[i]) = (s.dy.x, s.dy.y);
        }
        Self { uv, slopes: Some(columns) }
    }
}
