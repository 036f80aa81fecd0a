//! Writes seed corpora for every fuzz target, from `fuzz/`: `cargo run --release --example seeds` (any toolchain),
//! or, after `cargo +nightly fuzz build`, `RASTTY_FUZZ_SEEDS=1 target/x86_64-unknown-linux-gnu/release/raster`
//! (what CI runs: the instrumented build serves both, so the code is compiled once, not twice).
//!
//! - `corpus/obj_load/`: hand-written OBJ/MTL files (quads, negative and relative indices, `v/vt/vn` forms,
//!   groups and `usemtl` switches, `mtllib` in a subdirectory, `map_Kd` with options, CRLF, vertex colours, `l`
//!   lines, a polygon, short faces) in the target's length-prefixed layout, with valid and corrupt textures.
//! - `corpus/stl_load/`: a tetrahedron as ASCII STL (mixed case, flat and smooth) and as binary STL (a header that
//!   starts with `solid`, and one with bytes after the last triangle).
//! - `corpus/gltf_load/`: a triangle as `.gltf` JSON with its buffer in a data URI (flat normals); a `.glb` of
//!   squares placed by TRS, matrix, child and mirroring nodes, with normals, texture coordinates, colours, tangents,
//!   a PNG in the binary chunk as base colour, normal and emissive map, a texture transform, two materials and a
//!   point, a spot and a directional light; and
//!   a `.glb` of a strip, a fan, a sparse accessor and a line primitive.
//! - `corpus/gltf_animation/`: the target's skinned and morphed triangle with its joint turning a quarter turn,
//!   for every pair of interpolations, one to four keys and each rotation component type.
//! - `corpus/scene_parse/`: the scene files of `assets/scenes/`, and a scene of built-in meshes only (which the
//!   target draws).
//! - `corpus/raster/`: scenes found by decoding pseudo-random bytes exactly as the target does and keeping those
//!   that shade at least one pixel, one per kind (shading model, texture, depth test, band, wireframe, clipping).
//!   A candidate that breaks an invariant is not a seed: it is saved to `artifacts/raster/seed-panic-*` and
//!   reported, for `cargo +nightly fuzz run raster artifacts/raster/seed-panic-...` to reproduce, and the
//!   generator exits with status 1 once it has written the seeds (CI fails on it).
//!
//! Deterministic: the same files every run. Corpora are not committed (see `.gitignore`).

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

use crate::obj_load::encode;
use crate::raster::{Input, run};
use arbitrary::{Arbitrary, Unstructured};

const MTL: &str = "\
# two materials, one textured
newmtl red
Kd 1 0 0
Ks 0.5 0.5 0.5
Ns 20
newmtl wood
Kd 0.8 0.6 0.4
map_Kd ok.png
";

const CUBE_QUADS: &str = "\
# a unit cube of quads with texture coordinates and normals
mtllib m.mtl
o cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
vn 0 0 -1
vn 1 0 0
vn -1 0 0
vn 0 1 0
vn 0 -1 0
usemtl wood
f 5/1/1 6/2/1 7/3/1 8/4/1
f 2/1/2 1/2/2 4/3/2 3/4/2
usemtl red
f 6/1/3 2/2/3 3/3/3 7/4/3
f 1/1/4 5/2/4 8/3/4 4/4/4
g top
f 8/1/5 7/2/5 3/3/5 4/4/5
g bottom
f 1/1/6 2/2/6 6/3/6 5/4/6
";

const NEGATIVE: &str = "\
# relative (negative) indices, v//vn and v/vt forms, a pentagon
mtllib lib/m.mtl
v 0 0 0
v 1 0 0
v 1 1 0
vn 0 0 1
f -3//-1 -2//-1 -1//-1
v 0 0 1
v 1 0 1
v 1 1 1
v 0.5 1.5 1
v -0.5 0.8 1
vt 0 0
vt 1 0
vt 1 1
vt 0.5 1
vt 0 0.5
usemtl wood
f -5/-5 -4/-4 -3/-3 -2/-2 -1/-1
";

const ODD: &str = "v 0 0 0 1\r\nv 1 0 0 2\r\nv 0 1 0 0.5\r\nv 0 0 1 1 0 0\r\n# vertex colours above, CRLF here\r\n\
l 1 2 3\r\nf 1 2\r\nf 1 2 3\r\n  g  indented\r\nf 2 3 4\r\ns off\r\nusemtl nothing\r\nf 1 3 4\r\n";

const HUGE: &str = "\
v 1e15 0 0
v -1e15 1e15 0
v 0 -1e15 1e-30
v 1e-38 1e-38 1e-38
f 1 2 3
f 2 3 4
f 4 1 2
";

