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

use super::clip::ClipVertex;
use super::depth_stage::DepthStage;
use super::interpolator::Interpolator;
use super::{Cull, Fragment, Shader, Varyings, Winding};
use crate::camera::Viewport;
use crate::math::float;
use crate::target::{ColorBuffer, DepthBuffer, Target};

/// A vertex in screen space, snapped to the sub-pixel grid.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScreenVertex<V> {
    /// Fixed-point x, in units of `2^-(S+1)` pixel.
    x: i64,
    /// Fixed-point y (down), same units.
    y: i64,
    /// NDC depth.
    z: f32,
    /// `1 / w`.
    inv_w: f32,
    var: V,
}

/// Largest magnitude, in pixels, that a snapped coordinate is clamped to: twice the guard band, so clamping never
/// happens to a clipped triangle and merely bounds the integers if rounding ever pushed a vertex out.
const SNAP_LIMIT_PX: f32 = 2.0 * super::clip::GUARD_BAND;

/// What became of one triangle (or clipped piece) at set-up.
pub(crate) enum Setup<V: Copy> {
    /// Zero area on the sub-pixel grid.
    Degenerate,
    /// Removed by face culling.
    Culled,
    /// Facing is fine but its bounding box holds no pixel centre of the target.
    Empty,
    /// Ready for the pixel loop.
    Ready(Triangle<V>),
}

/// Per-draw rasterizer settings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rasterizer {
    viewport: Viewport,
    /// `2^S`.
    scale: f32,
    /// `S + 1`: pixels to fixed-point units.
    shift: u32,
    width: i32,
    row0: i32,
    row1: i32,
    cull: Cull,
    front_face: Winding,
}

impl Rasterizer {
    pub fn new<C: ColorBuffer, D: DepthBuffer>(
        target: &Target<C, D>,
        subpixel_bits: u8,
        cull: Cull,
        front_face: Winding,
    ) -> Self {
        let rows = target.rows();
        Self {
            viewport: Viewport::full(target.width(), target.height()),
            scale: (1u32 << subpixel_bits) as f32,
            shift: u32::from(subpixel_bits) + 1,
            width: target.width() as i32,
            row0: rows.start as i32,
            row1: rows.end as i32,
            cull,
            front_face,
        }
    }

    /// Divides by `w`, maps to the screen and snaps. `None` when `w <= 0` (only possible for the degenerate
    /// all-zero clip-space point once clipping is done).
    #[inline(always)]
    pub fn snap<V: Copy>(&self, v: &ClipVertex<V>) -> Option<ScreenVertex<V>> {
        let w_positive = v.pos.w > 0.0; // false for NaN too
        if !w_positive {
            return None;
        }
        let s = self.viewport.clip_to_screen(v.pos);
        let fixed = |p: f32| {
            let p = float::clamp(p, -SNAP_LIMIT_PX, SNAP_LIMIT_PX) * self.scale;
            i64::from(float::floor_to_i32(p + 0.5)) << 1
        };
        Some(ScreenVertex { x: fixed(s.x), y: fixed(s.y), z: s.z, inv_w: 1.0 / v.pos.w, var: v.var })
    }

