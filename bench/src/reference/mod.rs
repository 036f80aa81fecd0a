//! A slow, high-precision reference renderer: the "truth" that rastty's pictures are measured against.
//!
//! Everything is `f64`: transforms, projection, visibility, interpolation, shading and texture sampling. Each
//! pixel is sampled on a regular [`SAMPLES_PER_AXIS`]² grid (sample `(k, l)` of pixel `(i, j)` at
//! `(i + (k + 0.5) / 16, j + (l + 0.5) / 16)` in screen space); every sample is shaded, clamped to `[0, 1]`, and
//! the samples are averaged with equal weights (a box filter). Samples that hit nothing take the background colour.
//! In linear light ([`ReferenceScene::space`], the default) the samples are light, the texels and the background decoded
//! from sRGB ([`srgb`]), and each pixel's average is encoded back; on the stored values nothing is converted.
//!
//! # How a sample is decided
//!
//! A sample is a ray from the eye (perspective) or along the view direction (orthographic) through the sample
//! point, cast against every triangle that might cover it (triangles are binned into 8x8-pixel tiles first):
//!
//! - **Coverage**: the three edge functions of the triangle's view-space vertices, evaluated for the ray: for a
//!   perspective ray `d`, `E_i = d . (v_j x v_k)`, the 2D homogeneous edge functions of Olano and Greer ("Triangle
//!   scan conversion using 2D homogeneous coordinates", Graphics Hardware 1997), which need no clipping; the hit's
//!   barycentric coordinates are `E_i / sum E`. A triangle is closed: a sample exactly on an edge is covered. Two
//!   triangles sharing an edge get exactly opposite edge functions (same operations, negated operands), so no
//!   sample falls through a shared edge. The decision is made in `f64` arithmetic on the `f64`-transformed
//!   vertices: exact up to rounding of the order of 1e-16 relative, not in exact rational arithmetic.
//! - **Depth**: the ray-plane intersection; the sample is visible on the triangle only when the hit's view depth
//!   (distance along the view axis) is within `[near, far]`. A triangle crossing the near plane (or passing
//!   behind the eye) is therefore cut exactly at the plane, with no clipping polygon involved.
//! - **Order**: the nearest hit wins; on an exact depth tie the triangle drawn first (the earlier object, then the
//!   earlier triangle) wins, as rastty's `less` depth test does.
//! - **Facing**: counter-clockwise on screen is the front, flipped for a mirroring model matrix, and
//!   [`ReferenceObject::cull`] discards faces as rastty's [`Cull`] does. Edge-on triangles cover nothing.
//! - **Attributes**: the barycentric coordinates of the 3D hit point, which makes interpolation
//!   perspective-correct by construction.
//!
//! # Shading
//!
//! The albedo is [`ReferenceMaterial::color`] times the bilinearly sampled texture ([`sample_bilinear`], in the scene's
//! space) when the object has one and has texture coordinates. [`Shading::Unlit`] draws the albedo; [`Shading::Lit`] is rastty's
//! per-pixel Blinn-Phong (`ShadingModel::Phong` of [`rastty_core::draw_mesh`]) in `f64`, with the interpolated vertex normal
//! renormalised:
//! `albedo * (ambient + sum c s max(0, n.l)) + specular * sum over lights with n.l > 0 of c s max(0, n.h)^shininess`,
//! `h = normalize(l + v)`, `v = normalize(eye - p)`, `l` toward the light and `s` the share of it arriving (1 for a
//! directional light; the fall-off and cone of a point or spot light, [`ReferenceLight::toward`]).
//! [`Shading::MetallicRoughness`] is glTF's BRDF (single scattering, as rastty's `shading::brdf`) with Kulla and
//! Conty's multiple-scattering lobe, lit by the lights, the ambient light and the scene's
//! [`ReferenceEnvironment`], whose light is integrated over the BRDF by [`ENVIRONMENT_SAMPLES`] directions per
//! sample drawn from the GGX lobe, the cosine lobe and the environment's brightness (multiple importance
//! sampling): no spherical harmonics, prefiltering or table.
//!
//! # Use
//!
//! Build a [`ReferenceScene`] by hand, or from a rastty scene, camera and plan options with [`ReferenceScene::from_scene`] (the
//! same picture as rastty's scene renderer, [`rastty_scene::scene_render::SceneRenderer`], draws: a model shown without
//! a scene file is a scene too, [`rastty_scene::scene_file::SceneData::from_model`]), then call [`render`] for a
//! [`ReferenceImage`], or make a [`Renderer`] to render and also [`Renderer::probe`] single points.
//!
//! ```
//! use rastty_bench::reference::{Camera, ReferenceObject, ReferenceProjection, ReferenceScene, Shading, render};
//!
//! // An orthographic camera whose view box is the 4x4 image itself (view y = -screen y), and a triangle whose
//! // right edge is the line x = 2.
//! let camera = Camera {
//!     eye: [0.0, 0.0, 1.0],
//!     target: [0.0, 0.0, 0.0],
//!     up: [0.0, 1.0, 0.0],
//!     projection: ReferenceProjection::Orthographic { left: 0.0, right: 4.0, bottom: -4.0, top: 0.0, near: 0.0, far: 2.0 },
//! };
//! let mut triangle = ReferenceObject::new(vec![[2.0, -20.0, 0.0], [2.0, 10.0, 0.0], [-20.0, -2.0, 0.0]], vec![0, 1, 2]);
//! triangle.material.color = [1.0, 0.0, 0.0];
//! triangle.shading = Shading::Unlit;
//! let scene = ReferenceScene { objects: vec![triangle], ..ReferenceScene::new(4, 4, camera) };
//! let image = render(&scene).unwrap();
//! assert_eq!(image.rgb[1], [1.0, 0.0, 0.0]); // pixel (1, 0): inside
//! assert_eq!(image.coverage[1], 1.0);
//! assert_eq!(image.rgb[3], [0.0, 0.0, 0.0]); // pixel (3, 0): outside, the background
//! assert_eq!(image.coverage[3], 0.0);
//! ```

