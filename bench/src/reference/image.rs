//! The reference renderer's output.

/// A rendered reference image: per pixel, the averaged colour and what covered the pixel.
///
/// All three vectors are row-major, top row first, `width * height` long.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The mean of the pixel's samples, each clamped to `[0, 1]` before averaging: linear channel values, not
    /// quantised.
    pub rgb: Vec<[f64; 3]>,
    /// True when a triangle is hit through the pixel centre `(i + 0.5, j + 0.5)` (a centre exactly on a
    /// triangle's edge counts as hit).
    pub centre_covered: Vec<bool>,
    /// The fraction of the pixel's samples that hit a triangle, a multiple of 1/256 in `[0, 1]`.
    pub coverage: Vec<f64>,
}

impl ReferenceImage {
    /// The index of pixel `(x, y)` in the vectors.
    pub fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// The colour of pixel `(x, y)`.
    pub fn pixel(&self, x: u32, y: u32) -> [f64; 3] {
        self.rgb[self.index(x, y)]
    }

    /// The image as `0x00RRGGBB` pixels, each channel rounded to the nearest of 256 levels (what
    /// [`rastty_scene::png_file::write_png`] takes).
    pub fn to_rgb888(&self) -> Vec<u32> {
        let q = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u32;
        self.rgb.iter().map(|c| (q(c[0]) << 16) | (q(c[1]) << 8) | q(c[2])).collect()
    }

    /// Mean squared error against `0x00RRGGBB` pixels of the same size (channels as `value / 255`), over all
    /// pixels and the three channels; `None` when the sizes differ.
    pub fn mse_rgb888(&self, pixels: &[u32]) -> Option<f64> {
        if pixels.len() != self.rgb.len() || pixels.is_empty() {
            return None;
        }
        let sum: f64 = self
            .rgb
            .iter()
            .zip(pixels)
            .map(|(c, &p)| {
                let ch = |shift: u32| f64::from((p >> shift) & 0xFF) / 255.0;
                let d = [c[0] - ch(16), c[1] - ch(8), c[2] - ch(0)];
                d.iter().map(|v| v * v).sum::<f64>()
            })
            .sum();
        Some(sum / (3 * pixels.len()) as f64)
    }

    /// Peak signal-to-noise ratio against `0x00RRGGBB` pixels, in decibels: `10 log10(1 / MSE)` with channels in
    /// `[0, 1]` (infinite for identical images). Rounding to 8 bits alone costs about 59 dB (MSE `1 / (12 * 255²)`
    /// for uniformly spread values). `None` when the sizes differ.
    pub fn psnr_rgb888(&self, pixels: &[u32]) -> Option<f64> {
        self.mse_rgb888(pixels).map(|mse| -10.0 * mse.log10())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packing_and_psnr() {
        let image = ReferenceImage {
            width: 2,
            height: 1,
            rgb: vec![[1.0, 0.5, 0.0], [0.2, 0.2, 0.2]],
            centre_covered: vec![true, false],
            coverage: vec![1.0, 0.0],
        };
        assert_eq!(image.to_rgb888(), vec![0xFF8000, 0x333333]);
        assert_eq!(image.pixel(1, 0), [0.2; 3]);
        // 0.5 is 127.5 levels: half a level off in one channel of six.
        let mse = image.mse_rgb888(&[0xFF8000, 0x333333]).unwrap();
        assert!((mse - (0.5f64 / 255.0).powi(2) / 6.0).abs() < 1e-18, "{mse}");
        assert!((image.psnr_rgb888(&[0xFF8000, 0x333333]).unwrap() - -10.0 * mse.log10()).abs() < 1e-12);
        assert!(image.psnr_rgb888(&[0]).is_none());
    }
}
