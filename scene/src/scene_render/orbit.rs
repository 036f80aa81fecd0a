//! The one camera of the viewer and of `rastty render`: a scene's camera orbited about its target, zoomed, its
//! lens switched, and set from the command line's `--yaw`, `--pitch` and `--distance`.

use rastty_core::math::BoundingSphere;
use rastty_core::math::{Quat, Vec3, float};

use crate::scene_file::{FramedCamera, SceneCamera, SceneProjection};

/// How close to straight above or below the target the eye may orbit: the cosine of the smallest angle between
/// the view direction and `up` (about 2.6 degrees). Beyond it, "up" on screen would flip.
const POLE_COSINE: f32 = 0.999;
/// How far zooming may go, as a factor of the starting distance (or orthographic height), each way.
const ZOOM_RANGE: f32 = 20.0;

/// A scene's camera that the viewer turns and zooms. It starts as the scene's (placed by the file, or framed
/// around the scene); rotations orbit the eye about the target (yaw about the camera's `up`, pitch about the
/// screen's horizontal axis), zooming moves the eye along the view direction (or, for an orthographic lens,
/// scales the height shown).
///
/// Angles are measured in a frame of `up`: yaw 0 looks from the `+z` side (the projection of `+z` on the plane
/// across `up`, or `+x` when `up` is along `z`), positive yaw moves the eye round to the left (the scene's front
/// turns to the right), positive pitch raises it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    /// The camera now.
    pub camera: SceneCamera,
    /// The eye's distance from the target and its elevation in radians: kept here rather than measured again after
    /// each rotation, so that rounding cannot add up over many of them.
    distance: f32,
    pitch: f32,
    /// The distance from eye to target at the start, which zooming is limited around.
    start_distance: f32,
    /// The orthographic height at the start (or the one a perspective lens turns into).
    start_height: Option<f32>,
}

impl Orbit {
    /// Starts at `camera`.
    pub fn new(camera: SceneCamera) -> Self {
        let start_height = match camera.projection {
            SceneProjection::Orthographic { height } => Some(height),
            SceneProjection::Perspective { .. } => None,
        };
        let distance = camera_distance(&camera);
        let mut orbit = Self { camera, distance, pitch: 0.0, start_distance: distance, start_height };
        orbit.pitch = orbit.measured_angles().1;
        orbit
    }

    /// Starts at `framed` around `bounds`: looking at the centre with `up` along `+y`, every length of `framed`
    /// (in radii) times the radius.
    pub fn framed(framed: &FramedCamera, bounds: &BoundingSphere) -> Self {
        let r = bounds.radius;
        let projection = match framed.projection {
            SceneProjection::Orthographic { height } => SceneProjection::Orthographic { height: height * r },
            lens @ SceneProjection::Perspective { .. } => lens,
        };
        let camera = SceneCamera {
            position: bounds.centre + Vec3::Z * (framed.distance * r),
            target: bounds.centre,
            up: Vec3::Y,
            projection,
            near: framed.near.map(|n| n * r),
            far: framed.far.map(|f| f * r),
        };
        let mut orbit = Self::new(camera);
        orbit.set_angles(framed.yaw_degrees.to_radians(), framed.pitch_degrees.to_radians());
        orbit
    }

    /// The reference frame of the angles, both across `up`: the direction of the eye at yaw 0, and the screen's
    /// right seen from there.
    fn frame(&self) -> (Vec3, Vec3) {
        let up = self.up();
        let front = (Vec3::Z - up * Vec3::Z.dot(up)).try_normalize().unwrap_or(Vec3::X);
        (front, up.cross(front))
    }

    /// The camera's `up`, of unit length.
    fn up(&self) -> Vec3 {
        self.camera.up.try_normalize().unwrap_or(Vec3::Y)
    }

    /// The eye's yaw and pitch now, in radians.
    pub fn angles(&self) -> (f32, f32) {
        (self.measured_angles().0, self.pitch)
    }

    /// The eye's yaw and pitch measured from its position.
    fn measured_angles(&self) -> (f32, f32) {
        let c = &self.camera;
        let offset = (c.position - c.target).normalize_or_zero();
        let (front, right) = self.frame();
        let pitch = float::asin(float::clamp(offset.dot(self.up()), -1.0, 1.0));
        let yaw = (-offset.dot(right)).atan2(offset.dot(front));
        (yaw, pitch)
    }

    /// Puts the eye at `yaw` and `pitch` radians (see [`Orbit`]) at its distance from the target; the pitch stops
    /// short of straight above or below.
    pub(crate) fn set_angles(&mut self, yaw: f32, pitch: f32) {
        let (front, right) = self.frame();
        self.place(front * float::cos(yaw) - right * float::sin(yaw), pitch);
    }

    /// Puts the eye `pitch` radians (within the poles' limit) above the horizontal unit direction `horizontal`, at
    /// its distance.
    fn place(&mut self, horizontal: Vec3, pitch: f32) {
        let limit = float::asin(POLE_COSINE);
        let pitch = float::clamp(pitch, -limit, limit);
        let direction = horizontal * float::cos(pitch) + self.up() * float::sin(pitch);
        let offset = direction * self.distance;
        if offset.is_finite() && offset.length() > 0.0 {
            self.camera.position = self.camera.target + offset;
            self.pitch = pitch;
        }
    }

