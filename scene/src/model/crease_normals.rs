//! Normals for a triangle soup (a file that gives each triangle its own three corners, as STL does): flat, or
//! smooth across the edges where faces meet at less than an angle.

use std::collections::HashMap;

use rastty_core::math::Vec3;

use super::smooth_normals::FALLBACK_NORMAL;

/// The most groups of faces with different normals kept at one vertex; faces past them keep their own normal
/// (flat). It bounds the work at a vertex that thousands of faces with scattered normals share.
pub(crate) const MAX_GROUPS_PER_VERTEX: usize = 64;

/// An indexed mesh made from a triangle soup: one vertex per distinct position and normal.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct IndexedSoup {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// One unit normal per position.
    pub normals: Vec<Vec3>,
    /// Three indices per triangle, in the soup's order.
    pub indices: Vec<u32>,
}

/// Indexes the soup `corners` (three per triangle) with normals: each triangle's own when `smooth_angle` is
/// `None` (flat); else, at each vertex, the faces whose normals lie within `smooth_angle` degrees of each other
/// share one.
///
/// Smooth: corners at exactly the same position are one vertex. Its faces are put in groups in file order: a face
/// joins the first group whose first face's normal is within the angle of its own, or starts a group (at most
/// [`MAX_GROUPS_PER_VERTEX`]; a face past them keeps its own normal). A group's normal is the sum of its faces'
/// cross products `(b - a) x (c - a)` (so each counts by its area), normalised. A face with no area has no normal of
/// its own: it gets [`FALLBACK_NORMAL`] and joins no group. Sums are in `f64`.
///
/// Vertices with the same position and normal are shared, so the renderer's vertex cache sees the mesh's sharing.
/// `None` if the mesh has more vertices than `u32` indices address.
pub(crate) fn crease_normals(corners: &[Vec3], smooth_angle: Option<f32>) -> Option<IndexedSoup> {
    let crosses: Vec<[f64; 3]> = corners.chunks_exact(3).map(|t| cross(t[0], t[1], t[2])).collect();
    let face_normals: Vec<Option<Vec3>> = crosses.iter().map(|&c| unit(c)).collect();
    let corner_normals: Vec<Vec3> = match smooth_angle {
        None => (0..corners.len() - corners.len() % 3)
            .map(|corner| face_normals[corner / 3].unwrap_or(FALLBACK_NORMAL))
            .collect(),
        Some(degrees) => smooth(corners, &crosses, &face_normals, degrees),
    };
    share_vertices(corners, &corner_normals)
}

/// Position key: `-0.0` and `0.0` are the same place.
fn position_key(p: Vec3) -> [u32; 3] {
    [(p.x + 0.0).to_bits(), (p.y + 0.0).to_bits(), (p.z + 0.0).to_bits()]
}

fn cross(a: Vec3, b: Vec3, c: Vec3) -> [f64; 3] {
    let wide = |p: Vec3| [f64::from(p.x), f64::from(p.y), f64::from(p.z)];
    let (a, b, c) = (wide(a), wide(b), wide(c));
    let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
}

/// `v` normalised, or `None` for a zero (or not finite) vector.
fn unit(v: [f64; 3]) -> Option<Vec3> {
    let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (length > 0.0 && length.is_finite())
        .then(|| Vec3::new((v[0] / length) as f32, (v[1] / length) as f32, (v[2] / length) as f32))
}

/// One normal per corner, faces grouped at each vertex by `degrees` (see [`crease_normals`]).
fn smooth(corners: &[Vec3], crosses: &[[f64; 3]], face_normals: &[Option<Vec3>], degrees: f32) -> Vec<Vec3> {
    let cos_limit = f64::from(degrees.clamp(0.0, 180.0)).to_radians().cos();
    let count = crosses.len() * 3;
    // Weld corners into vertices, then list each vertex's corners (counting sort: offsets, then corners).
    let mut vertex_of_key: HashMap<[u32; 3], usize> = HashMap::new();
    let vertex: Vec<usize> = corners[..count]
        .iter()
        .map(|&p| {
            let next = vertex_of_key.len();
            *vertex_of_key.entry(position_key(p)).or_insert(next)
        })
        .collect();
    let mut start = vec![0usize; vertex_of_key.len() + 1];
    for &v in &vertex {
        start[v + 1] += 1;
    }
    for v in 0..vertex_of_key.len() {
        start[v + 1] += start[v];
    }
    let mut filled = start.clone();
    let mut corners_of = vec![0usize; count];
    for (corner, &v) in vertex.iter().enumerate() {
        corners_of[filled[v]] = corner;
        filled[v] += 1;
    }

    let mut normals: Vec<Vec3> = (0..count).map(|c| face_normals[c / 3].unwrap_or(FALLBACK_NORMAL)).collect();
    // Per group: its first face's normal and the sum of its faces' cross products.
    let mut groups: Vec<(Vec3, [f64; 3])> = Vec::new();
    let mut group_of: Vec<Option<usize>> = Vec::new();
    for v in 0..vertex_of_key.len() {
        let list = &corners_of[start[v]..start[v + 1]];
        groups.clear();
        group_of.clear();
        for &corner in list {
            let face = corner / 3;
            let Some(n) = face_normals[face] else {
                group_of.push(None);
                continue;
            };
            let dot = |s: Vec3| {
                f64::from(s.x) * f64::from(n.x) + f64::from(s.y) * f64::from(n.y) + f64::from(s.z) * f64::from(n.z)
            };
            let found = groups.iter().position(|&(seed, _)| dot(seed) >= cos_limit);
            let group = match found {
                Some(g) => Some(g),
                None if groups.len() < MAX_GROUPS_PER_VERTEX => {
                    groups.push((n, [0.0; 3]));
                    Some(groups.len() - 1)
                }
                None => None,
            };
            if let Some(g) = group {
                let (sum, c) = (&mut groups[g].1, crosses[face]);
                (sum[0], sum[1], sum[2]) = (sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]);
            }
            group_of.push(group);
        }
        for (&corner, group) in list.iter().zip(&group_of) {
            if let Some(g) = *group {
                normals[corner] = unit(groups[g].1).unwrap_or(normals[corner]);
            }
        }
    }
    normals
}

