//! glTF materials as the renderer's [`ModelMaterial`]s: base colour, normal and emissive maps, double-sidedness, and
//! the metallic-roughness model approximated by a Blinn-Phong highlight.

use gltf::texture::Info;
use rastty_core::color::{SRGB_DECODE, linear_to_srgb, linear_to_srgb8};
use rastty_core::math::{Vec2, Vec3};
use rastty_core::shading::brdf::DIELECTRIC_F0;

use super::material::ModelMaterial;
use super::texture_image::TextureImage;

/// The Blinn-Phong exponent's range: a roughness of 0 would give an infinite exponent.
const SHININESS_RANGE: (f32, f32) = (1.0, 1024.0);

/// A texture transform (`KHR_texture_transform`): `uv' = T(offset) R(rotation) S(scale) uv`, in glTF's
/// texture space (`v` down).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct UvTransform {
    /// Added last.
    pub offset: [f32; 2],
    /// Radians, counter-clockwise in texture space.
    pub rotation: f32,
    /// Applied first.
    pub scale: [f32; 2],
}

impl UvTransform {
    /// No change.
    pub const IDENTITY: Self = Self { offset: [0.0, 0.0], rotation: 0.0, scale: [1.0, 1.0] };

    /// The transform of a texture reference, or the identity without the extension.
    pub fn of(info: &gltf::texture::Info<'_>) -> Self {
        info.texture_transform().map_or(Self::IDENTITY, |t| Self {
            offset: t.offset(),
            rotation: t.rotation(),
            scale: t.scale(),
        })
    }

    /// `uv` (glTF space, `v` down) transformed (the extension's matrix: `x' = cos r sx x + sin r sy y + ox`,
    /// `y' = -sin r sx x + cos r sy y + oy`).
    pub fn apply(&self, uv: [f32; 2]) -> [f32; 2] {
        let (s, c) = self.rotation.sin_cos();
        let (x, y) = (uv[0] * self.scale[0], uv[1] * self.scale[1]);
        [c * x + s * y + self.offset[0], -s * x + c * y + self.offset[1]]
    }
}

/// A glTF texture coordinate (`v` down, from the image's top) as the renderer's (`v` up).
pub(crate) fn renderer_uv(uv: [f32; 2]) -> Vec2 {
    Vec2::new(uv[0], 1.0 - uv[1])
}

