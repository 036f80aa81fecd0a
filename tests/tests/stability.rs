//! Hard cases through the scene API, as the viewer and `rastty render` use it: bands of 1, 7 and 16 rows on hard
//! scenes, degenerate models, degenerate cameras, and rotation drift as the viewer applies rotations. Each test
//! states the exact expected result. The core's own families are in `core/tests/stability/`.

use std::sync::LazyLock;

use rastty::builtin::builtin_model;
use rastty::model::{NoFiles, load_obj_bytes};
use rastty::scene::{Appearance, Lens, OrbitCamera, RenderError, Scene, ShadingMode};
use rastty_core::camera::CameraError;
use rastty_core::color::pack_rgb888;
use rastty_core::math::Vec3;
use rastty_core::target::{Rgb888, Target};

static SPOT: LazyLock<Scene> = LazyLock::new(|| Scene::new(builtin_model().expect("the built-in model loads")));

/// Renders a whole frame.
fn whole(scene: &Scene, (w, h): (u32, u32), camera: &OrbitCamera, look: &Appearance) -> Result<Vec<u32>, RenderError> {
    let n = (w * h) as usize;
    let (mut color, mut depth) = (vec![0u32; n], vec![0f32; n]);
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], w, h).expect("a valid frame");
    scene.render(&mut target, camera, look, w as f32 / h as f32)?;
    Ok(color)
}

/// Renders the frame as bands of `rows` rows into one small buffer, rows assembled.
fn banded(scene: &Scene, (w, h): (u32, u32), rows: u32, camera: &OrbitCamera, look: &Appearance) -> Vec<u32> {
    let (mut color, mut depth) = (vec![0u32; (w * rows) as usize], vec![0f32; (w * rows) as usize]);
    let mut out = Vec::new();
    for y0 in (0..h).step_by(rows as usize) {
        let y1 = (y0 + rows).min(h);
        let n = (w * (y1 - y0)) as usize;
        color.fill(0x00FF_00FF);
        let mut band = Target::band(Rgb888(&mut color[..n]), &mut depth[..n], w, h, y0..y1).expect("a valid band");
        scene.render(&mut band, camera, look, w as f32 / h as f32).expect("the band renders");
        out.extend_from_slice(&color[..n]);
    }
    out
}

/// Hard scenes in bands of 1, 7 and 16 rows: bit-identical to the whole frame. The scenes: the near plane cutting
/// the model, the camera inside the model, an orthographic view with wireframe, a very wide frame, every shading
/// mode.
#[test]
fn bands_of_1_7_16_rows_equal_the_whole_frame_on_hard_scenes() {
    let near_cut = OrbitCamera { near: Some(2.2), ..OrbitCamera::default() };
    let inside = OrbitCamera::new(10.0, 5.0, 0.3, Lens::Perspective { fov_degrees: 90.0 });
    let ortho = OrbitCamera::new(200.0, -30.0, 2.8, Lens::Orthographic { fov_degrees: 40.0 });
    let wire = Appearance { wireframe: true, ..Appearance::default() };
    let mut cases = vec![
        ((97, 61), near_cut, Appearance::default()),
        ((80, 53), inside, Appearance::default()),
        ((90, 70), ortho, wire),
        ((400, 9), OrbitCamera::default(), Appearance::default()),
    ];
    for shading in ShadingMode::ALL {
        cases.push((
            (64, 48),
            OrbitCamera::default(),
            Appearance { shading, wireframe: true, ..Appearance::default() },
        ));
    }
    for (size, camera, look) in cases {
        let frame = whole(&SPOT, size, &camera, &look).expect("renders");
        for rows in [1, 7, 16] {
            let bands = banded(&SPOT, size, rows, &camera, &look);
            let differing = frame.iter().zip(&bands).filter(|(a, b)| a != b).count();
            assert_eq!(differing, 0, "{size:?} {:?} in {rows}-row bands", look.shading);
        }
    }
}

