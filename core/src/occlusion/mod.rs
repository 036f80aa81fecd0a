//! Screen-space ambient occlusion: darkens creases and contact areas from the finished depth buffer.
//!
//! A horizon-based estimate (Bavoil, Sainz and Dimitrov, "Image-Space Horizon-Based Ambient Occlusion",
//! SIGGRAPH 2008), cosine-weighted. A point's view-space position comes back from its depth through the inverse
//! projection, and its surface normal from the depths of its neighbours. Along a few screen directions, a few
//! samples out to the projected `radius` find the point that rises highest above the tangent plane; the mean over
//! the directions of the squared sine of that elevation (the share of the direction's slice of the hemisphere it
//! hides from cosine-weighted light, less a small bias, faded with distance) is the occlusion.
//!
//! The search runs once per 2x2 block of pixels, at its top-left pixel (a cell, `grid.rs`), with the directions of
//! the four cells of each 2x2 block of cells turned a quarter of their spacing apart. A 1-2-1 filter across and
//! down the cells averages the four turns (only cells on the same surface count), and every pixel takes the mean
//! of the filtered cells at and next to it on its own surface. The search itself is linear algebra on
//! homogeneous coordinates in units of the radius (`around.rs`), four directions at a time (`lanes.rs`), with one
//! division per sample and no square root.
//!
//! Everything a pixel computes depends on frame coordinates and depths only, so a band given enough rows of depth
//! around it ([`AmbientOcclusion::margin_rows`]) gets exactly the pixels of the whole frame. No memory is
//! allocated: the cells of a strip of columns live in a few kilobytes of stack.

mod around;
mod cell;
mod error;
mod frame;
mod grid;
mod horizon;
mod normal;

use core::ops::Range;

pub use error::OcclusionError;
use frame::DepthFrame;
use grid::Grid;
use horizon::Kernel;

use crate::color::{SRGB_DECODE, ShadingSpace, linear_to_srgb8};
use crate::math::{Lanes, Mat4, float};
use crate::target::MAX_DIMENSION;

/// Directions the horizon search follows at once: four `f32`s, the width of an SSE or NEON register.
const LANES: usize = 4;

/// One `f32` per direction of a group.
type F4 = Lanes<f32, LANES>;

/// Screen-space ambient occlusion settings: how far to look, how dark to make it, and how many samples to take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmbientOcclusion {
    /// How far around a point other surfaces occlude it, in view-space units (`>= 0`; 0 turns the effect off).
    pub radius: f32,
    /// How much of the estimated occlusion darkens the colour: 0 leaves it unchanged, 1 applies it fully
    /// (`>= 0`; above 1 exaggerates).
    pub strength: f32,
    /// Screen directions searched per pixel (0 turns the effect off).
    pub directions: u32,
    /// Samples along each direction (0 turns the effect off).
    pub steps: u32,
    /// Where the darkening applies: to the light the pixel shows ([`ShadingSpace::Linear`], the sRGB code decoded,
    /// scaled and encoded again) or to its stored code.
    pub space: ShadingSpace,
}

impl AmbientOcclusion {
    /// The defaults: a radius of half a unit (a quarter of a model scaled to fit `[-1, 1]`, so the corners and
    /// contacts of its parts darken but not the whole model), full strength, and 4 directions of 3 steps,
    /// darkening the light a pixel shows.
    ///
    /// That is 12 samples per 2x2 block of pixels (3 a pixel), the directions turned through 4 angles over each
    /// 2x2 block of cells and averaged by the filter, so 16 directions and 16 distances shape every pixel. Creases
    /// and contacts come out soft and smooth, with no dither pattern; open surfaces stay untouched.
    ///
    /// Measured with `cargo bench -p rastty-bench --bench occlusion` on one core of a 2-core x86-64 virtual
    /// machine (AMD EPYC, SSE2) shared with other work, so noisy: an 800x800 frame took a median of 14.8 ms
    /// (fastest 13.0 ms) for a model filling most of it and 19.7 ms (fastest 16.9 ms) with a floor and boxes
    /// around it, where the previous search, 8 directions of 4 steps at every pixel (32 samples a pixel), took
    /// 290 ms and 370 ms (fastest 222 ms and 266 ms) on the same machine.
    pub const DEFAULT: Self = Self { radius: 0.5, strength: 1.0, directions: 4, steps: 3, space: ShadingSpace::Linear };

