//! The first sum of the split-sum approximation: an environment's light averaged over the GGX lobe of one
//! roughness around each direction (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013, the
//! `PrefilterEnvMap` listing, with `n = v = r`), read from the level of detail whose texels match each sample's
//! share of the lobe (Křivánek and Colbert, "Real-time Shading with Filtered Importance Sampling", 2008), so that
//! few samples give a smooth result.

use core::f32::consts::PI;
use core::ops::Range;

use super::Irradiance;
use super::chain::{MOST_LEVELS, PanoramaChain, level_height, level_range, reduce};
use super::panorama::{Panorama, PanoramaError, check_shape, texel_direction};
use super::sampling::{ggx_half_vector, hammersley, reflect};
use crate::math::{Vec3, float};
use crate::shading::brdf::distribution;

/// Fills `out` with rows `rows` of a `2 height x height` panorama of `source`'s light prefiltered for perceptual
/// roughness `roughness` (clamped to `[0, 1]`), over `samples` microfacet normals per texel: each texel the mean
/// of the light from the sampled directions `l` around its direction `r`, weighted by `n . l`. At roughness 0 each
/// texel is `source`'s light in its direction (its first level's texel when the sizes match).
///
/// Rows are independent: a caller may fill a level's rows on several threads and get the same texels.
///
/// # Errors
/// [`PanoramaError::Shape`] for a height that is not a panorama's or rows beyond it; [`PanoramaError::Length`]
/// when `out` does not hold exactly those rows.
pub fn prefilter_rows(
    source: &PanoramaChain<'_>,
    roughness: f32,
    samples: u32,
    height: u32,
    rows: Range<u32>,
    out: &mut [Vec3],
) -> Result<(), PanoramaError> {
    let width = height.checked_mul(2).unwrap_or(0);
    check_shape(width, height)?;
    if rows.start > rows.end || rows.end > height {
        return Err(PanoramaError::Shape { width, height });
    }
    let expected = (rows.end - rows.start) as usize * width as usize;
    if out.len() != expected {
        return Err(PanoramaError::Length { expected, actual: out.len() });
    }
    let roughness = float::clamp(roughness, 0.0, 1.0);
    let base = source.level(0);
    let same_size = base.height() == height;
    let alpha = roughness * roughness;
    // The solid angle of one texel of the source's first level, on average.
    let texel_angle = 4.0 * PI / (base.width() as f32 * base.height() as f32);
    let samples = samples.max(1);
    for (y, row) in rows.zip(out.chunks_exact_mut(width as usize)) {
        for (x, texel) in (0..width).zip(row.iter_mut()) {
            *texel = if roughness == 0.0 && same_size {
                base.texel(x, y)
            } else if roughness == 0.0 {
                base.sample(texel_direction(x, y, width, height))
            } else {
                lobe_mean(source, texel_direction(x, y, width, height), alpha, samples, texel_angle)
            };
        }
    }
    Ok(())
}

/// The light of `source` over the GGX lobe of `alpha` around the unit direction `r`, weighted by `n . l`.
fn lobe_mean(source: &PanoramaChain<'_>, r: Vec3, alpha: f32, samples: u32, texel_angle: f32) -> Vec3 {
    let (mut sum, mut weight) = (Vec3::ZERO, 0.0);
    for i in 0..samples {
        let (a, b) = hammersley(i, samples);
        let h = ggx_half_vector(a, b, alpha, r);
        let l = reflect(r, h);
        let n_dot_l = r.dot(l);
        if n_dot_l <= 0.0 {
            continue;
        }
        // With n = v the density of l is D / 4; its share of the sphere, 1 / (samples pdf), against a texel's.
        let density = distribution(alpha, r.dot(h)) * 0.25;
        let sample_angle = 1.0 / (samples as f32 * density + 1e-20);
        let lod = 0.5 * float::log2(sample_angle / texel_angle) + 1.0;
        sum += source.sample(l, lod) * n_dot_l;
        weight += n_dot_l;
    }
    if weight > 0.0 { sum * (1.0 / weight) } else { source.sample(r, 0.0) }
}

/// How finely an environment's specular light is prefiltered: the quality knobs of image-based lighting.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prefiltering {
    /// Rows of the first level (roughness 0), at most: a smaller source keeps its own.
    pub height: u32,
    /// Levels, roughness 0 to 1 in equal steps (at least 2; the sample viewer's chains have 6 to 10).
    pub levels: u32,
    /// Microfacet normals sampled per texel.
    pub samples: u32,
}

impl Prefiltering {
    /// 128 rows (256x128 texels), 6 levels (roughness steps of 0.2), 64 samples per texel.
    pub const DEFAULT: Self = Self { height: 128, levels: 6, samples: 64 };

