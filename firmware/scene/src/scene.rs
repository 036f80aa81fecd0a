//! What each frame shows ([`VIEWS`]`[frame]`): Spot turned about the vertical axis, lit, seen from a fixed camera,
//! plain or with its texture ([`Look`]); and how it is drawn.
//!
//! # One shader per look, compiled for what the scene uses
//! [`Scene::draw`] resolves the scene's variant and runs the surface shader compiled for its layout (the normal
//! and the world position carried, and the texture coordinates for [`Look::Textured`]) and for per-pixel lighting
//! from directional lights only ([`capabilities::PER_PIXEL`]), through [`rastty_core::pipeline::draw`]:
//! [`PlainShader`] or [`TexturedShader`]. [`draw_mesh`] gives the same pixels (the host test checks it), but it
//! picks the shader at run time, so a firmware calling it links every variant of the pipeline.

use rastty_core::pipeline::{BandBins, Bands, BinnedTriangle, draw};
use rastty_core::shading::{Absent, Layout, LightUse, Slot, SurfaceShader, Variant, capabilities};
use rastty_core::target::{ColorBuffer, DepthBuffer, FrameGeometry, VertexMemory};
use rastty_core::texture::{FilterMode, MipFilter, Texture, WrapMode};
use rastty_core::{
    DrawState, DrawStats, Indices, Light, Lighting, Mat4, Material, Mesh, Object, Quat, ShadingError, ShadingModel,
    ShadingSpace, Target, Transforms, Vec2, Vec3, draw_mesh, look_at, perspective,
};

use crate::{HEIGHT, SceneError, WIDTH, spot};

/// How Spot looks in a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Look {
    /// Untextured, covering about a quarter of the display (field of view [`PLAIN_FOVY`]).
    Plain,
    /// With its texture ([`spot::textured`]), sampled bilinearly without levels of detail, covering about half of
    /// the display (field of view [`TEXTURED_FOVY`]).
    Textured,
}

/// What a frame shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// The model's rotation about the vertical axis, in radians.
    pub yaw: f32,
    /// Plain or textured.
    pub look: Look,
}

/// Each frame's view: two plain ones, then a textured one; those of the looks the crate's features keep (both by
/// default: a firmware built with one alone links that look's pipeline alone, whose code `firmware/measure.sh`
/// reports).
pub const VIEWS: &[View] = &[
    #[cfg(feature = "plain")]
    View { yaw: 2.3, look: Look::Plain },
    #[cfg(feature = "plain")]
    View { yaw: 3.9, look: Look::Plain },
    #[cfg(feature = "textured")]
    View { yaw: 2.3, look: Look::Textured },
];
/// Number of frames: one per entry of [`VIEWS`].
pub const FRAMES: usize = VIEWS.len();

/// Background colour.
pub const BACKGROUND: Vec3 = Vec3::new(0.08, 0.1, 0.16);
/// Point of the model that is turned about and looked at: the middle of Spot's bounding box, rounded.
const MODEL_CENTRE: Vec3 = Vec3::new(0.0, 0.11, 0.19);
/// Camera position.
const EYE: Vec3 = Vec3::new(0.0, 0.5, 2.9);
/// Vertical field of view of [`Look::Plain`], radians.
pub const PLAIN_FOVY: f32 = 0.7;
/// Vertical field of view of [`Look::Textured`], radians: Spot about 1.4 times as wide and high as with
/// [`PLAIN_FOVY`] (`tan(0.35) / tan(0.25)`), about twice the pixels (48 % of the display), its horns and hooves
/// cut by the display's edges.
pub const TEXTURED_FOVY: f32 = 0.5;
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

/// The slots the plain look's variant carries: the normal and the world position (for the highlight), nothing
/// else.
const PLAIN_LAYOUT: Layout = Layout { first: true, second: true, uvs: false, tangents: false, colors: false };
/// The slots the textured look's variant carries: those of [`PLAIN_LAYOUT`] and the texture coordinates.
const TEXTURED_LAYOUT: Layout = Layout { uvs: true, ..PLAIN_LAYOUT };

/// A shader the firmware links: per-pixel lighting from directional lights, the normal and the world position
/// carried, and the texture coordinates when `U` is [`Vec2`].
type SpotShader<'a, U> = SurfaceShader<'a, Vec3, Vec3, U, Absent, Absent, { capabilities::PER_PIXEL }>;
/// The shader of [`Look::Plain`].
pub type PlainShader<'a> = SpotShader<'a, Absent>;
/// The shader of [`Look::Textured`].
pub type TexturedShader<'a> = SpotShader<'a, Vec2>;

/// One frame's scene: Spot, its place and the light, built once and drawn into each band.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    object: Object<'static>,
    lights: [Light<'static>; 1],
    look: Look,
}

