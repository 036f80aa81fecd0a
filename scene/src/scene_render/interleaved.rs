//! A part's maps of one size stored texel by texel in one buffer ([`Texture::interleaved`]), and their levels of
//! detail likewise: a fragment reads all of its material's maps at the same texel, so one cache line brings in
//! what would otherwise take one line per map. The samples are the same as the images' own.

use std::collections::HashMap;
use std::sync::Arc;

use rastty_core::texture::{MAX_INTERLEAVED, MipContent, Texture, TextureError};

use crate::model::TextureImage;
use crate::scene_file::SceneObject;

/// What a map is to its material (its discriminant is its place in a [`PartMaps`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapRole {
    /// The diffuse texture (the scene's, else the part's MTL `map_Kd`).
    Diffuse,
    /// The normal map.
    Normal,
    /// The specular map.
    Specular,
    /// The glow map.
    Glow,
    /// The occlusion map (the part's own: scene files have no key for it).
    Occlusion,
    /// The metallic-roughness map (the part's own, glTF's: scene files have no key for it).
    MetallicRoughness,
}

impl MapRole {
    /// What the texels of a map in this role mean: colour (diffuse, specular, glow) or data (normals, occlusion,
    /// metallic-roughness),
    /// which decides how its levels of detail are averaged.
    pub fn content(self) -> MipContent {
        match self {
            Self::Diffuse | Self::Specular | Self::Glow => MipContent::Color,
            Self::Normal | Self::Occlusion | Self::MetallicRoughness => MipContent::Data,
        }
    }
}

/// Interleaved buffers already made, texels and levels of detail, by the addresses of their images in order:
/// parts (of any object) with the same maps share them.
pub(crate) type InterleavedBuffers = HashMap<Vec<usize>, Interleaved>;

/// The texels of maps of one size, interleaved, and their levels of detail, interleaved likewise.
#[derive(Clone, Debug)]
pub struct Interleaved {
    texels: Arc<[u32]>,
    levels: Arc<[u32]>,
}

/// Where one map of a part sits in an interleaved buffer.
#[derive(Clone, Debug)]
struct Place {
    /// The address of the image it was made from: the place is used only for that image.
    image: usize,
    buffers: Interleaved,
    width: u32,
    height: u32,
    maps: u32,
    map: u32,
}

/// The maps of one part, each interleaved with the part's other maps of its size. A map with no other of its size
/// (or none at all) has no place: it is read from its image.
#[derive(Clone, Debug)]
pub struct PartMaps {
    /// Per [`MapRole`], indexed by its discriminant.
    places: [Option<Place>; 6],
}

impl PartMaps {
    /// No map interleaved: every map is read from its image.
    pub const NONE: Self = Self { places: [None, None, None, None, None, None] };

