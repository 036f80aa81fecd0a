//! The scene file's schema: the TOML tables and keys, as `serde` types.
//!
//! Every table refuses keys it does not know (`deny_unknown_fields`), so a misspelt key is an error, not a silent
//! default. Values that [`super::parse`] checks beyond their type keep their place in the file ([`Spanned`]), so
//! its errors name the line too. Vectors are arrays of three numbers; integers are accepted where numbers are
//! expected (`fov = 40`).

use std::fmt;

use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use toml::Spanned;

/// Three numbers: a point, a vector, an RGB colour (components from 0 to 1 unless a key says otherwise) or
/// angles.
pub(crate) type Triple = [f32; 3];

/// The whole file: the top-level keys and the `[camera]`, `[[lights]]` and `[[objects]]` tables.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a scene table")]
pub struct SceneSpec {
    /// `background = "RRGGBB"` (a leading `#` is accepted): the colour behind the objects. Optional; the viewer's
    /// dark blue-grey (`16191f`) when absent.
    pub background: Option<Spanned<String>>,
    /// `ambient = [r, g, b]`: light reaching every surface from every direction, each component finite and not
    /// negative. Optional; the viewer's ambient light ([`super::defaults::AMBIENT`]) when absent.
    pub ambient: Option<Spanned<Triple>>,
    /// `environment = "studio"|"none"|"FILE"`: the light from every direction that metallic-roughness surfaces
    /// reflect: the built-in studio, none, or an equirectangular image (Radiance `.hdr`, PNG or JPEG, twice as wide
    /// as tall), its path relative to the scene file. Optional; the studio when an object's material is
    /// physically based (a glTF model's, or one that gives `metallic` or `roughness`), else none.
    pub environment: Option<Spanned<String>>,
    /// `ambient_occlusion = true|false`: darken creases and contact areas. Default `false`.
    #[serde(default)]
    pub ambient_occlusion: bool,
    /// `linear_light = true|false`: light in linear light, sRGB-correct (the colours of the file, of MTL
    /// materials and of images decoded from sRGB, light added up, each pixel encoded back); `false` lights the
    /// stored sRGB values as they are, as most small renderers do. Default `true`.
    #[serde(default = "linear_light_default")]
    pub linear_light: bool,
    /// `[camera]`: where the scene is seen from. Optional; the viewer's framed camera when absent (yaw 30, pitch
    /// 15, distance 2.8, fov 40: see [`CameraSpec`]).
    pub camera: Option<Spanned<CameraSpec>>,
    /// `[[lights]]`: any number of lights, in file order. Optional; with none (and no `viewer_lights`), only the
    /// ambient light shows.
    #[serde(default)]
    pub lights: Vec<Spanned<LightSpec>>,
    /// `viewer_lights = true|false`: add the viewer's two lights after the file's: a warm key light from the upper
    /// left and a cool fill light from the right, both in camera space (they follow the camera), without shadows.
    /// Default `false`; a model shown without a scene file has them.
    #[serde(default)]
    pub viewer_lights: bool,
    /// `[[objects]]`: the meshes to draw, at least one, in file order.
    pub objects: Spanned<Vec<Spanned<ObjectSpec>>>,
}

/// Scenes light in linear light unless they say otherwise.
fn linear_light_default() -> bool {
    true
}

/// `[camera]`: either placed, at `position` looking at `target` (both given, in world units), or framed around
/// the scene (neither given): looking at the centre of the sphere around every object, from `distance` times its
/// radius, turned by `yaw` and `pitch`. A perspective (`fov`) or an orthographic (`orthographic`) lens, at most one
/// of the two; perspective with a 40 degree field of view when neither is given.
///
/// A framed camera measures every length in radii of the scene's bounding sphere (`distance`, `orthographic`,
/// `near`, `far`), so the same keys frame any scene; a placed one measures them in world units.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table of camera keys")]
pub struct CameraSpec {
    /// `position = [x, y, z]`: the eye, in world coordinates. Given with `target`, not with the framing keys.
    pub position: Option<Spanned<Triple>>,
    /// `target = [x, y, z]`: the point looked at; must differ from `position`. Given with `position`.
    pub target: Option<Spanned<Triple>>,
    /// `yaw = DEGREES`, framed cameras: the scene turned about the vertical axis (its front to the right for a
    /// positive angle: the eye goes round to the left). Finite. Default 30.
    pub yaw: Option<Spanned<f32>>,
    /// `pitch = DEGREES`, framed cameras: the eye raised above the horizontal plane through the centre, from -89.9
    /// to 89.9. Default 15.
    pub pitch: Option<Spanned<f32>>,
    /// `distance = RADII`, framed cameras: the eye's distance from the centre, in radii of the scene's bounding
    /// sphere; positive. Default 2.8.
    pub distance: Option<Spanned<f32>>,
    /// `up = [x, y, z]`, placed cameras: which way is up in the image; not zero. Default `[0, 1, 0]` (always, for a
    /// framed camera). When it is parallel to the view direction, another axis is used (as
    /// [`rastty_core::camera::look_at`] does).
    pub up: Option<Spanned<Triple>>,
    /// `fov = DEGREES`: a perspective lens with this field of view across the frame's shorter side (vertical in a
    /// landscape frame), strictly between 0 and 180.
    pub fov: Option<Spanned<f32>>,
    /// `orthographic = HEIGHT`: an orthographic (parallel) lens showing this much of the world across the frame's
    /// shorter side; positive.
    pub orthographic: Option<Spanned<f32>>,
    /// `near = DISTANCE`: the near clipping plane's distance from the eye, positive. Optional; the renderer chooses
    /// when absent.
    pub near: Option<Spanned<f32>>,
    /// `far = DISTANCE`: the far clipping plane's distance from the eye, positive and greater than `near`.
    /// Optional; the renderer chooses when absent.
    pub far: Option<Spanned<f32>>,
}

