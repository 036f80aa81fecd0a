//! Scene files: the shipped example scenes and the docs' scenes load; every kind of error names the file, line,
//! column and key exactly; paths resolve from the scene file's directory; a file named twice loads once; the
//! transform follows the documented order. Also the recipe of the project-made assets of `assets/scenes/`.

use crate::common;

use common::{root, scenes_in};
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rastty_core::math::{Mat4, Vec3};
use rastty_core::texture::{Anisotropy, FilterMode, MipFilter, WrapMode};
use rastty_scene::model::TextureImage;
use rastty_scene::scene_file::{
    CameraPlacement, FramedCamera, LightFalloff, LightSpace, NormalSpaceSpec, SceneCamera, SceneData, SceneFileError,
    SceneFileErrorKind, SceneLightKind, SceneProjection, defaults, load, object_transform, parse,
};

// ---------------------------------------------------------------------------------------------------------------
// Helpers

/// The scene's camera, which must be placed by the file.
fn placed(scene: &SceneData) -> SceneCamera {
    match scene.camera {
        CameraPlacement::Placed(camera) => camera,
        CameraPlacement::Framed(framed) => panic!("a framed camera: {framed:?}"),
    }
}

/// A temporary directory holding the given files.
fn dir_with(files: &[(&str, &[u8])]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in files {
        let path = dir.path().join(name);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, bytes).unwrap();
    }
    dir
}

/// A 2x2 PNG.
fn png_bytes() -> Vec<u8> {
    encode_png(2, 2, png::ColorType::Rgb, &[255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255])
}

fn encode_png(width: u32, height: u32, color: png::ColorType, data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(color);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(data).unwrap();
    writer.finish().unwrap();
    out
}

/// A one-triangle OBJ with texture coordinates.
const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";

/// The error message for scene text, parsed as `scene.toml`.
fn error(text: &str) -> String {
    match parse(text, "scene.toml") {
        Ok(_) => panic!("the scene should be refused:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// Lines 1 to 4 of most scenes below.
const CAMERA: &str = "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = 40\n";
/// One object, two lines.
const SPOT: &str = "[[objects]]\nmesh = \"builtin:spot\"\n";

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-5
}

// ---------------------------------------------------------------------------------------------------------------
// The shipped scenes

#[test]
fn every_example_scene_loads() {
    let scenes = scenes_in(&root().join("assets/scenes"));
    assert!(scenes.len() >= 2, "{scenes:?}");
    for path in &scenes {
        let scene = load(path).unwrap_or_else(|e| panic!("{e}"));
        assert!(!scene.objects.is_empty());
        assert!(scene.warnings.is_empty(), "{}: {:?}", path.display(), scene.warnings);
        for object in &scene.objects {
            assert!(object.model.triangle_count() > 0);
            assert!(object.model.warnings.is_empty(), "{:?}", object.model.warnings);
            assert!(object.transform.is_finite());
        }
        if let CameraPlacement::Placed(camera) = scene.camera {
            assert!(camera.view().unwrap().is_finite());
        }
    }
}

#[test]
fn the_example_scenes_show_what_they_say() {
    let dir = root().join("assets/scenes");
    let sun = load(dir.join("spot_sun.toml")).unwrap();
    assert!(matches!(placed(&sun).projection, SceneProjection::Perspective { .. }));
    assert!(sun.lights.iter().any(|l| l.shadows && matches!(l.kind, SceneLightKind::Directional { .. })));
    assert!(!sun.ambient_occlusion);

    let lamp = load(dir.join("spot_lamp.toml")).unwrap();
    assert!(lamp.ambient_occlusion);
    assert!(lamp.lights.iter().any(|l| l.shadows && matches!(l.kind, SceneLightKind::Point { .. })));
    let ground = &lamp.objects.iter().find(|o| o.mesh_path.ends_with("ground.obj")).unwrap().material;
    assert!(ground.diffuse.is_some() && ground.specular_map.is_some() && ground.glow_map.is_some());
    assert_eq!(ground.normal_map.as_ref().unwrap().space, NormalSpaceSpec::Tangent);

    let herd = load(dir.join("spot_herd.toml")).unwrap();
    assert!(matches!(placed(&herd).projection, SceneProjection::Orthographic { .. }));
    // Three cows from one OBJ file, loaded once; the texture named by two of them, loaded once.
    let cows: Vec<_> = herd.objects.iter().filter(|o| o.mesh_path.ends_with("spot.obj")).collect();
    assert_eq!(cows.len(), 3);
    assert!(cows.windows(2).all(|w| Arc::ptr_eq(&w[0].model, &w[1].model)));
    let textures: Vec<_> = cows.iter().filter_map(|c| c.material.diffuse.as_ref()).collect();
    assert_eq!(textures.len(), 2);
    assert!(Arc::ptr_eq(textures[0], textures[1]));
}

/// The tinyrenderer models live outside the repository, in `../shared/models/tinyrenderer/` (not an open licence:
/// never copied into the project). Their scenes are in `docs/scenes/`.
#[test]
fn the_docs_scenes_load_the_tinyrenderer_models() {
    let models = root().join("../shared/models/tinyrenderer");
    if !models.is_dir() {
        println!("skipped: {} is absent, so the docs' scenes cannot load their models", models.display());
        return;
    }
    let scenes = scenes_in(&root().join("docs/scenes"));
    let names: Vec<_> = scenes.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
    assert_eq!(names, ["african_head.toml", "diablo3_pose.toml"]);
    let [head, diablo] = [&scenes[0], &scenes[1]].map(|path| {
        let scene = load(path).unwrap_or_else(|e| panic!("{e}"));
        assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
        assert!(scene.lights.iter().any(|l| l.shadows));
        for object in &scene.objects {
            let m = &object.material;
            assert!(m.diffuse.is_some() && m.specular_map.is_some(), "{}", object.mesh_path.display());
            assert_eq!(m.normal_map.as_ref().map(|n| n.space), Some(NormalSpaceSpec::Tangent));
            assert!(object.mesh_path.starts_with(path.parent().unwrap()));
        }
        scene
    });
    assert_eq!(head.objects.len(), 2, "the head and the eyes (the inner layer; the clear outer one is left out)");
    // The head's specular map is 8-bit grey: its level arrives in all three channels.
    let spec = head.objects[0].material.specular_map.as_ref().unwrap();
    assert!(spec.texels.iter().all(|&t| t >> 16 == t & 0xFF && (t >> 8) & 0xFF == t & 0xFF));
    let glow = diablo.objects[0].material.glow_map.as_ref().expect("diablo's glow map");
    assert_eq!((glow.width, glow.height), (1024, 1024));
}

// ---------------------------------------------------------------------------------------------------------------
// Errors: each names the file, line, column and key

#[test]
fn the_format_documents_example_parses_with_every_key() {
    let doc = fs::read_to_string(root().join("docs/scene-format.md")).unwrap();
    let example = doc.split("```toml\n").nth(1).and_then(|rest| rest.split("```").next()).expect("a toml example");
    let parsed = rastty_scene::scene_file::parse(example, "scene-format.md");
    assert!(parsed.is_ok(), "{}", parsed.unwrap_err());
    // Every key of the table appears in the example.
    let table_keys = doc.lines().filter_map(|l| l.strip_prefix("| `")).filter_map(|l| l.split('`').next());
    for key in table_keys {
        let leaf = key.rsplit(['.', ']']).next().unwrap();
        assert!(example.contains(&format!("{leaf} =")), "`{key}` is in the table but not in the example");
    }
}

#[test]
fn toml_syntax_errors_name_the_line_and_the_key_being_written() {
    assert_eq!(
        error("[camera]\nposition = [0, 1, 4]\nfov = \n"),
        "scene.toml:3:7: camera.fov: TOML syntax error: string values must be quoted, expected literal string"
    );
    assert_eq!(error(&format!("{CAMERA}{SPOT}[camera]\n")), "scene.toml:7:2: camera: TOML syntax error: duplicate key");
}

#[test]
fn unknown_keys_are_named_with_their_table() {
    assert_eq!(
        error(&format!("backgruond = \"000000\"\n{CAMERA}{SPOT}")),
        "scene.toml:1:1: backgruond: unknown key, expected one of `background`, `ambient`, `environment`, `ambient_occlusion`, \
         `linear_light`, `camera`, `lights`, `viewer_lights`, `objects`"
    );
    assert_eq!(
        error(&format!("{CAMERA}fvo = 30\n{SPOT}")),
        "scene.toml:5:1: camera.fvo: unknown key, expected one of `position`, `target`, `yaw`, `pitch`, \
         `distance`, `up`, `fov`, `orthographic`, `near`, `far`"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}{SPOT}[objects.material]\ncolour = [1, 0, 0]\n")),
        "scene.toml:10:1: objects[1].material.colour: unknown key, expected one of `color`, `diffuse`, \
         `normal_map`, `normal_space`, `specular`, `shininess`, `metallic`, `roughness`, `specular_map`, \
         `glow_map`, `filter`, `wrap`, `mipmaps`"
    );
    // A key holding control characters is escaped in the message.
    let text = error(&format!("{CAMERA}{SPOT}\"evil\\u001b[2J\" = 1\n"));
    assert!(!text.chars().any(char::is_control), "{text:?}");
    assert!(text.starts_with("scene.toml:7:1: objects[0].\"evil\\u{1b}[2J\": unknown key"), "{text}");
}

#[test]
fn wrong_types_name_the_value() {
    assert_eq!(
        error("[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = \"wide\"\n"),
        "scene.toml:4:7: camera.fov: invalid type: string \"wide\", expected a number"
    );
    assert_eq!(
        error("[camera]\nposition = [0, 1]\n"),
        "scene.toml:2:12: camera.position: invalid length 2, expected an array of length 3"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}scale = [1, \"x\", 1]\n")),
        "scene.toml:7:13: objects[0].scale: invalid type: string \"x\", expected a number"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}scale = true\n")),
        "scene.toml:7:9: objects[0].scale: invalid type: boolean `true`, expected a number or an array of three \
         numbers"
    );
    assert_eq!(
        error(&format!("{CAMERA}[[lights]]\ntype = \"area\"\n{SPOT}")),
        "scene.toml:6:8: lights[0].type: unknown variant `area`, expected one of `directional`, `point`, `spot`"
    );
    assert_eq!(
        error(&format!("{CAMERA}[[lights]]\ntype = \"point\"\nposition = [0, 1, 0]\nshadows = \"yes\"\n{SPOT}")),
        "scene.toml:8:11: lights[0].shadows: invalid type: string \"yes\", expected a boolean"
    );
    assert_eq!(
        error(&format!("{CAMERA}[objects]\nmesh = \"builtin:spot\"\n")),
        "scene.toml:5:1: objects: invalid type: table, expected an array"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}material = \"shiny\"\n")),
        "scene.toml:7:12: objects[0].material: invalid type: string \"shiny\", expected a table of material keys"
    );
    assert_eq!(
        error(&format!("lights = [3]\n{CAMERA}{SPOT}")),
        "scene.toml:1:11: lights: invalid type: integer `3`, expected a table of light keys"
    );
    assert_eq!(
        error(&format!("background = [1]\n{CAMERA}{SPOT}")),
        "scene.toml:1:14: background: invalid type: array, expected a string"
    );
    assert_eq!(
        error(&format!("camera = 3\n{SPOT}")),
        "scene.toml:1:10: camera: invalid type: integer `3`, expected a table of camera keys"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}[objects.material]\nnormal_space = \"world\"\n")),
        "scene.toml:8:16: objects[0].material.normal_space: unknown variant `world`, expected `tangent` or `object`"
    );
}