/// The renderer's material for glTF material `material`, with `image` giving decoded images by index, and the
/// transform to bake into the texture coordinates of its primitives: the base colour texture's, else the
/// emissive texture's (`KHR_texture_transform`). `warn` hears what is approximated or left out.
pub(crate) fn convert(
    material: &gltf::Material<'_>,
    mut image: impl FnMut(usize) -> Option<TextureImage>,
    mut warn: impl FnMut(String),
) -> (ModelMaterial, UvTransform) {
    let label = match material.name() {
        Some(name) => format!("material {:?}", crate::escaped::Escaped(name).to_string()),
        None => format!("material {}", material.index().map_or_else(|| "(default)".into(), |i| i.to_string())),
    };
    let pbr = material.pbr_metallic_roughness();
    let [r, g, b, a] = pbr.base_color_factor();
    let base = Vec3::new(r, g, b);
    let base = if base.is_finite() { base.max(Vec3::ZERO).min(Vec3::ONE) } else { Vec3::ONE };
    let (base_texture, normal_texture) = (pbr.base_color_texture(), material.normal_texture());
    let emissive_texture = material.emissive_texture();
    let occlusion_texture = material.occlusion_texture();
    let metallic_roughness_texture = pbr.metallic_roughness_texture();
    let sets = [
        ("base colour", base_texture.as_ref().map(Info::tex_coord)),
        ("normal", normal_texture.as_ref().map(|n| n.tex_coord())),
        ("emissive", emissive_texture.as_ref().map(Info::tex_coord)),
        ("occlusion", occlusion_texture.as_ref().map(|o| o.tex_coord())),
        ("metallic-roughness", metallic_roughness_texture.as_ref().map(Info::tex_coord)),
    ];
    for (role, set) in sets {
        if let Some(set) = set.filter(|&set| set != 0) {
            warn(format!("{label}: the {role} texture uses texture coordinates {set}; set 0 is used"));
        }
    }
    let transforms: Vec<UvTransform> =
        [&base_texture, &emissive_texture].into_iter().flatten().map(UvTransform::of).collect();
    let texture = base_texture.and_then(|info| image(info.texture().source().index()));
    let normal_map =
        normal_texture.and_then(|n| image(n.texture().source().index()).map(|map| scaled_normals(map, n.scale())));
    let strength = material.emissive_strength().unwrap_or(1.0);
    let [er, eg, eb] = material.emissive_factor();
    let emissive = Vec3::new(er, eg, eb) * strength;
    let emissive = if emissive.is_finite() { emissive.max(Vec3::ZERO) } else { Vec3::ZERO };
    let glow_map = match emissive_texture.and_then(|info| image(info.texture().source().index())) {
        Some(map) => Some(tinted(map, emissive)),
        None if emissive != Vec3::ZERO => Some(tinted(TextureImage::new(1, 1, vec![0xFF_FF_FF]), emissive)),
        None => None,
    };
    let metallic = finite_unit(pbr.metallic_factor(), 1.0);
    let roughness = finite_unit(pbr.roughness_factor(), 1.0);
    let metallic_roughness_map = metallic_roughness_texture.and_then(|info| image(info.texture().source().index()));
    let occlusion_map = occlusion_texture
        .and_then(|o| image(o.texture().source().index()).map(|map| occlusion_grey(map, o.strength())));
    let alpha_cutoff = match material.alpha_mode() {
        gltf::material::AlphaMode::Opaque => None,
        // The specification's default cut-off is 0.5; one that is not finite cuts everything out.
        gltf::material::AlphaMode::Mask => Some(material.alpha_cutoff().unwrap_or(0.5)),
        gltf::material::AlphaMode::Blend => {
            warn(format!("{label}: alpha mode BLEND is drawn opaque (no blending)"));
            None
        }
    };
    let uv_transform = transforms.first().copied().unwrap_or(UvTransform::IDENTITY);
    if transforms.iter().any(|t| *t != uv_transform) {
        warn(format!("{label}: its maps have different texture transforms; the base colour's is used for all"));
    }
    let (specular, shininess) = highlight(base, metallic, roughness);
    let converted = ModelMaterial {
        name: material.name().unwrap_or_default().to_owned(),
        // Linear in glTF; a `ModelMaterial` holds every colour sRGB-encoded (decoded again for linear light).
        diffuse: base.map(linear_to_srgb),
        texture,
        normal_map,
        glow_map,
        occlusion_map,
        metallic_roughness_map,
        specular: Some(specular.map(linear_to_srgb)),
        shininess: Some(shininess),
        metallic: Some(metallic),
        roughness: Some(roughness),
        double_sided: material.double_sided(),
        opacity: finite_unit(a, 1.0),
        alpha_cutoff,
    };
    (converted, uv_transform)
}

/// The highlight for metallic-roughness factors: colour `F0 = mix(0.04, base, metallic)` (the glTF 2.0
/// specification's appendix B), exponent `2 / a^2 - 2` with `a = roughness^2`, the Blinn-Phong exponent whose lobe
/// matches a microfacet distribution of that width (Walter et al., "Microfacet Models for Refraction", 2007,
/// eq. 29), clamped to 1..=1024. The diffuse colour stays the base colour: with lamps alone and no reflected
/// surroundings, a metal darkened as the specification's BRDF does would be black.
fn highlight(base: Vec3, metallic: f32, roughness: f32) -> (Vec3, f32) {
    let f0 = Vec3::splat(DIELECTRIC_F0).lerp(base, metallic);
    let a = roughness * roughness;
    let shininess = if a > 0.0 { 2.0 / (a * a) - 2.0 } else { SHININESS_RANGE.1 };
    (f0, shininess.clamp(SHININESS_RANGE.0, SHININESS_RANGE.1))
}

/// glTF's occlusion texture as grey texels: its red channel `r` (in `[0, 1]`) becomes `1 + strength (r - 1)`
/// (the specification's `lerp(1, r, strength)`, strength clamped to `[0, 1]`), in every channel, opaque.
fn occlusion_grey(mut map: TextureImage, strength: f32) -> TextureImage {
    let strength = finite_unit(strength, 1.0);
    for t in &mut map.texels {
        let r = ((*t >> 16) & 0xFF) as f32 / 255.0;
        let grey = ((1.0 + strength * (r - 1.0)) * 255.0).round().clamp(0.0, 255.0) as u32;
        *t = grey * 0x01_0101;
    }
    map
}

/// `value` clamped to `[0, 1]`, or `default` when it is not finite.
fn finite_unit(value: f32, default: f32) -> f32 {
    if value.is_finite() { value.clamp(0.0, 1.0) } else { default }
}

