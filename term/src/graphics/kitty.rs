//! The kitty graphics protocol: a frame sent as one image rather than as cells
//! (<https://sw.kovidgoyal.net/kitty/graphics-protocol/>).
//!
//! A frame goes out as 24-bit RGB (`f=24`) compressed with zlib (`o=z`), its base64 split into chunks of at most
//! [`CHUNK_BYTES`] bytes (`m=1` on every chunk but the last, which has `m=0`; only the first chunk carries the
//! other keys, as the protocol asks). It is transmitted and placed in one step (`a=T`) under an image id and a
//! placement id of the viewer's own: the terminal replaces the image it showed under the same ids in place, so
//! there is no blank frame between two pictures. The placement covers a rectangle of cells (`c`, `r`), leaves the
//! cursor where it was (`C=1`) and lies under the text (`z=-1`), so the HUD and help drawn as cells stay on top;
//! `q=2` asks the terminal not to answer, so no reply arrives among the keys. [`write_placement`] shows the image
//! the terminal holds again without sending it (`a=p`), and [`write_delete`] removes the image and frees its memory
//! (`a=d,d=I`). Inside tmux, [`write_virtual_frame`] sends a frame to be shown by Unicode placeholders instead
//! ([`crate::screen::image_placeholder`]).

use std::io::Write;

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;
use flate2::Compression;
use flate2::write::ZlibEncoder;

use crate::screen::PixelFrame;

/// The most base64 bytes in one escape sequence (the protocol's limit for chunked transmission).
pub const CHUNK_BYTES: usize = 4096;

/// The placement id the viewer uses for its one image.
pub const PLACEMENT_ID: u32 = 1;

/// Where a frame goes on the cell grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KittyPlacement {
    /// The image's id (at least 1); a frame sent under the id of an image on the screen replaces it.
    pub image_id: u32,
    /// Column of the top-left cell, from 0.
    pub column: u16,
    /// Row of the top-left cell, from 0.
    pub row: u16,
    /// Columns the image covers (scaled to fit them).
    pub columns: u16,
    /// Rows the image covers.
    pub rows: u16,
}

/// Appends to `out` the escape sequences that show `frame` at `placement`, replacing the image shown under the same
/// id. The cursor is moved to the placement's top-left cell first and stays there. An empty frame sends nothing.
pub fn write_frame(out: &mut Vec<u8>, frame: PixelFrame<'_>, placement: &KittyPlacement) {
    if frame.pixels().is_empty() {
        return;
    }
    // Cursor position (CUP) is 1-based.
    let _ = write!(out, "\x1b[{};{}H", u32::from(placement.row) + 1, u32::from(placement.column) + 1);
    let keys = format!(
        "a=T,f=24,o=z,s={},v={},i={},p={PLACEMENT_ID},c={},r={},C=1,z=-1,q=2,",
        frame.width(),
        frame.height(),
        placement.image_id,
        placement.columns,
        placement.rows
    );
    write_chunks(out, frame, &keys);
}

/// Appends to `out` the escape sequences that send `frame` as image `image_id` with a virtual placement of
/// `columns` x `rows` cells (`U=1`), for Unicode placeholders to show
/// ([`crate::screen::image_placeholder`]); it replaces the image sent under the same id, and the placeholders on the
/// screen show the new one. The cursor does not move. An empty frame sends nothing.
pub fn write_virtual_frame(out: &mut Vec<u8>, frame: PixelFrame<'_>, image_id: u32, columns: u16, rows: u16) {
    if frame.pixels().is_empty() {
        return;
    }
    let keys =
        format!("a=T,U=1,f=24,o=z,s={},v={},i={image_id},c={columns},r={rows},q=2,", frame.width(), frame.height());
    write_chunks(out, frame, &keys);
}

/// Appends `frame` as zlib-compressed RGB in base64 chunks, the first one with `keys` (which end with a comma).
fn write_chunks(out: &mut Vec<u8>, frame: PixelFrame<'_>, keys: &str) {
    let mut rgb = Vec::with_capacity(frame.pixels().len() * 3);
    for &pixel in frame.pixels() {
        let [_, r, g, b] = pixel.to_be_bytes();
        rgb.extend_from_slice(&[r, g, b]);
    }
    // Level 1: a frame is compressed for every picture the viewer sends, so speed counts more than the last bytes.
    let mut zlib = ZlibEncoder::new(Vec::with_capacity(rgb.len() / 4), Compression::fast());
    let compressed = zlib.write_all(&rgb).and_then(|()| zlib.finish()).expect("writing into memory cannot fail");
    let payload = BASE64.encode(compressed);
    let chunks = payload.as_bytes().chunks(CHUNK_BYTES);
    let last = chunks.len().saturating_sub(1);
    for (i, chunk) in chunks.enumerate() {
        out.extend_from_slice(b"\x1b_G");
        if i == 0 {
            out.extend_from_slice(keys.as_bytes());
        }
        let _ = write!(out, "m={};", u8::from(i < last));
        out.extend_from_slice(chunk);
        out.extend_from_slice(b"\x1b\\");
    }
}

/// Appends the escape sequences that place the image the terminal already holds under `placement`'s id again, at
/// `placement` (`a=p`, with the keys [`write_frame`] places with): no pixels cross the link.
pub fn write_placement(out: &mut Vec<u8>, placement: &KittyPlacement) {
    let _ = write!(
        out,
        "\x1b[{};{}H\x1b_Ga=p,i={},p={PLACEMENT_ID},c={},r={},C=1,z=-1,q=2\x1b\\",
        u32::from(placement.row) + 1,
        u32::from(placement.column) + 1,
        placement.image_id,
        placement.columns,
        placement.rows
    );
}

