//! A loaded scene: owned camera, lights and objects, with meshes and images loaded and shared.

use std::path::PathBuf;
use std::sync::Arc;

use rastty_core::camera::{CameraError, look_at};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::shading::Falloff;
use rastty_core::texture::{FilterMode, MipFilter, WrapMode};

use super::schema::{LightSpace, NormalSpaceSpec};
use crate::environment::EnvironmentLight;
use crate::model::{self, Model, TextureImage};

/// Everything a scene file describes, loaded and checked, ready for a renderer.
#[derive(Clone, Debug)]
pub struct SceneData {
    /// The camera: placed by the file, or framed around the scene.
    pub camera: CameraPlacement,
    /// The lights, in file order (possibly none).
    pub lights: Vec<SceneLight>,
    /// The object whose model's own lights are [`Self::lights`] (a glTF model with lights, shown alone), placed
    /// again from it when it is posed ([`SceneObject::own_lights`]); `None` when the lights are the file's or the
    /// viewer's.
    pub lights_of: Option<usize>,
    /// The objects, in file order (at least one).
    pub objects: Vec<SceneObject>,
    /// The background colour (the file's, or [`super::defaults::BACKGROUND`]).
    pub background: Vec3,
    /// The ambient light (the file's, or [`super::defaults::AMBIENT`]).
    pub ambient: Vec3,
    /// Whether ambient occlusion is wanted.
    pub ambient_occlusion: bool,
    /// The light from every direction that metallic-roughness surfaces reflect (the file's `environment`, or
    /// the studio for a scene with a physically based material), made ready.
    pub environment: Option<Arc<EnvironmentLight>>,
    /// How surfaces are lit: in linear light, or on the stored sRGB values (the file's `linear_light`). The
    /// colours here (background, ambient, lights, materials) are as written, sRGB-encoded; the plan decodes them
    /// for linear light.
    pub space: ShadingSpace,
    /// Every image file loaded, each once, in the order first referenced, with its path as resolved at that first
    /// reference. Objects hold the same [`Arc`]s.
    pub images: Vec<(PathBuf, Arc<TextureImage>)>,
    /// Non-fatal problems of the scene (an image on a mesh without texture coordinates), one line each, in the
    /// form of [`super::SceneFileError`]'s and with control characters escaped. The meshes' own warnings stay in
    /// each [`Model::warnings`].
    pub warnings: Vec<String>,
}

/// Where a scene's camera is: placed at a point, or framed around the scene (resolved once its bounds are known:
/// [`crate::scene_render::PreparedScene::camera`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraPlacement {
    /// At a position, looking at a target.
    Placed(SceneCamera),
    /// Around the scene's bounding sphere.
    Framed(FramedCamera),
}

/// A camera looking at the centre of the scene's bounding sphere from outside it, every length in radii of the
/// sphere: the viewer's camera for a model, and a scene file's `[camera]` without `position` and `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FramedCamera {
    /// The scene turned about the vertical axis, in degrees: positive turns its front to the right (the eye goes
    /// round to the left).
    pub yaw_degrees: f32,
    /// The eye's elevation above the horizontal plane through the centre, in degrees.
    pub pitch_degrees: f32,
    /// The eye's distance from the centre, in radii.
    pub distance: f32,
    /// The lens (an orthographic height in radii).
    pub projection: SceneProjection,
    /// The near plane's distance in radii, if given.
    pub near: Option<f32>,
    /// The far plane's distance in radii, if given.
    pub far: Option<f32>,
}

impl FramedCamera {
    /// The viewer's camera: yaw 30, pitch 15, 2.8 radii away, a 40 degree perspective lens, planes around the
    /// scene.
    pub const DEFAULT: Self = Self {
        yaw_degrees: 30.0,
        pitch_degrees: 15.0,
        distance: 2.8,
        projection: SceneProjection::Perspective { fov_degrees: 40.0 },
        near: None,
        far: None,
    };
}

impl Default for FramedCamera {
    /// [`Self::DEFAULT`].
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// A camera at a point: a scene file's placed camera, or a framed or orbited one resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneCamera {
    /// The eye.
    pub position: Vec3,
    /// The point looked at (differs from `position`).
    pub target: Vec3,
    /// Which way is up in the image, unit length.
    pub up: Vec3,
    /// The lens.
    pub projection: SceneProjection,
    /// The near plane's distance, when the file gives one (positive).
    pub near: Option<f32>,
    /// The far plane's distance, when the file gives one (positive, beyond `near` when both are given).
    pub far: Option<f32>,
}

impl SceneCamera {
    /// The view matrix (world to view space).
    ///
    /// # Errors
    /// Never for a camera from a scene file, whose values are checked; [`CameraError`] for one changed by hand to
    /// have the eye at the target or a non-finite value.
    pub fn view(&self) -> Result<Mat4, CameraError> {
        look_at(self.position, self.target, self.up)
    }
}

