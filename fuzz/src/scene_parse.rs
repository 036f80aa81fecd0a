//! The `scene_parse` target: arbitrary bytes as a scene file, through `rastty_scene::scene_file::parse` (TOML, the schema
//! and every range check). A scene that parses and names no file (its meshes built in, no images) is loaded,
//! prepared, planned and drawn once into a small frame; scenes that name files are not loaded, so that a run does not
//! depend on the machine's files.

use rastty_core::target::{Rgb888, Target};
use rastty_scene::scene_file::parse;
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer};

use crate::model_checks::has_control;

const WIDTH: u32 = 24;
const HEIGHT: u32 = 16;

/// Parses (and, when it names no file, draws) one input; a failure is a panic. Returns whether it parsed.
pub fn run(data: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(data) else { return false };
    let file = match parse(text, "fuzz.toml") {
        Ok(file) => file,
        Err(e) => {
            let message = e.to_string();
            assert!(message.starts_with("fuzz.toml"), "an error that does not name the file: {message:?}");
            assert!(!has_control(&message), "an error holds a control character: {message:?}");
            return false;
        }
    };
    let spec = &file.spec;
    let names_files = spec.objects.get_ref().iter().any(|o| {
        let o = o.get_ref();
        let m = &o.material;
        !o.mesh.get_ref().starts_with("builtin:")
            || [&m.diffuse, &m.normal_map, &m.specular_map, &m.glow_map].iter().any(|image| image.is_some())
    });
    if names_files {
        return true;
    }
    let data = file.load().unwrap_or_else(|e| panic!("a scene of built-in meshes does not load: {e}"));
    // A scene may be refused when planned (a shadow-casting point light inside it): that is its contract.
    let Ok(scene) = PreparedScene::new(data) else { return true };
    let camera = CameraOptions::default().orbit(&scene).camera;
    let Ok(plan) = ScenePlan::new(&scene, &camera, (WIDTH, HEIGHT), &PlanOptions::default()) else { return true };
    let (mut pixels, mut depth) = (vec![0u32; (WIDTH * HEIGHT) as usize], vec![0f32; (WIDTH * HEIGHT) as usize]);
    let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], WIDTH, HEIGHT).expect("a valid frame");
    SceneRenderer::with_threads(1)
        .render(&scene, &plan, &mut target)
        .unwrap_or_else(|e| panic!("does not render: {e}"));
    true
}
