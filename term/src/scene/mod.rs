//! A loaded model ready to draw: camera, lights, shading choices, and drawing into any core target.
//!
//! Both front ends use it: [`crate::headless`] for PNG files and the terminal viewer. A [`Scene`] draws into a
//! [`Target`] — a whole frame or one band of rows — so the same code renders a PNG, a terminal frame, or a strip.

mod appearance;
mod camera;

pub use appearance::{Appearance, ShadingMode, parse_hex_color};
pub use camera::{CameraMatrices, Lens, OrbitCamera};

use std::fmt;

use rastty_core::camera::CameraError;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::pipeline::{DrawError, DrawState, DrawStats, LineStyle, draw_wireframe};
use rastty_core::shading::{Effects, Light, Lighting, Material, ShadingModel, TextureBinding, Transforms, draw_mesh};
use rastty_core::target::{ColorBuffer, DepthBuffer, Target};
use rastty_core::texture::{FilterMode, WrapMode};

use crate::model::Model;

/// The scene's lights, fixed relative to the camera: a warm key light from the upper left, a cool fill light from
/// the right, and a little ambient light.
pub const LIGHTS: [Light; 2] = [
    Light { to_light: Vec3::new(-0.445_435, 0.668_153, 0.596_559), color: Vec3::new(0.9, 0.87, 0.8) },
    Light { to_light: Vec3::new(0.882_353, 0.0, 0.470_588), color: Vec3::new(0.18, 0.2, 0.26) },
];
/// The ambient light.
pub const AMBIENT: Vec3 = Vec3::new(0.14, 0.14, 0.16);
/// Specular colour of lit surfaces.
pub const SPECULAR: Vec3 = Vec3::new(0.22, 0.22, 0.22);
/// Blinn-Phong exponent of lit surfaces.
pub const SHININESS: f32 = 28.0;
/// Wireframe lines: a pale cyan drawn just in front of the surface.
pub const WIREFRAME: LineStyle = LineStyle { color: Vec3::new(0.55, 0.9, 1.0), depth_bias: 2e-4 };

/// Why a frame could not be drawn.
#[derive(Debug, Clone, PartialEq)]
pub enum RenderError {
    /// The camera settings do not make a camera.
    Camera(CameraError),
    /// The core refused a draw.
    Draw(DrawError),
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Camera(e) => write!(f, "bad camera: {e}"),
            Self::Draw(e) => write!(f, "cannot draw: {e}"),
        }
    }
}

impl std::error::Error for RenderError {}

/// A model with its fit transform.
#[derive(Debug, Clone)]
pub struct Scene {
    model: Model,
    fit: Mat4,
}

impl Scene {
    /// A scene showing `model`, centred and scaled to a unit sphere.
    pub fn new(model: Model) -> Self {
        let fit = model.fit();
        Self { model, fit }
    }

    /// The transforms of one frame for an image of physical aspect `aspect` (width over height).
    ///
    /// # Errors
    /// [`RenderError::Camera`] when the camera is degenerate.
    pub fn transforms(&self, camera: &OrbitCamera, aspect: f32) -> Result<(Transforms, CameraMatrices), RenderError> {
        let m = camera.matrices(aspect).map_err(RenderError::Camera)?;
        Ok((Transforms::new(camera.model_matrix(&self.fit), m.view, m.projection), m))
    }

    /// Draws the model into `target` (whose frame has physical aspect `aspect`) and returns what the core did.
    ///
    /// The target is not cleared first; [`Scene::render`] does that too.
    ///
    /// # Errors
    /// [`RenderError`] when the camera is degenerate or the core refuses a draw.
    pub fn draw<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
        camera: &OrbitCamera,
        appearance: &Appearance,
        aspect: f32,
    ) -> Result<DrawStats, RenderError> {
        let (transforms, matrices) = self.transforms(camera, aspect)?;
        let shading = self.shading_model(appearance.shading, camera, &matrices);
        let state = DrawState::default();
        let mut stats = DrawStats::default();
        for part in 0..self.model.parts.len() {
            let Some(mesh) = self.model.part_mesh(part) else { continue };
            let effects = self.effects(part, shading, appearance);
            stats += draw_mesh(target, &mesh, &transforms, &effects, &state).map_err(RenderError::Draw)?;
            if appearance.wireframe {
                // The lines' pixels count as fragments; their triangles are the ones counted above. (The model
                // matrix never mirrors, so the default winding is right for culling the lines too.)
                stats.fragments +=
                    draw_wireframe(target, &mesh, &transforms.clip_from_object, &WIREFRAME, &state).fragments;
            }
        }
        Ok(stats)
    }

    /// Clears `target` to the background and draws the model.
    ///
    /// # Errors
    /// As [`Scene::draw`].
    pub fn render<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
        camera: &OrbitCamera,
        appearance: &Appearance,
        aspect: f32,
    ) -> Result<DrawStats, RenderError> {
        target.clear(appearance.background);
        self.draw(target, camera, appearance, aspect)
    }

    /// What each part's draw compiles to (the shader variant and state), for `rastty render --stats`.
    ///
    /// # Errors
    /// As [`Scene::draw`].
    pub fn explain(
        &self,
        camera: &OrbitCamera,
        appearance: &Appearance,
        aspect: f32,
    ) -> Result<Vec<String>, RenderError> {
        let (transforms, matrices) = self.transforms(camera, aspect)?;
        let shading = self.shading_model(appearance.shading, camera, &matrices);
        let mut lines = Vec::new();
        for part in 0..self.model.parts.len() {
            let Some(mesh) = self.model.part_mesh(part) else { continue };
            let effects = self.effects(part, shading, appearance);
            let variant = effects.resolve(&mesh, &transforms, &DrawState::default()).map_err(RenderError::Draw)?;
            let line = variant.to_string();
            if !lines.contains(&line) {
                lines.push(line);
            }
        }
        Ok(lines)
    }

    /// The core shading model for a mode; the depth view spans the model's bounding sphere.
    fn shading_model(&self, mode: ShadingMode, camera: &OrbitCamera, m: &CameraMatrices) -> ShadingModel {
        match mode {
            ShadingMode::Unlit => ShadingModel::Unlit,
            ShadingMode::Flat => ShadingModel::Flat,
            ShadingMode::Gouraud => ShadingModel::Gouraud,
            ShadingMode::Phong => ShadingModel::Phong,
            ShadingMode::Normals => ShadingModel::Normals,
            ShadingMode::Depth => {
                let ndc = |distance: f32| {
                    let p = m.projection.project_point(Vec3::new(0.0, 0.0, -distance));
                    p.z / p.w
                };
                let near = ndc((camera.distance - 1.0).max(m.near));
                let far = ndc((camera.distance + 1.0).min(m.far));
                ShadingModel::Depth { near, far }
            }
        }
    }

    fn effects(&self, part: usize, shading: ShadingModel, appearance: &Appearance) -> Effects<'_> {
        let material = self.model.part_material(part);
        let texture = material
            .filter(|_| appearance.textures)
            .and_then(|m| m.texture.as_ref())
            .and_then(|t| t.texture().ok())
            .map(|texture| TextureBinding { texture, filter: FilterMode::Bilinear, wrap: WrapMode::Repeat });
        Effects {
            shading,
            material: Material {
                color: material.map_or(crate::model::DEFAULT_DIFFUSE, |m| m.diffuse),
                specular: SPECULAR,
                shininess: SHININESS,
            },
            lighting: Lighting { ambient: AMBIENT, lights: &LIGHTS },
            texture,
        }
    }
}