/// A camera's lens.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneProjection {
    /// Perspective.
    Perspective {
        /// The field of view across the frame's shorter side in degrees, strictly between 0 and 180.
        fov_degrees: f32,
    },
    /// Orthographic (parallel rays).
    Orthographic {
        /// How much of the world the view shows across the frame's shorter side, in world units (positive).
        height: f32,
    },
}

/// A light of a scene file.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneLight {
    /// Where the light comes from.
    pub kind: SceneLightKind,
    /// Its colour (components not negative), not yet multiplied by `intensity`.
    pub color: Vec3,
    /// Multiplies `color` (not negative).
    pub intensity: f32,
    /// Whether it casts shadows.
    pub shadows: bool,
    /// Whether its direction or position is in world or camera coordinates.
    pub space: LightSpace,
}

/// The kind of a light and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneLightKind {
    /// Parallel rays.
    Directional {
        /// The unit direction the light travels, from the light toward the scene (the opposite of the core's
        /// `to_light`).
        direction: Vec3,
    },
    /// Rays from one point in every direction.
    Point {
        /// Where the light is.
        position: Vec3,
        /// How its light weakens with distance.
        falloff: LightFalloff,
    },
    /// Rays from one point within a cone.
    Spot {
        /// Where the light is.
        position: Vec3,
        /// The unit direction of the cone's axis, the way the light shines.
        direction: Vec3,
        /// The angle from the axis within which the light is full, in radians (from 0, below `outer`).
        inner: f32,
        /// The angle from the axis beyond which there is no light, in radians (at most pi / 2).
        outer: f32,
        /// How its light weakens with distance.
        falloff: LightFalloff,
    },
}

/// How the light of a point or spot light weakens with distance (the core's `Falloff`, with the range as given).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightFalloff {
    /// Not at all: the light's colour times its intensity reaches every distance.
    None,
    /// As the inverse square of the distance, ended smoothly at the range when there is one: the colour times the
    /// intensity is what a surface facing the light receives at distance 1.
    InverseSquare {
        /// Where the light ends (positive), or `None` for nowhere.
        range: Option<f32>,
    },
}

impl LightFalloff {
    /// The core's fall-off.
    pub fn core(self) -> Falloff {
        match self {
            Self::None => Falloff::None,
            Self::InverseSquare { range } => Falloff::inverse_square(range),
        }
    }
}

/// An object of a scene file: a mesh, where it is, and how it looks.
#[derive(Clone, Debug)]
pub struct SceneObject {
    /// The mesh file as resolved against the scene file's directory, or `builtin:spot`. Raw: sanitise before
    /// printing.
    pub mesh_path: PathBuf,
    /// The mesh in its own coordinates (not fitted), with its MTL materials. Objects naming the same file share
    /// it.
    pub model: Arc<Model>,
    /// Object to world (see [`super::object_transform`]).
    pub transform: Mat4,
    /// The material keys of the scene file, over the model's own materials.
    pub material: ObjectMaterial,
    /// The animation of its own it plays, whatever is chosen for the others (`animation`, `time`).
    pub animation: Option<ObjectAnimation>,
}

impl SceneObject {
    /// Its model's own lights ([`Model::lights`]) in the world, placed by its transform
    /// ([`crate::model::ModelLight::scene_light`]); those the transform leaves no place or direction are left out.
    pub fn own_lights(&self) -> Vec<SceneLight> {
        self.model.lights.iter().filter_map(|light| light.scene_light(&self.transform)).collect()
    }

    /// Whether part `part` is physically based: its material gives a metallic factor or a roughness, the scene's
    /// keys or its model's own (every glTF material does). Such a part is drawn with the metallic-roughness model
    /// unless a front end asks for another ([`crate::scene_render::ShadingMode::Material`]).
    pub fn physically_based(&self, part: usize) -> bool {
        let mtl = self.model.part_material(part);
        self.material.metallic_over(mtl).is_some() || self.material.roughness_over(mtl).is_some()
    }
}

impl SceneData {
    /// Whether any part of any object is physically based ([`SceneObject::physically_based`]): such a scene gets
    /// the studio environment unless it names another.
    pub fn physically_based(&self) -> bool {
        self.objects.iter().any(|o| (0..o.model.parts.len()).any(|part| o.physically_based(part)))
    }
}

/// An object's own animation ([`SceneObject::animation`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectAnimation {
    /// Its number in the object's model ([`crate::model::Rig::animations`]).
    pub index: usize,
    /// Where it stands when the scene's clock reads 0, in seconds.
    pub start: f32,
}

