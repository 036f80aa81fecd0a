//! Textures over borrowed texels, and how they are sampled.
//!
//! A texture is a `&[u32]` of `0xTTRRGGBB` texels, row 0 at the top of the image. Texture coordinates follow the
//! OBJ and OpenGL convention: `u` runs left to right, `v` bottom to top, and `(0, 0)` is the bottom-left corner of
//! the image. The top byte `TT` is the texel's transparency, `255 - alpha` ([`crate::color::texel_alpha`]): a
//! plain `0x00RRGGBB` texel is opaque. Only an alpha cut-out reads it ([`crate::shading::Material::alpha_cutoff`]).
//!
//! Several maps of one size can share one slice, texel by texel ([`Texture::interleaved`]): a fragment reads all
//! of a material's maps at the same texel, so their texels then come in on the same cache line instead of one line
//! per map.

mod mip_chain;
mod mipmapped;
mod sampler;

pub use mip_chain::{MAX_MIP_LEVELS, MipChain, MipContent, build_mip_levels, mip_chain_texels};
pub use mipmapped::{Anisotropy, Footprint, LEVEL, MipFilter};
pub(crate) use mipmapped::{footprint, light_between};
pub use sampler::{Bilinear, Clamp, Filter, FilterMode, Nearest, Repeat, Wrap, WrapMode};

use crate::math::{Vec2, Vec3};

/// Largest texture width or height, in texels: sample positions are computed in fixed point with 8 fractional
/// bits inside a float's 23-bit mantissa.
pub const MAX_TEXTURE_SIZE: u32 = 16384;

/// Most maps one slice of texels can interleave ([`Texture::interleaved`]).
pub const MAX_INTERLEAVED: u32 = 8;

/// Why a texture could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureError {
    /// Zero width or height.
    Empty,
    /// Wider or higher than [`MAX_TEXTURE_SIZE`] texels.
    TooLarge,
    /// The texel slice does not hold `width * height` texels (times the number of interleaved maps).
    Length {
        /// `width * height` (times the number of interleaved maps).
        expected: usize,
        /// Texels given.
        actual: usize,
    },
    /// [`Texture::interleaved`] was asked for map `map` of `maps`: `maps` must be in `1..=`[`MAX_INTERLEAVED`]
    /// and `map` below it.
    Interleaving {
        /// The number of interleaved maps.
        maps: u32,
        /// The map asked for.
        map: u32,
    },
}

impl core::fmt::Display for TextureError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Empty => f.write_str("the texture has no texels"),
            Self::TooLarge => f.write_str("the texture is too large"),
            Self::Length { expected, actual } => {
                write!(f, "the texture needs {expected} texels, {actual} given")
            }
            Self::Interleaving { maps, map } => {
                write!(f, "map {map} of {maps} interleaved maps asked for (at most {MAX_INTERLEAVED} maps)")
            }
        }
    }
}

impl core::error::Error for TextureError {}

/// A borrowed image of `0xTTRRGGBB` texels (`TT`: transparency; see the [module](self) documentation).
#[derive(Clone, Copy, Debug)]
pub struct Texture<'a> {
    texels: &'a [u32],
    width: i32,
    height: i32,
    /// The number of maps interleaved in `texels` (1 for a texture of its own).
    stride: usize,
    /// This map's place among them.
    offset: usize,
    /// The levels of detail below this one, interleaved like it ([`Texture::with_mip_levels`]); empty without.
    mips: &'a [u32],
}

impl<'a> Texture<'a> {
    /// A `width x height` texture; `texels` are row-major, the top row first.
    ///
    /// # Errors
    /// [`TextureError`] for an empty or oversized texture or a slice of the wrong length.
    pub fn new(texels: &'a [u32], width: u32, height: u32) -> Result<Self, TextureError> {
        Self::interleaved(texels, width, height, 1, 0)
    }

    /// Map `map` of `maps` textures of `width x height` texels that `texels` holds texel by texel: texel `i` of the
    /// row-major order (top row first) of map `k` is `texels[i * maps + k]`. Samples are those of a texture made
    /// with [`Texture::new`] from the map's own texels.
    ///
    /// # Errors
    /// [`TextureError`] for an empty or oversized texture, `maps` outside `1..=`[`MAX_INTERLEAVED`] or `map` not
    /// below it, or a slice not of `width * height * maps` texels.
    ///
    /// # Examples
    /// ```
    /// use rastty_core::{math::{Vec2, Vec3}, texture::{Nearest, Repeat, Texture}};
    /// // Two 2x1 maps: red, blue (the first) and white, black (the second), texel by texel.
    /// let texels = [0xFF0000, 0xFFFFFF, 0x0000FF, 0x000000];
    /// let second = Texture::interleaved(&texels, 2, 1, 2, 1).unwrap();
    /// assert_eq!(second.sample::<Nearest, Repeat>(Vec2::new(0.25, 0.5)), Vec3::ONE);
    /// assert_eq!(second.sample::<Nearest, Repeat>(Vec2::new(0.75, 0.5)), Vec3::ZERO);
    /// ```
    pub fn interleaved(texels: &'a [u32], width: u32, height: u32, maps: u32, map: u32) -> Result<Self, TextureError> {
        if width == 0 || height == 0 {
            return Err(TextureError::Empty);
        }
        if width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE {
            return Err(TextureError::TooLarge);
        }
        if maps == 0 || maps > MAX_INTERLEAVED || map >= maps {
            return Err(TextureError::Interleaving { maps, map });
        }
        let expected = width as usize * height as usize * maps as usize;
        if texels.len() != expected {
            return Err(TextureError::Length { expected, actual: texels.len() });
        }
        let (width, height, stride, offset) = (width as i32, height as i32, maps as usize, map as usize);
        Ok(Self { texels, width, height, stride, offset, mips: &[] })
    }

