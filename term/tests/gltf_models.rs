//! glTF models made by the tests themselves (`common::gltf_writer`): Spot's OBJ written as `.gltf` and `.glb`,
//! and a small scene of nodes and materials. Each feature has a known answer: Spot's own triangles and picture,
//! where a node transform puts a part, what a texture transform does to texture coordinates, and the message of
//! each kind of bad file.

use std::fs;
use std::path::{Path, PathBuf};

use rastty_core::color::{linear_to_srgb, srgb_to_linear};
use rastty_core::math::{Vec2, Vec3};
use rastty_scene::model::{LoadError, Model, ModelOptions, load_model};

use crate::common::gltf_writer::GltfWriter;
use crate::common::rastty_in as rastty;

/// Spot's OBJ file and texture in the repository.
fn spot(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/spot").join(file)
}

fn flat3(v: &[Vec3]) -> Vec<f32> {
    v.iter().flat_map(|p| [p.x, p.y, p.z]).collect()
}

/// Spot as glTF in `dir`: `spot.gltf` (buffer in a data URI, texture a PNG file beside it) and `spot.glb`
/// (texture inside the binary chunk), both with the base colour of an OBJ given `--texture`: sRGB 0.8, written in
/// linear light as glTF's factors are. Returns the OBJ's model.
fn write_spot_gltf(dir: &Path) -> Model {
    let obj = load_model(spot("spot.obj"), &ModelOptions::default()).expect("Spot's OBJ");
    let uvs = obj.uvs.as_ref().expect("Spot has texture coordinates");
    let png = fs::read(spot("spot_texture.png")).unwrap();
    let mut w = GltfWriter::new();
    let position = w.floats(&flat3(&obj.positions), "VEC3");
    let normal = w.floats(&flat3(&obj.normals), "VEC3");
    // glTF's v runs down from the image's top.
    let uv: Vec<f32> = uvs.iter().flat_map(|t| [t.x, 1.0 - t.y]).collect();
    let uv = w.floats(&uv, "VEC2");
    let indices = w.indices(&obj.indices, 4);
    let image_view = w.view(&png);
    let base = srgb_to_linear(0.8);
    let rest = |image: &str| {
        format!(
            r#""scene": 0, "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0, "name": "spot"}}],
            "meshes": [{{"name": "spot", "primitives": [{{"attributes": {{"POSITION": {position}, "NORMAL": {normal},
            "TEXCOORD_0": {uv}}}, "indices": {indices}, "material": 0}}]}}],
            "materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [{base}, {base}, {base}, 1], "baseColorTexture":
            {{"index": 0}}}}}}], "textures": [{{"source": 0}}], "images": [{image}]"#
        )
    };
    fs::write(dir.join("spot_texture.png"), &png).unwrap();
    fs::write(dir.join("spot.gltf"), w.embedded(&rest(r#"{"uri": "spot_texture.png"}"#))).unwrap();
    let in_buffer = format!(r#"{{"bufferView": {image_view}, "mimeType": "image/png"}}"#);
    fs::write(dir.join("spot.glb"), w.glb(&rest(&in_buffer))).unwrap();
    obj
}

/// The RGB bytes of the picture `rastty render MODEL -o OUT ARGS` draws at 160x120.
fn picture(dir: &Path, model: &str, args: &[&str]) -> Vec<u8> {
    let mut all = vec!["render", model, "-o", "out.png", "--size", "160x120"];
    all.extend_from_slice(args);
    let output = rastty(dir, &all);
    assert!(output.status.success(), "rastty {all:?}: {}", String::from_utf8_lossy(&output.stderr));
    image::open(dir.join("out.png")).expect("a PNG").to_rgb8().into_raw()
}

#[test]
fn spot_as_gltf_and_glb_has_the_vertices_and_triangles_of_its_obj() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write_spot_gltf(dir.path());
    for name in ["spot.gltf", "spot.glb"] {
        let model = load_model(dir.path().join(name), &ModelOptions::default()).expect(name);
        assert!(model.warnings.is_empty(), "{name}: {:?}", model.warnings);
        assert_eq!(model.positions, obj.positions, "{name}");
        assert_eq!(model.normals, obj.normals, "{name}");
        assert_eq!(model.indices, obj.indices, "{name}");
        // 1 - (1 - v) rounds for v below 0.5: within one unit in the last place of 1.
        let (a, b) = (model.uvs.as_ref().unwrap(), obj.uvs.as_ref().unwrap());
        assert!(a.iter().zip(b).all(|(a, b)| a.x == b.x && (a.y - b.y).abs() <= f32::EPSILON), "{name}");
        let material = model.part_material(0).expect("a material");
        let texture = material.texture.as_ref().expect("the base colour texture");
        assert_eq!((texture.width, texture.height), (1024, 1024), "{name}");
        // Encoded again for the material: 0.8 to within the rounding of the two conversions.
        let d = material.diffuse;
        assert!([d.x, d.y, d.z].iter().all(|c| (c - 0.8).abs() < 1e-6), "{d:?}");
    }
}

#[test]
fn spot_from_obj_and_gltf_gives_the_same_picture() {
    let dir = tempfile::tempdir().unwrap();
    write_spot_gltf(dir.path());
    let obj = spot("spot.obj");
    let obj = obj.to_str().unwrap();
    let depth = picture(dir.path(), obj, &["--shading", "depth"]);
    assert!(depth.chunks_exact(3).collect::<std::collections::HashSet<_>>().len() > 20, "a picture of Spot");
    for name in ["spot.gltf", "spot.glb"] {
        assert!(depth == picture(dir.path(), name, &["--shading", "depth"]), "{name}: another depth picture");
    }
    // Textured and lit (without the highlight, which glTF's roughness sets): the same but where a texture
    // coordinate's last bit differs (see above) and picks a neighbouring texel.
    let texture = spot("spot_texture.png");
    let lit = picture(dir.path(), obj, &["--texture", texture.to_str().unwrap(), "--without", "specular"]);
    for name in ["spot.gltf", "spot.glb"] {
        // Blinn-Phong, as the OBJ is drawn (a glTF material is drawn with the metallic-roughness model by default).
        let other = picture(dir.path(), name, &["--without", "specular", "--shading", "phong"]);
        let differing = lit.chunks_exact(3).zip(other.chunks_exact(3)).filter(|(a, b)| a != b).count();
        assert!(differing * 1000 < lit.len() / 3, "{name}: {differing} of {} pixels differ", lit.len() / 3);
    }
}

/// A unit square in the z = 0 plane facing +z, as accessors: (positions, normals, texture coordinates,
/// indices).
fn square(w: &mut GltfWriter) -> (usize, usize, usize, usize) {
    let positions = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0], "VEC3");
    let normals = w.floats(&[0.0, 0.0, 1.0].repeat(4), "VEC3");
    let uvs = w.floats(&[0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0], "VEC2");
    let indices = w.indices(&[0, 1, 2, 0, 2, 3], 2);
    (positions, normals, uvs, indices)
}

