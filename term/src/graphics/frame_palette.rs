//! A frame reduced to a palette of at most 256 colours, for the formats that need one (Sixel, the GIF turntable).
//!
//! A frame of at most as many distinct colours as the palette may hold keeps them exactly. Otherwise the palette
//! comes from NeuQuant (Dekker, "Kohonen neural networks for optimal colour quantization", 1994; the `color_quant`
//! crate, which the `image` crate's GIF encoder uses too), and each pixel takes its nearest entry, or, with
//! [`Dither::FloydSteinberg`], the nearest entry to the pixel plus the error diffused from its neighbours (Floyd and
//! Steinberg, "An adaptive algorithm for spatial greyscale", 1976).

use std::collections::HashMap;

use color_quant::NeuQuant;

use crate::screen::PixelFrame;

/// How pixels are mapped to the palette.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Dither {
    /// Each pixel its nearest entry: flat areas stay flat, gradients band.
    #[default]
    None,
    /// Floyd-Steinberg error diffusion: gradients without bands, at the price of noise that changes from frame to
    /// frame.
    FloydSteinberg,
}

/// The most colours a palette holds.
pub const MAX_COLORS: usize = 256;

/// How much of a frame NeuQuant learns its palette from: one pixel in every `1..=30` (its sampling factor).
/// Learning from more pixels errs less (`thorough_learning_sees_more_pixels_and_errs_less` checks it on a
/// gradient) and takes longer: `rastty render --turntable 36 -o spin.gif --stats` (release, the built-in model at
/// 800x600, [`Learning::Thorough`]) took a median of 63 and 62 ms a frame to learn in two runs, against 3.1 and
/// 2.9 ms to render.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Learning {
    /// A frame shown live (Sixel), where the time counts: one pixel in 30 of a large frame, fewer skipped in a
    /// small one, so that it sees at least 30 pixels a palette entry.
    #[default]
    Quick,
    /// A frame written to a file (the GIF turntable), learnt once and looked at many times: every pixel of a frame
    /// of up to [`THOROUGH_SAMPLES`] pixels, about that many of a larger one (one in 5 at 800x600), at most one in
    /// 30.
    Thorough,
}

impl Learning {
    /// The sampling factor for a frame of `pixels` reduced to `colors` colours.
    fn sample_factor(self, pixels: usize, colors: usize) -> usize {
        let factor = match self {
            Self::Quick => pixels / (colors * SAMPLES_PER_COLOR),
            Self::Thorough => pixels.div_ceil(THOROUGH_SAMPLES),
        };
        factor.clamp(1, MAX_SAMPLE_FACTOR)
    }
}

/// NeuQuant's largest sampling factor: it learns from one pixel in 30 at least.
const MAX_SAMPLE_FACTOR: usize = 30;

/// The fewest pixels NeuQuant learns from for each palette entry ([`Learning::Quick`]).
const SAMPLES_PER_COLOR: usize = 30;

/// About how many pixels NeuQuant learns from with [`Learning::Thorough`].
pub const THOROUGH_SAMPLES: usize = 100_000;

/// Slots of the cache of searched colours (a power of two; each holds the last colour that hashed to it).
const CACHE_SLOTS: usize = 1 << 14;

/// A frame as palette indices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IndexedFrame {
    /// The colours, `[r, g, b]`; at most [`MAX_COLORS`].
    pub palette: Vec<[u8; 3]>,
    /// One index into `palette` per pixel, row-major.
    pub indices: Vec<u8>,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
}

