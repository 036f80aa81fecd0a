//! A chain of panoramas, each level half the height of the one before and never fewer than [`LEAST_HEIGHT`] rows,
//! in one buffer the caller owns: the environment's levels of detail, and its light prefiltered for each roughness.

use core::ops::Range;

use super::panorama::{Panorama, PanoramaError, check_shape, to_panorama};
use crate::math::{Vec3, float};

/// The fewest rows a level has: below that, the chain's levels keep this height.
pub const LEAST_HEIGHT: u32 = 8;

/// The most levels a chain has.
pub const MOST_LEVELS: u32 = 16;

/// Levels of panoramas, borrowed: level 0 is `2 height x height` texels, level `i` the larger of `height >> i`
/// and [`LEAST_HEIGHT`] rows (or `height` when that is smaller), one after another in one slice.
#[derive(Clone, Copy, Debug)]
pub struct PanoramaChain<'a> {
    height: u32,
    levels: u32,
    texels: &'a [Vec3],
}

impl<'a> PanoramaChain<'a> {
    /// A chain of `levels` levels below a first of `2 height x height` texels, in `texels`
    /// ([`Self::texel_count`] of them).
    ///
    /// # Errors
    /// [`PanoramaError::Shape`] for a height of 0, no levels or more than [`MOST_LEVELS`];
    /// [`PanoramaError::Length`] when `texels` holds another number of texels.
    pub fn new(height: u32, levels: u32, texels: &'a [Vec3]) -> Result<Self, PanoramaError> {
        let expected = Self::texel_count(height, levels)?;
        if texels.len() != expected {
            return Err(PanoramaError::Length { expected, actual: texels.len() });
        }
        Ok(Self { height, levels, texels })
    }

    /// The texels a chain of `levels` levels below a first of `2 height x height` needs.
    ///
    /// # Errors
    /// [`PanoramaError::Shape`] for a height of 0 or one whose first level's texels overflow, no levels or more
    /// than [`MOST_LEVELS`].
    pub fn texel_count(height: u32, levels: u32) -> Result<usize, PanoramaError> {
        let width = height.checked_mul(2).unwrap_or(0);
        check_shape(width, height)?;
        if levels == 0 || levels > MOST_LEVELS {
            return Err(PanoramaError::Shape { width, height });
        }
        Ok(level_range(height, levels, levels - 1).end)
    }

    /// Levels.
    #[must_use]
    pub fn levels(&self) -> u32 {
        self.levels
    }

    /// Level `i` (the last for a larger `i`).
    #[must_use]
    pub fn level(&self, i: u32) -> Panorama<'a> {
        let i = i.min(self.levels - 1);
        let h = level_height(self.height, i);
        let texels = &self.texels[level_range(self.height, self.levels, i)];
        Panorama::new(2 * h, h, texels).unwrap_or_else(|_| unreachable!("a level's range holds its texels"))
    }

    /// The light from direction `d` at level of detail `lod` (0 the first level): the two levels around it, each
    /// blended from its four nearest texels, blended by `lod`'s fraction. A `lod` below 0, or NaN, reads the first
    /// level; one past the last level reads the last.
    pub fn sample(&self, d: Vec3, lod: f32) -> Vec3 {
        let last = (self.levels - 1) as f32;
        let lod = float::clamp(lod, 0.0, last);
        let below = float::floor(lod);
        let fraction = lod - below;
        // The direction's coordinates once, for both levels.
        let (u, v) = to_panorama(d);
        let near = self.level(below as u32).sample_at(u, v);
        if fraction == 0.0 {
            return near;
        }
        near.lerp(self.level(below as u32 + 1).sample_at(u, v), fraction)
    }
}

/// The rows of level `i` of a chain whose first level has `height` rows.
#[inline(always)]
#[must_use]
pub fn level_height(height: u32, i: u32) -> u32 {
    (height >> i.min(31)).max(height.min(LEAST_HEIGHT))
}

/// Where level `i` of a chain of `levels` levels, the first `height` rows high, lies in its texels.
#[must_use]
pub fn level_range(height: u32, levels: u32, i: u32) -> Range<usize> {
    let size = |level: u32| {
        let h = level_height(height, level) as usize;
        2 * h * h
    };
    let start = (0..i.min(levels)).map(size).sum();
    start..start + size(i)
}

/// Averages the panorama `source` into the `2 height x height` texels `out`, no larger: each texel of `source`
/// goes into the texel of `out` its centre falls in, weighted by the solid angle it covers (the sine of its polar
/// angle), so a texel of `out` holds the mean light over its own solid angle. A panorama of the same size is
/// copied as it is.
///
/// # Errors
/// [`PanoramaError::Shape`] when `out` is not a panorama's shape or larger than `source`;
/// [`PanoramaError::Length`] when `out` does not hold `2 height x height` texels.
pub fn reduce(source: &Panorama<'_>, height: u32, out: &mut [Vec3]) -> Result<(), PanoramaError> {
    let width = height.checked_mul(2).unwrap_or(0);
    check_shape(width, height)?;
    if height > source.height() {
        return Err(PanoramaError::Shape { width, height });
    }
    let expected = width as usize * height as usize;
    if out.len() != expected {
        return Err(PanoramaError::Length { expected, actual: out.len() });
    }
    if height == source.height() {
        out.copy_from_slice(source.texels());
        return Ok(());
    }
    let (sw, sh) = (source.width(), source.height());
    let sine = |sy: u32| float::sin(core::f32::consts::PI * (sy as f32 + 0.5) / sh as f32);
    for (y, row_out) in (0..height).zip(out.chunks_exact_mut(width as usize)) {
        let rows = first_centre_in(y, height, sh)..first_centre_in(y + 1, height, sh);
        // Each source row's weighted sums into the row of `out`, row by row in order (each row's weight worked out
        // once), then the means.
        row_out.fill(Vec3::ZERO);
        let mut weight = 0.0;
        for sy in rows {
            let w = sine(sy);
            weight += w;
            for (x, sum) in (0..width).zip(row_out.iter_mut()) {
                let mut row = Vec3::ZERO;
                for sx in first_centre_in(x, width, sw)..first_centre_in(x + 1, width, sw) {
                    row += source.texel(sx, sy);
                }
                *sum += row * w;
            }
        }
        for (x, texel) in (0..width).zip(row_out.iter_mut()) {
            let total = weight * (first_centre_in(x + 1, width, sw) - first_centre_in(x, width, sw)) as f32;
            *texel = if total > 0.0 { *texel * (1.0 / total) } else { Vec3::ZERO };
        }
    }
    Ok(())
}

/// The first of `from` texels in a line whose centre falls in or after texel `i` of `to` texels over the same
/// span: the least `s` with `(2 s + 1) to >= 2 i from`.
fn first_centre_in(i: u32, to: u32, from: u32) -> u32 {
    let (i, to, from) = (u64::from(i), u64::from(to), u64::from(from));
    (2 * i * from).saturating_sub(to).div_ceil(2 * to) as u32
}
