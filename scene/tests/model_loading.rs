//! Loading OBJ models, MTL materials and textures: every face form, indices, parts, normals, texture formats,
//! errors with their lines, and no panic on any input.

use std::fs;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::{DynamicImage, ImageFormat};
use proptest::prelude::*;
use rastty_core::math::{Vec2, Vec3};
use rastty_scene::model::{
    COORDINATE_LIMIT, DEFAULT_DIFFUSE, Element, Embedded, FALLBACK_NORMAL, LoadError, LoadErrorKind, Model,
    ModelOptions, NoFiles, TextureImage, load_model, load_obj_bytes,
};

// ---------------------------------------------------------------------------------------------------------------
// Helpers

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

/// Writes `obj` as `model.obj` (next to `files`) and loads it from the file system.
fn load_with(obj: &str, files: &[(&str, &[u8])]) -> Result<Model, LoadError> {
    let mut all = files.to_vec();
    all.push(("model.obj", obj.as_bytes()));
    let dir = dir_with(&all);
    load_model(dir.path().join("model.obj"), &ModelOptions::default())
}

fn load(obj: &str) -> Model {
    load_with(obj, &[]).unwrap_or_else(|e| panic!("{e}"))
}

fn load_err(obj: &str) -> LoadError {
    load_obj_bytes("bad.obj", obj.as_bytes(), &NoFiles).expect_err("the OBJ should be refused")
}

/// The positions of each triangle's corners.
fn triangles(m: &Model) -> Vec<[Vec3; 3]> {
    m.indices.chunks_exact(3).map(|t| [0, 1, 2].map(|k| m.positions[t[k] as usize])).collect()
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-5
}

/// Structural invariants every loaded model must satisfy.
fn assert_consistent(m: &Model) {
    let n = m.positions.len();
    assert_eq!(m.normals.len(), n);
    if let Some(uvs) = &m.uvs {
        assert_eq!(uvs.len(), n);
        assert!(uvs.iter().all(|t| t.is_finite()));
    }
    assert!(!m.indices.is_empty() && m.indices.len() % 3 == 0);
    assert!(m.indices.iter().all(|&i| (i as usize) < n));
    assert!(m.positions.iter().all(|p| p.is_finite() && p.x.abs().max(p.y.abs()).max(p.z.abs()) <= COORDINATE_LIMIT));
    assert!(m.normals.iter().all(|v| v.is_finite()));
    let mut next = 0;
    for (i, part) in m.parts.iter().enumerate() {
        assert_eq!(part.indices.start, next);
        assert!(part.indices.len() % 3 == 0 && !part.indices.is_empty());
        next = part.indices.end;
        assert!(part.material.is_none_or(|k| k < m.materials.len()));
        assert!(m.part_mesh(i).is_some());
    }
    assert_eq!(next, m.indices.len());
    for w in &m.warnings {
        assert!(!w.chars().any(char::is_control), "{w:?}");
    }
}

const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nvn 0 1 0\n";

fn png(image: DynamicImage) -> Vec<u8> {
    let mut out = Vec::new();
    image.write_to(&mut Cursor::new(&mut out), ImageFormat::Png).unwrap();
    out
}

/// A 2x1 PNG: red, then blue.
fn red_blue_png() -> Vec<u8> {
    png(DynamicImage::ImageRgb8(image::RgbImage::from_raw(2, 1, vec![255, 0, 0, 0, 0, 255]).unwrap()))
}

// ---------------------------------------------------------------------------------------------------------------
// Face forms and indices

#[test]
fn face_with_positions_only_has_no_uvs_and_computed_normals() {
    let m = load(&format!("{SQUARE}f 1 2 3\n"));
    assert_consistent(&m);
    assert_eq!(m.triangle_count(), 1);
    assert!(m.uvs.is_none());
    assert_eq!(m.normals, [Vec3::Z; 3]);
    assert_eq!(triangles(&m), [[Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0)]]);
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
}

#[test]
fn face_with_texture_coordinates_keeps_them_per_vertex() {
    let m = load(&format!("{SQUARE}f 1/1 2/2 3/3\n"));
    assert_consistent(&m);
    let uvs = m.uvs.as_ref().unwrap();
    // The square's texture coordinates equal its x and y.
    for (p, t) in m.positions.iter().zip(uvs) {
        assert_eq!(Vec2::new(p.x, p.y), *t);
    }
}

#[test]
fn face_with_normals_keeps_the_files_normals() {
    // The file's normal (0, 1, 0) is not the face's geometric normal, so it must come from the file.
    let m = load(&format!("{SQUARE}f 1//2 2//2 3//2\n"));
    assert_consistent(&m);
    assert!(m.uvs.is_none());
    assert_eq!(m.normals, [Vec3::Y; 3]);
    assert!(m.warnings.is_empty());
}

#[test]
fn face_with_all_three_indices() {
    let m = load(&format!("{SQUARE}f 1/1/2 2/2/2 3/3/2\n"));
    assert_consistent(&m);
    assert_eq!(m.normals, [Vec3::Y; 3]);
    let uvs = m.uvs.as_ref().unwrap();
    for (p, t) in m.positions.iter().zip(uvs) {
        assert_eq!(Vec2::new(p.x, p.y), *t);
    }
}

