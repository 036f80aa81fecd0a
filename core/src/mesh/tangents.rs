//! Per-vertex tangent frames from texture coordinates, for tangent-space normal maps.

use super::Mesh;
use crate::math::{Vec3, Vec4};

/// Why tangents could not be computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TangentError {
    /// The mesh has no normals or no texture coordinates: a tangent frame needs both.
    MissingAttributes,
    /// The output slice does not have one entry per vertex.
    OutputLength {
        /// Number of vertices.
        expected: usize,
        /// Number of entries given.
        actual: usize,
    },
}

impl core::fmt::Display for TangentError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::MissingAttributes => f.write_str("tangents need normals and texture coordinates"),
            Self::OutputLength { expected, actual } => {
                write!(f, "{actual} tangents given for {expected} vertices")
            }
        }
    }
}

impl core::error::Error for TangentError {}

/// Computes a tangent for every vertex of `mesh` into `out` (one entry per vertex): in `xyz` a unit vector
/// perpendicular to the vertex normal pointing toward increasing `u`, in `w` the handedness, `1.0` or `-1.0`, so
/// that the bitangent (toward increasing `v`) is `w * normal.cross(tangent)`.
///
/// Each triangle's direction of increasing `u` is solved from its edges and their texture-coordinate deltas
/// (Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh", 2001), accumulated unnormalised on its
/// vertices so that larger triangles weigh more, then made perpendicular to the vertex normal (Gram-Schmidt). A
/// triangle whose texture coordinates are mirrored votes for handedness -1. A vertex with no usable triangle
/// (degenerate texture coordinates, a zero normal) still gets a finite unit tangent perpendicular to its normal.
/// Triangles with an index out of range or a non-finite value are ignored.
///
/// # Errors
/// [`TangentError::MissingAttributes`] without normals or texture coordinates, [`TangentError::OutputLength`]
/// when `out` does not have one entry per vertex. No allocation: the caller owns `out`.
pub fn compute_tangents(mesh: &Mesh<'_>, out: &mut [Vec4]) -> Result<(), TangentError> {
    let (Some(normals), Some(uvs)) = (mesh.normals(), mesh.uvs()) else {
        return Err(TangentError::MissingAttributes);
    };
    let positions = mesh.positions();
    if out.len() != positions.len() {
        return Err(TangentError::OutputLength { expected: positions.len(), actual: out.len() });
    }
    out.fill(Vec4::ZERO);
    mesh.for_each_triangle(|triangle| {
        let Some([a, b, c]) = triangle else { return };
        let (e1, e2) = (positions[b] - positions[a], positions[c] - positions[a]);
        let (d1, d2) = (uvs[b] - uvs[a], uvs[c] - uvs[a]);
        // e1 = du1 T + dv1 B, e2 = du2 T + dv2 B: T = (e1 dv2 - e2 dv1) / det, det = du1 dv2 - du2 dv1.
        let det = d1.x * d2.y - d2.x * d1.y;
        let tangent = e1 * d2.y - e2 * d1.y;
        if !(det != 0.0 && det.is_finite() && tangent.is_finite()) {
            return;
        }
        // Dividing by |det| would weigh triangles by their texel density; the sign alone keeps area weighting.
        let (tangent, mirrored) = if det > 0.0 { (tangent, false) } else { (-tangent, true) };
        let face_normal = e1.cross(e2);
        for i in [a, b, c] {
            // Handedness is relative to the vertex normal: a triangle wound against it counts mirrored too.
            let against = face_normal.dot(normals[i]) < 0.0;
            let vote = if mirrored != against { -1.0 } else { 1.0 };
            out[i] = out[i] + tangent.extend(vote);
        }
    });
    for (t, &normal) in out.iter_mut().zip(normals) {
        *t = orthonormal_tangent(normal, t.truncate(), t.w);
    }
    Ok(())
}

/// The accumulated `tangent` made a unit vector perpendicular to `normal`, with handedness from the sum of votes;
/// any perpendicular unit vector when nothing usable is left.
fn orthonormal_tangent(normal: Vec3, tangent: Vec3, votes: f32) -> Vec4 {
    // `normalize_or_zero` gives zero for a zero or non-finite vector; a subnormal one can still come out
    // non-finite, hence the check.
    let n = normal.normalize_or_zero();
    let handedness = if votes < 0.0 { -1.0 } else { 1.0 };
    let t = (tangent - n * n.dot(tangent)).normalize_or_zero();
    if t != Vec3::ZERO && t.is_finite() {
        return t.extend(handedness);
    }
    // Any perpendicular; the X axis for a zero normal.
    let t = n.cross(n.least_aligned_axis()).normalize_or_zero();
    if t != Vec3::ZERO && t.is_finite() { t.extend(handedness) } else { Vec3::X.extend(handedness) }
}
