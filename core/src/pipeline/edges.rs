//! Edge functions over pixel centres: exact fixed-point integers (the default) or plain `f32`.
//!
//! A triangle covers a pixel centre when its three edge functions are all positive there, or zero on a top or left
//! edge (the fill rule). [`FixedEdges`] snaps vertices to the sub-pixel grid and evaluates the functions exactly in
//! `i64`, stepping by integer additions; [`FloatEdges`] evaluates them in `f32` from unsnapped positions, as
//! simple rasterizers do: no snapping, but no exactness either (shared edges may crack or overlap, slivers flicker),
//! which is what the accuracy report measures. Both evaluate each row from frame coordinates alone, so bands give
//! the frame's pixels.

use crate::math::float;
use crate::target::{SAMPLE_COUNT, SAMPLE_POSITIONS};

/// Edge functions of an oriented triangle (positive inside) at pixel centres, walked along rows: what the pixel
/// loops read.
pub(crate) trait CentreEdges: Copy {
    /// The three values at one pixel centre.
    type At: Copy;
    /// The values at the centre of pixel `(x, y)`.
    fn at(&self, x: i32, y: i32) -> Self::At;
    /// The values one pixel to the right.
    fn step(&self, at: Self::At) -> Self::At;
    /// The values at the centre of pixel `(x, y + 1)`, from `at`, those at `(x, y)`: what [`Self::at`] gives
    /// there. Exact edges add a step; the default works the row out from its coordinates, as `f32` edges must
    /// (so that a band's rows get the frame's values).
    #[inline(always)]
    fn down(&self, _at: Self::At, x: i32, y: i32) -> Self::At {
        self.at(x, y + 1)
    }
    /// Whether the centre is covered, fill rule included.
    fn covered(&self, at: &Self::At) -> bool;
    /// The three values as non-negative weights: barycentric coordinates times twice the area.
    fn weights(&self, at: &Self::At) -> [f32; 3];
}

/// Edge functions of an oriented triangle, with what set-up, multisampling and the depth-only loop also read.
pub(crate) trait Edges: CentreEdges {
    /// How [`CentreEdges::weights`] change one pixel to the right and one pixel down (inside the triangle, where no
    /// weight is clamped).
    fn steps(&self) -> [[f32; 3]; 2];
    /// What takes the values at a pixel centre to those at each of its [`SAMPLE_POSITIONS`], with
    /// [`Self::at_sample`].
    fn sample_offsets(&self) -> [Self::At; SAMPLE_COUNT];
    /// Each edge's largest offset over the samples: [`Self::at_sample`] with it gives, edge by edge, the largest
    /// value of any sample of the pixel (values grow with the offset, exactly or through monotonic rounding). When
    /// those are not [`CentreEdges::covered`], no sample is; when they are [`Self::closed`], no sample is there or further
    /// right in the row.
    fn sample_reach(&self) -> Self::At;
    /// The values at a sample, from those at its pixel's centre and its one of [`Self::sample_offsets`]: covered as
    /// [`CentreEdges::covered`] says, weighted as [`Self::sample_weights`] says.
    fn at_sample(&self, centre: &Self::At, offset: &Self::At) -> Self::At;
    /// [`CentreEdges::weights`] of values at a sample.
    fn sample_weights(&self, at: &Self::At) -> [f32; 3];
    /// Whether values `at` (at a centre or a sample) fail an edge whose value never rises to the right: then the
    /// same point of every pixel further right in the row is uncovered too, as [`CentreEdges::step`] computes it.
    fn closed(&self, at: &Self::At) -> bool;
    /// The functions as [`NarrowEdges`] over the pixel centres `x0..=x1` by `y0..=y1`, when that computes exactly
    /// what [`CentreEdges::at`], [`CentreEdges::step`], [`CentreEdges::covered`] and [`CentreEdges::weights`] do there; `None` otherwise.
    #[inline(always)]
    fn narrow(&self, _x0: i32, _x1: i32, _y0: i32, _y1: i32) -> Option<NarrowEdges> {
        None
    }
}

