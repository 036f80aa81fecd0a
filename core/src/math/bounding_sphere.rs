//! A bounding sphere: what a camera is framed on and a shadow map is fitted to.

use super::Vec3;

/// A sphere that holds everything of interest: a scene's objects, or what a shadow map must see.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingSphere {
    /// Its centre, in world space.
    pub centre: Vec3,
    /// Its radius (positive).
    pub radius: f32,
}
