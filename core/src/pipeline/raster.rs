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

use super::edges::{CentreEdges, DynamicEdges, Edges, FixedEdges, FloatEdges, NarrowEdges};
use super::fragment_stage::{FragmentStage, Writes, one_at_a_time};
use super::fragments::Fragments;
use super::interpolator::{Affine, DynamicInterpolator, Interpolator, PerspectiveCorrect};
use super::slopes::FractionSteps;
use super::{Cull, Fragment, Interpolation, Winding};
use crate::camera::Viewport;
use crate::math::{Lanes, Vec4, float};
use crate::target::{
    ColorBuffer, DEPTH_LANES, DepthBuffer, DepthView, SAMPLE_REACH, Samples, Target, TargetView, VertexMemory,
    clamp_depth,
};

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
        let fixed = |p: &Snapped| (p.x, p.y);
        let (a, b, c) = (fixed(&v[0]), fixed(&v[1]), fixed(&v[2]));
        // Coordinates are within ±2^24 (`SNAP_LIMIT_PX`), so their differences fit `i32`, and each product of two is
        // one 32 x 32 -> 64-bit multiply (on a 32-bit target one instruction, where an `i64` product takes three).
        let wide = |p: i32, q: i32| i64::from(p) * i64::from(q);
        // Twice the signed area in fixed-point units.
        let area = wide(b.0 - a.0, c.1 - a.1) - wide(b.1 - a.1, c.0 - a.0);
        if area == 0 {
            return Setup::Degenerate;
        }
        let Some(front_facing) = self.facing(area > 0) else { return Setup::Culled };

        let shift = self.shift;
        let half = 1i32 << (shift - 1);
        // Pixel centres inside the bounding box widened by the samples' reach (none with one sample): i with
        // (i << shift) + half in [min - reach, max + reach]. (Rounded up, the reach may take in a pixel none of whose
        // samples is inside: the pixel loop tests each.)
        let reach = self.reach.0;
        let min = |p: i32, q: i32, r: i32| i64::from(p.min(q).min(r));
        let max = |p: i32, q: i32, r: i32| i64::from(p.max(q).max(r));
        let (min_x, max_x) = (min(a.0, b.0, c.0) - reach, max(a.0, b.0, c.0) + reach);
        let (min_y, max_y) = (min(a.1, b.1, c.1) - reach, max(a.1, b.1, c.1) + reach);
        let half_wide = i64::from(half);
        let first_centre = |lo: i64| ((lo - half_wide + (1 << shift) - 1) >> shift) as i32;
        let last_centre = |hi: i64| ((hi - half_wide) >> shift) as i32;
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
            edges.origin[k] = wide(dx, half - p.1) - wide(dy, half - p.0) + edges.bias[k];
            edges.step_x[k] = -i64::from(dy) << shift;
            edges.step_y[k] = i64::from(dx) << shift;
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
#[derive(Clone, Copy, Debug)]
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
#[derive(Clone, Copy, Debug)]
pub(crate) struct Coverage<E> {
    edges: E,
    frame: Frame,
}

impl<E: Edges> Coverage<E> {
    /// The triangle as the pixel loops read it.
    #[inline(always)]
    fn covered(&self) -> Covered<'_, E> {
        Covered { edges: &self.edges, frame: &self.frame }
    }

    /// [`Covered::covers_a_centre`].
    #[inline(always)]
    pub fn covers_a_centre(&self) -> bool {
        self.covered().covers_a_centre()
    }

    /// The first and last rows of the triangle's bounding box, clamped to the target's rows.
    #[inline(always)]
    pub fn rows(&self) -> (i32, i32) {
        (self.frame.y0, self.frame.y1)
    }

    /// Per-vertex values given in input order, in the triangle's oriented order (see [`oriented`]).
    #[inline(always)]
    pub fn oriented<T: Copy>(&self, values: [T; 3]) -> [T; 3] {
        oriented(self.frame.swapped, values)
    }
}

/// The depth format of the pixel loop compiled into each draw loop ([`EdgeSetup::fill_inline`]): `f32` where there
/// are 64-bit registers (a desktop's), `u16` elsewhere (a microcontroller's, where memory is scarce). A target with
/// another depth buffer draws through the shared loops, which test its [`DepthView`] pixel by pixel. One format,
/// not one loop per format: the loop is compiled once per shader.
#[cfg(target_pointer_width = "64")]
pub(crate) type InlineDepth = f32;
/// See the 64-bit definition.
#[cfg(not(target_pointer_width = "64"))]
pub(crate) type InlineDepth = u16;

