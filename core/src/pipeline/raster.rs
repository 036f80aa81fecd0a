//! The fixed-point rasterizer: snapping, triangle set-up, the top-left fill rule and the pixel loop.
//!
//! Screen coordinates are snapped to a grid of `2^-S` pixel (`S` = [`super::DrawState::subpixel_bits`]) and
//! held as integers in units of `2^-(S+1)` pixel, so that pixel centres `(i + 0.5, j + 0.5)` are integers too.
//! Edge functions are evaluated exactly in `i64` — inside the guard band coordinates stay below 2^24 units, their
//! products below 2^50 — and stepped by integer additions, so coverage is exact and independent of where the
//! walk started: a band of rows gets the same pixels as the whole frame.
//!
//! Fill rule: a pixel centre exactly on an edge belongs to the triangle only if that edge is a top or a left edge
//! (Direct3D 11.3 functional specification, 3.4.2.1; Pineda, "A Parallel Algorithm for Polygon Rasterization",
//! SIGGRAPH 1988). Two triangles sharing an edge therefore cover each pixel on it exactly once.
//!
//! A multisampled target's pixels are covered sample by sample (`multisample.rs`): the same edge functions, times
//! eight at the samples (which lie on eighths of a pixel), so that they stay exact integers and the same rule covers
//! each sample on a shared edge exactly once.

mod multisample;

use super::batch::{BATCH_SIZE, FragmentBatch};
use super::depth_stage::DepthStage;
use super::edges::{CentreEdges, EdgeLanes, Edges, FixedEdges, FloatEdges};
use super::interpolator::Interpolator;
use super::slopes::FractionSteps;
use super::{Cull, Fragment, Shader, Slopes, Varyings, Winding};
use crate::camera::Viewport;
use crate::math::{Vec3, Vec4, float};
use crate::target::{ColorBuffer, DEPTH_LANES, DepthBuffer, SAMPLE_REACH, Samples, Target, VertexMemory, clamp_depth};

/// A vertex position in screen space, snapped to the sub-pixel grid (and kept unsnapped for `f32` edges).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Snapped {
    /// Fixed-point x, in units of `2^-(S+1)` pixel.
    x: i32,
    /// Fixed-point y (down), same units.
    y: i32,
    /// Unsnapped x in pixels.
    fx: f32,
    /// Unsnapped y (down) in pixels.
    fy: f32,
    /// NDC depth.
    z: f32,
    /// `1 / w`.
    inv_w: f32,
}

impl Snapped {
    /// A placeholder for a vertex without a screen position.
    pub const ZERO: Self = Self { x: 0, y: 0, fx: 0.0, fy: 0.0, z: 0.0, inv_w: 0.0 };

    /// The unsnapped row (y down) in pixels.
    pub fn row(&self) -> f32 {
        self.fy
    }
}

/// Per-vertex values given in input order, in the oriented order of a triangle whose first two vertices were
/// `swapped` to make its area positive.
#[inline(always)]
fn oriented<T: Copy>(swapped: bool, [a, b, c]: [T; 3]) -> [T; 3] {
    if swapped { [b, a, c] } else { [a, b, c] }
}

/// Largest magnitude, in pixels, that a snapped coordinate is clamped to: twice the guard band, so clamping never
/// happens to a clipped triangle and merely bounds the integers if rounding ever pushed a vertex out. Times
/// 2^[`super::MAX_SUBPIXEL_BITS`] it stays below 2^23, where `f32` still holds every integer.
const SNAP_LIMIT_PX: f32 = 2.0 * super::clip::GUARD_BAND;
const _: () = assert!(SNAP_LIMIT_PX * (1u32 << super::MAX_SUBPIXEL_BITS) as f32 <= 8_388_608.0);

/// Whether the target has no 64-bit registers (a Cortex-M4, 32-bit RISC-V): there the batched pixel loop walks a
/// triangle's edge values in `i32` where they fit ([`Edges::lanes`]), one add each instead of two.
const NARROW: bool = cfg!(not(target_pointer_width = "64"));

