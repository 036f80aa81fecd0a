//! Unit quaternion: an orientation that can be composed many times without drifting.

use core::ops::Mul;

use super::{Mat3, Mat4, Vec3, float};

/// A rotation as a unit quaternion `w + xi + yj + zk`.
///
/// Composing rotations multiplies quaternions; [`Quat::normalize`] after each step keeps it a pure rotation,
/// where repeatedly multiplied matrices would slowly shear and scale.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Quat {
    /// Vector part, i.
    pub x: f32,
    /// Vector part, j.
    pub y: f32,
    /// Vector part, k.
    pub z: f32,
    /// Scalar part.
    pub w: f32,
}

impl Quat {
    /// No rotation.
    pub const IDENTITY: Self = Self { x: 0.0, y: 0.0, z: 0.0, w: 1.0 };

    /// A rotation by `angle` radians about `axis` (right-handed: counter-clockwise looking down the axis toward the
    /// origin). The axis need not be unit length; a zero or non-finite axis or angle gives the identity.
    pub fn from_axis_angle(axis: Vec3, angle: f32) -> Self {
        match axis.try_normalize() {
            Some(a) if angle.is_finite() => {
                let half = angle * 0.5;
                let s = float::sin(half);
                Self { x: a.x * s, y: a.y * s, z: a.z * s, w: float::cos(half) }
            }
            _ => Self::IDENTITY,
        }
    }

    /// The same rotation scaled back to unit length; the identity if the quaternion is zero or not finite.
    pub fn normalize(self) -> Self {
        let n = float::sqrt(self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w);
        if n > 0.0 && n.is_finite() {
            let r = 1.0 / n;
            Self { x: self.x * r, y: self.y * r, z: self.z * r, w: self.w * r }
        } else {
            Self::IDENTITY
        }
    }

    /// The inverse rotation (the conjugate, for a unit quaternion).
    pub fn conjugate(self) -> Self {
        Self { x: -self.x, y: -self.y, z: -self.z, w: self.w }
    }

    /// Rotates a vector.
    pub fn rotate(self, v: Vec3) -> Vec3 {
        // v' = v + 2w (q x v) + 2 q x (q x v), with q the vector part (expanded q v q*).
        let q = Vec3::new(self.x, self.y, self.z);
        let t = q.cross(v) * 2.0;
        v + t * self.w + q.cross(t)
    }

    /// The rotation as a 3x3 matrix (exact for a unit quaternion).
    pub fn to_mat3(self) -> Mat3 {
        let Self { x, y, z, w } = self;
        let (x2, y2, z2) = (x + x, y + y, z + z);
        let (xx, yy, zz) = (x * x2, y * y2, z * z2);
        let (xy, xz, yz) = (x * y2, x * z2, y * z2);
        let (wx, wy, wz) = (w * x2, w * y2, w * z2);
        Mat3::from_cols(
            Vec3::new(1.0 - (yy + zz), xy + wz, xz - wy),
            Vec3::new(xy - wz, 1.0 - (xx + zz), yz + wx),
            Vec3::new(xz + wy, yz - wx, 1.0 - (xx + yy)),
        )
    }

    /// The rotation as a 4x4 matrix.
    pub fn to_mat4(self) -> Mat4 {
        Mat4::from_mat3(self.to_mat3())
    }
}

impl Default for Quat {
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// Composition: `a * b` rotates by `b` first, then by `a` (Hamilton product).
impl Mul for Quat {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }
}
