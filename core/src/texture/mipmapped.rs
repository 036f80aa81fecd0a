//! Sampling a mipmap chain: the level of detail from how fast the texture coordinates change across the screen,
//! and the filter between levels.

use super::sampler::blend;
use super::{Filter, MipChain, Texture, Wrap};
use crate::math::{Vec2, Vec3, float};
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
    /// Up to the given number of [`MipFilter::Linear`] probes, spread along the longer side of the pixel's
    /// footprint and averaged, each at the level of detail of the footprint's length over the number of probes:
    /// a footprint 8 texels long and 1 wide reads 8 probes at level 0 where `Linear` reads one at level 3, so a
    /// surface seen at a grazing angle keeps its detail across the view (`EXT_texture_filter_anisotropic`).
    Anisotropic(Anisotropy),
}

impl MipFilter {
    /// The most probes a sample averages, as a power of two: 0 unless [`MipFilter::Anisotropic`].
    #[must_use]
    pub const fn max_probes_log2(self) -> u32 {
        match self {
            Self::Anisotropic(most) => most.probes_log2(),
            Self::Off | Self::Nearest | Self::Linear => 0,
        }
    }
}

/// The most probes one anisotropic sample averages ([`MipFilter::Anisotropic`]): a power of two, so that the
/// average is a shift.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anisotropy {
    /// 2 probes.
    X2,
    /// 4 probes.
    X4,
    /// 8 probes.
    X8,
    /// 16 probes.
    X16,
}

impl Anisotropy {
    /// `log2` of the number of probes.
    #[must_use]
    pub const fn probes_log2(self) -> u32 {
        match self {
            Self::X2 => 1,
            Self::X4 => 2,
            Self::X8 => 3,
            Self::X16 => 4,
        }
    }

    /// The number of probes: 2, 4, 8 or 16.
    #[must_use]
    pub const fn probes(self) -> u32 {
        1 << self.probes_log2()
    }
}

/// One level of detail, in the units [`Footprint::lod`] counts them.
pub const LEVEL: u32 = 256;

/// Where a sample reads a chain ([`MipChain::footprint`]): the level of detail and, for an anisotropic sample,
/// the probes along the pixel's footprint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Footprint {
    /// The level of detail each probe is read at, in 1/[`LEVEL`] of a level.
    pub lod: u32,
    /// `log2` of the number of probes: 0 for one (at the sample's coordinates).
    pub probes_log2: u32,
    /// The longer side of the footprint in texture coordinates: the probes lie evenly along it, centred on the
    /// sample's coordinates.
    pub axis: Vec2,
}

impl Footprint {
    /// One probe at level of detail `lod`.
    #[must_use]
    pub const fn at_level(lod: u32) -> Self {
        Self { lod, probes_log2: 0, axis: Vec2::ZERO }
    }
}