/// What became of one triangle (or clipped piece) at set-up.
pub(crate) enum Setup<E> {
    /// Zero area on the sub-pixel grid.
    Degenerate,
    /// Removed by face culling.
    Culled,
    /// Facing is fine but its bounding box holds no pixel centre of the target.
    Empty,
    /// Its bounding box holds pixel centres of the target (a sliver may still cover none): ready for the pixel
    /// loop.
    Ready(Coverage<E>),
}

impl<E> Setup<E> {
    /// The same outcome with the edge functions converted.
    #[inline(always)]
    pub fn map<F>(self, f: impl FnOnce(E) -> F) -> Setup<F> {
        match self {
            Self::Degenerate => Setup::Degenerate,
            Self::Culled => Setup::Culled,
            Self::Empty => Setup::Empty,
            Self::Ready(c) => Setup::Ready(Coverage { edges: f(c.edges), frame: c.frame }),
        }
    }
}

/// Per-draw rasterizer settings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rasterizer {
    viewport: Viewport,
    /// `2^S`.
    scale: f32,
    /// `S + 1`: pixels to fixed-point units.
    shift: u32,
    /// The samples per pixel of the target.
    samples: Samples,
    /// How far the samples lie from the pixel centre, at most, in fixed-point units (rounded up) and in pixels: 0
    /// with one sample per pixel.
    reach: (i64, f32),
    width: i32,
    row0: i32,
    row1: i32,
    cull: Cull,
    front_face: Winding,
}