/// `[[lights]]`: one light. `type = "directional"` needs `direction` (and takes no `position`); `type = "point"`
/// needs `position` (and takes no `direction`); `type = "spot"` needs both. Only point and spot lights take
/// `falloff` and `range`, only spots the cone's angles.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table of light keys")]
pub struct LightSpec {
    /// `type = "directional" | "point" | "spot"`. Required.
    #[serde(rename = "type")]
    pub kind: Spanned<LightType>,
    /// `direction = [x, y, z]`, directional and spot lights: the direction the light **travels**, from the light
    /// toward the scene (so `[0, -1, 0]` is a sun straight overhead, or a spot pointing down). Not zero; its length
    /// does not matter.
    pub direction: Option<Spanned<Triple>>,
    /// `position = [x, y, z]`, point and spot lights: where the light is, in world coordinates.
    pub position: Option<Spanned<Triple>>,
    /// `inner_angle = DEGREES`, spot lights: the angle from the axis within which the light is full, from 0 and
    /// below `outer_angle`. Default 0.
    pub inner_angle: Option<Spanned<f32>>,
    /// `outer_angle = DEGREES`, spot lights: the angle from the axis beyond which there is no light, above
    /// `inner_angle` and at most 90. Default 45. Between the two the light fades as `KHR_lights_punctual` writes.
    pub outer_angle: Option<Spanned<f32>>,
    /// `falloff = "none" | "inverse-square"`, point and spot lights: whether the light weakens with the square of
    /// the distance (`intensity` is then what arrives at distance 1). Default `"none"`.
    pub falloff: Option<Spanned<FalloffSpec>>,
    /// `range = NUMBER`, with `falloff = "inverse-square"`: the distance, positive, at which the light has faded to
    /// nothing (smoothly, by `KHR_lights_punctual`'s window). Default: none, the light reaches everywhere.
    pub range: Option<Spanned<f32>>,
    /// `color = [r, g, b]`: the light's colour, components finite and not negative. Default white `[1, 1, 1]`.
    pub color: Option<Spanned<Triple>>,
    /// `intensity = NUMBER`: multiplies `color`; finite and not negative. Default 1.
    pub intensity: Option<Spanned<f32>>,
    /// `shadows = true|false`: whether this light casts shadows. Default `false`.
    #[serde(default)]
    pub shadows: bool,
    /// `space = "world" | "camera"`: what `direction` and `position` are relative to: the world, or the camera (x
    /// to the right of the image, y up, z toward the viewer), so that the light follows the camera as it orbits.
    /// Default `"world"`.
    #[serde(default)]
    pub space: LightSpace,
}

/// What a light's direction and position are given in (`space = "..."` of a `[[lights]]` table).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"world\" or \"camera\"")]
pub enum LightSpace {
    /// `"world"`: world coordinates.
    #[default]
    World,
    /// `"camera"`: the camera's coordinates, x right, y up, z toward the viewer.
    Camera,
}

/// The kinds of light (`type = "..."` of a `[[lights]]` table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"directional\", \"point\" or \"spot\"")]
pub enum LightType {
    /// `"directional"`: parallel rays from far away, like the sun.
    Directional,
    /// `"point"`: rays in every direction from one point, like a bulb.
    Point,
    /// `"spot"`: rays within a cone from one point, like a stage light.
    Spot,
}

/// How a point or spot light weakens with distance (`falloff = "..."` of a `[[lights]]` table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case", expecting = "\"none\" or \"inverse-square\"")]
pub enum FalloffSpec {
    /// `"none"`: the same light at every distance.
    None,
    /// `"inverse-square"`: as one over the distance squared.
    InverseSquare,
}

