//! The `rastty` binary on scene files: `render SCENE.toml -o`, `--explain`, and the errors.

use crate::common;

use common::root;
use std::fs;
use std::path::Path;
use std::process::{Command, Output};

/// Runs the binary in `dir` with `args`.
fn rastty(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let Output { status, stdout, stderr } =
        Command::new(env!("CARGO_BIN_EXE_rastty")).current_dir(dir).args(args).output().expect("run rastty");
    let stderr = String::from_utf8_lossy(&stderr).into_owned();
    assert!(!stderr.contains("panicked"), "a panic: {stderr}");
    (status.code(), String::from_utf8_lossy(&stdout).into_owned(), stderr)
}

#[test]
fn explain_prints_the_plan_and_renders_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("assets/scenes/spot_lamp.toml");
    let (code, stdout, stderr) = rastty(dir.path(), &["render", scene.to_str().unwrap(), "--explain"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(lines[0].starts_with("frame 800x600: perspective, fov 45 degrees; near 0.1 (given)"), "{stdout}");
    assert!(stdout.contains("\npasses:\n  1. shadow map of light 1 (point at [1.6, 4.2, 1.4]): 1024x1024 texels"));
    assert!(stdout.contains("\n  2. forward: 2 draws\n"), "{stdout}");
    assert!(lines.last().unwrap().starts_with("  3. ambient occlusion"), "{stdout}");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 0, "--explain alone wrote a file");

    let (code, stdout, _) = rastty(
        dir.path(),
        &["render", scene.to_str().unwrap(), "--explain", "--without", "shadows", "--size", "64x64"],
    );
    assert_eq!(code, Some(0));
    assert!(stdout.starts_with("frame 64x64") && !stdout.contains("shadow"), "{stdout}");
}

#[test]
fn a_scene_renders_to_a_png_with_its_plan_and_stats() {
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("assets/scenes/spot_sun.toml");
    let args = ["render", scene.to_str().unwrap(), "-o", "sun.png", "--size", "80x60", "--explain", "--stats"];
    let (code, stdout, stderr) = rastty(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.starts_with("frame 80x60"), "{stdout}");
    assert!(stdout.contains("\nshadow map of light 1: 512x512 texels, "), "{stdout}");
    assert!(stdout.contains("\nrender: ") && stdout.contains(" at 80x60: shadows "), "{stdout}");
    let decoder = png::Decoder::new(std::io::BufReader::new(fs::File::open(dir.path().join("sun.png")).unwrap()));
    let info = decoder.read_info().unwrap();
    assert_eq!((info.info().width, info.info().height), (80, 60));
}

#[test]
fn scene_file_errors_name_the_file_and_line_and_exit_non_zero() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("bad.toml"),
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = 200\n\n[[objects]]\nmesh = \"builtin:spot\"\n",
    )
    .unwrap();
    for args in [&["render", "bad.toml", "-o", "x.png"][..], &["render", "bad.toml", "--explain"], &["bad.toml"]] {
        let (code, stdout, stderr) = rastty(dir.path(), args);
        assert_eq!(code, Some(1), "{args:?}: {stderr}");
        assert!(stdout.is_empty());
        // The viewer refuses a non-terminal first; render reads the file.
        if args[0] == "render" {
            assert_eq!(
                stderr.trim(),
                "rastty: error: bad.toml:4:7: camera.fov: must be between 0 and 180 degrees, got 200",
                "{args:?}"
            );
        }
    }
    assert!(!dir.path().join("x.png").exists());
}

#[test]
fn a_point_light_inside_the_scene_casts_through_a_cube_map() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("lamp.toml"),
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0, 0]\nfov = 40\n\
         [[lights]]\ntype = \"point\"\nposition = [0, 0.5, 0.6]\nshadows = true\n\
         [[objects]]\nmesh = \"builtin:spot\"\n",
    )
    .unwrap();
    let (code, stdout, stderr) = rastty(dir.path(), &["render", "lamp.toml", "--explain"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("shadow map of light 1 (point at [0, 0.5, 0.6]): 6 faces of 1024x1024 texels"), "{stdout}");
    let (code, _, stderr) = rastty(dir.path(), &["render", "lamp.toml", "-o", "lamp.png", "--size", "64x48"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(dir.path().join("lamp.png").exists());
}

#[test]
fn options_that_do_not_fit_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("assets/scenes/spot_sun.toml");
    let scene = scene.to_str().unwrap();
    let (code, stdout, stderr) = rastty(dir.path(), &["render", scene, "--explain", "--stats"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stdout.is_empty(), "{stdout}");
    assert!(stderr.starts_with("rastty: error: --stats needs -o OUT.png"), "{stderr}");
    // Without --explain, -o is required (a usage error).
    let (code, _, stderr) = rastty(dir.path(), &["render", scene]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("--output"), "{stderr}");
    // Scene options are taken.
    let (code, stdout, stderr) =
        rastty(dir.path(), &["render", scene, "--explain", "--wireframe", "--no-texture", "--background", "000000"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("background #000000") && stdout.contains("with wireframe lines, diffuse textures off"));
    assert!(!stdout.contains("samples per pixel"), "{stdout}");
    let (code, stdout, stderr) = rastty(dir.path(), &["render", scene, "--explain", "--msaa"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("forward: 2 draws, 4 samples per pixel (shaded once, averaged)"), "{stdout}");
}

/// A model and a scene file take the same options: the camera's, the shading mode and `--without`; `--explain`
/// plans a model's frame as it does a scene's.
#[test]
fn a_model_and_a_scene_file_take_the_same_options() {
    let dir = tempfile::tempdir().unwrap();
    let scene = root().join("assets/scenes/spot_sun.toml");
    let scene = scene.to_str().unwrap();
    let explain = |args: &[&str]| {
        let (code, stdout, stderr) = rastty(dir.path(), args);
        assert_eq!(code, Some(0), "{args:?}: {stderr}");
        stdout
    };
    // The camera options move a scene file's camera: the plan's clipping planes follow the eye.
    let file_camera = explain(&["render", scene, "--explain"]);
    let moved = explain(&["render", scene, "--explain", "--yaw", "10", "--distance", "1.5", "--near", "0.5"]);
    assert_ne!(file_camera.lines().next(), moved.lines().next(), "{moved}");
    // `--near` is in radii of the scene's bounding sphere: the plane is given, not derived around the scene.
    assert!(moved.lines().next().unwrap().contains(" (given), far "), "{moved}");
    // The shading mode reaches every draw of a scene file.
    let flat = explain(&["render", scene, "--explain", "--shading", "flat"]);
    assert!(flat.contains(": flat; varyings"), "{flat}");
    assert!(!flat.contains(": phong;"), "{flat}");
    // A model: its plan, its lights that follow the camera, its effects switched off.
    let model = explain(&["render", "--explain", "--without", "specular"]);
    assert!(model.contains("object 1 (builtin:spot)"), "{model}");
    assert!(model.contains("lights 2 directional") && model.contains("; no specular;"), "{model}");
    let model = explain(&["render", "--explain"]);
    assert!(model.contains("; specular constant;"), "{model}");
}