impl Rasterizer {
    pub fn new<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
        target: &Target<C, D, M>,
        subpixel_bits: u8,
        cull: Cull,
        front_face: Winding,
    ) -> Self {
        let (width, height, rows, samples) = (target.width(), target.height(), target.rows(), target.samples());
        Self::for_frame(width, height, rows, samples, subpixel_bits, cull, front_face)
    }

    /// The rasterizer of a `width x height` frame drawn in rows `rows` with `samples` per pixel.
    pub fn for_frame(
        width: u32,
        height: u32,
        rows: core::ops::Range<u32>,
        samples: Samples,
        subpixel_bits: u8,
        cull: Cull,
        front_face: Winding,
    ) -> Self {
        let shift = u32::from(subpixel_bits) + 1;
        // Eighths of a pixel, 2^shift units each.
        let reach = match samples {
            Samples::One => (0, 0.0),
            Samples::Four => (((i64::from(SAMPLE_REACH) << shift) + 7) >> 3, SAMPLE_REACH as f32 / 8.0),
        };
        Self {
            viewport: Viewport::full(width, height),
            scale: (1u32 << subpixel_bits) as f32,
            shift,
            samples,
            reach,
            width: width as i32,
            row0: rows.start as i32,
            row1: rows.end as i32,
            cull,
            front_face,
        }
    }

    /// Divides by `w`, maps to the screen and snaps. `None` when `w <= 0` (only possible for the degenerate
    /// all-zero clip-space point once clipping is done).
    #[inline(always)]
    pub fn snap(&self, pos: Vec4) -> Option<Snapped> {
        let w_positive = pos.w > 0.0; // false for NaN too
        if !w_positive {
            return None;
        }
        Some(self.snap_any(pos))
    }

    /// [`Self::snap`] without the test of `w` (meaningless values, but no fault, when `w <= 0`): branch-free, so
    /// that a loop of it over several vertices widens to SIMD.
    #[inline(always)]
    pub fn snap_any(&self, pos: Vec4) -> Snapped {
        let inv_w = 1.0 / pos.w;
        let s = self.viewport.to_screen(pos.truncate() * inv_w);
        let (fx, fy) =
            (float::clamp(s.x, -SNAP_LIMIT_PX, SNAP_LIMIT_PX), float::clamp(s.y, -SNAP_LIMIT_PX, SNAP_LIMIT_PX));
        // Round to the nearest grid point; within the clamp, |p| < 2^23 and `floor` and the cast are exact.
        let fixed = |p: f32| (float::floor(p * self.scale + 0.5) as i32) << 1;
        Snapped { x: fixed(fx), y: fixed(fy), fx, fy, z: s.z, inv_w }
    }

    /// Facing and culling from the sign of twice the signed area in screen coordinates (positive: clockwise as
    /// displayed, which is clockwise on the y-up NDC plane too).
    #[inline(always)]
    fn facing(&self, area_positive: bool) -> Option<bool> {
        // Counter-clockwise on the y-up NDC plane is a negative area here.
        let front_facing = area_positive != (self.front_face == Winding::CounterClockwise);
        match self.cull {
            Cull::Back if !front_facing => None,
            Cull::Front if front_facing => None,
            _ => Some(front_facing),
        }
    }

    /// The target's pixels whose centres lie in `[lo, hi]` (in pixels, inclusive), as an inclusive range clamped to
    /// the target: columns when `rows` is false, the target's rows otherwise.
    #[inline(always)]
    fn centres(&self, first: i32, last: i32, rows: bool) -> (i32, i32) {
        if rows { (first.max(self.row0), last.min(self.row1 - 1)) } else { (first.max(0), last.min(self.width - 1)) }
    }

    /// Exact fixed-point set-up: area, facing, bounding box and `i64` edge functions of the snapped triangle. On a
    /// multisampled target the box takes in every pixel with a sample inside the triangle's bounds.
    #[inline(always)]
    pub fn setup_fixed(&self, v: [Snapped; 3]) -> Setup<FixedEdges> {
        // Element by element, not with array maps: `perf` put 8 to 15 % of sphere1m's samples in `try_map`.
        let fixed = |p: &Snapped| (i64::from(p.x), i64::from(p.y));
        let (a, b, c) = (fixed(&v[0]), fixed(&v[1]), fixed(&v[2]));
        // Twice the signed area in fixed-point units.
        let area = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        if area == 0 {
            return Setup::Degenerate;
        }
        let Some(front_facing) = self.facing(area > 0) else { return Setup::Culled };

        let shift = self.shift;
        let half = 1i64 << (shift - 1);
        // Pixel centres inside the bounding box widened by the samples' reach (none with one sample): i with
        // (i << shift) + half in [min - reach, max + reach]. (Rounded up, the reach may take in a pixel none of whose
        // samples is inside: the pixel loop tests each.)
        let reach = self.reach.0;
        let (min_x, max_x) = (a.0.min(b.0).min(c.0) - reach, a.0.max(b.0).max(c.0) + reach);
        let (min_y, max_y) = (a.1.min(b.1).min(c.1) - reach, a.1.max(b.1).max(c.1) + reach);
        let first_centre = |lo: i64| ((lo - half + (1 << shift) - 1) >> shift) as i32;
        let last_centre = |hi: i64| ((hi - half) >> shift) as i32;
        let (x0, x1) = self.centres(first_centre(min_x), last_centre(max_x), false);
        let (y0, y1) = self.centres(first_centre(min_y), last_centre(max_y), true);
        if x0 > x1 || y0 > y1 {
            return Setup::Empty;
        }

        // Orient clockwise on screen (positive area) so that every edge function is positive inside.
        let swapped = area < 0;
        let verts = oriented(swapped, [a, b, c]);
        // Edge k is the one opposite vertex k; its function is k's barycentric coordinate times `area`, evaluated
        // at pixel centres (i << shift) + half.
        let mut edges = FixedEdges { origin: [0; 3], step_x: [0; 3], step_y: [0; 3], bias: [0; 3] };
        for k in 0..3 {
            let (p, q) = (verts[(k + 1) % 3], verts[(k + 2) % 3]);
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            // Inside is to the right of p->q in y-down screen space; the edge is "left" when y decreases along
            // it and "top" when it is horizontal running to +x.
            let top_left = dy < 0 || (dy == 0 && dx > 0);
            edges.bias[k] = if top_left { 0 } else { -1 };
            edges.origin[k] = dx * (half - p.1) - dy * (half - p.0) + edges.bias[k];
            edges.step_x[k] = -dy << shift;
            edges.step_y[k] = dx << shift;
        }
        let frame = Frame::new([x0, x1, y0, y1], front_facing, swapped, v, float::from_i64(area.abs()), self.samples);
        Setup::Ready(Coverage { edges, frame })
    }

    /// Plain `f32` set-up from the unsnapped positions: area, facing, bounding box and edge functions.
    #[inline(always)]
    pub fn setup_float(&self, v: [Snapped; 3]) -> Setup<FloatEdges> {
        let (a, b, c) = ((v[0].fx, v[0].fy), (v[1].fx, v[1].fy), (v[2].fx, v[2].fy));
        let area = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        // Zero, or NaN from an overflow: nothing to draw.
        if !(area != 0.0 && area.is_finite()) {
            return Setup::Degenerate;
        }
        let Some(front_facing) = self.facing(area > 0.0) else { return Setup::Culled };
        // Widened by the samples' reach, as in `setup_fixed` (an exact multiple of 2^-3).
        let reach = self.reach.1;
        let (min_x, max_x) = (float::min(a.0, float::min(b.0, c.0)), float::max(a.0, float::max(b.0, c.0)));
        let (min_y, max_y) = (float::min(a.1, float::min(b.1, c.1)), float::max(a.1, float::max(b.1, c.1)));
        let (min_x, max_x, min_y, max_y) = (min_x - reach, max_x + reach, min_y - reach, max_y + reach);
        // Centres i + 0.5 in [lo, hi]: i from ceil(lo - 0.5) to floor(hi - 0.5).
        let first_centre = |lo: f32| -(float::floor(0.5 - lo) as i32);
        let last_centre = |hi: f32| float::floor(hi - 0.5) as i32;
        let (x0, x1) = self.centres(first_centre(min_x), last_centre(max_x), false);
        let (y0, y1) = self.centres(first_centre(min_y), last_centre(max_y), true);
        if x0 > x1 || y0 > y1 {
            return Setup::Empty;
        }
        let swapped = area < 0.0;
        let verts = oriented(swapped, [a, b, c]);
        let mut edges = FloatEdges { a: [0.0; 3], b: [0.0; 3], c: [0.0; 3], threshold: [0.0; 3] };
        for k in 0..3 {
            let (p, q) = (verts[(k + 1) % 3], verts[(k + 2) % 3]);
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            let top_left = dy < 0.0 || (dy == 0.0 && dx > 0.0);
            edges.threshold[k] = if top_left { -f32::from_bits(1) } else { 0.0 };
            // E(x, y) = dx (y - p.y) - dy (x - p.x) = -dy x + dx y + (dy p.x - dx p.y).
            edges.a[k] = -dy;
            edges.b[k] = dx;
            edges.c[k] = dy * p.0 - dx * p.1;
        }
        let frame = Frame::new([x0, x1, y0, y1], front_facing, swapped, v, float::abs(area), self.samples);
        Setup::Ready(Coverage { edges, frame })
    }
}