    /// Moves the eye to `distance` from the target along the view direction, and makes that the distance zooming
    /// is limited around (`--distance`).
    pub(crate) fn set_distance(&mut self, distance: f32) {
        let c = &mut self.camera;
        let offset = c.position - c.target;
        let before = offset.length();
        if before > 0.0 && distance.is_finite() && distance > 0.0 {
            c.position = c.target + offset * (distance / before);
            (self.distance, self.start_distance) = (distance, distance);
        }
    }

    /// Orbits by `yaw` and `pitch` radians: positive yaw turns the scene's front to the right (the eye moves left
    /// about `up`), positive pitch tilts its top toward the eye (the eye rises). The pitch stops short of straight
    /// above or below the target, where "up" on screen would flip.
    ///
    /// Only the eye's horizontal direction is turned; its elevation and distance are set again from the values
    /// kept, so that the rounding of a million turntable steps cannot move it up, down, in or out.
    pub fn rotate(&mut self, yaw: f32, pitch: f32) {
        let up = self.up();
        let offset = self.camera.position - self.camera.target;
        // Straight above or below the target (a file's camera may look straight down): no horizontal direction,
        // so the one of yaw 0 is used.
        let horizontal = (offset - up * offset.dot(up)).try_normalize().unwrap_or(self.frame().0);
        let turned = Quat::from_axis_angle(up, -yaw).rotate(horizontal).try_normalize().unwrap_or(horizontal);
        self.place(turned, self.pitch + pitch);
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
            SceneProjection::Perspective { .. } => {
                let offset = c.position - c.target;
                let before = offset.length();
                let lo = self.start_distance / ZOOM_RANGE;
                let hi = self.start_distance * ZOOM_RANGE;
                let after = (before * factor).clamp(lo, hi);
                if !(before > 0.0 && after.is_finite()) {
                    return;
                }
                c.position = c.target + offset * (after / before);
                self.distance = after;
                let near = c.near.map(|n| n * after / before);
                c.far = c.far.map(|f| {
                    let moved = f + (after - before);
                    let floor = near.unwrap_or(0.0) * 2.0;
                    if moved > floor { moved } else { floor.max(f * after / before) }
                });
                c.near = near;
            }
            SceneProjection::Orthographic { height } => {
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
            SceneProjection::Perspective { fov_degrees } => {
                let height = 2.0 * d * float::tan(fov_degrees.to_radians() * 0.5);
                self.start_height.get_or_insert(height);
                SceneProjection::Orthographic { height }
            }
            SceneProjection::Orthographic { height } => {
                let fov = 2.0 * float::atan(height / (2.0 * d));
                SceneProjection::Perspective { fov_degrees: fov.to_degrees().clamp(1.0, 179.0) }
            }
        };
    }

    /// True for an orthographic lens.
    pub fn is_orthographic(&self) -> bool {
        matches!(self.camera.projection, SceneProjection::Orthographic { .. })
    }
}

fn camera_distance(camera: &SceneCamera) -> f32 {
    (camera.position - camera.target).length()
}

#[cfg(test)]
mod tests {
    use rastty_core::math::Vec3;

    use super::*;

    fn orbit() -> Orbit {
        Orbit::new(SceneCamera {
            position: Vec3::new(0.0, 0.0, 5.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection: SceneProjection::Perspective { fov_degrees: 40.0 },
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
    fn angles_place_the_eye_and_read_back() {
        let mut o = orbit();
        assert!(close(Vec3::new(o.angles().0, o.angles().1, 0.0), Vec3::ZERO));
        o.set_angles(30f32.to_radians(), 15f32.to_radians());
        // Yaw 30 moves the eye round to the left, pitch 15 raises it: the model viewer's default view.
        let (s, c) = (30f32.to_radians().sin_cos(), 15f32.to_radians().sin_cos());
        let expected = Vec3::new(-s.0 * c.1, c.0, s.1 * c.1) * 5.0;
        assert!(close(o.camera.position, expected), "{:?}", o.camera.position);
        let (yaw, pitch) = o.angles();
        assert!((yaw - 30f32.to_radians()).abs() < 1e-5 && (pitch - 15f32.to_radians()).abs() < 1e-5);
        o.set_distance(2.0);
        assert!((o.camera.position.length() - 2.0).abs() < 1e-5);
    }

    #[test]
    fn a_framed_camera_measures_in_radii() {
        let bounds = BoundingSphere { centre: Vec3::new(1.0, 2.0, 3.0), radius: 10.0 };
        let framed = FramedCamera { yaw_degrees: 0.0, pitch_degrees: 0.0, near: Some(1.0), ..FramedCamera::DEFAULT };
        let o = Orbit::framed(&framed, &bounds);
        assert!(close(o.camera.position, Vec3::new(1.0, 2.0, 31.0)));
        assert_eq!(o.camera.target, bounds.centre);
        assert_eq!(o.camera.near, Some(10.0));
    }

    #[test]
    fn the_lens_switches_keeping_the_size_at_the_target() {
        let mut o = orbit();
        o.toggle_projection();
        let SceneProjection::Orthographic { height } = o.camera.projection else { panic!() };
        assert!((height - 10.0 * 20f32.to_radians().tan()).abs() < 1e-4);
        o.toggle_projection();
        let SceneProjection::Perspective { fov_degrees } = o.camera.projection else { panic!() };
        assert!((fov_degrees - 40.0).abs() < 1e-3);
    }
}
