//! Reading a draw's maps over a batch, and the colour maps: albedo, specular colour, glow and occlusion.

use core::marker::PhantomData;

use super::columns::{Column2, Column3};
use super::scratch::Scratch;
use crate::color::unpack_rgb888;
use crate::math::Vec3;
use crate::pipeline::{BATCH_SIZE, lanes};
use crate::texture::{Filter, Texture, Wrap};

/// A batch's reads of the draw's maps at its texture coordinates, with one filter and wrap mode: the texel
/// addresses are worked out for one map size and used again by every following map of that size.
pub(crate) struct MapReader<F: Filter, W: Wrap> {
    addresses: Option<((u32, u32), F::Addresses<BATCH_SIZE>)>,
    _wrap: PhantomData<W>,
}

impl<F: Filter, W: Wrap> MapReader<F, W> {
    /// A reader with no addresses yet.
    #[inline(always)]
    pub fn new() -> Self {
        Self { addresses: None, _wrap: PhantomData }
    }

    /// The texels of `map` at the lanes' coordinates `uv` (the same `uv` at every call), packed.
    #[inline(always)]
    pub fn read(&mut self, map: &Texture<'_>, uv: &Column2, out: &mut [u32; BATCH_SIZE]) {
        let size = (map.width(), map.height());
        let addresses = match &mut self.addresses {
            Some((made_for, addresses)) if *made_for == size => addresses,
            slot => &mut slot.insert((size, F::addresses::<W, BATCH_SIZE>(size.0, size.1, &uv.x, &uv.y))).1,
        };
        F::read::<W, BATCH_SIZE>(map, addresses, out);
    }
}

/// Albedo: its base colour (the material's, times the vertex colours) times the diffuse map.
pub(crate) fn albedo<F: Filter, W: Wrap>(s: &mut Scratch, maps: &mut MapReader<F, W>, map: &Texture<'_>) {
    let base = s.albedo;
    modulated(&mut s.albedo, &s.uv, maps, map, Some(&base), s.len);
}

/// Specular colour: `specular` times the specular map.
pub(crate) fn specular_color<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    specular: Vec3,
) {
    modulated(&mut s.specular_color, &s.uv, maps, map, Some(&Column3::splat(specular)), s.len);
}

/// Ambient light: `ambient` times the occlusion map, into `s.ambient`.
pub(crate) fn occluded_ambient<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    ambient: Vec3,
) {
    modulated(&mut s.ambient, &s.uv, maps, map, Some(&Column3::splat(ambient)), s.len);
}

/// Emission: the glow map.
pub(crate) fn glow<F: Filter, W: Wrap>(s: &mut Scratch, maps: &mut MapReader<F, W>, map: &Texture<'_>) {
    modulated(&mut s.emission, &s.uv, maps, map, None, s.len);
}

/// The map at the texture coordinates of each lane of a batch of `len`, times that lane's `color` if given, into
/// `out`.
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
pub(crate) fn modulated<F: Filter, W: Wrap>(
    out: &mut Column3,
    uv: &Column2,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    color: Option<&Column3>,
    len: usize,
) {
    let mut texels = [0; BATCH_SIZE];
    maps.read(map, uv, &mut texels);
    match color {
        // `color.mul_elem(texel)`, lane by lane.
        Some(color) => {
            for i in 0..lanes(len) {
                let c = unpack_rgb888(texels[i]);
                out.x[i] = color.x[i] * c.x;
                out.y[i] = color.y[i] * c.y;
                out.z[i] = color.z[i] * c.z;
            }
        }
        None => {
            for i in 0..lanes(len) {
                out.set(i, unpack_rgb888(texels[i]));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{Bilinear, Clamp, Nearest, Repeat};

    /// A reader gives each map's own samples when maps of different sizes take turns (its addresses are made
    /// again whenever the size changes), for both filters.
    #[test]
    fn maps_of_other_sizes_get_their_own_addresses() {
        let small: [u32; 12] = core::array::from_fn(|i| i as u32 * 0x01_0203);
        let large: [u32; 35] = core::array::from_fn(|i| 0xFF_FFFF - i as u32 * 0x03_0201);
        let wide: [u32; 35] = core::array::from_fn(|i| i as u32 * 0x05_0505);
        let small = Texture::new(&small, 4, 3).unwrap();
        let large = Texture::new(&large, 5, 7).unwrap();
        let wide = Texture::new(&wide, 7, 5).unwrap();
        let uv = Column2 {
            x: core::array::from_fn(|i| i as f32 * 0.0731 - 0.4),
            y: core::array::from_fn(|i| 1.3 - i as f32 * 0.0517),
        };
        fn check<F: Filter, W: Wrap>(maps: [&Texture<'_>; 5], uv: &Column2) {
            let mut reader = MapReader::<F, W>::new();
            for map in maps {
                let (mut read, mut expected) = ([0; BATCH_SIZE], [0; BATCH_SIZE]);
                reader.read(map, uv, &mut read);
                F::sample_packed_lanes::<W, BATCH_SIZE>(map, &uv.x, &uv.y, &mut expected);
                assert_eq!(read, expected, "{}x{}", map.width(), map.height());
            }
        }
        // The same size twice in a row, then other sizes, one with the same texel count.
        let maps = [&small, &small, &large, &wide, &small];
        check::<Nearest, Repeat>(maps, &uv);
        check::<Nearest, Clamp>(maps, &uv);
        check::<Bilinear, Repeat>(maps, &uv);
        check::<Bilinear, Clamp>(maps, &uv);
    }
}