/// Everything about a triangle in the pixel loop that does not depend on how its edges are evaluated.
pub(crate) struct Frame {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
    front_facing: bool,
    /// Whether the input's first two vertices were swapped to orient the triangle (see [`oriented`]).
    swapped: bool,
    z0: f32,
    /// Depth change per unit of edge function 1 and 2.
    dz1: f32,
    dz2: f32,
    inv_w: [f32; 3],
    inv_area: f32,
    /// The target's samples per pixel: which pixel loop covers it.
    samples: Samples,
}

impl Frame {
    #[inline(always)]
    fn new(
        [x0, x1, y0, y1]: [i32; 4],
        front_facing: bool,
        swapped: bool,
        v: [Snapped; 3],
        area: f32,
        samples: Samples,
    ) -> Self {
        let inv_area = 1.0 / area;
        let [a, b, c] = oriented(swapped, v);
        let (za, zb, zc) = (a.z, b.z, c.z);
        Self {
            x0,
            x1,
            y0,
            y1,
            front_facing,
            swapped,
            z0: za,
            dz1: (zb - za) * inv_area,
            dz2: (zc - za) * inv_area,
            inv_w: [a.inv_w, b.inv_w, c.inv_w],
            inv_area,
            samples,
        }
    }

    /// The depth of the fragment whose edge functions 1 and 2 are `w1` and `w2`, as every fill tests and stores it.
    #[inline(always)]
    fn depth(&self, w1: f32, w2: f32) -> f32 {
        clamp_depth(self.z0 + w1 * self.dz1 + w2 * self.dz2)
    }
}