#[test]
fn negative_indices_count_back_from_the_last_element_defined() {
    let absolute = load(&format!("{SQUARE}f 1/1/1 2/2/1 3/3/1\n"));
    let relative = load(&format!("{SQUARE}f -4/-4/-2 -3/-3/-2 -2/-2/-2\n"));
    assert_eq!(triangles(&absolute), triangles(&relative));
    assert_eq!(absolute.uvs, relative.uvs);
    assert_eq!(absolute.normals, relative.normals);

    // Relative to the point of the face, not the end of the file.
    let m = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf -3 -2 -1\n");
    let t = triangles(&m);
    assert_eq!(t[0], [Vec3::ZERO, Vec3::X, Vec3::Y]);
    assert_eq!(t[1], [Vec3::new(5.0, 0.0, 0.0), Vec3::new(6.0, 0.0, 0.0), Vec3::new(5.0, 1.0, 0.0)]);
}

#[test]
fn quads_and_polygons_are_fanned_into_triangles_keeping_the_winding() {
    let quad = load(&format!("{SQUARE}f 1 2 3 4\n"));
    assert_consistent(&quad);
    assert_eq!(quad.triangle_count(), 2);
    let p = |x: f32, y: f32| Vec3::new(x, y, 0.0);
    assert_eq!(triangles(&quad), [[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)], [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]]);

    let pentagon = load("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 3 0\nv -1 1 0\nf 1 2 3 4 5\n");
    assert_consistent(&pentagon);
    assert_eq!(pentagon.triangle_count(), 3);
    for [a, b, c] in triangles(&pentagon) {
        assert!((b - a).cross(c - a).z > 0.0, "every triangle keeps the counter-clockwise winding");
        assert_eq!(a, Vec3::ZERO, "a fan from the first vertex");
    }
    assert!(pentagon.normals.iter().all(|&n| n == Vec3::Z));
}

#[test]
fn faces_with_fewer_than_three_vertices_and_polylines_are_ignored() {
    let m = load(&format!("{SQUARE}f 1 2\nf 3\nl 1 2 3 4\nf 1 2 3\n"));
    assert_eq!(m.triangle_count(), 1, "the polyline of four vertices is not a face");
    assert_eq!(m.warnings.len(), 1, "{:?}", m.warnings);
    assert!(m.warnings[0].contains("2 face(s) with fewer than 3 vertices ignored, the first at line 11"));
}

#[test]
fn vertex_colours_and_w_are_accepted() {
    // tobj alone fails when only some vertices have colours; the loader drops colours.
    let m = load("v 0 0 0 1 0 0\nv 2 0 0 2\nv 0 1 0\nf 1 2 3\n");
    assert_consistent(&m);
    assert_eq!(triangles(&m), [[Vec3::ZERO, Vec3::X, Vec3::Y]], "w divides the coordinates");
}

#[test]
fn a_texture_coordinate_of_one_number_has_v_zero() {
    let m = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25\nvt 0.5 1\nf 1/1 2/2 3/1\n");
    assert_eq!(m.uvs.unwrap(), [Vec2::new(0.25, 0.0), Vec2::new(0.5, 1.0), Vec2::new(0.25, 0.0)]);
}

#[test]
fn windows_line_endings_and_indentation_are_fine() {
    let m = load("  v 0 0 0\r\n\tv 1 0 0\r\nv 0 1 0\r\n  g  indented\r\nf 1 2 3\r\n");
    assert_eq!(m.parts[0].name, "indented");
}

// ---------------------------------------------------------------------------------------------------------------
// Objects, groups and parts

#[test]
fn objects_and_groups_become_parts_over_one_vertex_array() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
               f 1 2 3\n\
               o first\nf 1 2 4\n\
               g second\nf 2 3 4\nf 1 3 4\n\
               o empty\n\
               g\nf 4 3 2\n";
    let m = load(obj);
    assert_consistent(&m);
    let names: Vec<&str> = m.parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["unnamed_object", "first", "second", "unnamed_object"]);
    let ranges: Vec<_> = m.parts.iter().map(|p| p.indices.clone()).collect();
    assert_eq!(ranges, [0..3, 3..6, 6..12, 12..15]);
    let v = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    assert_eq!(
        triangles(&m),
        [[v[0], v[1], v[2]], [v[0], v[1], v[3]], [v[1], v[2], v[3]], [v[0], v[2], v[3]], [v[3], v[2], v[1]]]
    );
    // Each part's mesh draws exactly its triangles.
    let second = m.part_mesh(2).unwrap();
    assert_eq!(second.triangle_count(), 2);
    let [a, b, c] = second.triangle(1).unwrap().map(|i| second.position(i));
    assert_eq!([a, b, c], [v[0], v[2], v[3]]);
}

#[test]
fn a_material_change_inside_an_object_starts_a_part_of_the_same_name() {
    let mtl = b"newmtl red\nKd 1 0 0\nnewmtl green\nKd 0 1 0\n";
    let obj = format!("mtllib m.mtl\n{SQUARE}o box\nusemtl red\nf 1 2 3\nusemtl green\nf 1 3 4\nusemtl red\nf 2 3 4\n");
    let m = load_with(&obj, &[("m.mtl", mtl)]).unwrap();
    assert_consistent(&m);
    let parts: Vec<(&str, Option<usize>)> = m.parts.iter().map(|p| (p.name.as_str(), p.material)).collect();
    assert_eq!(parts, [("box", Some(0)), ("box", Some(1)), ("box", Some(0))]);
    assert_eq!(m.part_material(1).unwrap().diffuse, Vec3::Y);
}

