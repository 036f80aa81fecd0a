//! Scoring a picture against the reference.

use crate::reference::ReferenceImage;

use super::core_render::Rendered;

/// How far a picture is from the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Score {
    /// Peak signal-to-noise ratio over all channels of all pixels, in dB (infinite for an exact match).
    pub psnr: f64,
    /// The same over the pixels that no edge crosses (the reference covers all or none of their samples): the
    /// error of shading and texturing alone, without that of edges.
    pub inside_psnr: f64,
    /// Largest difference of any channel, in 8-bit steps, from the reference rounded to 8 bits.
    pub max_error: u32,
    /// Pixels covered in one picture and not in the other: the pixel centre against the exact centre test for
    /// one sample per pixel; the majority of samples against the reference's coverage of at least one half with
    /// supersampling or multisampling.
    pub coverage_errors: usize,
}

/// Scores `rendered` (drawn with one sample per pixel unless `sampled`) against `reference`.
pub fn score(reference: &ReferenceImage, rendered: &Rendered, sampled: bool) -> Score {
    let psnr = reference.psnr_rgb888(&rendered.pixels).unwrap_or(f64::INFINITY);
    let truth = reference.to_rgb888();
    let channel = |p: u32, shift: u32| ((p >> shift) & 0xFF) as i32;
    let max_error = truth
        .iter()
        .zip(&rendered.pixels)
        .map(|(&t, &p)| [16, 8, 0].iter().map(|&s| channel(t, s).abs_diff(channel(p, s))).max().unwrap_or(0))
        .max()
        .unwrap_or(0);
    let coverage_errors = (0..truth.len())
        .filter(|&i| {
            let ours = rendered.coverage[i];
            if sampled {
                (ours >= 0.5) != (reference.coverage[i] >= 0.5)
            } else {
                (ours > 0.0) != reference.centre_covered[i]
            }
        })
        .count();
    let inside: Vec<usize> =
        (0..truth.len()).filter(|&i| reference.coverage[i] == 0.0 || reference.coverage[i] == 1.0).collect();
    let squared: f64 = inside
        .iter()
        .map(|&i| {
            let (c, p) = (reference.rgb[i], rendered.pixels[i]);
            let ch = |shift: u32| f64::from((p >> shift) & 0xFF) / 255.0;
            [c[0] - ch(16), c[1] - ch(8), c[2] - ch(0)].iter().map(|v| v * v).sum::<f64>()
        })
        .sum();
    let inside_psnr = if squared > 0.0 { -10.0 * (squared / (3 * inside.len()) as f64).log10() } else { f64::INFINITY };
    Score { psnr, inside_psnr, max_error, coverage_errors }
}