/// A triangle that reaches the pixel loop: its edge functions and its geometric interpolants (depth, `1/w`).
pub(crate) struct Coverage<E> {
    edges: E,
    frame: Frame,
}

/// The per-draw stages the pixel loop is specialised on.
pub(crate) struct Stages<'s, S, I, Z> {
    pub shader: &'s S,
    pub interpolator: I,
    pub depth: Z,
    /// The shader discards fragments in this draw: [`Shader::CUTOUT`] and [`Shader::cutout`], asked once.
    pub cutout: bool,
    /// The shader reads its varyings' slopes in this draw ([`Shader::slopes`], asked once).
    pub slopes: bool,
}

/// A triangle's varyings as the pixel loops interpolate them, made once per triangle by
/// [`Stages::triangle_varyings`].
struct TriangleVaryings<V, T> {
    /// The first (oriented) vertex's varyings and the differences to the second's and the third's.
    v0: V,
    d1: V,
    d2: V,
    /// The interpolator's set-up.
    setup: T,
    /// The fraction steps when the draw reads slopes, zero otherwise.
    steps: FractionSteps,
    /// Zero slopes, for draws that do not read them.
    no_slopes: Slopes<V>,
}

impl<S: Shader, I: Interpolator, Z> Stages<'_, S, I, Z> {
    /// The fraction steps of a triangle with interpolator set-up `setup` and edge functions `edges`, when the draw
    /// reads slopes; zero otherwise.
    #[inline(always)]
    fn fraction_steps<E: Edges>(&self, setup: &I::Setup, edges: &E) -> FractionSteps {
        if self.slopes { self.interpolator.fraction_steps(setup, edges.steps()) } else { FractionSteps::default() }
    }

    /// The varyings of the triangle covering `frame` with edge functions `edges`, given for its input vertices in
    /// input order, ready for [`Self::interpolate`] (or a batch).
    #[inline(always)]
    fn triangle_varyings<E: Edges>(
        &self,
        frame: &Frame,
        edges: &E,
        varyings: [&S::Varyings; 3],
    ) -> TriangleVaryings<S::Varyings, I::Setup> {
        let setup = self.interpolator.setup(frame.inv_w, frame.inv_area);
        let steps = self.fraction_steps(&setup, edges);
        let [v0, v1, v2] = oriented(frame.swapped, varyings);
        TriangleVaryings { v0: *v0, d1: v1.sub(v0), d2: v2.sub(v0), setup, steps, no_slopes: Slopes::zero(v0) }
    }

    /// A fragment's varyings at edge weights `ef` and, when the draw reads them, their slopes (zero otherwise).
    #[inline(always)]
    fn interpolate(
        &self,
        t: &TriangleVaryings<S::Varyings, I::Setup>,
        ef: [f32; 3],
    ) -> (S::Varyings, Slopes<S::Varyings>) {
        let [w1, w2, r] = self.interpolator.weights(&t.setup, ef);
        let var = t.v0.interpolate(&t.d1, w1, &t.d2, w2);
        let slopes = if self.slopes { Slopes::of(&t.d1, &t.d2, t.steps.weight_slopes(w1, w2, r)) } else { t.no_slopes };
        (var, slopes)
    }
}

/// Largest bounding box, in pixel centres, that [`Coverage::covers_a_centre`] tests centre by centre.
const SMALL_BOX: i64 = 4;

impl<E: Edges> Coverage<E> {
    /// The first and last rows of the triangle's bounding box, clamped to the target's rows.
    #[inline(always)]
    pub fn rows(&self) -> (i32, i32) {
        (self.frame.y0, self.frame.y1)
    }