    /// Area, facing and bounding box of a triangle, and if it has any pixels, everything the pixel loop needs.
    #[inline(always)]
    pub fn setup<V: Varyings>(&self, v: [&ScreenVertex<V>; 3]) -> Setup<V> {
        let [mut a, mut b, c] = v;
        // Twice the signed area in fixed-point units. Positive means clockwise on the y-up NDC plane.
        let area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if area == 0 {
            return Setup::Degenerate;
        }
        let ccw = area < 0;
        let front_facing = ccw == (self.front_face == Winding::CounterClockwise);
        match self.cull {
            Cull::Back if !front_facing => return Setup::Culled,
            Cull::Front if front_facing => return Setup::Culled,
            _ => {}
        }
        if ccw {
            core::mem::swap(&mut a, &mut b);
        }
        let area = area.abs();

        let shift = self.shift;
        let half = 1i64 << (shift - 1);
        // Pixel centres inside the bounding box: i with (i << shift) + half in [min, max].
        let (min_x, max_x) = (a.x.min(b.x).min(c.x), a.x.max(b.x).max(c.x));
        let (min_y, max_y) = (a.y.min(b.y).min(c.y), a.y.max(b.y).max(c.y));
        let first_centre = |lo: i64| ((lo - half + (1 << shift) - 1) >> shift) as i32;
        let last_centre = |hi: i64| ((hi - half) >> shift) as i32;
        let x0 = first_centre(min_x).max(0);
        let x1 = last_centre(max_x).min(self.width - 1);
        let y0 = first_centre(min_y).max(self.row0);
        let y1 = last_centre(max_y).min(self.row1 - 1);
        if x0 > x1 || y0 > y1 {
            return Setup::Empty;
        }

        // Edge k is the one opposite vertex k; its function is k's barycentric coordinate times `area`.
        let verts = [a, b, c];
        let start_x = (i64::from(x0) << shift) + half;
        let start_y = (i64::from(y0) << shift) + half;
        let mut edge = [0i64; 3];
        let mut step_x = [0i64; 3];
        let mut step_y = [0i64; 3];
        let mut bias = [0i64; 3];
        for k in 0..3 {
            let (p, q) = (verts[(k + 1) % 3], verts[(k + 2) % 3]);
            let (dx, dy) = (q.x - p.x, q.y - p.y);
            // Inside is to the right of p->q in y-down screen space; the edge is "left" when y decreases along
            // it and "top" when it is horizontal running to +x.
            let top_left = dy < 0 || (dy == 0 && dx > 0);
            bias[k] = if top_left { 0 } else { -1 };
            edge[k] = dx * (start_y - p.y) - dy * (start_x - p.x) + bias[k];
            step_x[k] = -dy << shift;
            step_y[k] = dx << shift;
        }

        let inv_area = 1.0 / area as f32;
        Setup::Ready(Triangle {
            edge,
            step_x,
            step_y,
            bias,
            x0,
            x1,
            y0,
            y1,
            front_facing,
            z0: a.z,
            dz1: (b.z - a.z) * inv_area,
            dz2: (c.z - a.z) * inv_area,
            inv_w: [a.inv_w, b.inv_w, c.inv_w],
            inv_area,
            var0: a.var,
            var_d1: b.var.sub(&a.var),
            var_d2: c.var.sub(&a.var),
        })
    }
}

/// A triangle ready for the pixel loop.
pub(crate) struct Triangle<V> {
    /// Biased edge functions at the first pixel centre of the bounding box: a centre is covered when all three
    /// are `>= 0`.
    edge: [i64; 3],
    step_x: [i64; 3],
    step_y: [i64; 3],
    /// The fill-rule bias folded into `edge` (0 for top-left edges, -1 otherwise).
    bias: [i64; 3],
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
    front_facing: bool,
    z0: f32,
    /// Depth change per unit of edge function 1 and 2.
    dz1: f32,
    dz2: f32,
    inv_w: [f32; 3],
    inv_area: f32,
    var0: V,
    var_d1: V,
    var_d2: V,
}

/// The per-draw stages the pixel loop is specialised on.
pub(crate) struct Stages<'s, S, I, Z> {
    pub shader: &'s S,
    pub interpolator: I,
    pub depth: Z,
}

impl<V: Varyings> Triangle<V> {
    /// Visits every covered pixel centre in the target's rows: depth test, interpolation, fragment stage, write.
    /// Returns the number of fragments shaded.
    #[inline(always)]
    pub fn fill<S, I, Z, C, D>(&self, stages: &Stages<'_, S, I, Z>, face: &S::Face, target: &mut Target<C, D>) -> u64
    where
        S: Shader<Varyings = V>,
        I: Interpolator,
        Z: DepthStage,
        C: ColorBuffer,
        D: DepthBuffer,
    {
        let setup = stages.interpolator.setup(self.inv_w, self.inv_area);
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let mut shaded = 0u64;
        let mut row = self.edge;
        for y in self.y0..=self.y1 {
            let mut e = row;
            let mut x = self.x0;
            // The covered centres of a row are contiguous (a triangle is convex): skip to them, run, stop.
            while x <= self.x1 && (e[0] | e[1] | e[2]) < 0 {
                e = add3(e, self.step_x);
                x += 1;
            }
            let base = (y - row0) as usize * width;
            while x <= self.x1 && (e[0] | e[1] | e[2]) >= 0 {
                // Unbiased edge values: >= 0 and summing to the area, so weights are a convex combination.
                let ef = [(e[0] - self.bias[0]) as f32, (e[1] - self.bias[1]) as f32, (e[2] - self.bias[2]) as f32];
                let z = self.z0 + ef[1] * self.dz1 + ef[2] * self.dz2;
                let index = base + x as usize;
                if stages.depth.test(&mut target.depth, index, z) {
                    let (w1, w2) = stages.interpolator.weights(&setup, ef);
                    let var = self.var0.interpolate(&self.var_d1, w1, &self.var_d2, w2);
                    let fragment = Fragment { x: x as u32, y: y as u32, depth: z, front_facing: self.front_facing };
                    let color = stages.shader.fragment(&fragment, face, &var);
                    target.color.write(index, color);
                    shaded += 1;
                }
                e = add3(e, self.step_x);
                x += 1;
            }
            row = add3(row, self.step_y);
        }
        shaded
    }
}

#[inline(always)]
fn add3(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
