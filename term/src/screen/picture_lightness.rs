//! The lightness range of a frame's picture, for the modes that show lightness by characters rather than colour.
//!
//! The picture is every pixel that is not the background colour. Its darkest pixel maps to level 0 and its
//! lightest to 1, in perceived lightness (`cbrt(Y)`, which is Oklab's L for greys), so the characters span what
//! the picture holds: a dim model uses the whole ramp, and the background stays blank.

use std::sync::OnceLock;

use super::oklab::srgb_to_linear;
use super::pixel_frame::PixelFrame;

/// Linear-light value of every 8-bit sRGB channel value.
fn linear_table() -> &'static [f32; 256] {
    static TABLE: OnceLock<[f32; 256]> = OnceLock::new();
    TABLE.get_or_init(|| std::array::from_fn(|v| srgb_to_linear(v as f32 / 255.0)))
}

/// Relative luminance Y (linear light, Rec. 709 / sRGB primaries) of a pixel `0x00RRGGBB`, in `0.0..=1.0`.
#[inline]
pub fn relative_luminance(pixel: u32) -> f32 {
    let [_, r, g, b] = pixel.to_be_bytes();
    let linear = linear_table();
    0.2126 * linear[usize::from(r)] + 0.7152 * linear[usize::from(g)] + 0.0722 * linear[usize::from(b)]
}

/// The darkest and lightest perceived lightness of a picture's pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PictureLightness {
    background: u32,
    darkest: f32,
    span: f32,
}

impl PictureLightness {
    /// The range over the pixels of `frame` that are not `background` (`0x00RRGGBB`); a frame of background
    /// alone gets the range of black to white.
    pub fn of_frame(frame: PixelFrame<'_>, background: u32) -> Self {
        let (mut low, mut high) = (f32::INFINITY, f32::NEG_INFINITY);
        for &pixel in frame.pixels().iter().filter(|&&p| p != background) {
            let y = relative_luminance(pixel);
            low = low.min(y);
            high = high.max(y);
        }
        if low > high {
            (low, high) = (0.0, 1.0);
        }
        let (darkest, lightest) = (low.cbrt(), high.cbrt());
        PictureLightness { background, darkest, span: lightest - darkest }
    }

    /// Whether `pixel` is the background (not part of the picture).
    #[inline]
    pub fn is_background(&self, pixel: u32) -> bool {
        pixel == self.background
    }

    /// Where `pixel`'s lightness lies in the picture's range, `0.0..=1.0` (1 when the picture has one lightness).
    #[inline]
    pub fn level(&self, pixel: u32) -> f32 {
        if self.span <= 0.0 {
            return 1.0;
        }
        ((relative_luminance(pixel).cbrt() - self.darkest) / self.span).clamp(0.0, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_range_ignores_the_background() {
        let pixels = [0x808080, 0x202020, 0x404040, 0x808080, 0x606060, 0x202020];
        let range = PictureLightness::of_frame(PixelFrame::new(&pixels, 3, 2), 0x808080);
        assert!(range.is_background(0x808080));
        assert_eq!(range.level(0x202020), 0.0);
        assert_eq!(range.level(0x606060), 1.0);
        let middle = range.level(0x404040);
        assert!(middle > 0.3 && middle < 0.7, "{middle}");
    }

    #[test]
    fn one_lightness_is_the_top_level() {
        let pixels = [0, 0x303030];
        let range = PictureLightness::of_frame(PixelFrame::new(&pixels, 2, 1), 0);
        assert_eq!(range.level(0x303030), 1.0);
    }

    #[test]
    fn background_alone_spans_black_to_white() {
        let range = PictureLightness::of_frame(PixelFrame::new(&[7; 4], 2, 2), 7);
        assert_eq!(range.level(0), 0.0);
        assert_eq!(range.level(0xFFFFFF), 1.0);
    }
}
