//! A photographer's studio made in code: the environment a model is lit by when none is given.
//!
//! A grey room, brighter toward the ceiling, a darker floor, and three soft boxes: a warm key light above and to
//! the left of a default camera (which looks along `-z`), a cool fill light to its right, and a long strip light
//! above and behind the model for its rims. Every edge is soft (a smoothstep over a tenth of its size), so any
//! resolution samples it without aliasing, and a white Lambertian surface facing the key light reflects about 1.

use super::panorama::{PanoramaError, check_shape, texel_direction};
use crate::math::{Vec3, float};

/// One soft box: a rectangle of light on the sphere around its centre direction.
struct SoftBox {
    /// Unit direction of its centre (toward the light).
    centre: Vec3,
    /// Half its angular width and height, as sines of the angles from the centre.
    half: (f32, f32),
    /// Its radiance.
    color: Vec3,
}

/// The studio's soft boxes.
fn boxes() -> [SoftBox; 3] {
    let unit = |x: f32, y: f32, z: f32| Vec3::new(x, y, z).normalize_or_zero();
    [
        SoftBox { centre: unit(-0.55, 0.55, 0.63), half: (0.34, 0.26), color: Vec3::new(6.5, 6.0, 5.3) },
        SoftBox { centre: unit(0.85, 0.15, 0.5), half: (0.22, 0.34), color: Vec3::new(1.7, 1.9, 2.2) },
        SoftBox { centre: unit(0.0, 0.72, -0.69), half: (0.6, 0.1), color: Vec3::new(4.0, 4.0, 4.0) },
    ]
}

/// `0` at `edge0`, `1` at `edge1`, a cubic between (the smoothstep of shading languages).
fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let t = float::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The studio's light from the unit direction `d` (linear light).
pub fn radiance(d: Vec3) -> Vec3 {
    // The room: walls from 0.22 at the horizon to 0.4 overhead, the floor 0.09, blended over a band around the
    // horizon.
    let wall = Vec3::new(0.22, 0.22, 0.23) + Vec3::new(0.18, 0.18, 0.19) * float::max(d.y, 0.0);
    let floor = Vec3::new(0.09, 0.085, 0.08);
    let mut light = floor.lerp(wall, smoothstep(-0.04, 0.04, d.y));
    for soft_box in boxes() {
        let facing = d.dot(soft_box.centre);
        if facing <= 0.0 {
            continue;
        }
        // The box's own axes: across (horizontal) and up, both perpendicular to its centre.
        let across = Vec3::Y.cross(soft_box.centre).normalize_or_zero();
        let up = soft_box.centre.cross(across);
        let (s, t) = (float::abs(d.dot(across)), float::abs(d.dot(up)));
        let (w, h) = soft_box.half;
        let inside = (1.0 - smoothstep(0.9 * w, w, s)) * (1.0 - smoothstep(0.9 * h, h, t));
        light += soft_box.color * inside;
    }
    light
}

/// Fills `out` with the studio as a `2 height x height` panorama, each texel its light at the texel's centre.
///
/// # Errors
/// [`PanoramaError::Shape`] for a height of 0 or too large; [`PanoramaError::Length`] when `out` does not hold
/// `2 height x height` texels.
pub fn fill(height: u32, out: &mut [Vec3]) -> Result<(), PanoramaError> {
    let width = height.checked_mul(2).unwrap_or(0);
    check_shape(width, height)?;
    let expected = width as usize * height as usize;
    if out.len() != expected {
        return Err(PanoramaError::Length { expected, actual: out.len() });
    }
    for (i, texel) in out.iter_mut().enumerate() {
        let (x, y) = ((i % width as usize) as u32, (i / width as usize) as u32);
        *texel = radiance(texel_direction(x, y, width, height));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{Irradiance, Panorama};

    extern crate std;
    use std::vec;

    #[test]
    fn a_white_surface_facing_the_key_light_reflects_about_one() {
        let mut texels = vec![Vec3::ZERO; 128 * 64];
        fill(64, &mut texels).unwrap();
        let irradiance = Irradiance::of(&Panorama::new(128, 64, &texels).unwrap());
        let key = boxes()[0].centre;
        let facing = irradiance.at(key).x;
        assert!((0.8..=1.2).contains(&facing), "{facing}");
        // Lit from every side: less facing away, least facing the floor.
        assert!(irradiance.at(-key).x < facing && irradiance.at(-Vec3::Y).x < irradiance.at(-key).x);
    }
}
