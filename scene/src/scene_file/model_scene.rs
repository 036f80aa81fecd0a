//! A model shown without a scene file, as a scene: one object, the model fitted into the unit sphere, under the
//! viewer's framed camera and lights. Everything that draws a scene then draws it, with nothing of its own.

use std::path::PathBuf;
use std::sync::Arc;

use rastty_core::color::ShadingSpace;

use super::defaults::{AMBIENT, BACKGROUND, VIEWER_LIGHTS};
use super::loaded::{CameraPlacement, FramedCamera, ObjectMaterial, SceneData, SceneObject};
use crate::model::Model;

impl SceneData {
    /// The scene of `model` alone, loaded from `mesh_path`: one object whose transform is the model's fit into the
    /// unit sphere ([`Model::fit`]), with the model's own materials; the viewer's framed camera
    /// ([`FramedCamera::DEFAULT`]), lights ([`VIEWER_LIGHTS`], which follow the camera), ambient light and
    /// background; linear light; no ambient occlusion. The model keeps its warnings ([`Model::warnings`]).
    pub fn from_model(model: Model, mesh_path: PathBuf) -> Self {
        let transform = model.fit();
        let object = SceneObject {
            mesh_path,
            model: Arc::new(model),
            transform,
            material: ObjectMaterial::default(),
            animation: None,
        };
        Self {
            camera: CameraPlacement::Framed(FramedCamera::DEFAULT),
            lights: VIEWER_LIGHTS.to_vec(),
            objects: vec![object],
            background: BACKGROUND,
            ambient: AMBIENT,
            ambient_occlusion: false,
            space: ShadingSpace::Linear,
            images: Vec::new(),
            warnings: Vec::new(),
        }
    }
}