const TGA_MTL: &str =
    "newmtl t\nmap_Kd -s 2 2 1 -o 0.5 0 0 ok.tga\nnewmtl raw\nmap_Kd t.png\nnewmtl rawtga\nmap_Kd t.tga\n";

const TEXTURED_TRIS: &str = "\
mtllib m.mtl
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
vt 0 0
vt 2 0
vt 0 2
vt -1 3
usemtl t
f 1/1 2/2 3/3
usemtl raw
f 2/2 4/4 3/3
usemtl rawtga
f 1/1 4/4 3/3
";

const TETRA_ASCII: &str = "solid tetra
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 1 0 0
 endloop
endfacet
FACET NORMAL 0 -1 0
 OUTER LOOP
  VERTEX 0 0 0
  VERTEX 1 0 0
  VERTEX 0 0 1
 ENDLOOP
ENDFACET
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 0 1 0
 endloop
endfacet
facet normal 0 0 0
 outer loop
  vertex 1 0 0
  vertex 0 1 0
  vertex 0 0 1
 endloop
endfacet
endsolid tetra
";

/// A scene of built-in meshes only, with both kinds of light and shadows.
const BUILTIN_SCENE: &str = "background = \"202830\"
ambient = [0.1, 0.1, 0.1]

[camera]
position = [0, 1, 4]
target = [0, 0.5, 0]
fov = 40

[[lights]]
type = \"directional\"
direction = [-0.3, -1, -0.5]
shadows = true

[[lights]]
type = \"point\"
position = [0, 6, 0]
color = [1, 0.9, 0.8]

[[objects]]
mesh = \"builtin:spot\"
rotate = [0, 30, 0]

[[objects]]
mesh = \"builtin:spot\"
translate = [1.5, 0, 0]
scale = 0.5
[objects.material]
color = [0.2, 0.6, 0.9]
specular = 0.5
";

fn write(dir: &Path, name: &str, bytes: &[u8]) {
    fs::write(dir.join(name), bytes).unwrap_or_else(|e| panic!("writing {}: {e}", dir.join(name).display()));
}

