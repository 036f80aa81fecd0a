//! What each frame shows: Spot turned by [`YAWS`]`[frame]`, lit, seen from a fixed camera; and how it is drawn.
//!
//! # One shader, not `draw_mesh`
//! [`Scene::draw`] resolves the scene's [`Effects`] and runs the one shader they call for through
//! [`rastty_core::pipeline::draw`]. [`draw_mesh`] gives the same pixels (the host test checks it), but it picks
//! the shader at run time, so a firmware calling it links every variant of the pipeline: 3.1 MB of Cortex-M4 code
//! (`.text`) at `opt-level = 3`, against 51 KB this way (one build each, 2026-11-21; docs/firmware.md).

use rastty_core::camera::{look_at, perspective};
use rastty_core::effects::{
    Absent, Layout, LightSource, LightUse, SceneLights, SurfaceDraw, SurfaceError, SurfaceMaterial, SurfaceShader,
    SurfaceVariant, capabilities,
};
use rastty_core::math::{Mat4, Quat, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{DrawState, DrawStats, draw};
use rastty_core::shading::{
    Effects, Light, Lighting, Material, PhongShader, ShadingModel, Specular, Surface, Transforms, Untextured, draw_mesh,
};
use rastty_core::target::{ColorBuffer, DepthBuffer, Target};

use crate::{HEIGHT, SceneError, WIDTH, spot};

/// The model's rotation about the vertical axis in each frame, in radians.
pub const YAWS: [f32; 2] = [2.3, 3.9];
/// Number of frames: one per entry of [`YAWS`].
pub const FRAMES: usize = YAWS.len();

/// Background colour.
pub const BACKGROUND: Vec3 = Vec3::new(0.08, 0.1, 0.16);
/// Point of the model that is turned about and looked at: the middle of Spot's bounding box, rounded.
const MODEL_CENTRE: Vec3 = Vec3::new(0.0, 0.11, 0.19);
/// Camera position.
const EYE: Vec3 = Vec3::new(0.0, 0.5, 2.9);
/// Vertical field of view, radians.
const FOVY: f32 = 0.7;
/// Near plane: just in front of Spot's bounding sphere (radius about 1.3).
const NEAR: f32 = 1.0;
/// Far plane: just behind Spot's bounding sphere.
const FAR: f32 = 4.5;
/// From the surface toward the one light, in world space (normalised by [`Light::directional`]).
const TO_LIGHT: Vec3 = Vec3::new(0.5, 0.8, 0.6);
/// The light's colour.
const LIGHT_COLOR: Vec3 = Vec3::new(1.0, 0.97, 0.9);

/// Fixed-function state: the core's default (back faces culled, depth test, perspective-correct, fixed-point
/// edges with full sub-pixel precision).
const STATE: DrawState = DrawState::DEFAULT;

/// One frame's scene: the mesh, its transforms and the light, built once and drawn into each strip.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    mesh: Mesh<'static>,
    transforms: Transforms,
    lights: [Light; 1],
    sources: [LightSource<'static>; 1],
}

impl Scene {
    /// The scene of frame `frame`.
    ///
    /// # Panics
    /// If `frame >= FRAMES`.
    ///
    /// # Errors
    /// [`SceneError::Mesh`] if the model arrays do not make a mesh, [`SceneError::Camera`] if the camera constants
    /// do not make a camera (neither happens).
    pub fn new(frame: usize) -> Result<Self, SceneError> {
        Ok(Self {
            mesh: spot_mesh()?,
            transforms: transforms(YAWS[frame])?,
            lights: [Light::directional(TO_LIGHT, LIGHT_COLOR)],
            sources: [LightSource::directional(TO_LIGHT, LIGHT_COLOR)],
        })
    }

    /// Per-pixel lighting with a highlight, untextured.
    fn effects(&self) -> Effects<'_> {
        Effects {
            shading: ShadingModel::Phong,
            material: Material { color: Vec3::new(0.85, 0.78, 0.7), specular: Vec3::splat(0.35), shininess: 24.0 },
            lighting: Lighting { ambient: Vec3::new(0.12, 0.12, 0.15), lights: &self.lights },
            texture: None,
        }
    }

    /// Clears `target` to [`BACKGROUND`] and draws Spot: into a band, or a whole frame (the same pixels).
    ///
    /// Runs the one shader the scene's [`Effects`] resolve to, [`PhongShader`] untextured with [`Specular`]
    /// highlights, through [`draw`]: the pixels of [`draw_mesh`], without linking its other variants (see the
    /// module docs).
    ///
    /// # Errors
    /// [`SceneError::Draw`] if the draw fails, [`SceneError::Variant`] if the effects resolve to another variant
    /// (neither happens).
    pub fn draw<C: ColorBuffer, D: DepthBuffer>(&self, target: &mut Target<C, D>) -> Result<DrawStats, SceneError> {
        let effects = self.effects();
        let variant = effects.resolve(&self.mesh, &self.transforms, &STATE).map_err(SceneError::Draw)?;
        let phong_untextured_specular = variant.shading == ShadingModel::Phong
            && !variant.vertex_colors
            && variant.texture.is_none()
            && variant.specular;
        if !phong_untextured_specular || variant.state != STATE {
            return Err(SceneError::Variant);
        }
        let surface = Surface { transforms: self.transforms, material: effects.material, lighting: effects.lighting };
        let shader = PhongShader::<_, Specular>::new(surface, Untextured);
        target.clear(BACKGROUND);
        draw(target, &self.mesh, &shader, &STATE).map_err(SceneError::Draw)
    }

    /// [`Scene::draw`] through the batched surface shader, compiled for the one layout the scene's variant
    /// resolves to (per-pixel lighting with a highlight, untextured: the normal and the world position carried)
    /// and for per-pixel lighting from directional lights only: the same pixels, for the host test to prove it
    /// while the core moves every shading model onto that shader. (On the Cortex-M4 it takes 121.9 M instructions
    /// a frame and 38,848 bytes of the core's code, against the per-pixel shader's 84.6 M and 25,348; 2026-11-26.)
    ///
    /// # Errors
    /// [`SceneError::Draw`] if the draw fails, [`SceneError::Variant`] if the scene resolves to another variant
    /// (neither happens).
    pub fn draw_through_surface_shader<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
    ) -> Result<DrawStats, SceneError> {
        let effects = self.effects();
        let m = effects.material;
        let material =
            SurfaceMaterial { specular: m.specular, shininess: m.shininess, ..SurfaceMaterial::plain(m.color) };
        let object = SurfaceDraw {
            mesh: self.mesh,
            tangents: None,
            transforms: self.transforms,
            shading: ShadingModel::Phong,
            material,
        };
        let lights = SceneLights { ambient: effects.lighting.ambient, lights: &self.sources };
        let variant =
            SurfaceVariant::resolve(&object, self.sources.iter().map(LightUse::from), &STATE).map_err(|e| match e {
                SurfaceError::Draw(e) => SceneError::Draw(e),
                _ => SceneError::Variant,
            })?;
        let expected = Layout { first: true, second: true, uvs: false, tangents: false };
        if variant.layout() != expected || variant.state != STATE {
            return Err(SceneError::Variant);
        }
        // Compiled for per-pixel lighting from directional lights only: the code of the other models, point lights,
        // shadow maps and maps is left out of the firmware.
        let shader = SurfaceShader::<Vec3, Vec3, Absent, Absent, { capabilities::PER_PIXEL }>::new(
            variant,
            self.transforms,
            &[],
            material,
            lights,
        )
        .map_err(|_| SceneError::Variant)?;
        target.clear(BACKGROUND);
        draw(target, &self.mesh, &shader, &STATE).map_err(SceneError::Draw)
    }

    /// [`Scene::draw`] through [`draw_mesh`], which picks the shader at run time: the same pixels, for the host
    /// test to prove it. (A firmware calling this links every variant of the pipeline.)
    ///
    /// # Errors
    /// [`SceneError::Draw`] if the draw fails (it does not).
    pub fn draw_through_draw_mesh<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
    ) -> Result<DrawStats, SceneError> {
        target.clear(BACKGROUND);
        draw_mesh(target, &self.mesh, &self.transforms, &self.effects(), &STATE).map_err(SceneError::Draw)
    }
}

/// Spot as a mesh over the generated arrays.
fn spot_mesh() -> Result<Mesh<'static>, SceneError> {
    Mesh::new(&spot::POSITIONS, Indices::U16(&spot::INDICES))
        .and_then(|mesh| mesh.with_normals(&spot::NORMALS))
        .map_err(SceneError::Mesh)
}

/// Spot turned by `yaw` radians about the vertical axis through [`MODEL_CENTRE`], seen from [`EYE`], slightly
/// above.
fn transforms(yaw: f32) -> Result<Transforms, SceneError> {
    let turn = Quat::from_axis_angle(Vec3::Y, yaw).to_mat4();
    let model = turn * Mat4::from_translation(Vec3::new(-MODEL_CENTRE.x, -MODEL_CENTRE.y, -MODEL_CENTRE.z));
    let view = look_at(EYE, Vec3::ZERO, Vec3::Y).map_err(SceneError::Camera)?;
    // WIDTH / HEIGHT, divided at compile time: the same f32 on every machine.
    const ASPECT: f32 = WIDTH as f32 / HEIGHT as f32;
    let projection = perspective(FOVY, ASPECT, NEAR, FAR).map_err(SceneError::Camera)?;
    Ok(Transforms::new(model, view, projection))
}