impl Scene {
    /// The scene of frame `frame`: Spot lit per pixel with a highlight, as [`VIEWS`]`[frame]` says.
    ///
    /// # Panics
    /// If `frame >= FRAMES`.
    ///
    /// # Errors
    /// [`SceneError::Mesh`] if the model arrays do not make a mesh, [`SceneError::Texture`] if the texture's do not
    /// make a texture, [`SceneError::Camera`] if the camera constants do not make a camera (none happens).
    pub fn new(frame: usize) -> Result<Self, SceneError> {
        let View { yaw, look } = VIEWS[frame];
        let (mesh, material, fovy) = match look {
            Look::Plain => (spot_mesh()?, spot_material(Vec3::new(0.85, 0.78, 0.7)), PLAIN_FOVY),
            Look::Textured => {
                let size = spot::textured::TEXTURE_SIZE;
                let texture = Texture::new(&spot::textured::TEXELS, size, size).map_err(SceneError::Texture)?;
                let material = Material {
                    diffuse: Some(texture),
                    filter: FilterMode::Bilinear,
                    wrap: WrapMode::Repeat,
                    mip_filter: MipFilter::Off,
                    ..spot_material(Vec3::ONE)
                };
                (textured_spot_mesh()?, material, TEXTURED_FOVY)
            }
        };
        Ok(Self {
            object: Object {
                mesh,
                tangents: None,
                transforms: transforms(yaw, fovy)?,
                shading: ShadingModel::Phong,
                material,
            },
            lights: [Light::directional(TO_LIGHT, LIGHT_COLOR)],
            look,
        })
    }

    /// The scene's lights.
    fn lights(&self) -> Lighting<'_> {
        Lighting { ambient: AMBIENT, lights: &self.lights, environment: None, space: SPACE }
    }

    /// Clears `target` to [`BACKGROUND`] and draws Spot: into a band, or a whole frame (the same pixels).
    ///
    /// Runs the look's shader ([`PlainShader`] or [`TexturedShader`]) through [`draw`]: the pixels of
    /// [`draw_mesh`], without linking its other variants (see the module docs).
    ///
    /// # Errors
    /// [`SceneError::Draw`] if the draw fails, [`SceneError::Variant`] if the scene resolves to another variant
    /// than the look's shader draws (neither happens).
    pub fn draw<C: ColorBuffer, D: DepthBuffer>(&self, target: &mut Target<C, D>) -> Result<DrawStats, SceneError> {
        target.clear(BACKGROUND);
        self.draw_spot(target)
    }

    /// Bins Spot's triangles by the bands of `bands` into `memory`, once for the frame: what
    /// [`Scene::draw_band`] reads.
    ///
    /// # Errors
    /// As [`Scene::draw`].
    pub fn bin<'m>(&self, memory: &'m mut [BinnedTriangle], bands: Bands) -> Result<BandBins<'m>, SceneError> {
        let (mesh, matrix) = (&self.object.mesh, &self.object.transforms.clip_from_object);
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
        target.clear(BACKGROUND);
        let mut target = target.for_draw(FrameGeometry { vertices: None, bins: core::slice::from_ref(bins) });
        self.draw_spot(&mut target)
    }

    /// Draws Spot into `target` with the shader of its look.
    fn draw_spot<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
        &self,
        target: &mut Target<C, D, M>,
    ) -> Result<DrawStats, SceneError> {
        let mesh = &self.object.mesh;
        // A look the features leave out is not compiled: no view has it.
        match self.look {
            Look::Plain if cfg!(feature = "plain") => draw(target, mesh, &self.shader::<Absent>(PLAIN_LAYOUT)?, &STATE),
            Look::Textured if cfg!(feature = "textured") => {
                draw(target, mesh, &self.shader::<Vec2>(TEXTURED_LAYOUT)?, &STATE)
            }
            _ => return Err(SceneError::Variant),
        }
        .map_err(SceneError::Draw)
    }

    /// The shader the scene's variant calls for, if its slots are `layout`.
    fn shader<U: Slot<Vec2>>(&self, layout: Layout) -> Result<SpotShader<'_, U>, SceneError> {
        let variant = Variant::resolve(&self.object, self.lights.iter().map(LightUse::from), SPACE, &STATE)
            .map_err(draw_error)?;
        if variant.layout() != layout || variant.state != STATE {
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

/// Spot's material: `color`, with a highlight.
fn spot_material(color: Vec3) -> Material<'static> {
    Material { specular: Vec3::splat(0.35), shininess: 24.0, ..Material::plain(color) }
}

/// Spot as a mesh over the generated arrays.
fn spot_mesh() -> Result<Mesh<'static>, SceneError> {
    Mesh::new(&spot::POSITIONS, Indices::U16(&spot::INDICES))
        .and_then(|mesh| mesh.with_normals(&spot::NORMALS))
        .map_err(SceneError::Mesh)
}

/// Spot with texture coordinates, over the generated arrays.
fn textured_spot_mesh() -> Result<Mesh<'static>, SceneError> {
    use spot::textured::{INDICES, NORMALS, POSITIONS, UVS};
    Mesh::new(&POSITIONS, Indices::U16(&INDICES))
        .and_then(|mesh| mesh.with_normals(&NORMALS))
        .and_then(|mesh| mesh.with_uvs(&UVS))
        .map_err(SceneError::Mesh)
}

/// Spot turned by `yaw` radians about the vertical axis through [`MODEL_CENTRE`], seen from [`EYE`], slightly
/// above, with a vertical field of view of `fovy` radians.
fn transforms(yaw: f32, fovy: f32) -> Result<Transforms, SceneError> {
    let turn = Quat::from_axis_angle(Vec3::Y, yaw).to_mat4();
    let model = turn * Mat4::from_translation(Vec3::new(-MODEL_CENTRE.x, -MODEL_CENTRE.y, -MODEL_CENTRE.z));
    let view = look_at(EYE, Vec3::ZERO, Vec3::Y).map_err(SceneError::Camera)?;
    // WIDTH / HEIGHT, divided at compile time: the same f32 on every machine.
    const ASPECT: f32 = WIDTH as f32 / HEIGHT as f32;
    let projection = perspective(fovy, ASPECT, NEAR, FAR).map_err(SceneError::Camera)?;
    Ok(Transforms::new(model, view, projection))
}
