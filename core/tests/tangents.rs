//! Tangent frames for normal mapping: along increasing `u`, perpendicular to the normal, handedness from the
//! texture mapping, and finite for degenerate input.

use rastty_core::math::{Vec2, Vec3, Vec4};
use rastty_core::mesh::{Indices, Mesh, TangentError, compute_tangents};

fn tangents(positions: &[Vec3], normals: &[Vec3], uvs: &[Vec2], indices: &[u16]) -> Vec<Vec4> {
    let mesh = Mesh::new(positions, Indices::U16(indices)).unwrap().with_normals(normals).unwrap();
    let mesh = mesh.with_uvs(uvs).unwrap();
    let mut out = vec![Vec4::ZERO; positions.len()];
    compute_tangents(&mesh, &mut out).unwrap();
    out
}

/// A unit quad in the z = 0 plane facing +z, two triangles, counter-clockwise.
const QUAD: [Vec3; 4] =
    [Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
const QUAD_INDICES: [u16; 6] = [0, 1, 2, 0, 2, 3];

#[test]
fn a_quad_mapped_along_x_has_tangent_x_and_right_handed_frames() {
    let uvs = QUAD.map(|p| Vec2::new(p.x, p.y));
    for t in tangents(&QUAD, &[Vec3::Z; 4], &uvs, &QUAD_INDICES) {
        assert_eq!(t, Vec4::new(1.0, 0.0, 0.0, 1.0));
        // The bitangent w * n x t is +y: the direction of increasing v.
        assert_eq!(Vec3::Z.cross(t.truncate()) * t.w, Vec3::Y);
    }
}

#[test]
fn rotated_and_mirrored_mappings() {
    // u along y, v along -x: tangent +y, and the bitangent n x t = -x is increasing v, so right-handed.
    let uvs = QUAD.map(|p| Vec2::new(p.y, -p.x));
    for t in tangents(&QUAD, &[Vec3::Z; 4], &uvs, &QUAD_INDICES) {
        assert_eq!(t, Vec4::new(0.0, 1.0, 0.0, 1.0));
    }
    // u mirrored (increasing toward -x): tangent -x; v along +y, but n x t = -y, so the frame is left-handed.
    let uvs = QUAD.map(|p| Vec2::new(-p.x, p.y));
    for t in tangents(&QUAD, &[Vec3::Z; 4], &uvs, &QUAD_INDICES) {
        assert_eq!(t, Vec4::new(-1.0, 0.0, 0.0, -1.0));
    }
}

#[test]
fn tangents_are_unit_and_perpendicular_to_tilted_normals() {
    // Normals tilted away from the face normal: the tangent is made perpendicular to each vertex normal.
    let normals =
        [Vec3::new(0.3, 0.0, 1.0), Vec3::new(0.0, 0.5, 1.0), Vec3::new(-0.2, 0.1, 1.0), Vec3::new(0.0, 0.0, 2.0)];
    let uvs = QUAD.map(|p| Vec2::new(p.x, p.y));
    for (t, n) in tangents(&QUAD, &normals, &uvs, &QUAD_INDICES).iter().zip(normals) {
        let (t3, n) = (t.truncate(), n.normalize_or_zero());
        assert!((t3.length() - 1.0).abs() < 1e-6, "{t:?}");
        assert!(t3.dot(n).abs() < 1e-6, "{t:?} against {n:?}");
        assert!(t3.x > 0.9, "still along +x: {t:?}");
        assert_eq!(t.w, 1.0);
    }
}

#[test]
fn degenerate_input_still_gives_finite_perpendicular_frames() {
    // All texture coordinates equal: no direction of increasing u anywhere.
    let flat_uvs = [Vec2::new(0.5, 0.5); 4];
    let normals = [Vec3::Z, Vec3::X, Vec3::new(0.0, 0.0, 0.0), Vec3::new(f32::NAN, 0.0, 1.0)];
    for (t, n) in tangents(&QUAD, &normals, &flat_uvs, &QUAD_INDICES).iter().zip(normals) {
        assert!(t.is_finite(), "{t:?}");
        assert!((t.truncate().length() - 1.0).abs() < 1e-6, "{t:?}");
        if n.is_finite() {
            assert!(t.truncate().dot(n).abs() < 1e-6, "{t:?} against {n:?}");
        }
        assert_eq!(t.w, 1.0);
    }
    // A vertex used by no triangle, and an index out of range, are ignored.
    let positions = [QUAD[0], QUAD[1], QUAD[2], QUAD[3], Vec3::new(5.0, 5.0, 5.0)];
    let uvs = positions.map(|p| Vec2::new(p.x, p.y));
    let t = tangents(&positions, &[Vec3::Z; 5], &uvs, &[0, 1, 2, 0, 2, 3, 0, 1, 99]);
    assert_eq!(&t[..4], &[Vec4::new(1.0, 0.0, 0.0, 1.0); 4]);
    assert!(t[4].is_finite() && t[4].truncate().dot(Vec3::Z) == 0.0);
}

#[test]
fn missing_attributes_and_wrong_sizes_are_errors() {
    let bare = Mesh::new(&QUAD, Indices::U16(&QUAD_INDICES)).unwrap();
    let mut out = vec![Vec4::ZERO; 4];
    assert_eq!(compute_tangents(&bare, &mut out), Err(TangentError::MissingAttributes));
    let normals = [Vec3::Z; 4];
    let uvs = [Vec2::ZERO; 4];
    let full = bare.with_normals(&normals).unwrap().with_uvs(&uvs).unwrap();
    let mut short = vec![Vec4::ZERO; 3];
    assert_eq!(compute_tangents(&full, &mut short), Err(TangentError::OutputLength { expected: 4, actual: 3 }));
    assert_eq!(TangentError::OutputLength { expected: 4, actual: 3 }.to_string(), "3 tangents given for 4 vertices");
}
