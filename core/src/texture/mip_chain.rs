//! Mipmap chains: a texture's levels of detail, each half the size of the one above, built once into texels the
//! caller provides ([`mip_chain_texels`] says how many).
//!
//! Each texel of a level is the box-filtered average of the texels of the level above that it covers. A side of
//! odd length `2n + 1` halves to `n`, and each texel then covers two and a fraction texels: three taps, weighted by
//! how much of each it covers (the polyphase box of NVIDIA's "Non-Power-of-Two Mipmap Creation", 2005). Colour
//! maps are averaged in linear light and encoded back to sRGB, so a level is as bright as the texels it stands
//! for; other maps are averaged as stored. The sums are `f32` in a fixed order, so every target builds the same
//! chain.

use super::{MAX_TEXTURE_SIZE, Texture, TextureError};
use crate::color::{SRGB_DECODE, linear_to_srgb8};
use crate::math::float;

/// Most levels a chain has, the texture itself included: a side of [`MAX_TEXTURE_SIZE`] (2^14) halves 14 times.
pub const MAX_MIP_LEVELS: usize = 15;

/// What a texture's texels mean, which decides how its levels are averaged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MipContent {
    /// sRGB-encoded colour (diffuse, specular and glow maps): averaged in linear light.
    Color,
    /// Values averaged as stored (normal and occlusion maps).
    Data,
}

/// A texture and its levels of detail, from the texture itself down to 1x1 ([`Texture::mip_chain`]).
///
/// It holds where each level starts, not the levels: a draw makes a chain for every map and batch it reads, and
/// [`MipChain::level`] makes the level it is asked for.
#[derive(Clone, Copy, Debug)]
pub struct MipChain<'a> {
    /// The texture itself: level 0.
    top: Texture<'a>,
    /// The levels below it, laid out as [`build_mip_levels`] fills them.
    below: &'a [u32],
    /// Where level `k` starts in `below` (entry 0 unused).
    starts: [u32; MAX_MIP_LEVELS],
    /// The number of levels, the texture itself included.
    count: usize,
}

impl<'a> MipChain<'a> {
    /// The chain of `texture`, whose levels below it are `below` (laid out as [`build_mip_levels`] fills them,
    /// interleaved like the texture), or `texture` alone when `below` is empty. The levels are those `below`
    /// holds whole.
    pub(super) fn new(texture: Texture<'a>, below: &'a [u32]) -> Self {
        let (mut starts, mut count, mut start) = ([0; MAX_MIP_LEVELS], 1, 0);
        for (w, h) in level_sizes(texture.width(), texture.height()).skip(1) {
            let end = start + w as usize * h as usize * texture.stride;
            if end > below.len() {
                break;
            }
            // At most 8 maps of MAX_TEXTURE_SIZE^2 / 3 texels: below 2^30.
            starts[count] = start as u32;
            count += 1;
            start = end;
        }
        Self { top: texture, below, starts, count }
    }

    /// The number of levels, the texture itself included.
    #[must_use]
    pub fn level_count(&self) -> usize {
        self.count
    }

    /// Level `k`: the texture itself for 0, then each half the size of the one before (rounded down, at least 1),
    /// the last 1x1; the last for any `k` past it.
    #[must_use]
    #[inline(always)]
    pub fn level(&self, k: usize) -> Texture<'a> {
        let k = k.min(self.count - 1);
        if k == 0 {
            return self.top;
        }
        // Halving k times, each rounded down and at least 1, is shifting by k, at least 1.
        let (width, height) = ((self.top.width >> k).max(1), (self.top.height >> k).max(1));
        let start = self.starts[k] as usize;
        let len = width as usize * height as usize * self.top.stride;
        // In range: `new` kept only the levels `below` holds whole.
        let texels = self.below.get(start..start + len).unwrap_or(&[]);
        Texture { texels, width, height, mips: &[], ..self.top }
    }
}

/// A side of `size` texels one level down: half, rounded down, and at least 1 (OpenGL's rule).
const fn half(size: u32) -> u32 {
    if size > 1 { size / 2 } else { 1 }
}

/// The sizes of the levels of a `width x height` texture, its own first, down to 1x1.
fn level_sizes(width: u32, height: u32) -> impl Iterator<Item = (u32, u32)> {
    core::iter::successors(Some((width, height)), |&(w, h)| (w > 1 || h > 1).then_some((half(w), half(h))))
}

