//! `rastty snapshot`: the stored pictures of the example scenes (`tests/snapshots/command/`) checked through the
//! command itself; a golden set written and checked, a changed material caught with a diff image, tolerances,
//! JUnit, thumbnails; and bad input that fails its row and not the others.

use crate::common;

use common::rastty_in;
use std::fs;
use std::path::Path;

/// An OBJ cube, 12 triangles.
const CUBE: &str = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n\
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 7 3\nf 4 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

/// An ASCII STL tetrahedron.
const TETRAHEDRON: &str = "solid t\n\
facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n\
facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n\
facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n\
facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n";

/// A scene of Spot in a colour, through its own camera.
fn spot_scene(color: &str) -> String {
    format!(
        "[camera]\nposition = [0, 1, 4]\ntarget = [0, 0.5, 0]\n\n[[lights]]\ntype = \"directional\"\n\
         direction = [-1, -2, -1]\n\n[[objects]]\nmesh = \"builtin:spot\"\n[objects.material]\ncolor = {color}\n"
    )
}

/// A folder of three models: the cube, the tetrahedron and the Spot scene.
fn models(dir: &Path) {
    let models = dir.join("models");
    fs::create_dir_all(&models).unwrap();
    fs::write(models.join("cube.obj"), CUBE).unwrap();
    fs::write(models.join("tetrahedron.stl"), TETRAHEDRON).unwrap();
    fs::write(models.join("spot.toml"), spot_scene("[1, 1, 1]")).unwrap();
}

/// Runs `rastty snapshot` in `dir`: its exit code, standard output and standard error.
fn snapshot(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let mut all = vec!["snapshot", "--size", "64x48", "--jobs", "2"];
    all.extend_from_slice(args);
    let output = rastty_in(dir, &all);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "{stderr}");
    (output.status.code(), String::from_utf8_lossy(&output.stdout).into_owned(), stderr)
}

/// The names of the files in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

#[test]
fn a_golden_set_is_written_then_checked_and_a_changed_material_fails_with_a_diff_image() {
    let dir = tempfile::tempdir().unwrap();
    models(dir.path());
    let (code, stdout, stderr) = snapshot(dir.path(), &["models", "--out", "golden"]);
    assert_eq!(code, Some(0), "{stdout}{stderr}");
    assert!(stdout.contains("7 pictures: 7 written"), "{stdout}");
    let golden = dir.path().join("golden");
    assert_eq!(
        names(&golden),
        [
            "cube-front.png",
            "cube-side.png",
            "cube-three-quarter.png",
            "spot-camera.png",
            "tetrahedron-front.png",
            "tetrahedron-side.png",
            "tetrahedron-three-quarter.png"
        ]
    );
    // Decoded by the `image` crate: pictures of the size asked for, not blank.
    let front = image::open(golden.join("cube-front.png")).unwrap().to_rgb8();
    assert_eq!(front.dimensions(), (64, 48));
    assert!(front.pixels().any(|p| *p != *front.get_pixel(0, 0)), "the cube shows");
    // Checked against themselves: every picture matches, nothing else is written.
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden", "--check"]);
    assert_eq!(code, Some(0), "{stdout}");
    assert!(stdout.contains("7 pictures: 7 matching") && !stdout.contains('|'), "{stdout}");
    assert_eq!(names(&golden).len(), 7);

    // Spot turns red: her picture differs, with the new picture and a diff image beside the golden.
    fs::write(dir.path().join("models/spot.toml"), spot_scene("[1, 0.2, 0.2]")).unwrap();
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden", "--check", "--junit", "report.xml"]);
    assert_eq!(code, Some(1), "{stdout}");
    let row = stdout.lines().find(|l| l.contains("spot.toml")).expect("a row for the changed file");
    assert!(row.contains("| camera |") && row.contains("differs in"), "{row}");
    assert!(stdout.contains("7 pictures: 6 matching, 1 differing"), "{stdout}");
    let diff = image::open(golden.join("spot-camera.diff.png")).unwrap().to_rgb8();
    let red = diff.pixels().filter(|p| p[0] >= 128 && p[1] == 0 && p[2] == 0).count();
    assert!(red > 100, "{red} red pixels in the diff image");
    let new = image::open(golden.join("spot-camera.new.png")).unwrap().to_rgb8();
    assert_ne!(new, image::open(golden.join("spot-camera.png")).unwrap().to_rgb8());
    // JUnit: seven cases, one failure.
    let xml = fs::read_to_string(dir.path().join("report.xml")).unwrap();
    assert!(xml.contains("tests=\"7\" failures=\"1\" errors=\"0\""), "{xml}");
    assert_eq!(xml.matches("<testcase ").count(), 7);
    assert!(xml.contains("<failure message=\"differs in"), "{xml}");

    // Within a tolerance wide enough for the whole change it matches; --update accepts it and tidies up.
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden", "--check", "--tolerance", "1"]);
    assert_eq!(code, Some(0), "{stdout}");
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden", "--update"]);
    assert_eq!(code, Some(0), "{stdout}");
    assert!(stdout.contains("6 matching, 1 updated"), "{stdout}");
    assert_eq!(names(&golden).len(), 7, "the .new and .diff pictures are gone");
    let (code, _, _) = snapshot(dir.path(), &["models", "--out", "golden", "--check"]);
    assert_eq!(code, Some(0));
}