/// `[[objects]]`: one mesh, placed in the world by `scale`, then `rotate`, then `translate`.
///
/// The mesh is used in its own coordinates (it is not centred or fitted to a size, unlike the viewer's single
/// model), so the transform gives its place and size in the world.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table of object keys")]
pub struct ObjectSpec {
    /// `mesh = "PATH"`: a model file (OBJ with its MTL library and textures, or STL; see
    /// [`crate::model::load_model`]), relative to the scene file's directory (an absolute path is used as is); or
    /// `"builtin:spot"`, the model built into `rastty` (Spot, facing `+z`, with her texture; see
    /// [`crate::builtin`]). Required.
    pub mesh: Spanned<String>,
    /// `smooth_angle = DEGREES`: an STL mesh's normals are shared across edges where its faces meet within this
    /// angle, from 0 to 180. Default: flat faces.
    pub smooth_angle: Option<Spanned<f32>>,
    /// `translate = [x, y, z]`: moves the object, in world units. Default `[0, 0, 0]`.
    pub translate: Option<Spanned<Triple>>,
    /// `rotate = [x, y, z]`: rotations in degrees about the X, Y and Z axes, applied in that order (first about X,
    /// then about Y, then about Z, all about the world's axes through the object's origin), each counter-clockwise
    /// when looking down its axis toward the origin (the right-hand rule). Default `[0, 0, 0]`.
    pub rotate: Option<Spanned<Triple>>,
    /// `scale = NUMBER` or `scale = [x, y, z]`: a uniform or per-axis scale, applied first; every factor positive.
    /// Default 1.
    pub scale: Option<Spanned<NumberOrTriple>>,
    /// `animation = "NAME"` or `animation = NUMBER` (from 0): a glTF model that moves plays this animation of its
    /// own, whatever the viewer's keys choose for the others. Default: the scene's chosen animation.
    pub animation: Option<Spanned<NameOrIndex>>,
    /// `time = SECONDS`: where the object's animation stands when the scene's clock reads 0 (a still drawn without
    /// `--time` shows it there). Finite. Default 0; needs `animation`.
    pub time: Option<Spanned<f32>>,
    /// `[objects.material]`: how the surface looks. Optional.
    #[serde(default)]
    pub material: MaterialSpec,
}

/// A name or a number from 0 (`animation = "Walk"` or `animation = 2`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NameOrIndex {
    /// By name.
    Name(String),
    /// By number.
    Index(u64),
}

impl<'de> Deserialize<'de> for NameOrIndex {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct NameOrIndexVisitor;

        impl Visitor<'_> for NameOrIndexVisitor {
            type Value = NameOrIndex;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a name or a number from 0")
            }

            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Ok(NameOrIndex::Name(v.to_owned()))
            }

            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(NameOrIndex::Index(v))
            }

            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                u64::try_from(v).map(NameOrIndex::Index).map_err(|_| E::custom(format!("{v} is below 0")))
            }
        }

        deserializer.deserialize_any(NameOrIndexVisitor)
    }
}

