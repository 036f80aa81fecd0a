//! STL models made by the test itself from Spot's OBJ file: binary with the `stl_io` crate's writer (an
//! independent encoder), ASCII by hand. Each must give Spot's own triangles, and the same depth picture.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use rastty_core::math::Vec3;
use rastty_scene::model::{Model, ModelOptions, load_model};

/// Spot's OBJ file in the repository.
fn spot_obj() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/spot/spot.obj")
}

/// The corners of every triangle of `model`, in order.
fn corners(model: &Model) -> Vec<Vec3> {
    model.indices.iter().map(|&i| model.positions[i as usize]).collect()
}

/// Spot as STL in `dir`: `spot.stl` (binary, by `stl_io`) and `spot_ascii.stl` (by hand, `{}` writing the
/// shortest decimal that reads back as the same `f32`).
fn write_spot_stl(dir: &Path) -> Model {
    let spot = load_model(spot_obj(), &ModelOptions::default()).expect("Spot's OBJ");
    let triangles: Vec<stl_io::Triangle> = corners(&spot)
        .chunks_exact(3)
        .map(|t| stl_io::Triangle {
            normal: stl_io::Normal::new([0.0; 3]),
            vertices: [t[0], t[1], t[2]].map(|p| stl_io::Vertex::new([p.x, p.y, p.z])),
        })
        .collect();
    let mut binary = fs::File::create(dir.join("spot.stl")).unwrap();
    stl_io::write_stl(&mut binary, triangles.iter()).expect("write the binary STL");
    let mut ascii = String::from("solid spot\n");
    for t in &triangles {
        ascii.push_str("  facet normal 0 0 0\n    outer loop\n");
        for v in &t.vertices {
            let _ = writeln!(ascii, "      vertex {} {} {}", v[0], v[1], v[2]);
        }
        ascii.push_str("    endloop\n  endfacet\n");
    }
    ascii.push_str("endsolid spot\n");
    fs::write(dir.join("spot_ascii.stl"), ascii).unwrap();
    spot
}

#[test]
fn spot_as_binary_and_ascii_stl_has_the_triangles_of_its_obj() {
    let dir = tempfile::tempdir().unwrap();
    let spot = write_spot_stl(dir.path());
    for name in ["spot.stl", "spot_ascii.stl"] {
        for smooth_angle in [None, Some(45.0)] {
            let model = load_model(dir.path().join(name), &ModelOptions { smooth_angle }).expect(name);
            assert_eq!(corners(&model), corners(&spot), "{name}, {smooth_angle:?}");
            assert!(model.warnings.is_empty() && model.uvs.is_none(), "{name}");
            assert!(model.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5), "{name}: unit normals");
        }
    }
    // Flat: no two faces with different normals share a vertex; smooth at 45 degrees: most corners are shared.
    let flat = load_model(dir.path().join("spot.stl"), &ModelOptions::default()).unwrap();
    let smooth = load_model(dir.path().join("spot.stl"), &ModelOptions { smooth_angle: Some(45.0) }).unwrap();
    assert!(
        smooth.positions.len() * 3 < flat.positions.len(),
        "{} against {}",
        smooth.positions.len(),
        flat.positions.len()
    );
}

/// `rastty ARGS` in `dir`; panics unless it succeeds.
fn rastty(dir: &Path, args: &[&str]) {
    let output = Command::new(env!("CARGO_BIN_EXE_rastty"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("the rastty binary runs");
    assert!(output.status.success(), "rastty {args:?}: {}", String::from_utf8_lossy(&output.stderr));
}

#[test]
fn spot_from_obj_and_stl_gives_the_same_depth_picture() {
    let dir = tempfile::tempdir().unwrap();
    write_spot_stl(dir.path());
    let obj = spot_obj();
    let picture = |model: &str, out: &str| {
        rastty(dir.path(), &["render", model, "-o", out, "--shading", "depth", "--size", "160x120"]);
        image::open(dir.path().join(out)).expect("a PNG").to_rgb8().into_raw()
    };
    let from_obj = picture(obj.to_str().unwrap(), "obj.png");
    assert!(from_obj.chunks_exact(3).collect::<std::collections::HashSet<_>>().len() > 20, "a picture of Spot");
    assert!(from_obj == picture("spot.stl", "stl.png"), "the binary STL's depth picture differs from the OBJ's");
    assert!(from_obj == picture("spot_ascii.stl", "ascii.png"), "the ASCII STL's depth picture differs");
    // Smooth normals change the shaded picture, not the depth.
    rastty(dir.path(), &["render", "spot.stl", "-o", "smooth.png", "--smooth-angle", "60", "--size", "160x120"]);
    rastty(dir.path(), &["render", "spot.stl", "-o", "flat.png", "--size", "160x120"]);
    let read = |name: &str| image::open(dir.path().join(name)).unwrap().to_rgb8().into_raw();
    assert!(read("smooth.png") != read("flat.png"), "--smooth-angle changed nothing");
}

#[test]
fn a_scene_places_the_same_stl_flat_and_smooth() {
    let dir = tempfile::tempdir().unwrap();
    write_spot_stl(dir.path());
    let scene = |second: &str| {
        let light = "[[lights]]\ntype = \"directional\"\ndirection = [-0.5, -1, -0.7]\n\n";
        format!(
            "{light}[[objects]]\nmesh = \"spot.stl\"\n\n[[objects]]\nmesh = \"spot.stl\"\ntranslate = [1.5, 0, 0]\n{second}"
        )
    };
    fs::write(dir.path().join("flat.toml"), scene("")).unwrap();
    fs::write(dir.path().join("mixed.toml"), scene("smooth_angle = 40\n")).unwrap();
    let picture = |name: &str| {
        rastty(dir.path(), &["render", name, "-o", "out.png", "--size", "160x120"]);
        image::open(dir.path().join("out.png")).expect("a PNG").to_rgb8().into_raw()
    };
    // The second Spot, smoothed, is a second mesh from the same file: the picture changes.
    assert!(picture("flat.toml") != picture("mixed.toml"), "smooth_angle in a scene changed nothing");
}