#[test]
fn missing_keys_are_named_at_their_table() {
    assert_eq!(
        error(&format!("[camera]\nposition = [0, 1, 4]\nfov = 40\n{SPOT}")),
        "scene.toml:1:1: camera.target: required with camera.position (or leave both out to frame the scene)"
    );
    assert_eq!(
        error(&format!("[camera]\ntarget = [0, 1, 4]\n{SPOT}")),
        "scene.toml:1:1: camera.position: required with camera.target (or leave both out to frame the scene)"
    );
    assert_eq!(
        error(&format!("{CAMERA}{SPOT}[[objects]]\nscale = 2\n")),
        "scene.toml:7:1: objects[1].mesh: required, but missing"
    );
    assert_eq!(error(""), "scene.toml:1:1: objects: required, but missing");
    assert_eq!(error(CAMERA), "scene.toml:1:1: objects: required, but missing");
    assert_eq!(
        error(&format!("{CAMERA}[[lights]]\ndirection = [0, -1, 0]\n{SPOT}")),
        "scene.toml:5:1: lights[0].type: required, but missing"
    );
}

#[test]
fn invalid_camera_values_name_the_value() {
    let camera = |lines: &str| error(&format!("[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\n{lines}{SPOT}"));
    assert_eq!(camera("fov = 200\n"), "scene.toml:4:7: camera.fov: must be between 0 and 180 degrees, got 200");
    assert_eq!(camera("fov = 0\n"), "scene.toml:4:7: camera.fov: must be between 0 and 180 degrees, got 0");
    assert_eq!(camera("fov = nan\n"), "scene.toml:4:7: camera.fov: must be between 0 and 180 degrees, got NaN");
    assert_eq!(
        camera("fov = 40\northographic = 3\n"),
        "scene.toml:5:16: camera.orthographic: cannot be given with camera.fov: choose a perspective (fov) or an \
         orthographic lens"
    );
    assert_eq!(
        camera("orthographic = -2\n"),
        "scene.toml:4:16: camera.orthographic: must be positive (the height shown across the frame's shorter side), \
         got -2"
    );
    assert_eq!(
        camera("yaw = 10\n"),
        "scene.toml:4:7: camera.yaw: frames the scene, so it cannot be given with camera.position and camera.target"
    );
    let framed = |lines: &str| error(&format!("[camera]\n{lines}{SPOT}"));
    assert_eq!(framed("pitch = 90\n"), "scene.toml:2:9: camera.pitch: must be between -90 and 90 degrees, got 90");
    assert_eq!(framed("yaw = inf\n"), "scene.toml:2:7: camera.yaw: must be a finite number of degrees, got inf");
    assert_eq!(
        framed("distance = 0\n"),
        "scene.toml:2:12: camera.distance: must be positive (in radii of the scene's bounding sphere), got 0"
    );
    assert_eq!(
        framed("up = [0, 0, 1]\n"),
        "scene.toml:2:6: camera.up: a framed camera's up is [0, 1, 0]; give camera.position and camera.target to \
         choose"
    );
    assert_eq!(camera("fov = 40\nnear = 0\n"), "scene.toml:5:8: camera.near: must be positive, got 0");
    assert_eq!(
        camera("fov = 40\nnear = 5\nfar = 1.5\n"),
        "scene.toml:6:7: camera.far: must be greater than camera.near (5), got 1.5"
    );
    assert_eq!(camera("fov = 40\nup = [0, 0, 0]\n"), "scene.toml:5:6: camera.up: must not be zero");
    assert_eq!(
        error(&format!("[camera]\nposition = [1, 2, 3]\ntarget = [1, 2, 3]\nfov = 40\n{SPOT}")),
        "scene.toml:3:10: camera.target: is the same point as camera.position"
    );
    assert_eq!(
        error(&format!("[camera]\nposition = [-3e38, 0, 0]\ntarget = [3e38, 0, 0]\nfov = 40\n{SPOT}")),
        "scene.toml:3:10: camera.target: is too close to or too far from camera.position for a view direction"
    );
    assert_eq!(
        error(&format!("[camera]\nposition = [0, inf, 4]\ntarget = [0, 0, 0]\nfov = 40\n{SPOT}")),
        "scene.toml:2:12: camera.position: must be finite numbers, got [0, inf, 4]"
    );
    // A number too large for f32 becomes infinite, and is refused as such.
    assert_eq!(
        error(&format!("[camera]\nposition = [0, 1e39, 4]\ntarget = [0, 0, 0]\nfov = 40\n{SPOT}")),
        "scene.toml:2:12: camera.position: must be finite numbers, got [0, inf, 4]"
    );
}