    /// The first level's rows for a source of `source_height` rows: the smaller of the two.
    #[must_use]
    pub fn height_for(&self, source_height: u32) -> u32 {
        self.height.min(source_height)
    }

    /// The texels [`prepare`] fills for a source of `source_height` rows: its levels of detail, its specular chain.
    ///
    /// # Errors
    /// As [`PanoramaChain::texel_count`].
    pub fn texel_counts(&self, source_height: u32) -> Result<(usize, usize), PanoramaError> {
        let height = self.height_for(source_height);
        Ok((
            PanoramaChain::texel_count(height, detail_levels(height))?,
            PanoramaChain::texel_count(height, self.levels)?,
        ))
    }
}

/// Makes `source` ready on this thread as `prefiltering` says: its levels of detail into `lods`
/// ([`fill_levels_of_detail`]), its specular chain into `specular` ([`prefilter`]), each sized by
/// [`Prefiltering::texel_counts`]; returns its irradiance. A caller with threads fills the chain's rows itself
/// ([`prefilter_rows`]).
///
/// # Errors
/// As [`fill_levels_of_detail`] and [`prefilter`].
pub fn prepare(
    source: &Panorama<'_>,
    prefiltering: &Prefiltering,
    lods: &mut [Vec3],
    specular: &mut [Vec3],
) -> Result<Irradiance, PanoramaError> {
    let height = prefiltering.height_for(source.height());
    fill_levels_of_detail(source, height, lods)?;
    let lods = PanoramaChain::new(height, detail_levels(height), lods)?;
    prefilter(&lods, prefiltering, height, specular)?;
    Ok(Irradiance::of(&lods.level(0)))
}

impl Default for Prefiltering {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The levels of detail of a chain whose first level has `height` rows: one for each halving down to
/// [`LEAST_HEIGHT`](super::chain::LEAST_HEIGHT) rows (1 for a height of at most that).
#[must_use]
pub fn detail_levels(height: u32) -> u32 {
    let mut levels = 1;
    while level_height(height, levels) < level_height(height, levels - 1) {
        levels += 1;
    }
    levels.min(MOST_LEVELS)
}

/// Fills `out` with the levels of detail of `source` from `height` rows down ([`detail_levels`] of them): the first
/// `source` averaged to `2 height x height` texels, each next the one before averaged to half its size
/// ([`reduce`]).
///
/// # Errors
/// As [`reduce`]; [`PanoramaError::Length`] when `out` does not hold the chain's texels.
pub fn fill_levels_of_detail(source: &Panorama<'_>, height: u32, out: &mut [Vec3]) -> Result<(), PanoramaError> {
    let levels = detail_levels(height);
    let expected = PanoramaChain::texel_count(height, levels)?;
    if out.len() != expected {
        return Err(PanoramaError::Length { expected, actual: out.len() });
    }
    reduce(source, height, &mut out[level_range(height, levels, 0)])?;
    for i in 1..levels {
        let (done, rest) = out.split_at_mut(level_range(height, levels, i).start);
        let before = level_range(height, levels, i - 1);
        let h = level_height(height, i - 1);
        let previous = Panorama::new(2 * h, h, &done[before])?;
        let next = level_height(height, i);
        reduce(&previous, next, &mut rest[..2 * next as usize * next as usize])?;
    }
    Ok(())
}

/// Fills `out` with the specular light of the environment whose levels of detail are `lods`: a chain of
/// `prefiltering.levels` levels from `height` rows, level `i` prefiltered for roughness `i / (levels - 1)`
/// ([`prefilter_rows`], on this thread).
///
/// # Errors
/// As [`prefilter_rows`]; [`PanoramaError::Length`] when `out` does not hold the chain's texels;
/// [`PanoramaError::Shape`] for fewer than 2 levels.
pub fn prefilter(
    lods: &PanoramaChain<'_>,
    prefiltering: &Prefiltering,
    height: u32,
    out: &mut [Vec3],
) -> Result<(), PanoramaError> {
    let levels = prefiltering.levels;
    let expected = PanoramaChain::texel_count(height, levels)?;
    if levels < 2 {
        return Err(PanoramaError::Shape { width: 2 * height, height });
    }
    if out.len() != expected {
        return Err(PanoramaError::Length { expected, actual: out.len() });
    }
    for i in 0..levels {
        let h = level_height(height, i);
        let roughness = i as f32 / (levels - 1) as f32;
        prefilter_rows(lods, roughness, prefiltering.samples, h, 0..h, &mut out[level_range(height, levels, i)])?;
    }
    Ok(())
}