mod from_scene;
mod image;
pub mod math;
mod metallic_roughness;
mod render;
pub mod srgb;
mod texture;

use std::fmt;

use rastty_core::camera::CameraError;
use rastty_core::color::ShadingSpace;
use rastty_core::pipeline::Cull;
use rastty_core::texture::WrapMode;

pub use image::ReferenceImage;
pub use metallic_roughness::ReferenceEnvironment;
pub use render::{Probe, Renderer, SAMPLES_PER_AXIS, render};
pub use texture::sample_bilinear;

use math::DMat4;
use rastty_scene::model::TextureImage;
use rastty_scene::scene_render::SceneRenderError;

/// Everything the reference renderer draws: image size, camera, lights, background and objects.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceScene {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The camera.
    pub camera: Camera,
    /// The lights (used by [`Shading::Lit`] objects).
    pub lighting: ReferenceLighting,
    /// The colour of samples that hit nothing, channels in `[0, 1]`, as stored (sRGB-encoded).
    pub background: [f64; 3],
    /// The objects, in drawing order (which only matters for exact depth ties).
    pub objects: Vec<ReferenceObject>,
    /// The light from every direction that [`Shading::MetallicRoughness`] objects reflect, if any.
    pub environment: Option<ReferenceEnvironment>,
    /// How the truth is lit, as rastty's [`ShadingSpace`]: in linear light (texels decoded before filtering,
    /// light added up, the samples' light averaged and encoded) or on the stored values.
    pub space: ShadingSpace,
}

impl ReferenceScene {
    /// An empty `width x height` scene seen by `camera`: black background, no lights, no objects, linear light.
    pub fn new(width: u32, height: u32, camera: Camera) -> Self {
        Self {
            width,
            height,
            camera,
            lighting: ReferenceLighting::default(),
            background: [0.0; 3],
            objects: Vec::new(),
            environment: None,
            space: ShadingSpace::Linear,
        }
    }
}

/// A camera: where it is, where it looks, and how it projects.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The camera position in world space (also the eye of specular highlights, for either projection).
    pub eye: [f64; 3],
    /// The point looked at.
    pub target: [f64; 3],
    /// Roughly up on screen; replaced as [`rastty_core::camera::look_at`] does when parallel to the view.
    pub up: [f64; 3],
    /// The projection.
    pub projection: ReferenceProjection,
}

