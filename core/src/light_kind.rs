//! Where a light's rays come from: what shading lights a surface with and what a shadow map is fitted to.

use crate::math::Vec3;

/// Where a light's rays come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// Parallel rays, like the sun's.
    Directional {
        /// Unit vector from the surface toward the light, in world space.
        to_light: Vec3,
    },
    /// Rays from one point, like a bulb's. There is no fall-off with distance (OpenGL's default attenuation,
    /// OpenGL 1.5 specification 2.14.1: constant 1, linear and quadratic 0), so `color` is what a lit surface
    /// receives at any distance.
    Point {
        /// The light's position in world space.
        position: Vec3,
    },
}