/// A scene of four placed squares in two materials, a triangle strip and a fan without normals.
fn scene_file(w: &mut GltfWriter) -> String {
    let (p, n, t, i) = square(w);
    let corners = w.floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 2.0, 0.0], "VEC3");
    let strip = w.indices(&[0, 1, 2, 3, 4], 1);
    let fan = w.indices(&[0, 1, 3, 2], 4);
    format!(
        r#""scene": 0, "scenes": [{{"nodes": [0, 1, 3, 4]}}],
        "nodes": [
          {{"mesh": 0}},
          {{"mesh": 1, "translation": [2, 0, 0], "children": [2]}},
          {{"mesh": 0, "matrix": [0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 3, 0, 1]}},
          {{"mesh": 0, "scale": [-1, 1, 1]}},
          {{"mesh": 2, "translation": [0, 0, -5]}}
        ],
        "meshes": [
          {{"name": "red square", "primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}, "TEXCOORD_0": {t}}},
            "indices": {i}, "material": 0}}]}},
          {{"name": "glowing square", "primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}}},
            "indices": {i}, "material": 1}}]}},
          {{"name": "strip and fan", "primitives": [
            {{"attributes": {{"POSITION": {corners}}}, "indices": {strip}, "mode": 5}},
            {{"attributes": {{"POSITION": {corners}}}, "indices": {fan}, "mode": 6}},
            {{"attributes": {{"POSITION": {corners}}}, "mode": 1}}]}}
        ],
        "materials": [
          {{"name": "red", "doubleSided": true, "pbrMetallicRoughness": {{"baseColorFactor": [1, 0, 0, 1],
            "metallicFactor": 0, "roughnessFactor": 0.5}}}},
          {{"name": "glow", "emissiveFactor": [0, 0.5, 0], "pbrMetallicRoughness": {{"baseColorFactor": [0, 0, 1, 1]}}}}
        ]"#
    )
}

