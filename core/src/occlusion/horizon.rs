//! The horizon search at one pixel: how far the surfaces around it rise above its tangent plane.

use super::around::Around;
use super::cell::Cell;
use super::frame::{DepthFrame, Window};
use super::{AmbientOcclusion, max_inv_w, max_reach};
use super::{F4, LANES};
use crate::math::{Mat4, Vec3, float};

/// Sine of the elevation above its tangent plane a sample must exceed to occlude a point: keeps surfaces from
/// occluding themselves through depth rounding and flat facets (the angle bias of Bavoil et al. 2008).
const ANGLE_BIAS: f32 = 0.1;

/// The 2x2 ordered-dither matrix (Bayer, "An optimum method for two-level rendition of continuous-tone pictures",
/// 1973), row by row: the four turns of the directions, a quarter of their spacing apart, over each 2x2 block of
/// cells.
const BAYER: [u8; 4] = [0, 2, 3, 1];

/// What every pixel's search shares, computed once per call.
pub(super) struct Kernel {
    /// Pixels the radius spans at clip `w = 1`, along the longer of the screen axes.
    reach_per_w: f32,
    /// The ellipse a circle in view space makes on screen, per pixel along the longer axis: across and down.
    ellipse: (f32, f32),
    /// Largest inverse-projection `w` that the reach uses: bounds it as [`AmbientOcclusion::margin_rows`] says.
    max_inv_w: f32,
    /// Longest reach in pixels.
    max_reach: f32,
    /// `1 / radius`: the search measures view space in units of the radius ([`Around`]).
    inv_radius: f32,
    /// Cosines and sines of the first [`LANES`] directions (0 in lanes beyond `directions`), per position of a
    /// cell in its 2x2 block (row by row), turned by that position's entry of [`BAYER`].
    first_directions: [(F4, F4); 4],
    /// Cosine and sine of the turn from one group of [`LANES`] directions to the next.
    group_turn: (f32, f32),
    /// Where along each step the samples of each lane sit (`[0, 1)`), per position of a cell in its 2x2 block.
    jitter: [F4; 4],
    /// Directions searched per cell ([`AmbientOcclusion::directions`]).
    directions: u32,
    /// Samples along each direction ([`AmbientOcclusion::steps`]).
    steps: u32,
    /// `1 / directions`.
    inv_directions: f32,
    /// `1 / steps`.
    inv_steps: f32,
}

impl Kernel {
    /// The search of `settings` (radius, directions and steps all above 0) in a `width x height` frame seen
    /// through `projection`, whose inverse is `inverse`.
    pub(super) fn new(settings: &AmbientOcclusion, projection: &Mat4, inverse: &Mat4, width: u32, height: u32) -> Self {
        let turn = core::f32::consts::TAU / settings.directions as f32;
        let (across, down) = settings.reach_per_w(projection, width, height);
        // The same ellipse at every depth: only its size changes.
        let longer = float::max(across, down);
        let live = settings.directions.min(LANES as u32) as usize;
        let first_directions = core::array::from_fn(|k| {
            let (mut dx, mut dy) = (F4::ZERO, F4::ZERO);
            for lane in 0..live {
                let angle = ((f32::from(BAYER[k]) + 0.5) * 0.25 + lane as f32) * turn;
                (dx[lane], dy[lane]) = (float::cos(angle), float::sin(angle));
            }
            (dx, dy)
        });
        // The transposed pattern, so a cell's step offset does not follow its angle, in sixteenths: each lane a
        // quarter further on, so the four cells of a block and the four directions of a cell sample sixteen
        // distances between them.
        let jitter = core::array::from_fn(|k| {
            let first = usize::from(BAYER[(k % 2) * 2 + k / 2]);
            F4::from_fn(|lane| ((first + 4 * lane) % 16) as f32 * (1.0 / 16.0) + 1.0 / 32.0)
        });
        let group = LANES as f32 * turn;
        Self {
            reach_per_w: longer,
            ellipse: (across / longer, down / longer),
            max_inv_w: max_inv_w(inverse),
            max_reach: max_reach(width, height),
            inv_radius: 1.0 / settings.radius,
            first_directions,
            group_turn: (float::cos(group), float::sin(group)),
            jitter,
            directions: settings.directions,
            steps: settings.steps,
            inv_directions: 1.0 / settings.directions as f32,
            inv_steps: 1.0 / settings.steps as f32,
        }
    }

