//! The diffuse light of an environment: its irradiance as nine spherical-harmonic coefficients (Ramamoorthi and
//! Hanrahan, "An Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001).

use core::f32::consts::PI;

use super::panorama::{Panorama, texel_direction, texel_solid_angle};
use crate::math::Vec3;

/// The irradiance of an environment, per unit of `pi`: what a white Lambertian surface facing each way reflects.
/// A uniform environment of radiance `L` gives `L` in every direction.
///
/// Nine coefficients, the environment's projection on the real spherical harmonics of bands 0 to 2, each already
/// convolved with the clamped cosine (the paper's `A_l`: `pi`, `2 pi / 3`, `pi / 4`) and divided by `pi`. Their
/// error for irradiance is below 3 % for any environment and far less for most (the paper, section 3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Irradiance {
    coefficients: [Vec3; 9],
}

/// The nine real spherical harmonics at the unit direction `d`, bands 0, 1, 2 (the paper's equation 3 with its
/// constants).
#[inline(always)]
fn harmonics(d: Vec3) -> [f32; 9] {
    let (x, y, z) = (d.x, d.y, d.z);
    [
        0.282_095,
        0.488_603 * y,
        0.488_603 * z,
        0.488_603 * x,
        1.092_548 * x * y,
        1.092_548 * y * z,
        0.315_392 * (3.0 * z * z - 1.0),
        1.092_548 * x * z,
        0.546_274 * (x * x - y * y),
    ]
}

/// The clamped cosine's convolution weights per band over `pi`: `A_0 = pi`, `A_1 = 2 pi / 3`, `A_2 = pi / 4`.
const BAND_WEIGHTS: [f32; 9] = [1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25];

impl Irradiance {
    /// No light from anywhere.
    pub const ZERO: Self = Self { coefficients: [Vec3::ZERO; 9] };

    /// A uniform environment of radiance `radiance`.
    #[must_use]
    pub fn uniform(radiance: Vec3) -> Self {
        let mut coefficients = [Vec3::ZERO; 9];
        // L_00 = 4 pi Y_00 L; times A_0 / pi and Y_00 again at evaluation: L.
        coefficients[0] = radiance * (4.0 * PI * 0.282_095);
        Self { coefficients }
    }

    /// The irradiance of the environment `panorama`: each texel's light projected on the harmonics at its centre,
    /// weighted by the solid angle it covers, row by row in order (the same sums on every machine).
    #[must_use]
    pub fn of(panorama: &Panorama<'_>) -> Self {
        let (w, h) = (panorama.width(), panorama.height());
        let mut coefficients = [Vec3::ZERO; 9];
        for y in 0..h {
            let solid_angle = texel_solid_angle(y, w, h);
            let mut row = [Vec3::ZERO; 9];
            for x in 0..w {
                let light = panorama.texel(x, y);
                for (sum, basis) in row.iter_mut().zip(harmonics(texel_direction(x, y, w, h))) {
                    *sum += light * basis;
                }
            }
            for (c, r) in coefficients.iter_mut().zip(row) {
                *c += r * solid_angle;
            }
        }
        Self { coefficients }
    }

    /// The irradiance over `pi` at a surface of unit normal `n`.
    pub fn at(&self, n: Vec3) -> Vec3 {
        let basis = harmonics(n);
        let mut sum = Vec3::ZERO;
        for ((c, b), w) in self.coefficients.iter().zip(basis).zip(BAND_WEIGHTS) {
            sum += *c * (b * w);
        }
        sum.max(Vec3::ZERO)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::panorama::Panorama;

    #[test]
    fn a_uniform_environment_gives_its_radiance() {
        // Each texel's harmonics are taken at its centre: the sums' error falls with the square of the rows.
        let texels = [Vec3::new(0.5, 1.0, 2.0); 128 * 64];
        let panorama = Panorama::new(128, 64, &texels).unwrap();
        let irradiance = Irradiance::of(&panorama);
        for n in [Vec3::Y, -Vec3::X, Vec3::new(0.6, 0.0, 0.8)] {
            let e = irradiance.at(n);
            assert!((e - Vec3::new(0.5, 1.0, 2.0)).length() < 5e-4, "{n:?}: {e:?}");
            assert!((Irradiance::uniform(Vec3::ONE).at(n) - Vec3::ONE).length() < 1e-5);
        }
    }

    #[test]
    fn light_from_above_lights_the_upper_hemisphere() {
        // Radiance 1 over the upper hemisphere, 0 below. Its band-2 part is 0, so bands 0 and 1 give the exact
        // irradiance over pi at the poles and the horizon: 1 facing up, 0 facing down, 1/2 facing sideways.
        let (w, h) = (64, 32);
        let texels: [Vec3; 64 * 32] = core::array::from_fn(|i| if (i / w) < h / 2 { Vec3::ONE } else { Vec3::ZERO });
        let irradiance = Irradiance::of(&Panorama::new(w as u32, h as u32, &texels).unwrap());
        let (up, down, side) = (irradiance.at(Vec3::Y).x, irradiance.at(-Vec3::Y).x, irradiance.at(Vec3::X).x);
        assert!((up - 1.0).abs() < 2e-3 && down.abs() < 2e-3 && (side - 0.5).abs() < 2e-3, "{up} {down} {side}");
    }
}