fn corners_of(model: &Model, part: usize) -> Vec<Vec3> {
    model.indices[model.parts[part].indices.clone()].iter().map(|&i| model.positions[i as usize]).collect()
}

#[test]
fn nodes_place_their_meshes_and_materials_come_with_them() {
    let dir = tempfile::tempdir().unwrap();
    let mut w = GltfWriter::new();
    let rest = scene_file(&mut w);
    fs::write(dir.path().join("scene.gltf"), w.embedded(&rest)).unwrap();
    let model = load_model(dir.path().join("scene.gltf"), &ModelOptions::default()).unwrap();
    // Depth first: node 0, node 1, its child node 2, node 3, then node 4's two triangle primitives.
    let names: Vec<&str> = model.parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["red square", "glowing square", "red square", "red square", "strip and fan", "strip and fan"]);
    let v = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
    let square =
        [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(0.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)];
    assert_eq!(corners_of(&model, 0), square);
    // Translated by (2, 0, 0).
    assert_eq!(corners_of(&model, 1), square.map(|p| p + v(2.0, 0.0, 0.0)));
    // Turned a quarter about z and raised by 3 under its parent's (2, 0, 0): (x, y) -> (2 - y, x + 3).
    assert_eq!(corners_of(&model, 2), square.map(|p| v(2.0 - p.y, p.x + 3.0, 0.0)));
    // Mirrored in x: the winding turns round, so the square still faces +z as drawn.
    let mirrored = corners_of(&model, 3);
    let expected: Vec<Vec3> = square.chunks(3).flat_map(|t| [t[0], t[2], t[1]]).map(|p| v(-p.x, p.y, p.z)).collect();
    assert_eq!(mirrored, expected);
    let [a, b, c] = [mirrored[0], mirrored[1], mirrored[2]];
    assert!((b - a).cross(c - a).z > 0.0, "the mirrored square's triangles face +z");
    let n = model.indices[model.parts[3].indices.start] as usize;
    assert_eq!(model.normals[n], v(0.0, 0.0, 1.0));
    // The strip alternates its winding; the fan turns about its first corner; both without normals get their
    // faces' (flat), and the line primitive is left out with a warning.
    let z = v(0.0, 0.0, -5.0);
    let c = [v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(1.0, 1.0, 0.0), v(0.0, 2.0, 0.0)].map(|p| p + z);
    let strip = [c[0], c[1], c[2], c[1], c[3], c[2], c[2], c[3], c[4]];
    assert_eq!(corners_of(&model, 4), strip);
    assert_eq!(corners_of(&model, 5), [c[1], c[3], c[0], c[3], c[2], c[0]]);
    for part in [4, 5] {
        for &i in &model.indices[model.parts[part].indices.clone()] {
            assert_eq!(model.normals[i as usize], v(0.0, 0.0, 1.0), "part {part}: flat normals face +z");
        }
    }
    assert!(model.warnings.iter().any(|w| w.contains("Lines") && w.contains("left out")), "{:?}", model.warnings);
    // Materials: red, double-sided, a highlight of F0 = 0.04 (linear light, stored encoded) and exponent
    // 2 / 0.25^2 - 2 = 30; blue glowing green (half of the light of full green: code 188).
    let red = model.part_material(0).unwrap();
    assert_eq!((red.name.as_str(), red.diffuse, red.double_sided), ("red", v(1.0, 0.0, 0.0), true));
    assert_eq!((red.specular, red.shininess), (Some(Vec3::splat(linear_to_srgb(0.04))), Some(30.0)));
    let glow = model.part_material(1).unwrap();
    assert_eq!((glow.diffuse, glow.double_sided), (v(0.0, 0.0, 1.0), false));
    assert_eq!(glow.glow_map.as_ref().map(|g| g.texels.clone()), Some(vec![0x00_BC_00]));
    assert_eq!(model.parts[2].material, model.parts[0].material, "one material per glTF material");
    // The parts without a material share the default one.
    assert_eq!(model.part_material(4), model.part_material(5));
}

