//! Reading a draw's maps over a batch, and the colour maps: albedo, specular colour, glow and occlusion.

use core::marker::PhantomData;

use super::scratch::{Coordinates, Scratch};
use crate::color::{ShadingSpace, unpack_rgb888};
use crate::math::{Vec2, Vec3};
use crate::pipeline::columns::{Column, Column3};
use crate::pipeline::{BATCH_SIZE, Slopes, lanes};
use crate::texture::{Filter, Footprint, MipChain, MipFilter, Texture, Wrap, footprint, light_between};

/// A map's width, height and number of levels read.
type MapShape = (u32, u32, usize);

/// A batch's reads of the draw's maps at its texture coordinates, with one filter, wrap mode and filter between
/// levels: where the maps are read (texel addresses, or each lane's level of detail) is worked out for one map
/// size and used again by every following map of that size.
pub(crate) struct MapReader<F: Filter, W: Wrap> {
    mip_filter: MipFilter,
    /// The texel addresses, for maps of the size they were made for.
    addresses: Option<((u32, u32), F::Addresses<BATCH_SIZE>)>,
    /// Where each lane reads a map's levels, for maps of the size and number of levels they were worked out for.
    footprints: Option<(MapShape, [Footprint; BATCH_SIZE])>,
    _wrap: PhantomData<W>,
}

impl<F: Filter, W: Wrap> MapReader<F, W> {
    /// A reader with no addresses yet, choosing levels of detail as `mip_filter` says.
    #[inline(always)]
    pub fn new(mip_filter: MipFilter) -> Self {
        Self { mip_filter, addresses: None, footprints: None, _wrap: PhantomData }
    }

    /// The texels of `map` at the lanes' coordinates `at` (the same at every call), packed and as stored: from its
    /// levels of detail when the draw mipmaps and the map has them, else from the map alone.
    #[inline(always)]
    pub fn read(&mut self, map: &Texture<'_>, at: &Coordinates, out: &mut [u32; BATCH_SIZE]) {
        if self.mip_filter != MipFilter::Off && map.has_mip_levels() {
            return self.read_levels(map, at, out);
        }
        F::read::<W, BATCH_SIZE>(map, self.addresses(map, at), out);
    }

    /// The colours of the sRGB-encoded colour map `map` at the lanes' coordinates `at` in linear light, every
    /// texel decoded before it is blended ([`Filter::sample_light`], [`crate::texture::MipChain::sample_light`]),
    /// into the first `len` lanes of `out`.
    #[inline(always)]
    pub fn read_light(&mut self, map: &Texture<'_>, at: &Coordinates, out: &mut Column3, len: usize) {
        if self.mip_filter != MipFilter::Off && map.has_mip_levels() {
            return self.read_light_levels(map, at, out, len);
        }
        let mut light = [Vec3::ZERO; BATCH_SIZE];
        F::read_light::<W, BATCH_SIZE>(map, self.addresses(map, at), &mut light);
        (0..lanes(len)).for_each(|i| out.set(i, light[i]));
    }

    /// Where the lanes read a map of `map`'s size, worked out for the first map of that size.
    #[inline(always)]
    fn addresses(&mut self, map: &Texture<'_>, at: &Coordinates) -> &F::Addresses<BATCH_SIZE> {
        let size = (map.width(), map.height());
        if self.addresses.as_ref().is_some_and(|(made_for, _)| *made_for != size) {
            self.addresses = None;
        }
        &self
            .addresses
            .get_or_insert_with(|| (size, F::addresses::<W, BATCH_SIZE>(size.0, size.1, &at.uv.x, &at.uv.y)))
            .1
    }