#[test]
fn invalid_lights_name_the_key() {
    let light = |lines: &str| error(&format!("{CAMERA}[[lights]]\n{lines}{SPOT}"));
    assert_eq!(
        light("type = \"directional\"\n"),
        "scene.toml:5:1: lights[0].direction: required for a directional light"
    );
    assert_eq!(light("type = \"point\"\n"), "scene.toml:5:1: lights[0].position: required for a point light");
    assert_eq!(
        light("type = \"directional\"\ndirection = [0, -1, 0]\nposition = [0, 5, 0]\n"),
        "scene.toml:8:12: lights[0].position: a directional light has no position; give direction"
    );
    assert_eq!(
        light("type = \"point\"\nposition = [0, 5, 0]\ndirection = [0, -1, 0]\n"),
        "scene.toml:8:13: lights[0].direction: a point light has no direction; give position"
    );
    assert_eq!(
        light("type = \"directional\"\ndirection = [0, 0, 0]\n"),
        "scene.toml:7:13: lights[0].direction: must not be zero"
    );
    assert_eq!(
        light("type = \"point\"\nposition = [0, 5, 0]\ncolor = [1, -0.5, 1]\n"),
        "scene.toml:8:9: lights[0].color: must be finite and not negative, got [1, -0.5, 1]"
    );
    assert_eq!(
        light("type = \"point\"\nposition = [0, 5, 0]\nintensity = -1\n"),
        "scene.toml:8:13: lights[0].intensity: must be finite and not negative, got -1"
    );
    // Spots: both places, their angles in order and within a quarter turn, and a range only with the inverse
    // square, positive.
    assert_eq!(
        light("type = \"spot\"\nposition = [0, 5, 0]\n"),
        "scene.toml:5:1: lights[0].direction: required for a spot light"
    );
    let spot = "type = \"spot\"\nposition = [0, 5, 0]\ndirection = [0, -1, 0]\n";
    assert_eq!(
        light(&format!("{spot}outer_angle = 95\n")),
        "scene.toml:9:15: lights[0].outer_angle: must be an angle above 0 and at most 90 degrees, got 95"
    );
    assert_eq!(
        light(&format!("{spot}inner_angle = 30\nouter_angle = 20\n")),
        "scene.toml:9:15: lights[0].inner_angle: must be an angle from 0 degrees and below outer_angle (20), got 30"
    );
    assert_eq!(
        light(&format!("{spot}inner_angle = nan\n")),
        "scene.toml:9:15: lights[0].inner_angle: must be an angle from 0 degrees and below outer_angle (45), got NaN"
    );
    assert_eq!(
        light(&format!("{spot}range = 4\n")),
        "scene.toml:9:9: lights[0].range: a range needs falloff = \"inverse-square\" (a light that does not fall \
         off has no end)"
    );
    assert_eq!(
        light(&format!("{spot}falloff = \"inverse-square\"\nrange = -4\n")),
        "scene.toml:10:9: lights[0].range: must be positive, got -4"
    );
    assert_eq!(
        light("type = \"point\"\nposition = [0, 5, 0]\ninner_angle = 10\n"),
        "scene.toml:8:15: lights[0].inner_angle: a point light has no inner_angle"
    );
    assert_eq!(
        light("type = \"directional\"\ndirection = [0, -1, 0]\nfalloff = \"none\"\n"),
        "scene.toml:8:11: lights[0].falloff: a directional light has no falloff"
    );
    assert!(
        light("type = \"spot\"\nposition = [0, 5, 0]\ndirection = [0, -1, 0]\nfalloff = \"linear\"\n")
            .contains("unknown variant `linear`, expected `none` or `inverse-square`")
    );
    // The second light's index.
    assert_eq!(
        error(&format!(
            "{CAMERA}[[lights]]\ntype = \"point\"\nposition = [0, 5, 0]\n[[lights]]\ntype = \"point\"\n{SPOT}"
        )),
        "scene.toml:8:1: lights[1].position: required for a point light"
    );
}

