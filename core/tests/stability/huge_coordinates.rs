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

/// Fuzzing finding F2: an orthographic view of a triangle with one corner 3.7e35 units away. Before exact
/// clipping, cutting the edge from that corner lost the small coordinates (`a + (b - a) t` with `t` rounded to 1),
/// so the whole frame drew 363 fragments up to row 17 while every vertex lies below row 25, and the band of rows
/// 0..21, which rejects the triangle by its vertices, differed from the frame. Now, with each culling mode, the band
/// equals the frame's rows bit for bit and nothing is drawn in rows 0..21, and the part in view (105 fragments
/// here) is drawn by exactly one of front-face and back-face culling.
#[test]
fn a_band_equals_the_frame_when_a_corner_is_1e35_away() {
    use rastty_core::camera::{look_at, orthographic};
    use rastty_core::color::ShadingSpace;
    use rastty_core::math::{Mat4, Vec3};
    use rastty_core::mesh::{Indices, Mesh};
    use rastty_core::pipeline::{Cull, DepthTest, DrawState};
    use rastty_core::shading::{Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
    use rastty_core::target::Rgb888;

    let positions = [
        Vec3::new(-113.679_69, -11.734_375, -60.695_313),
        Vec3::new(-50.324_22, -16.1875, -3.685_537e35),
        Vec3::new(27.878_906, -71.648_44, 0.0),
    ];
    let view = look_at(
        Vec3::new(-77.210_94, 1e-45, -55.355_47),
        Vec3::new(29.0, -33.0, -61.0),
        Vec3::new(-79.679_69, 1.570_796_4, 5.757_812_5),
    )
    .unwrap();
    let projection = orthographic(-59.121_094, 46.0, 28.0, 80.925_78, 74.363_28, 4.992_137e26).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let object =
        Object { mesh, tangents: None, transforms, shading: ShadingModel::Unlit, material: Material::default() };
    let lighting = Lighting { ambient: Vec3::ONE, lights: &[], environment: None, space: ShadingSpace::Linear };
    let (w, h, band) = (40u32, 35u32, 0..21u32);
    let draw = |cull: Cull, rows: core::ops::Range<u32>| {
        let state = DrawState { cull, depth_test: DepthTest::Off, subpixel_bits: 0, ..DrawState::DEFAULT };
        let n = (w * (rows.end - rows.start)) as usize;
        let (mut color, mut depth) = (vec![0u32; n], vec![0f32; n]);
        let mut target = crate::common::band(Rgb888(&mut color), &mut depth[..], w, h, rows);
        target.clear(Vec3::ZERO);
        let (_, stats) = draw_mesh(&mut target, &object, &lighting, &state).unwrap();
        (color, stats.fragments)
    };
    let mut fragments = [0; 3];
    for (cull, count) in [Cull::None, Cull::Front, Cull::Back].into_iter().zip(&mut fragments) {
        let (frame, drawn) = draw(cull, 0..h);
        let (banded, _) = draw(cull, band.clone());
        assert!(banded == frame[..(w * band.end) as usize], "{cull:?}: the band's rows differ from the frame's");
        assert!(frame[..(w * band.end) as usize].iter().all(|&c| c == 0), "{cull:?}: something drawn in rows 0..21");
        *count = drawn;
    }
    // The part in view faces one way: culling one side or the other splits the unculled picture.
    let [all, front_culled, back_culled] = fragments;
    assert!(all > 0, "part of the triangle is in view");
    assert_eq!(front_culled + back_culled, all);
}
