//! An equirectangular panorama: the light arriving from every direction, as an image twice as wide as it is
//! tall.
//!
//! Directions are world directions, `+y` up (glTF's convention). The column gives the azimuth and the row the
//! polar angle from `+y`: a direction `d` is at `u = 1/2 + atan2(d.x, -d.z) / (2 pi)`, `v = acos(d.y) / pi`, so
//! the image's centre is seen looking along `-z` (the way a default camera looks), its top row is straight up, and
//! its left and right edges meet behind the viewer, at `+z`.

use core::f32::consts::{FRAC_1_PI, PI, TAU};

use crate::math::{Vec3, float};

/// A panorama's texels, borrowed: `width x height` linear-light colours, row by row from the top.
#[derive(Clone, Copy, Debug)]
pub struct Panorama<'a> {
    width: u32,
    height: u32,
    texels: &'a [Vec3],
}

/// Why a panorama or a chain of them could not be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PanoramaError {
    /// The width is not twice the height, or the height is 0.
    Shape {
        /// Texels across.
        width: u32,
        /// Texels down.
        height: u32,
    },
    /// The texel slice does not hold exactly the texels the shape needs.
    Length {
        /// Texels the shape needs.
        expected: usize,
        /// Texels given.
        actual: usize,
    },
}

impl core::fmt::Display for PanoramaError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Shape { width, height } => write!(
                f,
                "an equirectangular panorama is twice as wide as it is tall and at least 2x1 texels, not {width}x{height}"
            ),
            Self::Length { expected, actual } => {
                write!(f, "the panorama needs {expected} texels, {actual} given")
            }
        }
    }
}

impl core::error::Error for PanoramaError {}

impl<'a> Panorama<'a> {
    /// A panorama of `width x height` texels, `width` twice `height`.
    ///
    /// # Errors
    /// [`PanoramaError::Shape`] for another shape, [`PanoramaError::Length`] when `texels` does not hold
    /// `width * height` colours.
    pub fn new(width: u32, height: u32, texels: &'a [Vec3]) -> Result<Self, PanoramaError> {
        check_shape(width, height)?;
        let expected = width as usize * height as usize;
        if texels.len() != expected {
            return Err(PanoramaError::Length { expected, actual: texels.len() });
        }
        Ok(Self { width, height, texels })
    }

    /// Texels across.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Texels down.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The texels, row by row from the top.
    pub fn texels(&self) -> &'a [Vec3] {
        self.texels
    }

    /// The texel in column `x` and row `y`.
    #[inline(always)]
    pub fn texel(&self, x: u32, y: u32) -> Vec3 {
        self.texels[y as usize * self.width as usize + x as usize]
    }

    /// The light from direction `d` (unit length, or zero: straight up), blended from the four nearest texels:
    /// columns wrap around, rows stop at the poles.
    pub fn sample(&self, d: Vec3) -> Vec3 {
        let (u, v) = to_panorama(d);
        self.sample_at(u, v)
    }

    /// The light at panorama coordinates `(u, v)` ([`to_panorama`]), blended as [`Self::sample`] blends it.
    pub fn sample_at(&self, u: f32, v: f32) -> Vec3 {
        let (w, h) = (self.width, self.height);
        let x = u * w as f32 - 0.5;
        let y = float::clamp(v * h as f32 - 0.5, 0.0, (h - 1) as f32);
        let (x0, y0) = (float::floor(x), float::floor(y));
        let (fx, fy) = (x - x0, y - y0);
        // `u` is in [0, 1], so `x0` is in [-1, w]: one step of wrapping either way.
        let column = |c: i32| c.rem_euclid(w as i32) as u32;
        let (c0, c1) = (column(x0 as i32), column(x0 as i32 + 1));
        let r0 = y0 as u32;
        let r1 = (r0 + 1).min(h - 1);
        let top = self.texel(c0, r0).lerp(self.texel(c1, r0), fx);
        let bottom = self.texel(c0, r1).lerp(self.texel(c1, r1), fx);
        top.lerp(bottom, fy)
    }
}

/// Checks a panorama's shape: twice as wide as tall, at least one row.
pub(crate) fn check_shape(width: u32, height: u32) -> Result<(), PanoramaError> {
    if height == 0 || Some(width) != height.checked_mul(2) {
        return Err(PanoramaError::Shape { width, height });
    }
    Ok(())
}