#[test]
fn names_keep_control_characters_raw() {
    let m = load("v 0 0 0\nv 1 0 0\nv 0 1 0\no evil\u{1b}[31mname\u{7}\nf 1 2 3\n");
    assert_eq!(m.parts[0].name, "evil\u{1b}[31mname\u{7}");
}

// ---------------------------------------------------------------------------------------------------------------
// Normals and texture coordinates

#[test]
fn missing_normals_are_smooth_and_area_weighted() {
    // A roof: a wide slope (cross product (1, 0, 2) per triangle) and a narrow one ((-1, 0, 0.5) per triangle)
    // meet at the ridge z = 1. Every ridge vertex touches as many triangles of each slope, so the area-weighted sum
    // points straight up; averaging unit face normals instead would tilt it towards -x.
    let obj = "v 0 0 1\nv 0 1 1\nv 2 0 0\nv 2 1 0\nv -0.5 0 0\nv -0.5 1 0\nf 1 3 4 2\nf 1 2 6 5\n";
    let m = load(obj);
    assert_consistent(&m);
    let wide = Vec3::new(1.0, 0.0, 2.0).try_normalize().unwrap();
    let narrow = Vec3::new(-1.0, 0.0, 0.5).try_normalize().unwrap();
    for (p, n) in m.positions.iter().zip(&m.normals) {
        let expected = if p.x == 0.0 {
            Vec3::Z
        } else if p.x > 0.0 {
            wide
        } else {
            narrow
        };
        assert!(close(*n, expected), "{p:?}: {n:?} vs {expected:?}");
    }
    let unweighted = (wide + narrow).try_normalize().unwrap();
    assert!(!close(unweighted, Vec3::Z));
}

#[test]
fn partial_normals_give_smooth_normals_for_all_with_a_warning() {
    // The file normal (0, 1, 0) is wrong on purpose: it must be replaced by the computed one.
    let m = load(&format!("{SQUARE}f 1//2 2//2 3//2\nf 1 3 4\n"));
    assert_consistent(&m);
    assert!(m.normals.iter().all(|&n| close(n, Vec3::Z)), "{:?}", m.normals);
    assert_eq!(m.warnings.len(), 1);
    assert!(m.warnings[0].contains("normals are given for only some vertices"), "{:?}", m.warnings);
}

