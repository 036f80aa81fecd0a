//! glTF models that move, written by the tests (`common::gltf_writer`): a skin of two joints, a mesh of two morph
//! targets, and animations of every interpolation. Each answer is worked out by hand from the glTF 2.0
//! specification's formulas: where a joint turned a quarter turn puts a vertex, what weights of 0.5 and 0.25 add,
//! the cubic spline's value half way, and what each kind of bad data gives.

use std::fs;

use rastty_core::math::Vec3;
use rastty_scene::model::{LoadError, Model, ModelOptions, load_model};

use crate::common::gltf_writer::GltfWriter;
use crate::common::rastty_in as rastty;

const H: f32 = std::f32::consts::FRAC_1_SQRT_2;

/// An accessor of unsigned bytes, four to an element (`JOINTS_0`), normalised or not; its index.
fn bytes4(w: &mut GltfWriter, values: &[u8], normalized: bool) -> usize {
    let view = w.view(values);
    w.accessor(&format!(
        r#"{{"bufferView": {view}, "componentType": 5121, "normalized": {normalized}, "count": {}, "type": "VEC4"}}"#,
        values.len() / 4
    ))
}

/// A skin of two joints: joint 0 (node 0) at the origin, joint 1 (node 1, its child) one unit along x; a triangle
/// (node 2) with its corner (2, 0, 0) on joint 1, the normal there +y, corner (0, 0, 0) on joint 0 and corner
/// (0, 1, 0) half on each, its weights normalised bytes of 100 and 100 (200/255 in all, which loading
/// normalises). Animation "bend" turns joint 1 from nothing to a quarter turn about z in one second (`LINEAR`) at
/// key `times`. `joints` replaces the vertices' joints when given.
fn skinned(joints: Option<&[u8]>, times: &[f32]) -> String {
    let mut w = GltfWriter::new();
    let position = w.floats(&[0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0], "VEC3");
    let normal = w.floats(&[0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0], "VEC3");
    let joints = bytes4(&mut w, joints.unwrap_or(&[0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0]), false);
    let weights = bytes4(&mut w, &[255, 0, 0, 0, 255, 0, 0, 0, 100, 100, 0, 0], true);
    let inverse_binds: Vec<f32> = [
        [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0],
    ]
    .concat();
    let bytes: Vec<u8> = inverse_binds.iter().flat_map(|v| v.to_le_bytes()).collect();
    let view = w.view(&bytes);
    let ibm = w.accessor(&format!(r#"{{"bufferView": {view}, "componentType": 5126, "count": 2, "type": "MAT4"}}"#));
    let input = w.floats(times, "SCALAR");
    let output = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, H, H], "VEC4");
    w.embedded(&format!(
        r#""scene": 0, "scenes": [{{"nodes": [0, 2]}}],
        "nodes": [{{"name": "root", "children": [1]}}, {{"name": "bone", "translation": [1, 0, 0]}},
                  {{"mesh": 0, "skin": 0}}],
        "skins": [{{"name": "arm", "joints": [0, 1], "inverseBindMatrices": {ibm}}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {position}, "NORMAL": {normal},
            "JOINTS_0": {joints}, "WEIGHTS_0": {weights}}}}}]}}],
        "animations": [{{"name": "bend", "samplers": [{{"input": {input}, "output": {output}}}],
            "channels": [{{"sampler": 0, "target": {{"node": 1, "path": "rotation"}}}}]}}]"#
    ))
}