#[test]
fn texture_transforms_move_texture_coordinates() {
    let dir = tempfile::tempdir().unwrap();
    let mut png = Vec::new();
    let mut encoder = png::Encoder::new(&mut png, 2, 2);
    encoder.set_color(png::ColorType::Rgb);
    encoder.write_header().unwrap().write_image_data(&[255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255]).unwrap();
    let mut w = GltfWriter::new();
    let (p, n, t, i) = square(&mut w);
    let image = w.view(&png);
    let model_with = |transform: &str| {
        format!(
            r#""extensionsUsed": ["KHR_texture_transform"], "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
            "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}, "TEXCOORD_0": {t}}},
              "indices": {i}, "material": 0}}]}}],
            "materials": [{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0{transform}}}}}}}],
            "textures": [{{"source": 0}}], "images": [{{"bufferView": {image}, "mimeType": "image/png"}}]"#
        )
    };
    let transform = r#", "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [2, 2]}}"#;
    fs::write(dir.path().join("moved.glb"), w.glb(&model_with(transform))).unwrap();
    fs::write(dir.path().join("plain.glb"), w.glb(&model_with(""))).unwrap();
    let uvs = |name: &str| load_model(dir.path().join(name), &ModelOptions::default()).unwrap().uvs.unwrap();
    // glTF (u, v) -> (2u + 0.5, 2v) -> the renderer's (u', 1 - v').
    let expected =
        [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(u, v)| Vec2::new(2.0 * u + 0.5, 1.0 - 2.0 * v));
    assert_eq!(uvs("moved.glb"), expected);
    assert_eq!(uvs("plain.glb"), [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)].map(|(u, v)| Vec2::new(u, v)));
    let plain = picture(dir.path(), "plain.glb", &["--yaw", "0", "--pitch", "0"]);
    assert!(
        plain != picture(dir.path(), "moved.glb", &["--yaw", "0", "--pitch", "0"]),
        "the transform changed nothing"
    );
}

/// A square with a 16x1 RGBA texture, opaque red on the left half and fully transparent green on the right, in
/// a material of alpha mode `mode` (`"MASK"` or `"OPAQUE"`) and with `more` material keys. Bilinear filtering
/// blends the halves only near where they meet.
fn half_clear_square(mode: &str, more: &str) -> Vec<u8> {
    textured_square(mode, "", more)
}

/// [`half_clear_square`] with `pbr` after the base colour texture in `pbrMetallicRoughness`.
fn textured_square(mode: &str, pbr: &str, more: &str) -> Vec<u8> {
    let mut png = Vec::new();
    let mut encoder = png::Encoder::new(&mut png, 16, 1);
    encoder.set_color(png::ColorType::Rgba);
    let texels = [[255, 0, 0, 255]; 8].into_iter().chain([[0, 255, 0, 0]; 8]).flatten().collect::<Vec<u8>>();
    encoder.write_header().unwrap().write_image_data(&texels).unwrap();
    let mut w = GltfWriter::new();
    let (p, n, t, i) = square(&mut w);
    let image = w.view(&png);
    w.glb(&format!(
        r#""scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}, "TEXCOORD_0": {t}}},
          "indices": {i}, "material": 0}}]}}],
        "materials": [{{"alphaMode": "{mode}", "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}{pbr}}}{more}}}],
        "textures": [{{"source": 0}}],
        "images": [{{"bufferView": {image}, "mimeType": "image/png"}}]"#
    ))
}

#[test]
fn alpha_mask_cuts_out_what_its_texture_makes_transparent() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("mask.glb"), half_clear_square("MASK", "")).unwrap();
    fs::write(dir.path().join("opaque.glb"), half_clear_square("OPAQUE", "")).unwrap();
    let model = load_model(dir.path().join("mask.glb"), &ModelOptions::default()).unwrap();
    assert!(model.warnings.is_empty(), "{:?}", model.warnings);
    let material = model.part_material(0).unwrap();
    assert_eq!((material.alpha_cutoff, material.opacity), (Some(0.5), 1.0));
    // Transparency (255 - alpha) in the top byte.
    let texels = &material.texture.as_ref().unwrap().texels;
    assert_eq!((texels[7], texels[8]), (0x00FF_0000, 0xFF00_FF00));
    let output = rastty(dir.path(), &["render", "mask.glb", "--explain"]);
    assert!(String::from_utf8_lossy(&output.stdout).contains("alpha cut-out below 0.5"));
    let front = ["--yaw", "0", "--pitch", "0", "--shading", "unlit", "--background", "000000"];
    let count = |picture: &[u8], rgb: [u8; 3]| picture.chunks_exact(3).filter(|p| *p == rgb).count();
    let (masked, opaque) = (picture(dir.path(), "mask.glb", &front), picture(dir.path(), "opaque.glb", &front));
    let (red, green) = ([255, 0, 0], [0, 255, 0]);
    assert!(count(&opaque, red) > 100 && count(&opaque, green) > 100, "the opaque square shows both texels");
    assert_eq!(count(&masked, red), count(&opaque, red), "the opaque half is drawn alike");
    assert_eq!(count(&masked, green), 0, "the transparent half is cut out");
    assert!(count(&masked, [0, 0, 0]) >= count(&opaque, [0, 0, 0]) + count(&opaque, green));
}