/// Reduces `frame` to at most `colors` colours (clamped to `2..=`[`MAX_COLORS`]), the palette learnt as closely as
/// `learning` says.
pub fn reduce(frame: PixelFrame<'_>, colors: usize, dither: Dither, learning: Learning) -> IndexedFrame {
    let colors = colors.clamp(2, MAX_COLORS);
    let (width, height) = (frame.width(), frame.height());
    if let Some((palette, indices)) = exact(frame.pixels(), colors) {
        return IndexedFrame { palette, indices, width, height };
    }
    let rgba: Vec<u8> = frame.pixels().iter().flat_map(|p| rgb(*p).into_iter().chain([255])).collect();
    let sample_factor = learning.sample_factor(frame.pixels().len(), colors);
    let quantizer = NeuQuant::new(sample_factor as i32, colors, &rgba);
    let palette: Vec<[u8; 3]> = quantizer.color_map_rgb().chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    let nearest = |c: [u8; 3]| quantizer.index_of(&[c[0], c[1], c[2], 255]) as u8;
    let indices = match dither {
        Dither::None => {
            // A rendered frame repeats its colours (the background, flat faces, runs along a row): a small cache
            // of the last colour searched for in each of its slots saves most searches.
            let mut known = vec![(u32::MAX, 0u8); CACHE_SLOTS];
            let slot = |p: u32| (p.wrapping_mul(0x9E37_79B1) >> (32 - CACHE_SLOTS.trailing_zeros())) as usize;
            let mut index_of = |p: u32| {
                let entry = &mut known[slot(p)];
                if entry.0 != p {
                    *entry = (p, nearest(rgb(p)));
                }
                entry.1
            };
            frame.pixels().iter().map(|&p| index_of(p)).collect()
        }
        Dither::FloydSteinberg => floyd_steinberg(frame, &palette, nearest),
    };
    IndexedFrame { palette, indices, width, height }
}

/// The frame's own colours as the palette, when there are at most `colors` of them.
fn exact(pixels: &[u32], colors: usize) -> Option<(Vec<[u8; 3]>, Vec<u8>)> {
    let mut index: HashMap<u32, u8> = HashMap::new();
    let mut palette = Vec::new();
    let mut indices = Vec::with_capacity(pixels.len());
    for &pixel in pixels {
        let i = match index.get(&pixel) {
            Some(&i) => i,
            None => {
                if palette.len() == colors {
                    return None;
                }
                // At most MAX_COLORS entries, so the index fits in a byte.
                let i = palette.len() as u8;
                index.insert(pixel, i);
                palette.push(rgb(pixel));
                i
            }
        };
        indices.push(i);
    }
    Some((palette, indices))
}

/// Maps every pixel to the entry `nearest` picks for it plus the error carried from the pixels before it: 7/16 to
/// the right, 3/16 down-left, 5/16 down, 1/16 down-right.
fn floyd_steinberg(frame: PixelFrame<'_>, palette: &[[u8; 3]], nearest: impl Fn([u8; 3]) -> u8) -> Vec<u8> {
    let width = frame.width();
    // The error carried into this row and the next, per channel, in 16ths of a level; one spare column each side.
    let mut this_row = vec![[0i32; 3]; width + 2];
    let mut next_row = vec![[0i32; 3]; width + 2];
    let mut indices = Vec::with_capacity(frame.pixels().len());
    for y in 0..frame.height() {
        for (x, &pixel) in frame.row(y).iter().enumerate() {
            let carried = this_row[x + 1];
            let wanted: [i32; 3] = std::array::from_fn(|c| i32::from(rgb(pixel)[c]) + carried[c] / 16);
            let index = nearest(wanted.map(|v| v.clamp(0, 255) as u8));
            let shown = palette[usize::from(index)];
            for c in 0..3 {
                let error = wanted[c] - i32::from(shown[c]);
                this_row[x + 2][c] += error * 7;
                next_row[x][c] += error * 3;
                next_row[x + 1][c] += error * 5;
                next_row[x + 2][c] += error;
            }
            indices.push(index);
        }
        std::mem::swap(&mut this_row, &mut next_row);
        next_row.fill([0; 3]);
    }
    indices
}

