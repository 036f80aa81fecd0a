//! What a draw computes, decided once per draw from the mesh, the material and the lights.

use core::fmt;

use super::{LightUse, Object};
use crate::color::ShadingSpace;
use crate::math::{Vec3, Vec4};
use crate::mesh::Attributes;
use crate::pipeline::{Cull, DrawError, DrawState, FixedFunction};
use crate::shading::ShadingModel;
use crate::texture::{FilterMode, MipFilter, WrapMode};

/// Where the shading normal comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalSource {
    /// None: the model reads no normal (unlit, the depth view).
    None,
    /// The triangle's own normal, once per triangle (flat shading).
    Face,
    /// The vertex normals, lit per vertex (Gouraud shading).
    Vertex,
    /// The interpolated vertex normal, per pixel.
    Interpolated,
    /// A tangent-space normal map, applied with the interpolated tangent frame.
    TangentMap,
    /// An object-space normal map.
    ObjectMap,
}

/// Where the specular colour comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpecularSource {
    /// No highlights: none computed.
    None,
    /// The material's specular colour.
    Constant,
    /// The material's specular colour times the specular map.
    Map,
}

/// Whether a draw discards fragments by their alpha ([`super::Material::alpha_cutoff`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cutout {
    /// Drawn whole: no cut-off, a model that reads no colour, or an opacity at or above the cut-off and no map
    /// to lower it.
    None,
    /// Per fragment: the opacity times the diffuse map's alpha is tested against this cut-off.
    Map(f32),
    /// Not drawn at all: the opacity is below the cut-off and no map is read.
    Everything,
}

/// Why a draw was refused (nothing was drawn).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadingError {
    /// Refused by the pipeline (the mesh has no normals, or the state is out of range).
    Draw(DrawError),
    /// A tangent-space normal map on a mesh drawn without tangents, or with a tangent slice whose length is not
    /// the vertex count.
    Tangents {
        /// Vertices of the mesh.
        expected: usize,
        /// Tangents given (0 for none).
        actual: usize,
    },
    /// A surface shader whose slot types do not carry the variant's layout, or whose capabilities leave out what
    /// the variant uses ([`super::SurfaceShader::new`]).
    Unsupported,
}

impl fmt::Display for ShadingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Draw(e) => e.fmt(f),
            Self::Tangents { expected, actual } => write!(
                f,
                "a tangent-space normal map needs one tangent per vertex ({expected}), {actual} given \
                 (see mesh::compute_tangents)"
            ),
            Self::Unsupported => {
                f.write_str("the surface shader was not compiled for this draw's varyings, shading model or lights")
            }
        }
    }
}

impl core::error::Error for ShadingError {}

/// The stages and varyings one draw runs: exactly what its mesh, material and lights call for.
///
/// Its [`Display`](fmt::Display) form is the explanation `rastty render --explain` prints, e.g.
/// `phong; varyings normal+world+uv+tangent; albedo texture; linear light; normals tangent-space map; specular map;
/// glow map; maps bilinear/repeat; lights 1 directional (1 with shadows, pcf 3x3); perspective-correct, depth
/// less, cull back`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    /// The shading model.
    pub shading: ShadingModel,
    /// The albedo is the material colour times the mesh's vertex colours (a model that colours, on a mesh with
    /// colours).
    pub vertex_colors: bool,
    /// The world position is interpolated (per-pixel lighting with point or spot lights, highlights or shadows).
    pub world: bool,
    /// Texture coordinates are interpolated (for any map).
    pub uvs: bool,
    /// Tangents are interpolated (for a tangent-space normal map).
    pub tangents: bool,
    /// The albedo is sampled from the diffuse map.
    pub albedo_map: bool,
    /// Where the shading normal comes from.
    pub normals: NormalSource,
    /// Where the specular colour comes from.
    pub specular: SpecularSource,
    /// The glow map is added.
    pub glow_map: bool,
    /// The ambient light is scaled by the occlusion map (per-pixel lighting).
    pub occlusion_map: bool,
    /// The metallic factor and the roughness are scaled by the metallic-roughness map (the metallic-roughness
    /// model).
    pub metallic_roughness_map: bool,
    /// The environment's light is reflected (the metallic-roughness model under an environment).
    pub environment: bool,
    /// Fragments discarded by alpha.
    pub cutout: Cutout,
    /// Back faces are lit as seen from behind: per-pixel lighting of a draw that does not cull back faces turns
    /// the normal of back-facing fragments round (glTF's double-sided lighting).
    pub two_sided: bool,
    /// How colours are lit: the lighting's [`ShadingSpace`] for a model that colours, [`ShadingSpace::Encoded`]
    /// (values shown as computed) for the depth and normals views.
    pub space: ShadingSpace,
    /// Filter of the maps sampled.
    pub filter: FilterMode,
    /// Wrap mode of the maps sampled.
    pub wrap: WrapMode,
    /// How the maps sampled choose among their levels of detail: the material's when one of them has levels,
    /// [`MipFilter::Off`] otherwise (the draw then reads no slopes).
    pub mip_filter: MipFilter,
    /// Directional lights.
    pub directional_lights: usize,
    /// Point and spot lights.
    pub point_lights: usize,
    /// Lights with a shadow map that this draw reads (per-pixel lighting only).
    pub shadowed_lights: usize,
    /// The largest percentage-closer filtering radius among them.
    pub pcf_radius: u32,
    /// The draw state, with interpolation set to affine under an orthographic projection and the front face
    /// flipped for a mirroring model matrix.
    pub state: DrawState,
}

