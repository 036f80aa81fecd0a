//! Spot's texture, reduced for the firmware: `spot_texture.png` (1024 texels square) averaged over blocks of
//! texels into [`SIZE`] texels square, in linear light, and written as `0x00RRGGBB` sRGB texels (the core's
//! texture format) in a `static` array.
//!
//! A 256-texel square is 256 KiB of flash, and drawn over about half of a 320x240 display it gives about one texel
//! a pixel. The sRGB transfer functions are IEC 61966-2-1's, in `f64`, and every result is rounded to the nearest
//! code: a build machine whose `powf` differs in its last bit writes other texels only if that bit decides a
//! rounding, and the host test and the firmware, built on one machine, read the same array either way.

use std::fmt::Write as _;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

/// Width and height of the reduced texture, in texels.
pub const SIZE: usize = 256;

/// Writes `TEXTURE_SIZE` and `TEXELS`, the texture at `path` reduced to [`SIZE`] texels square.
///
/// # Panics
/// If the file cannot be read or decoded, is not 8-bit RGB or RGBA, or is not square with a side a multiple of
/// [`SIZE`] (a build script's error).
pub fn write(out: &mut String, path: &Path) {
    let texels = reduce(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    writeln!(out, "/// Width and height of [`TEXELS`], in texels.\npub const TEXTURE_SIZE: u32 = {SIZE};").unwrap();
    writeln!(
        out,
        "/// The texture, `0x00RRGGBB` sRGB texels, row-major, the top row first: `spot_texture.png` averaged in \
         linear light over blocks of texels.\npub static TEXELS: [u32; {}] = [",
        texels.len()
    )
    .unwrap();
    for row in texels.chunks(8) {
        let row: Vec<String> = row.iter().map(|t| format!("0x{t:06x}")).collect();
        writeln!(out, "    {},", row.join(", ")).unwrap();
    }
    out.push_str("];\n");
}

/// The texture at `path` averaged over square blocks into [`SIZE`] x [`SIZE`] texels.
fn reduce(path: &Path) -> Result<Vec<u32>, String> {
    let file = File::open(path).map_err(|e| e.to_string())?;
    let mut reader = png::Decoder::new(BufReader::new(file)).read_info().map_err(|e| e.to_string())?;
    let size = reader.output_buffer_size().ok_or("the image is too large")?;
    let mut bytes = vec![0u8; size];
    let info = reader.next_frame(&mut bytes).map_err(|e| e.to_string())?;
    let channels = match (info.color_type, info.bit_depth) {
        (png::ColorType::Rgb, png::BitDepth::Eight) => 3,
        (png::ColorType::Rgba, png::BitDepth::Eight) => 4,
        other => return Err(format!("{other:?}: 8-bit RGB or RGBA expected")),
    };
    let side = info.width as usize;
    if info.height as usize != side || side % SIZE != 0 {
        return Err(format!("{}x{}: square, a multiple of {SIZE} texels, expected", info.width, info.height));
    }
    let block = side / SIZE;
    let mut texels = Vec::with_capacity(SIZE * SIZE);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let mut sum = [0f64; 3];
            for dy in 0..block {
                let row = &bytes[(y * block + dy) * info.line_size..];
                for dx in 0..block {
                    let texel = &row[(x * block + dx) * channels..];
                    for (s, &code) in sum.iter_mut().zip(texel) {
                        *s += decode(code);
                    }
                }
            }
            let [r, g, b] = sum.map(|s| encode(s / (block * block) as f64));
            texels.push(r << 16 | g << 8 | b);
        }
    }
    Ok(texels)
}

/// An sRGB code as linear light.
fn decode(code: u8) -> f64 {
    let c = f64::from(code) / 255.0;
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// Linear light as the nearest sRGB code.
fn encode(linear: f64) -> u32 {
    let c = if linear <= 0.003_130_8 { linear * 12.92 } else { 1.055 * linear.powf(1.0 / 2.4) - 0.055 };
    (c * 255.0).round().clamp(0.0, 255.0) as u32
}
