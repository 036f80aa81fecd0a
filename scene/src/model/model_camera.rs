//! A camera a model file gives (glTF's `cameras`, placed by their nodes), as a scene camera.

use rastty_core::math::{Mat4, Vec3};

use crate::scene_file::{SceneCamera, SceneProjection};

/// A camera of a glTF file: its lens and its node's world transform in the rest pose. glTF cameras look down their
/// node's `-z` with `+y` up (glTF 2.0, section 3.10).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelCamera {
    /// Its name in the file, raw (escape before printing), or `None`.
    pub name: Option<String>,
    /// Its node's world transform.
    pub world: Mat4,
    /// The lens.
    pub lens: ModelLens,
    /// The near plane's distance along `-z` in the node's units (positive).
    pub near: f32,
    /// The far plane's distance, when the file gives one (beyond `near`).
    pub far: Option<f32>,
}

/// A glTF camera's lens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ModelLens {
    /// Perspective, with this vertical field of view in radians (between 0 and pi).
    Perspective {
        /// `yfov`.
        yfov: f32,
    },
    /// Orthographic, half as tall as this many units (`ymag`, positive).
    Orthographic {
        /// `ymag`.
        ymag: f32,
    },
}

impl ModelCamera {
    /// Its name for messages: its own, or "camera N" (N from 0, its place among the model's cameras).
    pub fn label(&self, index: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("camera {index}"))
    }

    /// The camera in the world of an object placed by `object_transform`: the eye at its origin, looking along its
    /// `-z`, its planes and orthographic height scaled as the transforms scale its `-z` axis. The field of view
    /// spans the frame's shorter side (the vertical one in a landscape frame, as `yfov` does); the file's aspect
    /// ratio is not used (the frame's is). `None` when the transforms leave it no direction.
    pub fn scene_camera(&self, object_transform: &Mat4) -> Option<SceneCamera> {
        let m = *object_transform * self.world;
        let position = m.transform_point(Vec3::ZERO);
        let forward = m.transform_vector(-Vec3::Z);
        let scale = forward.length();
        let up = m.transform_vector(Vec3::Y).try_normalize()?;
        let forward = forward.try_normalize()?;
        let projection = match self.lens {
            ModelLens::Perspective { yfov } => SceneProjection::Perspective { fov_degrees: yfov.to_degrees() },
            ModelLens::Orthographic { ymag } => SceneProjection::Orthographic { height: 2.0 * ymag * scale },
        };
        let camera = SceneCamera {
            position,
            target: position + forward,
            up,
            projection,
            near: Some(self.near * scale),
            far: self.far.map(|f| f * scale),
        };
        (position.is_finite() && scale.is_finite() && scale > 0.0).then_some(camera)
    }
}