/// A triangle with two morph targets, +2 and +4 in z everywhere, at default weights 0.5 and 0.25, on a node whose
/// translation animation "pulse" follows a cubic spline (x: 1 at 0 s, 3 at 2 s, out-tangent 2, in-tangent -1) and
/// whose weights step from (0, 0) at 0 s to (1, 0) at 1 s.
fn morphed() -> String {
    let mut w = GltfWriter::new();
    let position = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0], "VEC3");
    let normal = w.floats(&[0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0], "VEC3");
    let up2 = w.floats(&[0.0, 0.0, 2.0, 0.0, 0.0, 2.0, 0.0, 0.0, 2.0], "VEC3");
    let up4 = w.floats(&[0.0, 0.0, 4.0, 0.0, 0.0, 4.0, 0.0, 0.0, 4.0], "VEC3");
    let spline_times = w.floats(&[0.0, 2.0], "SCALAR");
    let spline =
        w.floats(&[9.0, 9.0, 9.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.0, -1.0, 0.0, 0.0, 3.0, 0.0, 0.0, 9.0, 9.0, 9.0], "VEC3");
    let step_times = w.floats(&[0.0, 1.0], "SCALAR");
    let step = w.floats(&[0.0, 0.0, 1.0, 0.0], "SCALAR");
    w.embedded(&format!(
        r#""scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
        "meshes": [{{"weights": [0.5, 0.25], "primitives": [{{"attributes": {{"POSITION": {position},
            "NORMAL": {normal}}}, "targets": [{{"POSITION": {up2}}}, {{"POSITION": {up4}}}]}}]}}],
        "animations": [{{"name": "pulse", "samplers": [
            {{"input": {spline_times}, "output": {spline}, "interpolation": "CUBICSPLINE"}},
            {{"input": {step_times}, "output": {step}, "interpolation": "STEP"}}],
            "channels": [{{"sampler": 0, "target": {{"node": 0, "path": "translation"}}}},
                         {{"sampler": 1, "target": {{"node": 0, "path": "weights"}}}}]}}]"#
    ))
}

/// Loads glTF JSON text from a fresh folder.
fn load(json: &str) -> Result<Model, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("m.gltf"), json).unwrap();
    load_model(dir.path().join("m.gltf"), &ModelOptions::default())
}

/// Poses `model` at `time` of its animation named `name` (else numbered so; its first when `None`).
fn pose(model: &mut Model, name: Option<&str>, time: f32) {
    let rig = model.rig.clone().expect("a rig");
    let animation = name.map_or(Some(0), |n| rig.find(n));
    assert!(animation.is_some(), "no animation {name:?}");
    model.pose(animation, time);
}

fn near(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-6
}

#[test]
fn a_joint_turned_a_quarter_turn_carries_its_vertex_there() {
    let mut model = load(&skinned(None, &[0.0, 1.0])).expect("the skinned triangle loads");
    assert!(model.warnings.is_empty(), "{:?}", model.warnings);
    // At rest the joints stand where they were bound: the file's positions (corner 2 too: its weights were
    // normalised to 0.5 and 0.5; as given, 200/255 in all, it would lie at (0, 0.78, 0)).
    assert_eq!(model.positions, [Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::Y]);
    let rig = model.rig.clone().expect("a rig");
    assert_eq!(rig.animations().len(), 1);
    assert_eq!((rig.animations()[0].name.as_deref(), rig.animations()[0].length), (Some("bend"), 1.0));
    assert_eq!(rig.find("bend"), Some(0));
    pose(&mut model, None, 1.0);
    // The bone, one unit long from (1, 0, 0), now points along +y: (1, 1, 0); the normal +y turns to -x; the
    // corner on joint 0 stays. Corner 2 is half where joint 0 leaves it, (0, 1, 0), and half where joint 1 takes
    // it, (1, 0, 0) + the quarter turn of (-1, 1, 0) = (0, -1, 0): the origin.
    assert!(near(model.positions[1], Vec3::new(1.0, 1.0, 0.0)), "{:?}", model.positions[1]);
    assert!(near(model.normals[1], Vec3::new(-1.0, 0.0, 0.0)), "{:?}", model.normals[1]);
    assert_eq!(model.positions[0], Vec3::ZERO);
    assert!(near(model.positions[2], Vec3::ZERO), "{:?}", model.positions[2]);
    // Half way, an eighth of a turn (spherical interpolation at constant speed).
    pose(&mut model, Some("bend"), 0.5);
    assert!(near(model.positions[1], Vec3::new(1.0 + H, H, 0.0)), "{:?}", model.positions[1]);
    // Before the first key and after the last, the keys' own poses; by number as well as by name.
    pose(&mut model, Some("0"), -3.0);
    assert!(near(model.positions[1], Vec3::new(2.0, 0.0, 0.0)));
    pose(&mut model, Some("0"), 30.0);
    assert!(near(model.positions[1], Vec3::new(1.0, 1.0, 0.0)));
    // The rest pose again.
    model.pose(None, 0.0);
    assert_eq!(model.positions[1], Vec3::new(2.0, 0.0, 0.0));
    assert_eq!((rig.find("walk"), rig.find("1")), (None, None));
}