/// Which of a draw's varying slots are carried ([`super::SurfaceVaryings`]): what its pipeline is compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The first `Vec3` slot: the world normal (per-pixel lighting, the normals view) or the diffuse light
    /// (Gouraud).
    pub first: bool,
    /// The second `Vec3` slot: the world position (per-pixel lighting) or the specular light (Gouraud). Only with
    /// the first.
    pub second: bool,
    /// Texture coordinates.
    pub uvs: bool,
    /// Tangents (a tangent-space normal map). Only with the first slot and texture coordinates.
    pub tangents: bool,
    /// Vertex colours.
    pub colors: bool,
}

impl Variant {
    /// Decides what a draw of `object` under `lights` (one [`LightUse`] per light, as
    /// `scene_lights.lights.iter().map(LightUse::from)` gives), lit in `space`, computes.
    ///
    /// - Normals are read by Gouraud and per-pixel lighting and the normals view only; vertex colours by every
    ///   model that colours (unlit, flat, Gouraud, per-pixel), as a factor of its albedo (glTF's `COLOR_0`).
    /// - Maps are sampled only on a mesh with texture coordinates; without, the draw is untextured. The albedo map
    ///   serves every model that colours (unlit, flat, Gouraud, per-pixel), the specular and glow maps the lit
    ///   ones, normal and occlusion maps per-pixel lighting only. The depth and normals views read no map.
    /// - Maps are read through their levels of detail, as the material's [`MipFilter`] says, only when one of the
    ///   maps read has levels ([`crate::texture::Texture::with_mip_levels`]); only then are slopes worked out.
    /// - A tangent-space normal map needs `tangents` (one per vertex), and only then are tangents interpolated.
    /// - Lights reach the lit models: per triangle (flat, at its centroid), per vertex (Gouraud) or per pixel.
    ///   Shadow maps are read per pixel only.
    /// - An alpha cut-off is tested per fragment only where the diffuse map is read; without it, the opacity
    ///   decides for the whole draw ([`Cutout`]).
    /// - Back faces, where a draw keeps them, are lit with their normal turned round: per-pixel lighting only
    ///   (flat and Gouraud light both faces alike).
    /// - Highlights only for a non-zero [`super::Material::specular`] with at least one light; the metallic-roughness
    ///   model's specular lobe with any light, of its own colour (no specular map).
    /// - An environment ([`LightUse::environment`]) is reflected by the metallic-roughness model alone, which then
    ///   has its specular lobe.
    /// - The world position only for per-pixel point or spot lights, highlights or shadows.
    /// - Affine interpolation under an orthographic projection, and the front face flipped for a mirroring model
    ///   matrix ([`crate::shading::Transforms::adapt`]).
    ///
    /// # Errors
    /// [`ShadingError::Draw`] when the model needs normals and the mesh has none; [`ShadingError::Tangents`] for a
    /// tangent-space normal map without a tangent per vertex.
    pub fn resolve(
        object: &Object<'_>,
        lights: impl IntoIterator<Item = LightUse>,
        space: ShadingSpace,
        state: &DrawState,
    ) -> Result<Self, ShadingError> {
        let (mesh, material, shading) = (&object.mesh, &object.material, object.shading);
        let present = mesh.attributes();
        let per_pixel = shading.per_pixel();
        let lit = per_pixel || matches!(shading, ShadingModel::Flat | ShadingModel::Gouraud);
        let colored = lit || shading == ShadingModel::Unlit;
        let reads_normals = per_pixel || matches!(shading, ShadingModel::Gouraud | ShadingModel::Normals);
        if reads_normals && !present.normals {
            let needed = Attributes { normals: true, ..Attributes::NONE };
            return Err(ShadingError::Draw(DrawError::MissingAttributes { needed, present }));
        }
        let uvs = present.uvs;
        let normals = match shading {
            ShadingModel::Unlit | ShadingModel::Depth { .. } => NormalSource::None,
            ShadingModel::Flat => NormalSource::Face,
            ShadingModel::Gouraud => NormalSource::Vertex,
            ShadingModel::Normals => NormalSource::Interpolated,
            ShadingModel::Phong | ShadingModel::MetallicRoughness => match material.normal_map {
                Some(map) if uvs => match map.space {
                    super::NormalSpace::Tangent => {
                        let actual = object.tangents.map_or(0, <[Vec4]>::len);
                        if actual != mesh.vertex_count() {
                            return Err(ShadingError::Tangents { expected: mesh.vertex_count(), actual });
                        }
                        NormalSource::TangentMap
                    }
                    super::NormalSpace::Object => NormalSource::ObjectMap,
                },
                _ => NormalSource::Interpolated,
            },
        };
        // The metallic-roughness model always has its specular lobe, of its own colour.
        let metallic_roughness = shading == ShadingModel::MetallicRoughness;
        let (mut directional_lights, mut point_lights, mut shadowed_lights, mut pcf_radius) = (0, 0, 0, 0);
        let mut environment = false;
        for light in lights.into_iter().filter(|_| lit) {
            if light.environment {
                environment |= metallic_roughness;
                continue;
            }
            if light.point {
                point_lights += 1;
            } else {
                directional_lights += 1;
            }
            if let (Some(r), true) = (light.shadow_pcf, per_pixel) {
                shadowed_lights += 1;
                pcf_radius = pcf_radius.max(r);
            }
        }
        let specular = if directional_lights + point_lights == 0 && !environment {
            SpecularSource::None
        } else if metallic_roughness {
            SpecularSource::Constant
        } else if material.specular == Vec3::ZERO {
            SpecularSource::None
        } else if material.specular_map.is_some() && uvs {
            SpecularSource::Map
        } else {
            SpecularSource::Constant
        };
        let albedo_map = colored && material.diffuse.is_some() && uvs;
        let glow_map = lit && material.glow_map.is_some() && uvs;
        let occlusion_map = per_pixel && material.occlusion_map.is_some() && uvs;
        let metallic_roughness_map = metallic_roughness && material.metallic_roughness_map.is_some() && uvs;
        let cutout = match material.alpha_cutoff {
            Some(cutoff) if albedo_map => Cutout::Map(cutoff),
            Some(cutoff) if colored && !material.keeps(255, cutoff) => Cutout::Everything,
            _ => Cutout::None,
        };
        let normal_map = matches!(normals, NormalSource::TangentMap | NormalSource::ObjectMap);
        let read = [
            (albedo_map, material.diffuse),
            (normal_map, material.normal_map.map(|map| map.texture)),
            (specular == SpecularSource::Map, material.specular_map),
            (glow_map, material.glow_map),
            (occlusion_map, material.occlusion_map),
            (metallic_roughness_map, material.metallic_roughness_map),
        ];
        let mipmapped = read.iter().any(|(reads, map)| *reads && map.is_some_and(|map| map.has_mip_levels()));
        let state = object.transforms.adapt(state);
        Ok(Self {
            shading,
            vertex_colors: colored && present.colors,
            world: per_pixel && (specular != SpecularSource::None || point_lights > 0 || shadowed_lights > 0),
            uvs: read.iter().any(|(reads, _)| *reads),
            tangents: normals == NormalSource::TangentMap,
            albedo_map,
            normals,
            specular,
            glow_map,
            occlusion_map,
            metallic_roughness_map,
            environment,
            cutout,
            two_sided: per_pixel && state.cull != Cull::Back,
            space: if colored { space } else { ShadingSpace::Encoded },
            filter: material.filter,
            wrap: material.wrap,
            mip_filter: if mipmapped { material.mip_filter } else { MipFilter::Off },
            directional_lights,
            point_lights,
            shadowed_lights,
            pcf_radius,
            state,
        })
    }

