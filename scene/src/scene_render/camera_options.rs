//! The command line's camera options (`--yaw`, `--pitch`, `--distance`, `--fov`, `--ortho`, `--near`, `--far`),
//! applied to a scene's camera: the same for a model and for a scene file.

use super::{Orbit, PreparedScene};
use crate::scene_file::SceneProjection;

/// Camera settings given on the command line; each left out keeps the scene's own. Lengths are in radii of the
/// scene's bounding sphere (a model is fitted into the unit sphere, so for a model they are world units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CameraOptions {
    /// The eye's yaw in degrees ([`Orbit`]: positive turns the scene's front to the right).
    pub yaw_degrees: Option<f32>,
    /// The eye's elevation in degrees.
    pub pitch_degrees: Option<f32>,
    /// The eye's distance from the target, in radii.
    pub distance: Option<f32>,
    /// A perspective lens with this field of view across the frame's shorter side, in degrees.
    pub fov_degrees: Option<f32>,
    /// An orthographic lens, showing at the target what the perspective lens showed there.
    pub orthographic: bool,
    /// The near plane's distance, in radii.
    pub near: Option<f32>,
    /// The far plane's distance, in radii.
    pub far: Option<f32>,
}

impl CameraOptions {
    /// The scene's camera ([`PreparedScene::camera`]) with these settings applied, as an [`Orbit`]: the angles
    /// first (a pitch or yaw given alone keeps the other), then the distance, the lens and the planes.
    pub fn orbit(&self, scene: &PreparedScene) -> Orbit {
        let mut orbit = Orbit::new(scene.camera());
        let radius = scene.bounds().radius;
        if self.yaw_degrees.is_some() || self.pitch_degrees.is_some() {
            let (yaw, pitch) = orbit.angles();
            let yaw = self.yaw_degrees.map_or(yaw, f32::to_radians);
            let pitch = self.pitch_degrees.map_or(pitch, f32::to_radians);
            orbit.set_angles(yaw, pitch);
        }
        if let Some(distance) = self.distance {
            orbit.set_distance(distance * radius);
        }
        if let Some(fov_degrees) = self.fov_degrees {
            orbit.camera.projection = SceneProjection::Perspective { fov_degrees };
        }
        if self.orthographic && !orbit.is_orthographic() {
            orbit.toggle_projection();
        }
        if let Some(near) = self.near {
            orbit.camera.near = Some(near * radius);
        }
        if let Some(far) = self.far {
            orbit.camera.far = Some(far * radius);
        }
        orbit
    }
}
