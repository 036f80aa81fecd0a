//! The shading models: how a draw colours its surfaces.

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
    /// Lighting per pixel by glTF's metallic-roughness BRDF ([`super::brdf`]), from the material's base colour,
    /// [`super::Material::metallic`] and [`super::Material::roughness`]. The ambient light reaches its diffuse
    /// lobe alone.
    MetallicRoughness,
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
    /// Whether the model lights each pixel: [`Self::Phong`] and [`Self::MetallicRoughness`].
    #[must_use]
    pub fn per_pixel(&self) -> bool {
        matches!(self, Self::Phong | Self::MetallicRoughness)
    }

    /// A short lowercase name (`"phong"`, `"depth"`...).
    pub fn name(&self) -> &'static str {
        match self {
            Self::Unlit => "unlit",
            Self::Flat => "flat",
            Self::Gouraud => "gouraud",
            Self::Phong => "phong",
            Self::MetallicRoughness => "metallic-roughness",
            Self::Depth { .. } => "depth",
            Self::Normals => "normals",
        }
    }
}