    /// The occlusion at pixel `(x, y)` and its view-space depth coordinate, its directions turned by the pattern
    /// entry of the 2x2 cell it lies in.
    pub(super) fn cell(&self, frame: &DepthFrame<'_>, x: i32, y: i32) -> Cell {
        let Some(d) = frame.depth_at(x, y) else {
            return Cell::NONE;
        };
        let Some(around) = frame.around(x, y, d, self.inv_radius) else {
            return Cell::NONE;
        };
        let z = around.z;
        let full = self.reach_per_w * float::min(around.w, self.max_inv_w);
        if full.is_nan() || full <= 1.0 {
            // The radius spans less than a pixel: no other pixel is near enough to occlude.
            return Cell { occlusion: 0.0, z };
        }
        // A tip or a thin line has no known tangent plane, and guessing one would darken the corners of planes.
        let Some(n) = frame.normal(x, y, &around) else {
            return Cell { occlusion: Cell::UNKNOWN, z };
        };
        // How many pixels the samples go out to along the longer axis.
        let reach = float::min(full, self.max_reach);
        let pattern = (((y >> 1) & 1) * 2 + ((x >> 1) & 1)) as usize;
        let (mut c, mut s) = self.first_directions[pattern];
        let (ex, ey) = (F4::splat(self.ellipse.0), F4::splat(self.ellipse.1));
        let mut search = Search {
            around,
            n,
            normal_squared: n.dot(n),
            window: frame.window(x, y),
            d: F4::splat(d),
            directions: (F4::ZERO, F4::ZERO),
            jitter: self.jitter[pattern],
            step: F4::splat((reach - 1.0) * self.inv_steps),
        };
        let mut sum = 0.0;
        // Directions go LANES at a time, one per lane, so each step's arithmetic runs on all of them at once.
        for first in (0..self.directions).step_by(LANES) {
            let live = (self.directions - first).min(LANES as u32) as usize;
            // The directions' steps in pixels per pixel of reach along the longer axis.
            search.directions = (c * ex, s * ey);
            let mut horizon = F4::ZERO;
            for i in 0..self.steps {
                self.step(frame, &search, i as f32, &mut horizon);
            }
            for h in &horizon[..live] {
                sum += h;
            }
            // The next group: these directions turned by LANES directions' spacing.
            let (tc, ts) = (F4::splat(self.group_turn.0), F4::splat(self.group_turn.1));
            (c, s) = (c * tc - s * ts, s * tc + c * ts);
        }
        Cell { occlusion: sum * self.inv_directions, z }
    }

    /// Raises `horizon` to the occlusion by the samples of step `i` of `search`.
    ///
    /// Not inlined, and given its lanes by reference: on its own the compiler keeps each [`F4`] in one register,
    /// where inlined into the search it splits them into pairs.
    #[inline(never)]
    fn step(&self, frame: &DepthFrame<'_>, search: &Search, i: f32, horizon: &mut F4) {
        // From one pixel out, so the first sample is not the pixel itself.
        let t = F4::splat(1.0) + (F4::splat(i) + search.jitter) * search.step;
        // The pixel whose centre is nearest each sample point: the offset rounded. A lane without a direction
        // stays on the pixel itself, which never occludes.
        let (dx, dy) = search.directions;
        let (ox, oy) = ((dx * t).round_small(), (dy * t).round_small());
        let (ox, oy, depth, drawn) = frame.gather(&search.window, ox, oy);
        *horizon = horizon.max(self.elevation(search, ox, oy, depth - search.d, drawn));
    }