/// Edge functions as `i32`, for working out several pixels of a row at once (SIMD lanes): the values of
/// [`FixedEdges`] over a box where every one of them fits, with room to add back the bias.
///
/// The arithmetic wraps: a value is exact wherever the true one fits, whatever the intermediate terms (sums and
/// products modulo 2^32), so only the box's values are checked, and a lane past the box's edge, which may wrap,
/// must be masked off by the caller.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NarrowEdges {
    /// The box's top-left pixel.
    pub x0: i32,
    pub y0: i32,
    /// The (biased) values at its centre.
    pub origin: [i32; 3],
    pub step_x: [i32; 3],
    pub step_y: [i32; 3],
    /// The fill-rule bias folded into the values (0 or -1).
    pub bias: [i32; 3],
}

/// The values of [`FixedEdges`] inside the box, one pixel at a time: `i32` steps where a target has no 64-bit
/// registers, the same values (outside the box they may wrap: the pixel loops do not leave it).
impl CentreEdges for NarrowEdges {
    type At = [i32; 3];

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> [i32; 3] {
        let (dx, dy) = (x.wrapping_sub(self.x0), y.wrapping_sub(self.y0));
        let at = |k: usize| {
            self.origin[k].wrapping_add(self.step_x[k].wrapping_mul(dx)).wrapping_add(self.step_y[k].wrapping_mul(dy))
        };
        [at(0), at(1), at(2)]
    }

    #[inline(always)]
    fn step(&self, e: [i32; 3]) -> [i32; 3] {
        [0, 1, 2].map(|k| e[k].wrapping_add(self.step_x[k]))
    }

    #[inline(always)]
    fn down(&self, e: [i32; 3], _: i32, _: i32) -> [i32; 3] {
        [0, 1, 2].map(|k| e[k].wrapping_add(self.step_y[k]))
    }

    #[inline(always)]
    fn covered(&self, e: &[i32; 3]) -> bool {
        (e[0] | e[1] | e[2]) >= 0
    }

    #[inline(always)]
    fn weights(&self, e: &[i32; 3]) -> [f32; 3] {
        [0, 1, 2].map(|k| e[k].wrapping_sub(self.bias[k]) as f32)
    }
}

/// Exact edge functions in units of `2^-(S+1)` pixel, stepped incrementally.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FixedEdges {
    /// Biased edge values at the centre of pixel (0, 0) (possibly far outside the frame: the values fit `i64`).
    pub origin: [i64; 3],
    pub step_x: [i64; 3],
    pub step_y: [i64; 3],
    /// The fill-rule bias folded into the values (0 for top-left edges, -1 otherwise).
    pub bias: [i64; 3],
}

impl CentreEdges for FixedEdges {
    type At = [i64; 3];

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> [i64; 3] {
        let (x, y) = (i64::from(x), i64::from(y));
        let at = |k: usize| self.origin[k] + self.step_x[k] * x + self.step_y[k] * y;
        [at(0), at(1), at(2)]
    }

    #[inline(always)]
    fn step(&self, e: [i64; 3]) -> [i64; 3] {
        [e[0] + self.step_x[0], e[1] + self.step_x[1], e[2] + self.step_x[2]]
    }

    #[inline(always)]
    fn down(&self, e: [i64; 3], _: i32, _: i32) -> [i64; 3] {
        [e[0] + self.step_y[0], e[1] + self.step_y[1], e[2] + self.step_y[2]]
    }

    #[inline(always)]
    fn covered(&self, e: &[i64; 3]) -> bool {
        (e[0] | e[1] | e[2]) >= 0
    }

    #[inline(always)]
    fn weights(&self, e: &[i64; 3]) -> [f32; 3] {
        // Unbiased: >= 0 and summing to the doubled area, so the weights are a convex combination.
        [0, 1, 2].map(|k| float::from_i64(e[k] - self.bias[k]))
    }
}

impl Edges for FixedEdges {
    #[inline(always)]
    fn steps(&self) -> [[f32; 3]; 2] {
        [self.step_x.map(float::from_i64), self.step_y.map(float::from_i64)]
    }

    /// A sample `(ox, oy)` eighths of a pixel from the centre changes an edge function `E` by `(step_x ox + step_y
    /// oy) / 8`, which need not be whole. Eight times it is: a sample's values are `8 E + bias`, an integer that is
    /// non-negative exactly when the sample is covered (the bias of -1 turns `8 E > 0` into `8 E + bias >= 0`, as
    /// it does for `E`). From the biased centre value `e = E + bias` that is `8 e + step_x ox + step_y oy - 7 bias`.
    #[inline(always)]
    fn sample_offsets(&self) -> [[i64; 3]; SAMPLE_COUNT] {
        SAMPLE_POSITIONS.map(|(ox, oy)| {
            let (ox, oy) = (i64::from(ox), i64::from(oy));
            [0, 1, 2].map(|k| self.step_x[k] * ox + self.step_y[k] * oy - 7 * self.bias[k])
        })
    }

