//! What a draw asks for, and the shader variant that provides exactly that.

use core::fmt;

use super::{Lighting, Material, Transforms};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{DrawError, DrawState};
use crate::texture::{FilterMode, Texture, WrapMode};

/// How surfaces are coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadingModel {
    /// No lighting: the material colour (or the mesh's vertex colours, when it has them) times the texture.
    Unlit,
    /// Lighting once per triangle with its face normal.
    Flat,
    /// Lighting per vertex, interpolated.
    Gouraud,
    /// Lighting per pixel with the interpolated normal.
    Phong,
    /// The depth buffer as grey levels: NDC depth `near` white to `far` black.
    Depth {
        /// NDC depth shown white.
        near: f32,
        /// NDC depth shown black.
        far: f32,
    },
    /// World-space normals as colours.
    Normals,
}

impl ShadingModel {
    /// A short lowercase name (`"phong"`, `"depth"`...).
    pub fn name(&self) -> &'static str {
        match self {
            Self::Unlit => "unlit",
            Self::Flat => "flat",
            Self::Gouraud => "gouraud",
            Self::Phong => "phong",
            Self::Depth { .. } => "depth",
            Self::Normals => "normals",
        }
    }

    fn is_lit(&self) -> bool {
        matches!(self, Self::Flat | Self::Gouraud | Self::Phong)
    }

    fn takes_texture(&self) -> bool {
        matches!(self, Self::Unlit | Self::Flat | Self::Gouraud | Self::Phong)
    }

    fn needs_normals(&self) -> bool {
        matches!(self, Self::Gouraud | Self::Phong | Self::Normals)
    }
}

/// A texture with the filter and wrap mode to sample it with.
#[derive(Clone, Copy, Debug)]
pub struct TextureBinding<'t> {
    /// The texels.
    pub texture: Texture<'t>,
    /// Nearest or bilinear.
    pub filter: FilterMode,
    /// Repeat or clamp.
    pub wrap: WrapMode,
}

/// Everything a mesh draw may use. [`Effects::resolve`] keeps only what the mesh and the settings call for.
#[derive(Clone, Copy, Debug)]
pub struct Effects<'a> {
    /// The shading model.
    pub shading: ShadingModel,
    /// The surface material.
    pub material: Material,
    /// The lights.
    pub lighting: Lighting<'a>,
    /// A diffuse texture, if any.
    pub texture: Option<TextureBinding<'a>>,
}

/// The shader variant and fixed-function state a draw compiles down to: what is computed, and nothing else.
///
/// Its [`Display`](fmt::Display) form explains the choice, e.g.
/// `phong, texture bilinear/repeat, no specular, perspective-correct, depth less, cull back`.
#[derive(Clone, Copy, Debug)]
pub struct Variant<'a> {
    /// The shading model.
    pub shading: ShadingModel,
    /// Unlit with the mesh's vertex colours instead of the material colour.
    pub vertex_colors: bool,
    /// The texture actually sampled (`None` also when the mesh has no texture coordinates).
    pub texture: Option<TextureBinding<'a>>,
    /// Specular highlights computed.
    pub specular: bool,
    /// The draw state, with interpolation set to affine under an orthographic projection and the front face
    /// flipped for a mirroring model matrix.
    pub state: DrawState,
}

impl<'a> Effects<'a> {
    /// Decides what a draw of `mesh` with these effects computes.
    ///
    /// - A texture is sampled only by a colour shading model on a mesh with texture coordinates.
    /// - Specular highlights only for a lit model with a non-zero [`Material::specular`].
    /// - Vertex colours only for [`ShadingModel::Unlit`] on a mesh that has them.
    /// - Interpolation is affine whenever the projection is orthographic: it is then exact, and it saves the
    ///   per-pixel division.
    /// - A mirroring model matrix flips which winding is front-facing, so culling still removes the back.
    ///
    /// # Errors
    /// [`DrawError::MissingAttributes`] when the model needs normals (Gouraud, Phong, normals view) that the mesh
    /// does not have.
    pub fn resolve(
        &self,
        mesh: &Mesh<'_>,
        transforms: &Transforms,
        state: &DrawState,
    ) -> Result<Variant<'a>, DrawError> {
        let present = mesh.attributes();
        if self.shading.needs_normals() && !present.normals {
            let needed = Attributes { normals: true, ..Attributes::NONE };
            return Err(DrawError::MissingAttributes { needed, present });
        }
        let state = transforms.adapt(state);
        Ok(Variant {
            shading: self.shading,
            vertex_colors: self.shading == ShadingModel::Unlit && present.colors,
            texture: self.texture.filter(|_| self.shading.takes_texture() && present.uvs),
            specular: self.shading.is_lit() && self.material.has_specular(),
            state,
        })
    }
}

impl fmt::Display for Variant<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.shading.name())?;
        if self.vertex_colors {
            f.write_str(", vertex colours")?;
        }
        if self.shading.takes_texture() {
            match &self.texture {
                Some(t) => {
                    let filter = match t.filter {
                        FilterMode::Nearest => "nearest",
                        FilterMode::Bilinear => "bilinear",
                    };
                    let wrap = match t.wrap {
                        WrapMode::Repeat => "repeat",
                        WrapMode::Clamp => "clamp",
                    };
                    write!(f, ", texture {filter}/{wrap}")?;
                }
                None => f.write_str(", untextured")?,
            }
        }
        if self.shading.is_lit() {
            f.write_str(if self.specular { ", specular" } else { ", no specular" })?;
        }
        write!(f, ", {}", crate::pipeline::FixedFunction(&self.state))
    }
}