    /// Rows of depth needed above and below a band, for a `width x height` frame seen through `projection`.
    ///
    /// Give [`AmbientOcclusion::apply`] the depth of the band's rows plus this many on each side (clamped to the
    /// frame) and it changes the band's pixels exactly as it would the whole frame's. The bound is the vertical
    /// reach of the samples, `radius` projected at the nearest depth the projection can show and at most an eighth
    /// of the frame's larger side, rounded up (at least the two rows the normals look at), plus the three rows
    /// around a pixel whose cells it takes its occlusion from. A projection without an inverse gets the eighth
    /// (`apply` refuses it anyway).
    pub fn margin_rows(&self, projection: &Mat4, width: u32, height: u32) -> u32 {
        let limit = max_reach(width, height);
        let reach = match projection.inverse() {
            Some(inverse) => float::min(self.reach_per_w(projection, width, height).1 * max_inv_w(&inverse), limit),
            None => limit,
        };
        // Negative or NaN radius (refused by `apply`) counts as no reach.
        let reach = float::clamp(reach, 0.0, limit);
        let ceil = (-float::floor_to_i32(-reach)) as u32;
        // At least the two rows the normals look at, around the cell rows a pixel depends on.
        (ceil.max(2) + grid::ROWS_AROUND).min(height)
    }

    /// Darkens `color`, rows `rows` of a `width x height` frame (`rows.len() * width` values, `0x00RRGGBB`, row
    /// `rows.start` first), by the occlusion the depth buffer shows.
    ///
    /// `depth` holds the NDC depth of rows `depth_rows`, which must contain `rows` (for a whole frame both are
    /// `0..height`); `projection` is the camera's projection matrix (view space to clip space), perspective or
    /// orthographic, whose inverse brings depths back to view space. Samples beyond the frame's edges are taken at
    /// the nearest edge pixel; samples outside `depth_rows` are skipped: see [`AmbientOcclusion::margin_rows`] for
    /// how many rows make a band exact.
    ///
    /// Background pixels (depth `>= 1.0`, or NaN) keep their colour and occlude nothing. Surfaces that nothing
    /// rises above, such as a lone plane at any angle or the outside of a box, keep theirs too. A point is searched
    /// only where its surface goes on for two pixels to one side across and to one side up or down; a tip or a
    /// line one or two pixels thin (orientation unknown) takes the occlusion found around it on its surface, or
    /// keeps its colour. A pixel's occlusion comes from searches at most three pixels away across and down, so it
    /// reaches that far beyond `radius`. Each channel of a darkened pixel is multiplied by
    /// `1 - strength * occlusion` (clamped to `[0, 1]`) in `space`, and rounded to the nearest code.
    ///
    /// # Errors
    /// [`OcclusionError::Settings`] for a negative or non-finite `radius` or `strength`; [`OcclusionError::Frame`]
    /// for a frame of zero or more than [`MAX_DIMENSION`] pixels a side; [`OcclusionError::Rows`] for empty
    /// `rows` or rows outside the frame; [`OcclusionError::DepthRows`] when `depth_rows` does not contain `rows` or
    /// leaves the frame; [`OcclusionError::ColorLength`] / [`OcclusionError::DepthLength`] when a slice has the
    /// wrong length; [`OcclusionError::Projection`] when `projection` has no inverse. Nothing is changed then.
    #[allow(clippy::too_many_arguments)] // A band of colour and a band of depth, each with its rows, and the frame.
    pub fn apply(
        &self,
        projection: &Mat4,
        depth: &[f32],
        depth_rows: Range<u32>,
        color: &mut [u32],
        rows: Range<u32>,
        width: u32,
        height: u32,
    ) -> Result<(), OcclusionError> {
        self.check_settings()?;
        check_layout(depth.len(), &depth_rows, color.len(), &rows, width, height)?;
        let inverse = projection.inverse().ok_or(OcclusionError::Projection)?;
        if self.strength == 0.0 || self.radius == 0.0 || self.directions == 0 || self.steps == 0 {
            return Ok(());
        }
        let frame = DepthFrame::new(depth, depth_rows, width, height, &inverse);
        let kernel = Kernel::new(self, projection, &inverse, width, height);
        let mut grid = Grid::new(&kernel, &frame, self);
        for first in Grid::strips(width) {
            grid.strip(first);
            for (y, line) in rows.clone().zip(color.chunks_exact_mut(width as usize)) {
                grid.darken_row(line, y as i32);
            }
        }
        Ok(())
    }