    /// [`Self::read`] from the map's levels of detail, each lane where its footprint says. Not inlined: one copy
    /// per filter and wrap mode serves every draw's stages, which call it once per map and batch.
    #[inline(never)]
    fn read_levels(&mut self, map: &Texture<'_>, at: &Coordinates, out: &mut [u32; BATCH_SIZE]) {
        let (chain, mip) = (map.mip_chain(), self.mip_filter);
        let footprints = self.footprints((map.width(), map.height(), chain.level_count()), at);
        for (i, o) in out.iter_mut().enumerate() {
            *o = chain.sample_packed::<F, W>(Vec2::new(at.uv.x[i], at.uv.y[i]), &footprints[i], mip);
        }
    }

    /// [`Self::read_light`] from the map's levels of detail, each lane where its footprint says; not inlined, as
    /// [`Self::read_levels`].
    #[inline(never)]
    fn read_light_levels(&mut self, map: &Texture<'_>, at: &Coordinates, out: &mut Column3, len: usize) {
        let (chain, mip) = (map.mip_chain(), self.mip_filter);
        let footprints = self.footprints((map.width(), map.height(), chain.level_count()), at);
        if read_light_level_by_level::<F, W>(&chain, footprints, mip, at, out, len) {
            return;
        }
        for (i, footprint) in footprints.iter().enumerate().take(lanes(len)) {
            out.set(i, chain.sample_light::<F, W>(Vec2::new(at.uv.x[i], at.uv.y[i]), footprint, mip));
        }
    }

    /// Where each lane reads a map of `shape`, worked out for the first map of that shape.
    #[inline(always)]
    fn footprints(&mut self, shape: MapShape, at: &Coordinates) -> &[Footprint; BATCH_SIZE] {
        if self.footprints.as_ref().is_some_and(|(made_for, _)| *made_for != shape) {
            self.footprints = None;
        }
        let most = self.mip_filter.max_probes_log2();
        &self
            .footprints
            .get_or_insert_with(|| {
                // Without slopes (coordinates gathered for a draw that does not mipmap), the texture itself.
                let (w, h) = (shape.0 as f32, shape.1 as f32);
                let footprints = match &at.slopes {
                    Some(Slopes { dx, dy }) => {
                        core::array::from_fn(|i| footprint(w, h, [dx.x[i], dx.y[i], dy.x[i], dy.y[i]], shape.2, most))
                    }
                    None => [Footprint::at_level(0); BATCH_SIZE],
                };
                (shape, footprints)
            })
            .1
    }
}

/// The most levels [`read_light_level_by_level`] reads: trilinear lanes spanning two levels read three.
const MOST_LEVELS_READ: usize = 3;

/// [`MapReader::read_light`] from `chain`'s levels for one probe a lane ([`MipFilter::Nearest`],
/// [`MipFilter::Linear`]), a level at a time: every level some lane reads is sampled at every lane by the filter's
/// lane loop ([`Filter::read_light`], as a map without levels is read: one loop the compiler widens, where a
/// level per lane keeps each lane's sample on its own), and each lane keeps its levels' samples and blends them
/// as [`MipChain::sample_light`] does, to the same bits. Reads nothing and returns false when the lanes read more
/// than [`MOST_LEVELS_READ`] levels (or the filter takes probes).
///
/// [`MipChain::sample_light`]: crate::texture::MipChain::sample_light
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
fn read_light_level_by_level<F: Filter, W: Wrap>(
    chain: &MipChain<'_>,
    footprints: &[Footprint; BATCH_SIZE],
    mip: MipFilter,
    at: &Coordinates,
    out: &mut Column3,
    len: usize,
) -> bool {
    if !matches!(mip, MipFilter::Nearest | MipFilter::Linear) {
        return false;
    }
    // Each lane's level and its fraction of the way to the next (0 when it reads one level).
    let mut near = [0usize; BATCH_SIZE];
    let mut fraction = [0u32; BATCH_SIZE];
    for i in 0..lanes(len) {
        (near[i], fraction[i]) = chain.levels_read(footprints[i].lod, mip);
    }
    // The levels read: from the least lane's level to the greatest level a lane reads, its own or, with a
    // fraction, the next (never past the chain: the last level has no fraction).
    let n = len.min(BATCH_SIZE);
    let first = near[..n].iter().min();
    let last = (0..n).map(|i| near[i] + usize::from(fraction[i] > 0)).max();
    let (Some(&first), Some(last)) = (first, last) else { return true };
    if last - first >= MOST_LEVELS_READ {
        return false;
    }
    let (mut near_light, mut far_light) = ([Vec3::ZERO; BATCH_SIZE], [Vec3::ZERO; BATCH_SIZE]);
    for level in first..=last {
        let texture = chain.level(level);
        let addresses = F::addresses::<W, BATCH_SIZE>(texture.width(), texture.height(), &at.uv.x, &at.uv.y);
        let mut light = [Vec3::ZERO; BATCH_SIZE];
        F::read_light::<W, BATCH_SIZE>(&texture, &addresses, &mut light);
        for i in 0..BATCH_SIZE {
            if near[i] == level {
                near_light[i] = light[i];
            }
            if near[i] + 1 == level {
                far_light[i] = light[i];
            }
        }
    }
    for i in 0..lanes(len) {
        let light =
            if fraction[i] == 0 { near_light[i] } else { light_between(near_light[i], far_light[i], fraction[i]) };
        out.set(i, light);
    }
    true
}

