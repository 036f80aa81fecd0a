//! Comparing a rendered picture with the one stored: bit for bit by default, or within a perceptual tolerance, and
//! the diff image that shows where they differ.

use std::fmt;
use std::str::FromStr;

use rastty::screen::oklab::Oklab;

/// A picture: `width x height` pixels, `0x00RRGGBB`, row by row from the top.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Picture {
    /// Pixels across.
    pub width: u32,
    /// Pixels down.
    pub height: u32,
    /// The pixels.
    pub pixels: Vec<u32>,
}

/// How different two pictures may be and still match: a pixel differs when its colours are more than `distance`
/// apart in Oklab (Euclidean, lightness from 0 to 1: 0.02 is the just-noticeable difference CSS Color 4 takes for
/// this distance), and at most `pixels` pixels may differ. Exact ([`MatchTolerance::EXACT`]) by default: any
/// change of any channel differs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MatchTolerance {
    /// The largest Oklab distance between a pixel's two colours that counts as the same.
    pub distance: f32,
    /// How many pixels may differ beyond it.
    pub pixels: PixelCount,
}

/// How many pixels may differ: a number, or a share of the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PixelCount {
    /// At most this many.
    Count(u64),
    /// At most this percentage of the picture's pixels.
    Percent(f64),
}

impl MatchTolerance {
    /// Every channel of every pixel equal.
    pub const EXACT: Self = Self { distance: 0.0, pixels: PixelCount::Count(0) };

    /// The most pixels of a picture of `total` pixels that may differ.
    fn allowed(&self, total: u64) -> u64 {
        match self.pixels {
            PixelCount::Count(n) => n,
            PixelCount::Percent(p) => (total as f64 * p / 100.0).floor() as u64,
        }
    }
}

impl FromStr for MatchTolerance {
    type Err = String;

    /// `DISTANCE`, `DISTANCE:PIXELS` or `DISTANCE:PERCENT%`: `0.02`, `0.02:50`, `0.02:0.1%`.
    fn from_str(s: &str) -> Result<Self, String> {
        let bad =
            || format!("{s:?} is not a tolerance: DISTANCE[:PIXELS|:PERCENT%], e.g. 0.02 or 0.02:50 or 0.02:0.1%");
        let (distance, pixels) = s.split_once(':').map_or((s, None), |(d, p)| (d, Some(p)));
        let distance: f32 = distance.parse().map_err(|_| bad())?;
        if !(distance.is_finite() && distance >= 0.0) {
            return Err(bad());
        }
        let pixels = match pixels {
            None => PixelCount::Count(0),
            Some(p) => match p.strip_suffix('%') {
                Some(percent) => {
                    let percent: f64 = percent.parse().map_err(|_| bad())?;
                    if !(0.0..=100.0).contains(&percent) {
                        return Err(bad());
                    }
                    PixelCount::Percent(percent)
                }
                None => PixelCount::Count(p.parse().map_err(|_| bad())?),
            },
        };
        Ok(Self { distance, pixels })
    }
}

impl fmt::Display for MatchTolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.pixels {
            PixelCount::Count(n) => write!(f, "{}:{n}", self.distance),
            PixelCount::Percent(p) => write!(f, "{}:{p}%", self.distance),
        }
    }
}

/// What comparing two pictures of the same size found.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Pixels whose colours differ beyond the tolerance's distance (with an exact tolerance: in any channel).
    pub differing: u64,
    /// The largest Oklab distance between a pixel's two colours.
    pub largest: f32,
    /// Whether the pictures match under the tolerance.
    pub matches: bool,
}

/// Compares `new` with `stored`, of the same size, under `tolerance`.
pub fn compare(stored: &Picture, new: &Picture, tolerance: &MatchTolerance) -> Comparison {
    let mut differing = 0;
    let mut largest = 0.0f32;
    for (&a, &b) in stored.pixels.iter().zip(&new.pixels) {
        if a == b {
            continue;
        }
        let distance = oklab(a).distance_squared(oklab(b)).sqrt();
        largest = largest.max(distance);
        if distance > tolerance.distance || tolerance.distance == 0.0 {
            differing += 1;
        }
    }
    let total = u64::from(stored.width) * u64::from(stored.height);
    Comparison { differing, largest, matches: differing <= tolerance.allowed(total) }
}

