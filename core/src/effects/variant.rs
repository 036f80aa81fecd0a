//! What a mapped draw computes, decided once per draw from the mesh, the material and the lights.

use core::fmt;

use super::{LightUse, SurfaceMaterial};
use crate::math::Vec4;
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{DrawError, DrawState, FixedFunction};
use crate::shading::Transforms;
use crate::texture::{FilterMode, WrapMode};

/// Where the shading normal comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalSource {
    /// The interpolated vertex normal.
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

/// Why a mapped draw was refused (nothing was drawn).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceError {
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
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Draw(e) => e.fmt(f),
            Self::Tangents { expected, actual } => write!(
                f,
                "a tangent-space normal map needs one tangent per vertex ({expected}), {actual} given \
                 (see mesh::compute_tangents)"
            ),
        }
    }
}

/// The stages and varyings one mapped draw runs: exactly what its mesh, material and lights call for.
///
/// Its [`Display`](fmt::Display) form is the explanation `rastty render --explain` prints, e.g.
/// `varyings normal+world+uv+tangent; albedo texture; normals tangent-space map; specular map; glow map;
/// maps bilinear/repeat; lights 1 directional (1 with shadows, pcf 3x3); perspective-correct, depth less, cull back`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceVariant {
    /// The world position is interpolated (for point lights, highlights or shadows).
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
    /// Filter of the maps sampled.
    pub filter: FilterMode,
    /// Wrap mode of the maps sampled.
    pub wrap: WrapMode,
    /// Directional lights.
    pub directional_lights: usize,
    /// Point lights.
    pub point_lights: usize,
    /// Lights with a shadow map.
    pub shadowed_lights: usize,
    /// The largest percentage-closer filtering radius among them.
    pub pcf_radius: u32,
    /// The draw state, with interpolation set to affine under an orthographic projection and the front face
    /// flipped for a mirroring model matrix.
    pub state: DrawState,
}

impl SurfaceVariant {
    /// Decides what a draw of `mesh` with `material` under `lights` (one [`LightUse`] per light, as
    /// `scene_lights.lights.iter().map(LightUse::from)` gives) computes.
    ///
    /// - Maps are sampled only on a mesh with texture coordinates; without, the draw is untextured.
    /// - A tangent-space normal map needs `tangents` (one per vertex), and only then are tangents interpolated.
    /// - Highlights only for a non-zero [`SurfaceMaterial::specular`] with at least one light.
    /// - The world position only for point lights, highlights or shadows.
    /// - Affine interpolation under an orthographic projection, and the front face flipped for a mirroring model
    ///   matrix, as [`crate::shading::Effects::resolve`] does.
    ///
    /// # Errors
    /// [`SurfaceError::Draw`] when the mesh has no normals; [`SurfaceError::Tangents`] for a tangent-space normal
    /// map without a tangent per vertex.
    pub fn resolve(
        mesh: &Mesh<'_>,
        tangents: Option<&[Vec4]>,
        transforms: &Transforms,
        material: &SurfaceMaterial<'_>,
        lights: impl IntoIterator<Item = LightUse>,
        state: &DrawState,
    ) -> Result<Self, SurfaceError> {
        let present = mesh.attributes();
        if !present.normals {
            let needed = Attributes { normals: true, ..Attributes::NONE };
            return Err(SurfaceError::Draw(DrawError::MissingAttributes { needed, present }));
        }
        let uvs = present.uvs;
        let normals = match material.normal_map {
            Some(map) if uvs => match map.space {
                super::NormalSpace::Tangent => {
                    let actual = tangents.map_or(0, <[Vec4]>::len);
                    if actual != mesh.vertex_count() {
                        return Err(SurfaceError::Tangents { expected: mesh.vertex_count(), actual });
                    }
                    NormalSource::TangentMap
                }
                super::NormalSpace::Object => NormalSource::ObjectMap,
            },
            _ => NormalSource::Interpolated,
        };
        let (mut directional_lights, mut point_lights, mut shadowed_lights, mut pcf_radius) = (0, 0, 0, 0);
        for light in lights {
            if light.point {
                point_lights += 1;
            } else {
                directional_lights += 1;
            }
            if let Some(r) = light.shadow_pcf {
                shadowed_lights += 1;
                pcf_radius = pcf_radius.max(r);
            }
        }
        let lit = directional_lights + point_lights > 0;
        let specular = if !lit || material.specular == crate::math::Vec3::ZERO {
            SpecularSource::None
        } else if material.specular_map.is_some() && uvs {
            SpecularSource::Map
        } else {
            SpecularSource::Constant
        };
        let albedo_map = material.diffuse.is_some() && uvs;
        let glow_map = material.glow_map.is_some() && uvs;
        let state = transforms.adapt(state);
        Ok(Self {
            world: specular != SpecularSource::None || point_lights > 0 || shadowed_lights > 0,
            uvs: albedo_map || glow_map || specular == SpecularSource::Map || normals != NormalSource::Interpolated,
            tangents: normals == NormalSource::TangentMap,
            albedo_map,
            normals,
            specular,
            glow_map,
            filter: material.filter,
            wrap: material.wrap,
            directional_lights,
            point_lights,
            shadowed_lights,
            pcf_radius,
            state,
        })
    }
}

impl fmt::Display for SurfaceVariant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("varyings normal")?;
        for (on, name) in [(self.world, "+world"), (self.uvs, "+uv"), (self.tangents, "+tangent")] {
            if on {
                f.write_str(name)?;
            }
        }
        f.write_str(if self.albedo_map { "; albedo texture" } else { "; albedo colour" })?;
        f.write_str(match self.normals {
            NormalSource::Interpolated => "; normals interpolated",
            NormalSource::TangentMap => "; normals tangent-space map",
            NormalSource::ObjectMap => "; normals object-space map",
        })?;
        f.write_str(match self.specular {
            SpecularSource::None => "; no specular",
            SpecularSource::Constant => "; specular constant",
            SpecularSource::Map => "; specular map",
        })?;
        if self.glow_map {
            f.write_str("; glow map")?;
        }
        if self.uvs {
            let filter = match self.filter {
                FilterMode::Nearest => "nearest",
                FilterMode::Bilinear => "bilinear",
            };
            let wrap = match self.wrap {
                WrapMode::Repeat => "repeat",
                WrapMode::Clamp => "clamp",
            };
            write!(f, "; maps {filter}/{wrap}")?;
        }
        match (self.directional_lights, self.point_lights) {
            (0, 0) => f.write_str("; unlit but ambient")?,
            (d, 0) => write!(f, "; lights {d} directional")?,
            (0, p) => write!(f, "; lights {p} point")?,
            (d, p) => write!(f, "; lights {d} directional + {p} point")?,
        }
        if self.shadowed_lights > 0 {
            let side = 2 * self.pcf_radius + 1;
            write!(f, " ({} with shadows, pcf {side}x{side})", self.shadowed_lights)?;
        }
        write!(f, "; {}", FixedFunction(&self.state))
    }
}