#[test]
fn the_occlusion_texture_scales_the_ambient_light_by_its_red_channel() {
    let dir = tempfile::tempdir().unwrap();
    let occlusion = r#", "occlusionTexture": {"index": 0, "strength": 0.5}"#;
    fs::write(dir.path().join("occluded.glb"), half_clear_square("OPAQUE", occlusion)).unwrap();
    let model = load_model(dir.path().join("occluded.glb"), &ModelOptions::default()).unwrap();
    assert!(model.warnings.is_empty(), "{:?}", model.warnings);
    // Red 255 on the left stays 1; red 0 on the right becomes 1 + 0.5 (0 - 1) = 0.5, grey 128.
    let texels = &model.part_material(0).unwrap().occlusion_map.as_ref().unwrap().texels;
    assert_eq!((texels[7], texels[8]), (0xFF_FFFF, 0x80_8080));
    let explain = |more: &[&str]| {
        let mut args = vec!["render", "occluded.glb", "--explain"];
        args.extend_from_slice(more);
        String::from_utf8_lossy(&rastty(dir.path(), &args).stdout).into_owned()
    };
    assert!(explain(&[]).contains("; occlusion map"), "{}", explain(&[]));
    assert!(!explain(&["--without", "ambient-occlusion"]).contains("occlusion map"));
    // Lit by a white ambient light alone (no lights in the scene file), under Blinn-Phong, the right half gets half the light: in
    // linear light (occlusion 128 / 255 times white) that encodes to 188.3, code 188.
    let scene = "ambient = [1, 1, 1]\n\n[camera]\nposition = [0.5, 0.5, 2]\ntarget = [0.5, 0.5, 0]\n\n[[objects]]\nmesh = \"occluded.glb\"\n";
    fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let args = ["--background", "000000", "--size", "160x120", "--shading", "phong"];
    let mut all = vec!["render", "scene.toml", "-o", "ambient.png"];
    all.extend_from_slice(&args);
    let output = rastty(dir.path(), &all);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let picture = image::open(dir.path().join("ambient.png")).unwrap().to_rgb8();
    // Red on the left, green on the right: the brightest channel of each.
    let brightest = |x| picture.get_pixel(x, 60).0.into_iter().max().unwrap();
    let (left, right) = (brightest(60), brightest(100));
    assert_eq!(left, 255, "the unoccluded half in full ambient light");
    assert_eq!(right, 188, "the occluded half gets half the light: {left}, {right}");
}

#[test]
fn the_metallic_roughness_texture_is_read_by_the_metallic_roughness_model() {
    let dir = tempfile::tempdir().unwrap();
    // The square's texture as its metallic-roughness texture too: red (no metal, no roughness) on the left, green
    // (roughness 1, no metal) on the right.
    let pbr = r#", "metallicRoughnessTexture": {"index": 0}, "metallicFactor": 0.75"#;
    fs::write(dir.path().join("metal.glb"), textured_square("OPAQUE", pbr, "")).unwrap();
    let model = load_model(dir.path().join("metal.glb"), &ModelOptions::default()).unwrap();
    assert!(model.warnings.is_empty(), "{:?}", model.warnings);
    let material = model.part_material(0).unwrap();
    assert_eq!((material.metallic, material.roughness), (Some(0.75), Some(1.0)));
    let texels = &material.metallic_roughness_map.as_ref().unwrap().texels;
    assert_eq!((texels[7], texels[8]), (0x00FF_0000, 0xFF00_FF00));
    let explain = |more: &[&str]| {
        let mut args = vec!["render", "metal.glb", "--explain"];
        args.extend_from_slice(more);
        String::from_utf8_lossy(&rastty(dir.path(), &args).stdout).into_owned()
    };
    // A glTF material is drawn with the metallic-roughness model by default, under the studio environment.
    let pbr = explain(&[]);
    assert!(pbr.contains("metallic-roughness; varyings") && pbr.contains("; metallic-roughness map"), "{pbr}");
    assert!(pbr.contains("environment studio (") && pbr.contains("reflected by 1 metallic-roughness draw"), "{pbr}");
    assert_eq!(explain(&["--shading", "metallic-roughness"]), pbr);
    assert!(!explain(&["--shading", "phong"]).contains("metallic-roughness map"), "Blinn-Phong reads no such map");
    let dark = explain(&["--environment", "none"]);
    assert!(dark.contains("metallic-roughness; varyings") && !dark.contains("environment"), "{dark}");
}