/// How the camera projects (the same parameters as [`rastty_core::camera::Projection`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReferenceProjection {
    /// Perspective.
    Perspective {
        /// Vertical field of view in radians, in `(0, pi)`.
        fovy: f64,
        /// Width over height of the view (the image's physical aspect).
        aspect: f64,
        /// View depth of the near plane, `> 0`.
        near: f64,
        /// View depth of the far plane, `> near`.
        far: f64,
    },
    /// Orthographic: the view-space box `[left, right] x [bottom, top]` fills the image.
    Orthographic {
        /// Left edge of the box in view space.
        left: f64,
        /// Right edge.
        right: f64,
        /// Bottom edge.
        bottom: f64,
        /// Top edge.
        top: f64,
        /// View depth of the near plane.
        near: f64,
        /// View depth of the far plane, `> near`.
        far: f64,
    },
}

impl ReferenceProjection {
    /// The near and far view depths.
    pub fn depth_range(&self) -> (f64, f64) {
        match *self {
            Self::Perspective { near, far, .. } | Self::Orthographic { near, far, .. } => (near, far),
        }
    }
}

/// The lights of a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReferenceLighting {
    /// ReferenceLight reaching every surface from every direction.
    pub ambient: [f64; 3],
    /// The lights: directional, point and spot.
    pub lights: Vec<ReferenceLight>,
}

/// A light: directional, or at a place (a point or spot light).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceLight {
    /// Unit vector from the surface toward a directional light, in world space (used as given); not read for a
    /// light with a [`Self::place`].
    pub to_light: [f64; 3],
    /// Colour and intensity.
    pub color: [f64; 3],
    /// Where a point or spot light is and how its light weakens; `None` for a directional light.
    pub place: Option<ReferencePlace>,
}

/// Where a point or spot light is, and how its light weakens: the core's `LightKind::toward` in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferencePlace {
    /// The light's position in world space.
    pub position: [f64; 3],
    /// `Some(range)` for the inverse square of the distance `d`, windowed by `clamp(1 - (d / range)^4, 0, 1)`
    /// (`Some(None)`: no range); `None` for no fall-off.
    pub inverse_square: Option<Option<f64>>,
    /// A spot's cone: its unit axis (the way it shines) and its inner and outer angles in radians; the share
    /// `clamp((cos a - cos outer) / max(cos inner - cos outer, 0.001), 0, 1)²` at angle `a` from the axis.
    pub cone: Option<([f64; 3], f64, f64)>,
}

impl ReferenceLight {
    /// A light shining from `to_light`, normalised here (a zero vector gives a light that adds nothing).
    pub fn directional(to_light: [f64; 3], color: [f64; 3]) -> Self {
        Self { to_light: math::V3::from_array(to_light).normalize_or_zero().to_array(), color, place: None }
    }

    /// The unit direction from `point` toward the light and the share of its colour that arrives there.
    pub fn toward(&self, point: [f64; 3]) -> ([f64; 3], f64) {
        let Some(place) = &self.place else { return (self.to_light, 1.0) };
        let d = math::V3::from_array(place.position) - math::V3::from_array(point);
        let squared = d.dot(d);
        let l = d.normalize_or_zero();
        let mut share = 1.0;
        if let Some(range) = place.inverse_square {
            let ratio = range.map_or(0.0, |r| squared / (r * r));
            share *= (1.0 - ratio * ratio).clamp(0.0, 1.0) / squared.max(f64::MIN_POSITIVE);
        }
        if let Some((axis, inner, outer)) = place.cone {
            let cos = -math::V3::from_array(axis).dot(l);
            let t = ((cos - outer.cos()) / (inner.cos() - outer.cos()).max(0.001)).clamp(0.0, 1.0);
            share *= t * t;
        }
        (l.to_array(), share)
    }
}

/// How a surface reflects light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceMaterial {
    /// Base (diffuse) colour; multiplied by the texture when there is one.
    pub color: [f64; 3],
    /// Specular colour; zero for no highlights.
    pub specular: [f64; 3],
    /// Blinn-Phong exponent.
    pub shininess: f64,
    /// How much of a metal the surface is, 0 to 1 ([`Shading::MetallicRoughness`] only).
    pub metallic: f64,
    /// Perceptual roughness, 0 to 1 ([`Shading::MetallicRoughness`] only).
    pub roughness: f64,
}