#[test]
fn invalid_objects_and_materials_name_the_key() {
    let object = |lines: &str| error(&format!("{CAMERA}{SPOT}{lines}"));
    assert_eq!(object("scale = 0\n"), "scene.toml:7:9: objects[0].scale: must be positive, got 0");
    assert_eq!(
        object("smooth_angle = 200\n"),
        "scene.toml:7:16: objects[0].smooth_angle: must be an angle from 0 to 180 degrees, got 200"
    );
    assert_eq!(object("scale = [1, -1, 1]\n"), "scene.toml:7:9: objects[0].scale: must be positive, got [1, -1, 1]");
    assert_eq!(
        object("rotate = [0, nan, 0]\n"),
        "scene.toml:7:10: objects[0].rotate: must be finite numbers, got [0, NaN, 0]"
    );
    assert_eq!(
        object("[objects.material]\ncolor = [2, 0, 0]\n"),
        "scene.toml:8:9: objects[0].material.color: must be between 0 and 1, got [2, 0, 0]"
    );
    assert_eq!(
        object("[objects.material]\nspecular = 1.5\n"),
        "scene.toml:8:12: objects[0].material.specular: must be between 0 and 1, got 1.5"
    );
    assert_eq!(
        object("[objects.material]\nshininess = 0\n"),
        "scene.toml:8:13: objects[0].material.shininess: must be positive, got 0"
    );
    assert_eq!(
        object("[objects.material]\nmetallic = 1.5\n"),
        "scene.toml:8:12: objects[0].material.metallic: must be between 0 and 1, got 1.5"
    );
    assert_eq!(
        object("[objects.material]\nroughness = -0.1\n"),
        "scene.toml:8:13: objects[0].material.roughness: must be between 0 and 1, got -0.1"
    );
    assert_eq!(
        object("[objects.material]\ndiffuse = \"a.png\"\nnormal_space = \"object\"\n"),
        "scene.toml:9:16: objects[0].material.normal_space: given without objects[0].material.normal_map (it says \
         how to read that map)"
    );
    assert_eq!(
        object("material.diffuse = \"\"\n"),
        "scene.toml:7:20: objects[0].material.diffuse: must name an image file"
    );
    assert_eq!(
        error(&format!("{CAMERA}[[objects]]\nmesh = \"builtin:teapot\"\n")),
        "scene.toml:6:8: objects[0].mesh: no built-in model is called \"teapot\" (there is builtin:spot)"
    );
    assert_eq!(
        error(&format!("{CAMERA}[[objects]]\nmesh = \"\"\n")),
        "scene.toml:6:8: objects[0].mesh: must name an OBJ file or builtin:spot"
    );
    assert_eq!(error(&format!("objects = []\n{CAMERA}")), "scene.toml:1:11: objects: the scene has no objects");
}

#[test]
fn invalid_top_level_values_name_the_key() {
    assert_eq!(
        error(&format!("background = \"blue\"\n{CAMERA}{SPOT}")),
        "scene.toml:1:14: background: must be a colour written RRGGBB, got \"blue\""
    );
    assert_eq!(
        error(&format!("ambient = [0.1, -0.1, 0]\n{CAMERA}{SPOT}")),
        "scene.toml:1:11: ambient: must be finite and not negative, got [0.1, -0.1, 0]"
    );
}

#[test]
fn errors_carry_their_parts() {
    let e = parse(format!("{CAMERA}{SPOT}scale = 0\n"), "dir/scene.toml").unwrap_err();
    assert_eq!(e.file, Path::new("dir/scene.toml"));
    assert_eq!(e.location.map(|l| (l.line, l.column)), Some((7, 9)));
    assert_eq!(e.key.as_deref(), Some("objects[0].scale"));
    assert!(matches!(e.kind, SceneFileErrorKind::Invalid(_)));
}

// ---------------------------------------------------------------------------------------------------------------
// Files: the scene file, and the files it names

#[test]
fn an_unreadable_or_non_utf8_scene_file_is_an_error() {
    let dir = dir_with(&[("bad.toml", b"[camera]\nposition = \"\xff\"\n")]);
    let missing = dir.path().join("missing.toml");
    let e = load(&missing).unwrap_err();
    assert!(matches!(e.kind, SceneFileErrorKind::Io(_)));
    assert_eq!(
        e.to_string(),
        format!("{}: cannot read the scene file: No such file or directory (os error 2)", missing.display())
    );
    let bad = dir.path().join("bad.toml");
    assert_eq!(
        load(&bad).unwrap_err().to_string(),
        format!("{}:2:13: TOML syntax error: the file is not UTF-8 text", bad.display())
    );
}

/// Loads `scene` written as `scenes/scene.toml` beside `files`, and returns the error and the directory.
fn load_error(scene: &str, files: &[(&str, &[u8])]) -> (SceneFileError, tempfile::TempDir) {
    let mut all = files.to_vec();
    all.push(("scenes/scene.toml", scene.as_bytes()));
    let dir = dir_with(&all);
    let e = load(dir.path().join("scenes/scene.toml")).expect_err("the scene should not load");
    (e, dir)
}

#[test]
fn a_missing_mesh_names_the_file_the_key_and_the_line() {
    let (e, dir) = load_error(&format!("{CAMERA}{SPOT}[[objects]]\nmesh = \"../meshes/gone.obj\"\n"), &[]);
    let scene = dir.path().join("scenes/scene.toml");
    let mesh = dir.path().join("scenes/../meshes/gone.obj");
    assert!(matches!(&e.kind, SceneFileErrorKind::Mesh { path, .. } if *path == mesh));
    assert_eq!(
        e.to_string(),
        format!(
            "{}:8:8: objects[1].mesh: cannot load the mesh: {}: cannot read the file: No such file or directory \
             (os error 2)",
            scene.display(),
            mesh.display()
        )
    );
}

#[test]
fn a_bad_mesh_reports_the_line_of_the_obj_file_too() {
    let (e, dir) =
        load_error(&format!("{CAMERA}[[objects]]\nmesh = \"bad.obj\"\n"), &[("scenes/bad.obj", b"v 0 0 0\nf 1 2 3\n")]);
    assert_eq!(
        e.to_string(),
        format!(
            "{}:6:8: objects[0].mesh: cannot load the mesh: {}, line 2: vertex index 2 is out of range (1 defined \
             before it)",
            dir.path().join("scenes/scene.toml").display(),
            dir.path().join("scenes/bad.obj").display()
        )
    );
}

