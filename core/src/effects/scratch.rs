//! The working set of one batch of fragments, as a structure of arrays: each stage reads and writes whole
//! columns.

use crate::math::{Vec2, Vec3, Vec4};
use crate::pipeline::BATCH_SIZE;

/// Per-fragment values of one batch. Only the first `len` entries of each column are meaningful, and a column
/// is filled only by a draw that uses it.
pub(crate) struct Scratch {
    pub len: usize,
    /// Interpolated world normal (not normalised).
    pub normal: [Vec3; BATCH_SIZE],
    /// Unit geometric normal: the interpolated one, normalised (for shadow offsets).
    pub geometric: [Vec3; BATCH_SIZE],
    /// Unit shading normal: the geometric one, or the normal map's.
    pub shading: [Vec3; BATCH_SIZE],
    pub world: [Vec3; BATCH_SIZE],
    pub uv: [Vec2; BATCH_SIZE],
    pub tangent: [Vec4; BATCH_SIZE],
    /// Albedo: material colour, times the diffuse map.
    pub albedo: [Vec3; BATCH_SIZE],
    /// Light arriving: ambient plus diffuse.
    pub diffuse: [Vec3; BATCH_SIZE],
    /// Specular light arriving.
    pub specular: [Vec3; BATCH_SIZE],
    /// Specular colour: the material's, times the specular map.
    pub specular_color: [Vec3; BATCH_SIZE],
    /// Emitted light (glow map).
    pub emission: [Vec3; BATCH_SIZE],
}

impl Scratch {
    #[inline(always)]
    pub fn new(len: usize) -> Self {
        let v3 = [Vec3::ZERO; BATCH_SIZE];
        Self {
            len,
            normal: v3,
            geometric: v3,
            shading: v3,
            world: v3,
            uv: [Vec2::ZERO; BATCH_SIZE],
            tangent: [Vec4::ZERO; BATCH_SIZE],
            albedo: v3,
            diffuse: v3,
            specular: v3,
            specular_color: v3,
            emission: v3,
        }
    }
}
