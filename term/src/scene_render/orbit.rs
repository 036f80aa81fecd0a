//! Moving a scene file's camera in the viewer: orbiting about its target, zooming, switching the lens.

use rastty_core::math::{Quat, float};

use crate::scene_file::{Projection, SceneCamera};

/// How close to straight above or below the target the eye may orbit: the cosine of the smallest angle between
/// the view direction and `up` (about 2.6 degrees). Beyond it, "up" on screen would flip.
const POLE_COSINE: f32 = 0.999;
/// How far zooming may go, as a factor of the starting distance (or orthographic height), each way.
const ZOOM_RANGE: f32 = 20.0;

/// A scene file's camera that the viewer turns and zooms. It starts as the file's; rotations orbit the eye about
/// the target (yaw about the camera's `up`, pitch about the screen's horizontal axis), zooming moves the eye along
/// the view direction (or, for an orthographic lens, scales the height shown).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneOrbit {
    /// The camera now.
    pub camera: SceneCamera,
    /// The distance from eye to target at the start, which zooming is limited around.
    start_distance: f32,
    /// The orthographic height at the start (or the one a perspective lens turns into).
    start_height: Option<f32>,
}

impl SceneOrbit {
    /// Starts at `camera`.
    pub fn new(camera: SceneCamera) -> Self {
        let start_height = match camera.projection {
            Projection::Orthographic { height } => Some(height),
            Projection::Perspective { .. } => None,
        };
        Self { camera, start_distance: camera_distance(&camera), start_height }
    }

    /// Orbits by `yaw` and `pitch` radians, as the model viewer's keys turn a model: positive yaw turns the scene's
    /// front to the right (the eye moves left about `up`), positive pitch tilts its top toward the eye (the eye
    /// rises). The pitch stops short of straight above or below the target, where "up" on screen would flip.
    pub fn rotate(&mut self, yaw: f32, pitch: f32) {
        let c = &mut self.camera;
        let mut offset = Quat::from_axis_angle(c.up, -yaw).rotate(c.position - c.target);
        if let Some(right) = (-offset).cross(c.up).try_normalize() {
            // Elevation of the eye above the plane through the target perpendicular to `up`.
            let elevation = float::asin(float::clamp(offset.normalize_or_zero().dot(c.up), -1.0, 1.0));
            let limit = float::asin(POLE_COSINE);
            let wanted = float::clamp(elevation + pitch, -limit, limit);
            // Rotating about `right` by a negative angle raises the eye.
            offset = Quat::from_axis_angle(right, elevation - wanted).rotate(offset);
        }
        if offset.is_finite() && offset.length() > 0.0 {
            c.position = c.target + offset;
        }
    }

    /// Zooms by `factor` (below 1 closer): the eye moves toward the target for a perspective lens, within
    /// 20 times the starting distance either way; an orthographic lens shows `factor` times the height. Clipping
    /// planes the file gives move with the eye: `far` by the distance the eye moved, `near` in proportion.
    pub fn zoom(&mut self, factor: f32) {
        if !(factor.is_finite() && factor > 0.0) {
            return;
        }
        let c = &mut self.camera;
        match &mut c.projection {
            Projection::Perspective { .. } => {
                let offset = c.position - c.target;
                let before = offset.length();
                let lo = self.start_distance / ZOOM_RANGE;
                let hi = self.start_distance * ZOOM_RANGE;
                let after = (before * factor).clamp(lo, hi);
                if !(before > 0.0 && after.is_finite()) {
                    return;
                }
                c.position = c.target + offset * (after / before);
                let near = c.near.map(|n| n * after / before);
                c.far = c.far.map(|f| {
                    let moved = f + (after - before);
                    let floor = near.unwrap_or(0.0) * 2.0;
                    if moved > floor { moved } else { floor.max(f * after / before) }
                });
                c.near = near;
            }
            Projection::Orthographic { height } => {
                let start = self.start_height.unwrap_or(*height);
                *height = (*height * factor).clamp(start / ZOOM_RANGE, start * ZOOM_RANGE);
            }
        }
    }

    /// Switches between perspective and orthographic, keeping the size of things at the target: a vertical field
    /// of view `fov` becomes the height `2 d tan(fov / 2)` at the eye's distance `d`, and back.
    pub fn toggle_projection(&mut self) {
        let d = camera_distance(&self.camera);
        self.camera.projection = match self.camera.projection {
            Projection::Perspective { fov_degrees } => {
                let height = 2.0 * d * float::tan(fov_degrees.to_radians() * 0.5);
                self.start_height.get_or_insert(height);
                Projection::Orthographic { height }
            }
            Projection::Orthographic { height } => {
                let fov = 2.0 * float::atan(height / (2.0 * d));
                Projection::Perspective { fov_degrees: fov.to_degrees().clamp(1.0, 179.0) }
            }
        };
    }

    /// True for an orthographic lens.
    pub fn is_orthographic(&self) -> bool {
        matches!(self.camera.projection, Projection::Orthographic { .. })
    }
}

fn camera_distance(camera: &SceneCamera) -> f32 {
    (camera.position - camera.target).length()
}

#[cfg(test)]
mod tests {
    use rastty_core::math::Vec3;

    use super::*;

    fn orbit() -> SceneOrbit {
        SceneOrbit::new(SceneCamera {
            position: Vec3::new(0.0, 0.0, 5.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection: Projection::Perspective { fov_degrees: 40.0 },
            near: Some(1.0),
            far: Some(10.0),
        })
    }

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-4
    }

    #[test]
    fn yaw_moves_the_eye_the_other_way_round_up() {
        let mut o = orbit();
        // Turning the scene's front to the right: the eye goes to the left (-x).
        o.rotate(90f32.to_radians(), 0.0);
        assert!(close(o.camera.position, Vec3::new(-5.0, 0.0, 0.0)), "{:?}", o.camera.position);
    }

    #[test]
    fn pitch_raises_the_eye_and_stops_short_of_the_pole() {
        let mut o = orbit();
        o.rotate(0.0, 30f32.to_radians());
        assert!(o.camera.position.y > 2.4 && close(o.camera.target, Vec3::ZERO));
        for _ in 0..10 {
            o.rotate(0.0, 30f32.to_radians());
        }
        let dir = o.camera.position.normalize_or_zero();
        assert!(dir.dot(Vec3::Y) < POLE_COSINE + 1e-6 && dir.dot(Vec3::Y) > 0.9);
        assert!((o.camera.position.length() - 5.0).abs() < 1e-3);
    }

    #[test]
    fn zoom_moves_the_eye_and_the_files_planes() {
        let mut o = orbit();
        o.zoom(0.5);
        assert!(close(o.camera.position, Vec3::new(0.0, 0.0, 2.5)));
        assert_eq!(o.camera.near, Some(0.5));
        assert_eq!(o.camera.far, Some(7.5));
        o.zoom(1e-6);
        assert!((o.camera.position.length() - 0.25).abs() < 1e-5);
    }

    #[test]
    fn the_lens_switches_keeping_the_size_at_the_target() {
        let mut o = orbit();
        o.toggle_projection();
        let Projection::Orthographic { height } = o.camera.projection else { panic!() };
        assert!((height - 10.0 * 20f32.to_radians().tan()).abs() < 1e-4);
        o.toggle_projection();
        let Projection::Perspective { fov_degrees } = o.camera.projection else { panic!() };
        assert!((fov_degrees - 40.0).abs() < 1e-3);
    }
}
