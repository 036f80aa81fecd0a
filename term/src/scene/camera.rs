//! The orbit camera: a model turned by a quaternion in front of a fixed camera, seen in perspective or
//! orthographically.

use rastty_core::camera::{CameraError, look_at, orthographic, perspective};
use rastty_core::math::{Mat4, Quat, Vec3, float};

/// Radius of the sphere every model is fitted into (see [`crate::model::Model::fit`]), plus a margin so that the
/// default near and far planes never touch the model.
const FITTED_RADIUS: f32 = 1.05;

/// How the camera projects.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Lens {
    /// Perspective with a vertical field of view in degrees.
    Perspective {
        /// Vertical field of view in degrees, strictly between 0 and 180.
        fov_degrees: f32,
    },
    /// Orthographic, framed like a perspective camera with this field of view at the model's centre.
    Orthographic {
        /// The field of view whose framing at the model's centre the parallel projection keeps.
        fov_degrees: f32,
    },
}

impl Lens {
    /// The field of view in degrees.
    pub fn fov_degrees(&self) -> f32 {
        match *self {
            Self::Perspective { fov_degrees } | Self::Orthographic { fov_degrees } => fov_degrees,
        }
    }

    /// The other kind of lens with the same field of view (the viewer's `p` key).
    pub fn toggled(self) -> Self {
        match self {
            Self::Perspective { fov_degrees } => Self::Orthographic { fov_degrees },
            Self::Orthographic { fov_degrees } => Self::Perspective { fov_degrees },
        }
    }

    /// True for an orthographic lens.
    pub fn is_orthographic(&self) -> bool {
        matches!(self, Self::Orthographic { .. })
    }
}

/// Where the model is seen from: its orientation, the camera's distance from its centre (in fitted radii), the
/// lens, and optional near/far planes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// The model's orientation in front of the camera.
    pub orientation: Quat,
    /// Distance from the camera to the model's centre, in units of the model's bounding radius.
    pub distance: f32,
    /// The lens.
    pub lens: Lens,
    /// Near plane distance; by default just in front of the model's bounding sphere.
    pub near: Option<f32>,
    /// Far plane distance; by default just behind the model's bounding sphere.
    pub far: Option<f32>,
}

/// The matrices for one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraMatrices {
    /// World (fitted model space, after the orientation) to view space.
    pub view: Mat4,
    /// View space to clip space.
    pub projection: Mat4,
    /// Distance of the near plane.
    pub near: f32,
    /// Distance of the far plane.
    pub far: f32,
}

impl OrbitCamera {
    /// Default distance: a model fills most of the height with the default lens.
    pub const DEFAULT_DISTANCE: f32 = 2.8;
    /// Default vertical field of view.
    pub const DEFAULT_FOV_DEGREES: f32 = 40.0;

    /// A camera with the model turned by `yaw` (about the vertical axis) and then `pitch` (about the horizontal
    /// axis), both in degrees.
    pub fn new(yaw_degrees: f32, pitch_degrees: f32, distance: f32, lens: Lens) -> Self {
        let orientation = Quat::from_axis_angle(Vec3::X, pitch_degrees.to_radians())
            * Quat::from_axis_angle(Vec3::Y, yaw_degrees.to_radians());
        Self { orientation, distance, lens, near: None, far: None }
    }

    /// Turns the model by `yaw` and `pitch` radians about the screen's vertical and horizontal axes, as seen now.
    pub fn rotate(&mut self, yaw: f32, pitch: f32) {
        let turn = Quat::from_axis_angle(Vec3::X, pitch) * Quat::from_axis_angle(Vec3::Y, yaw);
        self.orientation = (turn * self.orientation).normalize();
    }

    /// The near and far plane distances.
    pub fn planes(&self) -> (f32, f32) {
        let near = self.near.unwrap_or((self.distance - FITTED_RADIUS).max(self.distance * 0.01));
        let far = self.far.unwrap_or(self.distance + FITTED_RADIUS);
        (near, far)
    }

    /// View and projection for an image whose width over height (in physical units, so terminal cells count as
    /// their real shape) is `aspect`.
    ///
    /// The field of view spans the image's shorter side, so a model framed in a landscape image stays framed in
    /// a portrait one.
    ///
    /// # Errors
    /// [`CameraError`] for a distance, field of view or plane that does not make a camera.
    pub fn matrices(&self, aspect: f32) -> Result<CameraMatrices, CameraError> {
        if !(self.distance.is_finite() && self.distance > 0.0) {
            return Err(CameraError::DepthRange);
        }
        let view = look_at(Vec3::new(0.0, 0.0, self.distance), Vec3::ZERO, Vec3::Y)?;
        let (near, far) = self.planes();
        let fov = self.lens.fov_degrees().to_radians();
        if !(fov > 0.0 && fov < std::f32::consts::PI) {
            return Err(CameraError::FieldOfView);
        }
        // Half the height of the view at unit distance: tan(fov / 2), divided by the aspect in portrait.
        let half_tan = float::tan(fov * 0.5) / aspect.min(1.0);
        let fovy = if aspect >= 1.0 { fov } else { 2.0 * float::atan(half_tan) };
        let projection = match self.lens {
            Lens::Perspective { .. } => perspective(fovy, aspect, near, far)?,
            Lens::Orthographic { .. } => {
                let half_height = self.distance * half_tan;
                let half_width = half_height * aspect;
                orthographic(-half_width, half_width, -half_height, half_height, near, far)?
            }
        };
        Ok(CameraMatrices { view, projection, near, far })
    }

    /// The model matrix for a model whose fit transform is `fit`.
    pub fn model_matrix(&self, fit: &Mat4) -> Mat4 {
        self.orientation.to_mat4() * *fit
    }
}

impl Default for OrbitCamera {
    fn default() -> Self {
        Self::new(30.0, 15.0, Self::DEFAULT_DISTANCE, Lens::Perspective { fov_degrees: Self::DEFAULT_FOV_DEGREES })
    }
}