    /// False when the triangle covers none of the pixel centres (the samples, on a multisampled target) of its
    /// bounding box in the target, which is tested centre by centre for a box of at most [`SMALL_BOX`] pixels; true
    /// otherwise. A dense mesh's triangles are mostly smaller than a pixel and many cover no centre: this lets them
    /// skip their varyings and set-up.
    #[inline(always)]
    pub fn covers_a_centre(&self) -> bool {
        let f = &self.frame;
        if i64::from(f.x1 - f.x0 + 1) * i64::from(f.y1 - f.y0 + 1) > SMALL_BOX {
            return true;
        }
        if f.samples != Samples::One {
            return self.covers_a_sample();
        }
        for y in f.y0..=f.y1 {
            let mut e = self.edges.at(f.x0, y);
            for _ in f.x0..=f.x1 {
                if self.edges.covered(&e) {
                    return true;
                }
                e = self.edges.step(e);
            }
        }
        false
    }

    /// Visits every covered pixel centre in the target's rows: depth test, interpolation of `varyings` (given for
    /// the input vertices, in input order), fragment stage, write. Returns the number of fragments shaded.
    ///
    /// A [`Shader::BATCHED`] shader's fragments go into `batch`, which is shaded and written whenever it fills;
    /// the caller shades what is left at the end of the draw ([`shade_batch`]).
    #[inline(always)]
    pub fn fill<S, I, Z, C, D, M>(
        &self,
        stages: &Stages<'_, S, I, Z>,
        face: &S::Face,
        varyings: [&S::Varyings; 3],
        batch: &mut FragmentBatch<S::Varyings, S::Face>,
        target: &mut Target<C, D, M>,
    ) -> u64
    where
        S: Shader,
        I: Interpolator,
        Z: DepthStage,
        C: ColorBuffer,
        D: DepthBuffer,
        M: VertexMemory,
    {
        let f = &self.frame;
        if f.samples != Samples::One {
            return self.fill_multisample(stages, face, varyings, batch, target);
        }
        if !S::FRAGMENT_STAGE {
            // Depth only: nothing to shade. Several pixels at a time where the edge values fit `i32`.
            if let Some(lanes) = self.edges.lanes(f.x0, f.x1, f.y0, f.y1) {
                return self.fill_depth(lanes, &stages.depth, target);
            }
        } else if S::BATCHED {
            // Where a target has no 64-bit registers, the edge values in `i32` where they fit (the same values).
            let lanes = if NARROW { self.edges.lanes(f.x0, f.x1, f.y0, f.y1) } else { None };
            return match (&lanes, stages.cutout) {
                (Some(l), true) => {
                    self.fill_batched::<true, _, _, _, _, _, _, _>(l, stages, face, varyings, batch, target)
                }
                (Some(l), false) => {
                    self.fill_batched::<false, _, _, _, _, _, _, _>(l, stages, face, varyings, batch, target)
                }
                (None, true) => {
                    self.fill_batched::<true, _, _, _, _, _, _, _>(&self.edges, stages, face, varyings, batch, target)
                }
                (None, false) => {
                    self.fill_batched::<false, _, _, _, _, _, _, _>(&self.edges, stages, face, varyings, batch, target)
                }
            };
        }
        let edges = &self.edges;
        let triangle = stages.triangle_varyings(f, edges, varyings);
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let mut shaded = 0u64;
        for y in f.y0..=f.y1 {
            let mut e = edges.at(f.x0, y);
            let mut x = f.x0;
            // The covered centres of a row are contiguous (a triangle is convex): skip to them, run, stop.
            while x <= f.x1 && !edges.covered(&e) {
                e = edges.step(e);
                x += 1;
            }
            let base = (y - row0) as usize * width;
            while x <= f.x1 && edges.covered(&e) {
                let ef = edges.weights(&e);
                let z = f.depth(ef[1], ef[2]);
                let index = base + x as usize;
                if S::CUTOUT && stages.cutout {
                    // Shaded when nearer, written (and counted) when kept and still nearer.
                    if stages.depth.nearer(&target.depth, index, z) {
                        let (var, slopes) = stages.interpolate(&triangle, ef);
                        let fragment = Fragment { x: x as u32, y: y as u32, depth: z, front_facing: f.front_facing };
                        if stages.shader.kept(&fragment, face, &var, &slopes)
                            && stages.depth.test(&mut target.depth, index, z)
                        {
                            target.color.write(index, stages.shader.fragment(&fragment, face, &var, &slopes));
                            shaded += 1;
                        }
                    }
                } else if stages.depth.test(&mut target.depth, index, z) {
                    // A constant: a depth-only shader compiles without the fragment stage.
                    if S::FRAGMENT_STAGE {
                        let (var, slopes) = stages.interpolate(&triangle, ef);
                        let fragment = Fragment { x: x as u32, y: y as u32, depth: z, front_facing: f.front_facing };
                        let color = stages.shader.fragment(&fragment, face, &var, &slopes);
                        target.color.write(index, color);
                    }
                    shaded += 1;
                }
                e = edges.step(e);
                x += 1;
            }
        }
        shaded
    }

