//! Screen-space ambient occlusion: darkens creases and contact areas from the finished depth buffer.
//!
//! A horizon-based estimate (Bavoil, Sainz and Dimitrov, "Image-Space Horizon-Based Ambient Occlusion",
//! SIGGRAPH 2008). Each pixel's view-space position comes back from its depth through the inverse projection,
//! and its surface normal from the positions of its neighbours. Along a few screen directions, a few samples out
//! to the projected `radius` find the highest point that rises above the pixel's tangent plane; the mean over the
//! directions of that elevation (its sine, less a small bias, faded with distance) is the occlusion.
//!
//! The directions are turned per pixel by a 4x4 ordered pattern, so neighbouring pixels look along different
//! angles and few directions still cover the circle. Everything a pixel computes depends on frame coordinates and
//! depths only, so a band given enough rows of depth around it ([`AmbientOcclusion::margin_rows`]) gets exactly
//! the pixels of the whole frame.

mod error;

use core::ops::Range;

pub use error::OcclusionError;

use crate::math::{Mat4, Vec3, Vec4, float};
use crate::target::MAX_DIMENSION;

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
}

impl AmbientOcclusion {
    /// The defaults: a radius of half a unit (a quarter of a model scaled to fit `[-1, 1]`, so the corners and
    /// contacts of its parts darken but not the whole model), full strength, and 8 directions of 4 steps: 32 samples
    /// a pixel, the 8 directions turned per pixel through 16 angles so 128 directions are covered per 4x4 block.
    pub const DEFAULT: Self = Self { radius: 0.5, strength: 1.0, directions: 8, steps: 4 };

    /// Rows of depth needed above and below a band, for a `width x height` frame seen through `projection`.
    ///
    /// Give [`AmbientOcclusion::apply`] the depth of the band's rows plus this many on each side (clamped to the
    /// frame) and it changes the band's pixels exactly as it would the whole frame's. The bound is the vertical
    /// reach of the samples, `radius` projected at the nearest depth the projection can show and at most an eighth
    /// of the frame's larger side, rounded up, plus one row; at least the two rows the normals look at. A
    /// projection without an inverse gets the eighth (`apply` refuses it anyway).
    pub fn margin_rows(&self, projection: &Mat4, width: u32, height: u32) -> u32 {
        let limit = max_reach(width, height);
        let reach = match projection.inverse() {
            Some(inverse) => float::min(self.reach_per_w(projection, width, height).1 * max_inv_w(&inverse), limit),
            None => limit,
        };
        // Negative or NaN radius (refused by `apply`) counts as no reach.
        let reach = float::clamp(reach, 0.0, limit);
        let ceil = (-float::floor_to_i32(-reach)) as u32;
        // One more row for rounding; at least two for the normals.
        (ceil + 1).max(2).min(height)
    }