    /// Refuses settings that have no meaning.
    fn check_settings(&self) -> Result<(), OcclusionError> {
        let ok = |v: f32| v.is_finite() && v >= 0.0;
        if ok(self.radius) && ok(self.strength) { Ok(()) } else { Err(OcclusionError::Settings) }
    }

    /// Pixels that `radius` spans across and down at clip `w = 1`: divide by a point's clip `w` (multiply by the
    /// inverse projection's `w`) for its reach. Exact for a step of `radius` along view x or y under the
    /// perspective and orthographic projections of [`crate::camera`], off-centre ones included.
    fn reach_per_w(&self, projection: &Mat4, width: u32, height: u32) -> (f32, f32) {
        let across = float::abs(projection.cols[0].x) * width as f32 * 0.5;
        let down = float::abs(projection.cols[1].y) * height as f32 * 0.5;
        (self.radius * across, self.radius * down)
    }
}

impl Default for AmbientOcclusion {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Checks that the frame, the two bands and the two slices fit together.
fn check_layout(
    depth_len: usize,
    depth_rows: &Range<u32>,
    color_len: usize,
    rows: &Range<u32>,
    width: u32,
    height: u32,
) -> Result<(), OcclusionError> {
    if width == 0 || height == 0 || width > MAX_DIMENSION || height > MAX_DIMENSION {
        return Err(OcclusionError::Frame { width, height });
    }
    if rows.start >= rows.end || rows.end > height {
        return Err(OcclusionError::Rows { rows: rows.clone(), height });
    }
    if depth_rows.start > rows.start || depth_rows.end < rows.end || depth_rows.end > height {
        return Err(OcclusionError::DepthRows { depth_rows: depth_rows.clone(), rows: rows.clone(), height });
    }
    let expected = (rows.end - rows.start) as usize * width as usize;
    if color_len != expected {
        return Err(OcclusionError::ColorLength { expected, actual: color_len });
    }
    let expected = (depth_rows.end - depth_rows.start) as usize * width as usize;
    if depth_len != expected {
        return Err(OcclusionError::DepthLength { expected, actual: depth_len });
    }
    Ok(())
}

/// Longest reach of a pixel's samples, in pixels: an eighth of the frame's larger side. It bounds the work per
/// pixel and the rows a band needs when a surface comes close to the camera.
fn max_reach(width: u32, height: u32) -> f32 {
    width.max(height) as f32 * 0.125
}

/// Largest `w` of the inverse projection (`1 / clip w`) over the visible NDC box `[-1, 1]^2 x [0, 1]`: it is
/// linear in NDC, so the largest value is at a corner, and this sums the corner's terms. At most 0 when nothing
/// visible is in front of the camera.
fn max_inv_w(inverse: &Mat4) -> f32 {
    let w = inverse.row(3);
    float::abs(w.x) + float::abs(w.y) + float::max(w.z, 0.0) + w.w
}

/// `color` (`0x00RRGGBB`) with each channel multiplied by `factor` in `[0, 1]` in `space`, rounded to the nearest
/// code.
#[inline(always)]
fn darken(color: u32, factor: f32, space: ShadingSpace) -> u32 {
    let code = |shift: u32| (color >> shift) & 0xFF;
    let channel = |shift: u32| match space {
        ShadingSpace::Linear => linear_to_srgb8(SRGB_DECODE[code(shift) as usize] * factor) << shift,
        ShadingSpace::Encoded => float::round_small_to_u32(code(shift) as f32 * factor) << shift,
    };
    channel(16) | channel(8) | channel(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Half the light of white is code 188; half of code 255 is 127.5, rounded to even: 128. Black stays black
    /// and a factor of 1 changes nothing either way.
    #[test]
    fn darkening_applies_to_light_or_to_codes() {
        assert_eq!(darken(0xFF_FF_FF, 0.5, ShadingSpace::Linear), 0xBC_BC_BC);
        assert_eq!(darken(0xFF_FF_FF, 0.5, ShadingSpace::Encoded), 0x80_80_80);
        for space in [ShadingSpace::Linear, ShadingSpace::Encoded] {
            assert_eq!(darken(0x00_00_00, 0.3, space), 0);
            assert_eq!(darken(0x12_80_FE, 1.0, space), 0x12_80_FE);
        }
        // Code 188 at half strength: 0.5 light halved is 0.25, code 137.
        assert_eq!(darken(0xBC_00_00, 0.5, ShadingSpace::Linear), 0x89_00_00);
    }
}