/// The texels the levels below a `width x height` texture need together: per map, the length of the buffer
/// [`build_mip_levels`] fills (times the number of maps interleaved). 0 for a size no texture has (empty, or
/// larger than [`MAX_TEXTURE_SIZE`]).
///
/// # Examples
/// ```
/// use rastty_core::texture::mip_chain_texels;
/// // 512x512 + 256x256 + ... + 1x1.
/// assert_eq!(mip_chain_texels(1024, 1024), 349_525);
/// // 2x1, then 1x1.
/// assert_eq!(mip_chain_texels(5, 3), 3);
/// ```
#[must_use]
pub fn mip_chain_texels(width: u32, height: u32) -> usize {
    if width == 0 || height == 0 || width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE {
        return 0;
    }
    level_sizes(width, height).skip(1).map(|(w, h)| w as usize * h as usize).sum()
}

/// Builds the levels of detail below `texture`, whose texels mean `content`, into `out`: [`mip_chain_texels`]
/// texels times the number of maps the texture interleaves, laid out level by level, largest first, and within a
/// level interleaved like the texture (this map's texels at its place; the others' left as they are, so that the
/// chains of a slice's maps go into one buffer). [`Texture::with_mip_levels`] then samples them.
///
/// # Errors
/// [`TextureError::Length`] when `out` is not of that length.
///
/// # Examples
/// ```
/// use rastty_core::texture::{MipContent, Texture, build_mip_levels, mip_chain_texels};
/// // White and black: their average in linear light is 0.5, sRGB code 188, not the 128 of the codes' average.
/// let texels = [0xFF_FFFF, 0x00_0000];
/// let texture = Texture::new(&texels, 2, 1).unwrap();
/// let mut levels = vec![0; mip_chain_texels(2, 1)];
/// build_mip_levels(&texture, MipContent::Color, &mut levels).unwrap();
/// assert_eq!(levels, [0xBC_BCBC]);
/// let texture = texture.with_mip_levels(&levels).unwrap();
/// assert_eq!(texture.mip_chain().level_count(), 2);
/// ```
pub fn build_mip_levels(texture: &Texture<'_>, content: MipContent, out: &mut [u32]) -> Result<(), TextureError> {
    let (width, height) = (texture.width(), texture.height());
    let (maps, map) = texture.interleaving();
    let expected = mip_chain_texels(width, height) * maps as usize;
    if out.len() != expected {
        return Err(TextureError::Length { expected, actual: out.len() });
    }
    // Each 8-bit code's value in the space it is averaged in: 256 conversions instead of one per texel read.
    let decode: [f32; 256] = match content {
        MipContent::Color => SRGB_DECODE,
        MipContent::Data => core::array::from_fn(|code| code as f32 / 255.0),
    };
    // Level k is built from level k - 1: the texture itself, then the level just built, which starts at `above`.
    let (mut above, mut start) = (None::<(usize, u32, u32)>, 0);
    for (w, h) in level_sizes(width, height).skip(1) {
        let len = w as usize * h as usize * maps as usize;
        let (built, rest) = out.split_at_mut(start);
        let level = Level { texels: &mut rest[..len], width: w, height: h, maps, map };
        match above {
            None => downsample(texture, content, &decode, level),
            Some((from, aw, ah)) => {
                let source = Texture::interleaved(&built[from..], aw, ah, maps, map)?;
                downsample(&source, content, &decode, level);
            }
        }
        above = Some((start, w, h));
        start += len;
    }
    Ok(())
}

/// The taps along one side of a level `size` texels long, for its texel `i`: the texels of the side above
/// (`above` texels long) it covers, each with the share of it covered, the shares summing to 1. Unused taps
/// weigh 0.
fn taps(above: u32, size: u32, i: u32) -> [(u32, f32); 3] {
    if above == size {
        // A side already 1 texel long while the other still halves.
        [(i, 1.0), (i, 0.0), (i, 0.0)]
    } else if above == 2 * size {
        [(2 * i, 0.5), (2 * i + 1, 0.5), (2 * i + 1, 0.0)]
    } else {
        // above = 2 size + 1: texel i spans [i above / size, (i + 1) above / size) of the side above, which covers
        // texel 2i for (size - i) / size, texel 2i + 1 whole and texel 2i + 2 for (i + 1) / size; divided by the
        // span's length, above / size.
        let length = above as f32;
        [(2 * i, (size - i) as f32 / length), (2 * i + 1, size as f32 / length), (2 * i + 2, (i + 1) as f32 / length)]
    }
}