    /// This texture with its levels of detail, `levels`, as [`build_mip_levels`] filled them (for an interleaved
    /// map: the buffer all its slice's maps were built into). Mipmapped sampling ([`crate::texture::MipFilter`])
    /// reads them; the others read the texture alone.
    ///
    /// # Errors
    /// [`TextureError::Length`] when `levels` is not [`mip_chain_texels`] texels times the maps interleaved.
    pub fn with_mip_levels(self, levels: &'a [u32]) -> Result<Self, TextureError> {
        let expected = mip_chain_texels(self.width(), self.height()) * self.stride;
        if levels.len() != expected {
            return Err(TextureError::Length { expected, actual: levels.len() });
        }
        Ok(Self { mips: levels, ..self })
    }

    /// Whether levels of detail are attached ([`Texture::with_mip_levels`]; a 1x1 texture never has any).
    #[must_use]
    pub fn has_mip_levels(&self) -> bool {
        !self.mips.is_empty()
    }

    /// The texture and its levels of detail ([`Texture::with_mip_levels`]); the texture alone without them.
    #[must_use]
    pub fn mip_chain(&self) -> MipChain<'a> {
        MipChain::new(Texture { mips: &[], ..*self }, self.mips)
    }

    /// The number of maps interleaved in the texels, and this map's place among them.
    fn interleaving(&self) -> (u32, u32) {
        (self.stride as u32, self.offset as u32)
    }

    /// Width in texels.
    pub fn width(&self) -> u32 {
        self.width as u32
    }

    /// Height in texels.
    pub fn height(&self) -> u32 {
        self.height as u32
    }

    /// The packed texel at column `x`, row `y` (row 0 at the top); the caller keeps them in range.
    #[inline(always)]
    fn packed(&self, x: i32, y: i32) -> u32 {
        self.at(self.index(x, y))
    }

    /// The packed texel at position `index` of the map's row-major texels (0 past the end, which in-range texels
    /// never are).
    #[inline(always)]
    fn at(&self, index: u32) -> u32 {
        self.texels.get(index as usize * self.stride + self.offset).copied().unwrap_or(0)
    }

    /// The position in the map's row-major texels of column `x`, row `y`, both in range (at most
    /// [`MAX_TEXTURE_SIZE`]^2 = 2^28).
    #[inline(always)]
    fn index(&self, x: i32, y: i32) -> u32 {
        Self::index_in(self.width, x, y)
    }

    /// [`Self::index`] in a texture `width` texels wide.
    #[inline(always)]
    fn index_in(width: i32, x: i32, y: i32) -> u32 {
        y as u32 * width as u32 + x as u32
    }

    /// Samples the texture at `uv` with filter `F` and wrap mode `W`, chosen at compile time.
    ///
    /// Any `uv` is safe: NaN or infinite coordinates select the texel at `u = 0` or `v = 0` (see [`Wrap`]).
    ///
    /// # Examples
    /// ```
    /// use rastty_core::{math::{Vec2, Vec3}, texture::{Nearest, Repeat, Texture}};
    /// // 2x1: red on the left, blue on the right.
    /// let texels = [0xFF0000, 0x0000FF];
    /// let t = Texture::new(&texels, 2, 1).unwrap();
    /// assert_eq!(t.sample::<Nearest, Repeat>(Vec2::new(0.25, 0.5)), Vec3::new(1.0, 0.0, 0.0));
    /// assert_eq!(t.sample::<Nearest, Repeat>(Vec2::new(1.75, 0.5)), Vec3::new(0.0, 0.0, 1.0));
    /// ```
    #[inline(always)]
    pub fn sample<F: Filter, W: Wrap>(&self, uv: Vec2) -> Vec3 {
        F::sample::<W>(self, uv)
    }

    /// Like [`Texture::sample`], but the texel value packed as `0x00RRGGBB`, before conversion to `[0, 1]`: for
    /// maps whose 8-bit codes mean something else than a colour (normal maps).
    #[inline(always)]
    pub fn sample_packed<F: Filter, W: Wrap>(&self, uv: Vec2) -> u32 {
        F::sample_packed::<W>(self, uv)
    }

    /// Samples with a filter and wrap mode chosen at run time (a branch per sample; prefer [`Texture::sample`]).
    pub fn sample_with(&self, filter: FilterMode, wrap: WrapMode, uv: Vec2) -> Vec3 {
        match (filter, wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => self.sample::<Nearest, Repeat>(uv),
            (FilterMode::Nearest, WrapMode::Clamp) => self.sample::<Nearest, Clamp>(uv),
            (FilterMode::Bilinear, WrapMode::Repeat) => self.sample::<Bilinear, Repeat>(uv),
            (FilterMode::Bilinear, WrapMode::Clamp) => self.sample::<Bilinear, Clamp>(uv),
        }
    }
}