fn obj_seeds(dir: &Path) -> usize {
    // 2x2 texels for the generated ok.png/ok.tga: width byte, height byte, then RGB.
    let texture: &[u8] = &[1, 1, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
    // A valid 1x1 24-bit TGA as the raw texture (t.tga), and a PNG signature with garbage after it (t.png).
    let raw_tga: &[u8] = &[0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 24, 0x20, 10, 20, 30];
    let broken_png: &[u8] = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x02\0\0\0\x02\x08\x02\0\0\0garbage";
    let seeds: [(&str, u8, &str, &str, &[u8]); 8] = [
        ("cube_quads_phong_textured", 0x13, CUBE_QUADS, MTL, texture),
        ("cube_quads_wireframe_ortho", 0x3A, CUBE_QUADS, MTL, texture),
        ("negative_indices_lib_mtl", 0x10, NEGATIVE, MTL, texture),
        ("odd_statements_crlf", 0x01, ODD, "", b""),
        ("huge_coordinates_depth", 0x04, HUGE, "", b""),
        ("textured_tga_and_raw", 0x10, TEXTURED_TRIS, TGA_MTL, raw_tga),
        ("textured_broken_png", 0x12, TEXTURED_TRIS, TGA_MTL, broken_png),
        ("normals_view_no_mtl", 0x05, NEGATIVE, "", b""),
    ];
    for (name, config, obj, mtl, tex) in seeds {
        let data = encode(config, obj.as_bytes(), mtl.as_bytes(), tex);
        assert!(crate::obj_load::run(&data), "seed {name} does not load");
        write(dir, name, &data);
    }
    seeds.len()
}

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// Writes the `raster` seeds into `dir` and the candidates that broke an invariant into `panics`; returns how many
/// of each.
fn raster_seeds(dir: &Path, panics: &Path) -> (usize, usize) {
    let mut rng = Rng(0x5EED_0F7A_57E2);
    let mut kinds = BTreeSet::new();
    let (mut written, mut broken) = (0, 0);
    for _ in 0..2_000_000 {
        let len = 96 + (rng.next() % 320) as usize;
        let bytes: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        let Ok(input) = Input::arbitrary_take_rest(Unstructured::new(&bytes)) else { continue };
        let kind = input.kind();
        // A candidate that breaks an invariant is a finding for the fuzzer, not a seed: report it and go on.
        let result = std::panic::catch_unwind(|| run(input));
        let stats = match result {
            Ok(Some(stats)) if stats.fragments > 0 => stats,
            Ok(_) => continue,
            Err(_) => {
                let name = format!("seed-panic-{:016x}", rng.next());
                eprintln!("a random candidate broke an invariant: saved as {}", panics.join(&name).display());
                fs::create_dir_all(panics).expect("creating artifacts/raster");
                write(panics, &name, &bytes);
                broken += 1;
                continue;
            }
        };
        let kind = kind | u32::from(stats.clipped > 0) << 10;
        if !kinds.insert(kind) {
            continue;
        }
        write(dir, &format!("scene-{kind:03x}-{}px", stats.fragments), &bytes);
        written += 1;
    }
    (written, broken)
}

/// The tetrahedron's triangles as binary STL, after an 80-byte header starting with `header`.
fn binary_tetra(header: &[u8]) -> Vec<u8> {
    let corners: [[f32; 9]; 4] = [
        [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
    ];
    let mut bytes = vec![0u8; 80];
    bytes[..header.len()].copy_from_slice(header);
    bytes.extend_from_slice(&4u32.to_le_bytes());
    for triangle in corners {
        bytes.extend_from_slice(&[0; 12]);
        for v in triangle {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        bytes.extend_from_slice(&[0, 0]);
    }
    bytes
}

fn stl_seeds(dir: &Path) -> usize {
    let mut padded = binary_tetra(b"");
    padded.extend_from_slice(b"trailing bytes");
    let seeds: [(&str, u8, Vec<u8>); 4] = [
        ("ascii_flat_phong", 0x03, TETRA_ASCII.as_bytes().to_vec()),
        ("ascii_smooth_60_wireframe", 0x80 | 42 | 0x08, TETRA_ASCII.as_bytes().to_vec()),
        ("binary_solid_header_gouraud", 0x02, binary_tetra(b"solid but binary")),
        ("binary_padded_smooth_ortho", 0x80 | 0x20 | 0x7f, padded),
    ];
    for (name, config, stl) in &seeds {
        let data = crate::stl_load::encode(*config, stl);
        assert!(crate::stl_load::run(&data), "seed {name} does not load");
        write(dir, name, &data);
    }
    seeds.len()
}

/// A triangle in `.gltf` JSON, its buffer (three `f32` corners) in a data URI: flat normals are computed.
const GLTF_TRIANGLE: &str = r#"{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
"nodes": [{"mesh": 0, "rotation": [0, 0.7071068, 0, 0.7071068]}],
"buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews": [{"buffer": 0, "byteLength": 36}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]}"#;

/// A binary glTF file of `json` and the binary chunk `bin` (each padded to 4 bytes, as the format asks).
pub(crate) fn glb(json: &str, bin: &[u8]) -> Vec<u8> {
    let mut json = json.as_bytes().to_vec();
    json.resize(json.len().next_multiple_of(4), b' ');
    let mut bin = bin.to_vec();
    bin.resize(bin.len().next_multiple_of(4), 0);
    let total = (12 + 8 + json.len() + 8 + bin.len()) as u32;
    let mut out = b"glTF".to_vec();
    for word in [2, total, json.len() as u32] {
        out.extend_from_slice(&word.to_le_bytes());
    }
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

/// Little-endian bytes of `values`.
fn floats(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// Squares placed by every kind of node, with every attribute and map read, under a point, a spot and a
/// directional light.
fn gltf_squares() -> Vec<u8> {
    let mut bin = floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0]); // 0: 48 positions
    bin.extend(floats(&[0.0, 0.0, 1.0].repeat(4))); // 48: normals
    bin.extend(floats(&[0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0])); // 96: 32 texture coordinates
    bin.extend(floats(&[1.0, 0.0, 0.0, 1.0].repeat(4))); // 128: 64 tangents
    bin.extend([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255]); // 192: 16 colours
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes())); // 208: 12 indices
    let mut png = Vec::new();
    rastty_scene::png_file::encode_png(&mut png, 2, 2, &[0xFF0000, 0x00FF00, 0x8080FF, 0xFFFFFF]).expect("a PNG");
    let png_at = bin.len().next_multiple_of(4); // 220
    bin.resize(png_at, 0);
    bin.extend_from_slice(&png);
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}},
"extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_lights_punctual"],
"extensions": {{"KHR_lights_punctual": {{"lights": [{{"type": "point", "intensity": 4, "range": 5}},
  {{"type": "spot", "color": [1, 0.8, 0.6], "intensity": 9, "spot": {{"innerConeAngle": 0.2, "outerConeAngle": 0.6}}}},
  {{"type": "directional", "intensity": 2}}]}}}},
