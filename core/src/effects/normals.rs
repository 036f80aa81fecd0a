//! Shading normals over a batch: the interpolated normal, or a tangent-space or object-space normal map.

use super::material::decode_normal;
use super::scratch::Scratch;
use crate::math::{Mat3, Vec3};
use crate::texture::{Filter, Texture, Wrap};

/// The geometric normal (the interpolated one, normalised) and, without a normal map, the shading normal too.
pub(crate) fn interpolated(s: &mut Scratch, shading_too: bool) {
    for (g, n) in s.geometric[..s.len].iter_mut().zip(&s.normal) {
        *g = n.normalize_or_zero();
    }
    if shading_too {
        s.shading = s.geometric;
    }
}

/// Tangent-space normal map: the decoded texel in the frame of the interpolated tangent `t`, bitangent
/// `w * n.cross(t)` and normal `n` (the convention of [`crate::mesh::compute_tangents`]).
///
/// The frame's vectors are used as interpolated, not renormalised (the convention of MikkTSpace, mikktspace.com),
/// so the flat texel `(128, 128, 255)`, which decodes to exactly `(0, 0, 1)`, gives the interpolated normal
/// normalised, bit for bit the normal of a draw without the map.
pub(crate) fn tangent_map<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>) {
    for i in 0..s.len {
        let (n, t) = (s.normal[i], s.tangent[i]);
        let t3 = t.truncate();
        let b = n.cross(t3) * t.w;
        let m = decode_normal(map.sample_packed::<F, W>(s.uv[i]));
        s.shading[i] = (t3 * m.x + b * m.y + n * m.z).normalize_or_zero();
    }
}

/// Object-space normal map: the decoded texel through the normal matrix, normalised.
pub(crate) fn object_map<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>, normal_matrix: &Mat3) {
    for i in 0..s.len {
        let m: Vec3 = decode_normal(map.sample_packed::<F, W>(s.uv[i]));
        s.shading[i] = (*normal_matrix * m).normalize_or_zero();
    }
}