/// One level being built: `width x height` texels of map `map` of `maps` interleaved in `texels`.
struct Level<'a> {
    texels: &'a mut [u32],
    width: u32,
    height: u32,
    maps: u32,
    map: u32,
}

/// Fills `out` from `above`, the level above it: each texel the weighted sum of the texels it covers, colour
/// channels through `decode` and encoded back as `content` says, the transparency byte as stored.
fn downsample(above: &Texture<'_>, content: MipContent, decode: &[f32; 256], out: Level<'_>) {
    let (above_width, above_height) = (above.width(), above.height());
    for y in 0..out.height {
        let rows = taps(above_height, out.height, y);
        for x in 0..out.width {
            let columns = taps(above_width, out.width, x);
            let mut sum = [0.0f32; 4];
            for &(row, wy) in &rows {
                for &(column, wx) in &columns {
                    let weight = wy * wx;
                    let texel = above.packed(column as i32, row as i32);
                    for (channel, total) in sum.iter_mut().enumerate() {
                        let code = (texel >> (8 * (3 - channel))) & 0xFF;
                        let value = if channel == 0 { code as f32 / 255.0 } else { decode[code as usize] };
                        *total += weight * value;
                    }
                }
            }
            let [transparency, r, g, b] = sum;
            let encode = |v: f32| match content {
                MipContent::Color => linear_to_srgb8(v),
                MipContent::Data => float::quantize_unit(v, 255.0),
            };
            let index = (y * out.width + x) as usize * out.maps as usize + out.map as usize;
            out.texels[index] =
                float::quantize_unit(transparency, 255.0) << 24 | encode(r) << 16 | encode(g) << 8 | encode(b);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Builds the chain of `texels` (`width x height`) as `content` into `out`; the number of its levels.
    fn levels_of(texels: &[u32], width: u32, height: u32, content: MipContent, out: &mut [u32]) -> usize {
        let texture = Texture::new(texels, width, height).unwrap();
        build_mip_levels(&texture, content, out).unwrap();
        texture.with_mip_levels(out).unwrap().mip_chain().level_count()
    }

    #[test]
    fn a_chain_has_a_level_for_each_halving_down_to_one_texel() {
        assert_eq!(level_sizes(MAX_TEXTURE_SIZE, MAX_TEXTURE_SIZE).count(), MAX_MIP_LEVELS);
        assert_eq!(level_sizes(MAX_TEXTURE_SIZE, 1).count(), MAX_MIP_LEVELS);
        let sizes: [(u32, u32); 3] = core::array::from_fn(|i| level_sizes(7, 2).nth(i).unwrap());
        assert_eq!(sizes, [(7, 2), (3, 1), (1, 1)]);
        assert_eq!(level_sizes(7, 2).count(), 3);
        assert_eq!(mip_chain_texels(7, 2), 3 + 1);
        assert_eq!(mip_chain_texels(1, 1), 0);
        for (w, h) in [(0, 4), (4, 0), (MAX_TEXTURE_SIZE + 1, 1)] {
            assert_eq!(mip_chain_texels(w, h), 0);
        }
        let texels = [0; 4];
        let mut short = [0; 2];
        let texture = Texture::new(&texels, 2, 2).unwrap();
        let wrong = Some(TextureError::Length { expected: 1, actual: 2 });
        assert_eq!(build_mip_levels(&texture, MipContent::Data, &mut short).err(), wrong);
        assert_eq!(texture.with_mip_levels(&short).err(), wrong);
        // Without levels, the chain is the texture alone.
        assert_eq!(texture.mip_chain().level_count(), 1);
    }

    /// Every 8-bit code survives decoding to linear light and encoding back, so a texture of one texel value keeps
    /// it at every level, odd sides included, whatever its content.
    #[test]
    fn one_texel_value_stays_itself_at_every_level() {
        for code in 0..=255u32 {
            assert_eq!(linear_to_srgb8(SRGB_DECODE[code as usize]), code);
        }
        for texel in [0x3A_C0_11_7Fu32, 0x00_01_FE_80, 0xFF_FF_FF_FF] {
            let texels = [texel; 7 * 5];
            for content in [MipContent::Color, MipContent::Data] {
                let mut out = [0; 3 * 2 + 1];
                assert_eq!(levels_of(&texels, 7, 5, content, &mut out), 3);
                assert_eq!(out, [texel; 7], "{texel:#010x} as {content:?}");
            }
        }
    }

    /// Three white texels and a black one: colour averages their light, 0.75, sRGB 0.8808, code 225; data averages
    /// the codes, 191.25, code 191.
    #[test]
    fn colour_is_averaged_in_linear_light_and_data_as_stored() {
        let texels = [0xFF_FFFF, 0xFF_FFFF, 0xFF_FFFF, 0];
        let mut out = [0; 1];
        levels_of(&texels, 2, 2, MipContent::Color, &mut out);
        assert_eq!(out, [0xE1_E1E1]);
        levels_of(&texels, 2, 2, MipContent::Data, &mut out);
        assert_eq!(out, [0xBF_BFBF]);
        // The transparency byte is averaged as stored under either content: 191.25 of 255.
        let transparent = [0xFF00_0000, 0xFF00_0000, 0xFF00_0000, 0];
        levels_of(&transparent, 2, 2, MipContent::Color, &mut out);
        assert_eq!(out, [0xBF00_0000]);
    }

    /// An odd side of 2n + 1 texels halves to n, each texel covering two and a fraction texels.
    #[test]
    fn odd_sides_weigh_each_texel_by_the_share_covered() {
        let grey = |v: u32| v << 16 | v << 8 | v;
        // 3 -> 1: a third of each.
        let texels = [0, 90, 255].map(grey);
        let mut out = [0; 1];
        levels_of(&texels, 3, 1, MipContent::Data, &mut out);
        assert_eq!(out, [grey(115)]);
        // 5 -> 2: (2/5, 2/5, 1/5) of texels 0..3 and (1/5, 2/5, 2/5) of texels 2..5, 40 and 160; then 2 -> 1, 100.
        let texels = [0, 50, 100, 150, 200].map(grey);
        let mut out = [0; 3];
        levels_of(&texels, 5, 1, MipContent::Data, &mut out);
        assert_eq!(out, [grey(40), grey(160), grey(100)]);
        // The same down a column.
        let mut column = [0; 3];
        levels_of(&texels, 1, 5, MipContent::Data, &mut column);
        assert_eq!(column, out);
    }

    /// Maps interleaved in one slice get the chains of their own texels, interleaved level by level in one buffer.
    #[test]
    fn interleaved_maps_get_the_chains_of_their_own_texels() {
        let first: [u32; 12] = core::array::from_fn(|i| i as u32 * 0x0A_0B0C);
        let second: [u32; 12] = core::array::from_fn(|i| 0xFF_FFFF - i as u32 * 0x07_0503);
        let both: [u32; 24] = core::array::from_fn(|i| if i % 2 == 0 { first[i / 2] } else { second[i / 2] });
        // 4x3, then 2x1 and 1x1: 3 texels per map.
        let mut shared = [0; 6];
        for k in 0..2 {
            let map = Texture::interleaved(&both, 4, 3, 2, k).unwrap();
            build_mip_levels(&map, MipContent::Color, &mut shared).unwrap();
        }
        for (k, own) in [first, second].iter().enumerate() {
            let mut alone = [0; 3];
            levels_of(own, 4, 3, MipContent::Color, &mut alone);
            let own_levels: [u32; 3] = core::array::from_fn(|i| shared[2 * i + k]);
            assert_eq!(alone, own_levels, "map {k}");
            let map = Texture::interleaved(&both, 4, 3, 2, k as u32).unwrap().with_mip_levels(&shared).unwrap();
            let chain = map.mip_chain();
            let sizes: [(u32, u32); 3] = core::array::from_fn(|i| (chain.level(i).width(), chain.level(i).height()));
            assert_eq!(sizes, [(4, 3), (2, 1), (1, 1)]);
            assert_eq!(chain.level(2).packed(0, 0), alone[2], "map {k}");
        }
    }
}