/// How a draw sets up its triangles: exact fixed point ([`FixedPoint`]) or plain `f32` ([`FloatingPoint`]), the
/// type the draw loop is compiled for.
pub(crate) trait EdgeSetup: Copy {
    /// The edge functions it produces.
    type Edges: Edges;
    /// Area, facing, bounding box and edge functions of a triangle.
    fn setup(raster: &Rasterizer, v: [Snapped; 3]) -> Setup<Self::Edges>;
    /// The draw's pixel loop for its edge functions.
    fn pixel_loop(loops: &PixelLoops) -> Fill<Self::Edges>;
    /// Whether draws in this arithmetic may run the pixel loop compiled into their draw loop
    /// ([`Self::fill_inline`]): only the default's, exact fixed point.
    const INLINE: bool;

    /// The pixel loop of a draw with exact edges, one sample per pixel and perspective-correct interpolation that
    /// discards nothing, or of a depth-only draw (`!shaded`), compiled into the caller for a depth buffer of
    /// [`InlineDepth`]: its fragment stage `St` is called directly and its depth buffer tested without a branch on
    /// the format. What most draws run. `None`, having drawn nothing, for a target with another depth buffer.
    #[inline(always)]
    fn fill_inline<St: FragmentStage + ?Sized>(
        coverage: &Coverage<Self::Edges>,
        pass: &mut Pass<'_, St>,
        shaded: bool,
    ) -> Option<u64> {
        let view = core::mem::replace(&mut pass.target.depth, DepthView::Off);
        let mut depth = match <&mut [InlineDepth]>::try_from(view) {
            Ok(depth) => depth,
            Err(view) => {
                pass.target.depth = view;
                return None;
            }
        };
        let fragments = if shaded {
            fill_single::<_, PerspectiveCorrect, false, St, _>(coverage.covered(), pass, &mut depth)
        } else {
            fill_depth_only::<_, St, _>(coverage.covered(), pass, &mut depth)
        };
        pass.target.depth = depth.into();
        Some(fragments)
    }

    /// Runs the draw's pixel loop over `coverage`: the fragments it counts.
    #[inline(always)]
    fn fill(loops: &PixelLoops, coverage: &Coverage<Self::Edges>, pass: &mut Pass<'_, dyn FragmentStage + '_>) -> u64 {
        Self::pixel_loop(loops)(coverage.covered(), pass)
    }
}

/// Exact fixed point ([`super::EdgeArithmetic::FixedPoint`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FixedPoint;

impl EdgeSetup for FixedPoint {
    type Edges = FixedEdges;
    const INLINE: bool = true;
    #[inline(always)]
    fn setup(raster: &Rasterizer, v: [Snapped; 3]) -> Setup<FixedEdges> {
        raster.setup_fixed(v)
    }
    #[inline(always)]
    fn pixel_loop(loops: &PixelLoops) -> Fill<FixedEdges> {
        loops.fixed
    }
}

/// Plain `f32` ([`super::EdgeArithmetic::Float`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FloatingPoint;

impl EdgeSetup for FloatingPoint {
    type Edges = FloatEdges;
    const INLINE: bool = false;
    #[inline(always)]
    fn setup(raster: &Rasterizer, v: [Snapped; 3]) -> Setup<FloatEdges> {
        raster.setup_float(v)
    }
    #[inline(always)]
    fn pixel_loop(loops: &PixelLoops) -> Fill<FloatEdges> {
        loops.float
    }
}

/// A triangle as a pixel loop reads it: its edge functions in one arithmetic, and its frame.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Covered<'c, E> {
    edges: &'c E,
    frame: &'c Frame,
}