#[test]
fn degenerate_faces_give_the_fallback_normal() {
    let m = load("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    assert_eq!(m.normals, [FALLBACK_NORMAL; 3]);
}

#[test]
fn parts_without_texture_coordinates_get_zero() {
    let obj = format!("{SQUARE}o textured\nf 1/1 2/2 3/3\no plain\nf 1 3 4\n");
    let m = load(&obj);
    assert_consistent(&m);
    let uvs = m.uvs.as_ref().unwrap();
    let plain = m.part_mesh(1).unwrap();
    for t in 0..plain.triangle_count() {
        for i in plain.triangle(t).unwrap() {
            assert_eq!(uvs[i], Vec2::ZERO);
        }
    }
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
    assert!(m.part_mesh(0).unwrap().attributes().uvs);
}

#[test]
fn a_part_with_texture_coordinates_for_some_vertices_gets_zero_and_a_warning() {
    let m = load(&format!("{SQUARE}o mixed\nf 1/1 2/2 3/3\nf 1 3 4\n"));
    assert_consistent(&m);
    assert!(m.uvs.is_none(), "no part has a full set");
    assert!(m.warnings.iter().any(|w| w.contains("part \"mixed\" has texture coordinates for only some vertices")));
}

#[test]
fn texture_coordinates_defined_but_unused_mean_no_uvs() {
    let m = load(&format!("{SQUARE}f 1 2 3\n"));
    assert!(m.uvs.is_none());
}

// ---------------------------------------------------------------------------------------------------------------
// Materials

#[test]
fn mtl_colours_and_textures_resolve_relative_to_the_mtl_file() {
    let mtl = b"# materials\nnewmtl red\nKd 1 0 0\n\nnewmtl plain\nKs 1 1 1\n\nnewmtl wood\nKd 0.5 0.25 1\n\
                map_Kd -s 1 1 1 textures/wood.png\n";
    let decoy = png(DynamicImage::ImageRgb8(image::RgbImage::from_raw(1, 1, vec![0, 255, 0]).unwrap()));
    let obj = format!(
        "mtllib mats/lib.mtl\n{SQUARE}usemtl red\nf 1/1 2/2 3/3\nusemtl plain\nf 1/1 3/3 4/4\nusemtl wood\nf 4/4 2/2 3/3\n"
    );
    let m = load_with(
        &obj,
        &[("mats/lib.mtl", mtl), ("mats/textures/wood.png", &red_blue_png()), ("textures/wood.png", &decoy)],
    )
    .unwrap();
    assert_consistent(&m);
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
    let names: Vec<&str> = m.materials.iter().map(|x| x.name.as_str()).collect();
    assert_eq!(names, ["red", "plain", "wood"]);
    assert_eq!(m.materials[0].diffuse, Vec3::X);
    assert_eq!(m.materials[1].diffuse, DEFAULT_DIFFUSE);
    assert_eq!(m.materials[2].diffuse, Vec3::new(0.5, 0.25, 1.0));
    let texture = m.materials[2].texture.as_ref().expect("the wood texture");
    assert_eq!((texture.width, texture.height), (2, 1));
    assert_eq!(texture.texels, [0xFF0000, 0x0000FF], "the texture next to the MTL file, not the decoy");
    assert!(texture.texture().is_ok());
    assert!(m.materials[0].texture.is_none());
}

#[test]
fn a_missing_mtl_is_a_warning_and_parts_use_the_default_material() {
    let m = load_with(&format!("mtllib gone.mtl\n{SQUARE}usemtl red\nf 1 2 3\n"), &[]).unwrap();
    assert_consistent(&m);
    assert!(m.materials.is_empty());
    assert_eq!(m.parts[0].material, None);
    assert_eq!(m.warnings.len(), 2, "{:?}", m.warnings);
    assert!(m.warnings[0].contains("gone.mtl: cannot read the material library: No such file"), "{:?}", m.warnings);
    assert!(m.warnings[1].contains("line 12: usemtl \"red\": no such material"), "{:?}", m.warnings);
}

#[test]
fn bad_mtl_statements_are_warnings_with_their_line() {
    let mtl = b"newmtl red\nKd 1 0 0\nNs very shiny\nnewmtl half\nKd 0.5\nKa 1 2\n";
    let m = load_with(&format!("mtllib m.mtl\n{SQUARE}usemtl half\nf 1 2 3\n"), &[("m.mtl", mtl)]).unwrap();
    assert_consistent(&m);
    assert_eq!(m.materials.len(), 2);
    assert_eq!(m.materials[1].diffuse, Vec3::splat(0.5), "`Kd r` means `Kd r r r`");
    assert_eq!(m.warnings.len(), 2, "{:?}", m.warnings);
    assert!(m.warnings[0].contains("m.mtl, line 3: Ns needs a number"), "{:?}", m.warnings);
    assert!(m.warnings[1].contains("m.mtl, line 6: Ka needs three numbers"), "{:?}", m.warnings);
}

#[test]
fn binary_garbage_as_mtl_loads_no_material_without_failing() {
    let m = load_with(&format!("mtllib m.mtl\n{SQUARE}usemtl x\nf 1 2 3\n"), &[("m.mtl", &[0xFF, 0, 0x1B, 10, 200])])
        .unwrap();
    assert_consistent(&m);
    assert!(m.materials.is_empty());
}

#[test]
fn a_missing_texture_is_a_warning_naming_the_file_and_the_reason() {
    let mtl = b"newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd wood.png\n";
    let m = load_with(&format!("mtllib m.mtl\n{SQUARE}usemtl wood\nf 1/1 2/2 3/3\n"), &[("m.mtl", mtl)]).unwrap();
    assert_consistent(&m);
    assert!(m.materials[0].texture.is_none());
    assert_eq!(m.materials[0].diffuse, Vec3::splat(0.5));
    assert_eq!(m.warnings.len(), 1, "{:?}", m.warnings);
    let w = &m.warnings[0];
    assert!(w.contains("wood.png: cannot read the file: No such file or directory"), "{w}");
    assert!(w.ends_with("material \"wood\" is drawn untextured"), "{w}");
}

#[test]
fn a_corrupt_texture_is_a_warning_naming_the_file_and_the_reason() {
    let mtl = b"newmtl a\nmap_Kd a.png\nnewmtl b\nmap_Kd b.tga\n";
    let mut truncated = red_blue_png();
    truncated.truncate(truncated.len() / 2);
    let obj = format!("mtllib m.mtl\n{SQUARE}usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n");
    let m = load_with(&obj, &[("m.mtl", mtl), ("a.png", &truncated), ("b.tga", b"garbage")]).unwrap();
    assert_consistent(&m);
    assert!(m.materials.iter().all(|x| x.texture.is_none()));
    assert_eq!(m.warnings.len(), 2, "{:?}", m.warnings);
    assert!(m.warnings[0].contains("a.png: cannot decode the image: "), "{:?}", m.warnings);
    assert!(m.warnings[1].contains("b.tga: cannot decode the image: "), "{:?}", m.warnings);
}

#[test]
fn textures_are_not_loaded_for_models_without_texture_coordinates_or_unused_materials() {
    let mtl = b"newmtl used\nmap_Kd gone1.png\nnewmtl unused\nmap_Kd gone2.png\n";
    let m = load_with(&format!("mtllib m.mtl\n{SQUARE}usemtl used\nf 1 2 3\n"), &[("m.mtl", mtl)]).unwrap();
    assert_eq!(m.warnings.len(), 1, "{:?}", m.warnings);
    assert!(m.warnings[0].contains("gone1.png: texture of material \"used\" not loaded: the model has no texture"));
}

#[test]
fn a_texture_can_be_given_for_a_model_without_materials() {
    let mut m = load(&format!("{SQUARE}f 1/1 2/2 3/3\n"));
    let dir = dir_with(&[("t.png", &red_blue_png())]);
    m.set_texture(TextureImage::load(dir.path().join("t.png")).unwrap());
    assert_eq!(m.part_material(0).unwrap().texture.as_ref().unwrap().texels, [0xFF0000, 0x0000FF]);
}

// ---------------------------------------------------------------------------------------------------------------
// Texture formats

/// The 3 x 2 test image, top row first: red red green / blue white white.
const TOP_ROW: [[u8; 3]; 3] = [[255, 0, 0], [255, 0, 0], [0, 255, 0]];
const BOTTOM_ROW: [[u8; 3]; 3] = [[0, 0, 255], [255, 255, 255], [255, 255, 255]];
const EXPECTED: [u32; 6] = [0xFF0000, 0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF, 0xFFFFFF];

fn bgr(p: [u8; 3]) -> [u8; 3] {
    [p[2], p[1], p[0]]
}

/// Run-length encodes one row: runs as run packets, other pixels as raw packets.
fn rle_row(row: &[[u8; 3]], out: &mut Vec<u8>) {
    let mut i = 0;
    while i < row.len() {
        let mut run = 1;
        while i + run < row.len() && row[i + run] == row[i] {
            run += 1;
        }
        if run > 1 {
            out.push(0x80 | (run - 1) as u8);
            out.extend(bgr(row[i]));
            i += run;
        } else {
            let start = i;
            while i < row.len() && !(i + 1 < row.len() && row[i + 1] == row[i]) {
                i += 1;
            }
            out.push((i - start - 1) as u8);
            for &p in &row[start..i] {
                out.extend(bgr(p));
            }
        }
    }
}

/// A hand-made 24-bit TGA of the test image.
fn tga(rle: bool, top_origin: bool) -> Vec<u8> {
    let kind = if rle { 10 } else { 2 };
    let descriptor = if top_origin { 0x20 } else { 0x00 };
    let mut b = vec![0, 0, kind, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 2, 0, 24, descriptor];
    let rows = if top_origin { [TOP_ROW, BOTTOM_ROW] } else { [BOTTOM_ROW, TOP_ROW] };
    for row in rows {
        if rle {
            rle_row(&row, &mut b);
        } else {
            row.iter().for_each(|&p| b.extend(bgr(p)));
        }
    }
    b
}

#[test]
fn tga_in_all_four_combinations_of_compression_and_origin() {
    for rle in [false, true] {
        for top_origin in [false, true] {
            let bytes = tga(rle, top_origin);
            assert_eq!(bytes.len() < 18 + 18, rle, "the RLE data is shorter");
            let t = TextureImage::decode(Path::new("t.tga"), &bytes)
                .unwrap_or_else(|e| panic!("rle {rle}, top {top_origin}: {e}"));
            assert_eq!((t.width, t.height), (3, 2));
            assert_eq!(t.texels, EXPECTED, "rle {rle}, top origin {top_origin}");
        }
    }
}

#[test]
fn tga_through_a_model_and_its_mtl() {
    let mtl = b"newmtl skin\nmap_Kd skin.tga\n";
    let files: [(&str, &[u8]); 2] = [("m.mtl", mtl), ("skin.tga", &tga(true, false))];
    let m = load_with(&format!("mtllib m.mtl\n{SQUARE}usemtl skin\nf 1/1 2/2 3/3\n"), &files).unwrap();
    assert_eq!(m.materials[0].texture.as_ref().unwrap().texels, EXPECTED);
}

#[test]
fn tga_alpha_grey_and_palette() {
    // 32-bit BGRA, top-left origin, 8 alpha bits: colour kept, alpha 0x40 as the transparency 0xBF on top.
    let bgra = [0u8, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 32, 0x28, 0x10, 0x20, 0x30, 0x40];
    assert_eq!(TextureImage::decode(Path::new("a.tga"), &bgra).unwrap().texels, [0xBF30_2010]);
    // 8-bit grey.
    let grey = [0u8, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 1, 0, 8, 0x20, 0, 128, 255];
    assert_eq!(TextureImage::decode(Path::new("g.tga"), &grey).unwrap().texels, [0, 0x808080, 0xFFFFFF]);
    // Colour-mapped: a 2-entry 24-bit palette (red, blue), pixels 1, 0.
    let mapped = [0u8, 1, 1, 0, 0, 2, 0, 24, 0, 0, 0, 0, 2, 0, 1, 0, 8, 0x20, 0, 0, 255, 255, 0, 0, 1, 0];
    assert_eq!(TextureImage::decode(Path::new("p.tga"), &mapped).unwrap().texels, [0x0000FF, 0xFF0000]);
}

#[test]
fn png_colour_types_are_converted() {
    let rgba =
        png(DynamicImage::ImageRgba8(image::RgbaImage::from_raw(2, 1, vec![10, 20, 30, 0, 40, 50, 60, 255]).unwrap()));
    // Alpha kept as the transparency 255 - alpha in the top byte: opaque texels are 0x00RRGGBB.
    assert_eq!(TextureImage::decode(Path::new("a.png"), &rgba).unwrap().texels, [0xFF0A_141E, 0x0028_323C]);
    let grey = png(DynamicImage::ImageLuma8(image::GrayImage::from_raw(2, 1, vec![0, 200]).unwrap()));
    assert_eq!(TextureImage::decode(Path::new("g.png"), &grey).unwrap().texels, [0, 0xC8C8C8]);
    let grey_alpha = png(DynamicImage::ImageLumaA8(image::GrayAlphaImage::from_raw(1, 1, vec![7, 9]).unwrap()));
    assert_eq!(TextureImage::decode(Path::new("ga.png"), &grey_alpha).unwrap().texels, [0xF607_0707]);
    let deep = png(DynamicImage::ImageRgb16(image::ImageBuffer::from_raw(1, 1, vec![0xFFFF, 0, 0x8080]).unwrap()));
    assert_eq!(TextureImage::decode(Path::new("d.png"), &deep).unwrap().texels, [0xFF0080]);

    // Palette, written with the png crate (image's encoder writes no palettes).
    let mut palette_png = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut palette_png, 3, 1);
        encoder.set_color(png::ColorType::Indexed);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_palette(vec![255, 0, 0, 0, 255, 0, 0, 0, 255]);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&[2, 1, 0]).unwrap();
    }
    assert_eq!(TextureImage::decode(Path::new("p.png"), &palette_png).unwrap().texels, [0x0000FF, 0x00FF00, 0xFF0000]);
}

