//! The `obj_load` target: arbitrary bytes as OBJ text through `rastty_scene::model::load_obj_bytes`, with an
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
//! The config byte is [`render_once`]'s: the shading mode, the wireframe, textures and the lens.

use rastty_scene::model::{Embedded, load_obj_bytes};

use crate::model_checks::{check_load_error, check_model, render_once};

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
            check_load_error(&e);
            return false;
        }
    };
    check_model(&model);
    render_once(model, config, "fuzz.obj");
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
