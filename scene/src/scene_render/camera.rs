//! A scene file's camera as the matrices of one frame: the lens from the file, the aspect from the frame, and the
//! clipping planes from the file or around the scene.

use rastty_core::camera::{CameraError, orthographic, perspective};
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Mat4, float};

use crate::scene_file::{SceneCamera, SceneProjection};

/// How much the derived clipping planes stand off the scene's bounding sphere, as a fraction of its radius.
const PLANE_MARGIN: f32 = 0.01;
/// The smallest derived near plane of a perspective lens, as a fraction of the far plane's distance: with the eye
/// inside the scene, nearer than this is clipped (the depth buffer's precision is spread over `far / near`).
const MIN_NEAR_RATIO: f32 = 1e-3;

/// Where a clipping plane's distance came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlaneSource {
    /// Given: the scene file's `near` or `far`, or the command line's `--near` or `--far`.
    Given,
    /// Around the scene's bounding sphere, so that nothing is clipped.
    Derived,
}

/// The view and projection of one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedCamera {
    /// World to view space.
    pub view: Mat4,
    /// View to clip space.
    pub projection: Mat4,
    /// The lens.
    pub lens: SceneProjection,
    /// The near plane's distance along the view direction (negative for an orthographic lens whose box starts
    /// behind the eye).
    pub near: f32,
    /// The far plane's distance.
    pub far: f32,
    /// Where `near` came from.
    pub near_source: PlaneSource,
    /// Where `far` came from.
    pub far_source: PlaneSource,
}

impl PlannedCamera {
    /// The camera of `camera` for a frame whose width over height is `aspect`, with the clipping planes the file
    /// gives and the others fitted around `bounds` (with a margin of 1% of the radius):
    ///
    /// - perspective: `far` is the far side of the sphere along the view direction, `near` its near side, but at
    ///   least `far / 1000` (with the eye inside the scene, closer than that is clipped);
    /// - orthographic: both sides of the sphere, so `near` may be negative (the box then starts behind the eye).
    ///
    /// A derived plane that would contradict the file's other plane gives way (`far` becomes twice `near`, or
    /// `near` a thousandth of `far`). The field of view (or height) spans the frame's shorter side: vertically in
    /// a landscape frame, horizontally in a portrait one, so a scene framed in one stays framed in the other.
    ///
    /// # Errors
    /// [`CameraError`] for a camera the core refuses (the eye at the target, a non-positive aspect).
    pub fn new(camera: &SceneCamera, bounds: &BoundingSphere, aspect: f32) -> Result<Self, CameraError> {
        let view = camera.view()?;
        let forward = (camera.target - camera.position).try_normalize().ok_or(CameraError::EyeAtTarget)?;
        let centre_depth = (bounds.centre - camera.position).dot(forward);
        let r = bounds.radius * (1.0 + PLANE_MARGIN);
        let (near_fit, far_fit) = match camera.projection {
            SceneProjection::Perspective { .. } => {
                let far = centre_depth + r;
                if far > 0.0 {
                    (float::max(centre_depth - r, far * MIN_NEAR_RATIO), far)
                } else {
                    // Everything is behind the eye: any planes show the same nothing.
                    (bounds.radius * MIN_NEAR_RATIO, bounds.radius)
                }
            }
            SceneProjection::Orthographic { .. } => (centre_depth - r, centre_depth + r),
        };
        let (near, far, near_source, far_source) = match (camera.near, camera.far) {
            (Some(n), Some(f)) => (n, f, PlaneSource::Given, PlaneSource::Given),
            (Some(n), None) => {
                (n, if far_fit > n { far_fit } else { 2.0 * n }, PlaneSource::Given, PlaneSource::Derived)
            }
            (None, Some(f)) => {
                (if near_fit < f { near_fit } else { f * MIN_NEAR_RATIO }, f, PlaneSource::Derived, PlaneSource::Given)
            }
            (None, None) => (near_fit, far_fit, PlaneSource::Derived, PlaneSource::Derived),
        };
        // The share of the shorter side the frame's height is: 1 in landscape, the aspect in portrait.
        let portrait = float::min(aspect, 1.0);
        let projection = match camera.projection {
            SceneProjection::Perspective { fov_degrees } => {
                let fov = fov_degrees.to_radians();
                let fovy = if aspect >= 1.0 { fov } else { 2.0 * float::atan(float::tan(fov * 0.5) / portrait) };
                perspective(fovy, aspect, near, far)?
            }
            SceneProjection::Orthographic { height } => {
                if aspect.is_nan() || aspect <= 0.0 {
                    return Err(CameraError::Aspect);
                }
                if !height.is_finite() {
                    return Err(CameraError::NotFinite);
                }
                // A negative height would mirror the picture.
                if height <= 0.0 {
                    return Err(CameraError::EmptyBox);
                }
                let half_height = height * 0.5 / portrait;
                let half_width = half_height * aspect;
                orthographic(-half_width, half_width, -half_height, half_height, near, far)?
            }
        };
        Ok(Self { view, projection, lens: camera.projection, near, far, near_source, far_source })
    }
}

#[cfg(test)]
mod tests {
    use rastty_core::math::Vec3;

    use super::*;

    fn camera(projection: SceneProjection, near: Option<f32>, far: Option<f32>) -> SceneCamera {
        SceneCamera { position: Vec3::new(0.0, 0.0, 10.0), target: Vec3::ZERO, up: Vec3::Y, projection, near, far }
    }

    const SPHERE: BoundingSphere = BoundingSphere { centre: Vec3::ZERO, radius: 2.0 };
    const LENS: SceneProjection = SceneProjection::Perspective { fov_degrees: 40.0 };

    #[test]
    fn derived_planes_hold_the_sphere() {
        let c = PlannedCamera::new(&camera(LENS, None, None), &SPHERE, 1.5).unwrap();
        assert!(c.near < 8.0 && c.near > 7.9, "{}", c.near);
        assert!(c.far > 12.0 && c.far < 12.1, "{}", c.far);
        assert_eq!((c.near_source, c.far_source), (PlaneSource::Derived, PlaneSource::Derived));
    }

    #[test]
    fn the_files_planes_are_kept_and_the_other_gives_way() {
        let c = PlannedCamera::new(&camera(LENS, Some(0.5), Some(100.0)), &SPHERE, 1.0).unwrap();
        assert_eq!((c.near, c.far), (0.5, 100.0));
        let c = PlannedCamera::new(&camera(LENS, Some(20.0), None), &SPHERE, 1.0).unwrap();
        assert_eq!((c.near, c.far, c.far_source), (20.0, 40.0, PlaneSource::Derived));
        let c = PlannedCamera::new(&camera(LENS, None, Some(5.0)), &SPHERE, 1.0).unwrap();
        assert!(c.near < 5.0 && c.near > 0.0);
    }

    #[test]
    fn an_eye_inside_the_scene_keeps_a_positive_near_plane() {
        let inside = BoundingSphere { centre: Vec3::ZERO, radius: 50.0 };
        let c = PlannedCamera::new(&camera(LENS, None, None), &inside, 1.0).unwrap();
        assert!(c.near > 0.0 && c.near < c.far);
        let ortho = SceneProjection::Orthographic { height: 4.0 };
        let c = PlannedCamera::new(&camera(ortho, None, None), &inside, 1.0).unwrap();
        assert!(c.near < 0.0 && c.far > 50.0);
    }
}