    /// Darkens `color`, rows `rows` of a `width x height` frame (`rows.len() * width` values, `0x00RRGGBB`, row
    /// `rows.start` first), by the occlusion the depth buffer shows.
    ///
    /// `depth` holds the NDC depth of rows `depth_rows`, which must contain `rows` (for a whole frame both are
    /// `0..height`); `projection` is the camera's projection matrix (view space to clip space), perspective or
    /// orthographic, whose inverse brings depths back to view space. Samples outside the frame or outside
    /// `depth_rows` are skipped: see [`AmbientOcclusion::margin_rows`] for how many rows make a band exact.
    ///
    /// Background pixels (depth `>= 1.0`, or NaN) keep their colour and occlude nothing. Surfaces that nothing
    /// rises above, such as a lone plane at any angle or the outside of a box, keep theirs too, and so do pixels
    /// whose surface does not go on for two pixels to one side across and to one side up or down (tips and lines
    /// one or two pixels thin: their orientation is unknown). Each channel of a darkened pixel is multiplied by
    /// `1 - strength * occlusion` (clamped to `[0, 1]`) and rounded to nearest.
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
        for (y, line) in rows.zip(color.chunks_exact_mut(width as usize)) {
            for (x, pixel) in (0..width).zip(line.iter_mut()) {
                let occlusion = kernel.occlusion(&frame, x as i32, y as i32);
                let factor = float::clamp(1.0 - self.strength * occlusion, 0.0, 1.0);
                if factor < 1.0 {
                    *pixel = darken(*pixel, factor);
                }
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

/// Sine of the elevation above its tangent plane a sample must exceed to occlude a point: keeps surfaces from
/// occluding themselves through depth rounding and flat facets (the angle bias of Bavoil et al. 2008).
const ANGLE_BIAS: f32 = 0.1;

/// The 4x4 ordered-dither matrix (Bayer, "An optimum method for two-level rendition of continuous-tone pictures",
/// 1973), row by row: each 2x2 block holds values a quarter of the range apart, so neighbours differ most.
const BAYER: [u8; 16] = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];

/// The depth of some rows of a frame, and how to bring a pixel back to view space.
struct DepthFrame<'a> {
    depth: &'a [f32],
    first_row: i32,
    end_row: i32,
    width: i32,
    /// The inverse projection composed with the map from pixel `(x, y)` and depth `d` to NDC, by columns: the
    /// homogeneous view position of `(x, y, d)` is `x * per_x + y * per_y + d * per_depth + at_origin`.
    per_x: Vec4,
    per_y: Vec4,
    per_depth: Vec4,
    at_origin: Vec4,
}

impl<'a> DepthFrame<'a> {
    fn new(depth: &'a [f32], rows: Range<u32>, width: u32, height: u32, inverse: &Mat4) -> Self {
        // NDC x = (x + 0.5) * 2 / width - 1 and y = 1 - (y + 0.5) * 2 / height, folded into the matrix once.
        let [a, b, c, t] = inverse.cols;
        let (sx, sy) = (2.0 / width as f32, 2.0 / height as f32);
        Self {
            depth,
            first_row: rows.start as i32,
            end_row: rows.end as i32,
            width: width as i32,
            per_x: a * sx,
            per_y: b * -sy,
            per_depth: c,
            at_origin: t + a * (0.5 * sx - 1.0) + b * (1.0 - 0.5 * sy),
        }
    }

    /// The depth at pixel `(x, y)`, or `None` outside the stored rows or where nothing was drawn.
    #[inline(always)]
    fn depth_at(&self, x: i32, y: i32) -> Option<f32> {
        if x < 0 || x >= self.width || y < self.first_row || y >= self.end_row {
            return None;
        }
        let d = self.depth[(y - self.first_row) as usize * self.width as usize + x as usize];
        (d < 1.0).then_some(d)
    }

    /// The view-space position of the surface at pixel `(x, y)`, if there is one.
    #[inline(always)]
    fn position(&self, x: i32, y: i32) -> Option<Vec3> {
        self.depth_at(x, y).and_then(|d| self.unproject(x, y, d)).map(|(p, _)| p)
    }

    /// The view-space position of depth `d` at the centre of pixel `(x, y)`, and the inverse projection's `w`
    /// there (`1 / clip w`); `None` behind the camera.
    #[inline(always)]
    fn unproject(&self, x: i32, y: i32, d: f32) -> Option<(Vec3, f32)> {
        let h = self.per_x * x as f32 + self.per_y * y as f32 + self.per_depth * d + self.at_origin;
        (h.w > 0.0).then(|| {
            let r = 1.0 / h.w;
            (Vec3::new(h.x * r, h.y * r, h.z * r), h.w)
        })
    }