fn rgb(pixel: u32) -> [u8; 3] {
    let [_, r, g, b] = pixel.to_be_bytes();
    [r, g, b]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shown(frame: &IndexedFrame) -> Vec<[u8; 3]> {
        frame.indices.iter().map(|&i| frame.palette[usize::from(i)]).collect()
    }

    #[test]
    fn few_colours_are_kept_exactly() {
        let pixels = [0x102030, 0xFFFFFF, 0x102030, 0x000000, 0xFFFFFF, 0x0000FF];
        let frame = reduce(PixelFrame::new(&pixels, 3, 2), 4, Dither::FloydSteinberg, Learning::Quick);
        assert_eq!(frame.palette.len(), 4);
        assert_eq!(shown(&frame), pixels.map(rgb));
    }

    /// The mean over `size` x `size` blocks of a 64 x 64 frame of the summed channel distance between the block's
    /// mean shown colour and its mean wanted colour.
    fn block_error(shown: &[[u8; 3]], pixels: &[u32], size: usize) -> f64 {
        let mut total = 0.0;
        for by in (0..64).step_by(size) {
            for bx in (0..64).step_by(size) {
                let cells = || (by..by + size).flat_map(|y| (bx..bx + size).map(move |x| y * 64 + x));
                let sum = |colour: &dyn Fn(usize) -> [u8; 3]| {
                    cells().fold([0.0f64; 3], |s, i| std::array::from_fn(|c| s[c] + f64::from(colour(i)[c])))
                };
                let (shown_sum, wanted_sum) = (sum(&|i| shown[i]), sum(&|i| rgb(pixels[i])));
                total +=
                    shown_sum.iter().zip(wanted_sum).map(|(s, w)| (s - w).abs()).sum::<f64>() / (size * size) as f64;
            }
        }
        total / ((64 / size) * (64 / size)) as f64
    }

    #[test]
    fn a_gradient_gets_a_palette_of_the_size_asked_for_and_stays_close() {
        let pixels: Vec<u32> = (0..64 * 64).map(|i| ((i % 64) * 4) << 16 | ((i / 64) * 4) << 8 | 0x40).collect();
        let frame = |dither| reduce(PixelFrame::new(&pixels, 64, 64), 32, dither, Learning::Quick);
        let (flat, dithered) = (frame(Dither::None), frame(Dither::FloydSteinberg));
        for frame in [&flat, &dithered] {
            assert_eq!((frame.palette.len(), frame.indices.len()), (32, pixels.len()));
        }
        // A 32-entry grid over this square (about 6 x 6 steps of 50 levels) errs about 25 levels a pixel (12.5 in
        // each of red and green); NeuQuant is allowed a third more.
        let error = block_error(&shown(&flat), &pixels, 1);
        assert!(error < 33.0, "mean error {error} levels a pixel");
        // Dithering errs more per pixel but far less over an area (about half here).
        let (flat_area, dithered_area) =
            (block_error(&shown(&flat), &pixels, 4), block_error(&shown(&dithered), &pixels, 4));
        assert!(dithered_area < flat_area * 0.6, "4x4 areas: {dithered_area} dithered, {flat_area} not");
    }

    #[test]
    fn dithering_keeps_the_mean_colour_of_an_area() {
        // A flat grey on a black and white palette: every pixel is black or white, and the area's mean stays near
        // the grey.
        let pixels = vec![0x606060; 32 * 32];
        let palette = [[0, 0, 0], [255, 255, 255]];
        let indices = floyd_steinberg(PixelFrame::new(&pixels, 32, 32), &palette, |c| u8::from(c[0] >= 128));
        let mean = indices.iter().map(|&i| f64::from(palette[usize::from(i)][0])).sum::<f64>() / indices.len() as f64;
        assert!((mean - 96.0).abs() < 4.0, "mean {mean}");
        assert!(indices.contains(&0) && indices.contains(&1));
    }

    #[test]
    fn thorough_learning_sees_more_pixels_and_errs_less() {
        // Quick: one pixel in 30 at most, at least 30 a colour; thorough: about THOROUGH_SAMPLES pixels.
        assert_eq!(Learning::Quick.sample_factor(800 * 600, 256), 30);
        assert_eq!(Learning::Quick.sample_factor(320 * 240, 256), 10);
        assert_eq!(Learning::Thorough.sample_factor(800 * 600, 256), 5);
        assert_eq!(Learning::Thorough.sample_factor(320 * 240, 256), 1);
        assert_eq!(Learning::Thorough.sample_factor(8192 * 8192, 256), 30);
        // A 256 x 256 two-channel gradient in 64 colours: learning from every pixel errs less than from one in 30.
        let pixels: Vec<u32> = (0..256 * 256).map(|i| (i % 256) << 16 | (i / 256) << 8 | 0x80).collect();
        let error = |learning| {
            let frame = reduce(PixelFrame::new(&pixels, 256, 256), 64, Dither::None, learning);
            let shown = shown(&frame);
            let sum: u32 = shown
                .iter()
                .zip(&pixels)
                .map(|(s, &p)| (0..3).map(|c| u32::from(s[c].abs_diff(rgb(p)[c]))).sum::<u32>())
                .sum();
            f64::from(sum) / pixels.len() as f64
        };
        let (quick, thorough) = (error(Learning::Quick), error(Learning::Thorough));
        assert!(thorough < quick, "thorough {thorough}, quick {quick}");
    }
}