#[test]
fn a_missing_or_corrupt_image_names_the_file_the_key_and_the_line() {
    let scene = format!("{CAMERA}{SPOT}[objects.material]\ndiffuse = \"tex/a.png\"\nglow_map = \"tex/bad.img\"\n");
    let (e, dir) = load_error(&scene, &[("scenes/tex/bad.img", b"not an image")]);
    let scene_path = dir.path().join("scenes/scene.toml");
    assert!(matches!(e.kind, SceneFileErrorKind::Image { .. }));
    assert_eq!(
        e.to_string(),
        format!(
            "{}:8:11: objects[0].material.diffuse: cannot load the image: {}: cannot read the file: No such file or \
             directory (os error 2)",
            scene_path.display(),
            dir.path().join("scenes/tex/a.png").display()
        )
    );
    let png = png_bytes();
    let (e, dir) = load_error(&scene, &[("scenes/tex/a.png", &png), ("scenes/tex/bad.img", b"not an image")]);
    assert_eq!(
        e.to_string(),
        format!(
            "{}:9:12: objects[0].material.glow_map: cannot load the image: {}: cannot decode the image: unknown \
             image format (expected PNG, JPEG or TGA)",
            dir.path().join("scenes/scene.toml").display(),
            dir.path().join("scenes/tex/bad.img").display()
        )
    );
}

#[test]
fn relative_paths_resolve_from_the_scene_files_directory() {
    let png = png_bytes();
    let dir = dir_with(&[
        ("project/meshes/tri.obj", TRIANGLE_OBJ.as_bytes()),
        ("project/scenes/deep/tex/t.png", &png),
        (
            "project/scenes/deep/scene.toml",
            format!("{CAMERA}[[objects]]\nmesh = \"../../meshes/tri.obj\"\nmaterial.diffuse = \"tex/t.png\"\n")
                .as_bytes(),
        ),
    ]);
    // The test runs in the crate's directory, far from the scene file's.
    let scene = load(dir.path().join("project/scenes/deep/scene.toml")).unwrap();
    assert_eq!(scene.objects[0].mesh_path, dir.path().join("project/scenes/deep/../../meshes/tri.obj"));
    assert_eq!(scene.images.len(), 1);
    assert_eq!(scene.images[0].0, dir.path().join("project/scenes/deep/tex/t.png"));
    assert_eq!(scene.objects[0].material.diffuse.as_ref().unwrap().texels[0], 0xFF0000);

    // A scene parsed from text resolves against its origin's directory.
    let text = format!("{CAMERA}[[objects]]\nmesh = \"../meshes/tri.obj\"\n");
    let parsed = parse(text, dir.path().join("project/scenes/virtual.toml")).unwrap();
    assert_eq!(parsed.load().unwrap().objects[0].model.triangle_count(), 1);
}

#[test]
fn a_file_named_twice_loads_once() {
    let png = png_bytes();
    let dir = dir_with(&[("s/m/tri.obj", TRIANGLE_OBJ.as_bytes()), ("s/t/a.png", &png), ("s/t/b.png", &png)]);
    let text = format!(
        "{CAMERA}\
         [[objects]]\nmesh = \"m/tri.obj\"\nmaterial = {{ diffuse = \"t/a.png\", normal_map = \"t/b.png\" }}\n\
         [[objects]]\nmesh = \"./m/../m/tri.obj\"\nmaterial = {{ diffuse = \"./t/a.png\", specular_map = \"t/../t/a.png\" }}\n\
         [[objects]]\nmesh = \"builtin:spot\"\n[[objects]]\nmesh = \"builtin:spot\"\n"
    );
    fs::write(dir.path().join("s/scene.toml"), text).unwrap();
    let scene = load(dir.path().join("s/scene.toml")).unwrap();
    let [a, b, spot1, spot2] = &scene.objects[..] else { panic!("four objects") };
    assert!(Arc::ptr_eq(&a.model, &b.model));
    assert!(Arc::ptr_eq(&spot1.model, &spot2.model));
    // a.png three times (two spellings, two roles), b.png once, though its bytes are a.png's: two images.
    let paths: Vec<_> = scene.images.iter().map(|(p, _)| p.strip_prefix(dir.path()).unwrap().to_path_buf()).collect();
    assert_eq!(paths, [PathBuf::from("s/t/a.png"), PathBuf::from("s/t/b.png")]);
    let first = a.material.diffuse.as_ref().unwrap();
    assert!(Arc::ptr_eq(first, b.material.diffuse.as_ref().unwrap()));
    assert!(Arc::ptr_eq(first, b.material.specular_map.as_ref().unwrap()));
    assert!(Arc::ptr_eq(first, &scene.images[0].1));
    assert!(!Arc::ptr_eq(first, &a.material.normal_map.as_ref().unwrap().image));
}