#[test]
fn a_skinned_mesh_without_normals_keeps_flat_normals_as_it_moves() {
    let json = skinned(None, &[0.0, 1.0]);
    let at = json.find(r#""NORMAL": "#).unwrap();
    let end = at + json[at..].find(',').unwrap() + 1;
    let mut model = load(&format!("{}{}", &json[..at], &json[end..])).expect("loads without normals");
    // Each corner its own vertex, with its face's normal: (2, 0, 0) x (0, 1, 0) = +z at rest.
    assert_eq!(model.normals, [Vec3::Z; 3]);
    pose(&mut model, Some("bend"), 0.5);
    assert!(near(model.positions[1], Vec3::new(1.0 + H, H, 0.0)), "{:?}", model.positions[1]);
    let [a, b, c] = [model.positions[0], model.positions[1], model.positions[2]];
    assert!(near(model.normals[0], (b - a).cross(c - a).normalize_or_zero()));
}

#[test]
fn morph_weights_default_to_the_mesh_and_animations_step_and_spline() {
    let mut model = load(&morphed()).expect("the morphed triangle loads");
    // Weights 0.5 and 0.25 of +2 and +4 in z: +2.
    assert_eq!(model.positions, [Vec3::new(0.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 2.0), Vec3::new(0.0, 1.0, 2.0)]);
    // At 1 s: the weights have stepped to (1, 0), +2 in z; the spline is half way, x = 2.75
    // (0.5 * 1 + 0.25 * 2 + 0.5 * 3 - 0.25 * -1).
    pose(&mut model, None, 1.0);
    assert_eq!(model.positions[0], Vec3::new(2.75, 0.0, 2.0));
    // Just before 1 s the step still holds (0, 0).
    pose(&mut model, None, 0.999);
    assert_eq!(model.positions[0].z, 0.0);
    // At 0.5 s (u = 0.25): x = 1.96875; at the end, 3.
    pose(&mut model, Some("pulse"), 0.5);
    assert_eq!(model.positions[0], Vec3::new(1.968_75, 0.0, 0.0));
    pose(&mut model, Some("pulse"), 2.0);
    assert_eq!(model.positions[0], Vec3::new(3.0, 0.0, 2.0));
}

#[test]
fn bad_animation_data_is_an_error_or_a_warning_that_names_it() {
    // A joint beyond the skin's two, with a weight: an error naming the vertex and the joint.
    let e = load(&skinned(Some(&[0, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 0]), &[0.0, 1.0])).unwrap_err().to_string();
    assert!(e.contains("m.gltf") && e.contains("vertex 1") && e.contains("beyond the skin's 2 joints"), "{e}");
    // Key times that do not increase: the channel is left out with a warning, the model still loads.
    let model = load(&skinned(None, &[1.0, 0.5])).expect("loads without the bad channel");
    assert!(model.warnings.iter().any(|w| w.contains("bend") && w.contains("key 1") && w.contains("left out")));
    assert_eq!(model.rig.as_ref().unwrap().animations()[0].length, 0.0);
    // A cycle of nodes in a file with a skin.
    let cycle = skinned(None, &[0.0, 1.0]).replacen(
        r#"{"name": "bone", "translation": [1, 0, 0]}"#,
        r#"{"name": "bone", "translation": [1, 0, 0], "children": [0]}"#,
        1,
    );
    let e = load(&cycle).unwrap_err().to_string();
    assert!(e.contains("cycle") || e.contains("two parents"), "{e}");
    // Joints for fewer vertices than there are.
    let e = load(&skinned(Some(&[0; 8]), &[0.0, 1.0])).unwrap_err().to_string();
    assert!(e.contains("JOINTS_0 has 2 and WEIGHTS_0 3 entries for 3 positions"), "{e}");
}

#[test]
fn render_draws_the_moment_asked_for_and_explain_lists_the_animations() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("arm.gltf"), skinned(None, &[0.0, 1.0])).unwrap();
    let picture = |args: &[&str]| {
        let mut all = vec!["render", "arm.gltf", "-o", "out.png", "--size", "96x72"];
        all.extend_from_slice(args);
        let output = rastty(dir.path(), &all);
        assert!(output.status.success(), "{all:?}: {}", String::from_utf8_lossy(&output.stderr));
        fs::read(dir.path().join("out.png")).unwrap()
    };
    let rest = picture(&[]);
    let bent = picture(&["--time", "1"]);
    assert_ne!(rest, bent, "a quarter turn of the bone shows");
    assert_eq!(picture(&["--time", "0"]), rest, "time 0 is the first key, the bind pose");
    assert_eq!(picture(&["--time", "1", "--animation", "bend"]), bent);
    assert_eq!(picture(&["--time", "5", "--animation", "0"]), bent, "after the last key, the last");

    let output = rastty(dir.path(), &["render", "arm.gltf", "-o", "x.png", "--time", "1", "--animation", "walk"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("arm.gltf") && stderr.contains("no animation walk") && stderr.contains("0: bend"),
        "{stderr}"
    );

    let output = rastty(dir.path(), &["render", "arm.gltf", "--explain"]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success());
    for line in
        ["animations: 1", "  0: bend, 1 s, 1 channel", "    node 1 rotation: linear, 2 keys", "  0: arm, 2 joints"]
    {
        assert!(stdout.lines().any(|l| l == line), "{line:?} not in\n{stdout}");
    }
    // A model that does not move: a warning, and its rest picture.
    let output = rastty(dir.path(), &["render", "-o", "spot.png", "--size", "32x24", "--time", "1"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success() && stderr.contains("moves: --time leaves it at rest"), "{stderr}");
}

/// The animation line of the viewer's HUD on `screen`, if it shows one.
fn animation_line(screen: &str) -> Option<String> {
    let at = screen.find("animation 1/1")?;
    Some(screen[at..].lines().next()?.trim_end().trim_end_matches('│').trim_end().to_owned())
}

#[test]
fn the_viewer_plays_the_animation_and_its_keys_pause_and_speed_it() {
    use crate::common::tmux::{Tmux, tmux_wanted};
    if !tmux_wanted() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("arm.gltf");
    fs::write(&file, skinned(None, &[0.0, 1.0])).unwrap();
    let tmux = Tmux::start_with("animation", 100, 32, &[&file]);
    // Not a steady picture: it moves.
    tmux.wait_for("a picture", || tmux.screen().contains('▀').then_some(()));
    tmux.send_keys("i");
    let first = tmux.wait_for("the HUD's animation line", || animation_line(&tmux.screen()));
    assert!(first.contains("bend") && first.contains("/ 1.00 s") && first.contains("1x"), "{first}");
    let playing =
        tmux.wait_for("the animation's time to move", || animation_line(&tmux.screen()).filter(|line| *line != first));
    assert!(!playing.contains("paused"), "{playing}");
    tmux.send_keys("o");
    let paused = tmux.wait_for("the pause", || animation_line(&tmux.screen()).filter(|l| l.contains("paused")));
    std::thread::sleep(std::time::Duration::from_millis(300));
    let time = |line: &str| line.split("   ").nth(1).map(str::to_owned);
    assert_eq!(time(&animation_line(&tmux.screen()).unwrap()), time(&paused), "paused, the time stays");
    tmux.send_keys(">");
    tmux.wait_for("twice the speed", || animation_line(&tmux.screen()).filter(|l| l.contains("2x   paused")));
    tmux.send_keys("q");
    let (status, tty_same) = tmux.wait_for_exit();
    assert_eq!(status, 0);
    tmux.assert_restored(tty_same);
}

#[test]
fn an_animated_turntable_records_the_stills_of_its_times() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("arm.gltf"), skinned(None, &[0.0, 1.0])).unwrap();
    let view = ["--size", "64x48", "--yaw", "30"];
    let mut args = vec!["render", "arm.gltf", "--turntable", "4", "--animate", "-o", "f-#.png", "--stats"];
    args.extend_from_slice(&view);
    let output = rastty(dir.path(), &args);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    assert!(stdout.contains("frame 1 (time 0.25 s): render"), "{stdout}");
    let rgb = |file: &str| image::open(dir.path().join(file)).expect("a PNG").to_rgb8().into_raw();
    let mut frames = Vec::new();
    for k in 0..4 {
        let time = format!("{}", f64::from(k) * 0.25);
        let mut still = vec!["render", "arm.gltf", "-o", "still.png", "--time", &time];
        still.extend_from_slice(&view);
        assert!(rastty(dir.path(), &still).status.success());
        let frame = rgb(&format!("f-{k}.png"));
        assert_eq!(frame, rgb("still.png"), "frame {k} is the still at {time} s");
        frames.push(frame);
    }
    assert_ne!(frames[0], frames[2], "the bone moves");

    // Nothing to record, and --time with --animate: errors that say so.
    let output = rastty(dir.path(), &["render", "--turntable", "2", "--animate", "-o", "spot.gif"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("nothing in built-in Spot moves"), "{stderr}");
    let output =
        rastty(dir.path(), &["render", "arm.gltf", "--turntable", "2", "--animate", "--time", "1", "-o", "a.gif"]);
    assert_eq!(output.status.code(), Some(2), "{}", String::from_utf8_lossy(&output.stderr));
}

