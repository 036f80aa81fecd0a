//! Shading normals over a batch: the interpolated normal, or a tangent-space or object-space normal map.

use super::maps::MapReader;
use super::material::decode_normal;
use super::scratch::Scratch;
use crate::math::{Mat3, Vec3};
use crate::pipeline::{BATCH_SIZE, lanes};
use crate::texture::{Filter, Texture, Wrap};

/// Two-sided lighting: the geometric and shading normals of each back-facing fragment turned round (times
/// [`Scratch::facing`]). Turning round the interpolated normal and tangent frame before would give the same bits:
/// each normal is a sum of their products, normalised, and negating every term negates it exactly.
pub(crate) fn face_the_viewer(s: &mut Scratch) {
    for i in 0..lanes(s.len) {
        let sign = s.facing[i];
        s.geometric.set(i, s.geometric.get(i) * sign);
        s.shading.set(i, s.shading.get(i) * sign);
    }
}

/// The geometric normal (the interpolated one, normalised) and, without a normal map, the shading normal too.
pub(crate) fn interpolated(s: &mut Scratch, shading_too: bool) {
    s.geometric = s.normal;
    s.geometric.normalize(s.len);
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
pub(crate) fn tangent_map<F: Filter, W: Wrap>(s: &mut Scratch, maps: &mut MapReader<F, W>, map: &Texture<'_>) {
    let mut texels = [0; BATCH_SIZE];
    maps.read(map, &s.at, &mut texels);
    for (i, &texel) in texels.iter().enumerate().take(lanes(s.len)) {
        let (n, t) = (s.normal.get(i), s.tangent.get(i));
        let b = n.cross(t) * s.handedness[i];
        let m = decode_normal(texel);
        s.shading.set(i, t * m.x + b * m.y + n * m.z);
    }
    s.shading.normalize(s.len);
}

/// Object-space normal map: the decoded texel through the normal matrix, normalised.
pub(crate) fn object_map<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    normal_matrix: &Mat3,
) {
    let mut texels = [0; BATCH_SIZE];
    maps.read(map, &s.at, &mut texels);
    for (i, &texel) in texels.iter().enumerate().take(lanes(s.len)) {
        let m: Vec3 = decode_normal(texel);
        s.shading.set(i, *normal_matrix * m);
    }
    s.shading.normalize(s.len);
}