"scene": 0, "scenes": [{{"nodes": [0, 1, 3, 4, 5, 6]}}],
"nodes": [{{"mesh": 0}}, {{"mesh": 1, "translation": [2, 0, 0], "children": [2]}},
  {{"mesh": 0, "matrix": [0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 3, 0, 1]}}, {{"mesh": 1, "scale": [-1, 1, 1]}},
  {{"extensions": {{"KHR_lights_punctual": {{"light": 0}}}}, "translation": [0.5, 0.5, 1]}},
  {{"extensions": {{"KHR_lights_punctual": {{"light": 1}}}}, "translation": [1, 1, 2]}},
  {{"extensions": {{"KHR_lights_punctual": {{"light": 2}}}}, "rotation": [-0.38268343, 0, 0, 0.9238795]}}],
"buffers": [{{"byteLength": {}}}],
"bufferViews": [{{"buffer": 0, "byteLength": 192}}, {{"buffer": 0, "byteOffset": 192, "byteLength": 16}},
  {{"buffer": 0, "byteOffset": 208, "byteLength": 12}}, {{"buffer": 0, "byteOffset": {png_at}, "byteLength": {}}}],
"accessors": [
  {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}},
  {{"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"}},
  {{"bufferView": 0, "byteOffset": 96, "componentType": 5126, "count": 4, "type": "VEC2"}},
  {{"bufferView": 0, "byteOffset": 128, "componentType": 5126, "count": 4, "type": "VEC4"}},
  {{"bufferView": 1, "componentType": 5121, "normalized": true, "count": 4, "type": "VEC4"}},
  {{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
"meshes": [
  {{"name": "textured", "primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 3,
    "COLOR_0": 4}}, "indices": 5, "material": 0}}]}},
  {{"name": "plain", "primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 5, "material": 1}}]}}],
"materials": [
  {{"name": "maps", "doubleSided": true, "normalTexture": {{"index": 0, "scale": 0.5}},
    "emissiveTexture": {{"index": 0}}, "emissiveFactor": [1, 0.5, 0.25],
    "extensions": {{"KHR_materials_emissive_strength": {{"emissiveStrength": 2}}}},
    "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "extensions": {{"KHR_texture_transform":
      {{"offset": [0.5, 0], "rotation": 0.3, "scale": [2, 2]}}}}}}, "metallicFactor": 1, "roughnessFactor": 0.2}}}},
  {{"name": "plain", "pbrMetallicRoughness": {{"baseColorFactor": [0.2, 0.4, 0.8, 1]}}}}],
"textures": [{{"source": 0}}], "images": [{{"bufferView": 3, "mimeType": "image/png"}}]}}"#,
        bin.len(),
        png.len()
    );
    glb(&json, &bin)
}

/// A strip with 8-bit indices, a fan, a sparse accessor over the strip's corners and a line primitive.
fn gltf_strip_fan_sparse() -> Vec<u8> {
    let mut bin = floats(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 2.0, 0.0]); // 0: 60
    bin.extend([0u8, 1, 2, 3, 4, 0, 0, 0]); // 60: strip indices (padded)
    bin.extend([4u32].iter().flat_map(|i| i.to_le_bytes())); // 68: sparse index
    bin.extend(floats(&[0.5, 3.0, 0.0])); // 72: sparse value
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
"buffers": [{{"byteLength": {}}}],
"bufferViews": [{{"buffer": 0, "byteLength": 60}}, {{"buffer": 0, "byteOffset": 60, "byteLength": 5}},
  {{"buffer": 0, "byteOffset": 68, "byteLength": 4}}, {{"buffer": 0, "byteOffset": 72, "byteLength": 12}}],
"accessors": [
  {{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3", "min": [0, 0, 0], "max": [1, 2, 0]}},
  {{"bufferView": 1, "componentType": 5121, "count": 5, "type": "SCALAR"}},
  {{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3", "min": [0, 0, 0], "max": [1, 3, 0],
    "sparse": {{"count": 1, "indices": {{"bufferView": 2, "componentType": 5125}}, "values": {{"bufferView": 3}}}}}}],
"meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1, "mode": 5}},
  {{"attributes": {{"POSITION": 2}}, "mode": 6}}, {{"attributes": {{"POSITION": 0}}, "mode": 1}}]}}]}}"#,
        bin.len()
    );
    glb(&json, &bin)
}