/// `[objects.material]`: the object's surface. Every key is optional.
///
/// Where the OBJ file has its own MTL materials, the keys given here override them for every part of the object,
/// and keys left out fall back to each part's MTL material: `color` to its `Kd`, `diffuse` to its `map_Kd`. The
/// other keys have no MTL counterpart that `rastty` reads, so when left out they take the renderer's defaults.
/// Image paths are relative to the scene file's directory. Images are sampled with the object's texture
/// coordinates, so they show only on meshes that have them.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, expecting = "a table of material keys")]
pub struct MaterialSpec {
    /// `color = [r, g, b]`: the diffuse (base) colour, components from 0 to 1; multiplied by `diffuse` when both
    /// are given.
    pub color: Option<Spanned<Triple>>,
    /// `diffuse = "PATH"`: the diffuse texture (PNG, TGA or JPEG).
    pub diffuse: Option<Spanned<String>>,
    /// `normal_map = "PATH"`: a normal map, each texel a unit normal encoded as `rgb = normal * 0.5 + 0.5`, in the
    /// space `normal_space` names.
    pub normal_map: Option<Spanned<String>>,
    /// `normal_space = "tangent" | "object"`: how `normal_map` is read: relative to the surface (tangent space:
    /// `[0.5, 0.5, 1]` is the unperturbed normal), or as normals in the mesh's own coordinates (object space).
    /// Default `"tangent"`; an error without `normal_map`.
    pub normal_space: Option<Spanned<NormalSpaceSpec>>,
    /// `specular = [r, g, b]` or `specular = NUMBER` (grey): the colour of highlights, components from 0 to 1;
    /// 0 turns highlights off.
    pub specular: Option<Spanned<NumberOrTriple>>,
    /// `shininess = NUMBER`: the Blinn-Phong exponent, positive: larger is a smaller, sharper highlight.
    pub shininess: Option<Spanned<f32>>,
    /// `metallic = NUMBER`: under the metallic-roughness model (`--shading metallic-roughness`), how much of a
    /// metal the surface is, from 0 (a dielectric) to 1.
    pub metallic: Option<Spanned<f32>>,
    /// `roughness = NUMBER`: under the metallic-roughness model, the surface's roughness, from 0 (a mirror) to 1.
    pub roughness: Option<Spanned<f32>>,
    /// `specular_map = "PATH"`: an image that scales the specular colour per texel (a grey image scales all
    /// channels alike).
    pub specular_map: Option<Spanned<String>>,
    /// `glow_map = "PATH"`: light the surface emits itself, per texel, added after lighting (black emits nothing).
    pub glow_map: Option<Spanned<String>>,
    /// `filter = "nearest" | "bilinear"`: how the images are sampled. Default `"bilinear"`.
    #[serde(default)]
    pub filter: FilterSpec,
    /// `wrap = "repeat" | "clamp"`: what texture coordinates outside `[0, 1]` read. Default `"repeat"`.
    #[serde(default)]
    pub wrap: WrapSpec,
    /// `mipmaps = "off" | "nearest" | "linear" | "anisotropicN"` (N 2, 4, 8, 16): how the images' levels of
    /// detail are read where a pixel spans several texels: not at all, the nearest level, the two nearest blended,
    /// or that at up to N places along the pixel's footprint. Default `"linear"`.
    #[serde(default)]
    pub mipmaps: Mipmaps,
}

/// How a normal map's texels are to be read (`normal_space = "..."`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"tangent\" or \"object\"")]
pub enum NormalSpaceSpec {
    /// `"tangent"`: relative to the surface, along its tangent, bitangent and normal.
    #[default]
    Tangent,
    /// `"object"`: normals in the mesh's own coordinates.
    Object,
}

/// How images are sampled (`filter = "..."`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"nearest\" or \"bilinear\"")]
pub enum FilterSpec {
    /// `"nearest"`: the nearest texel.
    Nearest,
    /// `"bilinear"`: a blend of the four nearest texels.
    #[default]
    Bilinear,
}

/// How the images' levels of detail are read (`mipmaps = "..."`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(
    rename_all = "lowercase",
    expecting = "\"off\", \"nearest\", \"linear\", \"anisotropic2\", \"anisotropic4\", \"anisotropic8\" or \"anisotropic16\""
)]
pub enum Mipmaps {
    /// `"off"`: the image itself at every distance.
    Off,
    /// `"nearest"`: the level nearest the pixel's footprint.
    Nearest,
    /// `"linear"`: the two nearest levels, blended.
    #[default]
    Linear,
    /// `"anisotropic2"`: up to 2 `"linear"` probes along the footprint's longer side, averaged.
    Anisotropic2,
    /// `"anisotropic4"`: up to 4 probes.
    Anisotropic4,
    /// `"anisotropic8"`: up to 8 probes.
    Anisotropic8,
    /// `"anisotropic16"`: up to 16 probes.
    Anisotropic16,
}

/// What texture coordinates outside `[0, 1]` read (`wrap = "..."`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase", expecting = "\"repeat\" or \"clamp\"")]
pub enum WrapSpec {
    /// `"repeat"`: the image tiles.
    #[default]
    Repeat,
    /// `"clamp"`: the edge texels extend outward.
    Clamp,
}

/// A value written either as one number or as an array of three (`scale = 2` or `scale = [1, 2, 1]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NumberOrTriple {
    /// One number, for all three components.
    Number(f32),
    /// Three numbers.
    Triple(Triple),
}

impl NumberOrTriple {
    /// The three components.
    pub(crate) fn triple(self) -> Triple {
        match self {
            Self::Number(v) => [v; 3],
            Self::Triple(t) => t,
        }
    }
}

impl<'de> Deserialize<'de> for NumberOrTriple {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct NumberOrTripleVisitor;

        impl<'de> Visitor<'de> for NumberOrTripleVisitor {
            type Value = NumberOrTriple;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number or an array of three numbers")
            }

            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
                Ok(NumberOrTriple::Number(v as f32))
            }

            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(NumberOrTriple::Number(v as f32))
            }

            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(NumberOrTriple::Number(v as f32))
            }

            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
                Triple::deserialize(de::value::SeqAccessDeserializer::new(seq)).map(NumberOrTriple::Triple)
            }
        }

        deserializer.deserialize_any(NumberOrTripleVisitor)
    }
}
