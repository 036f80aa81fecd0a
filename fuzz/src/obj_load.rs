//! The `obj_load` target: arbitrary bytes as OBJ text through `rastty::model::load_obj_bytes`, with an
//! `Embedded` resolver offering an MTL library and textures cut from the same input; a model that loads is checked
//! for consistency and rendered once.
//!
//! Input layout (every part may be cut short; missing parts are empty), written by [`encode`]:
//!
//! ```text
//! [config: u8] [obj length: u16 LE] [obj bytes] [mtl length: u16 LE] [mtl bytes] [texture bytes: the rest]
//! ```
//!
//! The resolver offers, relative to the OBJ file:
//! - `m.mtl` and `lib/m.mtl`: the MTL bytes;
//! - `t.png`, `t.tga`, `t.jpg`, `lib/t.png`: the texture bytes as they are (decoder robustness);
//! - `ok.png`, `ok.tga`, `lib/ok.png`: a valid 1..=8 x 1..=8 image whose size and texels come from the texture
//!   bytes (so that textured models render).
//!
//! The config byte picks the shading mode (bits 0..3), the wireframe (bit 3), textures on/off (bit 4) and an
//! orthographic lens (bit 5).

use rastty::model::{COORDINATE_LIMIT, Embedded, MAX_TEXTURE_SIDE, Model, load_obj_bytes};
use rastty::scene_file::SceneData;
use rastty::scene_render::{CameraOptions, PlanOptions, PreparedScene, ScenePlan, SceneRenderer, ShadingMode};
use rastty_core::target::{Rgb888, Target};

const WIDTH: u32 = 32;
const HEIGHT: u32 = 24;

/// Takes a `u16 LE` length and that many bytes (or what is left).
fn take<'a>(data: &mut &'a [u8]) -> &'a [u8] {
    let len = match *data {
        [a, b, ..] => usize::from(u16::from_le_bytes([*a, *b])),
        _ => data.len(),
    };
    *data = &data[data.len().min(2)..];
    let (part, rest) = data.split_at(len.min(data.len()));
    *data = rest;
    part
}

/// A small valid image from `bytes`: width, height, then RGB texels (cycled; grey when there are none).
fn image_from(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let w = 1 + u32::from(bytes.first().copied().unwrap_or(0) % 8);
    let h = 1 + u32::from(bytes.get(1).copied().unwrap_or(0) % 8);
    let data = bytes.get(2..).unwrap_or_default();
    let rgb = (0..(w * h * 3) as usize).map(|i| if data.is_empty() { 128 } else { data[i % data.len()] }).collect();
    (w, h, rgb)
}

fn encode_png(w: u32, h: u32, rgb: &[u8]) -> Vec<u8> {
    use image::ImageEncoder;
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(rgb, w, h, image::ExtendedColorType::Rgb8)
        .expect("encoding a tiny PNG in memory");
    out
}

/// An uncompressed 24-bit true-colour TGA, top row first (bit 5 of the descriptor), pixels stored BGR.
fn encode_tga(w: u32, h: u32, rgb: &[u8]) -> Vec<u8> {
    let mut out = vec![0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, w as u8, 0, h as u8, 0, 24, 0x20];
    for p in rgb.chunks_exact(3) {
        out.extend_from_slice(&[p[2], p[1], p[0]]);
    }
    out
}

fn has_control(text: &str) -> bool {
    text.chars().any(char::is_control)
}