    /// Interleaves the maps that part `part_index` of `object` has, whether or not their effects are switched on
    /// (the switches change per frame), with their levels of detail when the object's material reads them,
    /// taking and leaving buffers in `made`.
    pub fn new(object: &SceneObject, part_index: usize, made: &mut InterleavedBuffers) -> Self {
        let m = &object.material;
        let mtl = object.model.part_material(part_index);
        let images: [Option<&TextureImage>; 6] = [
            m.diffuse_over(mtl),
            m.normal_over(mtl).map(|(image, _)| image),
            m.specular_map.as_deref(),
            m.glow_over(mtl),
            mtl.and_then(|mtl| mtl.occlusion_map.as_ref()),
            mtl.and_then(|mtl| mtl.metallic_roughness_map.as_ref()),
        ];
        let mut part = Self::NONE;
        const ROLES: [MapRole; 6] = [
            MapRole::Diffuse,
            MapRole::Normal,
            MapRole::Specular,
            MapRole::Glow,
            MapRole::Occlusion,
            MapRole::MetallicRoughness,
        ];
        // Groups of distinct images of one size with their first role, in role order; an image in two roles is
        // stored once.
        let mut groups: Vec<Vec<(&TextureImage, MapRole)>> = Vec::new();
        for (image, role) in images.into_iter().zip(ROLES).filter_map(|(image, role)| Some((image?, role))) {
            let consistent = image.texels.len() == image.width as usize * image.height as usize;
            if !consistent {
                continue; // read from the image, which reports it
            }
            match groups.iter_mut().find(|g| (g[0].0.width, g[0].0.height) == (image.width, image.height)) {
                Some(group) if group.iter().any(|(g, _)| std::ptr::eq(*g, image)) => {}
                Some(group) => group.push((image, role)),
                None => groups.push(vec![(image, role)]),
            }
        }
        let mipmapped = m.reads_mip_levels();
        for group in groups.iter().filter(|g| g.len() >= 2 && g.len() <= MAX_INTERLEAVED as usize) {
            let mut key: Vec<usize> = group.iter().map(|(image, _)| address(image)).collect();
            key.push(usize::from(mipmapped));
            let buffers = made.entry(key).or_insert_with(|| interleave(group, mipmapped)).clone();
            for (role, image) in images.iter().enumerate() {
                let Some(image) = image else { continue };
                let Some(map) = group.iter().position(|(g, _)| std::ptr::eq(*g, *image)) else { continue };
                let (width, height, maps, map) = (image.width, image.height, group.len() as u32, map as u32);
                let buffers = buffers.clone();
                part.places[role] = Some(Place { image: address(image), buffers, width, height, maps, map });
            }
        }
        part
    }

    /// The map `image` in `role` as the core samples it from the interleaved buffer, with its levels of detail,
    /// or `None` when that role's map is not interleaved or was made from another image (these maps belong to
    /// another part).
    pub fn texture(&self, role: MapRole, image: &TextureImage) -> Option<Result<Texture<'_>, TextureError>> {
        let p = self.places[role as usize].as_ref().filter(|p| p.image == address(image))?;
        let texture = Texture::interleaved(&p.buffers.texels, p.width, p.height, p.maps, p.map);
        let levels = &p.buffers.levels;
        Some(texture.and_then(|texture| if levels.is_empty() { Ok(texture) } else { texture.with_mip_levels(levels) }))
    }
}

/// An image's address: what identifies it among a scene's images (they are not moved while a scene is prepared).
fn address(image: &TextureImage) -> usize {
    std::ptr::from_ref(image) as usize
}

