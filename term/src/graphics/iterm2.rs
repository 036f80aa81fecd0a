//! iTerm2's inline images: a frame as a PNG file in one OSC 1337 sequence
//! (<https://iterm2.com/documentation-images.html>), which iTerm2, WezTerm and others show.
//!
//! `ESC ] 1337 ; File=inline=1;size=N;width=Cc;height=Rr;preserveAspectRatio=0 : BASE64 BEL`: the image fills
//! `C` columns and `R` rows from the cursor. The protocol has no image ids, so each frame is drawn over the last.

use std::io::Write;

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;

use crate::screen::PixelFrame;
use rastty_scene::png_file::encode_png;

/// Appends `frame` as an inline image covering `columns` x `rows` cells from the cursor. An empty frame sends
/// nothing.
pub fn write_image(out: &mut Vec<u8>, frame: PixelFrame<'_>, columns: u16, rows: u16) {
    if frame.pixels().is_empty() {
        return;
    }
    let mut png = Vec::new();
    // Sizes and pixel count agree (a PixelFrame checks them), and the PNG goes into memory: it cannot fail.
    let (width, height) = (frame.width() as u32, frame.height() as u32);
    encode_png(&mut png, width, height, frame.pixels()).expect("a PNG of a whole frame, into memory");
    let _ =
        write!(out, "\x1b]1337;File=inline=1;size={};width={columns};height={rows};preserveAspectRatio=0:", png.len());
    out.extend_from_slice(BASE64.encode(&png).as_bytes());
    out.push(0x07);
}