/// What a draw's pixel loops work with besides the triangle: its target, the batch they fill and the fragment
/// stage that shades it when full (no batch for a depth-only draw), and the draw's settings they read. `St` is
/// the stage: the draw's own type, seen by the pixel loops as `dyn FragmentStage`.
pub(crate) struct Pass<'t, St: ?Sized> {
    /// The target, through its views.
    pub target: TargetView<'t>,
    /// The batch, or `None` for a depth-only draw ([`super::Shader::FRAGMENT_STAGE`]).
    pub fragments: Option<Fragments>,
    /// The draw's interpolation (read by the general path's interpolator, per pixel).
    pub interpolation: Interpolation,
    /// The fragment stage discards fragments ([`super::Shader::cutout`]): depth is compared when a fragment is
    /// pushed and tested and written when it is kept.
    pub cutout: bool,
    /// The fragment stage reads its varyings' slopes ([`super::Shader::slopes`]).
    pub slopes: bool,
    /// The fragment stage.
    pub stage: St,
}

/// A triangle's pixel loop, shared by every shader: covered pixel centres (or samples), depth test, fragments into
/// the batch, which goes to the fragment stage through a `dyn` reference. The fragments it counts.
pub(crate) type Fill<E> = for<'c, 'p, 't, 's> fn(Covered<'c, E>, &'p mut Pass<'t, dyn FragmentStage + 's>) -> u64;

/// The pixel loops of a draw, one for each edge arithmetic, chosen once per draw: for its interpolation, its
/// target's samples and its fragment stage (none, shading, or shading what it keeps), or the general loops that
/// decide the edge arithmetic and the interpolation per pixel. They do not depend on the shader or the buffers,
/// so each is compiled once whatever a program draws.
#[derive(Clone, Copy)]
pub(crate) struct PixelLoops {
    fixed: Fill<FixedEdges>,
    float: Fill<FloatEdges>,
}

/// What a draw's fragments go through after the depth test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shading {
    /// Nothing: a depth-only draw.
    DepthOnly,
    /// The fragment stage.
    Shaded,
    /// The fragment stage, discarding some ([`super::Shader::cutout`]).
    CutOut,
}

impl PixelLoops {
    /// The loops specialised for a draw with `interpolation` into a target with `samples` per pixel.
    pub fn specialised(interpolation: Interpolation, samples: Samples, shading: Shading) -> Self {
        use {Interpolation as I, Shading as S};
        match (samples, shading, interpolation) {
            (_, S::DepthOnly, _) => Self { fixed: shared_depth_only, float: shared_depth_only },
            (Samples::Four, _, I::PerspectiveCorrect) => Self::multisample::<PerspectiveCorrect>(),
            (Samples::Four, _, I::Affine) => Self::multisample::<Affine>(),
            (Samples::One, S::Shaded, I::PerspectiveCorrect) => Self::single::<PerspectiveCorrect, false>(),
            (Samples::One, S::Shaded, I::Affine) => Self::single::<Affine, false>(),
            (Samples::One, S::CutOut, I::PerspectiveCorrect) => Self::single::<PerspectiveCorrect, true>(),
            (Samples::One, S::CutOut, I::Affine) => Self::single::<Affine, true>(),
        }
    }

    /// The general loops: edge arithmetic and interpolation decided per pixel, for a draw into a target with
    /// `samples` per pixel.
    pub fn general(samples: Samples, shading: Shading) -> Self {
        match (samples, shading) {
            (_, Shading::DepthOnly) => Self { fixed: general_depth_only, float: general_depth_only },
            (Samples::Four, _) => Self { fixed: general_multisample, float: general_multisample },
            (Samples::One, Shading::Shaded) => {
                Self { fixed: general_single::<_, false>, float: general_single::<_, false> }
            }
            (Samples::One, Shading::CutOut) => {
                Self { fixed: general_single::<_, true>, float: general_single::<_, true> }
            }
        }
    }

    fn single<I: Interpolator, const CUTOUT: bool>() -> Self {
        Self { fixed: shared_single::<_, I, CUTOUT>, float: shared_single::<_, I, CUTOUT> }
    }

    fn multisample<I: Interpolator>() -> Self {
        Self { fixed: shared_multisample::<_, I>, float: shared_multisample::<_, I> }
    }
}

/// [`fill_single`] for every shader, its fragment stage seen as `dyn FragmentStage`.
fn shared_single<E: Edges, I: Interpolator, const CUTOUT: bool>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, dyn FragmentStage + '_>,
) -> u64 {
    with_depth_view(pass, |pass, depth| fill_single::<E, I, CUTOUT, _, _>(c, pass, depth))
}