    #[inline(always)]
    fn sample_reach(&self) -> [i64; 3] {
        let offsets = self.sample_offsets();
        [0, 1, 2].map(|k| offsets.iter().fold(i64::MIN, |m, o| m.max(o[k])))
    }

    #[inline(always)]
    fn at_sample(&self, centre: &[i64; 3], offset: &[i64; 3]) -> [i64; 3] {
        [8 * centre[0] + offset[0], 8 * centre[1] + offset[1], 8 * centre[2] + offset[2]]
    }

    /// The values are eight times the edge functions: an eighth of the unbiased value, exactly (`f32` rounding
    /// commutes with a power of two), so a sample at a pixel centre would weigh what the centre weighs.
    #[inline(always)]
    fn sample_weights(&self, e: &[i64; 3]) -> [f32; 3] {
        self.weights(e).map(|w| w * 0.125)
    }

    #[inline(always)]
    fn closed(&self, e: &[i64; 3]) -> bool {
        // Each value masked to itself where the step is not positive, to 0 elsewhere: negative iff failed there.
        let closing = |k: usize| e[k] & -i64::from(self.step_x[k] <= 0);
        (closing(0) | closing(1) | closing(2)) < 0
    }

    /// A linear function is largest and smallest over a box at its corners: when those values fit `i32` (below its
    /// maximum, so the unbiased value `v + 1` fits too), all do, and `i32` comparisons and conversions to `f32` give
    /// what the `i64` ones give.
    #[inline(always)]
    fn narrow(&self, x0: i32, x1: i32, y0: i32, y1: i32) -> Option<NarrowEdges> {
        let fits = |v: i64| (i64::from(i32::MIN)..i64::from(i32::MAX)).contains(&v);
        let corners = [self.at(x0, y0), self.at(x1, y0), self.at(x0, y1), self.at(x1, y1)];
        if !corners.iter().all(|c| c.iter().all(|&v| fits(v))) {
            return None;
        }
        // Truncating casts: modulo 2^32, which is all the wrapping arithmetic of the lanes needs.
        let wrap = |v: [i64; 3]| v.map(|v| v as i32);
        Some(NarrowEdges {
            x0,
            y0,
            origin: wrap(corners[0]),
            step_x: wrap(self.step_x),
            step_y: wrap(self.step_y),
            bias: wrap(self.bias),
        })
    }
}

/// `f32` edge functions `a x + b y + c` in pixels, each row evaluated from its own coordinates and stepped along
/// the row.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FloatEdges {
    pub a: [f32; 3],
    pub b: [f32; 3],
    /// The value at the screen origin.
    pub c: [f32; 3],
    /// A centre is inside edge `k` when its value exceeds `threshold[k]`: 0 for an edge that does not own the
    /// centres exactly on it, and minus the smallest subnormal (no `f32` lies between it and 0, so the test
    /// becomes `>= 0`) for a top or left edge, which does. One comparison per edge, no branch.
    pub threshold: [f32; 3],
}

impl CentreEdges for FloatEdges {
    type At = [f32; 3];

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> [f32; 3] {
        let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
        let at = |k: usize| self.a[k] * x + self.b[k] * y + self.c[k];
        [at(0), at(1), at(2)]
    }

    #[inline(always)]
    fn step(&self, e: [f32; 3]) -> [f32; 3] {
        [e[0] + self.a[0], e[1] + self.a[1], e[2] + self.a[2]]
    }

    #[inline(always)]
    fn covered(&self, e: &[f32; 3]) -> bool {
        // `&`, not `&&`: three comparisons, no branches.
        (e[0] > self.threshold[0]) & (e[1] > self.threshold[1]) & (e[2] > self.threshold[2])
    }

    #[inline(always)]
    fn weights(&self, e: &[f32; 3]) -> [f32; 3] {
        [float::max(e[0], 0.0), float::max(e[1], 0.0), float::max(e[2], 0.0)]
    }
}

