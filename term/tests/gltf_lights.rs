//! A glTF file's own lights (`KHR_lights_punctual`): read and placed by their nodes, used instead of the viewer's
//! lights, weakening with distance and within their cones as the extension says; bad values refused by name.

use std::f32::consts::{FRAC_PI_4, PI};
use std::fs;
use std::path::Path;

use rastty_core::math::Vec3;
use rastty_scene::model::{LoadError, Model, ModelLightKind, ModelOptions, load_model};
use rastty_scene::scene_file::{LightFalloff, SceneData, SceneLightKind};

use crate::common::gltf_writer::GltfWriter;
use crate::common::rastty_in as rastty;

/// A unit square in the z = 0 plane facing +z, under a root node scaled by `scale` that also holds the lights
/// given (`lights`: the members of the extension's `lights` array; `light_nodes`: nodes, each a child of the
/// root, as JSON objects).
fn lit_square(scale: f32, lights: &str, light_nodes: &[&str], required: bool) -> String {
    lit_square_moving(scale, lights, light_nodes, required, None)
}

/// [`lit_square`] with an animation "sweep" that moves the first light's node (node 2) linearly through the
/// `(time, translation)` keys given.
fn lit_square_moving(
    scale: f32,
    lights: &str,
    light_nodes: &[&str],
    required: bool,
    keys: Option<&[(f32, [f32; 3])]>,
) -> String {
    let mut w = GltfWriter::new();
    let animations = match keys {
        Some(keys) => {
            let times = w.floats(&keys.iter().map(|(t, _)| *t).collect::<Vec<_>>(), "SCALAR");
            let places = w.floats(&keys.iter().flat_map(|(_, p)| *p).collect::<Vec<_>>(), "VEC3");
            format!(
                r#", "animations": [{{"name": "sweep", "samplers": [{{"input": {times}, "output": {places}}}],
                "channels": [{{"sampler": 0, "target": {{"node": 2, "path": "translation"}}}}]}}]"#
            )
        }
        None => String::new(),
    };
    let p = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0], "VEC3");
    let n = w.floats(&[0.0, 0.0, 1.0].repeat(4), "VEC3");
    let i = w.indices(&[0, 1, 2, 0, 2, 3], 2);
    let children: Vec<String> = (0..=light_nodes.len()).map(|k| (k + 1).to_string()).collect();
    let required = if required { r#""extensionsRequired": ["KHR_lights_punctual"], "# } else { "" };
    w.embedded(&format!(
        r#"{required}"extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {{"KHR_lights_punctual": {{"lights": [{lights}]}}}},
        "scenes": [{{"nodes": [0]}}],
        "nodes": [{{"scale": [{scale}, {scale}, {scale}], "children": [{}]}}, {{"mesh": 0}}{}],
        "materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
            "roughnessFactor": 1}}}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}}}, "indices": {i},
            "material": 0}}]}}]{animations}"#,
        children.join(", "),
        light_nodes.iter().map(|node| format!(", {node}")).collect::<String>()
    ))
}

/// Loads glTF JSON text from a fresh folder.
fn load(json: &str) -> Result<Model, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("m.gltf"), json).unwrap();
    load_model(dir.path().join("m.gltf"), &ModelOptions::default())
}

/// The RGB bytes of `rastty render FILE` at 160x120.
fn picture(dir: &Path, json: &str) -> Vec<u8> {
    picture_with(dir, json, &[])
}

/// The RGB bytes of `rastty render FILE ARGS` at 160x120.
fn picture_with(dir: &Path, json: &str, args: &[&str]) -> Vec<u8> {
    fs::write(dir.join("m.gltf"), json).unwrap();
    let mut all = vec!["render", "m.gltf", "-o", "out.png", "--size", "160x120"];
    all.extend_from_slice(args);
    let output = rastty(dir, &all);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    image::open(dir.join("out.png")).expect("a PNG").to_rgb8().into_raw()
}