/// [`fill_multisample`] for every shader, its fragment stage seen as `dyn FragmentStage`.
fn shared_multisample<E: Edges, I: Interpolator>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, dyn FragmentStage + '_>,
) -> u64 {
    fill_multisample::<E, I, _>(c, pass)
}

/// [`fill_depth_only`] for every shader ([`fill_multisample`] on a multisampled target).
fn shared_depth_only<E: Edges>(c: Covered<'_, E>, pass: &mut Pass<'_, dyn FragmentStage + '_>) -> u64 {
    if c.frame.samples != Samples::One {
        return fill_multisample::<E, PerspectiveCorrect, _>(c, pass);
    }
    with_depth_view(pass, |pass, depth| fill_depth_only::<E, _, _>(c, pass, depth))
}

/// Runs a pixel loop with the target's depth buffer, as its [`DepthView`], lent to it apart from the target.
#[inline(always)]
fn with_depth_view<'t, St: ?Sized>(
    pass: &mut Pass<'t, St>,
    fill: impl FnOnce(&mut Pass<'t, St>, &mut DepthView<'t>) -> u64,
) -> u64 {
    let mut depth = core::mem::replace(&mut pass.target.depth, DepthView::Off);
    let fragments = fill(pass, &mut depth);
    pass.target.depth = depth;
    fragments
}

/// [`fill_single`] with the edge arithmetic and the interpolation decided per pixel.
fn general_single<E: Edges + Into<DynamicEdges>, const CUTOUT: bool>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, dyn FragmentStage + '_>,
) -> u64 {
    let edges = (*c.edges).into();
    let c = Covered { edges: &edges, frame: c.frame };
    with_depth_view(pass, |pass, depth| fill_single::<_, DynamicInterpolator, CUTOUT, _, _>(c, pass, depth))
}

/// [`fill_multisample`] with the edge arithmetic and the interpolation decided per pixel.
fn general_multisample<E: Edges + Into<DynamicEdges>>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, dyn FragmentStage + '_>,
) -> u64 {
    let edges = (*c.edges).into();
    fill_multisample::<_, DynamicInterpolator, _>(Covered { edges: &edges, frame: c.frame }, pass)
}

/// [`fill_depth_only`] with the edge arithmetic decided per pixel.
fn general_depth_only<E: Edges + Into<DynamicEdges>>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, dyn FragmentStage + '_>,
) -> u64 {
    let edges = (*c.edges).into();
    let c = Covered { edges: &edges, frame: c.frame };
    if c.frame.samples != Samples::One {
        return fill_multisample::<_, PerspectiveCorrect, _>(c, pass);
    }
    with_depth_view(pass, |pass, depth| fill_depth_only::<_, _, _>(c, pass, depth))
}

/// Largest bounding box, in pixel centres, that [`Covered::covers_a_centre`] tests centre by centre.
const SMALL_BOX: i64 = 4;

impl<E: Edges> Covered<'_, E> {
    /// False when the triangle covers none of the pixel centres (the samples, on a multisampled target) of its
    /// bounding box in the target, which is tested centre by centre for a box of at most [`SMALL_BOX`] pixels; true
    /// otherwise. A dense mesh's triangles are mostly smaller than a pixel and many cover no centre: this lets them
    /// skip their varyings and set-up.
    #[inline(always)]
    fn covers_a_centre(self) -> bool {
        let (f, edges) = (self.frame, self.edges);
        if i64::from(f.x1 - f.x0 + 1) * i64::from(f.y1 - f.y0 + 1) > SMALL_BOX {
            return true;
        }
        if f.samples != Samples::One {
            return self.covers_a_sample();
        }
        for y in f.y0..=f.y1 {
            let mut e = edges.at(f.x0, y);
            for _ in f.x0..=f.x1 {
                if edges.covered(&e) {
                    return true;
                }
                e = edges.step(e);
            }
        }
        false
    }

    /// Starts the triangle in the batch: its facing, and the steps of its weight fractions when the draw reads
    /// slopes. Returns the interpolator's set-up for it.
    #[inline(always)]
    fn start<I: Interpolator, St: FragmentStage + ?Sized>(self, interpolator: &I, pass: &mut Pass<'_, St>) -> I::Setup {
        let f = self.frame;
        let setup = interpolator.setup(f.inv_w, f.inv_area);
        if let Some(fragments) = &mut pass.fragments {
            let steps = if pass.slopes {
                interpolator.fraction_steps(&setup, self.edges.steps())
            } else {
                FractionSteps::default()
            };
            fragments.start_triangle(f.front_facing, steps);
        }
        setup
    }
}

