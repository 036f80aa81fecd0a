//! What each frame shows: Spot turned by [`YAWS`]`[frame]`, lit, seen from a fixed camera; and how it is drawn.
//!
//! # One shader, compiled for what the scene uses
//! [`Scene::draw`] resolves the scene's variant and runs the surface shader compiled for its one layout (the
//! normal and the world position carried) and for per-pixel lighting from directional lights only
//! ([`capabilities::PER_PIXEL`]), through [`rastty_core::pipeline::draw`]. [`draw_mesh`] gives the same pixels
//! (the host test checks it), but it picks the shader at run time, so a firmware calling it links every variant
//! of the pipeline.

use rastty_core::pipeline::{BandBins, Bands, BinnedTriangle, Shader, draw};
use rastty_core::shading::{Absent, Layout, LightUse, SurfaceShader, Variant, capabilities};
use rastty_core::target::{ColorBuffer, DepthBuffer, FrameGeometry};
use rastty_core::{
    DrawState, DrawStats, Indices, Light, Lighting, Mat4, Material, Mesh, Object, Quat, ShadingError, ShadingModel,
    ShadingSpace, Target, Transforms, Vec3, draw_mesh, look_at, perspective,
};

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
/// Light reaching every surface from every direction.
const AMBIENT: Vec3 = Vec3::new(0.12, 0.12, 0.15);
/// Light on the stored sRGB codes: the pixels its checksums were first taken of, and without
/// [`capabilities::LINEAR_LIGHT`] the shader links no sRGB tables.
const SPACE: ShadingSpace = ShadingSpace::Encoded;

/// Fixed-function state: the core's default (back faces culled, depth test, perspective-correct, fixed-point
/// edges with full sub-pixel precision).
const STATE: DrawState = DrawState::DEFAULT;

/// The slots the scene's variant carries: the normal and the world position (for the highlight), nothing else.
const LAYOUT: Layout = Layout { first: true, second: true, uvs: false, tangents: false, colors: false };

/// The shader the firmware links: per-pixel lighting from directional lights, the normal and the world position
/// carried.
pub type SpotShader<'a> = SurfaceShader<'a, Vec3, Vec3, Absent, Absent, Absent, { capabilities::PER_PIXEL }>;

/// One frame's scene: Spot, its place and the light, built once and drawn into each band.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    object: Object<'static>,
    lights: [Light<'static>; 1],
}

impl Scene {
    /// The scene of frame `frame`: Spot lit per pixel with a highlight, untextured.
    ///
    /// # Panics
    /// If `frame >= FRAMES`.
    ///
    /// # Errors
    /// [`SceneError::Mesh`] if the model arrays do not make a mesh, [`SceneError::Camera`] if the camera constants
    /// do not make a camera (neither happens).
    pub fn new(frame: usize) -> Result<Self, SceneError> {
        let material =
            Material { specular: Vec3::splat(0.35), shininess: 24.0, ..Material::plain(Vec3::new(0.85, 0.78, 0.7)) };
        Ok(Self {
            object: Object {
                mesh: spot_mesh()?,
                tangents: None,
                transforms: transforms(YAWS[frame])?,
                shading: ShadingModel::Phong,
                material,
            },
            lights: [Light::directional(TO_LIGHT, LIGHT_COLOR)],
        })
    }

    /// The scene's lights.
    fn lights(&self) -> Lighting<'_> {
        Lighting { ambient: AMBIENT, lights: &self.lights, space: SPACE }
    }

    /// Clears `target` to [`BACKGROUND`] and draws Spot: into a band, or a whole frame (the same pixels).
    ///
    /// Runs [`SpotShader`] through [`draw`]: the pixels of [`draw_mesh`], without linking its other variants
    /// (see the module docs).
    ///
    /// # Errors
    /// [`SceneError::Draw`] if the draw fails, [`SceneError::Variant`] if the scene resolves to another variant
    /// than [`SpotShader`] draws (neither happens).
    pub fn draw<C: ColorBuffer, D: DepthBuffer>(&self, target: &mut Target<C, D>) -> Result<DrawStats, SceneError> {
        let shader = self.shader()?;
        target.clear(BACKGROUND);
        draw(target, &self.object.mesh, &shader, &STATE).map_err(SceneError::Draw)
    }

    /// Bins Spot's triangles by the bands of `bands` into `memory`, once for the frame: what
    /// [`Scene::draw_band`] reads.
    ///
    /// # Errors
    /// As [`Scene::draw`].
    pub fn bin<'m>(&self, memory: &'m mut [BinnedTriangle], bands: Bands) -> Result<BandBins<'m>, SceneError> {
        let shader = self.shader()?;
        let (mesh, matrix) = (&self.object.mesh, shader.clip_from_object());
        let matrix = matrix.ok_or(SceneError::Variant)?;
        BandBins::bin(memory, mesh, matrix, &STATE, bands, 0..mesh.triangle_count(), None).map_err(SceneError::Draw)
    }

    /// Clears `target`, one band of the frame, to [`BACKGROUND`] and draws the triangles of `bins` that meet it:
    /// the pixels of [`Scene::draw`] on the same target.
    ///
    /// # Errors
    /// As [`Scene::draw`].
    pub fn draw_band<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
        bins: &BandBins<'_>,
    ) -> Result<DrawStats, SceneError> {
        let shader = self.shader()?;
        target.clear(BACKGROUND);
        let mut target = target.for_draw(FrameGeometry { vertices: None, bins: core::slice::from_ref(bins) });
        draw(&mut target, &self.object.mesh, &shader, &STATE).map_err(SceneError::Draw)
    }

    /// The one shader the scene's variant calls for.
    fn shader(&self) -> Result<SpotShader<'_>, SceneError> {
        let variant = Variant::resolve(&self.object, self.lights.iter().map(LightUse::from), SPACE, &STATE)
            .map_err(draw_error)?;
        if variant.layout() != LAYOUT || variant.state != STATE {
            return Err(SceneError::Variant);
        }
        let o = &self.object;
        SpotShader::new(variant, o.transforms, &[], o.material, self.lights()).map_err(draw_error)
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
        let (_, stats) = draw_mesh(target, &self.object, &self.lights(), &STATE).map_err(draw_error)?;
        Ok(stats)
    }
}

/// A draw's error as the scene's: [`SceneError::Variant`] when the variant is not the one the scene draws.
fn draw_error(e: ShadingError) -> SceneError {
    match e {
        ShadingError::Draw(e) => SceneError::Draw(e),
        _ => SceneError::Variant,
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