/// `map`'s texels (sRGB) times `factor` (linear), in linear light: each channel decoded, scaled and encoded to the
/// nearest code (255 at most).
fn tinted(mut map: TextureImage, factor: Vec3) -> TextureImage {
    let scale = |texel: u32, shift: u32, f: f32| -> u32 {
        linear_to_srgb8(SRGB_DECODE[((texel >> shift) & 0xFF) as usize] * f) << shift
    };
    for t in &mut map.texels {
        *t = scale(*t, 16, factor.x) | scale(*t, 8, factor.y) | scale(*t, 0, factor.z);
    }
    map
}

/// A tangent-space normal map with glTF's `scale` applied: `normalize(x * scale, y * scale, z)` per texel (glTF
/// 2.0 specification, `normalTextureInfo.scale`), stored again as `rgb = n * 0.5 + 0.5`.
fn scaled_normals(mut map: TextureImage, scale: f32) -> TextureImage {
    if scale == 1.0 || !scale.is_finite() {
        return map;
    }
    let decode = |c: u32| (c & 0xFF) as f32 / 255.0 * 2.0 - 1.0;
    let encode = |v: f32| ((v * 0.5 + 0.5) * 255.0).round().clamp(0.0, 255.0) as u32;
    for t in &mut map.texels {
        let n = Vec3::new(decode(*t >> 16) * scale, decode(*t >> 8) * scale, decode(*t));
        let n = n.try_normalize().unwrap_or(Vec3::Z);
        *t = (encode(n.x) << 16) | (encode(n.y) << 8) | encode(n.z);
    }
    map
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texture_transforms_follow_the_extension() {
        let t = UvTransform { offset: [0.5, 0.25], rotation: 0.0, scale: [2.0, 3.0] };
        assert_eq!(t.apply([1.0, 1.0]), [2.5, 3.25]);
        let quarter = UvTransform { rotation: std::f32::consts::FRAC_PI_2, ..UvTransform::IDENTITY };
        let [x, y] = quarter.apply([1.0, 0.0]);
        assert!((x - 0.0).abs() < 1e-6 && (y + 1.0).abs() < 1e-6, "{x} {y}");
        assert_eq!(renderer_uv([0.25, 0.0]), Vec2::new(0.25, 1.0));
    }

    #[test]
    fn highlights_narrow_as_roughness_falls_and_take_the_colour_of_metals() {
        let red = Vec3::new(1.0, 0.0, 0.0);
        assert_eq!(highlight(red, 0.0, 1.0), (Vec3::splat(0.04), 1.0));
        assert_eq!(highlight(red, 1.0, 0.5).0, red);
        // a = 0.25: 2 / 0.0625 - 2 = 30.
        assert_eq!(highlight(red, 1.0, 0.5).1, 30.0);
        assert_eq!(highlight(red, 0.0, 0.0).1, 1024.0);
    }

    #[test]
    fn occlusion_takes_the_red_channel_at_its_strength() {
        let map = TextureImage::new(3, 1, vec![0xFF00_00FF, 0x0080_FFFF, 0x00FF_0000]);
        assert_eq!(occlusion_grey(map.clone(), 1.0).texels, [0x00_0000, 0x80_8080, 0xFF_FFFF]);
        // Half strength: 1 + 0.5 (r - 1), so black becomes 0.5 (128) and 0x80 (0.502) 0.751 (192).
        assert_eq!(occlusion_grey(map.clone(), 0.5).texels, [0x80_8080, 0xC0_C0C0, 0xFF_FFFF]);
        assert_eq!(occlusion_grey(map, 0.0).texels, [0xFF_FFFF; 3]);
    }

    #[test]
    fn emission_and_normal_scale_change_the_texels() {
        let white = TextureImage::new(1, 1, vec![0xFF_FF_FF]);
        // Half of white's light is code 188.
        assert_eq!(tinted(white, Vec3::new(1.0, 0.5, 2.0)).texels, vec![0xFF_BC_FF]);
        // (0, 0, 1) stays; a tilted normal flattens with scale 0.
        let flat = TextureImage::new(1, 1, vec![0x80_80_FF]);
        assert_eq!(scaled_normals(flat.clone(), 0.0).texels, flat.texels);
        let tilted = TextureImage::new(1, 1, vec![0xFF_80_80]);
        assert_eq!(scaled_normals(tilted, 0.0).texels, vec![0x80_80_FF]);
    }
}