fn gltf_seeds(dir: &Path) -> usize {
    let seeds: [(&str, u8, Vec<u8>); 3] = [
        ("triangle_data_uri_flat", 0x01, GLTF_TRIANGLE.as_bytes().to_vec()),
        ("squares_every_map_phong_textured", 0x13, gltf_squares()),
        ("strip_fan_sparse_wireframe", 0x0B, gltf_strip_fan_sparse()),
    ];
    for (name, config, gltf) in &seeds {
        let data = crate::gltf_load::encode(*config, gltf);
        if let Err(e) = rastty_scene::model::load_gltf_bytes(*name, gltf, &rastty_scene::model::NoFiles) {
            panic!("seed {name} does not load: {e}");
        }
        assert!(crate::gltf_load::run(&data), "seed {name} does not load");
        write(dir, name, &data);
    }
    seeds.len()
}

fn animation_seeds(dir: &Path) -> usize {
    use crate::gltf_animation::{encode, run, seed_buffer};
    let mut count = 0;
    // Every pair of interpolations, one to four keys, each rotation type (choice: bits 0-1 rotations, 2-3 weights
    // and translations, 4-5 keys less one, 6-7 rotation type).
    for choice in [0x11u8, 0x15, 0x1A, 0x2E, 0x31, 0x35, 0x55, 0x95, 0x05] {
        let cubic = |bits: u8| bits & 3 == 2;
        let buffer = seed_buffer(usize::from((choice >> 4) & 3) + 1, cubic(choice), cubic(choice >> 2));
        let data = encode(choice, choice & 3, 0.5, &buffer);
        // A rotation type other than float reads the float bytes as integers: it still loads.
        assert!(run(&data), "seed {choice:#04x} does not load");
        write(dir, &format!("skin_morph_{choice:02x}"), &data);
        count += 1;
    }
    count
}

fn scene_seeds(dir: &Path) -> usize {
    assert!(crate::scene_parse::run(BUILTIN_SCENE.as_bytes()), "the built-in scene does not parse");
    write(dir, "builtin_spots", BUILTIN_SCENE.as_bytes());
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes");
    let mut count = 1;
    let mut entries: Vec<_> =
        fs::read_dir(&scenes).expect("assets/scenes").map(|e| e.expect("an entry").path()).collect();
    entries.sort();
    for path in entries.into_iter().filter(|p| p.extension().is_some_and(|e| e == "toml")) {
        let text = fs::read(&path).expect("a scene file");
        assert!(crate::scene_parse::run(&text), "{} does not parse", path.display());
        write(dir, &path.file_name().expect("a name").to_string_lossy(), &text);
        count += 1;
    }
    count
}

/// The variable that makes the `raster` target write the corpora instead of fuzzing ([`write_if_asked`]).
pub const ASK: &str = "RASTTY_FUZZ_SEEDS";

/// Called by the `raster` target before it fuzzes: when [`ASK`] is set, writes the corpora ([`write_corpora`]) and
/// ends the process, with status 1 when a candidate broke an invariant.
pub fn write_if_asked() {
    if std::env::var_os(ASK).is_some() {
        std::process::exit(i32::from(write_corpora() > 0));
    }
}

/// Writes every target's seeds into `corpus/` and returns how many random candidates broke an invariant (each
/// saved in `artifacts/raster/`).
pub fn write_corpora() -> usize {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("corpus");
    let (obj, raster) = (root.join("obj_load"), root.join("raster"));
    let (stl, scene, gltf) = (root.join("stl_load"), root.join("scene_parse"), root.join("gltf_load"));
    let animation = root.join("gltf_animation");
    for dir in [&obj, &raster, &stl, &scene, &gltf, &animation] {
        fs::create_dir_all(dir).unwrap_or_else(|e| panic!("creating {}: {e}", dir.display()));
    }
    // The checks print panics of candidates they catch; keep the output to the summary.
    std::panic::set_hook(Box::new(|info| eprintln!("{info}")));
    let o = obj_seeds(&obj);
    let s = stl_seeds(&stl);
    let g = gltf_seeds(&gltf);
    let a = animation_seeds(&animation);
    let p = scene_seeds(&scene);
    let (r, broken) = raster_seeds(&raster, &Path::new(env!("CARGO_MANIFEST_DIR")).join("artifacts").join("raster"));
    println!(
        "wrote {o} seeds to {}, {s} to {}, {g} to {}, {a} to {}, {p} to {} and {r} to {}",
        obj.display(),
        stl.display(),
        gltf.display(),
        animation.display(),
        scene.display(),
        raster.display()
    );
    if broken > 0 {
        eprintln!("{broken} random candidates broke an invariant (saved in artifacts/raster/seed-panic-*)");
    }
    broken
}