/// The pixel loop of a draw with a fragment stage into a target of one sample per pixel: every covered pixel
/// centre in the target's rows, depth-tested, gathered with its interpolation weights into the batch, which is
/// shaded and written whenever it fills; the caller shades what is left at the end of the draw. Returns the
/// fragments that passed the depth test (in a cut-out draw, the fragments written when a batch was shaded).
///
/// With `CUTOUT` (a draw whose shader discards fragments) a fragment is pushed when it is nearer than the stored
/// depth, which is written only when its batch is shaded, for the fragments kept. Where a batch holds one fragment,
/// a draw that neither discards fragments nor reads slopes hands each fragment to the fragment stage as it passes
/// ([`FragmentStage::one`]) rather than through the batch.
///
/// Where a target has no 64-bit registers, the edge values are walked in `i32` where they fit (the same values).
#[inline(always)]
pub(super) fn fill_single<E: Edges, I: Interpolator, const CUTOUT: bool, St: FragmentStage + ?Sized, D: DepthBuffer>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, St>,
    depth: &mut D,
) -> u64 {
    let f = c.frame;
    if NARROW && let Some(narrow) = c.edges.narrow(f.x0, f.x1, f.y0, f.y1) {
        return c.walk_batched::<_, I, CUTOUT, St, D>(&narrow, pass, depth);
    }
    c.walk_batched::<_, I, CUTOUT, St, D>(c.edges, pass, depth)
}

/// The pixel loop of a depth-only draw into a target of one sample per pixel, with its depth buffer `depth`: the
/// depth test alone, several pixels of a row at a time where the edge values fit `i32` ([`Covered::fill_depth`]),
/// else pixel by pixel. Returns the pixels that passed.
#[inline(always)]
pub(super) fn fill_depth_only<E: Edges, St: FragmentStage + ?Sized, D: DepthBuffer>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, St>,
    depth: &mut D,
) -> u64 {
    let (f, edges) = (c.frame, c.edges);
    let width = pass.target.width() as usize;
    let row0 = pass.target.rows().start as i32;
    if let Some(narrow) = edges.narrow(f.x0, f.x1, f.y0, f.y1) {
        return c.fill_depth(narrow, width, row0, depth);
    }
    let mut passed = 0u64;
    let mut row = edges.at(f.x0, f.y0);
    for y in f.y0..=f.y1 {
        let mut e = row;
        if y < f.y1 {
            row = edges.down(row, f.x0, y);
        }
        let mut x = f.x0;
        // The covered centres of a row are contiguous (a triangle is convex): skip to them, run, stop.
        while x <= f.x1 && !edges.covered(&e) {
            e = edges.step(e);
            x += 1;
        }
        let base = (y - row0) as usize * width;
        while x <= f.x1 && edges.covered(&e) {
            let ef = edges.weights(&e);
            if depth.test_and_set(base + x as usize, f.depth(ef[1], ef[2])) {
                passed += 1;
            }
            e = edges.step(e);
            x += 1;
        }
    }
    passed
}

pub(super) use multisample::fill_multisample;