/// The texels of `images` (all of one size, each with its role) texel by texel, texel `i` of image `k` at
/// `i * images.len() + k`, and when `mipmapped` their levels of detail likewise (each image's own, as its role's
/// content; none otherwise).
fn interleave(images: &[(&TextureImage, MapRole)], mipmapped: bool) -> Interleaved {
    let texels = (0..images[0].0.texels.len()).flat_map(|i| images.iter().map(move |(image, _)| image.texels[i]));
    if !mipmapped {
        return Interleaved { texels: texels.collect(), levels: Arc::new([]) };
    }
    // The images are consistent (checked when grouped): their levels can be built.
    let levels: Vec<&[u32]> =
        images.iter().map(|(image, role)| image.mip_levels(role.content()).unwrap_or(&[])).collect();
    let interleaved_levels =
        (0..levels[0].len()).flat_map(|i| levels.iter().map(move |l| l.get(i).copied().unwrap_or(0)));
    Interleaved { texels: texels.collect(), levels: interleaved_levels.collect() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rastty_core::math::Vec2;
    use rastty_core::texture::{Bilinear, Clamp, Filter, Footprint, LEVEL, MipFilter, Nearest, Repeat};

    /// The ground of `spot_lamp.toml` has four 64x64 maps: one buffer holds them all, a second part with the
    /// same images shares it, and every map samples exactly as its image does, at every level of detail.
    #[test]
    fn a_parts_maps_share_one_buffer_and_sample_as_their_images() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/scenes/spot_lamp.toml");
        let data = crate::scene_file::load(path).unwrap();
        let ground = data.objects.iter().find(|o| o.material.glow_map.is_some()).unwrap();
        let mut made = InterleavedBuffers::new();
        let maps = PartMaps::new(ground, 0, &mut made);
        let again = PartMaps::new(ground, 0, &mut made);
        assert_eq!(made.len(), 1);
        let m = &ground.material;
        let images = [m.diffuse.as_deref(), Some(&*m.normal_map.as_ref().unwrap().image), m.specular_map.as_deref()];
        let images = [images[0], images[1], images[2], m.glow_map.as_deref()].map(Option::unwrap);
        let uv: [Vec2; 64] = core::array::from_fn(|i| Vec2::new(i as f32 * 0.0731 - 1.2, 2.1 - i as f32 * 0.0517));
        fn same<F: Filter>(a: &Texture<'_>, b: &Texture<'_>, uv: &[Vec2]) {
            let (a, b) = (a.mip_chain(), b.mip_chain());
            assert_eq!(a.level_count(), 7);
            assert_eq!(b.level_count(), 7);
            for &uv in uv {
                for lod in (0..7 * LEVEL).step_by(77) {
                    let (mip, lod) = (MipFilter::Linear, &Footprint::at_level(lod));
                    assert_eq!(a.sample_packed::<F, Repeat>(uv, lod, mip), b.sample_packed::<F, Repeat>(uv, lod, mip));
                    assert_eq!(a.sample_packed::<F, Clamp>(uv, lod, mip), b.sample_packed::<F, Clamp>(uv, lod, mip));
                    assert_eq!(a.sample_light::<F, Repeat>(uv, lod, mip), b.sample_light::<F, Repeat>(uv, lod, mip));
                    assert_eq!(a.sample_light::<F, Clamp>(uv, lod, mip), b.sample_light::<F, Clamp>(uv, lod, mip));
                }
            }
        }
        for (role, image) in
            [MapRole::Diffuse, MapRole::Normal, MapRole::Specular, MapRole::Glow].into_iter().zip(images)
        {
            let place = maps.places[role as usize].as_ref().unwrap();
            assert_eq!((place.maps, place.map), (4, role as u32));
            let shared = &again.places[role as usize].as_ref().unwrap().buffers;
            assert!(Arc::ptr_eq(&place.buffers.texels, &shared.texels));
            assert!(Arc::ptr_eq(&place.buffers.levels, &shared.levels));
            let own = image.mipmapped(role.content()).unwrap();
            let interleaved = maps.texture(role, image).unwrap().unwrap();
            // Another image in the same role is read from that image.
            assert!(maps.texture(role, images[(role as usize + 1) % 4]).is_none());
            same::<Nearest>(&own, &interleaved, &uv);
            same::<Bilinear>(&own, &interleaved, &uv);
        }
    }

    /// A map alone in its size is read from its image; one image in two roles is stored once.
    #[test]
    fn maps_alone_in_their_size_are_not_interleaved() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../assets/scenes/spot_lamp.toml");
        let mut data = crate::scene_file::load(path).unwrap();
        let ground = data.objects.iter_mut().find(|o| o.material.glow_map.is_some()).unwrap();
        let diffuse = ground.material.diffuse.clone().unwrap();
        // The glow map is the diffuse image again, and the specular map another size.
        ground.material.glow_map = Some(diffuse);
        ground.material.specular_map = Some(Arc::new(TextureImage::new(2, 1, vec![0x102030, 0x405060])));
        let maps = PartMaps::new(ground, 0, &mut InterleavedBuffers::new());
        let place = |role: MapRole| maps.places[role as usize].as_ref().map(|p| (p.maps, p.map));
        assert_eq!(place(MapRole::Diffuse), Some((2, 0)));
        assert_eq!(place(MapRole::Normal), Some((2, 1)));
        assert_eq!(place(MapRole::Specular), None);
        assert_eq!(place(MapRole::Glow), Some((2, 0)));
        assert!(maps.texture(MapRole::Specular, ground.material.specular_map.as_ref().unwrap()).is_none());
    }
}
