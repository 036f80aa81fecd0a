//! The six faces of a cube shadow map: how a point light among the objects sees every direction.
//!
//! Face `f` looks along `FACES[f]` (+x, -x, +y, -y, +z, -z) from the light, through a square perspective view a
//! little wider than 90 degrees: the directions of its quarter of the sphere land on its inner texels, and a
//! [`CUBE_BORDER`] texels wide margin on every side holds what lies just past its edges, so that a filter window
//! around any lookup stays inside the face it chose (a window across a seam would otherwise read another face's
//! texels as its own). A point is looked up in the face of its direction's largest component (OpenGL 4.6
//! specification 8.13, "Cube Map Texture Selection", with ties going to x, then y).

use crate::camera::{CameraError, look_at, perspective};
use crate::math::{Mat4, Vec3, float};

/// Texels of margin on each side of a cube face beyond its 90 degrees: filter windows of radius up to
/// `CUBE_BORDER - 1` around a lookup stay inside its face.
pub const CUBE_BORDER: u32 = 4;

/// The near plane of a cube face, as a fraction of its far plane: casters nearer the light than this are cut.
///
/// A perspective map's depth changes by `near / d^2` per unit of distance `d`, so the constant depth margin
/// ([`super::ShadowBias::depth`]) spans `depth * d^2 / near` world units: with `1 / 100` of the far plane it is
/// about one texel of a 1024-texel face at the far plane, and less nearer.
pub const CUBE_NEAR: f32 = 1.0 / 100.0;

/// Each face's direction from the light and the up vector of its view.
const FACES: [(Vec3, Vec3); 6] = [
    (Vec3::X, Vec3::new(0.0, -1.0, 0.0)),
    (Vec3::new(-1.0, 0.0, 0.0), Vec3::new(0.0, -1.0, 0.0)),
    (Vec3::Y, Vec3::Z),
    (Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.0, 0.0, -1.0)),
    (Vec3::Z, Vec3::new(0.0, -1.0, 0.0)),
    (Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, -1.0, 0.0)),
];

/// The six views of a cube shadow map around a point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct CubeFaces {
    /// The light's position.
    pub eye: Vec3,
    /// World space to each face's clip space, in the order of [`FACES`].
    pub clip_from_world: [Mat4; 6],
    /// `tan` of half of each face's field of view.
    pub tan_half: f32,
}

impl CubeFaces {
    /// The faces of a `size x size` map around a light at `eye` that must see as far as `far`.
    ///
    /// `size` must exceed `2 * CUBE_BORDER` (the caller checks).
    pub fn new(eye: Vec3, far: f32, size: u32) -> Result<Self, CameraError> {
        // The face's 90 degrees (tan 1) span its inner `size - 2 * border` texels: tan of the half view is
        // `size / (size - 2 * border)`.
        let tan_half = size as f32 / (size - 2 * CUBE_BORDER) as f32;
        let projection = perspective(2.0 * float::atan(tan_half), 1.0, far * CUBE_NEAR, far)?;
        let mut clip_from_world = [Mat4::IDENTITY; 6];
        for (face, (forward, up)) in clip_from_world.iter_mut().zip(FACES) {
            *face = projection * look_at(eye, eye + forward, up)?;
        }
        Ok(Self { eye, clip_from_world, tan_half })
    }

    /// The face that `p` is looked up in, and its projection.
    #[inline(always)]
    pub fn face(&self, p: Vec3) -> (usize, &Mat4) {
        let face = self.face_of(p);
        (face, &self.clip_from_world[face])
    }

    /// The face that `p` is looked up in: that of the largest component of its direction from the light (ties to
    /// x, then y). A NaN direction gets a face too, whose projection then has a NaN `w`.
    #[inline(always)]
    pub fn face_of(&self, p: Vec3) -> usize {
        let d = p - self.eye;
        let (x, y, z) = (float::abs(d.x), float::abs(d.y), float::abs(d.z));
        if x >= y && x >= z {
            usize::from(d.x < 0.0)
        } else if y >= z {
            2 + usize::from(d.y < 0.0)
        } else {
            4 + usize::from(d.z < 0.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each face sees its own axis at its centre, the directions at 45 degrees from it `CUBE_BORDER` texels in
    /// from its edges, and the lookups pick the face whose centre is nearest.
    #[test]
    fn faces_see_their_quarter_with_a_border() {
        const SIZE: u32 = 64;
        let eye = Vec3::new(1.0, -2.0, 0.5);
        let cube = CubeFaces::new(eye, 10.0, SIZE).unwrap();
        let texel = |face: usize, d: Vec3| {
            let clip = cube.clip_from_world[face].project_point(eye + d);
            assert!(clip.w > 0.0, "face {face}, {d:?} behind");
            let half = SIZE as f32 * 0.5;
            ((clip.x / clip.w + 1.0) * half, (1.0 - clip.y / clip.w) * half)
        };
        for (face, (forward, up)) in FACES.into_iter().enumerate() {
            assert_eq!(cube.face_of(eye + forward * 3.0), face);
            let (x, y) = texel(face, forward * 3.0);
            assert!((x - 32.0).abs() < 1e-3 && (y - 32.0).abs() < 1e-3, "face {face}: centre at ({x}, {y})");
            // Up is 45 degrees above the axis: at the inner edge of the top border.
            let (x, y) = texel(face, (forward + up) * 2.0);
            assert!((x - 32.0).abs() < 1e-3 && (y - CUBE_BORDER as f32).abs() < 1e-3, "face {face}: ({x}, {y})");
            // Slightly less than 45 degrees off the axis: still this face's.
            assert_eq!(cube.face_of(eye + forward + up * 0.99), face);
        }
        // Ties go to x, then y.
        assert_eq!(cube.face_of(eye + Vec3::new(1.0, 1.0, 1.0)), 0);
        assert_eq!(cube.face_of(eye + Vec3::new(0.5, -1.0, 1.0)), 3);
    }
}