impl<E: Edges> Covered<'_, E> {
    /// [`fill_depth_only`] with the edge functions narrowed to `i32` (`edges`): the depth test alone, [`DEPTH_LANES`] pixels of a
    /// row at a time across the bounding box, with coverage, weights and depth worked out per lane exactly as the
    /// pixel walk works them out per pixel (the same depths reach the same pixels). The lanes are one branch-free
    /// loop, which the compiler widens to SIMD.
    #[inline(always)]
    fn fill_depth<D: DepthBuffer>(self, edges: NarrowEdges, width: usize, row0: i32, depth: &mut D) -> u64 {
        const N: usize = DEPTH_LANES;
        let f = self.frame;
        let count = f.x1 - f.x0 + 1;
        // Lane j of a group lies j pixels right of its first: its values are the first's plus j steps.
        let offsets: [Lanes<i32, N>; 3] =
            core::array::from_fn(|k| Lanes::from_fn(|j| edges.step_x[k].wrapping_mul(j as i32)));
        let group_step = edges.step_x.map(|s| s.wrapping_mul(N as i32));
        let mut row = edges.origin;
        let mut passed = 0u64;
        for y in f.y0..=f.y1 {
            let first = (y - row0) as usize * width + f.x0 as usize;
            let mut e = row;
            let mut x = 0;
            while x < count {
                let (mut z, mut covered) = (Lanes::<f32, N>::ZERO, Lanes::splat(false));
                for j in 0..N {
                    let v0 = e[0].wrapping_add(offsets[0][j]);
                    let v1 = e[1].wrapping_add(offsets[1][j]);
                    let v2 = e[2].wrapping_add(offsets[2][j]);
                    let [_, w1, w2] = edges.weights(&[v0, v1, v2]);
                    // Lanes past the box's last column may have wrapped: never covered.
                    covered[j] = edges.covered(&[v0, v1, v2]) & (x + (j as i32) < count);
                    z[j] = f.depth(w1, w2);
                }
                passed += u64::from(depth.test_and_set_lanes(first + x as usize, &z, &covered));
                e = [0, 1, 2].map(|k| e[k].wrapping_add(group_step[k]));
                x += N as i32;
            }
            row = [0, 1, 2].map(|k| row[k].wrapping_add(edges.step_y[k]));
        }
        passed
    }

    /// [`fill_single`]'s walk with the triangle's edges as `edges` (in `i64`, or in `i32` where they fit,
    /// [`NarrowEdges`]): the covered centres of each row in order, each depth-tested (in a cut-out draw, compared)
    /// and pushed into the batch, which is handed to the fragment stage whenever it fills (or handed over one at a
    /// time, [`one_at_a_time`]).
    ///
    /// Out of line where it has two kinds of edges ([`NARROW`]): inlined, each kind was copied into each of the
    /// draw loop's calls (on the firmware, 12 KB more code).
    #[cfg_attr(target_pointer_width = "64", inline(always))]
    #[cfg_attr(not(target_pointer_width = "64"), inline(never))]
    fn walk_batched<W: CentreEdges, I: Interpolator, const CUTOUT: bool, St: FragmentStage + ?Sized, D: DepthBuffer>(
        self,
        edges: &W,
        pass: &mut Pass<'_, St>,
        depth: &mut D,
    ) -> u64 {
        let interpolator = I::new(pass.interpolation);
        let setup = self.start(&interpolator, pass);
        let f = self.frame;
        let Pass { target, fragments: Some(fragments), stage, .. } = pass else { return 0 };
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let samples = target.samples();
        // Decided once per triangle (a constant false where batches hold several fragments).
        let one = one_at_a_time(CUTOUT, pass.slopes) && samples == Samples::One;
        // At most one fragment per pixel of the frame, which has fewer than 2^32.
        let mut shaded = 0u32;
        // Each row's first values from the last row's by an addition (for exact edges), not worked out anew; as
        // a loop over `y`, which compiles to less than an iterator of rows.
        let mut row = edges.at(f.x0, f.y0);
        for y in f.y0..=f.y1 {
            let mut e = row;
            if y < f.y1 {
                row = edges.down(row, f.x0, y);
            }
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
                let passed = if CUTOUT { depth.nearer(index, z) } else { depth.test_and_set(index, z) };
                if passed {
                    let fractions = interpolator.fractions(&setup, ef);
                    if one {
                        let fragment = Fragment { x: x as u32, y: y as u32, depth: z, front_facing: f.front_facing };
                        stage.one(&fragment, fractions, index, &mut target.color);
                    } else if fragments.push(x as u32, y as u32, z, fractions, index) {
                        // A cut-out draw counts its fragments as written, and lends the fragment stage its depth
                        // buffer for those it keeps ([`Writes`]); the others count them as they pass.
                        if CUTOUT {
                            let depth = Some(&mut depth.view());
                            shaded +=
                                stage.flush(fragments, Writes { color: &mut target.color, depth, samples }) as u32;
                        } else {
                            stage.flush(fragments, Writes { color: &mut target.color, depth: None, samples });
                        }
                    }
                    if !CUTOUT {
                        shaded += 1;
                    }
                }
                e = edges.step(e);
                x += 1;
            }
        }
        u64::from(shaded)
    }
}