/// How a map's texels become values: colour maps are decoded from sRGB in a draw that lights in linear light,
/// data maps (occlusion) never.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Texels {
    /// Each code over 255.
    AsStored,
    /// Each code decoded to linear light ([`crate::color::SRGB_DECODE`]) before the texels are blended.
    Srgb,
}

impl Texels {
    /// How a colour map's texels are read in a draw lit in `space`.
    #[inline(always)]
    pub fn of_color(space: ShadingSpace) -> Self {
        match space {
            ShadingSpace::Linear => Self::Srgb,
            ShadingSpace::Encoded => Self::AsStored,
        }
    }
}

/// Albedo: its base colour (the material's, times the vertex colours) times the diffuse map.
pub(crate) fn albedo<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    texels: Texels,
) {
    let base = s.albedo;
    modulated(&mut s.albedo, &s.at, maps, map, texels, Some(&base), s.len);
}

/// Specular colour: `specular` times the specular map.
pub(crate) fn specular_color<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    texels: Texels,
    specular: Vec3,
) {
    modulated(&mut s.specular_color, &s.at, maps, map, texels, Some(&Column3::splat(specular)), s.len);
}

/// Ambient light: `ambient` times the occlusion map, into `s.ambient`.
pub(crate) fn occluded_ambient<F: Filter, W: Wrap>(
    s: &mut Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    ambient: Vec3,
) {
    modulated(&mut s.ambient, &s.at, maps, map, Texels::AsStored, Some(&Column3::splat(ambient)), s.len);
}

/// The occlusion map's share of the indirect light, channel by channel, into `s.ambient`.
pub(crate) fn occlusion<F: Filter, W: Wrap>(s: &mut Scratch, maps: &mut MapReader<F, W>, map: &Texture<'_>) {
    modulated(&mut s.ambient, &s.at, maps, map, Texels::AsStored, None, s.len);
}

/// Emission: the glow map.
pub(crate) fn glow<F: Filter, W: Wrap>(s: &mut Scratch, maps: &mut MapReader<F, W>, map: &Texture<'_>, texels: Texels) {
    modulated(&mut s.emission, &s.at, maps, map, texels, None, s.len);
}