#[test]
fn a_scene_file_names_an_animation_and_a_start_time_per_object() {
    use rastty_scene::scene_file::load as load_scene;
    use rastty_scene::scene_render::PreparedScene;
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("arm.gltf"), skinned(None, &[0.0, 1.0])).unwrap();
    let scene = |own: &str| {
        let text = format!(
            "[[objects]]\nmesh = \"arm.gltf\"\n{own}\n[[objects]]\nmesh = \"arm.gltf\"\ntranslate = [0, 0, 3]\n"
        );
        fs::write(dir.path().join("s.toml"), text).unwrap();
        load_scene(dir.path().join("s.toml"))
    };
    // The first object stands where its animation is at 1 s, the second at rest.
    let data = scene("animation = \"bend\"\ntime = 1").expect("the scene loads");
    assert!(near(data.objects[0].model.positions[1], Vec3::new(1.0, 1.0, 0.0)));
    assert_eq!(data.objects[1].model.positions[1], Vec3::new(2.0, 0.0, 0.0));
    // On the scene's clock, the first runs from its start: at -0.5 s it is half way; the second, at -0.5 s of the
    // chosen animation, holds its first key.
    let mut prepared = PreparedScene::new(data).unwrap();
    prepared.pose(Some(0), -0.5).unwrap();
    let objects = &prepared.data().objects;
    assert!(near(objects[0].model.positions[1], Vec3::new(1.0 + H, H, 0.0)), "{:?}", objects[0].model.positions[1]);
    assert!(near(objects[1].model.positions[1], Vec3::new(2.0, 0.0, 0.0)));

    let e = scene("animation = 3").unwrap_err().to_string();
    assert!(e.contains("s.toml:3") && e.contains("objects[0].animation") && e.contains("0: bend"), "{e}");
    let e = scene("time = 1").unwrap_err().to_string();
    assert!(e.contains("objects[0].time") && e.contains("needs `animation`"), "{e}");
}

