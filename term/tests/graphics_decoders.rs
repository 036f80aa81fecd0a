//! Pixel images decoded back by decoders made for their formats, not by the project's code: Sixel by `icy_sixel`,
//! kitty's payload by the base64 and zlib decoders and the frame's own framing rules, iTerm2's PNG by the `png`
//! crate's decoder.

use std::io::Read;

use base64::Engine;
use rastty::graphics::frame_palette::{Dither, IndexedFrame, Learning, reduce};
use rastty::graphics::{kitty, sixel};
use rastty::screen::PixelFrame;

/// A 173 x 97 test picture (its height not a multiple of six rows): gradients in two directions, a disc and
/// noise in one corner, so it has far more colours than a palette holds.
fn picture() -> (Vec<u32>, usize, usize) {
    let (width, height) = (173usize, 97usize);
    let mut state = 12345u32;
    let pixels = (0..width * height)
        .map(|i| {
            let (x, y) = (i % width, i / width);
            let (dx, dy) = (x as i32 - 120, y as i32 - 40);
            if dx * dx + dy * dy < 400 {
                return 0xE0B040;
            }
            if x < 30 && y < 30 {
                state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                return state >> 8;
            }
            ((x * 255 / width) as u32) << 16 | ((y * 255 / height) as u32) << 8 | 0x50
        })
        .collect();
    (pixels, width, height)
}

/// The decoded image's RGBA pixels of the frame's own rows. A decoder fills the last band of six rows whole, so
/// the rows below the frame's height must be left undrawn (alpha 0: what was on the screen stays).
fn frame_rows(image: &icy_sixel::SixelImage, width: usize, height: usize) -> Vec<[u8; 4]> {
    assert_eq!((image.width, image.height), (width, height.div_ceil(6) * 6));
    let (rows, below) = image.pixels.split_at(width * height * 4);
    assert!(below.chunks_exact(4).all(|p| p[3] == 0), "rows below the frame are drawn");
    rows.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]).collect()
}

fn shown(frame: &IndexedFrame) -> Vec<[u8; 3]> {
    frame.indices.iter().map(|&i| frame.palette[usize::from(i)]).collect()
}

#[test]
fn sixel_images_decode_to_their_palette_colours() {
    let (pixels, width, height) = picture();
    for dither in [Dither::None, Dither::FloydSteinberg] {
        let frame = reduce(PixelFrame::new(&pixels, width, height), 256, dither, Learning::Quick);
        let mut out = Vec::new();
        sixel::write_image(&mut out, &frame);
        let image = icy_sixel::SixelImage::decode(&out).expect("icy_sixel decodes the image");
        // Sixel gives channels in percent: a level comes back within 255 / 200 of itself.
        for (i, (decoded, wanted)) in frame_rows(&image, width, height).iter().zip(shown(&frame)).enumerate() {
            for c in 0..3 {
                let off = (i32::from(decoded[c]) - i32::from(wanted[c])).abs();
                assert!(off <= 2, "{dither:?} pixel ({}, {}): {decoded:?} for {wanted:?}", i % width, i / width);
            }
            assert_eq!(decoded[3], 255, "every pixel is drawn");
        }
    }
}

#[test]
fn sixel_images_of_few_colours_and_odd_sizes_decode_exactly() {
    for (width, height) in [(1, 1), (7, 5), (6, 6), (40, 13)] {
        let pixels: Vec<u32> = (0..width * height).map(|i| [0x000000, 0xFFFFFF, 0xFF0000][i % 3]).collect();
        let frame = reduce(PixelFrame::new(&pixels, width, height), 256, Dither::None, Learning::Quick);
        let mut out = Vec::new();
        sixel::write_image(&mut out, &frame);
        let image = icy_sixel::SixelImage::decode(&out).expect("icy_sixel decodes the image");
        let rows = frame_rows(&image, width, height);
        assert!(rows.iter().all(|p| p[3] == 255), "every pixel is drawn");
        let decoded: Vec<u32> = rows.iter().map(|p| u32::from_be_bytes([0, p[0], p[1], p[2]])).collect();
        assert_eq!(decoded, pixels, "{width}x{height}");
    }
}

#[test]
fn kitty_frames_decode_to_the_frame() {
    let (pixels, width, height) = picture();
    let placement = kitty::KittyPlacement { image_id: 3, column: 0, row: 0, columns: 60, rows: 17 };
    let mut out = Vec::new();
    kitty::write_frame(&mut out, PixelFrame::new(&pixels, width, height), &placement);
    let text = String::from_utf8(out).expect("the protocol is ASCII");
    let mut payload = String::new();
    for (i, sequence) in text.split("\x1b_G").skip(1).enumerate() {
        let sequence = sequence.strip_suffix("\x1b\\").expect("each sequence ends with ST");
        let (keys, data) = sequence.split_once(';').expect("keys ; payload");
        assert!(data.len() <= kitty::CHUNK_BYTES);
        if i == 0 {
            assert!(keys.contains(&format!("s={width},v={height},i=3")), "{keys}");
        }
        payload.push_str(data);
    }
    let compressed = base64::engine::general_purpose::STANDARD.decode(payload).expect("base64");
    let mut rgb = Vec::new();
    flate2::read::ZlibDecoder::new(&compressed[..]).read_to_end(&mut rgb).expect("zlib");
    let decoded: Vec<u32> = rgb.chunks_exact(3).map(|c| u32::from_be_bytes([0, c[0], c[1], c[2]])).collect();
    assert_eq!(decoded, pixels);
}

#[test]
fn iterm2_images_decode_to_the_frame() {
    let (pixels, width, height) = picture();
    let mut out = Vec::new();
    rastty::graphics::iterm2::write_image(&mut out, PixelFrame::new(&pixels, width, height), 60, 17);
    let text = String::from_utf8(out).expect("the protocol is ASCII");
    let body = text.strip_prefix("\x1b]1337;File=").and_then(|t| t.strip_suffix('\x07')).expect("one OSC 1337");
    let (arguments, data) = body.split_once(':').expect("arguments : data");
    let png = base64::engine::general_purpose::STANDARD.decode(data).expect("base64");
    assert_eq!(arguments, format!("inline=1;size={};width=60;height=17;preserveAspectRatio=0", png.len()),);
    let mut reader = png::Decoder::new(std::io::Cursor::new(png)).read_info().expect("a PNG");
    let mut rgb = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut rgb).expect("the image");
    assert_eq!((info.width as usize, info.height as usize, info.color_type), (width, height, png::ColorType::Rgb));
    let decoded: Vec<u32> = rgb.chunks_exact(3).map(|c| u32::from_be_bytes([0, c[0], c[1], c[2]])).collect();
    assert_eq!(decoded, pixels);
}