/// Shares the corners with the same position and normal.
fn share_vertices(corners: &[Vec3], normals: &[Vec3]) -> Option<IndexedSoup> {
    let mut soup = IndexedSoup::default();
    let mut index_of: HashMap<([u32; 3], [u32; 3]), u32> = HashMap::new();
    for (&p, &n) in corners.iter().zip(normals) {
        let next = u32::try_from(soup.positions.len()).ok()?;
        let index = *index_of.entry((position_key(p), position_key(n))).or_insert_with(|| {
            soup.positions.push(p);
            soup.normals.push(n);
            next
        });
        soup.indices.push(index);
    }
    Some(soup)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A floor (z = 0, facing +z) and a wall (x = 1, facing +x) of two triangles each, meeting at a right angle
    /// along the edge from (1, 0, 0) to (1, 1, 0), as a soup.
    fn folded() -> Vec<Vec3> {
        #[rustfmt::skip]
        let coordinates = [
            0.0, 0.0, 0.0,  1.0, 0.0, 0.0,  1.0, 1.0, 0.0,
            0.0, 0.0, 0.0,  1.0, 1.0, 0.0,  0.0, 1.0, 0.0,
            1.0, 0.0, 0.0,  1.0, 1.0, 1.0,  1.0, 0.0, 1.0,
            1.0, 0.0, 0.0,  1.0, 1.0, 0.0,  1.0, 1.0, 1.0,
        ];
        coordinates.chunks_exact(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect()
    }

    #[test]
    fn flat_gives_each_face_its_own_normal_and_shares_within_a_face() {
        let soup = crease_normals(&folded(), None).unwrap();
        // Four corners of the floor, four of the wall: the edge's two positions appear once per face.
        assert_eq!(soup.positions.len(), 8);
        assert_eq!(soup.indices.len(), 12);
        for (i, &index) in soup.indices.iter().enumerate() {
            let expected = if i < 6 { Vec3::Z } else { Vec3::X };
            assert_eq!(soup.normals[index as usize], expected, "corner {i}");
        }
    }

    #[test]
    fn smooth_joins_faces_within_the_angle_and_keeps_creases_beyond_it() {
        // A right angle is beyond 60 degrees: the same as flat.
        assert_eq!(crease_normals(&folded(), Some(60.0)), crease_normals(&folded(), None));
        // Within 100 degrees each corner on the edge gets one normal from the faces there, by area: at (1, 0, 0)
        // one floor and two wall triangles, at (1, 1, 0) two floor triangles and one wall triangle.
        let soup = crease_normals(&folded(), Some(100.0)).unwrap();
        assert_eq!(soup.positions.len(), 6);
        let normal_at = |p: Vec3| soup.normals[soup.positions.iter().position(|&q| q == p).unwrap()];
        let expect = |n: Vec3, x: f32, z: f32| {
            let e = Vec3::new(x, 0.0, z) * (1.0 / (x * x + z * z).sqrt());
            assert!((n - e).length() < 1e-6, "{n:?} against {e:?}");
        };
        expect(normal_at(Vec3::new(1.0, 0.0, 0.0)), 2.0, 1.0);
        expect(normal_at(Vec3::new(1.0, 1.0, 0.0)), 1.0, 2.0);
        assert_eq!(normal_at(Vec3::new(0.0, 1.0, 0.0)), Vec3::Z);
        assert_eq!(normal_at(Vec3::new(1.0, 1.0, 1.0)), Vec3::X);
    }

    #[test]
    fn faces_without_area_get_the_fallback_normal() {
        let p = Vec3::new(1.0, 2.0, 3.0);
        for angle in [None, Some(30.0)] {
            let soup = crease_normals(&[p, p, p], angle).unwrap();
            assert_eq!(soup.normals, vec![FALLBACK_NORMAL]);
            assert_eq!(soup.indices, vec![0, 0, 0]);
        }
    }

    #[test]
    fn a_vertex_shared_by_many_scattered_faces_keeps_a_bounded_number_of_groups() {
        // A fan of 1000 thin faces round one apex, each turned 0.36 degrees from the last: at 0.1 degrees no two
        // share a group, so only the first 64 groups are made and the rest stay flat.
        let apex = Vec3::new(0.0, 0.0, 1.0);
        let mut corners = Vec::new();
        for i in 0..1000 {
            let (a, b) = (i as f32 * 0.00628, (i + 1) as f32 * 0.00628);
            corners.extend([apex, Vec3::new(a.cos(), a.sin(), 0.0), Vec3::new(b.cos(), b.sin(), 0.0)]);
        }
        let smooth = crease_normals(&corners, Some(0.1)).unwrap();
        let flat = crease_normals(&corners, None).unwrap();
        assert_eq!(smooth.indices.len(), flat.indices.len());
        for (s, f) in smooth.indices.iter().zip(&flat.indices) {
            assert!((smooth.normals[*s as usize] - flat.normals[*f as usize]).length() < 1e-6);
        }
    }
}
