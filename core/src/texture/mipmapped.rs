//! Sampling a mipmap chain: the level of detail from how fast the texture coordinates change across the screen,
//! and the filter between levels.

use super::sampler::blend;
use super::{Filter, MipChain, Texture, Wrap};
use crate::math::{Vec2, float};
use crate::pipeline::Slopes;

/// How a sample chooses among a texture's levels of detail ([`Texture::with_mip_levels`]); within a level it is
/// filtered as [`super::FilterMode`] says. A texture without levels is sampled alone whatever this says.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MipFilter {
    /// The texture itself at every distance: distant texels alias.
    Off,
    /// The level nearest the sample's level of detail (`GL_*_MIPMAP_NEAREST`).
    Nearest,
    /// The two levels around it, blended by where it lies between them (`GL_*_MIPMAP_LINEAR`; trilinear
    /// filtering with [`super::FilterMode::Bilinear`]).
    #[default]
    Linear,
}

/// One level of detail, in the units [`MipChain::level_of_detail`] counts them.
pub const LEVEL: u32 = 256;

impl MipChain<'_> {
    /// The level of detail of a sample whose texture coordinates change by `slopes` per pixel, in 1/[`LEVEL`]
    /// of a level: `log2` of the longer side of the pixel's footprint, in texels of the texture (OpenGL 4.6 core
    /// profile, section 8.14.1, with `rho` the larger of the two lengths), 0 where a pixel covers at most a texel
    /// (magnification) and at most the last level's. Non-finite slopes give the last level.
    ///
    /// `log2` is read from the float's bits, exponent plus mantissa: a piecewise-linear `log2`, exact at powers
    /// of two and at most 0.086 below between them (Blinn, "Floating-point tricks", IEEE CG&A 17(4), 1997), the
    /// same on every target.
    #[must_use]
    #[inline(always)]
    pub fn level_of_detail(&self, slopes: &Slopes<Vec2>) -> u32 {
        let top = &self.levels()[0];
        level_of_detail(
            top.width() as f32,
            top.height() as f32,
            [slopes.dx.x, slopes.dx.y, slopes.dy.x, slopes.dy.y],
            self.levels().len(),
        )
    }

    /// The chain's texel at `uv` (wrap mode `W`) and level of detail `lod` ([`Self::level_of_detail`]), packed:
    /// filtered within a level by `F` and between levels as `mip` says.
    #[must_use]
    #[inline(always)]
    pub fn sample_packed<F: Filter, W: Wrap>(&self, uv: Vec2, lod: u32, mip: MipFilter) -> u32 {
        match mip {
            MipFilter::Off => F::sample_packed::<W>(self.level(0), uv),
            // Level 0 up to a level of detail of one half, then the nearest (OpenGL 4.6, equation 8.7).
            MipFilter::Nearest => F::sample_packed::<W>(self.level(((lod + LEVEL / 2 - 1) / LEVEL) as usize), uv),
            MipFilter::Linear => {
                let (level, fraction) = ((lod / LEVEL) as usize, lod % LEVEL);
                let near = F::sample_packed::<W>(self.level(level), uv);
                if fraction == 0 {
                    near
                } else {
                    blend(near, F::sample_packed::<W>(self.level(level + 1), uv), fraction)
                }
            }
        }
    }

    /// Level `k`, or the last.
    #[inline(always)]
    fn level(&self, k: usize) -> &Texture<'_> {
        let levels = self.levels();
        &levels[k.min(levels.len() - 1)]
    }
}