/// A skin of `joints` joints (nodes 1 to `joints`, children of node 0, none moved) over a triangle whose corners
/// hang on the first and last joints.
fn many_joints(joints: usize) -> String {
    let mut w = GltfWriter::new();
    let position = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0], "VEC3");
    let last = (joints - 1) as u16;
    let bytes: Vec<u8> =
        [[0u16, 0, 0, 0], [last, 0, 0, 0], [last, 0, 0, 0]].iter().flatten().flat_map(|j| j.to_le_bytes()).collect();
    let view = w.view(&bytes);
    let joint_sets =
        w.accessor(&format!(r#"{{"bufferView": {view}, "componentType": 5123, "count": 3, "type": "VEC4"}}"#));
    let weights = w.floats(&[1.0, 0.0, 0.0, 0.0].repeat(3), "VEC4");
    let children: Vec<String> = (1..=joints).map(|n| n.to_string()).collect();
    let nodes: Vec<&str> = vec!["{}"; joints];
    w.embedded(&format!(
        r#""scenes": [{{"nodes": [0, {mesh_node}]}}],
        "nodes": [{{"children": [{children}]}}, {nodes}, {{"mesh": 0, "skin": 0}}],
        "skins": [{{"joints": [{children}]}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {position}, "JOINTS_0": {joint_sets},
            "WEIGHTS_0": {weights}}}}}]}}]"#,
        mesh_node = joints + 1,
        children = children.join(", "),
        nodes = nodes.join(", "),
    ))
}

#[test]
fn a_skin_of_thousands_of_joints_loads_and_one_beyond_the_indices_is_refused() {
    let model = load(&many_joints(5_000)).expect("5,000 joints load");
    assert_eq!(model.rig.as_ref().unwrap().skins().next(), Some((None, 5_000)));
    assert_eq!(model.positions, [Vec3::ZERO, Vec3::X, Vec3::Y], "joints at rest without inverse binds: in place");
    let e = load(&many_joints(70_000)).unwrap_err().to_string();
    assert!(e.contains("skin 0: 70000 joints, more than the 65535 read"), "{e}");
}