#[test]
fn images_on_a_mesh_without_texture_coordinates_are_a_warning() {
    let png = png_bytes();
    let dir = dir_with(&[("flat.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), ("a.png", &png)]);
    let text = format!("{CAMERA}[[objects]]\nmesh = \"flat.obj\"\n[objects.material]\nglow_map = \"a.png\"\n");
    let path = dir.path().join("scene.toml");
    fs::write(&path, text).unwrap();
    let scene = load(&path).unwrap();
    assert_eq!(
        scene.warnings,
        [format!(
            "{}:8:12: objects[0].material.glow_map: the mesh has no texture coordinates, so this image does not show",
            path.display()
        )]
    );
}

// ---------------------------------------------------------------------------------------------------------------
// Values

#[test]
fn rotation_order_and_scale_give_the_documented_matrix() {
    let text = format!("{CAMERA}{SPOT}translate = [10, 20, 30]\nrotate = [90, 0, 90]\nscale = [1, 2, 3]\n");
    let scene = parse(text, "scene.toml").unwrap().load().unwrap();
    // Scale, then 90 degrees about X (+y to +z), then 90 degrees about Z (+x to +y), then translate:
    // +x -> (1,0,0) -> (1,0,0) -> (0,1,0); +y -> (0,2,0) -> (0,0,2) -> (0,0,2); +z -> (0,0,3) -> (0,-3,0) -> (3,0,0).
    let expected =
        Mat4::from_rows([0.0, 0.0, 3.0, 10.0], [1.0, 0.0, 0.0, 20.0], [0.0, 2.0, 0.0, 30.0], [0.0, 0.0, 0.0, 1.0]);
    let m = scene.objects[0].transform;
    assert!(m.max_abs_diff(&expected) < 1e-5, "{m:?}");
    assert_eq!(m, object_transform(Vec3::new(10.0, 20.0, 30.0), Vec3::new(90.0, 0.0, 90.0), Vec3::new(1.0, 2.0, 3.0)));
    // The other order (Z first) would send +x to +z instead.
    assert!(close(m.transform_vector(Vec3::X), Vec3::Y));

    // A number scales uniformly; no keys give the identity.
    let text = format!("{CAMERA}{SPOT}scale = 2.5\n{SPOT}");
    let scene = parse(text, "scene.toml").unwrap().load().unwrap();
    assert_eq!(scene.objects[0].transform, Mat4::from_scale(Vec3::splat(2.5)));
    assert_eq!(scene.objects[1].transform, Mat4::IDENTITY);
}

#[test]
fn a_framed_camera_and_the_viewer_lights_arrive_as_written() {
    let scene = parse(SPOT, "scene.toml").unwrap().load().unwrap();
    assert_eq!(scene.camera, CameraPlacement::Framed(FramedCamera::DEFAULT), "no [camera]: the viewer's");
    assert!(scene.lights.is_empty());
    let text = format!(
        "viewer_lights = true\n[camera]\nyaw = -20\npitch = 40\ndistance = 4\northographic = 2.5\nfar = 9\n\
         [[lights]]\ntype = \"point\"\nposition = [0, 0, 1]\nspace = \"camera\"\n{SPOT}"
    );
    let scene = parse(text, "scene.toml").unwrap().load().unwrap();
    let framed = FramedCamera {
        yaw_degrees: -20.0,
        pitch_degrees: 40.0,
        distance: 4.0,
        projection: SceneProjection::Orthographic { height: 2.5 },
        near: None,
        far: Some(9.0),
    };
    assert_eq!(scene.camera, CameraPlacement::Framed(framed));
    assert_eq!(scene.lights.len(), 3, "the file's light, then the viewer's two");
    assert_eq!(scene.lights[0].space, LightSpace::Camera);
    assert_eq!(scene.lights[0].kind, SceneLightKind::Point { position: Vec3::Z, falloff: LightFalloff::None });
    assert_eq!(scene.lights[1..], defaults::VIEWER_LIGHTS);
}

#[test]
fn defaults_and_values_arrive_as_written() {
    let text = format!(
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\northographic = 3\nnear = 0.5\nfar = 20\n\
         [[lights]]\ntype = \"directional\"\ndirection = [0, -3, 0]\n\
         [[lights]]\ntype = \"point\"\nposition = [1, 2, 3]\ncolor = [1, 0.5, 0]\nintensity = 2\nshadows = true\n{SPOT}"
    );
    let scene = parse(text, "scene.toml").unwrap().load().unwrap();
    let camera = placed(&scene);
    assert_eq!(camera.projection, SceneProjection::Orthographic { height: 3.0 });
    assert_eq!((camera.near, camera.far), (Some(0.5), Some(20.0)));
    assert_eq!(camera.up, Vec3::Y);
    assert_eq!(scene.lights[0].kind, SceneLightKind::Directional { direction: -Vec3::Y });
    // Directions too long (or too short) for f32 squares still have one.
    let text = format!(
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = 40\nup = [0, 3e38, 0]\n\
         [[lights]]\ntype = \"directional\"\ndirection = [1e-30, 0, 0]\n{SPOT}"
    );
    let huge = parse(text, "scene.toml").unwrap().load().unwrap();
    assert_eq!(placed(&huge).up, Vec3::Y);
    assert_eq!(huge.lights[0].kind, SceneLightKind::Directional { direction: Vec3::X });
    assert_eq!((scene.lights[0].color, scene.lights[0].intensity, scene.lights[0].shadows), (Vec3::ONE, 1.0, false));
    assert_eq!(
        scene.lights[1].kind,
        SceneLightKind::Point { position: Vec3::new(1.0, 2.0, 3.0), falloff: LightFalloff::None }
    );
    assert_eq!((scene.lights[1].color, scene.lights[1].intensity), (Vec3::new(1.0, 0.5, 0.0), 2.0));
    assert!(scene.lights[1].shadows);
    assert_eq!(scene.background, defaults::BACKGROUND);
    assert_eq!(scene.ambient, defaults::AMBIENT);
    assert!(!scene.ambient_occlusion);
    // A spot in degrees, falling off by the inverse square within a range; the cone's defaults are glTF's.
    let text = format!(
        "{CAMERA}[[lights]]\ntype = \"spot\"\nposition = [0, 4, 0]\ndirection = [0, -2, 0]\ninner_angle = 10\n\
         outer_angle = 30\nfalloff = \"inverse-square\"\nrange = 12\n\
         [[lights]]\ntype = \"spot\"\nposition = [0, 4, 0]\ndirection = [1, 0, 0]\n{SPOT}"
    );
    let spots = parse(text, "scene.toml").unwrap().load().unwrap();
    assert_eq!(
        spots.lights[0].kind,
        SceneLightKind::Spot {
            position: Vec3::new(0.0, 4.0, 0.0),
            direction: -Vec3::Y,
            inner: 10f32.to_radians(),
            outer: 30f32.to_radians(),
            falloff: LightFalloff::InverseSquare { range: Some(12.0) },
        }
    );
    assert_eq!(
        spots.lights[1].kind,
        SceneLightKind::Spot {
            position: Vec3::new(0.0, 4.0, 0.0),
            direction: Vec3::X,
            inner: 0.0,
            outer: std::f32::consts::FRAC_PI_4,
            falloff: LightFalloff::None,
        }
    );
    let m = &scene.objects[0].material;
    assert_eq!((m.filter, m.wrap, m.mip_filter), (FilterMode::Bilinear, WrapMode::Repeat, MipFilter::Linear));
    assert_eq!((m.color, m.specular, m.shininess), (None, None, None));
    assert_eq!((m.metallic, m.roughness), (None, None));

    let text = format!(
        "background = \"#102030\"\nambient = [0.2, 0.2, 0.2]\nambient_occlusion = true\n{CAMERA}{SPOT}\
         [objects.material]\nspecular = 0.25\nshininess = 12\nmetallic = 0.75\nroughness = 0.5\n\
         filter = \"nearest\"\nwrap = \"clamp\"\nmipmaps = \"nearest\"\n"
    );
    let scene = parse(&text, "scene.toml").unwrap().load().unwrap();
    assert!(close(scene.background, Vec3::new(16.0, 32.0, 48.0) / 255.0));
    assert_eq!(scene.ambient, Vec3::splat(0.2));
    assert!(scene.ambient_occlusion);
    let m = &scene.objects[0].material;
    assert_eq!((m.specular, m.shininess), (Some(Vec3::splat(0.25)), Some(12.0)));
    assert_eq!((m.metallic, m.roughness), (Some(0.75), Some(0.5)));
    assert_eq!((m.filter, m.wrap, m.mip_filter), (FilterMode::Nearest, WrapMode::Clamp, MipFilter::Nearest));
    let read = |mipmaps: &str| {
        let text = text.replace("mipmaps = \"nearest\"", &format!("mipmaps = \"{mipmaps}\""));
        parse(text, "scene.toml").unwrap().load().unwrap().objects[0].material.mip_filter
    };
    assert_eq!(read("off"), MipFilter::Off);
    assert_eq!(read("anisotropic2"), MipFilter::Anisotropic(Anisotropy::X2));
    assert_eq!(read("anisotropic16"), MipFilter::Anisotropic(Anisotropy::X16));
    let wrong = text.replace("mipmaps = \"nearest\"", "mipmaps = \"trilinear\"");
    let error = parse(wrong, "scene.toml").unwrap_err().to_string();
    let expected = "scene.toml:17:11: objects[0].material.mipmaps: unknown variant `trilinear`, expected one of \
                    `off`, `nearest`, `linear`, `anisotropic2`, `anisotropic4`, `anisotropic8`, `anisotropic16`";
    assert_eq!(error, expected);
}

#[test]
fn scene_material_keys_override_the_mtl_and_absent_keys_fall_back_to_it() {
    let png = png_bytes();
    let obj = format!("mtllib m.mtl\nusemtl red\n{TRIANGLE_OBJ}");
    let dir = dir_with(&[
        ("tri.obj", obj.as_bytes()),
        ("m.mtl", b"newmtl red\nKd 1 0 0\nmap_Kd mtl.png\n"),
        ("mtl.png", &png),
        ("scene.png", &png),
    ]);
    let text = format!(
        "{CAMERA}[[objects]]\nmesh = \"tri.obj\"\n\
         [[objects]]\nmesh = \"tri.obj\"\nmaterial = {{ color = [0, 0, 1], diffuse = \"scene.png\" }}\n"
    );
    let path = dir.path().join("scene.toml");
    fs::write(&path, text).unwrap();
    let scene = load(&path).unwrap();
    let [plain, dressed] = &scene.objects[..] else { panic!("two objects") };
    let mtl = plain.model.part_material(0);
    assert_eq!(plain.material.color_over(mtl), Vec3::X);
    let from_mtl: &TextureImage = plain.material.diffuse_over(mtl).unwrap();
    assert!(std::ptr::eq(from_mtl, mtl.unwrap().texture.as_ref().unwrap()));
    assert_eq!(dressed.material.color_over(mtl), Vec3::Z);
    let from_scene: &TextureImage = dressed.material.diffuse_over(mtl).unwrap();
    assert!(std::ptr::eq(from_scene, &**dressed.material.diffuse.as_ref().unwrap()));
    // A part without an MTL material and no scene colour: the default.
    assert_eq!(plain.material.color_over(None), rastty_scene::model::DEFAULT_DIFFUSE);
}

// ---------------------------------------------------------------------------------------------------------------
// The project-made assets of assets/scenes/ (see NOTICE.md there): generated by the recipe below. Regenerate with
// `UPDATE_SCENE_ASSETS=1 cargo test -p rastty --test integration scene_file::project_made`.

/// A 4 x 4 ground plane at y = 0, facing up, with texture coordinates 0..4 so that images repeat four times.
const GROUND_OBJ: &str = "\
# A 4 x 4 ground plane at y = 0, facing up. Made by the rastty project for its example scenes (see NOTICE.md).
# Texture coordinates run from 0 to 4 across it, so a repeating image tiles four times each way.
v -2 0 2
v 2 0 2
v 2 0 -2
v -2 0 -2
vt 0 0
vt 4 0
vt 4 4
vt 0 4
vn 0 1 0
f 1/1/1 2/2/1 3/3/1 4/4/1
";

/// The side of every generated image, and of one tile of the tile images.
const SIDE: u32 = 64;
const TILE: u32 = 16;

/// Where a texel lies on its tile: the grout line, the bevel (with the outward direction in texture space, `v`
/// up), or the face.
enum TilePart {
    Grout,
    Bevel(f32, f32),
    Face,
}

fn tile_part(x: u32, y: u32) -> TilePart {
    let (tx, ty) = (x % TILE, TILE - 1 - y % TILE);
    if tx == 0 || ty == 0 {
        return TilePart::Grout;
    }
    let axis = |t: u32| -> f32 {
        match t {
            1..=3 => -1.0,
            13..=15 => 1.0,
            _ => 0.0,
        }
    };
    let (dx, dy) = (axis(tx), axis(ty));
    if dx == 0.0 && dy == 0.0 { TilePart::Face } else { TilePart::Bevel(dx, dy) }
}

/// The images: name, colour type, bytes per texel and the texel function.
fn generated_images() -> Vec<(&'static str, png::ColorType, Vec<u8>)> {
    let mut images = Vec::new();
    let each = |f: &dyn Fn(u32, u32) -> Vec<u8>| -> Vec<u8> {
        (0..SIDE).flat_map(|y| (0..SIDE).map(move |x| (x, y))).flat_map(|(x, y)| f(x, y)).collect()
    };
    // An 8 x 8 checkerboard of two warm greys.
    images.push((
        "checker.png",
        png::ColorType::Rgb,
        each(&|x, y| if (x / 8 + y / 8) % 2 == 0 { vec![184, 180, 168] } else { vec![110, 108, 104] }),
    ));
    // Stone tiles, each a slightly different shade, with dark grout.
    images.push((
        "tiles.png",
        png::ColorType::Rgb,
        each(&|x, y| match tile_part(x, y) {
            TilePart::Grout => vec![40, 38, 36],
            _ => {
                let shade =
                    [0u8, 14, 6, 20, 10, 2, 18, 8, 16, 4, 12, 22, 0, 10, 6, 14][((y / TILE) * 4 + x / TILE) as usize];
                vec![150 + shade, 140 + shade, 120 + shade]
            }
        }),
    ));
    // Tangent-space normals: bevels lean outward, faces and grout are flat. `rgb = n * 0.5 + 0.5`.
    images.push((
        "tiles_normal.png",
        png::ColorType::Rgb,
        each(&|x, y| {
            let (nx, ny) = match tile_part(x, y) {
                TilePart::Bevel(dx, dy) => (dx * 0.6, dy * 0.6),
                _ => (0.0, 0.0),
            };
            let n = Vec3::new(nx, ny, 1.0).try_normalize().unwrap();
            [n.x, n.y, n.z].iter().map(|c| ((c * 0.5 + 0.5) * 255.0).round() as u8).collect()
        }),
    ));
    // Specular, 8-bit grey: shiny faces, duller bevels, matt grout.
    images.push((
        "tiles_specular.png",
        png::ColorType::Grayscale,
        each(&|x, y| match tile_part(x, y) {
            TilePart::Grout => vec![16],
            TilePart::Bevel(..) => vec![128],
            TilePart::Face => vec![192],
        }),
    ));
    // Glow: the grout lines shine teal, everything else emits nothing.
    images.push((
        "tiles_glow.png",
        png::ColorType::Rgb,
        each(&|x, y| match tile_part(x, y) {
            TilePart::Grout => vec![32, 160, 192],
            _ => vec![0, 0, 0],
        }),
    ));
    images
}

/// What `TextureImage` gives for generated data (grey replicated into RGB).
fn expected_texels(color: png::ColorType, data: &[u8]) -> Vec<u32> {
    let rgb = |p: &[u8]| (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]);
    match color {
        png::ColorType::Rgb => data.chunks_exact(3).map(rgb).collect(),
        _ => data.iter().map(|&g| rgb(&[g, g, g])).collect(),
    }
}

#[test]
fn project_made_assets_match_their_recipe() {
    let dir = root().join("assets/scenes");
    let update = std::env::var_os("UPDATE_SCENE_ASSETS").is_some();
    if update {
        fs::write(dir.join("ground.obj"), GROUND_OBJ).unwrap();
    }
    assert_eq!(fs::read_to_string(dir.join("ground.obj")).unwrap(), GROUND_OBJ, "ground.obj differs from its recipe");
    for (name, color, data) in generated_images() {
        let path = dir.join(name);
        if update {
            fs::write(&path, encode_png(SIDE, SIDE, color, &data)).unwrap();
        }
        let image = TextureImage::load(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((image.width, image.height), (SIDE, SIDE), "{name}");
        assert!(image.texels == expected_texels(color, &data), "{name} differs from its recipe");
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Environments

/// A Radiance `.hdr` file of `width x height` texels, uncompressed scanlines, each texel the RGBE bytes `texel(x, y)`.
fn hdr_bytes(width: u32, height: u32, texel: impl Fn(u32, u32) -> [u8; 4]) -> Vec<u8> {
    let mut out = format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n").into_bytes();
    for y in 0..height {
        for x in 0..width {
            out.extend_from_slice(&texel(x, y));
        }
    }
    out
}

/// The environment a scene of `environment_line` and Spot (a physically based one when `metal`) loads, from a
/// directory holding `files`: its name, or the error.
fn environment_of(environment_line: &str, metal: bool, files: &[(&str, &[u8])]) -> Result<Option<String>, String> {
    let dir = dir_with(files);
    let material = if metal { "[objects.material]\nmetallic = 1\n" } else { "" };
    let text = format!("{environment_line}\n{SPOT}{material}");
    let path = dir.path().join("scene.toml");
    fs::write(&path, &text).unwrap();
    let scene = load(&path).map_err(|e| e.to_string())?;
    Ok(scene.environment.as_ref().map(|e| e.name.clone()))
}

#[test]
fn a_physically_based_scene_gets_the_studio_unless_it_names_an_environment() {
    assert_eq!(environment_of("", true, &[]).unwrap().as_deref(), Some("studio"));
    assert_eq!(environment_of("", false, &[]).unwrap(), None);
    assert_eq!(environment_of("environment = \"none\"", true, &[]).unwrap(), None);
    assert_eq!(environment_of("environment = \"studio\"", false, &[]).unwrap().as_deref(), Some("studio"));
    // An image, relative to the scene file: a 16x8 panorama of RGBE (128, 64, 32, 129), which decodes to 1, 0.5,
    // 0.25.
    let hdr = hdr_bytes(16, 8, |_, _| [128, 64, 32, 129]);
    let name = environment_of("environment = \"sky/room.hdr\"", false, &[("sky/room.hdr", &hdr)]).unwrap();
    assert_eq!(name.as_deref(), Some("room.hdr"));
    let decoded = rastty_scene::environment::PanoramaImage::decode(Path::new("room.hdr"), &hdr).unwrap();
    assert_eq!((decoded.width, decoded.height, decoded.clamped), (16, 8, 0));
    assert!(decoded.texels.iter().all(|t| *t == Vec3::new(1.0, 0.5, 0.25)), "{:?}", decoded.texels[0]);
}

#[test]
fn a_bad_environment_image_is_refused_naming_the_line_and_the_reason() {
    let refused = |name: &str, bytes: &[u8]| {
        let line = format!("environment = \"{name}\"");
        environment_of(&line, true, &[(name, bytes)]).expect_err(name)
    };
    // Not twice as wide as tall.
    let square = encode_png(4, 4, png::ColorType::Rgb, &[0; 48]);
    let e = refused("square.png", &square);
    assert!(e.contains("scene.toml:1:15") && e.contains("environment") && e.contains("not 4x4"), "{e}");
    // A header promising more texels than allowed: refused before anything is allocated.
    let e = refused("huge.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 200000\n");
    assert!(e.contains("huge.hdr") && e.to_lowercase().contains("limit"), "{e}");
    // Empty, truncated and unknown data.
    let e = refused("empty.hdr", b"");
    assert!(e.contains("empty.hdr") && e.contains("unknown environment image format"), "{e}");
    let mut truncated = hdr_bytes(16, 8, |_, _| [128, 128, 128, 128]);
    truncated.truncate(truncated.len() - 100);
    let e = refused("truncated.hdr", &truncated);
    assert!(e.contains("truncated.hdr"), "{e}");
    let e = refused("notes.txt", b"not an image at all");
    assert!(e.contains("unknown environment image format"), "{e}");
    // A missing file.
    let e = environment_of("environment = \"gone.hdr\"", true, &[]).unwrap_err();
    assert!(e.contains("gone.hdr") && e.contains("scene.toml:1:15"), "{e}");
    // An empty name.
    let e = environment_of("environment = \" \"", true, &[]).unwrap_err();
    assert!(e.contains("environment") && e.contains("must name an environment"), "{e}");
}

#[test]
fn an_environment_brighter_than_half_floats_is_clamped_with_a_warning() {
    // Exponent 255: about 1.7e38 each, whose sums over the sphere would overflow.
    let hdr = hdr_bytes(16, 8, |x, _| if x < 4 { [255, 255, 255, 255] } else { [128, 128, 128, 129] });
    let dir = dir_with(&[("bright.hdr", &hdr)]);
    let path = dir.path().join("scene.toml");
    fs::write(&path, format!("environment = \"bright.hdr\"\n{SPOT}")).unwrap();
    let scene = load(&path).unwrap();
    let environment = scene.environment.as_ref().unwrap();
    assert_eq!(environment.clamped, 4 * 8);
    let warning = scene.warnings.iter().find(|w| w.contains("bright.hdr")).expect("a warning");
    assert!(
        warning.contains("32 texels") && warning.contains("clamped") && warning.contains("scene.toml:1"),
        "{warning}"
    );
    // What lights surfaces is finite.
    let light = environment.environment();
    for d in [Vec3::X, Vec3::Y, -Vec3::Z] {
        let r = light.radiance(d);
        assert!(r.is_finite() && r.max_elem() <= rastty_scene::environment::MAX_RADIANCE, "{r:?}");
    }
}
