//! Sixel: a frame as a palette image in a DCS string, six pixel rows per band (DEC, "VT330/VT340 Programmer
//! Reference Manual", chapter 14, "Sixel Graphics").
//!
//! The string opens with `ESC P 0;1;0 q` (pixels not drawn keep what is under them) and raster attributes
//! `"1;1;W;H` (square pixels, the image's size), then the palette (`#n;2;r;g;b`, channels in percent). Each band of
//! six rows draws every colour it uses in turn: `#n`, then one character per column, `?` (63) plus a bit per row
//! that has the colour, runs of four or more written `!count` and the character; `$` returns to the band's left
//! edge for the next colour, `-` moves to the next band. A colour's pass starts at its first column (the columns
//! before skipped as one run of `?`) and ends at its last. `ESC \` closes the string.

use std::io::Write;

use super::frame_palette::IndexedFrame;

/// Pixel rows per band.
const BAND_ROWS: usize = 6;

/// Appends `frame` as one Sixel image to `out`; it is drawn at the cursor. An empty frame sends nothing.
pub fn write_image(out: &mut Vec<u8>, frame: &IndexedFrame) {
    let (width, height) = (frame.width, frame.height);
    if width == 0 || height == 0 {
        return;
    }
    let _ = write!(out, "\x1bP0;1;0q\"1;1;{width};{height}");
    for (n, [r, g, b]) in frame.palette.iter().enumerate() {
        let percent = |v: u8| (u32::from(v) * 100 + 127) / 255;
        let _ = write!(out, "#{n};2;{};{};{}", percent(*r), percent(*g), percent(*b));
    }
    // Per colour: its six-bit column values in the band, and the first and last column it is in.
    let mut columns = vec![0u8; frame.palette.len() * width];
    let mut span = vec![(usize::MAX, 0usize); frame.palette.len()];
    let mut used: Vec<usize> = Vec::with_capacity(frame.palette.len());
    for (band, first_row) in (0..height).step_by(BAND_ROWS).enumerate() {
        if band > 0 {
            out.push(b'-');
        }
        for bit in 0..BAND_ROWS.min(height - first_row) {
            let row = &frame.indices[(first_row + bit) * width..][..width];
            for (x, &index) in row.iter().enumerate() {
                let colour = usize::from(index);
                if span[colour].0 == usize::MAX {
                    used.push(colour);
                }
                columns[colour * width + x] |= 1 << bit;
                span[colour] = (span[colour].0.min(x), span[colour].1.max(x));
            }
        }
        used.sort_unstable();
        for (k, &colour) in used.iter().enumerate() {
            if k > 0 {
                out.push(b'$');
            }
            let (start, end) = span[colour];
            let _ = write!(out, "#{colour}");
            write_run(out, b'?', start);
            let values = &mut columns[colour * width..][..width];
            let mut x = start;
            while x <= end {
                let value = values[x];
                let run = values[x..=end].iter().take_while(|&&v| v == value).count();
                write_run(out, b'?' + value, run);
                x += run;
            }
            values[start..=end].fill(0);
            span[colour] = (usize::MAX, 0);
        }
        used.clear();
    }
    out.extend_from_slice(b"\x1b\\");
}

/// Appends `count` copies of the sixel character `ch`: as they are below four, else `!count` and `ch`.
fn write_run(out: &mut Vec<u8>, ch: u8, count: usize) {
    if count >= 4 {
        let _ = write!(out, "!{count}");
        out.push(ch);
    } else {
        out.extend(std::iter::repeat_n(ch, count));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_image_is_written_as_the_manual_describes() {
        // 5 x 2: a red run of four then blue on top, all blue below.
        let frame = IndexedFrame {
            palette: vec![[255, 0, 0], [0, 0, 255]],
            indices: vec![0, 0, 0, 0, 1, 1, 1, 1, 1, 1],
            width: 5,
            height: 2,
        };
        let mut out = Vec::new();
        write_image(&mut out, &frame);
        let text = String::from_utf8(out).unwrap();
        // Red: rows 0 of columns 0-3 (bit 0: '@'). Blue: column 4 rows 0 and 1 ('B'), rows 1 of columns 0-3 ('A').
        assert_eq!(text, "\x1bP0;1;0q\"1;1;5;2#0;2;100;0;0#1;2;0;0;100#0!4@$#1!4AB\x1b\\");
    }
}
