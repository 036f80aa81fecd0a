//! A model shown without a scene file, as a scene: one object, the model fitted into the unit sphere, under the
//! viewer's framed camera and lights. Everything that draws a scene then draws it, with nothing of its own.

use std::path::PathBuf;
use std::sync::Arc;

use rastty_core::color::ShadingSpace;

use super::defaults::{AMBIENT, BACKGROUND, VIEWER_LIGHTS};
use super::loaded::{CameraPlacement, FramedCamera, ObjectMaterial, SceneData, SceneObject};
use crate::environment::EnvironmentLight;
use crate::model::Model;
#[cfg(doc)]
use crate::model::ModelLight;

impl SceneData {
    /// The scene of `model` alone, loaded from `mesh_path`: one object whose transform is the model's fit into the
    /// unit sphere ([`Model::fit`]), with the model's own materials; the viewer's framed camera
    /// ([`FramedCamera::DEFAULT`]), ambient light and background; the model's own lights, fitted with it
    /// ([`SceneObject::own_lights`], [`ModelLight::scene_light`]; [`Self::lights_of`] is then `Some(0)`), or the
    /// viewer's ([`VIEWER_LIGHTS`], which follow the camera) for a model
    /// that has none; linear light; no ambient occlusion; the built-in studio environment when a material is
    /// physically based ([`Self::physically_based`]). The model keeps its warnings ([`Model::warnings`]).
    pub fn from_model(model: Model, mesh_path: PathBuf) -> Self {
        let transform = model.fit();
        let object = SceneObject {
            mesh_path,
            model: Arc::new(model),
            transform,
            material: ObjectMaterial::default(),
            animation: None,
        };
        let (lights, lights_of) = if object.model.lights.is_empty() {
            (VIEWER_LIGHTS.to_vec(), None)
        } else {
            (object.own_lights(), Some(0))
        };
        let mut data = Self {
            camera: CameraPlacement::Framed(FramedCamera::DEFAULT),
            lights,
            lights_of,
            objects: vec![object],
            background: BACKGROUND,
            ambient: AMBIENT,
            ambient_occlusion: false,
            environment: None,
            space: ShadingSpace::Linear,
            images: Vec::new(),
            warnings: Vec::new(),
        };
        data.environment = data.physically_based().then(EnvironmentLight::studio);
        data
    }
}