/// The `[objects.material]` keys of an object, with their images loaded. `None` means the key was left out.
///
/// Each key given overrides the model's own materials (an OBJ file's MTL entries, a glTF file's materials) for
/// every part; a key left out keeps the part's own value when its material has one ([`Self::color_over`],
/// [`Self::diffuse_over`], [`Self::normal_over`], [`Self::glow_over`], [`Self::specular_over`],
/// [`Self::shininess_over`], [`Self::metallic_over`] and [`Self::roughness_over`] say which wins), else the
/// renderer's default.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ObjectMaterial {
    /// The diffuse colour (components from 0 to 1).
    pub color: Option<Vec3>,
    /// The diffuse texture.
    pub diffuse: Option<Arc<TextureImage>>,
    /// The normal map and how to read it.
    pub normal_map: Option<ObjectNormalMap>,
    /// The specular colour (components from 0 to 1).
    pub specular: Option<Vec3>,
    /// The Blinn-Phong exponent (positive).
    pub shininess: Option<f32>,
    /// The metallic factor (0 to 1).
    pub metallic: Option<f32>,
    /// The roughness (0 to 1).
    pub roughness: Option<f32>,
    /// The specular map, as decoded (a grey image has its level in all three channels).
    pub specular_map: Option<Arc<TextureImage>>,
    /// The glow (emission) map, as decoded.
    pub glow_map: Option<Arc<TextureImage>>,
    /// How the images are sampled.
    pub filter: FilterMode,
    /// What coordinates outside `[0, 1]` read.
    pub wrap: WrapMode,
    /// How the images' levels of detail are read.
    pub mip_filter: MipFilter,
}

impl ObjectMaterial {
    /// Whether the images are read through their levels of detail (which are then built for them).
    pub(crate) fn reads_mip_levels(&self) -> bool {
        self.mip_filter != MipFilter::Off
    }

    /// The diffuse colour of a part whose MTL material is `mtl` (`None` for a part without one): the scene's
    /// `color` if given, else the MTL's `Kd`, else [`model::DEFAULT_DIFFUSE`].
    pub fn color_over(&self, mtl: Option<&model::ModelMaterial>) -> Vec3 {
        self.color.or(mtl.map(|m| m.diffuse)).unwrap_or(model::DEFAULT_DIFFUSE)
    }

    /// The diffuse texture of a part whose MTL material is `mtl`: the scene's `diffuse` if given, else the MTL's
    /// `map_Kd` (when it loaded), else none.
    pub fn diffuse_over<'a>(&'a self, mtl: Option<&'a model::ModelMaterial>) -> Option<&'a TextureImage> {
        self.diffuse.as_deref().or(mtl.and_then(|m| m.texture.as_ref()))
    }

    /// The normal map of a part whose material is `mtl`: the scene's `normal_map` if given, else the model's own
    /// (tangent space), else none.
    pub fn normal_over<'a>(
        &'a self,
        mtl: Option<&'a model::ModelMaterial>,
    ) -> Option<(&'a TextureImage, NormalSpaceSpec)> {
        match &self.normal_map {
            Some(map) => Some((&map.image, map.space)),
            None => mtl.and_then(|m| m.normal_map.as_ref()).map(|image| (image, NormalSpaceSpec::Tangent)),
        }
    }

    /// The glow map of a part whose material is `mtl`: the scene's `glow_map` if given, else the model's own
    /// (glTF emission), else none.
    pub fn glow_over<'a>(&'a self, mtl: Option<&'a model::ModelMaterial>) -> Option<&'a TextureImage> {
        self.glow_map.as_deref().or(mtl.and_then(|m| m.glow_map.as_ref()))
    }

    /// The specular colour of a part whose material is `mtl`: the scene's, else the model's own, else `None` (the
    /// renderer's default).
    pub fn specular_over(&self, mtl: Option<&model::ModelMaterial>) -> Option<Vec3> {
        self.specular.or(mtl.and_then(|m| m.specular))
    }

    /// The Blinn-Phong exponent of a part whose material is `mtl`: the scene's, else the model's own, else `None`
    /// (the renderer's default).
    pub fn shininess_over(&self, mtl: Option<&model::ModelMaterial>) -> Option<f32> {
        self.shininess.or(mtl.and_then(|m| m.shininess))
    }

    /// The metallic factor of a part whose material is `mtl`: the scene's, else the model's own (glTF), else
    /// `None` (the renderer's default).
    pub fn metallic_over(&self, mtl: Option<&model::ModelMaterial>) -> Option<f32> {
        self.metallic.or(mtl.and_then(|m| m.metallic))
    }

    /// The roughness of a part whose material is `mtl`: the scene's, else the model's own (glTF), else `None` (the
    /// renderer's default).
    pub fn roughness_over(&self, mtl: Option<&model::ModelMaterial>) -> Option<f32> {
        self.roughness.or(mtl.and_then(|m| m.roughness))
    }
}

/// A normal map with the space its texels are in.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectNormalMap {
    /// The image, as RGB (`rgb = normal * 0.5 + 0.5`).
    pub image: Arc<TextureImage>,
    /// Tangent or object space.
    pub space: NormalSpaceSpec,
}
