//! Animation benchmarks: what posing a skinned, morphed model costs a frame, beside drawing it.
//!
//! Run with `cargo bench -p rastty-bench --bench animation`. The model is `rastty_bench::animated_tube`'s: 10,000
//! vertices on 50 joints with two morph targets. `rastty-bench animation` times the same frames taking turns.

use divan::{Bencher, black_box};
use rastty_bench::animated_tube::tube;
use rastty_core::target::{Rgb888, Target};
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer};

fn main() {
    divan::main();
}

/// A frame of the viewer's size in a 160x48 terminal of half-block cells.
const FRAME: (u32, u32) = (160, 96);

/// Morphing and skinning the tube's 10,000 vertices at a moment of its animation (nodes, joints, vertices).
#[divan::bench]
fn pose_10k_vertices_50_joints(bencher: Bencher) {
    let mut model = tube();
    let mut t = 0.0f32;
    bencher.bench_local(|| {
        t = (t + 0.013) % 1.0;
        model.pose(Some(0), black_box(t));
    });
}

/// One frame of the tube as the viewer draws it, standing still (the pose done once before).
#[divan::bench]
fn frame_still(bencher: Bencher) {
    let (scene, plan, mut renderer) = prepared();
    let (mut pixels, mut depth) = frame_buffers();
    bencher.bench_local(|| {
        let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], FRAME.0, FRAME.1).unwrap();
        renderer.render(&scene, &plan, &mut target).unwrap();
    });
}

/// One frame of the tube playing: the scene posed at the frame's time, then drawn.
#[divan::bench]
fn frame_playing(bencher: Bencher) {
    let (mut scene, plan, mut renderer) = prepared();
    let (mut pixels, mut depth) = frame_buffers();
    let mut t = 0.0f32;
    bencher.bench_local(|| {
        t = (t + 0.013) % 1.0;
        scene.pose(Some(0), t).unwrap();
        let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], FRAME.0, FRAME.1).unwrap();
        renderer.render(&scene, &plan, &mut target).unwrap();
    });
}

fn prepared() -> (PreparedScene, ScenePlan, SceneRenderer) {
    let mut scene = PreparedScene::new(SceneData::from_model(tube(), "tube.glb".into())).unwrap();
    scene.pose(Some(0), 0.5).unwrap();
    let camera = CameraOptions::default().orbit(&scene).camera;
    let plan = ScenePlan::new(&scene, &camera, FRAME, &PlanOptions::default()).unwrap();
    (scene, plan, SceneRenderer::new())
}

fn frame_buffers() -> (Vec<u32>, Vec<f32>) {
    let n = (FRAME.0 * FRAME.1) as usize;
    (vec![0; n], vec![0.0; n])
}