/// The model is what `Model`'s documentation promises.
fn check_model(model: &Model) {
    let n = model.positions.len();
    assert!(n > 0, "a loaded model has no positions");
    assert!(!model.indices.is_empty(), "a loaded model has no triangles (NoTriangles expected)");
    assert_eq!(model.indices.len() % 3, 0, "indices do not form whole triangles");
    if let Some(i) = model.indices.iter().find(|&&i| i as usize >= n) {
        panic!("index {i} out of range for {n} positions");
    }
    assert_eq!(model.normals.len(), n, "normals.len() != positions.len()");
    if let Some(uvs) = &model.uvs {
        assert_eq!(uvs.len(), n, "uvs.len() != positions.len()");
        assert!(uvs.iter().all(|t| t.is_finite()), "a non-finite texture coordinate");
    }
    for p in &model.positions {
        assert!(p.is_finite(), "a non-finite position {p:?}");
        let m = p.x.abs().max(p.y.abs()).max(p.z.abs());
        assert!(m <= COORDINATE_LIMIT, "position {p:?} beyond COORDINATE_LIMIT");
    }
    assert!(model.normals.iter().all(|v| v.is_finite()), "a non-finite normal");

    // Parts: contiguous, in order, covering the index buffer, whole triangles, valid materials, meshes.
    let mut next = 0;
    for (i, part) in model.parts.iter().enumerate() {
        assert_eq!(part.indices.start, next, "part {i} does not start where the previous one ended");
        assert!(part.indices.start <= part.indices.end, "part {i} has a reversed range");
        assert!(part.indices.end <= model.indices.len(), "part {i} ends past the index buffer");
        assert_eq!(part.indices.len() % 3, 0, "part {i} does not hold whole triangles");
        if let Some(m) = part.material {
            assert!(m < model.materials.len(), "part {i} uses material {m} of {}", model.materials.len());
        }
        let mesh = model.part_mesh(i).unwrap_or_else(|| panic!("part {i} gives no mesh"));
        assert_eq!(mesh.triangle_count(), part.indices.len() / 3);
        next = part.indices.end;
    }
    assert_eq!(next, model.indices.len(), "the parts do not cover the index buffer");
    assert!(model.mesh().is_some(), "the whole model gives no mesh");

    for m in &model.materials {
        assert!(m.diffuse.is_finite(), "material {:?}: non-finite diffuse", m.name);
        if let Some(t) = &m.texture {
            assert!(t.width >= 1 && t.height >= 1, "an empty texture");
            assert!(t.width <= MAX_TEXTURE_SIDE && t.height <= MAX_TEXTURE_SIDE, "an oversized texture");
            assert_eq!(t.texels.len(), t.width as usize * t.height as usize, "texel count");
            assert!(t.texture().is_ok(), "the core refuses a loaded texture");
        }
    }
    for w in &model.warnings {
        assert!(!has_control(w), "a warning holds a control character: {w:?}");
    }
}

/// Loads, checks and renders one input (a failure is a panic). Returns whether the model loaded.
pub fn run(data: &[u8]) -> bool {
    let Some((&config, mut rest)) = data.split_first() else { return false };
    let obj = take(&mut rest);
    let mtl = take(&mut rest);
    let texture = rest;
    let (w, h, rgb) = image_from(texture);
    let png = encode_png(w, h, &rgb);
    let tga = encode_tga(w, h, &rgb);
    let files: [(&str, &[u8]); 9] = [
        ("m.mtl", mtl),
        ("lib/m.mtl", mtl),
        ("t.png", texture),
        ("t.tga", texture),
        ("t.jpg", texture),
        ("lib/t.png", texture),
        ("ok.png", &png),
        ("ok.tga", &tga),
        ("lib/ok.png", &png),
    ];

    let model = match load_obj_bytes("fuzz.obj", obj, &Embedded::new(&files)) {
        Ok(model) => model,
        Err(e) => {
            let text = e.to_string();
            assert!(!has_control(&text), "a load error holds a control character: {text:?}");
            return false;
        }
    };
    check_model(&model);

    let options = PlanOptions {
        shading: ShadingMode::ALL[usize::from(config & 7) % ShadingMode::ALL.len()],
        wireframe: config & 8 != 0,
        textures: config & 16 != 0,
        ..PlanOptions::default()
    };
    let camera = CameraOptions { orthographic: config & 32 != 0, ..CameraOptions::default() };
    let triangles = model.triangle_count() as u64;
    // The model as `rastty` shows it: a scene of one object, planned and drawn by the scene renderer.
    let scene = PreparedScene::new(SceneData::from_model(model, "fuzz.obj".into()))
        .unwrap_or_else(|e| panic!("a loaded model does not prepare: {e}"));
    let camera = camera.orbit(&scene).camera;
    let plan = ScenePlan::new(&scene, &camera, (WIDTH, HEIGHT), &options)
        .unwrap_or_else(|e| panic!("a loaded model does not plan: {e}"));
    let (mut pixels, mut depth) = (vec![0u32; (WIDTH * HEIGHT) as usize], vec![0f32; (WIDTH * HEIGHT) as usize]);
    let mut target = Target::new(Rgb888(&mut pixels), &mut depth[..], WIDTH, HEIGHT).expect("a valid frame");
    let report = SceneRenderer::with_threads(1)
        .render(&scene, &plan, &mut target)
        .unwrap_or_else(|e| panic!("a loaded model does not render: {e}"));
    let s = report.forward;
    assert_eq!(s.triangles_in, triangles, "{s:?}");
    assert_eq!(s.invalid + s.outside + s.culled + s.degenerate + s.rasterized, s.triangles_in, "{s:?}");
    true
}

/// An input in the layout [`run`] reads.
pub fn encode(config: u8, obj: &[u8], mtl: &[u8], texture: &[u8]) -> Vec<u8> {
    let mut out = vec![config];
    for part in [obj, mtl] {
        let len = u16::try_from(part.len()).expect("parts shorter than 64 KiB");
        out.extend_from_slice(&len.to_le_bytes());
        out.extend_from_slice(part);
    }
    out.extend_from_slice(texture);
    out
}