/// A model whose vertices all lie at one point: every triangle has zero area, so the image is exactly the
/// background, with no panic and no NaN from fitting a model of size zero.
#[test]
fn a_model_of_one_point_draws_only_the_background() {
    let obj = b"v 1 2 3\nv 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\nf 1 3 4\n";
    let scene = Scene::new(load_obj_bytes("point.obj", obj, &NoFiles).expect("loads"));
    let look = Appearance::default();
    let image = whole(&scene, (32, 24), &OrbitCamera::default(), &look).expect("renders");
    assert!(image.iter().all(|&p| p == pack_rgb888(look.background)));
}

/// A model 1e14 units from the origin and one unit across: at that distance an f32 cannot tell its vertices
/// apart, so every triangle collapses; the result is exactly the background, not a panic or garbage.
#[test]
fn a_model_far_from_the_origin_collapses_cleanly() {
    let obj = b"v 100000000000000 0 0\nv 100000000000001 0 0\nv 100000000000000 1 0\nf 1 2 3\n";
    let scene = Scene::new(load_obj_bytes("far.obj", obj, &NoFiles).expect("loads"));
    let look = Appearance::default();
    let image = whole(&scene, (32, 24), &OrbitCamera::default(), &look).expect("renders");
    assert!(image.iter().all(|&p| p == pack_rgb888(look.background)));
}

/// Degenerate cameras are errors that name the problem, never a panic or a black frame.
#[test]
fn degenerate_cameras_are_errors() {
    let look = Appearance::default();
    let mut bad = Vec::new();
    for distance in [0.0, -1.0, f32::NAN, f32::INFINITY] {
        // The orbit distance places the eye, so a bad one leaves no valid depth range.
        bad.push((OrbitCamera { distance, ..OrbitCamera::default() }, CameraError::DepthRange));
    }
    for fov_degrees in [0.0, 180.0, -5.0, f32::NAN] {
        let lenses = [Lens::Perspective { fov_degrees }, Lens::Orthographic { fov_degrees }];
        for lens in lenses {
            bad.push((OrbitCamera { lens, ..OrbitCamera::default() }, CameraError::FieldOfView));
        }
    }
    bad.push((OrbitCamera { near: Some(5.0), far: Some(1.0), ..OrbitCamera::default() }, CameraError::DepthRange));
    bad.push((OrbitCamera { near: Some(0.0), ..OrbitCamera::default() }, CameraError::DepthRange));
    for (camera, expected) in bad {
        let result = whole(&SPOT, (16, 12), &camera, &look).map(|_| "an image");
        assert_eq!(result, Err(RenderError::Camera(expected)), "{camera:?}");
    }
}

/// A million small rotations applied as the viewer applies them (each renormalised): the orientation stays a
/// rotation within 1e-5, and the model turned by 1000 whole turns in 1000 steps each is where it started, to
/// within 1e-3 of the image size.
#[test]
fn a_million_viewer_rotations_do_not_drift() {
    let mut camera = OrbitCamera::default();
    let start = camera.orientation;
    let step = std::f32::consts::TAU / 1000.0;
    for _ in 0..1_000_000 {
        camera.rotate(step, 0.0);
    }
    let q = camera.orientation;
    let norm = (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w).sqrt();
    assert!((norm - 1.0).abs() < 1e-5, "|q| = {norm}");
    let m = q.to_mat3();
    for (i, a) in m.cols.iter().enumerate() {
        for (j, b) in m.cols.iter().enumerate() {
            let expected = if i == j { 1.0 } else { 0.0 };
            assert!((a.dot(*b) - expected).abs() < 1e-5, "columns {i} and {j}: {}", a.dot(*b));
        }
    }
    // 1000 turns later: a point on the unit sphere lands within 1e-3 of where it started.
    let p = Vec3::new(0.6, 0.0, 0.8);
    let moved = (q.rotate(p) - start.rotate(p)).length();
    assert!(moved < 1e-3, "a point moved {moved} after 1000 full turns");
}