#[test]
fn jpeg_decodes_to_about_the_right_colour() {
    let solid = image::RgbImage::from_pixel(16, 16, image::Rgb([200, 100, 50]));
    let mut jpeg = Vec::new();
    image::codecs::jpeg::JpegEncoder::new_with_quality(&mut jpeg, 95).encode_image(&solid).unwrap();
    // A misleading extension does not matter: the JPEG signature wins.
    let t = TextureImage::decode(Path::new("photo.png"), &jpeg).unwrap();
    assert_eq!((t.width, t.height), (16, 16));
    for texel in t.texels {
        let [_, r, g, b] = texel.to_be_bytes();
        assert!(r.abs_diff(200) <= 6 && g.abs_diff(100) <= 6 && b.abs_diff(50) <= 6, "{texel:06x}");
    }
}

#[test]
fn loading_a_missing_texture_file_names_it() {
    let e = TextureImage::load("/nonexistent/dir/t.png").unwrap_err();
    assert!(matches!(e.kind, LoadErrorKind::Io(_)));
    assert!(e.to_string().starts_with("/nonexistent/dir/t.png: cannot read the file: "), "{e}");
}

// ---------------------------------------------------------------------------------------------------------------
// Errors

fn assert_one_line(e: &LoadError, starts: &str) -> String {
    let text = e.to_string();
    assert!(text.starts_with(starts), "{text:?} should start with {starts:?}");
    assert!(!text.chars().any(char::is_control), "{text:?}");
    text
}

