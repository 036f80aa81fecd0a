//! Vectors, matrices, quaternions, cameras and colour packing.

use rastty_core::camera::{CameraError, Viewport, look_at, orthographic, perspective};
use rastty_core::color::{pack_rgb565, pack_rgb888, rgb565_to_rgb888, unpack_rgb565, unpack_rgb888};
use rastty_core::math::{Mat3, Mat4, Quat, Vec3, Vec4};

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).length() <= eps
}

fn sample_matrices() -> Vec<Mat4> {
    vec![
        Mat4::IDENTITY,
        Mat4::from_translation(Vec3::new(1.0, -2.0, 3.5)),
        Mat4::from_scale(Vec3::new(2.0, 0.5, -3.0)),
        Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 3.0), 0.7) * Mat4::from_translation(Vec3::new(0.3, 4.0, -1.0)),
        perspective(1.1, 1.6, 0.1, 100.0).unwrap() * look_at(Vec3::new(3.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap(),
        Mat4::from_rows([2.0, 1.0, 0.5, 3.0], [0.0, 3.0, 1.0, -1.0], [1.0, 0.0, 4.0, 2.0], [0.5, 0.2, 0.1, 1.0]),
    ]
}

#[test]
fn inverse_times_matrix_is_identity() {
    for m in sample_matrices() {
        let inv = m.inverse().expect("invertible");
        // f32 round-off grows with the size of the entries (a perspective matrix has entries near 10).
        let largest = |m: &Mat4| m.cols.iter().flat_map(|c| [c.x, c.y, c.z, c.w]).fold(0.0f32, |a, v| a.max(v.abs()));
        let scale = largest(&m) * largest(&inv);
        let tolerance = 4.0 * f32::EPSILON * scale.max(1.0);
        assert!((m * inv).max_abs_diff(&Mat4::IDENTITY) < tolerance, "{m:?}");
        assert!((inv * m).max_abs_diff(&Mat4::IDENTITY) < tolerance, "{m:?}");
    }
}

#[test]
fn singular_matrices_have_no_inverse() {
    assert_eq!(Mat4::from_scale(Vec3::new(1.0, 1.0, 0.0)).inverse(), None);
    let rank_deficient =
        Mat4::from_rows([1.0, 2.0, 3.0, 4.0], [2.0, 4.0, 6.0, 8.0], [0.0, 1.0, 0.0, 1.0], [1.0, 0.0, 1.0, 0.0]);
    assert_eq!(rank_deficient.inverse(), None);
    assert_eq!(Mat3::from_diagonal(Vec3::new(1.0, 0.0, 1.0)).inverse(), None);
    let nan = Mat4::from_scale(Vec3::new(f32::NAN, 1.0, 1.0));
    assert_eq!(nan.inverse(), None);
}

#[test]
fn determinants() {
    assert_eq!(Mat4::from_scale(Vec3::new(2.0, 3.0, 4.0)).determinant(), 24.0);
    assert_eq!(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)).determinant(), -1.0);
    assert!((Mat4::from_axis_angle(Vec3::new(1.0, 1.0, 0.0), 2.0).determinant() - 1.0).abs() < 1e-6);
    let m = sample_matrices()[5];
    assert_eq!(m.determinant(), m.transpose().determinant());
}

#[test]
fn transpose_swaps_rows_and_columns() {
    let m = sample_matrices()[5];
    assert_eq!(m.transpose().transpose(), m);
    assert_eq!(m.transpose().cols[1], m.row(1));
}

#[test]
fn cofactor_maps_cross_products() {
    let (a, b) = (Vec3::new(1.0, 2.0, -0.5), Vec3::new(-0.3, 0.7, 2.0));
    for m in [
        Mat3::from_diagonal(Vec3::new(2.0, 1.0, 1.0)),
        Mat3::from_diagonal(Vec3::new(-1.0, 1.0, 1.0)),
        Mat3::from_diagonal(Vec3::new(1.0, 1.0, 0.0)),
        Mat4::from_axis_angle(Vec3::new(0.2, 1.0, 0.4), 1.3).to_mat3() * Mat3::from_diagonal(Vec3::new(3.0, 0.5, 1.0)),
    ] {
        let lhs = (m * a).cross(m * b);
        let rhs = m.cofactor() * a.cross(b);
        assert!(close(lhs, rhs, 1e-5), "{m:?}: {lhs:?} vs {rhs:?}");
    }
}

