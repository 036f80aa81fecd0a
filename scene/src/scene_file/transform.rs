//! An object's placement: scale, then rotations about X, Y and Z, then translation, as one matrix.

use rastty_core::math::{Mat4, Vec3};

/// The object-to-world matrix of `scale`, `rotate` (degrees) and `translate`:
///
/// `translate * rotate_z * rotate_y * rotate_x * scale`
///
/// With column vectors the rightmost factor acts first, so a point is scaled, then turned about the X axis, then
/// about the Y axis, then about the Z axis (all world axes through the object's origin), then moved. Each rotation
/// is counter-clockwise looking down its axis toward the origin (right-handed): 90 degrees about Z takes `+x` to
/// `+y`, about X takes `+y` to `+z`, about Y takes `+z` to `+x`.
///
/// # Examples
/// ```
/// use rastty_scene::scene_file::object_transform;
/// use rastty_core::math::Vec3;
///
/// // Scaled by 2, turned a quarter about Z, moved up by 1: +x lands on (0, 3, 0).
/// let m = object_transform(Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 90.0), Vec3::splat(2.0));
/// let p = m.transform_point(Vec3::X);
/// assert!((p - Vec3::new(0.0, 3.0, 0.0)).length() < 1e-6);
/// ```
pub fn object_transform(translate: Vec3, rotate_degrees: Vec3, scale: Vec3) -> Mat4 {
    let rotate = |axis: Vec3, degrees: f32| Mat4::from_axis_angle(axis, degrees.to_radians());
    Mat4::from_translation(translate)
        * rotate(Vec3::Z, rotate_degrees.z)
        * rotate(Vec3::Y, rotate_degrees.y)
        * rotate(Vec3::X, rotate_degrees.x)
        * Mat4::from_scale(scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-6
    }

    #[test]
    fn quarter_turns_follow_the_right_hand_rule() {
        let turn = |r: Vec3| object_transform(Vec3::ZERO, r, Vec3::ONE);
        assert!(close(turn(Vec3::new(0.0, 0.0, 90.0)).transform_point(Vec3::X), Vec3::Y));
        assert!(close(turn(Vec3::new(90.0, 0.0, 0.0)).transform_point(Vec3::Y), Vec3::Z));
        assert!(close(turn(Vec3::new(0.0, 90.0, 0.0)).transform_point(Vec3::Z), Vec3::X));
    }

    #[test]
    fn identity_by_default() {
        assert_eq!(object_transform(Vec3::ZERO, Vec3::ZERO, Vec3::ONE), Mat4::IDENTITY);
    }
}