    /// [`Coverage::fill`] for a depth-only shader, with the edge functions as `lanes`: the depth test
    /// alone, [`DEPTH_LANES`] pixels of a row at a time across the bounding box, with coverage, weights and depth
    /// worked out per lane exactly as the pixel walk works them out per pixel (the same depths reach the same
    /// pixels). The lanes are one branch-free loop, which the compiler widens to SIMD.
    #[inline(always)]
    fn fill_depth<Z, C, D, M>(&self, lanes: EdgeLanes, depth: &Z, target: &mut Target<C, D, M>) -> u64
    where
        Z: DepthStage,
        C: ColorBuffer,
        D: DepthBuffer,
        M: VertexMemory,
    {
        const N: usize = DEPTH_LANES;
        let f = &self.frame;
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let count = f.x1 - f.x0 + 1;
        // Lane j of a group lies j pixels right of its first: its values are the first's plus j steps.
        let offsets: [[i32; N]; 3] =
            core::array::from_fn(|k| core::array::from_fn(|j| lanes.step_x[k].wrapping_mul(j as i32)));
        let group_step = lanes.step_x.map(|s| s.wrapping_mul(N as i32));
        let mut row = lanes.origin;
        let mut passed = 0u64;
        for y in f.y0..=f.y1 {
            let first = (y - row0) as usize * width + f.x0 as usize;
            let mut e = row;
            let mut x = 0;
            while x < count {
                let (mut z, mut covered) = ([0.0; N], [false; N]);
                for j in 0..N {
                    let v0 = e[0].wrapping_add(offsets[0][j]);
                    let v1 = e[1].wrapping_add(offsets[1][j]);
                    let v2 = e[2].wrapping_add(offsets[2][j]);
                    let [_, w1, w2] = lanes.weights(&[v0, v1, v2]);
                    // Lanes past the box's last column may have wrapped: never covered.
                    covered[j] = lanes.covered(&[v0, v1, v2]) & (x + (j as i32) < count);
                    z[j] = f.depth(w1, w2);
                }
                passed += u64::from(depth.test_lanes(&mut target.depth, first + x as usize, &z, &covered));
                e = [0, 1, 2].map(|k| e[k].wrapping_add(group_step[k]));
                x += N as i32;
            }
            row = [0, 1, 2].map(|k| row[k].wrapping_add(lanes.step_y[k]));
        }
        passed
    }

