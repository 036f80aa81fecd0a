//! Anti-aliasing by averaging samples into pixels: the four samples of a multisampled pixel, or the `k x k` pixels
//! of a frame rendered `k` times larger.
//!
//! A multisampled target ([`super::Target::multisampled`]) stores each pixel's samples one after the other;
//! [`resolve_rgb888`] averages them. For supersampling, render into a target `k` times wider and higher (or into
//! the matching band: rows `y0 * k .. y1 * k` of the large frame for rows `y0 .. y1` of the small one), then
//! [`downsample_rgb888`] averages each `k x k` block. Both are box filters, in linear light or on the stored codes.

use super::{Samples, TargetError};
use crate::color::{SRGB_DECODE, ShadingSpace, linear_to_srgb8};

/// Averages `factor x factor` blocks of `0x00RRGGBB` samples (`sample_width` per row) into `out`, one pixel per
/// block: in [`ShadingSpace::Linear`] the light the samples show (each code decoded, the mean encoded to the
/// nearest code), in [`ShadingSpace::Encoded`] the codes themselves (rounded to nearest).
///
/// # Errors
/// [`TargetError::ColorLength`] unless the samples form whole blocks and `out` holds exactly one pixel per block;
/// [`TargetError::Empty`] for a factor or width of zero.
///
/// # Examples
/// ```
/// use rastty_core::color::ShadingSpace;
/// use rastty_core::target::downsample_rgb888;
/// // Two 2x2 blocks: all red, and half red half black.
/// let samples = [0xFF0000, 0xFF0000, 0xFF0000, 0x000000, 0xFF0000, 0xFF0000, 0xFF0000, 0x000000];
/// let mut pixels = [0u32; 2];
/// downsample_rgb888(&samples, 4, 2, ShadingSpace::Encoded, &mut pixels).unwrap();
/// assert_eq!(pixels, [0xFF0000, 0x800000]);
/// // Half the light of full red is code 188, not 128.
/// downsample_rgb888(&samples, 4, 2, ShadingSpace::Linear, &mut pixels).unwrap();
/// assert_eq!(pixels, [0xFF0000, 0xBC0000]);
/// ```
pub fn downsample_rgb888(
    samples: &[u32],
    sample_width: u32,
    factor: u32,
    space: ShadingSpace,
    out: &mut [u32],
) -> Result<(), TargetError> {
    if factor == 0 || sample_width == 0 {
        return Err(TargetError::Empty);
    }
    let (f, sw) = (factor as usize, sample_width as usize);
    let sample_height = samples.len() / sw;
    let (w, h) = (sw / f, sample_height / f);
    if sw % f != 0 || samples.len() != sw * sample_height || sample_height % f != 0 {
        return Err(TargetError::ColorLength { expected: w * f * h * f, actual: samples.len() });
    }
    if out.len() != w * h {
        return Err(TargetError::ColorLength { expected: w * h, actual: out.len() });
    }
    let block = |y: usize, x: usize| {
        (0..f).flat_map(move |sy| {
            let start = (y * f + sy) * sw + x * f;
            samples[start..start + f].iter().copied()
        })
    };
    for (y, row) in out.chunks_exact_mut(w).enumerate() {
        for (x, pixel) in row.iter_mut().enumerate() {
            *pixel = average(block(y, x), (f * f) as u32, space);
        }
    }
    Ok(())
}

/// Averages the samples of a multisampled colour buffer, `per_pixel` consecutive `0x00RRGGBB` values per pixel (the
/// layout of [`super::Target::multisampled`]), into `out`, one value per pixel, as [`downsample_rgb888`] averages a
/// block: in light or on the codes, as `space` says. A band's samples resolve to that band's pixels.
///
/// # Errors
/// [`TargetError::ColorLength`] unless `samples` holds exactly `per_pixel` values for each pixel of `out`.
///
/// # Examples
/// ```
/// use rastty_core::color::ShadingSpace;
/// use rastty_core::target::{Samples, resolve_rgb888};
/// // A pixel with two of its four samples red: half the light of red.
/// let samples = [0xFF0000, 0x000000, 0xFF0000, 0x000000];
/// let mut pixel = [0u32; 1];
/// resolve_rgb888(&samples, Samples::Four, ShadingSpace::Linear, &mut pixel).unwrap();
/// assert_eq!(pixel, [0xBC0000]);
/// ```
pub fn resolve_rgb888(
    samples: &[u32],
    per_pixel: Samples,
    space: ShadingSpace,
    out: &mut [u32],
) -> Result<(), TargetError> {
    let n = per_pixel.count();
    if samples.len() != out.len() * n {
        return Err(TargetError::ColorLength { expected: out.len() * n, actual: samples.len() });
    }
    for (pixel, values) in out.iter_mut().zip(samples.chunks_exact(n)) {
        // Most pixels' samples agree (inside a triangle, or background), and the mean of equal values is that
        // value, in light too: each code's light lies inside its own rounding interval, so a rounding of the sum
        // does not change the code it encodes to (the unit test checks every code in both spaces).
        let first = values[0];
        *pixel = if values.iter().all(|&v| v == first) {
            first & 0x00FF_FFFF
        } else {
            average(values.iter().copied(), n as u32, space)
        };
    }
    Ok(())
}

/// The mean of `n` `0x00RRGGBB` values: in [`ShadingSpace::Linear`] of the light they show (each code decoded, the
/// mean encoded to the nearest code), in [`ShadingSpace::Encoded`] of the codes (rounded to nearest).
#[inline(always)]
fn average(values: impl Iterator<Item = u32>, n: u32, space: ShadingSpace) -> u32 {
    let channels = |v: u32| [(v >> 16) & 0xFF, (v >> 8) & 0xFF, v & 0xFF];
    let [r, g, b] = match space {
        ShadingSpace::Linear => {
            let mut sum = [0.0f32; 3];
            for value in values {
                for (total, code) in sum.iter_mut().zip(channels(value)) {
                    *total += SRGB_DECODE[code as usize];
                }
            }
            sum.map(|light| linear_to_srgb8(light / n as f32))
        }
        ShadingSpace::Encoded => {
            let mut sum = [0u32; 3];
            for value in values {
                for (total, code) in sum.iter_mut().zip(channels(value)) {
                    *total += code;
                }
            }
            sum.map(|c| (c + n / 2) / n)
        }
    };
    (r << 16) | (g << 8) | b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`resolve_rgb888`]'s shortcut for samples that agree gives what averaging them gives: every code of every
    /// channel (and a top byte, which both drop), in both spaces, at four samples per pixel.
    #[test]
    fn equal_samples_average_to_themselves() {
        for space in [ShadingSpace::Linear, ShadingSpace::Encoded] {
            for code in 0..=255u32 {
                for value in [(code << 16) | ((255 - code) << 8) | (code / 2), 0xFF00_0000 | (code * 0x0001_0101)] {
                    let averaged = average([value; 4].into_iter(), 4, space);
                    assert_eq!(averaged, value & 0x00FF_FFFF, "{value:#010x} in {space:?}");
                    let mut pixel = [0u32];
                    resolve_rgb888(&[value; 4], Samples::Four, space, &mut pixel).unwrap();
                    assert_eq!(pixel[0], averaged, "{value:#010x} in {space:?}");
                }
            }
        }
    }
}
