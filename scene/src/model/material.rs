//! Surface materials of a model's parts: what the renderer needs of an MTL `newmtl` entry or a glTF material.

use rastty_core::math::Vec3;

use super::texture_image::TextureImage;

/// The diffuse colour of a material whose MTL entry has no (usable) `Kd`, and of parts without a material.
pub const DEFAULT_DIFFUSE: Vec3 = Vec3::splat(0.8);

/// A material: a colour and the maps and settings a model file gave for one of its parts. An OBJ file's MTL
/// entries give the colour and the diffuse texture; a glTF material can give every field (see
/// `docs/models.md` for how glTF's metallic-roughness model is mapped to these).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelMaterial {
    /// The name given by `newmtl` or the glTF material, raw (it may hold control characters: sanitise before
    /// printing).
    pub name: String,
    /// Diffuse colour, sRGB-encoded like every colour a scene writes (`Kd`, or glTF's base colour factor, which
    /// is linear, encoded), each component clamped to `[0, 1]`; [`DEFAULT_DIFFUSE`] when absent or not finite.
    pub diffuse: Vec3,
    /// The diffuse texture (`map_Kd`, or glTF's base colour texture), when it names an image that could be read and
    /// decoded.
    pub texture: Option<TextureImage>,
    /// A tangent-space normal map (glTF's normal texture, its scale applied to the texels).
    pub normal_map: Option<TextureImage>,
    /// Emitted light, added to the lit colour (glTF's emissive texture times its factor and strength, or the
    /// factor alone as one texel).
    pub glow_map: Option<TextureImage>,
    /// Scales the ambient light per texel (glTF's occlusion texture: its red channel `r` as the grey
    /// `1 + strength (r - 1)`).
    pub occlusion_map: Option<TextureImage>,
    /// Scales the metallic factor by its blue channel and the roughness by its green one, per texel (glTF's
    /// metallic-roughness texture); read by the metallic-roughness model alone.
    pub metallic_roughness_map: Option<TextureImage>,
    /// The highlight's colour, sRGB-encoded, when the file gives one (glTF: from metallic and roughness); `None`
    /// keeps the renderer's default.
    pub specular: Option<Vec3>,
    /// The highlight's Blinn-Phong exponent, when the file gives one (glTF: from roughness).
    pub shininess: Option<f32>,
    /// How much of a metal the surface is, 0 to 1, under the metallic-roughness model (glTF's `metallicFactor`);
    /// `None` keeps the renderer's default (a dielectric).
    pub metallic: Option<f32>,
    /// The perceptual roughness, 0 to 1, under the metallic-roughness model (glTF's `roughnessFactor`); `None`
    /// keeps the renderer's default (1).
    pub roughness: Option<f32>,
    /// Both faces of each triangle are drawn (glTF's `doubleSided`); otherwise back faces are culled.
    pub double_sided: bool,
    /// The surface's alpha (glTF's base colour factor's), times the texture's; read only with `alpha_cutoff`.
    pub opacity: f32,
    /// Fragments whose alpha is below this are not drawn (glTF's alpha mode `MASK` and its `alphaCutoff`).
    pub alpha_cutoff: Option<f32>,
}

impl Default for ModelMaterial {
    /// An unnamed, untextured, one-sided material of [`DEFAULT_DIFFUSE`].
    fn default() -> Self {
        Self {
            name: String::new(),
            diffuse: DEFAULT_DIFFUSE,
            texture: None,
            normal_map: None,
            glow_map: None,
            occlusion_map: None,
            metallic_roughness_map: None,
            specular: None,
            shininess: None,
            metallic: None,
            roughness: None,
            double_sided: false,
            opacity: 1.0,
            alpha_cutoff: None,
        }
    }
}

/// The diffuse colour for a `Kd` entry, or `None` when it is present but not finite (use the default and warn).
pub(crate) fn diffuse_from_kd(kd: Option<[f32; 3]>) -> Option<Vec3> {
    match kd {
        None => Some(DEFAULT_DIFFUSE),
        Some(c) if c.iter().all(|v| v.is_finite()) => {
            Some(Vec3::new(c[0].clamp(0.0, 1.0), c[1].clamp(0.0, 1.0), c[2].clamp(0.0, 1.0)))
        }
        Some(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kd_is_clamped_defaulted_or_refused() {
        assert_eq!(diffuse_from_kd(None), Some(DEFAULT_DIFFUSE));
        assert_eq!(diffuse_from_kd(Some([0.25, 2.0, -1.0])), Some(Vec3::new(0.25, 1.0, 0.0)));
        assert_eq!(diffuse_from_kd(Some([f32::NAN, 0.0, 0.0])), None);
    }
}