    /// [`Coverage::fill`] for a [`Shader::BATCHED`] shader: the same fragments, in the same order, depth-tested
    /// alike, gathered with their interpolation weights into `batch` and shaded with [`Shader::shade_batch`]
    /// whenever it fills. `edges` are the triangle's, in `i64` or, where they fit, in `i32` ([`EdgeLanes`]).
    ///
    /// Its row walk repeats `fill`'s on purpose: sharing one walk through a closure made the per-pixel loop twice
    /// as slow (`cargo bench -p rastty-bench --bench render -- sphere_2_5k_phong_lambert_800x800`: fastest 13.4
    /// against 6.5 ms).
    ///
    /// With `CUTOUT` (a draw whose shader discards fragments) a fragment is pushed when it is nearer than the
    /// stored depth, which is written only at [`shade_batch`], for the fragments kept.
    ///
    /// Out of line where it has two kinds of edges ([`NARROW`]): inlined, each kind was copied into each of the draw
    /// loop's calls (on the firmware, 12 KB more code).
    #[cfg_attr(target_pointer_width = "64", inline(always))]
    #[cfg_attr(not(target_pointer_width = "64"), inline(never))]
    fn fill_batched<const CUTOUT: bool, W, S, I, Z, C, D, M>(
        &self,
        edges: &W,
        stages: &Stages<'_, S, I, Z>,
        face: &S::Face,
        varyings: [&S::Varyings; 3],
        batch: &mut FragmentBatch<S::Varyings, S::Face>,
        target: &mut Target<C, D, M>,
    ) -> u64
    where
        W: CentreEdges,
        S: Shader,
        I: Interpolator,
        Z: DepthStage,
        C: ColorBuffer,
        D: DepthBuffer,
        M: VertexMemory,
    {
        let f = &self.frame;
        let setup = stages.interpolator.setup(f.inv_w, f.inv_area);
        let steps = stages.fraction_steps(&setup, &self.edges);
        let [v0, v1, v2] = oriented(f.swapped, varyings);
        batch.start_triangle([*v0, v1.sub(v0), v2.sub(v0)], *face, f.front_facing, steps);
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let mut shaded = 0u64;
        for y in f.y0..=f.y1 {
            let mut e = edges.at(f.x0, y);
            let mut x = f.x0;
            while x <= f.x1 && !edges.covered(&e) {
                e = edges.step(e);
                x += 1;
            }
            let base = (y - row0) as usize * width;
            while x <= f.x1 && edges.covered(&e) {
                let ef = edges.weights(&e);
                let z = f.depth(ef[1], ef[2]);
                let index = base + x as usize;
                let passed = if CUTOUT {
                    stages.depth.nearer(&target.depth, index, z)
                } else {
                    stages.depth.test(&mut target.depth, index, z)
                };
                if passed {
                    let fractions = stages.interpolator.fractions(&setup, ef);
                    if !CUTOUT {
                        shaded += 1;
                    }
                    if batch.push(x as u32, y as u32, z, fractions, index) {
                        shaded += shade_batch(stages, batch, target);
                    }
                }
                e = edges.step(e);
                x += 1;
            }
        }
        shaded
    }
}

/// Shades `batch`'s fragments with the stages' shader, writes their colours in the order they were pushed, and
/// empties it. In a cut-out draw the fragments kept are found first (a batch with none is not shaded), and only
/// those that still pass the depth test (against the depths written by those before them) are written, depth and
/// colour; their number is returned (the fragments a cut-out draw counts); 0 otherwise (the others are counted
/// when pushed). On a multisampled target a fragment's colour goes to its samples (in a cut-out draw, to those
/// that pass).
///
/// Not inlined: it runs once per batch, and the draw loop calls it from three places (on the firmware its code
/// is 4.2 KB).
#[inline(never)]
pub(crate) fn shade_batch<S, I, Z, C, D, M>(
    stages: &Stages<'_, S, I, Z>,
    batch: &mut FragmentBatch<S::Varyings, S::Face>,
    target: &mut Target<C, D, M>,
) -> u64
where
    S: Shader,
    Z: DepthStage,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    let mut colors = [Vec3::ZERO; BATCH_SIZE];
    batch.resolve();
    let written = if S::CUTOUT && stages.cutout {
        let mut keep = [false; BATCH_SIZE];
        stages.shader.kept_batch(batch, &mut keep);
        // A batch with nothing kept (a draw cut out whole, a clear stretch of the map) is not shaded.
        if keep[..batch.len()].contains(&true) {
            stages.shader.shade_batch(batch, &mut colors);
        }
        if target.samples() != Samples::One {
            let written = multisample::write_batch(&stages.depth, batch, Some(&keep), &colors, target);
            batch.clear();
            return written;
        }
        let depths = batch.depths();
        let mut written = 0;
        for (i, &index) in batch.indices().iter().enumerate() {
            if keep[i] && stages.depth.test(&mut target.depth, index, depths[i]) {
                target.color.write(index, colors[i]);
                written += 1;
            }
        }
        written
    } else {
        stages.shader.shade_batch(batch, &mut colors);
        if target.samples() == Samples::One {
            for (&index, &color) in batch.indices().iter().zip(&colors) {
                target.color.write(index, color);
            }
        } else {
            multisample::write_batch(&stages.depth, batch, None, &colors, target);
        }
        0
    };
    batch.clear();
    written
}