#[test]
fn a_missing_file_names_the_file_and_the_os_reason() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("nothing.obj");
    let e = load_model(&path, &ModelOptions::default()).unwrap_err();
    assert!(matches!(&e.kind, LoadErrorKind::Io(io) if io.kind() == std::io::ErrorKind::NotFound));
    let text = assert_one_line(&e, &path.display().to_string());
    assert!(text.ends_with("cannot read the file: No such file or directory (os error 2)"), "{text}");

    let e = load_model(dir.path(), &ModelOptions::default()).unwrap_err();
    assert!(matches!(e.kind, LoadErrorKind::Io(_)), "a directory is not a file: {e}");
    assert!(e.to_string().ends_with("cannot read the file: not a regular file: a directory"), "{e}");
}

#[test]
fn malformed_statements_are_reported_with_their_line() {
    let cases: &[(&str, usize, &str)] = &[
        ("v 0 0 0\nv 1 0 zero\n", 2, "\"zero\" is not a number"),
        ("v 0 0 0\n\n# c\nv 1 0\n", 4, "a vertex (v) needs 3 numbers"),
        ("v 0 0 0\nvt 1 one\n", 2, "texture coordinates (vt) need 1 or 2 numbers"),
        ("vn 0 0 1\nvn 0 x 1\n", 2, "a normal (vn) needs 3 numbers"),
        ("v 0 0 0\nv 0 0 0 0\n", 2, "the w of a vertex (v) is zero"),
        ("v 0 0 0 1 1\n", 1, "found 5 numbers"),
        (&format!("{SQUARE}f 1 2 three\n"), 11, "\"three\" is not an index"),
        (&format!("{SQUARE}f 1/1/1/1 2 3\n"), 11, "more than 3 indices"),
        (&format!("{SQUARE}f //1 2 3\n"), 11, "has no position index"),
        (&format!("{SQUARE}f\n"), 11, "a face (f) without vertices"),
        (&format!("{SQUARE}f 1 2 3\nusemtl\n"), 12, "usemtl without a material name"),
    ];
    for (obj, line, says) in cases {
        let e = load_err(obj);
        assert!(matches!(e.kind, LoadErrorKind::Syntax { .. }), "{e}");
        assert_eq!(e.line(), Some(*line), "{e}");
        let text = assert_one_line(&e, &format!("bad.obj, line {line}: "));
        assert!(text.contains(says), "{text:?} should say {says:?}");
    }
}

#[test]
fn indices_out_of_range_are_reported_with_their_line() {
    let cases: &[(&str, Element, i64, usize)] = &[
        ("f 1 2 5\n", Element::Vertex, 5, 4),
        ("f 1 2 -5\n", Element::Vertex, -5, 4),
        ("f 0 1 2\n", Element::Vertex, 0, 4),
        ("f 1/1 2/5 3/3\n", Element::TextureCoordinate, 5, 4),
        ("f 1//1 2//3 3//1\n", Element::Normal, 3, 2),
        ("f 1//1 2//-3 3//1\n", Element::Normal, -3, 2),
    ];
    for &(face, element, index, defined) in cases {
        let e = load_err(&format!("{SQUARE}f 1 2 3\n{face}v 0 0 5\n"));
        match e.kind {
            LoadErrorKind::IndexOutOfRange { line, element: el, index: i, defined: d } => {
                assert_eq!((line, el, i, d), (12, element, index, defined), "{face}");
            }
            _ => panic!("{face}: {e}"),
        }
        assert_one_line(&e, "bad.obj, line 12: ");
    }
    // A later definition does not make an earlier face valid.
    assert_eq!(load_err("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n").line(), Some(2));
}