fn oklab(p: u32) -> Oklab {
    Oklab::from_srgb8((p >> 16) as u8, (p >> 8) as u8, p as u8)
}

/// The diff image of two pictures of the same size, as image-snapshot tools draw it: the stored picture faded to a
/// light grey, and each pixel that differs beyond `tolerance`'s distance in red (darker red for a larger difference),
/// those that differ within it in yellow.
pub fn diff_image(stored: &Picture, new: &Picture, tolerance: &MatchTolerance) -> Picture {
    let pixels = stored
        .pixels
        .iter()
        .zip(&new.pixels)
        .map(|(&a, &b)| {
            if a == b {
                // The stored pixel's lightness, faded toward white.
                let l = oklab(a).l.clamp(0.0, 1.0);
                let grey = (255.0 - (1.0 - l) * 64.0) as u32;
                return grey << 16 | grey << 8 | grey;
            }
            let distance = oklab(a).distance_squared(oklab(b)).sqrt();
            if distance <= tolerance.distance && tolerance.distance > 0.0 {
                return 0x00FF_D700;
            }
            // Red, from 255 for the least difference to 128 for a difference of 0.5 and more.
            let red = 255 - (distance.min(0.5) * 254.0) as u32;
            red << 16
        })
        .collect();
    Picture { width: stored.width, height: stored.height, pixels }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture(pixels: &[u32]) -> Picture {
        Picture { width: pixels.len() as u32, height: 1, pixels: pixels.to_vec() }
    }

    #[test]
    fn tolerances_parse_and_print() {
        assert_eq!(
            "0.02".parse::<MatchTolerance>(),
            Ok(MatchTolerance { distance: 0.02, pixels: PixelCount::Count(0) })
        );
        assert_eq!("0.02:50".parse::<MatchTolerance>().unwrap().pixels, PixelCount::Count(50));
        assert_eq!("0:0.5%".parse::<MatchTolerance>().unwrap().pixels, PixelCount::Percent(0.5));
        for bad in ["", "x", "-1", "nan", "inf", "0.1:", "0.1:-3", "0.1:101%", "0.1:a%"] {
            assert!(bad.parse::<MatchTolerance>().is_err(), "{bad:?}");
        }
        assert_eq!("0.02:0.5%".parse::<MatchTolerance>().unwrap().to_string(), "0.02:0.5%");
    }

    #[test]
    fn exact_pictures_match_and_one_changed_code_does_not() {
        let a = picture(&[0x102030, 0x405060, 0x708090]);
        let same = compare(&a, &a.clone(), &MatchTolerance::EXACT);
        assert_eq!(same, Comparison { differing: 0, largest: 0.0, matches: true });
        let b = picture(&[0x102030, 0x405061, 0x708090]);
        let one = compare(&a, &b, &MatchTolerance::EXACT);
        assert_eq!((one.differing, one.matches), (1, false));
        assert!(one.largest > 0.0 && one.largest < 0.01, "{}", one.largest);
        // Within a perceptual tolerance, one code is no difference; a red for a green is.
        assert!(compare(&a, &b, &"0.02".parse().unwrap()).matches);
        let c = picture(&[0xFF0000, 0x405060, 0x708090]);
        let red = compare(&a, &c, &"0.02".parse().unwrap());
        assert_eq!((red.differing, red.matches), (1, false));
        assert!(compare(&a, &c, &"0.02:1".parse().unwrap()).matches);
        assert!(compare(&a, &c, &"0.02:34%".parse().unwrap()).matches, "a third of three pixels is one");
        assert!(!compare(&a, &c, &"0.02:33%".parse().unwrap()).matches);
    }

    #[test]
    fn the_diff_image_marks_the_differing_pixels_in_red() {
        let a = picture(&[0x000000, 0xFFFFFF, 0x808080]);
        let b = picture(&[0x000000, 0xFFFFFE, 0x00FF00]);
        let diff = diff_image(&a, &b, &"0.02".parse().unwrap());
        assert_eq!(diff.pixels[0], 0xBFBFBF, "black faded");
        assert_eq!(diff.pixels[1], 0xFFD700, "within the tolerance: yellow");
        assert_eq!(diff.pixels[2] & 0x00FFFF, 0, "beyond it: red");
        assert!(diff.pixels[2] >> 16 >= 128);
    }
}
