//! Smooth, area-weighted vertex normals for models whose file gives none.

use std::collections::HashMap;

use rastty_core::math::Vec3;

/// The normal given to a vertex whose faces' cross products sum to zero (only degenerate faces, or faces that
/// cancel out): `+z`, finite and unit length.
pub const FALLBACK_NORMAL: Vec3 = Vec3::Z;

/// One unit normal per position: at each position, the sum of the unnormalised cross products `(b - a) x (c - a)`
/// of the triangles that use it (so each face counts in proportion to its area), normalised.
///
/// Vertices at exactly the same position share their sum, so the surface stays smooth across texture seams and
/// part boundaries, where the loader has split one OBJ vertex into several. Sums are kept in `f64`, so they do not
/// overflow for coordinates within [`super::COORDINATE_LIMIT`]. Triangles with an index out of range are skipped.
/// A zero sum gives [`FALLBACK_NORMAL`].
pub fn smooth_normals(positions: &[Vec3], indices: &[u32]) -> Vec<Vec3> {
    // Weld vertices by position: -0.0 and 0.0 are the same place.
    let key = |p: Vec3| [(p.x + 0.0).to_bits(), (p.y + 0.0).to_bits(), (p.z + 0.0).to_bits()];
    let mut slot_of: HashMap<[u32; 3], usize> = HashMap::with_capacity(positions.len());
    let slots: Vec<usize> = positions
        .iter()
        .map(|&p| {
            let next = slot_of.len();
            *slot_of.entry(key(p)).or_insert(next)
        })
        .collect();

    let mut sums = vec![[0f64; 3]; slot_of.len()];
    let wide = |p: Vec3| [f64::from(p.x), f64::from(p.y), f64::from(p.z)];
    for tri in indices.chunks_exact(3) {
        let (Some(&a), Some(&b), Some(&c)) =
            (positions.get(tri[0] as usize), positions.get(tri[1] as usize), positions.get(tri[2] as usize))
        else {
            continue;
        };
        let (a, b, c) = (wide(a), wide(b), wide(c));
        let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
        for &v in tri {
            let sum = &mut sums[slots[v as usize]];
            for k in 0..3 {
                sum[k] += n[k];
            }
        }
    }

    let unit: Vec<Vec3> = sums
        .iter()
        .map(|s| {
            let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
            if len > 0.0 && len.is_finite() {
                Vec3::new((s[0] / len) as f32, (s[1] / len) as f32, (s[2] / len) as f32)
            } else {
                FALLBACK_NORMAL
            }
        })
        .collect();
    slots.iter().map(|&s| unit[s]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-6
    }

    #[test]
    fn a_single_triangle_gets_its_face_normal() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        assert_eq!(smooth_normals(&p, &[0, 1, 2]), [Vec3::Z; 3]);
        assert_eq!(smooth_normals(&p, &[0, 2, 1]), [-Vec3::Z; 3]);
    }

    #[test]
    fn faces_are_weighted_by_area() {
        // A large triangle in z = 0 (area 2) and a small one in x = 0 (area 0.5) share the edge from the origin to
        // (0, 2, 0): its two vertices get (0, 0, 4) + (1, 0, 0), normalised.
        let p = [Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 0.0, -0.5)];
        // Triangle 1: (0, 1, 2): cross = (2,0,0) x (0,2,0) = (0,0,4).
        // Triangle 2: (0, 3, 2): cross = (0,0,-0.5) x (0,2,0) = (1,0,0).
        let n = smooth_normals(&p, &[0, 1, 2, 0, 3, 2]);
        let shared = Vec3::new(1.0, 0.0, 4.0) / 17f32.sqrt();
        assert!(close(n[0], shared) && close(n[2], shared), "{n:?}");
        assert!(close(n[1], Vec3::Z) && close(n[3], Vec3::X), "{n:?}");
    }

    #[test]
    fn vertices_at_the_same_position_share_a_normal() {
        // Two triangles with separate vertices (as across a texture seam) folded along the y axis.
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(-0.0, 0.0, 0.0), Vec3::Y, Vec3::Z];
        let n = smooth_normals(&p, &[0, 1, 2, 3, 4, 5]);
        // (1,0,0)x(0,1,0) = (0,0,1) and (0,1,0)x(0,0,1) = (1,0,0), equal areas.
        let shared = Vec3::new(1.0, 0.0, 1.0) / 2f32.sqrt();
        assert!(close(n[0], shared) && close(n[3], shared) && close(n[2], shared) && close(n[4], shared), "{n:?}");
    }

    #[test]
    fn degenerate_and_unused_vertices_get_the_fallback() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::new(2.0, 0.0, 0.0), Vec3::Y];
        assert_eq!(smooth_normals(&p, &[0, 1, 2, 0, 1, 9]), [FALLBACK_NORMAL; 4]);
    }

    #[test]
    fn huge_coordinates_do_not_overflow() {
        let l = 1e15;
        let p = [Vec3::new(-l, -l, 0.0), Vec3::new(l, -l, 0.0), Vec3::new(l, l, 0.0), Vec3::new(-l, l, 0.0)];
        let n = smooth_normals(&p, &[0, 1, 2, 0, 2, 3]);
        assert!(n.iter().all(|&v| close(v, Vec3::Z)), "{n:?}");
    }
}