impl MipChain<'_> {
    /// Where a sample whose texture coordinates change by `slopes` per pixel reads the chain under `mip`.
    ///
    /// The level of detail is `log2` of the longer side of the pixel's footprint in texels, `rho` (OpenGL 4.6
    /// core profile, section 8.14.1, with `rho` the larger of the two lengths), less half a level (a sharpening
    /// measured against the reference, see `SHARPENING`), 0 where a pixel covers at most `sqrt(2)` texels and at
    /// most the last level's. An anisotropic sample takes `2^k` probes, `k` the
    /// least with `2^k` at least the ratio of the longer side to the shorter, up to the filter's most, and reads
    /// each at `log2(rho / 2^k)`, less the same half (`EXT_texture_filter_anisotropic`, with the probe count rounded up to a power of
    /// two); one probe where the footprint is at most a texel long or the texture has no levels. Non-finite slopes
    /// give one probe at the last level.
    ///
    /// `log2` is read from the float's bits, exponent plus mantissa: a piecewise-linear `log2`, exact at powers
    /// of two and at most 0.086 below between them (Blinn, "Floating-point tricks", IEEE CG&A 17(4), 1997), the
    /// same on every target.
    #[must_use]
    #[inline(always)]
    pub fn footprint(&self, slopes: &Slopes<Vec2>, mip: MipFilter) -> Footprint {
        let top = self.level(0);
        footprint(
            top.width() as f32,
            top.height() as f32,
            [slopes.dx.x, slopes.dx.y, slopes.dy.x, slopes.dy.y],
            self.level_count(),
            mip.max_probes_log2(),
        )
    }

    /// The chain's texel at `uv` (wrap mode `W`) read where `at` says ([`Self::footprint`]), packed and as stored:
    /// filtered within a level by `F` and between levels as `mip` says, anisotropic probes averaged. Data maps
    /// (normals, occlusion, transparency) are read so, and colour maps in a draw that lights sRGB codes.
    #[must_use]
    #[inline(always)]
    pub fn sample_packed<F: Filter, W: Wrap>(&self, uv: Vec2, at: &Footprint, mip: MipFilter) -> u32 {
        match mip {
            MipFilter::Off => F::sample_packed::<W>(&self.level(0), uv),
            MipFilter::Nearest => F::sample_packed::<W>(&self.nearest_level(at.lod), uv),
            MipFilter::Linear => self.between_levels::<F, W>(uv, at.lod),
            MipFilter::Anisotropic(_) if at.probes_log2 == 0 => self.between_levels::<F, W>(uv, at.lod),
            MipFilter::Anisotropic(_) => {
                // Every channel summed in its own 16 bits of a word (16 probes of 255 fit), the mean rounded to
                // nearest.
                let (mut rb, mut tg) = (0u32, 0u32);
                for point in probe_points(uv, at) {
                    let probe = self.between_levels::<F, W>(point, at.lod);
                    rb += probe & 0xFF_00FF;
                    tg += (probe >> 8) & 0xFF_00FF;
                }
                let half = (1u32 << at.probes_log2) / 2 * 0x1_0001;
                let mean = |sum: u32| ((sum + half) >> at.probes_log2) & 0xFF_00FF;
                mean(rb) | mean(tg) << 8
            }
        }
    }

    /// The colour of the sRGB-encoded colour map at `uv` (wrap mode `W`) in linear light, read where `at` says:
    /// what [`Self::sample_packed`] reads, but with every texel decoded before any blend, within a level
    /// ([`Filter::sample_light`]), between levels and across probes, as the levels themselves are averaged
    /// ([`super::build_mip_levels`]). Blending codes instead darkens every blend of a dark and a light texel: half-way
    /// between codes 26 and 242 (a checkerboard's squares) it gives code 134 where the light's mean is code 179.
    #[inline(always)]
    pub fn sample_light<F: Filter, W: Wrap>(&self, uv: Vec2, at: &Footprint, mip: MipFilter) -> Vec3 {
        match mip {
            MipFilter::Off => F::sample_light::<W>(&self.level(0), uv),
            MipFilter::Nearest => F::sample_light::<W>(&self.nearest_level(at.lod), uv),
            MipFilter::Linear => self.light_between_levels::<F, W>(uv, at.lod),
            MipFilter::Anisotropic(_) if at.probes_log2 == 0 => self.light_between_levels::<F, W>(uv, at.lod),
            MipFilter::Anisotropic(_) => {
                // Summed in probe order and scaled by the exact `1 / n`: the same bits on every target.
                let mut light = Vec3::ZERO;
                for point in probe_points(uv, at) {
                    light += self.light_between_levels::<F, W>(point, at.lod);
                }
                light * (1.0 / (1u32 << at.probes_log2) as f32)
            }
        }
    }

    /// The level [`MipFilter::Nearest`] reads at `lod`: level 0 up to a level of detail of one half, then the
    /// nearest (OpenGL 4.6, equation 8.7).
    #[inline(always)]
    fn nearest_level(&self, lod: u32) -> Texture<'_> {
        self.level(self.levels_read(lod, MipFilter::Nearest).0)
    }

    /// The level a one-probe sample at level of detail `lod` reads under `mip` (not past the last), and how far
    /// it is toward the next, in 1/[`LEVEL`]: 0 when it reads that level alone (always under
    /// [`MipFilter::Nearest`] and [`MipFilter::Off`], which reads level 0).
    #[inline(always)]
    pub(crate) fn levels_read(&self, lod: u32, mip: MipFilter) -> (usize, u32) {
        let last = self.level_count() - 1;
        match mip {
            MipFilter::Off => (0, 0),
            MipFilter::Nearest => ((((lod + LEVEL / 2 - 1) / LEVEL) as usize).min(last), 0),
            MipFilter::Linear | MipFilter::Anisotropic(_) => match (lod / LEVEL) as usize {
                level if level >= last => (last, 0),
                level => (level, lod % LEVEL),
            },
        }
    }

    /// The two levels around `lod` at `uv`, blended by where it lies between them.
    #[inline(always)]
    fn between_levels<F: Filter, W: Wrap>(&self, uv: Vec2, lod: u32) -> u32 {
        let (level, fraction) = self.levels_read(lod, MipFilter::Linear);
        let near = F::sample_packed::<W>(&self.level(level), uv);
        if fraction == 0 { near } else { blend(near, F::sample_packed::<W>(&self.level(level + 1), uv), fraction) }
    }

    /// [`Self::between_levels`] in linear light.
    #[inline(always)]
    fn light_between_levels<F: Filter, W: Wrap>(&self, uv: Vec2, lod: u32) -> Vec3 {
        let (level, fraction) = self.levels_read(lod, MipFilter::Linear);
        let near = F::sample_light::<W>(&self.level(level), uv);
        if fraction == 0 {
            return near;
        }
        light_between(near, F::sample_light::<W>(&self.level(level + 1), uv), fraction)
    }
}