#[test]
fn a_scene_file_places_a_gltf_model_and_draws_its_double_sided_part_without_culling() {
    let dir = tempfile::tempdir().unwrap();
    let mut w = GltfWriter::new();
    let rest = scene_file(&mut w);
    fs::write(dir.path().join("squares.glb"), w.glb(&rest)).unwrap();
    let light = "[[lights]]\ntype = \"directional\"\ndirection = [0, 0, -1]\n\n";
    fs::write(dir.path().join("scene.toml"), format!("{light}[[objects]]\nmesh = \"squares.glb\"\n")).unwrap();
    let output = rastty(dir.path(), &["render", "scene.toml", "--explain"]);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let plan = String::from_utf8_lossy(&output.stdout);
    let line = |part: &str| plan.lines().find(|l| l.contains(part)).map(str::to_owned).unwrap_or_default();
    assert!(line("part \"red square\"").contains("cull none"), "{plan}");
    assert!(line("part \"glowing square\"").contains("cull back") && line("glowing").contains("glow map"), "{plan}");
    // Seen from behind, the double-sided red squares are still drawn; the one-sided glowing square is not.
    let args = ["--yaw", "180", "--pitch", "0", "--background", "000000", "--shading", "phong"];
    let behind = picture(dir.path(), "scene.toml", &args);
    let reddish = behind.chunks_exact(3).filter(|p| p[0] > 0 && p[1] == 0 && p[2] == 0).count();
    let greenish = behind.chunks_exact(3).filter(|p| p[1] > p[0] && p[1] > p[2]).count();
    assert!(reddish > 0 && greenish == 0, "from behind: {reddish} red, {greenish} green pixels");
}

/// The error loading `json` as `name` in a fresh folder (with `beside` files written there first).
fn load_error(name: &str, bytes: &[u8], beside: &[(&str, &[u8])]) -> LoadError {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("model");
    fs::create_dir(&folder).unwrap();
    for (file, contents) in beside {
        fs::write(dir.path().join(file), contents).unwrap();
    }
    fs::write(folder.join(name), bytes).unwrap();
    load_model(folder.join(name), &ModelOptions::default()).expect_err(name)
}