#[test]
fn non_finite_and_huge_coordinates_are_reported_with_value_and_line() {
    let cases: &[(&str, usize, &str)] = &[
        ("v 0 0 0\nv NaN 0 0\n", 2, "coordinate NaN is not a finite number"),
        ("v 0 inf 0\n", 1, "coordinate inf is not a finite number"),
        ("v 0 0 -1e39\n", 1, "coordinate -inf is not a finite number"),
        ("v 0 0 0\nv 0 0 0\nv 1e16 0 0\n", 3, "coordinate 1e16 is beyond the limit of ±1e15"),
        ("v 1 1 1 1e-30\n", 1, "coordinate 1e30 is beyond the limit"),
        ("vt 0 nan\n", 1, "not a finite number"),
        ("vn 0 0 2e15\n", 1, "coordinate 2e15 is beyond the limit"),
    ];
    for (obj, line, says) in cases {
        let e = load_err(obj);
        assert!(matches!(e.kind, LoadErrorKind::BadCoordinate { .. }), "{e}");
        let text = assert_one_line(&e, &format!("bad.obj, line {line}: "));
        assert!(text.contains(says), "{text:?} should say {says:?}");
    }
    // The limit itself is accepted.
    let m = load("v -1e15 0 0\nv 1e15 0 0\nv 0 1e15 0\nf 1 2 3\n");
    assert_consistent(&m);
}

#[test]
fn models_without_triangles_are_errors() {
    for obj in ["", "# nothing\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "v 0 0 0\nv 1 0 0\nl 1 2\nf 1 2\np 1\no x\n"] {
        let e = load_err(obj);
        assert!(matches!(e.kind, LoadErrorKind::NoTriangles), "{obj:?}: {e}");
        assert_eq!(e.to_string(), "bad.obj: the model has no triangles");
    }
}

#[test]
fn control_characters_never_reach_an_error_message() {
    let e = load_obj_bytes("evil\n\u{1b}[2J.obj", b"v 0 0 0\nv \x1b[31m 0 0\n", &NoFiles).unwrap_err();
    let text = assert_one_line(&e, "evil\\n\\u{1b}[2J.obj, line 2: ");
    assert!(text.contains("\\u{1b}[31m"), "{text}");
}

// ---------------------------------------------------------------------------------------------------------------
// In-memory loading

#[test]
fn in_memory_obj_with_embedded_files() {
    let png = red_blue_png();
    let files: &[(&str, &[u8])] = &[("m/lib.mtl", b"newmtl t\nmap_Kd tex/t.png\n"), ("m/tex/t.png", &png)];
    let obj = format!("mtllib ./m/lib.mtl\n{SQUARE}usemtl t\nf 1/1 2/2 3/3 4/4\n");
    let m = load_obj_bytes("built-in", obj.as_bytes(), &Embedded::new(files)).unwrap();
    assert_consistent(&m);
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
    assert_eq!(m.materials[0].texture.as_ref().unwrap().texels, [0xFF0000, 0x0000FF]);
}

#[test]
fn in_memory_obj_with_a_closure_resolver_and_backslashes() {
    let asked = std::cell::RefCell::new(Vec::new());
    let resolver = |p: &Path| -> std::io::Result<Vec<u8>> {
        asked.borrow_mut().push(p.to_path_buf());
        match p.to_str() {
            Some("sub/m.mtl") => Ok(b"newmtl t\nKd 0 0 1\nmap_Kd img\\t.png\n".to_vec()),
            Some("sub/img/t.png") => Ok(red_blue_png()),
            _ => Err(std::io::Error::new(std::io::ErrorKind::NotFound, "no")),
        }
    };
    let obj = format!("mtllib sub\\m.mtl\n{SQUARE}usemtl t\nf 1/1 2/2 3/3\n");
    let m = load_obj_bytes("mem.obj", obj.as_bytes(), &resolver).unwrap();
    assert_eq!(*asked.borrow(), [PathBuf::from("sub/m.mtl"), PathBuf::from("sub/img/t.png")]);
    assert_eq!(m.materials[0].diffuse, Vec3::Z);
    assert!(m.materials[0].texture.is_some());
}

#[test]
fn in_memory_obj_without_files_warns_about_its_library() {
    let m = load_obj_bytes("mem.obj", format!("mtllib m.mtl\n{SQUARE}f 1 2 3\n").as_bytes(), &NoFiles).unwrap();
    assert_eq!(m.warnings.len(), 1);
    assert!(m.warnings[0].starts_with("m.mtl: cannot read the material library"), "{:?}", m.warnings);
}

// ---------------------------------------------------------------------------------------------------------------
// Framing

#[test]
fn fit_frames_large_and_unit_models_the_same() {
    let cube = |s: f32, offset: f32| {
        let mut obj = String::new();
        for z in [-1.0, 1.0] {
            for y in [-1.0, 1.0] {
                for x in [-1.0, 1.0] {
                    obj += &format!("v {} {} {}\n", x * s + offset, y * s, z * s);
                }
            }
        }
        obj + "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n"
    };
    let big = load(&cube(250.0, 1000.0));
    let unit = load(&cube(0.5, 0.0));
    let bounds = big.bounds().unwrap();
    assert_eq!(bounds.min, Vec3::new(750.0, -250.0, -250.0));
    assert_eq!(bounds.max, Vec3::new(1250.0, 250.0, 250.0));
    let (fb, fu) = (big.fit(), unit.fit());
    for (a, b) in big.positions.iter().zip(&unit.positions) {
        let (a, b) = (fb.transform_point(*a), fu.transform_point(*b));
        assert!(close(a, b), "{a:?} vs {b:?}");
        assert!((a.length() - 1.0).abs() < 1e-5, "corners land on the unit sphere");
    }
}