impl Default for ReferenceMaterial {
    /// The core's default material: grey 0.8, no highlights, shininess 32; a dielectric of roughness 1.
    fn default() -> Self {
        Self { color: [0.8; 3], specular: [0.0; 3], shininess: 32.0, metallic: 0.0, roughness: 1.0 }
    }
}

/// What the truth of an object's colour is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Shading {
    /// The albedo (material colour times texture), no lighting.
    Unlit,
    /// Per-pixel Blinn-Phong with the interpolated, renormalised vertex normal (the geometric face normal when
    /// the object has no normals).
    #[default]
    Lit,
    /// glTF's metallic-roughness BRDF with a multiple-scattering lobe, lit by the lights (the BRDF times pi, as
    /// rastty's), the ambient light (times the diffuse colour) and the environment, integrated by
    /// [`ENVIRONMENT_SAMPLES`] directions per sample (see `metallic_roughness.rs`).
    MetallicRoughness,
}

/// Directions of the environment integrated per sample of a [`Shading::MetallicRoughness`] surface: with the
/// 256 samples of a pixel, 16,384 a pixel. On the accuracy report's spheres (320x240) 16 a sample left noise that
/// cost the comparison 0.6 dB of PSNR inside the spheres; 64 take 70 s on 2 cores.
pub const ENVIRONMENT_SAMPLES: u32 = 64;

/// A triangle mesh with its transform, material and texture.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceObject {
    /// Vertex positions in object space.
    pub positions: Vec<[f64; 3]>,
    /// Vertex normals in object space, one per position (need not be unit length), or `None`.
    pub normals: Option<Vec<[f64; 3]>>,
    /// Texture coordinates (`v` up), one per position, or `None`.
    pub uvs: Option<Vec<[f64; 2]>>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
    /// ReferenceObject space to world space: column-major (`model[c][r]`), acting on column vectors; must be affine.
    pub model: DMat4,
    /// The material.
    pub material: ReferenceMaterial,
    /// The diffuse texture (used only with [`Self::uvs`]): `0x00RRGGBB` texels, row 0 at the top.
    pub texture: Option<TextureImage>,
    /// How texture coordinates outside `[0, 1]` wrap.
    pub wrap: WrapMode,
    /// How the object is shaded.
    pub shading: Shading,
    /// Which faces are discarded (front faces are counter-clockwise on screen).
    pub cull: Cull,
}

impl ReferenceObject {
    /// An object of the given triangles: identity transform, default material, no normals, texture coordinates
    /// or texture, repeat wrap, lit, back faces culled (rastty's defaults).
    pub fn new(positions: Vec<[f64; 3]>, indices: Vec<u32>) -> Self {
        Self {
            positions,
            normals: None,
            uvs: None,
            indices,
            model: math::IDENTITY,
            material: ReferenceMaterial::default(),
            texture: None,
            wrap: WrapMode::Repeat,
            shading: Shading::Lit,
            cull: Cull::Back,
        }
    }
}

/// Why a scene cannot be rendered.
#[derive(Clone, Debug, PartialEq)]
pub enum ReferenceError {
    /// The image is empty or larger than [`rastty_core::target::MAX_DIMENSION`] on a side.
    Size {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// The camera does not make a camera.
    Camera(CameraError),
    /// An object is inconsistent.
    Object {
        /// Index into [`ReferenceScene::objects`].
        object: usize,
        /// What is wrong.
        reason: String,
    },
    /// [`ReferenceScene::from_scene`] was asked for something the reference does not draw.
    Unsupported(&'static str),
    /// rastty refuses to plan the frame [`ReferenceScene::from_scene`] was asked for (other than for its camera).
    Plan(SceneRenderError),
}

impl fmt::Display for ReferenceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Size { width, height } => write!(f, "cannot render a {width}x{height} reference image"),
            Self::Camera(e) => write!(f, "bad camera: {e}"),
            Self::Object { object, reason } => write!(f, "object {object}: {reason}"),
            Self::Unsupported(what) => write!(f, "the reference renderer does not draw {what}"),
            Self::Plan(e) => write!(f, "rastty cannot plan the frame: {e}"),
        }
    }
}

impl std::error::Error for ReferenceError {}
