//! Hard cases through the scene API, as the viewer and `rastty render` use it: bands of 1, 7 and 16 rows on hard
//! scenes, degenerate models, degenerate cameras, and rotation drift as the viewer applies rotations. Each test
//! states the exact expected result. The core's own families are in `core/tests/stability/`.

use std::sync::LazyLock;

use rastty_core::camera::CameraError;
use rastty_core::color::pack_rgb888;
use rastty_core::math::Vec3;
use rastty_core::target::{Rgb888, Target};
use rastty_scene::builtin::builtin_model;
use rastty_scene::model::{Model, NoFiles, load_obj_bytes};
use rastty_scene::scene_file::{SceneCamera, SceneData, SceneProjection, defaults};
use rastty_scene::scene_render::{
    CameraOptions, Orbit, PlanOptions, PreparedScene, ScenePlan, SceneRenderError, SceneRenderer, ShadingMode,
};

static SPOT: LazyLock<PreparedScene> = LazyLock::new(|| scene(builtin_model().expect("the built-in model loads")));

/// `model` as the scene `rastty` shows for it.
fn scene(model: Model) -> PreparedScene {
    PreparedScene::new(SceneData::from_model(model, "model.obj".into())).expect("the scene prepares")
}

/// Plans a frame of `scene` seen by `camera`.
fn plan(scene: &PreparedScene, (w, h): (u32, u32), camera: &SceneCamera, look: &PlanOptions) -> ScenePlan {
    ScenePlan::new(scene, camera, (w, h), look).expect("the frame plans")
}

/// Renders a whole frame on one thread.
fn whole(scene: &PreparedScene, (w, h): (u32, u32), camera: &SceneCamera, look: &PlanOptions) -> Vec<u32> {
    let n = (w * h) as usize;
    let (mut color, mut depth) = (vec![0u32; n], vec![0f32; n]);
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], w, h).expect("a valid frame");
    let plan = plan(scene, (w, h), camera, look);
    SceneRenderer::with_threads(1).render(scene, &plan, &mut target).expect("the frame renders");
    color
}

/// Renders the frame as bands of `rows` rows into one small buffer, rows assembled.
fn banded(scene: &PreparedScene, (w, h): (u32, u32), rows: u32, camera: &SceneCamera, look: &PlanOptions) -> Vec<u32> {
    let (plan, mut renderer) = (plan(scene, (w, h), camera, look), SceneRenderer::new());
    let (mut color, mut depth) = (vec![0u32; (w * rows) as usize], vec![0f32; (w * rows) as usize]);
    let mut out = Vec::new();
    for y0 in (0..h).step_by(rows as usize) {
        let y1 = (y0 + rows).min(h);
        let n = (w * (y1 - y0)) as usize;
        color.fill(0x00FF_00FF);
        let mut band = Target::band(Rgb888(&mut color[..n]), &mut depth[..n], w, h, y0..y1).expect("a valid band");
        renderer.render(scene, &plan, &mut band).expect("the band renders");
        out.extend_from_slice(&color[..n]);
    }
    out
}

/// The camera of the built-in model with `options`.
fn camera(options: CameraOptions) -> SceneCamera {
    options.orbit(&SPOT).camera
}