#[test]
fn bad_files_are_errors_that_say_what_is_wrong() {
    let mut w = GltfWriter::new();
    let (p, n, _, i) = square(&mut w);
    let mesh = format!(
        r#""scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}}}, "indices": {i}}}]}}]"#
    );
    let good = w.embedded(&mesh);
    let check = |name: &str, bytes: &[u8], beside: &[(&str, &[u8])], wanted: &[&str]| {
        let e = load_error(name, bytes, beside).to_string();
        assert!(e.contains(name), "{e}");
        for w in wanted {
            assert!(e.contains(w), "{name}: {e:?} lacks {w:?}");
        }
    };
    let required = good.replacen(
        "{",
        r#"{"extensionsRequired": ["KHR_draco_mesh_compression"], "extensionsUsed": ["KHR_draco_mesh_compression"], "#,
        1,
    );
    check("draco.gltf", required.as_bytes(), &[], &["requires KHR_draco_mesh_compression", "does not read"]);
    check("broken.gltf", &good.as_bytes()[..good.len() / 2], &[], &["line 1"]);
    check("truncated.glb", &w.glb(&mesh)[..100], &[], &[]);
    let too_many = good.replacen(r#""count": 4, "type": "VEC3""#, r#""count": 40, "type": "VEC3""#, 1);
    check("count.gltf", too_many.as_bytes(), &[], &["accessor 0", "40 elements", "do not fit"]);
    assert!(load_model_text(&good).is_ok(), "the file the bad ones are made from loads");
    let outside = w.json(Some("../outside.bin"), &mesh);
    check("outside.gltf", outside.as_bytes(), &[("outside.bin", &w.bin)], &["buffer 0", "leaves the model's folder"]);
    let missing = w.json(Some("missing.bin"), &mesh);
    check("missing.gltf", missing.as_bytes(), &[], &["buffer 0", "missing.bin"]);
    let short = w.json(Some("short.bin"), &mesh);
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("short.bin"), &w.bin[..8]).unwrap();
    fs::write(dir.path().join("short.gltf"), short).unwrap();
    let e = load_model(dir.path().join("short.gltf"), &ModelOptions::default()).unwrap_err().to_string();
    assert!(e.contains(&format!("declares {} bytes but its data holds 8", w.bin.len())), "{e}");
    let cycle =
        good.replacen(r#""nodes": [{"mesh": 0}]"#, r#""nodes": [{"children": [1]}, {"children": [0], "mesh": 0}]"#, 1);
    check("cycle.gltf", cycle.as_bytes(), &[], &["node", "reached twice"]);
    let points = good.replacen(r#""indices": 3}"#, r#""indices": 3, "mode": 0}"#, 1);
    check("points.gltf", points.as_bytes(), &[], &["no triangles"]);
    // The command line: exit status 1, the file and the reason on one line.
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("draco.glb"),
        w.glb(&format!(r#""extensionsRequired": ["EXT_meshopt_compression"], {mesh}"#)),
    )
    .unwrap();
    let output = rastty(dir.path(), &["render", "draco.glb", "-o", "x.png"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("draco.glb") && stderr.contains("EXT_meshopt_compression"), "{stderr}");
    assert!(!dir.path().join("x.png").exists());
}

/// Loads glTF JSON text from a fresh folder.
fn load_model_text(json: &str) -> Result<Model, LoadError> {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("m.gltf"), json).unwrap();
    load_model(dir.path().join("m.gltf"), &ModelOptions::default())
}

#[test]
fn vertex_colours_multiply_the_base_colour_under_every_shading_model() {
    let dir = tempfile::tempdir().unwrap();
    let mut w = GltfWriter::new();
    let (p, n, _, i) = square(&mut w);
    let colors = w.floats(&[0.0, 0.4, 0.8].repeat(4), "VEC3");
    let rest = format!(
        r#""scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}, "COLOR_0": {colors}}},
          "indices": {i}, "material": 0}}]}}],
        "materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [1, 0.5, 0.5, 1], "metallicFactor": 0}}}}]"#
    );
    fs::write(dir.path().join("colored.glb"), w.glb(&rest)).unwrap();
    let explain =
        String::from_utf8_lossy(&rastty(dir.path(), &["render", "colored.glb", "--explain"]).stdout).into_owned();
    assert!(
        explain.contains("metallic-roughness; varyings colour+normal")
            && explain.contains("albedo colour x vertex colours"),
        "{explain}"
    );
    // Lit by a white ambient light alone: the base colour (1, 0.5, 0.5) times the vertex colour (0, 0.4, 0.8) is
    // (0, 0.2, 0.4) in linear light (both are linear in glTF), encoded 123.55 and 170.28: bytes (0, 124, 170),
    // whichever model draws it.
    let scene = "ambient = [1, 1, 1]\n\n[camera]\nposition = [0.5, 0.5, 2]\ntarget = [0.5, 0.5, 0]\n\n[[objects]]\nmesh = \"colored.glb\"\n";
    fs::write(dir.path().join("scene.toml"), scene).unwrap();
    for shading in ["phong", "gouraud", "flat", "unlit"] {
        let args = ["render", "scene.toml", "-o", "lit.png", "--size", "160x120", "--shading", shading];
        let output = rastty(dir.path(), &args);
        assert!(output.status.success(), "{shading}: {}", String::from_utf8_lossy(&output.stderr));
        let picture = image::open(dir.path().join("lit.png")).unwrap().to_rgb8();
        for (x, y) in [(80, 60), (50, 30), (110, 90)] {
            assert_eq!(picture.get_pixel(x, y).0, [0, 124, 170], "{shading} at ({x}, {y})");
        }
    }
}

