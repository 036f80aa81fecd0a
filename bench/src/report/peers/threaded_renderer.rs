//! The same pictures through the program's threaded frame: each scene as a scene of one object, planned and drawn
//! by a [`SceneRenderer`] on a given number of threads, the way `rastty render` and the viewer draw a frame.
//!
//! The scene has the comparison's camera, one directional light of weight [`DIFFUSE`], ambient [`AMBIENT`],
//! per-pixel shading and no highlights, so its picture is the core renderer's
//! ([`super::core_renderer::CoreRenderer`]) pixel for pixel: the report counts the pixels that differ.

use std::path::PathBuf;
use std::sync::Arc;

use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::target::{Rgb888, Target};
use rastty_core::texture::{FilterMode, MipFilter, WrapMode};
use rastty_scene::model::{Model, ModelMaterial, Part};
use rastty_scene::scene_file::{
    CameraPlacement, LightSpace, ObjectMaterial, SceneCamera, SceneData, SceneLight, SceneLightKind, SceneObject,
    SceneProjection,
};
use rastty_scene::scene_render::{
    EffectToggles, PlanOptions, PreparedScene, ScenePlan, SceneRenderError, SceneRenderer,
};

use super::scenes::{AMBIENT, DIFFUSE, PeerScene, to_light};

/// A scene prepared and planned once, drawn by a renderer of its own into buffers kept between frames.
pub struct ThreadedRenderer {
    scene: PreparedScene,
    plan: ScenePlan,
    renderer: SceneRenderer,
    color: Vec<u32>,
    depth: Vec<f32>,
}

impl ThreadedRenderer {
    /// `scene` as a scene of one object, drawn on `threads` threads.
    ///
    /// # Errors
    /// When the scene renderer refuses the scene (it cannot for the scenes made in [`super::scenes`]).
    pub fn new(scene: &PeerScene, threads: usize) -> Result<Self, SceneRenderError> {
        let mut model = Model {
            positions: scene.positions.clone(),
            normals: scene.normals.clone(),
            uvs: scene.uvs.clone(),
            colors: None,
            tangents: None,
            indices: scene.indices.clone(),
            parts: vec![Part { name: scene.name.to_owned(), indices: 0..scene.indices.len(), material: Some(0) }],
            materials: vec![ModelMaterial {
                diffuse: scene.albedo(rastty_core::math::Vec2::ZERO),
                ..ModelMaterial::default()
            }],
            warnings: Vec::new(),
            rig: None,
            cameras: Vec::new(),
            lights: Vec::new(),
        };
        if let Some(texture) = &scene.texture {
            model.materials[0].diffuse = Vec3::ONE;
            model.set_texture(texture.clone());
        }
        let object = SceneObject {
            mesh_path: PathBuf::from(scene.name),
            model: Arc::new(model),
            transform: Mat4::IDENTITY,
            // Nearest texels and no mipmaps, as the peers sample.
            material: ObjectMaterial {
                filter: FilterMode::Nearest,
                wrap: WrapMode::Repeat,
                mip_filter: MipFilter::Off,
                ..Default::default()
            },
            animation: None,
        };
        let camera = SceneCamera {
            position: Vec3::new(0.0, 0.0, 3.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection: SceneProjection::Perspective { fov_degrees: 45.0 },
            near: Some(0.1),
            far: Some(100.0),
        };
        let light = SceneLight {
            kind: SceneLightKind::Directional { direction: -to_light() },
            color: Vec3::ONE,
            intensity: DIFFUSE,
            shadows: false,
            space: LightSpace::World,
        };
        let data = SceneData {
            camera: CameraPlacement::Placed(camera),
            lights: vec![light],
            lights_of: None,
            objects: vec![object],
            background: Vec3::ZERO,
            ambient: Vec3::splat(AMBIENT),
            ambient_occlusion: false,
            environment: None,
            // The peers light the stored sRGB values.
            space: ShadingSpace::Encoded,
            images: Vec::new(),
            warnings: Vec::new(),
        };
        let prepared = PreparedScene::new(data)?;
        // The frame is wider than tall or square in every scene, so the lens's angle is the vertical one.
        let options =
            PlanOptions { effects: EffectToggles { specular: false, ..EffectToggles::ALL_ON }, ..Default::default() };
        let plan = ScenePlan::new(&prepared, &camera, (scene.width, scene.height), &options)?;
        let n = (scene.width * scene.height) as usize;
        Ok(Self {
            scene: prepared,
            plan,
            renderer: SceneRenderer::with_threads(threads),
            color: vec![0; n],
            depth: vec![1.0; n],
        })
    }

    /// Draws the frame: clears it and draws the scene, in bands on the renderer's threads.
    ///
    /// # Errors
    /// When the renderer refuses the frame (it cannot: the buffers are the plan's size).
    pub fn render(&mut self) -> Result<(), SceneRenderError> {
        let (width, height) = self.plan.size;
        let mut target = Target::new(Rgb888(&mut self.color), &mut self.depth[..], width, height)?;
        self.renderer.render(&self.scene, &self.plan, &mut target)?;
        Ok(())
    }

    /// The last frame, `0x00RRGGBB`, top row first.
    pub fn pixels(&self) -> &[u32] {
        &self.color
    }
}