/// Hard scenes in bands of 1, 7 and 16 rows: bit-identical to the whole frame. The scenes: the near plane cutting
/// the model, the camera inside the model, an orthographic view with wireframe, a very wide frame, every shading
/// mode.
#[test]
fn bands_of_1_7_16_rows_equal_the_whole_frame_on_hard_scenes() {
    let near_cut = camera(CameraOptions { near: Some(2.2), ..CameraOptions::default() });
    let inside = camera(CameraOptions {
        yaw_degrees: Some(10.0),
        pitch_degrees: Some(5.0),
        distance: Some(0.3),
        fov_degrees: Some(90.0),
        ..CameraOptions::default()
    });
    let ortho = camera(CameraOptions {
        yaw_degrees: Some(200.0),
        pitch_degrees: Some(-30.0),
        orthographic: true,
        ..CameraOptions::default()
    });
    let default = camera(CameraOptions::default());
    let wire = PlanOptions { wireframe: true, ..PlanOptions::default() };
    let mut cases = vec![
        ((97, 61), near_cut, PlanOptions::default()),
        ((80, 53), inside, PlanOptions::default()),
        ((90, 70), ortho, wire),
        ((400, 9), default, PlanOptions::default()),
    ];
    for shading in ShadingMode::ALL {
        cases.push(((64, 48), default, PlanOptions { shading, wireframe: true, ..PlanOptions::default() }));
    }
    for (size, camera, look) in cases {
        let frame = whole(&SPOT, size, &camera, &look);
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
    let scene = scene(load_obj_bytes("point.obj", obj, &NoFiles).expect("loads"));
    let image = whole(&scene, (32, 24), &scene.camera(), &PlanOptions::default());
    assert!(image.iter().all(|&p| p == pack_rgb888(defaults::BACKGROUND)));
}

/// A model 1e14 units from the origin and one unit across: at that distance an f32 cannot tell its vertices
/// apart, so every triangle collapses; the result is exactly the background, not a panic or garbage.
#[test]
fn a_model_far_from_the_origin_collapses_cleanly() {
    let obj = b"v 100000000000000 0 0\nv 100000000000001 0 0\nv 100000000000000 1 0\nf 1 2 3\n";
    let scene = scene(load_obj_bytes("far.obj", obj, &NoFiles).expect("loads"));
    let image = whole(&scene, (32, 24), &scene.camera(), &PlanOptions::default());
    assert!(image.iter().all(|&p| p == pack_rgb888(defaults::BACKGROUND)));
}

/// Degenerate cameras are errors that name the problem, never a panic or a black frame.
#[test]
fn degenerate_cameras_are_errors() {
    let good = SPOT.camera();
    let mut bad = Vec::new();
    bad.push((SceneCamera { position: good.target, ..good }, CameraError::EyeAtTarget));
    for position in [Vec3::splat(f32::NAN), Vec3::new(f32::INFINITY, 0.0, 0.0)] {
        bad.push((SceneCamera { position, ..good }, CameraError::NotFinite));
    }
    for fov_degrees in [0.0, 180.0, -5.0] {
        let projection = SceneProjection::Perspective { fov_degrees };
        bad.push((SceneCamera { projection, ..good }, CameraError::FieldOfView));
    }
    let projection = SceneProjection::Perspective { fov_degrees: f32::NAN };
    bad.push((SceneCamera { projection, ..good }, CameraError::NotFinite));
    for height in [0.0, -1.0] {
        let projection = SceneProjection::Orthographic { height };
        bad.push((SceneCamera { projection, ..good }, CameraError::EmptyBox));
    }
    bad.push((SceneCamera { near: Some(5.0), far: Some(1.0), ..good }, CameraError::DepthRange));
    bad.push((SceneCamera { near: Some(0.0), ..good }, CameraError::DepthRange));
    for (camera, expected) in bad {
        let result = ScenePlan::new(&SPOT, &camera, (16, 12), &PlanOptions::default()).map(|_| "a plan");
        assert_eq!(result, Err(SceneRenderError::Camera(expected)), "{camera:?}");
    }
}

/// A million small rotations applied as the viewer applies them, about the default view of the built-in model:
/// the eye stays at its distance within 1e-5 of it and at its elevation within 1e-5 radians, and after 1000 whole
/// turns in 1000 steps each it is where it started, to within 1e-3 of the distance.
#[test]
fn a_million_viewer_rotations_do_not_drift() {
    let mut orbit = Orbit::new(SPOT.camera());
    let start = orbit.camera;
    let distance = (start.position - start.target).length();
    let (_, pitch) = orbit.angles();
    let step = std::f32::consts::TAU / 1000.0;
    for _ in 0..1_000_000 {
        orbit.rotate(step, 0.0);
    }
    let end = orbit.camera;
    let drift = ((end.position - end.target).length() - distance).abs() / distance;
    assert!(drift < 1e-5, "the distance changed by {drift} of itself");
    assert!((orbit.angles().1 - pitch).abs() < 1e-5, "the elevation went from {pitch} to {}", orbit.angles().1);
    assert_eq!(end.target, start.target, "the target does not move");
    let moved = (end.position - start.position).length() / distance;
    assert!(moved < 1e-3, "the eye moved {moved} of the distance after 1000 full turns");
}