/// The map at the texture coordinates `at` of each lane of a batch of `len`, its texels read as `texels` says,
/// times that lane's `color` if given, into `out`.
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
pub(crate) fn modulated<F: Filter, W: Wrap>(
    out: &mut Column3,
    at: &Coordinates,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    texels: Texels,
    color: Option<&Column3>,
    len: usize,
) {
    let mut values = Column3::ZERO;
    match texels {
        Texels::AsStored => {
            let mut packed = [0; BATCH_SIZE];
            maps.read(map, at, &mut packed);
            (0..lanes(len)).for_each(|i| values.set(i, unpack_rgb888(packed[i])));
        }
        Texels::Srgb => maps.read_light(map, at, &mut values, len),
    }
    match color {
        // `color.mul_elem(texel)`, lane by lane.
        Some(color) => {
            for i in 0..lanes(len) {
                out.x[i] = color.x[i] * values.x[i];
                out.y[i] = color.y[i] * values.y[i];
                out.z[i] = color.z[i] * values.z[i];
            }
        }
        None => *out = values,
    }
}

/// Each fragment's metallic factor and roughness into `out` (in that order): `metallic` and `roughness` times the
/// blue and green channels of the metallic-roughness map `map` at its coordinates, read as stored (data), as
/// [`super::material::metallic_roughness`] computes them.
#[inline(always)]
pub(crate) fn metallic_roughness<F: Filter, W: Wrap>(
    s: &Scratch,
    maps: &mut MapReader<F, W>,
    map: &Texture<'_>,
    metallic: f32,
    roughness: f32,
    out: &mut [Column; 2],
) {
    let mut packed = [0; BATCH_SIZE];
    maps.read(map, &s.at, &mut packed);
    for (i, &texel) in packed.iter().enumerate().take(lanes(s.len)) {
        (out[0][i], out[1][i]) = super::material::metallic_roughness(metallic, roughness, Some(texel));
    }
}