    /// The unit normal of the surface at pixel `(x, y)`, position `p`, depth `d`, facing the camera: the cross
    /// product of a horizontal and a vertical difference to a neighbour. Each is taken on a side whose next two
    /// pixels continue in a straight line through the pixel (NDC depth is affine across a plane), the straighter
    /// if both do, so a crease or a silhouette does not bend it (Wu, "Accurate normal reconstruction from depth
    /// buffer", 2021). `None` when no side across, or none up and down, continues the surface: the pixel is a tip
    /// or a line one or two pixels thin, and its orientation is unknown.
    fn normal(&self, x: i32, y: i32, p: Vec3, d: f32) -> Option<Vec3> {
        let across = self.tangent(x, y, p, d, (1, 0))?;
        let up = self.tangent(x, y, p, d, (0, -1))?;
        across.cross(up).try_normalize()
    }

    /// The view-space difference from pixel `(x, y)` (position `p`, depth `d`) one pixel along `step` (ahead) or
    /// against it (behind), from whichever side continues the surface better.
    fn tangent(&self, x: i32, y: i32, p: Vec3, d: f32, (sx, sy): (i32, i32)) -> Option<Vec3> {
        let ahead = self.side(x, y, d, sx, sy);
        let behind = self.side(x, y, d, -sx, -sy);
        let backward = match (ahead, behind) {
            (Some(a), Some(b)) => b.1 < a.1,
            (a, _) => a.is_none(),
        };
        let (near, sx, sy) = if backward { (behind?.0, -sx, -sy) } else { (ahead?.0, sx, sy) };
        let q = self.unproject(x + sx, y + sy, near)?.0;
        Some(if backward { p - q } else { q - p })
    }

    /// The depth of the neighbour one pixel along `(sx, sy)` from `(x, y)`, and how far extrapolating it and the
    /// next one misses depth `d`; `None` unless both are drawn and the miss is within half their own difference
    /// (and a rounding slack): otherwise they lie on another surface.
    fn side(&self, x: i32, y: i32, d: f32, sx: i32, sy: i32) -> Option<(f32, f32)> {
        let d1 = self.depth_at(x + sx, y + sy)?;
        let d2 = self.depth_at(x + 2 * sx, y + 2 * sy)?;
        let miss = float::abs(2.0 * d1 - d2 - d);
        (miss <= 0.5 * float::abs(d1 - d2) + DEPTH_SLACK).then_some((d1, miss))
    }
}

/// Depth rounding that a surface's depths may show and still count as one plane: a few units in the last place
/// of depths near 1, where they are coarsest.
const DEPTH_SLACK: f32 = 8.0 * f32::EPSILON;

/// What every pixel's search shares, computed once per call.
struct Kernel {
    /// Pixels the radius spans across and down at clip `w = 1`.
    reach_per_w: (f32, f32),
    /// Largest inverse-projection `w` that the reach uses: bounds it as [`AmbientOcclusion::margin_rows`] says.
    max_inv_w: f32,
    /// Longest reach in pixels.
    max_reach: f32,
    inv_radius_squared: f32,
    /// Cosine and sine of the first direction, per entry of [`BAYER`].
    first_direction: [(f32, f32); 16],
    /// Cosine and sine of the turn between directions, a full turn divided by their number.
    turn: (f32, f32),
    /// Where along each step the samples sit (`[0, 1)`), per entry of [`BAYER`].
    jitter: [f32; 16],
    directions: u32,
    steps: u32,
}

impl Kernel {
    fn new(settings: &AmbientOcclusion, projection: &Mat4, inverse: &Mat4, width: u32, height: u32) -> Self {
        let turn = core::f32::consts::TAU / settings.directions as f32;
        let first_direction = core::array::from_fn(|k| {
            let angle = (f32::from(BAYER[k]) + 0.5) * (1.0 / 16.0) * turn;
            (float::cos(angle), float::sin(angle))
        });
        // The transposed pattern, so a pixel's step offset does not follow its angle.
        let jitter = core::array::from_fn(|k| f32::from(BAYER[(k % 4) * 4 + k / 4]) * (1.0 / 16.0));
        Self {
            reach_per_w: settings.reach_per_w(projection, width, height),
            max_inv_w: max_inv_w(inverse),
            max_reach: max_reach(width, height),
            inv_radius_squared: 1.0 / (settings.radius * settings.radius),
            first_direction,
            turn: (float::cos(turn), float::sin(turn)),
            jitter,
            directions: settings.directions,
            steps: settings.steps,
        }
    }