/// Transformed normals stay perpendicular to transformed tangents and keep pointing out of the surface.
#[test]
fn normal_matrix_keeps_normals_perpendicular_and_outward() {
    // The plane x + y + z = 1 with outward normal (1, 1, 1) (pointing away from the origin), tangents in it.
    let normal = Vec3::ONE;
    let tangents = [Vec3::new(1.0, -1.0, 0.0), Vec3::new(1.0, 0.0, -1.0)];
    let point = Vec3::splat(1.0 / 3.0);
    for scale in
        [Vec3::new(2.0, 1.0, 1.0), Vec3::new(-1.0, 1.0, 1.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(3.0, -0.5, 2.0)]
    {
        let m = Mat4::from_scale(scale);
        let n = m.normal_matrix() * normal;
        assert!(n.is_finite() && n.length() > 0.0, "{scale:?}");
        for t in tangents {
            let t = m.transform_vector(t);
            assert!(n.dot(t).abs() < 1e-6, "{scale:?}: n {n:?} . t {t:?}");
        }
        // Outward: the transformed origin lies behind the transformed plane.
        let inside = m.transform_point(Vec3::ZERO) - m.transform_point(point);
        assert!(n.dot(inside) <= 0.0, "{scale:?}: normal {n:?} points inward");
    }
}

#[test]
fn quaternion_rotations() {
    let q = Quat::from_axis_angle(Vec3::Z, core::f32::consts::FRAC_PI_2);
    assert!(close(q.rotate(Vec3::X), Vec3::Y, 1e-6));
    assert!(close(q.to_mat3() * Vec3::X, Vec3::Y, 1e-6));
    let r = Quat::from_axis_angle(Vec3::new(1.0, 1.0, 0.0), 0.8);
    let v = Vec3::new(0.3, -2.0, 1.5);
    // a * b rotates by b first.
    assert!(close((q * r).rotate(v), q.rotate(r.rotate(v)), 1e-5));
    assert!(close((q * r).to_mat3() * v, q.to_mat3() * (r.to_mat3() * v), 1e-5));
    assert!(close(q.conjugate().rotate(q.rotate(v)), v, 1e-5));
    assert_eq!(Quat::from_axis_angle(Vec3::ZERO, 1.0), Quat::IDENTITY);
    assert_eq!(Quat::from_axis_angle(Vec3::X, f32::NAN), Quat::IDENTITY);
    assert_eq!(Quat { x: 0.0, y: 0.0, z: 0.0, w: 0.0 }.normalize(), Quat::IDENTITY);
}

#[test]
fn a_million_small_rotations_stay_orthonormal() {
    // As the viewer applies them: a small yaw and pitch per key press, renormalised each time.
    let step = Quat::from_axis_angle(Vec3::Y, 0.013) * Quat::from_axis_angle(Vec3::X, 0.0071);
    let mut q = Quat::IDENTITY;
    for _ in 0..1_000_000 {
        q = (step * q).normalize();
    }
    let m = q.to_mat3();
    let [a, b, c] = m.cols;
    for (x, y, expect) in [(a, a, 1.0), (b, b, 1.0), (c, c, 1.0), (a, b, 0.0), (b, c, 0.0), (a, c, 0.0)] {
        assert!((x.dot(y) - expect).abs() < 1e-5, "{m:?}");
    }
    assert!((m.determinant() - 1.0).abs() < 1e-5);
}

fn assert_orthonormal_view(view: &Mat4) {
    assert!(view.is_finite());
    let r = view.to_mat3();
    let [a, b, c] = r.cols;
    for (x, y, expect) in [(a, a, 1.0), (b, b, 1.0), (c, c, 1.0), (a, b, 0.0), (b, c, 0.0), (a, c, 0.0)] {
        assert!((x.dot(y) - expect).abs() < 1e-6, "{view:?}");
    }
    assert!((r.determinant() - 1.0).abs() < 1e-6, "right-handed");
}

#[test]
fn look_at_puts_the_target_ahead() {
    let eye = Vec3::new(1.0, 2.0, 3.0);
    let view = look_at(eye, Vec3::new(1.0, 2.0, -1.0), Vec3::Y).unwrap();
    assert_orthonormal_view(&view);
    assert!(close(view.transform_point(eye), Vec3::ZERO, 1e-6));
    assert!(close(view.transform_point(Vec3::new(1.0, 2.0, -1.0)), Vec3::new(0.0, 0.0, -4.0), 1e-6));
    assert!(close(view.transform_vector(Vec3::Y), Vec3::Y, 1e-6));
}

#[test]
fn look_at_straight_down_or_with_zero_up_stays_finite() {
    for (eye, up) in [
        (Vec3::new(0.0, 5.0, 0.0), Vec3::Y),
        (Vec3::new(0.0, -5.0, 0.0), Vec3::Y),
        (Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO),
        (Vec3::new(0.0, 5.0, 0.0), Vec3::new(0.0, 1.0, 1e-9)),
    ] {
        let view = look_at(eye, Vec3::ZERO, up).unwrap();
        assert_orthonormal_view(&view);
        assert!(close(view.transform_point(Vec3::ZERO), Vec3::new(0.0, 0.0, -5.0), 1e-5), "{eye:?} {up:?}");
    }
}

#[test]
fn look_at_refuses_a_missing_view_direction() {
    assert_eq!(look_at(Vec3::ONE, Vec3::ONE, Vec3::Y), Err(CameraError::EyeAtTarget));
    assert_eq!(look_at(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::ZERO, Vec3::Y), Err(CameraError::NotFinite));
    assert_eq!(look_at(Vec3::ZERO, Vec3::X, Vec3::new(0.0, f32::INFINITY, 0.0)), Err(CameraError::NotFinite));
}

#[test]
fn perspective_maps_near_to_0_and_far_to_1() {
    let p = perspective(1.0, 2.0, 0.5, 50.0).unwrap();
    let ndc = |z: f32| {
        let c = p.project_point(Vec3::new(0.0, 0.0, z));
        c.z / c.w
    };
    assert!(ndc(-0.5).abs() < 1e-6);
    assert!((ndc(-50.0) - 1.0).abs() < 1e-6);
    // The frustum's top edge at distance 1 is tan(fovy/2).
    let top = p.project_point(Vec3::new(0.0, (0.5f32).tan(), -1.0));
    assert!((top.y / top.w - 1.0).abs() < 1e-6);
    assert!(!p.is_affine());
}

#[test]
fn perspective_and_orthographic_refuse_degenerate_parameters() {
    assert_eq!(perspective(0.0, 1.0, 0.1, 10.0), Err(CameraError::FieldOfView));
    assert_eq!(perspective(core::f32::consts::PI, 1.0, 0.1, 10.0), Err(CameraError::FieldOfView));
    assert_eq!(perspective(1.0, 0.0, 0.1, 10.0), Err(CameraError::Aspect));
    assert_eq!(perspective(1.0, 1.0, 0.0, 10.0), Err(CameraError::DepthRange));
    assert_eq!(perspective(1.0, 1.0, 1.0, 1.0), Err(CameraError::DepthRange));
    assert_eq!(perspective(f32::NAN, 1.0, 0.1, 10.0), Err(CameraError::NotFinite));
    assert_eq!(orthographic(1.0, 1.0, -1.0, 1.0, 0.1, 10.0), Err(CameraError::EmptyBox));
    assert_eq!(orthographic(-1.0, 1.0, 2.0, 2.0, 0.1, 10.0), Err(CameraError::EmptyBox));
    assert_eq!(orthographic(-1.0, 1.0, -1.0, 1.0, 3.0, 3.0), Err(CameraError::DepthRange));
    assert_eq!(orthographic(-1.0, 1.0, -1.0, 1.0, 0.0, f32::INFINITY), Err(CameraError::NotFinite));
    // A box so thin that its scale overflows.
    assert_eq!(orthographic(-1e-45, 1e-45, -1.0, 1.0, 0.0, 1.0), Err(CameraError::NotFinite));
}

#[test]
fn orthographic_is_affine_with_depth_0_to_1() {
    let o = orthographic(-2.0, 4.0, -1.0, 1.0, 1.0, 11.0).unwrap();
    assert!(o.is_affine());
    assert_eq!(o.project_point(Vec3::new(-2.0, -1.0, -1.0)), Vec4::new(-1.0, -1.0, 0.0, 1.0));
    assert_eq!(o.project_point(Vec3::new(4.0, 1.0, -11.0)), Vec4::new(1.0, 1.0, 1.0, 1.0));
}

#[test]
fn viewport_maps_ndc_to_pixels_with_y_down() {
    let v = Viewport::full(200, 100);
    assert_eq!(v.to_screen(Vec3::new(-1.0, 1.0, 0.25)), Vec3::new(0.0, 0.0, 0.25));
    assert_eq!(v.to_screen(Vec3::new(1.0, -1.0, 0.5)), Vec3::new(200.0, 100.0, 0.5));
    let p = Vec3::new(0.3, -0.7, 0.9);
    assert!(close(v.matrix().transform_point(p), v.to_screen(p), 1e-4));
}

#[test]
fn colour_packing() {
    assert_eq!(pack_rgb888(Vec3::new(1.0, 0.0, 0.5)), 0xFF0080);
    assert_eq!(pack_rgb888(Vec3::new(2.0, -1.0, f32::NAN)), 0xFF0000);
    for p in [0u32, 0x123456, 0xFFFFFF, 0x00FF7F] {
        assert_eq!(pack_rgb888(unpack_rgb888(p)), p);
    }
    assert_eq!(pack_rgb565(Vec3::ONE), 0xFFFF);
    assert_eq!(pack_rgb565(Vec3::new(0.0, 1.0, 0.0)), 0x07E0);
    for p in [0u16, 0x1234, 0xFFFF, 0xF800, 0x001F] {
        assert_eq!(pack_rgb565(unpack_rgb565(p)), p);
    }
    assert_eq!(rgb565_to_rgb888(0xFFFF), 0xFFFFFF);
    assert_eq!(rgb565_to_rgb888(0xF800), 0xFF0000);
}