/// The light `fraction` (in 1/[`LEVEL`], above 0) of the way from a level's sample `near` to the next level's
/// `far`: the one blend between levels in light, so that every reader of levels gives the same bits.
#[inline(always)]
pub(crate) fn light_between(near: Vec3, far: Vec3, fraction: u32) -> Vec3 {
    // Exact: a fraction in 256ths.
    near.lerp(far, fraction as f32 * (1.0 / LEVEL as f32))
}

/// Where `at`'s probes lie around `uv`: probe `j` of `n` at `uv + axis (2j + 1 - n) / 2n`.
#[inline(always)]
fn probe_points(uv: Vec2, at: &Footprint) -> impl Iterator<Item = Vec2> {
    let n = 1i32 << at.probes_log2;
    // An odd integer over a power of two: exact.
    (0..n).map(move |j| uv + at.axis * ((2 * j + 1 - n) as f32 / (2 * n) as f32))
}

/// [`MipChain::footprint`] for a `width x height` texture of `levels` levels, from the coordinate slopes
/// `[du/dx, dv/dx, du/dy, dv/dy]` and at most `2^max_probes_log2` probes: a function of plain values, so that lane
/// loops can run it.
#[inline(always)]
pub(crate) fn footprint(
    width: f32,
    height: f32,
    [ux, vx, uy, vy]: [f32; 4],
    levels: usize,
    max_probes_log2: u32,
) -> Footprint {
    let (x, y) = (ux * width, vx * height);
    let (p, q) = (uy * width, vy * height);
    let (along_x, along_y) = (x * x + y * y, p * p + q * q);
    let last = (levels.saturating_sub(1) as i32) * LEVEL as i32;
    // NaN (either way round) and infinity: one probe at the last level.
    if !(along_x <= f32::MAX && along_y <= f32::MAX) {
        return Footprint::at_level(last as u32);
    }
    let rho = log2_of_root(float::max(along_x, along_y));
    // A texture without levels is read alone, as without anisotropy.
    let most = if levels > 1 { max_probes_log2 } else { 0 };
    if most == 0 {
        return Footprint::at_level((rho - SHARPENING).clamp(0, last) as u32);
    }
    let (shorter, axis) = if along_x >= along_y { (along_y, Vec2::new(ux, vx)) } else { (along_x, Vec2::new(uy, vy)) };
    // The least k with 2^k at least the longer side over the shorter (the difference of their logarithms, rounded
    // up to whole levels): 0 when the footprint is round, and when it is at most a texel long (magnified, the
    // probes would read one texel).
    let spread = if rho > 0 { (rho - log2_of_root(shorter)).max(0) as u32 } else { 0 };
    let k = spread.div_ceil(LEVEL).min(most);
    Footprint { lod: (rho - SHARPENING - (k * LEVEL) as i32).clamp(0, last) as u32, probes_log2: k, axis }
}