/// Appends the escape sequence that deletes image `image_id`, its placements and its data.
pub fn write_delete(out: &mut Vec<u8>, image_id: u32) {
    let _ = write!(out, "\x1b_Ga=d,d=I,i={image_id},q=2\x1b\\");
}

#[cfg(test)]
mod tests {
    use std::io::Read;

    use super::*;

    /// The escape sequences of `bytes` (after a leading cursor move): each one's keys and payload.
    fn sequences(bytes: &[u8]) -> Vec<(String, Vec<u8>)> {
        let text = std::str::from_utf8(bytes).expect("the protocol is ASCII");
        let body = &text[text.find("\x1b_G").expect("an APC")..];
        body.split_terminator("\x1b\\")
            .map(|sequence| {
                let sequence = sequence.strip_prefix("\x1b_G").expect("each sequence starts with ESC _ G");
                let (keys, payload) = sequence.split_once(';').expect("keys ; payload");
                (keys.to_owned(), payload.as_bytes().to_vec())
            })
            .collect()
    }

    #[test]
    fn a_frame_decodes_back_to_its_pixels() {
        // Noise compresses badly, so the payload takes several chunks.
        let mut state = 1u32;
        let pixels: Vec<u32> = (0..97 * 61)
            .map(|_| {
                state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                state >> 8
            })
            .collect();
        let placement = KittyPlacement { image_id: 7, column: 2, row: 3, columns: 40, rows: 12 };
        let mut out = Vec::new();
        write_frame(&mut out, PixelFrame::new(&pixels, 97, 61), &placement);
        assert!(out.starts_with(b"\x1b[4;3H\x1b_G"), "{:?}", &out[..16]);
        let sequences = sequences(&out);
        assert!(sequences.len() > 3, "{} chunks", sequences.len());
        assert_eq!(sequences[0].0, "a=T,f=24,o=z,s=97,v=61,i=7,p=1,c=40,r=12,C=1,z=-1,q=2,m=1");
        for (i, (keys, payload)) in sequences.iter().enumerate() {
            assert!(payload.len() <= CHUNK_BYTES && !payload.is_empty());
            let last = i + 1 == sequences.len();
            assert!(keys.ends_with(if last { "m=0" } else { "m=1" }), "{keys}");
            if i > 0 {
                assert_eq!(keys, if last { "m=0" } else { "m=1" });
            }
        }
        let base64: Vec<u8> = sequences.iter().flat_map(|(_, payload)| payload.iter().copied()).collect();
        let compressed = BASE64.decode(base64).expect("base64");
        let mut rgb = Vec::new();
        flate2::read::ZlibDecoder::new(&compressed[..]).read_to_end(&mut rgb).expect("zlib");
        let decoded: Vec<u32> = rgb.chunks_exact(3).map(|c| u32::from_be_bytes([0, c[0], c[1], c[2]])).collect();
        assert_eq!(decoded, pixels);
    }

    #[test]
    fn a_small_frame_is_one_sequence_and_delete_names_the_image() {
        let mut out = Vec::new();
        let placement = KittyPlacement { image_id: 1, column: 0, row: 0, columns: 1, rows: 1 };
        write_frame(&mut out, PixelFrame::new(&[0xFF0000; 4], 2, 2), &placement);
        assert_eq!(sequences(&out).len(), 1);
        assert!(sequences(&out)[0].0.ends_with(",q=2,m=0"));
        let mut empty = Vec::new();
        write_frame(&mut empty, PixelFrame::new(&[], 0, 0), &placement);
        assert!(empty.is_empty());
        let mut delete = Vec::new();
        write_delete(&mut delete, 9);
        assert_eq!(delete, b"\x1b_Ga=d,d=I,i=9,q=2\x1b\\");
    }

    #[test]
    fn a_placement_shows_the_held_image_again_without_pixels() {
        let mut out = Vec::new();
        write_placement(&mut out, &KittyPlacement { image_id: 7, column: 3, row: 2, columns: 40, rows: 12 });
        assert_eq!(out, b"\x1b[3;4H\x1b_Ga=p,i=7,p=1,c=40,r=12,C=1,z=-1,q=2\x1b\\");
    }

    #[test]
    fn a_virtual_frame_keeps_the_cursor_and_names_its_cells() {
        let pixels: Vec<u32> = (0..6 * 4).map(|i| i * 0x010203).collect();
        let mut out = Vec::new();
        write_virtual_frame(&mut out, PixelFrame::new(&pixels, 6, 4), 42, 3, 2);
        assert!(out.starts_with(b"\x1b_G"), "no cursor move: {:?}", &out[..8]);
        let sequences = sequences(&out);
        assert_eq!(sequences.len(), 1);
        assert_eq!(sequences[0].0, "a=T,U=1,f=24,o=z,s=6,v=4,i=42,c=3,r=2,q=2,m=0");
        let compressed = BASE64.decode(&sequences[0].1).expect("base64");
        let mut rgb = Vec::new();
        flate2::read::ZlibDecoder::new(&compressed[..]).read_to_end(&mut rgb).expect("zlib");
        let decoded: Vec<u32> = rgb.chunks_exact(3).map(|c| u32::from_be_bytes([0, c[0], c[1], c[2]])).collect();
        assert_eq!(decoded, pixels);
        let mut empty = Vec::new();
        write_virtual_frame(&mut empty, PixelFrame::new(&[], 0, 0), 42, 3, 2);
        assert!(empty.is_empty());
    }
}