impl Edges for FloatEdges {
    #[inline(always)]
    fn steps(&self) -> [[f32; 3]; 2] {
        [self.a, self.b]
    }

    #[inline(always)]
    fn sample_offsets(&self) -> [[f32; 3]; SAMPLE_COUNT] {
        SAMPLE_POSITIONS.map(|(ox, oy)| {
            let (ox, oy) = (ox as f32 / 8.0, oy as f32 / 8.0);
            [0, 1, 2].map(|k| self.a[k] * ox + self.b[k] * oy)
        })
    }

    #[inline(always)]
    fn sample_reach(&self) -> [f32; 3] {
        let offsets = self.sample_offsets();
        [0, 1, 2].map(|k| offsets.iter().fold(f32::NEG_INFINITY, |m, o| float::max(m, o[k])))
    }

    #[inline(always)]
    fn at_sample(&self, centre: &[f32; 3], offset: &[f32; 3]) -> [f32; 3] {
        [centre[0] + offset[0], centre[1] + offset[1], centre[2] + offset[2]]
    }

    #[inline(always)]
    fn sample_weights(&self, e: &[f32; 3]) -> [f32; 3] {
        self.weights(e)
    }

    /// Rounding is monotonic: adding a step `a <= 0` never gives more than the value it was added to, at a centre
    /// or at a sample (a centre's value plus a fixed offset).
    #[inline(always)]
    fn closed(&self, e: &[f32; 3]) -> bool {
        let inside = |k: usize| e[k] > self.threshold[k];
        let closing = |k: usize| self.a[k] <= 0.0;
        (!inside(0) & closing(0)) | (!inside(1) & closing(1)) | (!inside(2) & closing(2))
    }
}

/// Either kind, chosen per pixel: the general path.
#[derive(Clone, Copy, Debug)]
pub(crate) enum DynamicEdges {
    Fixed(FixedEdges),
    Float(FloatEdges),
}

impl From<FixedEdges> for DynamicEdges {
    #[inline(always)]
    fn from(edges: FixedEdges) -> Self {
        Self::Fixed(edges)
    }
}

impl From<FloatEdges> for DynamicEdges {
    #[inline(always)]
    fn from(edges: FloatEdges) -> Self {
        Self::Float(edges)
    }
}

/// Values of [`DynamicEdges`].
#[derive(Clone, Copy, Debug)]
pub(crate) enum DynamicAt {
    Fixed([i64; 3]),
    Float([f32; 3]),
}

impl CentreEdges for DynamicEdges {
    type At = DynamicAt;

    #[inline(always)]
    fn at(&self, x: i32, y: i32) -> DynamicAt {
        match self {
            Self::Fixed(e) => DynamicAt::Fixed(e.at(x, y)),
            Self::Float(e) => DynamicAt::Float(e.at(x, y)),
        }
    }

    #[inline(always)]
    fn step(&self, at: DynamicAt) -> DynamicAt {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => DynamicAt::Fixed(e.step(v)),
            (Self::Float(e), DynamicAt::Float(v)) => DynamicAt::Float(e.step(v)),
            (_, at) => at,
        }
    }

    #[inline(always)]
    fn down(&self, at: DynamicAt, x: i32, y: i32) -> DynamicAt {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => DynamicAt::Fixed(e.down(v, x, y)),
            (Self::Float(e), DynamicAt::Float(v)) => DynamicAt::Float(e.down(v, x, y)),
            (_, at) => at,
        }
    }

    #[inline(always)]
    fn covered(&self, at: &DynamicAt) -> bool {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => e.covered(v),
            (Self::Float(e), DynamicAt::Float(v)) => e.covered(v),
            _ => false,
        }
    }

    #[inline(always)]
    fn weights(&self, at: &DynamicAt) -> [f32; 3] {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => e.weights(v),
            (Self::Float(e), DynamicAt::Float(v)) => e.weights(v),
            _ => [0.0; 3],
        }
    }
}

impl Edges for DynamicEdges {
    #[inline(always)]
    fn steps(&self) -> [[f32; 3]; 2] {
        match self {
            Self::Fixed(e) => e.steps(),
            Self::Float(e) => e.steps(),
        }
    }

    #[inline(always)]
    fn sample_offsets(&self) -> [DynamicAt; SAMPLE_COUNT] {
        match self {
            Self::Fixed(e) => e.sample_offsets().map(DynamicAt::Fixed),
            Self::Float(e) => e.sample_offsets().map(DynamicAt::Float),
        }
    }