#[test]
fn bad_input_fails_its_own_row_and_the_other_files_are_drawn() {
    let dir = tempfile::tempdir().unwrap();
    models(dir.path());
    // A model that cannot be read among good ones.
    fs::write(dir.path().join("models/broken.obj"), "v 0 0 0\nf 1 2 3\n").unwrap();
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden"]);
    assert_eq!(code, Some(1), "{stdout}");
    let row = stdout.lines().find(|l| l.contains("broken.obj")).expect("a row for the broken model");
    assert!(row.contains("| - |") && row.contains("error:"), "{row}");
    assert!(stdout.contains("8 pictures: 7 written, 1 failed"), "{stdout}");
    fs::remove_file(dir.path().join("models/broken.obj")).unwrap();

    // A golden of the wrong size: a mismatch without a diff image; the others match.
    let golden = dir.path().join("golden");
    let small = image::RgbImage::new(8, 8);
    small.save(golden.join("cube-front.png")).unwrap();
    // A golden that cannot be read: a row of its own.
    fs::write(golden.join("cube-side.png"), b"not a png").unwrap();
    // A picture that cannot be written (a folder in its place).
    fs::remove_file(golden.join("tetrahedron-side.png")).unwrap();
    fs::create_dir(golden.join("tetrahedron-side.new.png")).unwrap();
    let (code, stdout, _) = snapshot(dir.path(), &["models", "--out", "golden", "--check"]);
    assert_eq!(code, Some(1), "{stdout}");
    let row = |view: &str| stdout.lines().find(|l| l.contains(view)).map(str::to_owned).unwrap_or_default();
    assert!(row("| front |").contains("the stored picture is 8x8, the new one 64x48"), "{stdout}");
    assert!(!golden.join("cube-front.diff.png").exists() && golden.join("cube-front.new.png").exists());
    assert!(row("cube.obj | side").contains("cannot read the stored picture"), "{stdout}");
    assert!(row("tetrahedron.stl | side").contains("error:"), "{stdout}");
    assert!(stdout.contains("7 pictures: 4 matching, 1 differing, 2 failed"), "{stdout}");

    // A folder of pictures that cannot be made (a file in its way): an error naming it.
    fs::write(dir.path().join("taken"), b"").unwrap();
    let (code, _, stderr) = snapshot(dir.path(), &["models", "--out", "taken/pictures"]);
    assert_eq!(code, Some(1));
    assert!(stderr.contains("taken/pictures"), "{stderr}");
    // Nothing to draw.
    fs::create_dir(dir.path().join("empty")).unwrap();
    let (code, _, stderr) = snapshot(dir.path(), &["empty"]);
    assert_eq!(code, Some(1));
    assert!(stderr.contains("no model or scene file"), "{stderr}");
}

#[test]
fn wildcards_views_around_and_thumbnails() {
    let dir = tempfile::tempdir().unwrap();
    models(dir.path());
    // A name with a wildcard, expanded by rastty; four views around.
    let (code, stdout, _) = snapshot(dir.path(), &["models/*.obj", "--out", "around", "--views", "4"]);
    assert_eq!(code, Some(0), "{stdout}");
    assert_eq!(
        names(&dir.path().join("around")),
        ["cube-turn-000.png", "cube-turn-090.png", "cube-turn-180.png", "cube-turn-270.png"]
    );
    // Thumbnails: one view of each model.
    let output =
        rastty_in(dir.path(), &["snapshot", "models", "--out", "thumbnails", "--views", "1", "--size", "32x32"]);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stdout));
    let thumbnails = names(&dir.path().join("thumbnails"));
    assert_eq!(thumbnails, ["cube-turn-000.png", "spot-turn-000.png", "tetrahedron-turn-000.png"]);
    let picture = image::open(dir.path().join("thumbnails/cube-turn-000.png")).unwrap();
    assert_eq!((picture.width(), picture.height()), (32, 32));
    // Bad options are refused before anything is drawn.
    for bad in [["--views", "0"], ["--tolerance", "-1"], ["--tolerance", "0.1:x"]] {
        let (code, _, stderr) = snapshot(dir.path(), &["models", bad[0], bad[1]]);
        assert_eq!(code, Some(2), "{bad:?}: {stderr}");
    }
}

#[test]
fn the_stored_pictures_of_the_example_scenes_pass_their_check() {
    // tests/snapshots/command/ holds `rastty snapshot` pictures of three example scenes at 96x72, each through its
    // own camera; a copy is checked, so that a failure writes its .new and .diff pictures outside the repository.
    let root = common::root();
    let dir = tempfile::tempdir().unwrap();
    let stored = root.join("tests/snapshots/command");
    for entry in fs::read_dir(&stored).unwrap() {
        let path = entry.unwrap().path();
        fs::copy(&path, dir.path().join(path.file_name().unwrap())).unwrap();
    }
    let scenes: Vec<String> = ["spot_sun", "spot_studio", "spot_herd"]
        .iter()
        .map(|name| root.join(format!("assets/scenes/{name}.toml")).display().to_string())
        .collect();
    let out = dir.path().display().to_string();
    let mut args = vec!["snapshot", "--size", "96x72", "--check", "--out", out.as_str()];
    args.extend(scenes.iter().map(String::as_str));
    let output = rastty_in(dir.path(), &args);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}{}", String::from_utf8_lossy(&output.stderr));
    assert!(stdout.contains("3 pictures: 3 matching"), "{stdout}");
    assert_eq!(names(dir.path()), names(&stored), "nothing written beside the stored pictures");
}
