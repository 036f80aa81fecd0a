//! The core material of one part of an object: the scene file's material keys over the part's MTL material, with
//! the maps of switched-off effects left out.

use rastty_core::color::ShadingSpace;
use rastty_core::math::Vec3;
use rastty_core::pipeline::{Cull, DrawState};
use rastty_core::shading::{Material, NormalMap, NormalSpace as CoreNormalSpace};
use rastty_core::texture::TextureError;

use super::interleaved::{MapRole, PartMaps};
use super::{PlanOptions, lit_color};
use crate::model::TextureImage;
use crate::scene_file::defaults::{METALLIC, ROUGHNESS, SHININESS, SPECULAR};
use crate::scene_file::{NormalSpaceSpec, SceneObject};

/// The material of part `part` of `object`:
///
/// - colour and diffuse texture: the scene's `color` and `diffuse` when given, else the part's MTL `Kd` and
///   `map_Kd` ([`crate::scene_file::ObjectMaterial::color_over`] and `diffuse_over`); no texture when
///   `options.textures` is off;
/// - specular colour: the scene's `specular`, else the part's own (glTF), else [`SPECULAR`]; zero (no highlights,
///   and no specular map) when the specular effect is off;
/// - both colours as lit in `space` ([`lit_color`]: the scene's and the model's colours are sRGB-encoded);
/// - shininess: the scene's, else the part's own, else [`SHININESS`];
/// - metallic and roughness (read by the metallic-roughness model alone): the scene's, else the part's own
///   (glTF), else [`METALLIC`] and [`ROUGHNESS`];
/// - normal and glow maps: the scene's, else the part's own (glTF), unless their effect is off;
/// - the metallic-roughness map: the part's own (glTF);
/// - filter, wrap and filter between levels of detail: the scene's, for every map (each map with its levels).
///
/// Each map is read from `maps` (the part's [`crate::scene_render::PreparedScene::part_maps`]) when interleaved
/// there from the same image, else from its image: the same samples either way.
///
/// # Errors
/// [`TextureError`] for an image whose fields are inconsistent (only possible if changed by hand after loading).
pub fn part_material<'a>(
    object: &'a SceneObject,
    maps: &'a PartMaps,
    part: usize,
    space: ShadingSpace,
    options: &PlanOptions,
) -> Result<Material<'a>, TextureError> {
    let mtl = object.model.part_material(part);
    let m = &object.material;
    let effects = &options.effects;
    // Levels of detail are built (once per image) only for a material that reads them.
    let texture = |role: MapRole, image: &'a TextureImage| {
        maps.texture(role, image)
            .unwrap_or_else(|| if m.reads_mip_levels() { image.mipmapped(role.content()) } else { image.texture() })
    };
    let diffuse = match m.diffuse_over(mtl) {
        Some(image) if options.textures => Some(texture(MapRole::Diffuse, image)?),
        _ => None,
    };
    let normal_map = match m.normal_over(mtl) {
        Some((image, space)) if effects.normal_maps => {
            let space = match space {
                NormalSpaceSpec::Tangent => CoreNormalSpace::Tangent,
                NormalSpaceSpec::Object => CoreNormalSpace::Object,
            };
            Some(NormalMap { texture: texture(MapRole::Normal, image)?, space })
        }
        _ => None,
    };
    let specular =
        if effects.specular { lit_color(m.specular_over(mtl).unwrap_or(SPECULAR), space) } else { Vec3::ZERO };
    let specular_map = match &m.specular_map {
        Some(image) if effects.specular => Some(texture(MapRole::Specular, image)?),
        _ => None,
    };
    let glow_map = match m.glow_over(mtl) {
        Some(image) if effects.glow_maps => Some(texture(MapRole::Glow, image)?),
        _ => None,
    };
    let occlusion_map = match mtl.and_then(|mtl| mtl.occlusion_map.as_ref()) {
        Some(image) if effects.ambient_occlusion => Some(texture(MapRole::Occlusion, image)?),
        _ => None,
    };
    let metallic_roughness_map = match mtl.and_then(|mtl| mtl.metallic_roughness_map.as_ref()) {
        Some(image) => Some(texture(MapRole::MetallicRoughness, image)?),
        None => None,
    };
    Ok(Material {
        color: lit_color(m.color_over(mtl), space),
        specular,
        shininess: m.shininess_over(mtl).unwrap_or(SHININESS),
        metallic: m.metallic_over(mtl).unwrap_or(METALLIC),
        roughness: m.roughness_over(mtl).unwrap_or(ROUGHNESS),
        diffuse,
        normal_map,
        specular_map,
        glow_map,
        occlusion_map,
        metallic_roughness_map,
        filter: m.filter,
        wrap: m.wrap,
        mip_filter: m.mip_filter,
        opacity: mtl.map_or(1.0, |mtl| mtl.opacity),
        alpha_cutoff: mtl.and_then(|mtl| mtl.alpha_cutoff),
    })
}

/// How part `part` of `object` is drawn: both faces of each triangle when its material is double-sided (glTF's
/// `doubleSided`), else front faces only ([`DrawState::DEFAULT`]).
pub fn part_state(object: &SceneObject, part: usize) -> DrawState {
    let double_sided = object.model.part_material(part).is_some_and(|m| m.double_sided);
    if double_sided { DrawState { cull: Cull::None, ..DrawState::DEFAULT } } else { DrawState::DEFAULT }
}
