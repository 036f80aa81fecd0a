//! Huge coordinates: vertices from 10^4 to 10^38 units away, against an exact f64 ray cast of the same triangle
//! (the triangle clipped in f64, in effect). Integer overflow would panic: these tests run with overflow checks.

use super::common::{PinholeCamera, ascii, both_sides};

const CAMERA: PinholeCamera = PinholeCamera { fovy: 1.2, near: 1.0, far: 50.0, width: 24, height: 16 };

/// A triangle on the plane z = -10 whose corners are `scale` units out. Two corners are exact opposites, so the
/// edge between them passes exactly through the view's centre, tilted by 0.1 rad, at every scale; the third is
/// far below it: the visible part is the half of the view below that edge.
fn far_flung(scale: f32) -> [[f32; 3]; 3] {
    let (c, s) = (0.995_004_2 * scale, 0.099_833_42 * scale);
    [[c, s, -10.0], [-c, -s, -10.0], [s, -c, -10.0]]
}

/// From 10^4 to 10^30: the same pixels as the exact ray cast.
#[test]
fn huge_triangles_cover_exactly_what_an_f64_ray_cast_covers() {
    for exponent in [4, 5, 6, 8, 10, 15, 20, 25, 30] {
        let scale = 10f32.powi(exponent);
        let tri = far_flung(scale);
        let (reference, fragile) = CAMERA.robust_ray_cast(&[tri]);
        assert_eq!(fragile, 0, "10^{exponent}: pick a scene with no pixel centre on an edge");
        let (counts, stats) = CAMERA.render(&[tri], &both_sides());
        assert!(
            counts == reference,
            "10^{exponent}:\nrendered:\n{}\nray cast:\n{}",
            ascii(&counts, CAMERA.width).join("\n"),
            ascii(&reference, CAMERA.width).join("\n")
        );
        assert_eq!((stats.rasterized, stats.invalid), (1, 0), "10^{exponent}");
        assert!(counts.iter().any(|&c| c > 0), "10^{exponent}: the triangle is visible");
    }
}

/// Large enough that the projection overflows to infinity: the triangle is discarded, nothing is drawn.
#[test]
fn triangles_whose_projection_overflows_are_discarded() {
    for scale in [3e38f32, f32::MAX] {
        let (counts, stats) = CAMERA.render(&[far_flung(scale)], &both_sides());
        assert!(counts.iter().all(|&c| c == 0), "{scale:e}");
        assert_eq!((stats.invalid, stats.rasterized), (1, 0), "{scale:e}");
    }
}

/// One corner huge and behind the camera, the others in view: clipping at the near plane with an extreme
/// intersection parameter.
#[test]
fn a_huge_corner_behind_the_camera_clips_exactly() {
    for exponent in [4, 8, 16, 30] {
        let s = 10f32.powi(exponent);
        let tri = [[-2.3, -1.7, -6.0], [2.9, -1.1, -7.0], [0.37 * s, 0.21 * s, s]];
        let (reference, fragile) = CAMERA.robust_ray_cast(&[tri]);
        assert_eq!(fragile, 0, "10^{exponent}: pick a scene with no pixel centre on an edge");
        let (counts, stats) = CAMERA.render(&[tri], &both_sides());
        assert!(
            counts == reference,
            "10^{exponent}:\nrendered:\n{}\nray cast:\n{}",
            ascii(&counts, CAMERA.width).join("\n"),
            ascii(&reference, CAMERA.width).join("\n")
        );
        assert_eq!(stats.clipped, 1);
    }
}
