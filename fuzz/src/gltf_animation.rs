//! The `gltf_animation` target: a skinned, morphed and animated triangle whose binary buffer (positions, normals,
//! joints, weights, inverse bind matrices, morph displacements, key times and values) is the fuzzer's bytes, and
//! whose interpolations, key count and rotation component type the input's first byte chooses. It is loaded
//! (`rastty_scene::model::load_gltf_bytes`), and a model that loads is checked ([`crate::model_checks`]), prepared
//! and posed (`PreparedScene::pose`) at the input's time and at the keys' edges, before and after them and at a
//! time that is not a number, each pose drawn.
//!
//! Input layout: `[choice: u8] [render config: u8] [time: f32 LE] [buffer: the rest, zero-padded]`.

use std::path::Path;

use rastty_core::target::{Rgb888, Target};
use rastty_scene::model::{NoFiles, load_gltf_bytes};
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer};

use crate::model_checks::{check_counted, check_load_error, check_model};

/// Where each accessor's bytes start in the buffer, and the buffer's length once padded.
const POSITIONS: usize = 0;
const NORMALS: usize = 36;
const JOINTS: usize = 72;
const WEIGHTS: usize = 84;
const INVERSE_BINDS: usize = 132;
const TARGET0: usize = 260;
const TARGET1: usize = 296;
const TIMES: usize = 332;
const ROTATIONS: usize = 348;
const MORPH_WEIGHTS: usize = 540;
const TRANSLATIONS: usize = 636;
const BUFFER: usize = 780;

/// The interpolations a choice's two bits name.
const INTERPOLATIONS: [&str; 4] = ["STEP", "LINEAR", "CUBICSPLINE", "LINEAR"];

/// The rotations' component types: float, normalised bytes and shorts, signed (glTF 2.0, section 3.11).
const ROTATION_TYPES: [(u32, bool, usize); 4] = [(5126, false, 4), (5120, true, 1), (5122, true, 2), (5126, false, 4)];

/// The glTF file for `choice` over `buffer` (zero-padded to what the accessors read).
pub fn gltf(choice: u8, buffer: &[u8]) -> Vec<u8> {
    let mut bin = buffer.to_vec();
    bin.resize(bin.len().max(BUFFER), 0);
    let rotation_interpolation = INTERPOLATIONS[usize::from(choice & 3)];
    let other_interpolation = INTERPOLATIONS[usize::from((choice >> 2) & 3)];
    let keys = usize::from((choice >> 4) & 3) + 1;
    let (rotation_type, normalized, size) = ROTATION_TYPES[usize::from(choice >> 6)];
    let per_key = |interpolation: &str| if interpolation == "CUBICSPLINE" { 3 * keys } else { keys };
    let accessor = |offset: usize, component: u32, count: usize, kind: &str, normalized: bool| {
        format!(
            r#"{{"bufferView": 0, "byteOffset": {offset}, "componentType": {component}, "normalized": {normalized},
            "count": {count}, "type": "{kind}"}}"#
        )
    };
    // The format asks for a position accessor's bounds; the loader does not read them.
    let positions =
        accessor(POSITIONS, 5126, 3, "VEC3", false).replacen('}', r#", "min": [0, 0, 0], "max": [1, 1, 1]}"#, 1);
    let accessors = [
        positions,
        accessor(NORMALS, 5126, 3, "VEC3", false),
        accessor(JOINTS, 5121, 3, "VEC4", false),
        accessor(WEIGHTS, 5126, 3, "VEC4", false),
        accessor(INVERSE_BINDS, 5126, 2, "MAT4", false),
        accessor(TARGET0, 5126, 3, "VEC3", false),
        accessor(TARGET1, 5126, 3, "VEC3", false),
        accessor(TIMES, 5126, keys, "SCALAR", false),
        accessor(ROTATIONS, rotation_type, per_key(rotation_interpolation), "VEC4", normalized),
        accessor(MORPH_WEIGHTS, 5126, 2 * per_key(other_interpolation), "SCALAR", false),
        accessor(TRANSLATIONS, 5126, per_key(other_interpolation), "VEC3", false),
    ];
    debug_assert!(ROTATIONS + 3 * 4 * 4 * size <= MORPH_WEIGHTS);
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "buffers": [{{"byteLength": {}}}],
        "bufferViews": [{{"buffer": 0, "byteLength": {}}}], "accessors": [{}],
        "scene": 0, "scenes": [{{"nodes": [0, 2]}}],
        "nodes": [{{"children": [1]}}, {{"translation": [1, 0, 0]}}, {{"mesh": 0, "skin": 0}}],
        "skins": [{{"joints": [0, 1], "inverseBindMatrices": 4}}],
        "meshes": [{{"weights": [0.5, 0.25], "primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1,
            "JOINTS_0": 2, "WEIGHTS_0": 3}}, "targets": [{{"POSITION": 5}}, {{"POSITION": 6}}]}}]}}],
        "animations": [{{"name": "fuzz", "samplers": [
            {{"input": 7, "output": 8, "interpolation": "{rotation_interpolation}"}},
            {{"input": 7, "output": 9, "interpolation": "{other_interpolation}"}},
            {{"input": 7, "output": 10, "interpolation": "{other_interpolation}"}}],
            "channels": [{{"sampler": 0, "target": {{"node": 1, "path": "rotation"}}}},
                {{"sampler": 1, "target": {{"node": 2, "path": "weights"}}}},
                {{"sampler": 2, "target": {{"node": 0, "path": "translation"}}}}]}}]}}"#,
        bin.len(),
        bin.len(),
        accessors.join(", ")
    );
    crate::seeds::glb(&json, &bin)
}