    /// How much the samples `(dx, dy)` pixels away, `dd` deeper, occlude the pixel of `search`: the squared sine
    /// of their elevation above its tangent plane, the share of a slice of the hemisphere below that horizon when
    /// light is cosine-weighted (Jimenez et al., "Practical Real-Time Strategies for Accurate Indirect Occlusion",
    /// 2016), less the squared bias and rescaled to reach 1 straight above, faded by `1 - |q - p|^2 / radius^2`
    /// (Bavoil et al. 2008's attenuation). 0 unless the sample is `drawn` (1), above the bias (so above the tangent
    /// plane), within the radius and in front of the camera; NaN (non-finite depths) fails every test. Without
    /// branches (which samples occlude is unpredictable) and with one division.
    #[inline(always)]
    fn elevation(&self, search: &Search, dx: F4, dy: F4, dd: F4, drawn: F4) -> F4 {
        let (lift, d2) = search.lift_and_distance_squared(dx, dy, dd);
        let rho = search.rho(dx, dy, dd);
        let (lift2, rho2, n2) = (lift * lift, rho * rho, F4::splat(search.normal_squared));
        // v = (q - p) rho / radius, so with r = 1 / (d2 rho^2 |n|^2): sin^2 = lift^2 / (d2 |n|^2) = lift^2 rho^2 r,
        // and |q - p|^2 / radius^2 = d2 / rho^2 = d2^2 |n|^2 r.
        let r = F4::splat(1.0) / (d2 * rho2 * n2);
        let sin2 = lift2 * rho2 * r;
        let fade = F4::splat(1.0) - d2 * d2 * n2 * r;
        let bias2 = F4::splat(ANGLE_BIAS * ANGLE_BIAS);
        let elevation = (sin2 - bias2) * F4::splat(1.0 / (1.0 - ANGLE_BIAS * ANGLE_BIAS)) * fade;
        elevation
            .where_less(F4::ZERO, lift)
            .where_less(bias2 * n2 * d2, lift2)
            .where_less(d2, rho2)
            .where_less(F4::ZERO, rho)
            .where_less(F4::ZERO, drawn)
    }
}

/// One pixel's search: where it is, and the directions and steps it samples along.
struct Search {
    /// The view space around the pixel's surface point `p`, in units of the radius.
    around: Around,
    /// The surface's normal there, its largest component `±1`.
    n: Vec3,
    /// `|n|^2`.
    normal_squared: f32,
    /// The offsets from the pixel that stay within the frame and the stored rows.
    window: Window,
    /// The pixel's depth.
    d: F4,
    /// The current group of directions' steps in pixels per pixel of reach: across, then down.
    directions: (F4, F4),
    /// Where along each step the samples of each lane sit.
    jitter: F4,
    /// Pixels between samples.
    step: F4,
}

impl Search {
    /// `v . n` and `|v|^2` for the samples `(dx, dy)` pixels away, `dd` deeper (`v` as [`Around`] has it).
    #[inline(always)]
    fn lift_and_distance_squared(&self, dx: F4, dy: F4, dd: F4) -> (F4, F4) {
        let axis = |a: f32, b: f32, c: f32| dx * F4::splat(a) + dy * F4::splat(b) + dd * F4::splat(c);
        let (a, b, c) = (self.around.per_x, self.around.per_y, self.around.per_depth);
        let (vx, vy, vz) = (axis(a.x, b.x, c.x), axis(a.y, b.y, c.y), axis(a.z, b.z, c.z));
        let lift = vx * F4::splat(self.n.x) + vy * F4::splat(self.n.y) + vz * F4::splat(self.n.z);
        (lift, vx * vx + vy * vy + vz * vz)
    }

    /// `rho = w_q / w` ([`Around`]) for the samples `(dx, dy)` pixels away, `dd` deeper.
    #[inline(always)]
    fn rho(&self, dx: F4, dy: F4, dd: F4) -> F4 {
        let per = self.around.rho_per;
        F4::splat(1.0) + dx * F4::splat(per.x) + dy * F4::splat(per.y) + dd * F4::splat(per.z)
    }
}