/// The shaded `colors` as a draw lit in `space` stores them: encoded from linear light to sRGB
/// ([`crate::color::encode_srgb`]), or as they are.
#[inline(always)]
pub(crate) fn stored(colors: &mut [Vec3], space: ShadingSpace) {
    if space == ShadingSpace::Linear {
        colors.iter_mut().for_each(|c| *c = space.stored(*c));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::columns::{Column, Column2};
    use crate::texture::{Anisotropy, Bilinear, Clamp, MipContent, Nearest, Repeat, build_mip_levels};

    /// A reader gives each map's own samples, as stored and in light, when maps of different sizes take turns
    /// (its addresses are made again whenever the size changes), for both filters.
    #[test]
    fn maps_of_other_sizes_get_their_own_addresses() {
        let small: [u32; 12] = core::array::from_fn(|i| i as u32 * 0x01_0203);
        let large: [u32; 35] = core::array::from_fn(|i| 0xFF_FFFF - i as u32 * 0x03_0201);
        let wide: [u32; 35] = core::array::from_fn(|i| i as u32 * 0x05_0505);
        let small = Texture::new(&small, 4, 3).unwrap();
        let large = Texture::new(&large, 5, 7).unwrap();
        let wide = Texture::new(&wide, 7, 5).unwrap();
        let uv = Column2 {
            x: Column::from_fn(|i| i as f32 * 0.0731 - 0.4),
            y: Column::from_fn(|i| 1.3 - i as f32 * 0.0517),
        };
        fn check<F: Filter, W: Wrap>(maps: [&Texture<'_>; 5], uv: &Column2) {
            let mut reader = MapReader::<F, W>::new(MipFilter::Off);
            let at = Coordinates { uv: *uv, ..Coordinates::ZERO };
            for map in maps {
                let (mut read, mut expected) = ([0; BATCH_SIZE], [0; BATCH_SIZE]);
                reader.read(map, &at, &mut read);
                F::sample_packed_lanes::<W, BATCH_SIZE>(map, &uv.x, &uv.y, &mut expected);
                assert_eq!(read, expected, "{}x{}", map.width(), map.height());
                let mut light = Column3::ZERO;
                reader.read_light(map, &at, &mut light, BATCH_SIZE);
                for i in 0..BATCH_SIZE {
                    let expected = F::sample_light::<W>(map, Vec2::new(uv.x[i], uv.y[i]));
                    assert_eq!(light.get(i), expected, "{}x{} lane {i}", map.width(), map.height());
                }
            }
        }
        // The same size twice in a row, then other sizes, one with the same texel count.
        let maps = [&small, &small, &large, &wide, &small];
        check::<Nearest, Repeat>(maps, &uv);
        check::<Nearest, Clamp>(maps, &uv);
        check::<Bilinear, Repeat>(maps, &uv);
        check::<Bilinear, Clamp>(maps, &uv);
    }

    /// Reading level by level gives each lane what its own trilinear or nearest-level sample gives, to the bit,
    /// for lanes reading one, two or three levels, all or some of the lanes; lanes spread over more levels, and
    /// anisotropic filters, are left to the reader's loop over lanes.
    #[test]
    fn reading_level_by_level_gives_each_lane_its_own_sample() {
        let texels: [u32; 256] = core::array::from_fn(|i| (i as u32 * 0x07_0B0D) & 0xFF_FFFF);
        let mut levels = [0; 85];
        let texture = Texture::new(&texels, 16, 16).unwrap();
        build_mip_levels(&texture, MipContent::Color, &mut levels).unwrap();
        let chain = texture.with_mip_levels(&levels).unwrap().mip_chain();
        let uv =
            Column2 { x: Column::from_fn(|i| i as f32 * 0.0731 - 0.4), y: Column::from_fn(|i| 0.9 - i as f32 * 0.037) };
        // Footprints from `from` texels long, growing by `step` a lane, as wide as long.
        let at = |from: f32, step: f32| {
            let length = |i: usize| (from + i as f32 * step) / 16.0;
            let dx = Column2 { x: Column::from_fn(length), y: Column::ZERO };
            let dy = Column2 { x: Column::ZERO, y: Column::from_fn(length) };
            Coordinates { uv, slopes: Some(Slopes { dx, dy }) }
        };
        let read = |at: &Coordinates, mip, len| {
            let footprints: [Footprint; BATCH_SIZE] = core::array::from_fn(|i| {
                let lane = Slopes {
                    dx: Vec2::new(at.slopes.unwrap().dx.x[i], 0.0),
                    dy: Vec2::new(0.0, at.slopes.unwrap().dy.y[i]),
                };
                chain.footprint(&lane, mip)
            });
            let mut out = Column3::ZERO;
            let read = read_light_level_by_level::<Bilinear, Repeat>(&chain, &footprints, mip, at, &mut out, len);
            for (i, footprint) in footprints.iter().enumerate().take(len) {
                let lane = Vec2::new(at.uv.x[i], at.uv.y[i]);
                let expected = chain.sample_light::<Bilinear, Repeat>(lane, footprint, mip);
                assert!(!read || out.get(i) == expected, "{mip:?} lane {i}");
            }
            (read, footprints.map(|f| f.lod))
        };
        for mip in [MipFilter::Nearest, MipFilter::Linear] {
            // Lanes reading one level (magnified), two (trilinear within level 1 and on to 2; nearest: 1) and three
            // (trilinear from level 0 into 1, and on to 2; nearest: 1 and 2).
            for (from, step) in [(0.2, 0.01), (2.9, 0.01), (2.0, 0.1)] {
                for len in [BATCH_SIZE, 5, 1] {
                    assert!(read(&at(from, step), mip, len).0, "{mip:?} from {from} by {step}, {len} lanes");
                }
            }
            // From magnified to the last level: left to the loop over lanes.
            let (read_by_level, lods) = read(&at(0.2, 1.0), mip, BATCH_SIZE);
            assert!(!read_by_level && lods[0] == 0 && lods[BATCH_SIZE - 1] == 4 * crate::texture::LEVEL, "{mip:?}");
        }
        let (read_by_level, _) = read(&at(2.9, 0.01), MipFilter::Anisotropic(Anisotropy::X2), BATCH_SIZE);
        assert!(!read_by_level);
    }

    /// A mipmapping reader gives each lane the chain's sample at the lane's own level of detail, as stored and in
    /// light, for maps with levels of different sizes taking turns and a map without levels, which is read alone.
    #[test]
    fn a_mipmapping_reader_samples_each_lane_at_its_level_of_detail() {
        let big: [u32; 64] = core::array::from_fn(|i| (i as u32 * 0x03_0507) & 0xFF_FFFF);
        let small: [u32; 12] = core::array::from_fn(|i| 0xFF_FFFF - i as u32 * 0x11_0203);
        let (mut big_levels, mut small_levels) = ([0; 21], [0; 3]);
        let big = Texture::new(&big, 8, 8).unwrap();
        let small = Texture::new(&small, 4, 3).unwrap();
        build_mip_levels(&big, MipContent::Color, &mut big_levels).unwrap();
        build_mip_levels(&small, MipContent::Data, &mut small_levels).unwrap();
        let (big, alone) = (big.with_mip_levels(&big_levels).unwrap(), big);
        let small = small.with_mip_levels(&small_levels).unwrap();
        // Slopes from magnified to beyond the last level: long and narrow footprints, and square ones (every third
        // lane).
        let slopes = Slopes {
            dx: Column2 { x: Column::from_fn(|i| i as f32 * 0.06), y: Column::splat(0.002) },
            dy: Column2 {
                x: Column::ZERO,
                y: Column::from_fn(|i| if i % 3 == 0 { i as f32 * 0.06 } else { (i % 5) as f32 * 0.07 }),
            },
        };
        let at = Coordinates {
            uv: Column2 { x: Column::from_fn(|i| i as f32 * 0.0731), y: Column::from_fn(|i| 0.9 - i as f32 * 0.05) },
            slopes: Some(slopes),
        };
        let lane = |i: usize| Slopes {
            dx: Vec2::new(slopes.dx.x[i], slopes.dx.y[i]),
            dy: Vec2::new(slopes.dy.x[i], slopes.dy.y[i]),
        };
        for mip in [MipFilter::Nearest, MipFilter::Linear, MipFilter::Anisotropic(Anisotropy::X4)] {
            let mut reader = MapReader::<Bilinear, Repeat>::new(mip);
            let (mut levels_seen, mut probes_seen) = ([false; 4], [false; 3]);
            // Colour maps read in light, data maps as stored.
            let maps = [(&big, true), (&small, false), (&alone, true), (&big, true), (&small, true)];
            for (map, in_light) in maps {
                let (mut read, mut light) = ([0; BATCH_SIZE], Column3::ZERO);
                if in_light {
                    reader.read_light(map, &at, &mut light, BATCH_SIZE);
                } else {
                    reader.read(map, &at, &mut read);
                }
                let chain = map.mip_chain();
                for (i, &stored) in read.iter().enumerate() {
                    let footprint = chain.footprint(&lane(i), mip);
                    levels_seen[(footprint.lod / crate::texture::LEVEL) as usize] = true;
                    probes_seen[footprint.probes_log2 as usize] = true;
                    let uv = Vec2::new(at.uv.x[i], at.uv.y[i]);
                    if in_light {
                        let expected = chain.sample_light::<Bilinear, Repeat>(uv, &footprint, mip);
                        assert_eq!(light.get(i), expected, "{mip:?} lane {i}");
                    } else {
                        let expected = chain.sample_packed::<Bilinear, Repeat>(uv, &footprint, mip);
                        assert_eq!(stored, expected, "{mip:?} lane {i}");
                    }
                }
            }
            let anisotropic = matches!(mip, MipFilter::Anisotropic(_));
            assert_eq!(levels_seen, [true; 4], "{mip:?}");
            assert_eq!(probes_seen, [true, anisotropic, anisotropic], "{mip:?}");
        }
    }
}