/// How much finer than `log2(rho)` a sample's level of detail is taken: half a level. A level's texel stands for
/// a box of texels above it, and the bilinear filter and the blend with the next level widen that further, so
/// `log2(rho)` blurs a pixel over more than its footprint. Chosen by measurement against the reference (the
/// accuracy report's floor and model, trilinear, for 0, 1/4, 1/2 and 3/4 of a level; docs/accuracy.md).
const SHARPENING: i32 = LEVEL as i32 / 2;

/// `log2(sqrt(squared))` in 1/[`LEVEL`] levels, for a finite `squared >= 0`: (exponent - 127) * 2^23 + mantissa,
/// over 2^23, is `log2` in the piecewise-linear approximation; over 2^16 it is the root's in 1/256 levels. Zero
/// gives -16,256.
#[inline(always)]
fn log2_of_root(squared: f32) -> i32 {
    ((squared.to_bits() & 0x7FFF_FFFF) as i32 - (127 << 23)) >> 16
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::SRGB_DECODE;
    use crate::texture::{Bilinear, MipContent, Nearest, Repeat, build_mip_levels, mip_chain_texels};

    fn slopes(dx: (f32, f32), dy: (f32, f32)) -> Slopes<Vec2> {
        Slopes { dx: Vec2::new(dx.0, dx.1), dy: Vec2::new(dy.0, dy.1) }
    }

    /// A pixel spanning 2^k texels along its longer side is at level k - 1/2 exactly; magnification and
    /// degenerate slopes clamp to the chain.
    #[test]
    fn the_level_of_detail_is_log2_of_the_footprint_less_a_half() {
        let texels = [0; 64 * 16];
        let mut levels = [0; 343];
        assert_eq!(levels.len(), mip_chain_texels(64, 16));
        let texture = Texture::new(&texels, 64, 16).unwrap();
        build_mip_levels(&texture, MipContent::Data, &mut levels).unwrap();
        // 64x16, 32x8, 16x4, 8x2, 4x1, 2x1, 1x1: seven levels.
        let chain = texture.with_mip_levels(&levels).unwrap().mip_chain();
        assert_eq!(chain.level_count(), 7);
        let at = |dx, dy| {
            let footprint = chain.footprint(&slopes(dx, dy), MipFilter::Linear);
            assert_eq!(footprint.probes_log2, 0);
            footprint.lod
        };
        // One texel per pixel across u (1/64) or down v (1/16), and sqrt(2) texels: level 0.
        assert_eq!(at((1.0 / 64.0, 0.0), (0.0, 1.0 / 16.0)), 0);
        assert_eq!(at((1.0 / 64.0, 1.0 / 16.0), (0.0, 0.0)), 0);
        // Four texels per pixel along the longer axis, whichever it is: level 2 less a half.
        assert_eq!(at((4.0 / 64.0, 0.0), (0.0, 1.0 / 16.0)), 2 * LEVEL - LEVEL / 2);
        assert_eq!(at((0.0, 0.0), (0.0, 4.0 / 16.0)), 2 * LEVEL - LEVEL / 2);
        // 3 texels: rho^2 = 9 = 2^3 x 1.125, read as log2 3 + 0.125, halved: 1.5625 levels (log2 3 = 1.585), 400
        // of 256, less 128.
        assert_eq!(at((3.0 / 64.0, 0.0), (0.0, 0.0)), 272);
        // A diagonal 3 by 4 texels, 5 long: rho^2 = 25 = 2^4 x 1.5625, (4 + 0.5625) / 2 levels (log2 5 = 2.32),
        // 584, less 128.
        assert_eq!(at((3.0 / 64.0, 4.0 / 16.0), (0.0, 0.0)), 456);
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
        let sample = |lod, mip| chain.sample_packed::<Bilinear, Repeat>(uv, &Footprint::at_level(lod), mip) & 0xFF;
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
        // In light the levels' decoded values are blended: a quarter of the way, 3/4 of 200's light and 1/4 of
        // 100's, not the light of code 175.
        let light = |lod, mip| chain.sample_light::<Bilinear, Repeat>(uv, &Footprint::at_level(lod), mip).x;
        let decoded = |code: usize| SRGB_DECODE[code];
        assert_eq!(light(0, MipFilter::Linear), decoded(200));
        assert_eq!(light(64, MipFilter::Linear), decoded(200) + (decoded(100) - decoded(200)) * 0.25);
        assert!((light(64, MipFilter::Linear) - 0.4650).abs() < 1e-3 && decoded(175) < 0.43);
        assert_eq!(light(LEVEL + 128, MipFilter::Linear), decoded(100) * 0.5);
        assert_eq!(light(129, MipFilter::Nearest), decoded(100));
        assert_eq!(light(2 * LEVEL, MipFilter::Off), decoded(200));
        // A texture without levels is itself at every level of detail.
        let alone = Texture::new(&texels, 4, 4).unwrap().mip_chain();
        let far = Footprint::at_level(2 * LEVEL);
        assert_eq!(alone.sample_packed::<Nearest, Repeat>(uv, &far, MipFilter::Linear) & 0xFF, 200);
        assert_eq!(alone.sample_light::<Nearest, Repeat>(uv, &far, MipFilter::Linear).x, decoded(200));
    }

    /// An anisotropic footprint takes the least power of two of probes that covers its longer side with squares
    /// of its shorter, up to the filter's most, and reads them at the longer side's level less that power (and
    /// less the half level every footprint is sharpened by).
    #[test]
    fn anisotropic_footprints_count_probes_along_the_longer_side() {
        let texels = [0; 64 * 64];
        let mut levels = [0; 1365];
        assert_eq!(levels.len(), mip_chain_texels(64, 64));
        let texture = Texture::new(&texels, 64, 64).unwrap();
        build_mip_levels(&texture, MipContent::Data, &mut levels).unwrap();
        let chain = texture.with_mip_levels(&levels).unwrap().mip_chain();
        let texel = 1.0 / 64.0;
        let at = |dx: (f32, f32), dy: (f32, f32), most| chain.footprint(&slopes(dx, dy), MipFilter::Anisotropic(most));
        let footprint =
            |lod, probes_log2, axis: (f32, f32)| Footprint { lod, probes_log2, axis: Vec2::new(axis.0, axis.1) };
        // 8 texels along x, 1 down y: 8 probes at level 0 along x's slope, or 4 at level 1/2 when 4 is the most.
        assert_eq!(at((8.0 * texel, 0.0), (0.0, texel), Anisotropy::X16), footprint(0, 3, (8.0 * texel, 0.0)));
        assert_eq!(at((8.0 * texel, 0.0), (0.0, texel), Anisotropy::X4), footprint(128, 2, (8.0 * texel, 0.0)));
        // The longer side down the screen, 16 by 2 texels: 8 probes at level 1/2.
        assert_eq!(
            at((2.0 * texel, 0.0), (0.0, 16.0 * texel), Anisotropy::X16),
            footprint(128, 3, (0.0, 16.0 * texel))
        );
        // Slanted in the texture, 20 (12 across, 16 down) by 2 texels: log2 400 read as 8 + 0.5625, halved, is 1,096
        // 256ths (log2 20 = 4.32 levels); 16 probes (log2 10 = 3.3, rounded up to 4 levels) at 1,096 - 128 -
        // 1,024 < 0, so level 0.
        let (du, dv) = (12.0 * texel, 16.0 * texel);
        assert_eq!(at((2.0 * texel, 0.0), (du, dv), Anisotropy::X16), footprint(0, 4, (du, dv)));
        // 3 by 1: 4 probes (the least power of two at least 3, log2 3 read as 1.5625 levels), at log2 3 - 2 < 0,
        // so level 0.
        assert_eq!(at((3.0 * texel, 0.0), (0.0, texel), Anisotropy::X16), footprint(0, 2, (3.0 * texel, 0.0)));
        // A round footprint, 4 by 4 texels: one probe, as trilinear reads it.
        assert_eq!(at((4.0 * texel, 0.0), (0.0, 4.0 * texel), Anisotropy::X16), footprint(384, 0, (4.0 * texel, 0.0)));
        // A line (no width), 32 texels long: the most probes, at level 5 - 3 - 1/2; magnified: one at level 0.
        assert_eq!(at((32.0 * texel, 0.0), (0.0, 0.0), Anisotropy::X8), footprint(384, 3, (32.0 * texel, 0.0)));
        assert_eq!(at((0.5 * texel, 0.0), (0.0, 0.25 * texel), Anisotropy::X16), footprint(0, 0, (0.5 * texel, 0.0)));
        // Not finite: one probe at the last level (six levels below the top).
        for bad in [f32::NAN, -f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert_eq!(at((bad, 0.0), (0.0, texel), Anisotropy::X16), Footprint::at_level(6 * LEVEL), "{bad}");
        }
    }

    /// An anisotropic sample is the mean of its probes, each read between levels at its place along the axis: as
    /// stored, or in linear light; with one probe it is the trilinear sample.
    #[test]
    fn an_anisotropic_sample_is_the_mean_of_its_probes() {
        // 4x1 texels 0, 10, 20, 250 (grey), no levels: probes of a 4-texel footprint along u read one texel each.
        let grey = |v: u32| v << 16 | v << 8 | v;
        let texels = [grey(0), grey(10), grey(20), grey(250)];
        let chain = Texture::new(&texels, 4, 1).unwrap().mip_chain();
        let mip = MipFilter::Anisotropic(Anisotropy::X4);
        let at = |probes_log2| Footprint { lod: 0, probes_log2, axis: Vec2::new(1.0, 0.0) };
        let centre = Vec2::new(0.5, 0.5);
        let stored = |probes_log2| chain.sample_packed::<Nearest, Repeat>(centre, &at(probes_log2), mip);
        let light = |probes_log2| chain.sample_light::<Nearest, Repeat>(centre, &at(probes_log2), mip);
        let decoded = |code: usize| SRGB_DECODE[code];
        // Probes at u = 0.5 + (-3, -1, 1, 3)/8: 0.125, 0.375, 0.625, 0.875, texels 0..4: (0 + 10 + 20 + 250) / 4 as
        // stored; in light, the mean of the decoded codes (0.2415, code 134.80).
        assert_eq!(stored(2), grey(70));
        assert_eq!(light(2), Vec3::splat((((decoded(0) + decoded(10)) + decoded(20)) + decoded(250)) * 0.25));
        // Two probes at 0.25 and 0.75: (10 + 250) / 2; in light, 184.03's.
        assert_eq!(stored(1), grey(130));
        assert_eq!(light(1), Vec3::splat((decoded(10) + decoded(250)) * 0.5));
        // Every channel apart, transparency too: 255 in one of four probes is 63.75, 64; in light a quarter of
        // white.
        let texels = [0xFF00_0000, 0x00FF_0000, 0x0000_FF00, 0x0000_00FF];
        let chain = Texture::new(&texels, 4, 1).unwrap().mip_chain();
        assert_eq!(chain.sample_packed::<Nearest, Repeat>(centre, &at(2), mip), 0x4040_4040);
        assert_eq!(chain.sample_light::<Nearest, Repeat>(centre, &at(2), mip), Vec3::splat(0.25));
        // One probe: the trilinear sample.
        let uv = Vec2::new(0.3, 0.5);
        let one = chain.sample_packed::<Bilinear, Repeat>(uv, &at(0), mip);
        assert_eq!(one, chain.sample_packed::<Bilinear, Repeat>(uv, &at(0), MipFilter::Linear));
        let one = chain.sample_light::<Bilinear, Repeat>(uv, &at(0), mip);
        assert_eq!(one, chain.sample_light::<Bilinear, Repeat>(uv, &at(0), MipFilter::Linear));
    }
}