/// Loads, checks, poses and draws one input (a failure is a panic). Returns whether the model loaded.
pub fn run(data: &[u8]) -> bool {
    let [choice, config, t0, t1, t2, t3, buffer @ ..] = data else { return false };
    let time = f32::from_le_bytes([*t0, *t1, *t2, *t3]);
    let name = Path::new("fuzz.glb");
    let model = match load_gltf_bytes(name, &gltf(*choice, buffer), &NoFiles) {
        Ok(model) => model,
        Err(e) => {
            check_load_error(&e);
            return false;
        }
    };
    check_model(&model);
    let (vertices, triangles) = (model.positions.len(), model.triangle_count() as u64);
    let length = model.rig.as_ref().and_then(|r| r.animations().first()).map_or(0.0, |a| a.length);
    let mut scene = PreparedScene::new(SceneData::from_model(model, name.into()))
        .unwrap_or_else(|e| panic!("a loaded model does not prepare: {e}"));
    let options = PlanOptions { wireframe: config & 1 != 0, ..PlanOptions::default() };
    let camera = CameraOptions { orthographic: config & 2 != 0, ..CameraOptions::default() }.orbit(&scene).camera;
    let mut renderer = SceneRenderer::with_threads(1);
    for t in [time, 0.0, length, length * 0.5, -1.0, length + 1.0, f32::MAX, f32::NAN] {
        scene.pose(Some(0), t).unwrap_or_else(|e| panic!("posing at {t} fails: {e}"));
        let model = &scene.data().objects[0].model;
        assert_eq!(model.positions.len(), vertices, "a pose changed the vertex count");
        assert_eq!(model.normals.len(), vertices, "a pose changed the normal count");
        // A pose may put vertices anywhere (the keys are any finite numbers): the frame must still be drawn, or
        // refused with a message, never a panic.
        let Ok(plan) = ScenePlan::new(&scene, &camera, (32, 24), &options) else { continue };
        let (mut pixels, mut depth) = (vec![0u32; 32 * 24], vec![0f32; 32 * 24]);
        let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], 32, 24).expect("a valid frame");
        if let Ok(report) = renderer.render(&scene, &plan, &mut target) {
            check_counted(&report.forward, triangles);
        }
    }
    true
}

/// An input in the layout [`run`] reads.
pub fn encode(choice: u8, config: u8, time: f32, buffer: &[u8]) -> Vec<u8> {
    let mut out = vec![choice, config];
    out.extend_from_slice(&time.to_le_bytes());
    out.extend_from_slice(buffer);
    out
}

/// The buffer of the skin the tests use: corner (2, 0, 0) on joint 1, the others on joint 0; joint 1 at (1, 0, 0)
/// turning a quarter turn about z over `keys` keys one second apart; morph displacements of 2 and 4 in z; the
/// weights' and translations' keys for `interpolation` (3 values a key for a cubic spline).
pub fn seed_buffer(keys: usize, cubic_rotations: bool, cubic_others: bool) -> Vec<u8> {
    let mut floats = vec![0f32; BUFFER / 4];
    let mut put = |offset: usize, values: &[f32]| floats[offset / 4..offset / 4 + values.len()].copy_from_slice(values);
    put(POSITIONS, &[0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    put(NORMALS, &[0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0]);
    put(WEIGHTS, &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.0]);
    let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    put(INVERSE_BINDS, &identity);
    put(INVERSE_BINDS + 64, &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0]);
    put(TARGET0, &[0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 0.0, 0.0, 2.0]);
    put(TARGET1, &[0.0, 0.0, 4.0, 0.0, 0.0, 4.0, 0.0, 0.0, 4.0]);
    let times: Vec<f32> = (0..keys).map(|k| k as f32).collect();
    put(TIMES, &times);
    let h = std::f32::consts::FRAC_1_SQRT_2;
    let mut rotations = Vec::new();
    for k in 0..keys {
        let turned = if k % 2 == 0 { [0.0, 0.0, 0.0, 1.0] } else { [0.0, 0.0, h, h] };
        if cubic_rotations {
            rotations.extend([0.0; 4]);
        }
        rotations.extend(turned);
        if cubic_rotations {
            rotations.extend([0.0; 4]);
        }
    }
    put(ROTATIONS, &rotations);
    let (mut weights, mut translations) = (Vec::new(), Vec::new());
    for k in 0..keys {
        let (w, x) = ([(k % 2) as f32, 0.0], [k as f32, 0.0, 0.0]);
        if cubic_others {
            weights.extend([0.0, 0.0]);
            translations.extend([1.0, 0.0, 0.0]);
        }
        weights.extend(w);
        translations.extend(x);
        if cubic_others {
            weights.extend([0.0, 0.0]);
            translations.extend([1.0, 0.0, 0.0]);
        }
    }
    put(MORPH_WEIGHTS, &weights);
    put(TRANSLATIONS, &translations);
    let mut bytes: Vec<u8> = floats.iter().flat_map(|v| v.to_le_bytes()).collect();
    bytes[JOINTS..JOINTS + 12].copy_from_slice(&[0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0]);
    bytes
}
