//! A part's maps of one size stored texel by texel in one buffer ([`Texture::interleaved`]): a fragment reads
//! all of its material's maps at the same texel, so one cache line brings in what would otherwise take one line per
//! map. The samples are the same as the images' own.

use std::collections::HashMap;
use std::sync::Arc;

use rastty_core::texture::{MAX_INTERLEAVED, Texture, TextureError};

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
}

/// Interleaved buffers already made, by the addresses of their images in order: parts (of any object) with the
/// same maps share one.
pub type InterleavedBuffers = HashMap<Vec<usize>, Arc<[u32]>>;

/// Where one map of a part sits in an interleaved buffer.
#[derive(Clone, Debug)]
struct Place {
    /// The address of the image it was made from: the place is used only for that image.
    image: usize,
    texels: Arc<[u32]>,
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
    places: [Option<Place>; 5],
}

impl PartMaps {
    /// No map interleaved: every map is read from its image.
    pub const NONE: Self = Self { places: [None, None, None, None, None] };

    /// Interleaves the maps that part `part_index` of `object` has, whether or not their effects are switched on
    /// (the switches change per frame), taking and leaving buffers in `made`.
    pub fn new(object: &SceneObject, part_index: usize, made: &mut InterleavedBuffers) -> Self {
        let m = &object.material;
        let mtl = object.model.part_material(part_index);
        let images: [Option<&TextureImage>; 5] = [
            m.diffuse_over(mtl),
            m.normal_over(mtl).map(|(image, _)| image),
            m.specular_map.as_deref(),
            m.glow_over(mtl),
            mtl.and_then(|mtl| mtl.occlusion_map.as_ref()),
        ];
        let mut part = Self::NONE;
        // Groups of distinct images of one size, in role order; an image in two roles is stored once.
        let mut groups: Vec<Vec<&TextureImage>> = Vec::new();
        for image in images.into_iter().flatten() {
            let consistent = image.texels.len() == image.width as usize * image.height as usize;
            if !consistent {
                continue; // read from the image, which reports it
            }
            match groups.iter_mut().find(|g| (g[0].width, g[0].height) == (image.width, image.height)) {
                Some(group) if group.iter().any(|g| std::ptr::eq(*g, image)) => {}
                Some(group) => group.push(image),
                None => groups.push(vec![image]),
            }
        }
        for group in groups.iter().filter(|g| g.len() >= 2 && g.len() <= MAX_INTERLEAVED as usize) {
            let key: Vec<usize> = group.iter().map(|image| address(image)).collect();
            let texels = made.entry(key).or_insert_with(|| interleave(group)).clone();
            for (role, image) in images.iter().enumerate() {
                let Some(image) = image else { continue };
                let Some(map) = group.iter().position(|g| std::ptr::eq(*g, *image)) else { continue };
                let (width, height, maps, map) = (group[0].width, group[0].height, group.len() as u32, map as u32);
                let texels = texels.clone();
                part.places[role] = Some(Place { image: address(image), texels, width, height, maps, map });
            }
        }
        part
    }

    /// The map `image` in `role` as the core samples it from the interleaved buffer, or `None` when that role's
    /// map is not interleaved or was made from another image (these maps belong to another part).
    pub fn texture(&self, role: MapRole, image: &TextureImage) -> Option<Result<Texture<'_>, TextureError>> {
        let p = self.places[role as usize].as_ref().filter(|p| p.image == address(image))?;
        Some(Texture::interleaved(&p.texels, p.width, p.height, p.maps, p.map))
    }
}

/// An image's address: what identifies it among a scene's images (they are not moved while a scene is prepared).
fn address(image: &TextureImage) -> usize {
    std::ptr::from_ref(image) as usize
}

/// The texels of `images` (all of one size) texel by texel: texel `i` of image `k` at `i * images.len() + k`.
fn interleave(images: &[&TextureImage]) -> Arc<[u32]> {
    let count = images[0].texels.len();
    (0..count).flat_map(|i| images.iter().map(move |image| image.texels[i])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rastty_core::math::Vec2;
    use rastty_core::texture::{Bilinear, Clamp, Filter, Nearest, Repeat};

    /// The ground of `spot_lamp.toml` has four 64x64 maps: one buffer holds them all, a second part with the
    /// same images shares it, and every map samples exactly as its image does.
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
            for &uv in uv {
                assert_eq!(F::sample_packed::<Repeat>(a, uv), F::sample_packed::<Repeat>(b, uv));
                assert_eq!(F::sample_packed::<Clamp>(a, uv), F::sample_packed::<Clamp>(b, uv));
            }
        }
        for (role, image) in
            [MapRole::Diffuse, MapRole::Normal, MapRole::Specular, MapRole::Glow].into_iter().zip(images)
        {
            let place = maps.places[role as usize].as_ref().unwrap();
            assert_eq!((place.maps, place.map), (4, role as u32));
            assert!(Arc::ptr_eq(&place.texels, &again.places[role as usize].as_ref().unwrap().texels));
            let (own, interleaved) = (image.texture().unwrap(), maps.texture(role, image).unwrap().unwrap());
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
        ground.material.specular_map =
            Some(Arc::new(TextureImage { width: 2, height: 1, texels: vec![0x102030, 0x405060] }));
        let maps = PartMaps::new(ground, 0, &mut InterleavedBuffers::new());
        let place = |role: MapRole| maps.places[role as usize].as_ref().map(|p| (p.maps, p.map));
        assert_eq!(place(MapRole::Diffuse), Some((2, 0)));
        assert_eq!(place(MapRole::Normal), Some((2, 1)));
        assert_eq!(place(MapRole::Specular), None);
        assert_eq!(place(MapRole::Glow), Some((2, 0)));
        assert!(maps.texture(MapRole::Specular, ground.material.specular_map.as_ref().unwrap()).is_none());
    }
}