/// The panorama coordinates `(u, v)`, each in `[0, 1]`, of direction `d` (see the module's documentation).
#[inline(always)]
#[must_use]
pub fn to_panorama(d: Vec3) -> (f32, f32) {
    let u = 0.5 + float::atan2(d.x, -d.z) * (0.5 * FRAC_1_PI);
    let length = d.length();
    let cos = if length > 0.0 { float::clamp(d.y / length, -1.0, 1.0) } else { 1.0 };
    (u, float::acos(cos) * FRAC_1_PI)
}

/// The unit direction at panorama coordinates `(u, v)`: the inverse of [`to_panorama`].
#[inline(always)]
pub fn from_panorama(u: f32, v: f32) -> Vec3 {
    let (azimuth, polar) = ((u - 0.5) * TAU, v * PI);
    let (sin_polar, cos_polar) = (float::sin(polar), float::cos(polar));
    Vec3::new(sin_polar * float::sin(azimuth), cos_polar, -sin_polar * float::cos(azimuth))
}

/// The direction through the centre of texel `(x, y)` of a `width x height` panorama.
#[inline(always)]
pub fn texel_direction(x: u32, y: u32, width: u32, height: u32) -> Vec3 {
    from_panorama((x as f32 + 0.5) / width as f32, (y as f32 + 0.5) / height as f32)
}

/// The solid angle each texel of row `y` of a `width x height` panorama covers, in steradians: `(2 pi / width)
/// (cos(pi y / height) - cos(pi (y + 1) / height))`. The rows' texels together cover `4 pi`.
#[inline(always)]
#[must_use]
pub fn texel_solid_angle(y: u32, width: u32, height: u32) -> f32 {
    let polar = |row: u32| PI * row as f32 / height as f32;
    TAU / width as f32 * (float::cos(polar(y)) - float::cos(polar(y + 1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions_and_coordinates_are_inverse() {
        for (u, v) in [(0.5, 0.5), (0.25, 0.3), (0.9, 0.8), (0.01, 0.05)] {
            let (u2, v2) = to_panorama(from_panorama(u, v));
            assert!((u - u2).abs() < 1e-5 && (v - v2).abs() < 1e-5, "{u} {v}: {u2} {v2}");
        }
        // The centre looks along -z, the top row up, a quarter turn right along +x.
        assert!((from_panorama(0.5, 0.5) - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-6);
        assert!((from_panorama(0.75, 0.5) - Vec3::X).length() < 1e-6);
        assert_eq!(to_panorama(Vec3::Y).1, 0.0);
        assert_eq!(to_panorama(Vec3::ZERO).1, 0.0);
    }

    #[test]
    fn the_texels_cover_the_sphere() {
        let (w, h) = (64, 32);
        let total: f32 = (0..h).map(|y| texel_solid_angle(y, w, h) * w as f32).sum();
        assert!((total - 4.0 * PI).abs() < 1e-4, "{total}");
    }

    #[test]
    fn a_sample_at_a_texel_centre_is_that_texel() {
        let texels: [Vec3; 32] = core::array::from_fn(|i| Vec3::new(i as f32, 0.0, 1.0));
        let p = Panorama::new(8, 4, &texels).unwrap();
        // Inside a block of equal texels the blend is exact; across the seam the columns wrap.
        let same = [Vec3::splat(0.25); 32];
        let flat = Panorama::new(8, 4, &same).unwrap();
        assert_eq!(flat.sample(texel_direction(3, 1, 8, 4)), Vec3::splat(0.25));
        let seam = p.sample(from_panorama(0.0, 0.5));
        // Halfway between column 7 and column 0 of rows 1 and 2: (15 + 8) / 2 and (23 + 16) / 2, then their mean.
        assert!((seam.x - (11.5 + 19.5) / 2.0).abs() < 1e-4, "{seam:?}");
        assert_eq!(Panorama::new(8, 3, &texels[..24]).map(|_| ()), Err(PanoramaError::Shape { width: 8, height: 3 }));
        assert_eq!(
            Panorama::new(8, 4, &texels[..5]).map(|_| ()),
            Err(PanoramaError::Length { expected: 32, actual: 5 })
        );
    }
}