/// The unit square seen by two cameras: "front", perspective (yfov 0.8), 4 units in front of the square's centre on
/// its node, under a parent that moves it up by 1 (so it looks at (0.5, 0.5) from (0.5, 0.5, 4) after its own
/// translation of (0.5, -0.5, 4)); and an orthographic one, 3 units high, looking down from above with +y up turned
/// to -z.
fn square_with_cameras() -> String {
    let mut w = GltfWriter::new();
    let (p, n, _, i) = square(&mut w);
    w.embedded(&format!(
        r#""scenes": [{{"nodes": [0, 1, 3]}}],
        "nodes": [{{"mesh": 0}}, {{"translation": [0, 1, 0], "children": [2]}},
          {{"camera": 0, "translation": [0.5, -0.5, 4]}},
          {{"camera": 1, "translation": [0.5, 5, 0], "rotation": [-0.70710677, 0, 0, 0.70710677]}}],
        "cameras": [{{"name": "front", "type": "perspective", "perspective": {{"yfov": 0.8, "znear": 0.5, "zfar": 50}}}},
          {{"type": "orthographic", "orthographic": {{"xmag": 2, "ymag": 1.5, "znear": 0, "zfar": 10}}}}],
        "meshes": [{{"primitives": [{{"attributes": {{"POSITION": {p}, "NORMAL": {n}}}, "indices": {i}}}]}}]"#
    ))
}

#[test]
fn the_files_cameras_are_placed_by_their_nodes_and_chosen_by_name_or_number() {
    use rastty_scene::model::ModelLens;
    use rastty_scene::scene_file::{CameraPlacement, SceneData, SceneProjection};
    let model = load_model_text(&square_with_cameras()).expect("the square with cameras loads");
    assert_eq!(model.cameras.len(), 2);
    let front = &model.cameras[0];
    assert_eq!(
        (front.name.as_deref(), front.lens, front.near, front.far),
        (Some("front"), ModelLens::Perspective { yfov: 0.8 }, 0.5, Some(50.0))
    );
    // Placed as the object is (unfitted here): the eye at (0.5, 0.5, 4), looking down -z, +y up.
    let camera = front.scene_camera(&rastty_core::math::Mat4::IDENTITY).unwrap();
    assert_eq!(
        (camera.position, camera.target, camera.up),
        (Vec3::new(0.5, 0.5, 4.0), Vec3::new(0.5, 0.5, 3.0), Vec3::Y)
    );
    assert_eq!(camera.projection, SceneProjection::Perspective { fov_degrees: 0.8f32.to_degrees() });
    // The orthographic camera looks straight down (-z turned to -y), 3 units high.
    let above = model.cameras[1].scene_camera(&rastty_core::math::Mat4::IDENTITY).unwrap();
    assert!((above.target - above.position - Vec3::new(0.0, -1.0, 0.0)).length() < 1e-6, "{above:?}");
    // 3 units high, as far as the quaternion's rounding (its axes are 1 - 6e-8 long) lets it be.
    let SceneProjection::Orthographic { height } = above.projection else { panic!("orthographic") };
    assert!((height - 3.0).abs() < 1e-6, "{height}");

    // In a scene of the model alone, fitted into the unit sphere, the camera is fitted with it; by name or number.
    let mut data = SceneData::from_model(model, "square.gltf".into());
    let fit = data.objects[0].transform;
    data.use_file_camera("front").unwrap();
    let CameraPlacement::Placed(placed) = data.camera else { panic!("a placed camera") };
    assert_eq!(placed.position, fit.transform_point(Vec3::new(0.5, 0.5, 4.0)));
    data.use_file_camera("1").unwrap();
    let e = data.use_file_camera("side").unwrap_err();
    assert!(e.contains("no camera side") && e.contains("0: front, 1: camera 1"), "{e}");

    // The command line: the view through each differs from the default, --explain lists them, a wrong name fails.
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("square.gltf"), square_with_cameras()).unwrap();
    let default = picture(dir.path(), "square.gltf", &[]);
    let through_front = picture(dir.path(), "square.gltf", &["--camera", "front"]);
    assert_ne!(default, through_front);
    assert_ne!(through_front, picture(dir.path(), "square.gltf", &["--camera", "1"]));
    let output = rastty(dir.path(), &["render", "square.gltf", "--explain"]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("cameras: 2") && stdout.contains("  0: front, perspective"), "{stdout}");
    let output = rastty(dir.path(), &["render", "square.gltf", "--camera", "side", "-o", "x.png"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("there is no camera side"));
}