    /// The occlusion of pixel `(x, y)`, in `[0, 1]`: 0 for background and for nothing above the tangent plane.
    fn occlusion(&self, frame: &DepthFrame<'_>, x: i32, y: i32) -> f32 {
        let Some(d) = frame.depth_at(x, y) else {
            return 0.0;
        };
        let Some((p, inv_w)) = frame.unproject(x, y, d) else {
            return 0.0;
        };
        let inv_w = float::min(inv_w, self.max_inv_w);
        let (rx, ry) = (self.reach_per_w.0 * inv_w, self.reach_per_w.1 * inv_w);
        let full = float::max(rx, ry);
        if full.is_nan() || full <= 1.0 {
            // The radius spans less than a pixel: no other pixel is near enough to occlude.
            return 0.0;
        }
        // The direction's unit step in pixels (a circle in view space is an ellipse on screen), and how many
        // pixels the samples go out to along the longer axis.
        let (ex, ey) = (rx / full, ry / full);
        let reach = float::min(full, self.max_reach);
        let step = (reach - 1.0) / self.steps as f32;
        let Some(n) = frame.normal(x, y, p, d) else {
            // A tip or a thin line: its tangent plane is unknown, and guessing one would darken the corners of
            // planes.
            return 0.0;
        };
        let k = ((y & 3) * 4 + (x & 3)) as usize;
        let (mut c, mut s) = self.first_direction[k];
        let jitter = self.jitter[k];
        let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
        let mut sum = 0.0;
        for _ in 0..self.directions {
            let (dx, dy) = (c * ex, s * ey);
            let mut horizon = 0.0;
            for i in 0..self.steps {
                // From one pixel out, so the first sample is not the pixel itself.
                let t = 1.0 + (i as f32 + jitter) * step;
                let sample = frame.position(float::floor_to_i32(cx + dx * t), float::floor_to_i32(cy + dy * t));
                if let Some(q) = sample {
                    // NaN elevations (the pixel itself, non-finite depths) lose to the horizon so far.
                    horizon = float::max(self.elevation(p, n, q), horizon);
                }
            }
            sum += horizon;
            (c, s) = (c * self.turn.0 - s * self.turn.1, s * self.turn.0 + c * self.turn.1);
        }
        sum / self.directions as f32
    }

    /// How much `q` occludes `p` (normal `n`): the sine of its elevation above the tangent plane less the bias,
    /// rescaled to reach 1 straight above, and faded by `1 - d^2 / radius^2` (Bavoil et al. 2008's attenuation);
    /// at most 0 beyond the radius or below the bias, NaN for `q == p`.
    #[inline(always)]
    fn elevation(&self, p: Vec3, n: Vec3, q: Vec3) -> f32 {
        let v = q - p;
        let d2 = v.dot(v);
        let fade = float::max(1.0 - d2 * self.inv_radius_squared, 0.0);
        let sin = v.dot(n) / float::sqrt(d2);
        (sin - ANGLE_BIAS) * (1.0 / (1.0 - ANGLE_BIAS)) * fade
    }
}

/// `color` (`0x00RRGGBB`) with each channel multiplied by `factor` in `[0, 1]`, rounded to nearest.
#[inline(always)]
fn darken(color: u32, factor: f32) -> u32 {
    let channel = |shift: u32| float::round_small_to_u32(((color >> shift) & 0xFF) as f32 * factor) << shift;
    channel(16) | channel(8) | channel(0)
}
