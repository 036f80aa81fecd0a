//! The checks every model loader's target makes: the model is what `Model`'s documentation promises, and it draws.

use rastty_core::pipeline::DrawStats;
use rastty_core::target::{Rgb888, Target};
use rastty_scene::model::{COORDINATE_LIMIT, MAX_TEXTURE_SIDE, Model};
use rastty_scene::scene_file::SceneData;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer, ShadingMode};

const WIDTH: u32 = 32;
const HEIGHT: u32 = 24;

/// Whether `text` holds a control character (errors and warnings must not: they reach terminals).
pub fn has_control(text: &str) -> bool {
    text.chars().any(char::is_control)
}

/// The model is what `Model`'s documentation promises (a failure is a panic).
pub fn check_model(model: &Model) {
    let n = model.positions.len();
    assert!(n > 0, "a loaded model has no positions");
    assert!(!model.indices.is_empty(), "a loaded model has no triangles (NoTriangles expected)");
    assert_eq!(model.indices.len() % 3, 0, "indices do not form whole triangles");
    if let Some(i) = model.indices.iter().find(|&&i| i as usize >= n) {
        panic!("index {i} out of range for {n} positions");
    }
    assert_eq!(model.normals.len(), n, "normals.len() != positions.len()");
    if let Some(uvs) = &model.uvs {
        assert_eq!(uvs.len(), n, "uvs.len() != positions.len()");
        assert!(uvs.iter().all(|t| t.is_finite()), "a non-finite texture coordinate");
    }
    for p in &model.positions {
        assert!(p.is_finite(), "a non-finite position {p:?}");
        let m = p.x.abs().max(p.y.abs()).max(p.z.abs());
        assert!(m <= COORDINATE_LIMIT, "position {p:?} beyond COORDINATE_LIMIT");
    }
    assert!(model.normals.iter().all(|v| v.is_finite()), "a non-finite normal");
    if let Some(colors) = &model.colors {
        assert_eq!(colors.len(), n, "colors.len() != positions.len()");
        assert!(colors.iter().all(|c| c.is_finite()), "a non-finite colour");
    }
    if let Some(tangents) = &model.tangents {
        assert_eq!(tangents.len(), n, "tangents.len() != positions.len()");
        assert!(tangents.iter().all(|t| t.is_finite() && t.w.abs() == 1.0), "a tangent without handedness");
    }

    // Parts: contiguous, in order, covering the index buffer, whole triangles, valid materials, meshes.
    let mut next = 0;
    for (i, part) in model.parts.iter().enumerate() {
        assert_eq!(part.indices.start, next, "part {i} does not start where the previous one ended");
        assert!(part.indices.start <= part.indices.end, "part {i} has a reversed range");
        assert!(part.indices.end <= model.indices.len(), "part {i} ends past the index buffer");
        assert_eq!(part.indices.len() % 3, 0, "part {i} does not hold whole triangles");
        if let Some(m) = part.material {
            assert!(m < model.materials.len(), "part {i} uses material {m} of {}", model.materials.len());
        }
        let mesh = model.part_mesh(i).unwrap_or_else(|| panic!("part {i} gives no mesh"));
        assert_eq!(mesh.triangle_count(), part.indices.len() / 3);
        next = part.indices.end;
    }
    assert_eq!(next, model.indices.len(), "the parts do not cover the index buffer");
    assert!(model.mesh().is_some(), "the whole model gives no mesh");

    for m in &model.materials {
        assert!(m.diffuse.is_finite(), "material {:?}: non-finite diffuse", m.name);
        for t in [&m.texture, &m.normal_map, &m.glow_map].into_iter().flatten() {
            assert!(t.width >= 1 && t.height >= 1, "an empty texture");
            assert!(t.width <= MAX_TEXTURE_SIDE && t.height <= MAX_TEXTURE_SIDE, "an oversized texture");
            assert_eq!(t.texels.len(), t.width as usize * t.height as usize, "texel count");
            assert!(t.texture().is_ok(), "the core refuses a loaded texture");
        }
        assert!(m.specular.is_none_or(|s| s.is_finite()), "material {:?}: non-finite specular", m.name);
        assert!(m.shininess.is_none_or(|s| s.is_finite() && s > 0.0), "material {:?}: bad shininess", m.name);
    }
    for w in &model.warnings {
        assert!(!has_control(w), "a warning holds a control character: {w:?}");
    }
}

/// Draws `model` (named `name`) as `rastty` shows it: a scene of one object, planned and drawn by the scene
/// renderer into a small frame. `config` picks the shading mode (bits 0..3), the wireframe (bit 3), textures on/off
/// (bit 4) and an orthographic lens (bit 5). A failure is a panic.
pub fn render_once(model: Model, config: u8, name: &str) {
    let options = PlanOptions {
        shading: ShadingMode::ALL[usize::from(config & 7) % ShadingMode::ALL.len()],
        wireframe: config & 8 != 0,
        textures: config & 16 != 0,
        ..PlanOptions::default()
    };
    let camera = CameraOptions { orthographic: config & 32 != 0, ..CameraOptions::default() };
    let triangles = model.triangle_count() as u64;
    let scene = PreparedScene::new(SceneData::from_model(model, name.into()))
        .unwrap_or_else(|e| panic!("a loaded model does not prepare: {e}"));
    let camera = camera.orbit(&scene).camera;
    let plan = ScenePlan::new(&scene, &camera, (WIDTH, HEIGHT), &options)
        .unwrap_or_else(|e| panic!("a loaded model does not plan: {e}"));
    let (mut pixels, mut depth) = (vec![0u32; (WIDTH * HEIGHT) as usize], vec![0f32; (WIDTH * HEIGHT) as usize]);
    let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], WIDTH, HEIGHT).expect("a valid frame");
    let report = SceneRenderer::with_threads(1)
        .render(&scene, &plan, &mut target)
        .unwrap_or_else(|e| panic!("a loaded model does not render: {e}"));
    check_counted(&report.forward, triangles);
}

/// A frame's counts: every one of the model's `triangles` went in, and each ended in exactly one of the five
/// outcomes (a failure is a panic).
pub fn check_counted(s: &DrawStats, triangles: u64) {
    assert_eq!(s.triangles_in, triangles, "{s:?}");
    assert_eq!(s.invalid + s.outside + s.culled + s.degenerate + s.rasterized, s.triangles_in, "{s:?}");
}

/// A loader's error is one line that may reach a terminal: no control character in it (a failure is a panic).
pub fn check_load_error(e: &dyn std::fmt::Display) {
    let text = e.to_string();
    assert!(!has_control(&text), "a load error holds a control character: {text:?}");
}