    #[inline(always)]
    fn sample_reach(&self) -> DynamicAt {
        match self {
            Self::Fixed(e) => DynamicAt::Fixed(e.sample_reach()),
            Self::Float(e) => DynamicAt::Float(e.sample_reach()),
        }
    }

    #[inline(always)]
    fn at_sample(&self, centre: &DynamicAt, offset: &DynamicAt) -> DynamicAt {
        match (self, centre, offset) {
            (Self::Fixed(e), DynamicAt::Fixed(v), DynamicAt::Fixed(o)) => DynamicAt::Fixed(e.at_sample(v, o)),
            (Self::Float(e), DynamicAt::Float(v), DynamicAt::Float(o)) => DynamicAt::Float(e.at_sample(v, o)),
            (_, centre, _) => *centre,
        }
    }

    #[inline(always)]
    fn sample_weights(&self, at: &DynamicAt) -> [f32; 3] {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => e.sample_weights(v),
            (Self::Float(e), DynamicAt::Float(v)) => e.sample_weights(v),
            _ => [0.0; 3],
        }
    }

    #[inline(always)]
    fn closed(&self, at: &DynamicAt) -> bool {
        match (self, at) {
            (Self::Fixed(e), DynamicAt::Fixed(v)) => e.closed(v),
            (Self::Float(e), DynamicAt::Float(v)) => e.closed(v),
            _ => true,
        }
    }

    #[inline(always)]
    fn narrow(&self, x0: i32, x1: i32, y0: i32, y1: i32) -> Option<NarrowEdges> {
        match self {
            Self::Fixed(e) => e.narrow(x0, x1, y0, y1),
            Self::Float(e) => e.narrow(x0, x1, y0, y1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A xorshift step: deterministic values for the test.
    fn next(state: &mut u64) -> u64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        *state
    }

    /// A value in `-range..=range`, zero one time in eight.
    fn signed(state: &mut u64, range: i64) -> i64 {
        let v = next(state);
        if v % 8 == 0 { 0 } else { (v >> 8) as i64 % (range + 1) * if v & 16 == 0 { 1 } else { -1 } }
    }

    /// Walks row 0 from pixel -64 to 64 at the centre and at every sample; once [`Edges::closed`] holds at a
    /// point, that point must be uncovered at every pixel further right (the multisampled loop leaves the row
    /// there). At each pixel, a covered sample needs the values at [`Edges::sample_reach`] covered, and once those
    /// are closed no sample may be covered again. Returns how many points (the centre, the samples and the reach)
    /// closed before the row's end, so the caller can check the walk exercised it.
    fn check_row<E: Edges + core::fmt::Debug>(edges: &E, i: u32) -> u32 {
        let (offsets, reach) = (edges.sample_offsets(), edges.sample_reach());
        let mut closed_at: [Option<i32>; SAMPLE_COUNT + 2] = [None; SAMPLE_COUNT + 2];
        let mut centre = edges.at(-64, 0);
        for x in -64..=64 {
            let points: [E::At; SAMPLE_COUNT + 2] = core::array::from_fn(|p| match p {
                0 => centre,
                p if p <= SAMPLE_COUNT => edges.at_sample(&centre, &offsets[p - 1]),
                _ => edges.at_sample(&centre, &reach),
            });
            let any_sample = points[1..=SAMPLE_COUNT].iter().any(|at| edges.covered(at));
            assert!(!any_sample || edges.covered(&points[SAMPLE_COUNT + 1]), "#{i} {edges:?}: reach at x = {x}");
            if let Some(x0) = closed_at[SAMPLE_COUNT + 1] {
                assert!(!any_sample, "#{i} {edges:?}: the reach closed at x = {x0}, a sample covered at x = {x}");
            }
            for (p, at) in points.iter().enumerate() {
                if let Some(x0) = closed_at[p] {
                    let covered = p <= SAMPLE_COUNT && edges.covered(at);
                    assert!(!covered, "#{i} {edges:?}: point {p} closed at x = {x0}, covered at x = {x}");
                } else if edges.closed(at) {
                    closed_at[p] = Some(x);
                }
            }
            centre = edges.step(centre);
        }
        closed_at.iter().filter(|c| c.is_some_and(|x| x < 64)).count() as u32
    }

    #[test]
    fn closed_points_and_reaches_stay_uncovered_to_the_right() {
        let mut state = 0x9E37_79B9_7F4A_7C15;
        let (mut fixed_closed, mut float_closed) = (0, 0);
        for i in 0..4000 {
            let fixed = FixedEdges {
                origin: [0; 3].map(|_| signed(&mut state, 1 << 30)),
                step_x: [0; 3].map(|_| signed(&mut state, 1 << 20)),
                step_y: [0; 3].map(|_| signed(&mut state, 1 << 20)),
                bias: [0; 3].map(|_| -((next(&mut state) & 1) as i64)),
            };
            fixed_closed += check_row(&fixed, i);
            // Float edges with steps from tiny to large, and values near the thresholds.
            let scale = |s: &mut u64| [1e-6, 1e-2, 1.0, 37.0][(next(s) % 4) as usize];
            let float = FloatEdges {
                a: [0; 3].map(|_| signed(&mut state, 1 << 16) as f32 / 65536.0 * scale(&mut state)),
                b: [0; 3].map(|_| signed(&mut state, 1 << 16) as f32 / 65536.0 * scale(&mut state)),
                c: [0; 3].map(|_| signed(&mut state, 1 << 16) as f32 / 256.0 * scale(&mut state)),
                threshold: [0; 3].map(|_| if next(&mut state) & 1 == 0 { 0.0 } else { -f32::from_bits(1) }),
            };
            float_closed += check_row(&float, i);
        }
        // Most rows close points before their end: the property was tested, not skipped.
        assert!(
            fixed_closed > 4000 && float_closed > 4000,
            "closed points: fixed {fixed_closed}, float {float_closed}"
        );
    }

    /// Where [`FixedEdges::lanes`] gives `i32` values, walking them as [`CentreEdges`] covers and weighs every
    /// pixel of the box as the `i64` values do, values at the limits of `i32` included; where it gives none, a
    /// value at a corner does not fit.
    #[test]
    fn i32_values_walk_the_box_as_the_i64_values_do() {
        let mut state = 0x2545_F491_4F6C_DD1D;
        let (mut narrow, mut wide) = (0, 0);
        for i in 0..4000 {
            // Half the boxes' values near `i32`'s limits, half beyond them.
            let (range, step) = if i % 2 == 0 { (1 << 30, 1 << 20) } else { (1 << 33, 1 << 24) };
            let fixed = FixedEdges {
                origin: [0; 3].map(|_| signed(&mut state, range)),
                step_x: [0; 3].map(|_| signed(&mut state, step)),
                step_y: [0; 3].map(|_| signed(&mut state, step)),
                bias: [0; 3].map(|_| -((next(&mut state) & 1) as i64)),
            };
            let (x0, y0) = (signed(&mut state, 300) as i32, signed(&mut state, 300) as i32);
            let (x1, y1) = (x0 + (next(&mut state) % 40) as i32, y0 + (next(&mut state) % 40) as i32);
            let Some(lanes) = fixed.narrow(x0, x1, y0, y1) else {
                let corners = [fixed.at(x0, y0), fixed.at(x1, y0), fixed.at(x0, y1), fixed.at(x1, y1)];
                let fits = |v: i64| (i64::from(i32::MIN)..i64::from(i32::MAX)).contains(&v);
                assert!(!corners.iter().flatten().all(|&v| fits(v)), "#{i}: every corner fits, not narrowed");
                wide += 1;
                continue;
            };
            narrow += 1;
            for y in y0..=y1 {
                let (mut e, mut l) = (fixed.at(x0, y), lanes.at(x0, y));
                for x in x0..=x1 {
                    assert_eq!(l.map(i64::from), e, "#{i} ({x}, {y}): values");
                    assert_eq!(lanes.covered(&l), fixed.covered(&e), "#{i} ({x}, {y}): coverage");
                    let bits = |w: [f32; 3]| w.map(f32::to_bits);
                    assert_eq!(bits(lanes.weights(&l)), bits(fixed.weights(&e)), "#{i} ({x}, {y}): weights");
                    (e, l) = (fixed.step(e), lanes.step(l));
                }
            }
        }
        assert!(narrow > 1000 && wide > 1000, "boxes with i32 values: {narrow}, without: {wide}");
    }
}
