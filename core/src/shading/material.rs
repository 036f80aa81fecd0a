//! A surface's material with its maps: what a draw colours its pixels with.

use crate::color::unpack_rgb888;
use crate::math::Vec3;
use crate::texture::{FilterMode, MipFilter, Texture, WrapMode};

/// The space a normal map's normals are given in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalSpace {
    /// Relative to the surface: `x` along the tangent (increasing `u`), `y` along the bitangent (increasing `v`),
    /// `z` along the interpolated normal. Needs per-vertex tangents ([`crate::mesh::compute_tangents`]).
    Tangent,
    /// In the mesh's own coordinates; transformed to world space with the normal matrix.
    Object,
}

/// A normal map: each texel a unit normal, 8 bits per component.
///
/// A code `c` decodes to `(c - 128) / 127`, so `128` is exactly 0 and `255` exactly 1: the flat tangent-space
/// texel `(128, 128, 255)` gives back the interpolated normal bit for bit. (The common `c / 255 * 2 - 1` has no
/// exact zero.) Code 0 gives `-1.008`; the decoded normal is normalised, so the asymmetry is immaterial.
#[derive(Clone, Copy, Debug)]
pub struct NormalMap<'a> {
    /// The texels.
    pub texture: Texture<'a>,
    /// Tangent or object space.
    pub space: NormalSpace,
}

/// How a surface looks: colours, Blinn-Phong exponent, and optional maps, all sampled with one filter, wrap mode
/// and filter between levels of detail.
///
/// The colours are the values lighting multiplies: linear light when the draw lights in
/// [`crate::color::ShadingSpace::Linear`] (decode a colour picked on a screen with
/// [`crate::color::srgb_to_linear`]), the stored values otherwise. The maps' texels are sRGB codes either way.
#[derive(Clone, Copy, Debug)]
pub struct Material<'a> {
    /// Diffuse colour; multiplied by `diffuse` when there is one.
    pub color: Vec3,
    /// Specular colour; zero turns highlights off (and the draw then computes none). Multiplied by
    /// `specular_map` when there is one.
    pub specular: Vec3,
    /// Blinn-Phong exponent.
    pub shininess: f32,
    /// How much of a metal the surface is under the metallic-roughness model, 0 to 1 (read by it alone; glTF's
    /// `metallicFactor`).
    pub metallic: f32,
    /// The surface's perceptual roughness under the metallic-roughness model, 0 (a mirror) to 1 (read by it alone;
    /// glTF's `roughnessFactor`).
    pub roughness: f32,
    /// The diffuse (albedo) texture.
    pub diffuse: Option<Texture<'a>>,
    /// The normal map.
    pub normal_map: Option<NormalMap<'a>>,
    /// Scales `specular` per texel.
    pub specular_map: Option<Texture<'a>>,
    /// Light the surface emits itself, added after lighting.
    pub glow_map: Option<Texture<'a>>,
    /// Scales the ambient light per texel, channel by channel (glTF's occlusion texture, whose red channel and
    /// strength a loader turns into grey texels). Read by per-pixel lighting only.
    pub occlusion_map: Option<Texture<'a>>,
    /// Scales `metallic` by its blue channel and `roughness` by its green one, per texel (glTF's
    /// metallic-roughness texture: data, never decoded from sRGB). Read by the metallic-roughness model only.
    pub metallic_roughness_map: Option<Texture<'a>>,
    /// Filter of every map.
    pub filter: FilterMode,
    /// Wrap mode of every map.
    pub wrap: WrapMode,
    /// How every map chooses among its levels of detail, where it has them ([`Texture::with_mip_levels`]): a
    /// draw none of whose maps has levels samples the maps alone.
    pub mip_filter: MipFilter,
    /// The surface's alpha, times the diffuse map's ([`crate::color::texel_alpha`]); read only with an
    /// `alpha_cutoff`.
    pub opacity: f32,
    /// Alpha cut-out: a fragment whose alpha (`opacity` times the diffuse map's, as `a / 255`) is below this is
    /// discarded, its depth and colour left as they were (glTF's alpha mode `MASK`). A surface without a diffuse
    /// map is drawn whole or, when `opacity` is below the cut-off, not at all. Read by the shading models that
    /// colour (not the depth and normals views), and not by shadow maps, whose casters are drawn whole.
    pub alpha_cutoff: Option<f32>,
}

impl Default for Material<'_> {
    /// A plain light grey (0.8), no highlights, no maps.
    fn default() -> Self {
        Self::plain(Vec3::splat(0.8))
    }
}

impl Material<'_> {
    /// A plain material: `color`, no highlights, no maps (bilinear, repeating and blending levels of detail when
    /// some are given); under the metallic-roughness model a dielectric of roughness 1.
    pub const fn plain(color: Vec3) -> Self {
        Self {
            color,
            specular: Vec3::ZERO,
            shininess: 32.0,
            metallic: 0.0,
            roughness: 1.0,
            diffuse: None,
            normal_map: None,
            specular_map: None,
            glow_map: None,
            occlusion_map: None,
            metallic_roughness_map: None,
            filter: FilterMode::Bilinear,
            wrap: WrapMode::Repeat,
            mip_filter: MipFilter::Linear,
            opacity: 1.0,
            alpha_cutoff: None,
        }
    }

    /// Whether a fragment whose diffuse-map alpha is `texel_alpha` (`0..=255`) is kept under `cutoff`: `opacity`
    /// times `texel_alpha / 255` at least `cutoff`. One expression for every path, so that they keep the same
    /// fragments.
    #[inline(always)]
    pub(crate) fn keeps(&self, texel_alpha: u32, cutoff: f32) -> bool {
        texel_alpha as f32 * (self.opacity * (1.0 / 255.0)) >= cutoff
    }
}

/// The metallic factor and the roughness of a fragment under the metallic-roughness model: the material's
/// `metallic` and `roughness`, times the blue and green channels of its metallic-roughness map's texel `texel`
/// (packed, as stored) where the draw reads one.
#[inline(always)]
pub(crate) fn metallic_roughness(metallic: f32, roughness: f32, texel: Option<u32>) -> (f32, f32) {
    match texel {
        Some(texel) => {
            let t = unpack_rgb888(texel);
            (metallic * t.z, roughness * t.y)
        }
        None => (metallic, roughness),
    }
}

/// Decodes a normal-map texel (see [`NormalMap`]); not normalised.
#[inline(always)]
pub(crate) fn decode_normal(texel: u32) -> Vec3 {
    const S: f32 = 1.0 / 127.0;
    let c = |shift: u32| (((texel >> shift) & 0xFF) as i32 - 128) as f32 * S;
    Vec3::new(c(16), c(8), c(0))
}