/// [`MipChain::level_of_detail`] for a `width x height` texture of `levels` levels, from the coordinate slopes
/// `[du/dx, dv/dx, du/dy, dv/dy]`: a function of plain values, so that lane loops can run it.
#[inline(always)]
pub(crate) fn level_of_detail(width: f32, height: f32, [ux, vx, uy, vy]: [f32; 4], levels: usize) -> u32 {
    let (x, y) = (ux * width, vx * height);
    let (p, q) = (uy * width, vy * height);
    let (along_x, along_y) = (x * x + y * y, p * p + q * q);
    let rho_squared = if along_x.is_nan() | along_y.is_nan() { f32::INFINITY } else { float::max(along_x, along_y) };
    // (exponent - 127) * 2^23 + mantissa, over 2^23: log2(rho^2) in the piecewise-linear approximation; over 2^16,
    // log2(rho) in 1/256 levels. The sign bit is dropped (a NaN may carry it): NaN and infinity give the top.
    let bits = (rho_squared.to_bits() & 0x7FFF_FFFF) as i32;
    let last = (levels.saturating_sub(1) as i32) * LEVEL as i32;
    ((bits - (127 << 23)) >> 16).clamp(0, last) as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{Bilinear, MipContent, Nearest, Repeat, build_mip_levels, mip_chain_texels};

    fn slopes(dx: (f32, f32), dy: (f32, f32)) -> Slopes<Vec2> {
        Slopes { dx: Vec2::new(dx.0, dx.1), dy: Vec2::new(dy.0, dy.1) }
    }

    /// A pixel spanning 2^k texels along its longer side is at level k exactly; magnification and degenerate
    /// slopes clamp to the chain.
    #[test]
    fn the_level_of_detail_is_log2_of_the_footprint() {
        let texels = [0; 64 * 16];
        let mut levels = [0; 343];
        assert_eq!(levels.len(), mip_chain_texels(64, 16));
        let texture = Texture::new(&texels, 64, 16).unwrap();
        build_mip_levels(&texture, MipContent::Data, &mut levels).unwrap();
        // 64x16, 32x8, 16x4, 8x2, 4x1, 2x1, 1x1: seven levels.
        let chain = texture.with_mip_levels(&levels).unwrap().mip_chain();
        assert_eq!(chain.levels().len(), 7);
        let at = |dx, dy| chain.level_of_detail(&slopes(dx, dy));
        // One texel per pixel across u (1/64) or down v (1/16): level 0.
        assert_eq!(at((1.0 / 64.0, 0.0), (0.0, 1.0 / 16.0)), 0);
        // Four texels per pixel along the longer axis, whichever it is: level 2.
        assert_eq!(at((4.0 / 64.0, 0.0), (0.0, 1.0 / 16.0)), 2 * LEVEL);
        assert_eq!(at((0.0, 0.0), (0.0, 4.0 / 16.0)), 2 * LEVEL);
        // 3 texels: rho^2 = 9 = 2^3 x 1.125, read as log2 3 + 0.125, halved: 1.5625 levels (log2 3 = 1.585), 400
        // of 256.
        assert_eq!(at((3.0 / 64.0, 0.0), (0.0, 0.0)), 400);
        // A diagonal 3 by 4 texels, 5 long: rho^2 = 25 = 2^4 x 1.5625, (4 + 0.5625) / 2 levels (log2 5 = 2.32).
        assert_eq!(at((3.0 / 64.0, 4.0 / 16.0), (0.0, 0.0)), 584);
        // Magnified, zero, and beyond the last level.
        assert_eq!(at((0.1 / 64.0, 0.0), (0.0, 0.0)), 0);
        assert_eq!(at((0.0, 0.0), (0.0, 0.0)), 0);
        assert_eq!(at((1e6, 0.0), (0.0, 0.0)), 6 * LEVEL);
        for bad in [f32::NAN, -f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert_eq!(at((bad, 0.0), (0.0, 0.0)), 6 * LEVEL, "{bad}");
        }
    }

    /// Between levels, `Linear` blends the two levels' samples by the fraction, `Nearest` takes the nearer
    /// (level 0 up to one half), and `Off` the texture itself.
    #[test]
    fn levels_are_chosen_and_blended_by_the_level_of_detail() {
        // 4x4 of 200, whose level 1 (2x2) and 2 (1x1) are 200 too but set apart by hand: 100 and 0.
        let grey = |v: u32| v << 16 | v << 8 | v;
        let texels = [grey(200); 16];
        let levels = [[grey(100); 4].as_slice(), &[grey(0)]].concat();
        let chain = Texture::new(&texels, 4, 4).unwrap().with_mip_levels(&levels).unwrap().mip_chain();
        let uv = Vec2::new(0.3, 0.6);
        let sample = |lod, mip| chain.sample_packed::<Bilinear, Repeat>(uv, lod, mip) & 0xFF;
        assert_eq!(sample(0, MipFilter::Linear), 200);
        // A quarter of the way from level 0 to level 1: 200 + (100 - 200) 64 / 256.
        assert_eq!(sample(64, MipFilter::Linear), 175);
        assert_eq!(sample(LEVEL + 128, MipFilter::Linear), 50);
        assert_eq!(sample(2 * LEVEL, MipFilter::Linear), 0);
        assert_eq!(sample(128, MipFilter::Nearest), 200);
        assert_eq!(sample(129, MipFilter::Nearest), 100);
        assert_eq!(sample(LEVEL + 128, MipFilter::Nearest), 100);
        assert_eq!(sample(LEVEL + 129, MipFilter::Nearest), 0);
        assert_eq!(sample(2 * LEVEL, MipFilter::Off), 200);
        // A texture without levels is itself at every level of detail.
        let alone = Texture::new(&texels, 4, 4).unwrap().mip_chain();
        assert_eq!(alone.sample_packed::<Nearest, Repeat>(uv, 2 * LEVEL, MipFilter::Linear) & 0xFF, 200);
    }
}
