//! A node's local transform as glTF stores and animates it: translation, rotation and scale.

use crate::math::{Mat4, Quat, Vec3};

/// Translation, rotation (a unit quaternion) and scale, applied scale first: the matrix `T * R * S` (glTF 2.0,
/// section 3.5.3, "Transformations").
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Trs {
    /// Translation.
    pub translation: Vec3,
    /// Rotation.
    pub rotation: Quat,
    /// Scale along each axis.
    pub scale: Vec3,
}

impl Trs {
    /// No translation, no rotation, unit scale.
    pub const IDENTITY: Self = Self { translation: Vec3::ZERO, rotation: Quat::IDENTITY, scale: Vec3::ONE };

    /// The transform as a matrix, `T * R * S`.
    pub fn to_mat4(&self) -> Mat4 {
        let r = self.rotation.to_mat3();
        let [x, y, z] = r.cols;
        let s = self.scale;
        Mat4::from_cols(
            (x * s.x).extend(0.0),
            (y * s.y).extend(0.0),
            (z * s.z).extend(0.0),
            self.translation.extend(1.0),
        )
    }
}

impl Default for Trs {
    fn default() -> Self {
        Self::IDENTITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec4;

    #[test]
    fn scale_then_rotate_then_translate() {
        // A quarter turn about z: x goes to y. The point (1, 0, 0) scaled by 2 is (2, 0, 0), turned (0, 2, 0), moved
        // by (5, 0, 0): (5, 2, 0).
        let quarter = Quat { x: 0.0, y: 0.0, z: core::f32::consts::FRAC_1_SQRT_2, w: core::f32::consts::FRAC_1_SQRT_2 };
        let trs = Trs { translation: Vec3::new(5.0, 0.0, 0.0), rotation: quarter, scale: Vec3::splat(2.0) };
        let p = trs.to_mat4() * Vec4::new(1.0, 0.0, 0.0, 1.0);
        assert!((p.x - 5.0).abs() < 1e-6 && (p.y - 2.0).abs() < 1e-6 && p.z.abs() < 1e-6 && p.w == 1.0, "{p:?}");
        assert_eq!(Trs::IDENTITY.to_mat4(), Mat4::IDENTITY);
    }
}
