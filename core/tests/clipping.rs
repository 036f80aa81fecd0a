//! Clipping: triangles crossing the near and far planes, vertices behind the camera or at w = 0, and huge
//! triangles cut by the guard band, each against an exact f64 ray-cast of the same view.

use crate::common;

use common::{PinholeCamera, ascii, both_sides};

const CAMERA: PinholeCamera = PinholeCamera { fovy: 1.2, near: 1.0, far: 50.0, width: 24, height: 16 };

/// Renders and ray-casts `tris`, asserting that the reference is robust (no pixel centre within 0.01 px of an
/// edge) and that the two agree on every pixel.
#[track_caller]
fn assert_matches_ray_cast(tris: &[[[f32; 3]; 3]]) -> rastty_core::pipeline::DrawStats {
    let (reference, fragile) = CAMERA.robust_ray_cast(tris);
    assert_eq!(
        fragile,
        0,
        "choose a scene without pixel centres on edges:\n{}",
        ascii(&reference, CAMERA.width).join("\n")
    );
    let (counts, stats) = CAMERA.render(tris, &both_sides());
    assert!(
        counts == reference,
        "rendered:\n{}\nray cast:\n{}",
        ascii(&counts, CAMERA.width).join("\n"),
        ascii(&reference, CAMERA.width).join("\n")
    );
    stats
}

#[test]
fn floor_crossing_the_near_plane() {
    // Two vertices behind the camera (w < 0), one far ahead: drawn unclipped the projection would invert.
    let floor = [[-10.0, -2.41, 2.0], [10.0, -1.1, 3.11], [0.3, -1.7, -40.0]];
    let stats = assert_matches_ray_cast(&[floor]);
    assert_eq!((stats.clipped, stats.rasterized), (1, 1));
}

#[test]
fn one_vertex_behind_the_camera() {
    let tri = [[-3.1, -2.2, -5.0], [2.7, -1.9, -4.0], [0.4, 3.3, 1.5]];
    let stats = assert_matches_ray_cast(&[tri]);
    assert_eq!(stats.clipped, 1);
}

#[test]
fn vertex_exactly_at_w_zero() {
    // The third vertex lies in the camera's own plane (z = 0, so w = 0).
    let tri = [[-3.1, -2.2, -5.0], [2.7, -1.9, -4.0], [0.7, 2.1, 0.0]];
    assert_matches_ray_cast(&[tri]);
}

#[test]
fn triangle_crossing_the_far_plane() {
    let tri = [[-30.0, -20.3, -30.0], [46.1, -18.1, -70.0], [1.1, 39.09, -45.0]];
    let stats = assert_matches_ray_cast(&[tri]);
    assert_eq!(stats.clipped, 1);
}

#[test]
fn huge_triangle_cut_by_the_guard_band() {
    // Corners a million units away: far outside the guard band, so the triangle is clipped, yet the visible part
    // (a corner of it crossing the frame) is exact.
    let tri = [[-1.0e6, -1.0e6, -10.0], [1.0e6, -0.93e6, -10.0], [-1.1e6, 0.011e6 + 3.3, -10.0]];
    let stats = assert_matches_ray_cast(&[tri]);
    assert_eq!(stats.clipped, 1);
}

#[test]
fn shared_edge_crossing_the_near_plane_stays_watertight() {
    // A quad of two triangles whose shared diagonal crosses the near plane: every covered pixel exactly once.
    let (a, b, c, d) = ([-4.1, -1.3, 3.0], [4.3, -1.2, 3.0], [4.2, -1.6, -30.0], [-3.9, -1.7, -30.0]);
    let quad = [[a, b, c], [a, c, d]];
    let stats = assert_matches_ray_cast(&quad);
    assert_eq!(stats.clipped, 2);
}

#[test]
fn triangles_wholly_behind_or_beside_are_rejected_without_clipping() {
    let behind = [[-1.0, -1.0, 3.0], [1.0, -1.0, 3.0], [0.0, 1.0, 3.0]];
    let left = [[-100.0, -1.0, -5.0], [-90.0, -1.0, -5.0], [-95.0, 1.0, -5.0]];
    let beyond_far = [[-1.0, -1.0, -60.0], [1.0, -1.0, -60.0], [0.0, 1.0, -60.0]];
    let (counts, stats) = CAMERA.render(&[behind, left, beyond_far], &both_sides());
    assert!(counts.iter().all(|&c| c == 0));
    assert_eq!((stats.outside, stats.clipped, stats.rasterized), (3, 0, 0));
}