/// A spot half a unit above the square's point (`x`, 0.5), pointing down at it, with the given angles and
/// intensity.
fn spot_over(x: f32, inner: f32, outer: f32, intensity: f32) -> (String, String) {
    (
        format!(
            r#"{{"type": "spot", "intensity": {intensity}, "spot": {{"innerConeAngle": {inner}, "outerConeAngle": {outer}}}}}"#
        ),
        format!(r#"{{"extensions": {{"KHR_lights_punctual": {{"light": 0}}}}, "translation": [{x}, 0.5, 0.5]}}"#),
    )
}

#[test]
fn lights_are_read_and_placed_by_their_nodes() {
    let lights = r#"{"type": "point", "name": "bulb", "color": [1, 0.5, 0.25], "intensity": 8, "range": 3},
        {"type": "spot", "intensity": 2, "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.3}},
        {"type": "directional", "intensity": 3},
        {"type": "spot"}"#;
    let nodes = [
        r#"{"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0.5, 0.5, 2]}"#,
        r#"{"extensions": {"KHR_lights_punctual": {"light": 1}}, "translation": [0, 0, 1]}"#,
        // Turned a quarter about -x: its -z becomes -y, straight down.
        r#"{"extensions": {"KHR_lights_punctual": {"light": 2}}, "rotation": [-0.70710677, 0, 0, 0.70710677]}"#,
        r#"{"extensions": {"KHR_lights_punctual": {"light": 3}}}"#,
    ];
    // Required by the file, the extension is read.
    let model = load(&lit_square(2.0, lights, &nodes, true)).expect("a file with lights loads");
    assert!(model.warnings.is_empty(), "{:?}", model.warnings);
    assert_eq!(model.lights.len(), 4);
    let bulb = &model.lights[0];
    assert_eq!(
        (bulb.name.as_deref(), bulb.kind, bulb.intensity, bulb.range),
        (Some("bulb"), ModelLightKind::Point, 8.0, Some(3.0))
    );
    assert_eq!(bulb.color, Vec3::new(1.0, 0.5, 0.25));
    // Placed under the root's scale of 2; the range and intensity are the file's, as the extension says.
    assert_eq!(bulb.world.transform_point(Vec3::ZERO), Vec3::new(1.0, 1.0, 4.0));
    assert_eq!(model.lights[1].kind, ModelLightKind::Spot { inner: 0.1, outer: 0.3 });
    // A spot without its `spot` object takes the defaults: inner 0, outer pi / 4.
    assert_eq!(model.lights[3].kind, ModelLightKind::Spot { inner: 0.0, outer: FRAC_PI_4 });

    // The scene of the model alone uses them, fitted with the model, in place of the viewer's lights: the square
    // is 2 units wide, fitted to the unit sphere (a scale of 1 / sqrt(2)), so the point light's range becomes
    // 3 / sqrt(2) and its intensity 8 / 2 / pi.
    let data = SceneData::from_model(model, "m.gltf".into());
    let fit = data.objects[0].transform;
    assert_eq!(data.lights.len(), 4);
    let SceneLightKind::Point { position, falloff } = data.lights[0].kind else { panic!("a point light") };
    assert!((position - fit.transform_point(Vec3::new(1.0, 1.0, 4.0))).length() < 1e-6);
    let LightFalloff::InverseSquare { range: Some(range) } = falloff else { panic!("{falloff:?}") };
    assert!((range - 3.0 / 2f32.sqrt()).abs() < 1e-5, "{range}");
    assert!((data.lights[0].intensity - 4.0 / PI).abs() < 1e-5, "{}", data.lights[0].intensity);
    let SceneLightKind::Directional { direction } = data.lights[2].kind else { panic!("a directional light") };
    assert!((direction + Vec3::Y).length() < 1e-6, "{direction:?}");
    assert_eq!(data.lights[2].intensity, 3.0 / PI);
}

#[test]
fn light_values_the_extension_forbids_are_left_out_by_name() {
    let lights = r#"{"type": "spot", "name": "backwards", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.2}},
        {"type": "spot", "name": "too wide", "spot": {"outerConeAngle": 2}},
        {"type": "point", "name": "no reach", "range": 0},
        {"type": "point", "name": "dark\u001b[31m", "intensity": -1},
        {"type": "point", "color": [1, -1, 0]},
        {"type": "point"}"#;
    let nodes: Vec<String> =
        (0..6).map(|k| format!(r#"{{"extensions": {{"KHR_lights_punctual": {{"light": {k}}}}}}}"#)).collect();
    let nodes: Vec<&str> = nodes.iter().map(String::as_str).collect();
    let model = load(&lit_square(1.0, lights, &nodes, false)).expect("bad lights are warnings");
    assert_eq!(model.lights.len(), 1, "only the good point light is kept");
    let warnings = model.warnings.join("\n");
    for name in ["backwards", "too wide", "no reach", "light 4"] {
        assert!(
            warnings.contains(&format!("{name} has a colour, intensity, range or cone out of range")),
            "{warnings}"
        );
    }
    // A name from the file reaches messages escaped.
    assert!(!warnings.contains('\u{1b}'), "{warnings:?}");

    // A node naming a light the file does not have, and a light of no known type, refuse the file by name.
    let missing =
        lit_square(1.0, r#"{"type": "point"}"#, &[r#"{"extensions": {"KHR_lights_punctual": {"light": 3}}}"#], false);
    let e = load(&missing).unwrap_err().to_string();
    assert!(e.contains("m.gltf") && e.contains("light"), "{e}");
    let strange = lit_square(1.0, r#"{"type": "area"}"#, &[], false);
    let e = load(&strange).unwrap_err().to_string();
    assert!(e.contains("m.gltf"), "{e}");
}

#[test]
fn light_ends_exactly_at_the_cone_and_the_range_and_follows_the_inverse_square() {
    let dir = tempfile::tempdir().unwrap();
    // The same square lit by a light that sheds nothing (left out of the frame): the ambient light alone.
    let (dark, dark_node) = spot_over(0.25, 0.1, 0.4, 0.0);
    let dark = picture(dir.path(), &lit_square(1.0, &dark, &[&dark_node], false));

    // A spot over the left half lights part of the square, and nothing of the rest: every pixel it does not
    // reach is exactly the ambient-only picture's.
    let (spot, node) = spot_over(0.25, 0.1, 0.4, 0.5);
    let lit = picture(dir.path(), &lit_square(1.0, &spot, &[&node], false));
    let brighter = lit.iter().zip(&dark).filter(|(l, d)| l > d).count();
    let darker = lit.iter().zip(&dark).filter(|(l, d)| l < d).count();
    assert!(brighter > 300 && darker == 0, "{brighter} brighter, {darker} darker");
    let changed_columns: Vec<usize> = (0..lit.len()).filter(|&k| lit[k] != dark[k]).map(|k| k / 3 % 160).collect();
    let (left, right) = (changed_columns.iter().min().unwrap(), changed_columns.iter().max().unwrap());
    // The cone's foot spans x from 0.04 to 0.46 of the square: the pixels it changes are in the left half of
    // the square, which the framed view shows in the middle of the picture.
    assert!(right - left < 60, "columns {left} to {right}");

    // Turned to point away from the square (a half turn about x), the same spot reaches none of it.
    let away = r#"{"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0.25, 0.5, 0.5], "rotation": [1, 0, 0, 0]}"#;
    assert_eq!(picture(dir.path(), &lit_square(1.0, &spot, &[away], false)), dark);
    // A point light whose range ends before the square reaches none of it either.
    let short = r#"{"type": "point", "intensity": 5, "range": 0.45}"#;
    let above = r#"{"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0.5, 0.5, 0.5]}"#;
    assert_eq!(picture(dir.path(), &lit_square(1.0, short, &[above], false)), dark);
    let reaching = r#"{"type": "point", "intensity": 5, "range": 0.9}"#;
    assert_ne!(picture(dir.path(), &lit_square(1.0, reaching, &[above], false)), dark);

    // The inverse square: the file drawn ten times larger (the light ten times farther, and its range and
    // intensity, which the node's scale does not change, given ten and a hundred times larger) is the same
    // picture, to the rounding of a code.
    let near = r#"{"type": "point", "intensity": 0.3, "range": 2}"#;
    let far = r#"{"type": "point", "intensity": 30, "range": 20}"#;
    let small = picture(dir.path(), &lit_square(1.0, near, &[above], false));
    let large = picture(dir.path(), &lit_square(10.0, far, &[above], false));
    let most = small.iter().zip(&large).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
    assert!(most <= 1, "differ by up to {most}");
    assert_ne!(small, dark);
}

#[test]
fn explain_lists_the_files_lights_and_the_frames() {
    let dir = tempfile::tempdir().unwrap();
    let (spot, node) = spot_over(0.25, 0.1, 0.4, 0.5);
    fs::write(dir.path().join("m.gltf"), lit_square(1.0, &spot, &[&node], false)).unwrap();
    let output = rastty(dir.path(), &["render", "m.gltf", "--explain"]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    assert!(
        stdout.contains("lights: 1") && stdout.contains("  0: light 0, spot, colour [1, 1, 1], 0.5 candela"),
        "{stdout}"
    );
    assert!(stdout.contains("(spot at ") && stdout.contains("falling off by the inverse square"), "{stdout}");
    // The fitted light, as the frame uses it: the unit square fitted to the unit sphere is scaled by sqrt(2), so
    // its colour is 0.5 / pi times 2.
    assert!(
        stdout.contains("colour [0.318, 0.318, 0.318], falling off by the inverse square, cone 5.73 to 22.918"),
        "{stdout}"
    );
}

#[test]
fn lights_ride_on_their_animated_nodes() {
    // A spot swept from over (0.25, 0.5) at 0 s to over (0.75, 0.5) at 2 s.
    let (spot, node) = spot_over(0.25, 0.1, 0.4, 0.5);
    let keys = [(0.0, [0.25, 0.5, 0.5]), (2.0, [0.75, 0.5, 0.5])];
    let moving = lit_square_moving(1.0, &spot, &[&node], false, Some(&keys));
    let mut model = load(&moving).expect("a moving light loads");
    assert_eq!(model.lights[0].world.transform_point(Vec3::ZERO), Vec3::new(0.25, 0.5, 0.5));
    model.pose(Some(0), 1.0);
    assert_eq!(model.lights[0].world.transform_point(Vec3::ZERO), Vec3::new(0.5, 0.5, 0.5));
    model.pose(None, 0.0);
    assert_eq!(model.lights[0].world.transform_point(Vec3::ZERO), Vec3::new(0.25, 0.5, 0.5));

    // A still at a time is the picture of the light standing where the animation has it then.
    let dir = tempfile::tempdir().unwrap();
    let at_rest = picture(dir.path(), &lit_square(1.0, &spot, &[&node], false));
    let (_, there) = spot_over(0.75, 0.1, 0.4, 0.5);
    let standing_there = picture(dir.path(), &lit_square(1.0, &spot, &[&there], false));
    assert_ne!(at_rest, standing_there);
    assert_eq!(picture_with(dir.path(), &moving, &[]), at_rest, "without --time, the rest pose");
    assert_eq!(picture_with(dir.path(), &moving, &["--time", "2"]), standing_there);
    assert_eq!(picture_with(dir.path(), &moving, &["--time", "0"]), at_rest);
}