    /// Whether the draw reads a map beyond the diffuse map: a normal, specular, glow, occlusion or
    /// metallic-roughness map (what [`super::capabilities::LIGHTING_MAPS`] compiles).
    #[must_use]
    pub fn lighting_maps(&self) -> bool {
        matches!(self.normals, NormalSource::TangentMap | NormalSource::ObjectMap)
            || self.specular == SpecularSource::Map
            || self.glow_map
            || self.occlusion_map
            || self.metallic_roughness_map
    }

    /// The varying slots this variant's draw carries.
    #[must_use]
    pub fn layout(&self) -> Layout {
        let first = match self.shading {
            ShadingModel::Unlit | ShadingModel::Flat | ShadingModel::Depth { .. } => false,
            ShadingModel::Gouraud | ShadingModel::Phong | ShadingModel::MetallicRoughness | ShadingModel::Normals => {
                true
            }
        };
        let second = match self.shading {
            ShadingModel::Gouraud => self.specular != SpecularSource::None,
            ShadingModel::Phong | ShadingModel::MetallicRoughness => self.world,
            _ => false,
        };
        Layout { first, second, uvs: self.uvs, tangents: self.tangents, colors: self.vertex_colors }
    }
}

impl fmt::Display for Variant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let layout = self.layout();
        let (first, second) = match self.shading {
            ShadingModel::Gouraud => ("light", "specular light"),
            _ => ("normal", "world"),
        };
        write!(f, "{}; varyings ", self.shading.name())?;
        let carried = [
            (layout.colors, "colour"),
            (layout.first, first),
            (layout.second, second),
            (layout.uvs, "uv"),
            (layout.tangents, "tangent"),
        ];
        let mut names = carried.iter().filter(|(on, _)| *on).map(|(_, name)| *name);
        match names.next() {
            None => f.write_str("none")?,
            Some(name) => {
                f.write_str(name)?;
                for name in names {
                    write!(f, "+{name}")?;
                }
            }
        }
        let lit = matches!(
            self.shading,
            ShadingModel::Flat | ShadingModel::Gouraud | ShadingModel::Phong | ShadingModel::MetallicRoughness
        );
        if lit || self.shading == ShadingModel::Unlit {
            f.write_str(match (self.vertex_colors, self.albedo_map) {
                (true, true) => "; albedo colour x vertex colours x texture",
                (true, false) => "; albedo colour x vertex colours",
                (false, true) => "; albedo texture",
                (false, false) => "; albedo colour",
            })?;
            f.write_str(match self.space {
                ShadingSpace::Linear => "; linear light",
                ShadingSpace::Encoded => "; light on sRGB codes",
            })?;
        }
        if lit {
            f.write_str(match self.normals {
                NormalSource::Face => "; normals per face",
                NormalSource::Vertex => "; normals per vertex",
                NormalSource::TangentMap => "; normals tangent-space map",
                NormalSource::ObjectMap => "; normals object-space map",
                NormalSource::Interpolated | NormalSource::None => "; normals interpolated",
            })?;
            f.write_str(match self.specular {
                SpecularSource::None => "; no specular",
                SpecularSource::Constant => "; specular constant",
                SpecularSource::Map => "; specular map",
            })?;
        }
        if self.glow_map {
            f.write_str("; glow map")?;
        }
        if self.occlusion_map {
            f.write_str("; occlusion map")?;
        }
        if self.metallic_roughness_map {
            f.write_str("; metallic-roughness map")?;
        }
        if self.two_sided {
            f.write_str("; two-sided")?;
        }
        match self.cutout {
            Cutout::None => {}
            Cutout::Map(cutoff) => write!(f, "; alpha cut-out below {cutoff}")?,
            Cutout::Everything => f.write_str("; cut out entirely (not drawn)")?,
        }
        if self.uvs {
            let filter = match (self.filter, self.mip_filter) {
                (FilterMode::Nearest, MipFilter::Off) => "nearest",
                (FilterMode::Bilinear, MipFilter::Off) => "bilinear",
                (FilterMode::Nearest, MipFilter::Nearest) => "nearest of the nearest level",
                (FilterMode::Bilinear, MipFilter::Nearest) => "bilinear of the nearest level",
                (FilterMode::Nearest, MipFilter::Linear | MipFilter::Anisotropic(_)) => "nearest of two levels",
                (FilterMode::Bilinear, MipFilter::Linear | MipFilter::Anisotropic(_)) => "trilinear",
            };
            let wrap = match self.wrap {
                WrapMode::Repeat => "repeat",
                WrapMode::Clamp => "clamp",
            };
            write!(f, "; maps {filter}/{wrap}")?;
            if let MipFilter::Anisotropic(most) = self.mip_filter {
                write!(f, ", anisotropic up to {} probes", most.probes())?;
            }
        }
        if lit {
            match (self.directional_lights, self.point_lights) {
                (0, 0) if self.environment => f.write_str("; lights the environment")?,
                (0, 0) => f.write_str("; unlit but ambient")?,
                (d, 0) => write!(f, "; lights {d} directional")?,
                (0, p) => write!(f, "; lights {p} point")?,
                (d, p) => write!(f, "; lights {d} directional + {p} point")?,
            }
        }
        if self.shadowed_lights > 0 {
            let side = 2 * self.pcf_radius + 1;
            write!(f, " ({} with shadows, pcf {side}x{side})", self.shadowed_lights)?;
        }
        if self.environment && self.directional_lights + self.point_lights > 0 {
            f.write_str(" + the environment")?;
        }
        write!(f, "; {}", FixedFunction(&self.state))
    }
}