// ---------------------------------------------------------------------------------------------------------------
// No panic on any input

const VALID_OBJ: &str = "mtllib m.mtl\n# a comment\no first\nv 0 0 0\nv 1 0 0 1\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n\
                         vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nusemtl a\nf 1/1/1 2/2/1 3/3/1 4/1/1\ng second\nusemtl b\n\
                         f -4//-1 -3//-1 -2//-1\nf 1 3 4\nl 1 2\ns 1\n";
const VALID_MTL: &str = "newmtl a\nKd 1 0.5 0\nmap_Kd -s 1 1 1 t.tga\nnewmtl b\nKa 0.1 0.1 0.1\nNs 10\nd 1\nillum 2\n\
                         map_Kd t.png\n";

fn fuzz_files() -> Vec<(&'static str, Vec<u8>)> {
    vec![("m.mtl", VALID_MTL.as_bytes().to_vec()), ("t.tga", tga(true, false)), ("t.png", red_blue_png())]
}

fn load_fuzzed(obj: &[u8], files: &[(&'static str, Vec<u8>)]) {
    let table: Vec<(&str, &[u8])> = files.iter().map(|(n, b)| (*n, b.as_slice())).collect();
    match load_obj_bytes("fuzz.obj", obj, &Embedded::new(&table)) {
        Ok(m) => assert_consistent(&m),
        Err(e) => assert_one_line(&e, "fuzz.obj").truncate(0),
    }
}

/// Applies `(position, byte, kind)` edits: 0 replaces, 1 inserts, 2 deletes.
fn mutate(base: &[u8], edits: &[(usize, u8, u8)]) -> Vec<u8> {
    let mut bytes = base.to_vec();
    for &(at, byte, kind) in edits {
        let at = if bytes.is_empty() { 0 } else { at % (bytes.len() + 1) };
        match kind {
            0 if at < bytes.len() => bytes[at] = byte,
            2 if at < bytes.len() => {
                bytes.remove(at);
            }
            _ => bytes.insert(at, byte),
        }
    }
    bytes
}

/// Lines built from OBJ keywords and tricky tokens, to reach deeper than random bytes.
fn obj_line() -> impl Strategy<Value = String> {
    let keyword =
        prop::sample::select(vec!["v", "vt", "vn", "f", "l", "p", "o", "g", "s", "usemtl", "mtllib", "#", ""]);
    let token = prop::sample::select(vec![
        "0",
        "1",
        "2",
        "3",
        "-1",
        "-2",
        "-3",
        "0.5",
        "-0",
        "1e15",
        "1e16",
        "nan",
        "inf",
        "x",
        "1/1",
        "1//1",
        "1/1/1",
        "-1/-1/-1",
        "2/-1/1",
        "/1",
        "1/",
        "1/1/1/1",
        "1/1/1/",
        "9223372036854775807",
        "-9223372036854775808",
        "a",
        "b",
        "m.mtl",
        "t.png",
        "\u{1b}",
        "\r",
    ]);
    (keyword, prop::collection::vec(token, 0..6)).prop_map(|(k, t)| format!("{k} {}", t.join(" ")))
}

proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..600)) {
        load_fuzzed(&bytes, &fuzz_files());
    }

    #[test]
    fn mutations_of_a_valid_obj_never_panic(edits in prop::collection::vec((any::<usize>(), any::<u8>(), 0u8..3), 1..10)) {
        load_fuzzed(&mutate(VALID_OBJ.as_bytes(), &edits), &fuzz_files());
    }

    #[test]
    fn random_statements_never_panic(lines in prop::collection::vec(obj_line(), 0..40)) {
        let text = format!("v 0 0 0\nv 1 0 0\nvt 0 0\nvn 0 0 1\n{}\nf 1 2 1\n", lines.join("\n"));
        load_fuzzed(text.as_bytes(), &fuzz_files());
    }

    #[test]
    fn mutations_of_the_mtl_and_textures_never_panic(
        mtl_edits in prop::collection::vec((any::<usize>(), any::<u8>(), 0u8..3), 0..10),
        tga_edits in prop::collection::vec((any::<usize>(), any::<u8>(), 0u8..3), 0..6),
        png_edits in prop::collection::vec((any::<usize>(), any::<u8>(), 0u8..3), 0..6),
    ) {
        let files = vec![
            ("m.mtl", mutate(VALID_MTL.as_bytes(), &mtl_edits)),
            ("t.tga", mutate(&tga(true, false), &tga_edits)),
            ("t.png", mutate(&red_blue_png(), &png_edits)),
        ];
        load_fuzzed(VALID_OBJ.as_bytes(), &files);
    }

    #[test]
    fn random_image_bytes_never_panic(
        bytes in prop::collection::vec(any::<u8>(), 0..300),
        name in prop::sample::select(vec!["a.tga", "a.png", "a.jpg", "a"]),
    ) {
        if let Ok(t) = TextureImage::decode(Path::new(name), &bytes) {
            prop_assert!(t.texture().is_ok());
        }
    }
}
