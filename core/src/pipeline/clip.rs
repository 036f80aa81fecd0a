//! Homogeneous clipping: near and far planes, and a guard band for x and y.
//!
//! Clipping happens in clip space, before the perspective division, so no vertex is ever divided by `w <= 0`.
//! A triangle whose vertices lie inside the near and far planes and inside the guard band (a square of
//! ±[`GUARD_BAND`] pixels around the frame origin) goes to the rasterizer unclipped: its edges are exact there and
//! only the pixels inside the frame are visited. Anything larger is cut to the guard band, which keeps every
//! coordinate far inside the fixed-point range.
//!
//! Plane distances are computed exactly (as floating-point expansions, [`crate::math::exact`]), so the clipper
//! never puts a vertex on the wrong side, and an intersection carries only a few roundings relative to itself: a triangle whose
//! corners are 10^30 units out still crosses the view exactly where it should. Intersections are computed from
//! the inside vertex toward the outside one, so the two triangles that share an edge cut it at bit-identical points
//! and stay watertight (Sutherland and Hodgman, "Reentrant Polygon Clipping", CACM 1974; Blinn and Newell,
//! "Clipping using homogeneous coordinates", SIGGRAPH 1978).

use super::Varyings;
use crate::math::Vec4;
use crate::math::exact::Expansion;

/// Half the side of the guard band, in pixels.
///
/// Within ±16384 px an `f32` screen coordinate has a resolution of 2^-9 px or better, finer than the 2^-8 px
/// sub-pixel grid, so snapping is exact inside the band.
pub const GUARD_BAND: f32 = 16384.0;

/// A vertex after the vertex stage: clip-space position and varyings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ClipVertex<V> {
    pub pos: Vec4,
    pub var: V,
}

/// A half-space `a . (x, y, z, w) >= 0` of clip space.
#[derive(Clone, Copy, Debug)]
struct Plane([f32; 4]);

impl Plane {
    /// The signed distance `a . p`, exactly.
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    fn distance(&self, p: Vec4) -> Expansion {
        let a = self.0;
        Expansion::product(a[0], p.x)
            .add(&Expansion::product(a[1], p.y))
            .add(&Expansion::product(a[2], p.z))
            .add(&Expansion::product(a[3], p.w))
    }

    /// The point where the segment from `p` (distance `dp`) to `q` (distance `dq`, of the other sign) meets the
    /// plane: `(dp q - dq p) / (dp - dq)`, with numerator and denominator exact and rounded once each.
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    fn meet(p: Vec4, dp: &Expansion, q: Vec4, dq: &Expansion) -> Vec4 {
        let den = dp.sub(dq).value();
        let coord = |a: f32, b: f32| (dp.scale(f64::from(b)).sub(&dq.scale(f64::from(a))).value() / den) as f32;
        Vec4::new(coord(p.x, q.x), coord(p.y, q.y), coord(p.z, q.z), coord(p.w, q.w))
    }
}

/// Planes that clipping cuts against, in the order it cuts: near, far, and the guard band's four sides.
const CLIP_PLANES: usize = 6;

/// Outcode bits of the clipping planes (bits `0..CLIP_PLANES`).
pub(crate) const CLIP_MASK: u16 = (1 << CLIP_PLANES) - 1;

/// Most vertices a triangle can have after clipping: each plane adds at most one.
pub(crate) const MAX_CLIPPED: usize = 3 + CLIP_PLANES;

/// The clipping and rejection planes of one draw into one target.
///
/// Outcode bits 0..6 are the clipping planes (near, far, guard left, right, bottom, top); bits 6..10 only reject:
/// the frame's left and right edges and the target's bottom and top rows, each with one pixel of margin.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ClipVolume {
    /// NDC limits: guard x, guard y, frame x, band y (each low, high).
    limits: [f32; 8],
    planes: [Plane; CLIP_PLANES],
}

impl ClipVolume {
    /// The volume for a `width x height` frame of which rows `row0..row1` are being rendered.
    pub fn new(width: u32, height: u32, row0: u32, row1: u32) -> Self {
        let (w, h) = (width as f32, height as f32);
        // Screen x = (ndc + 1) * w / 2 and screen y = (1 - ndc) * h / 2, solved for ndc at the limits.
        let ndc_x = |sx: f32| 2.0 * sx / w - 1.0;
        let ndc_y = |sy: f32| 1.0 - 2.0 * sy / h;
        let (gx0, gx1) = (ndc_x(-GUARD_BAND), ndc_x(GUARD_BAND));
        let (gy0, gy1) = (ndc_y(GUARD_BAND), ndc_y(-GUARD_BAND));
        let (vx0, vx1) = (ndc_x(-1.0), ndc_x(w + 1.0));
        let (vy0, vy1) = (ndc_y(row1 as f32 + 1.0), ndc_y(row0 as f32 - 1.0));
        Self {
            limits: [gx0, gx1, gy0, gy1, vx0, vx1, vy0, vy1],
            planes: [
                Plane([0.0, 0.0, 1.0, 0.0]),  // near: z >= 0
                Plane([0.0, 0.0, -1.0, 1.0]), // far: z <= w
                Plane([1.0, 0.0, 0.0, -gx0]), // guard left: x >= gx0 w
                Plane([-1.0, 0.0, 0.0, gx1]), // guard right: x <= gx1 w
                Plane([0.0, 1.0, 0.0, -gy0]), // guard bottom: y >= gy0 w
                Plane([0.0, -1.0, 0.0, gy1]), // guard top: y <= gy1 w
            ],
        }
    }

    /// One bit per plane the point is outside of (see [`ClipVolume`] for the order).
    ///
    /// A fast, not exact, classification: the product `k w` is rounded, so a vertex within a rounding error of
    /// a plane may get either bit. That is safe: the clipper decides sides with exact distances, the guard band is
    /// far inside the fixed-point range, and a frame-edge bit only rejects triangles that cover no pixel centre.
    #[inline(always)]
    pub fn outcode(&self, p: Vec4) -> u16 {
        let [gx0, gx1, gy0, gy1, vx0, vx1, vy0, vy1] = self.limits;
        let Vec4 { x, y, z, w } = p;
        u16::from(z < 0.0)
            | u16::from(z > w) << 1
            | u16::from(x < gx0 * w) << 2
            | u16::from(x > gx1 * w) << 3
            | u16::from(y < gy0 * w) << 4
            | u16::from(y > gy1 * w) << 5
            | u16::from(x < vx0 * w) << 6
            | u16::from(x > vx1 * w) << 7
            | u16::from(y < vy0 * w) << 8
            | u16::from(y > vy1 * w) << 9
    }

    /// Clips a triangle against the clipping planes named in `mask` into a convex polygon (empty if nothing is
    /// left).
    // Not inlined: few triangles are clipped (on the firmware, 206 bytes less code).
    #[inline(never)]
    pub fn clip<V: Varyings>(&self, tri: &[ClipVertex<V>; 3], mask: u16) -> Polygon<V> {
        let mut poly = Polygon { verts: [tri[0]; MAX_CLIPPED], len: 3 };
        poly.verts[1] = tri[1];
        poly.verts[2] = tri[2];
        let mut scratch = poly;
        for (i, plane) in self.planes.iter().enumerate() {
            if mask & (1 << i) == 0 {
                continue;
            }
            clip_against(plane, &poly, &mut scratch);
            core::mem::swap(&mut poly, &mut scratch);
            if poly.len < 3 {
                poly.len = 0;
                break;
            }
        }
        poly
    }
}

impl ClipVolume {
    /// The part of the segment `a`-`b` inside the clipping planes, by the parametric method of Liang and Barsky
    /// ("A new concept and method for line clipping", ACM TOG 1984): the segment enters at the largest entering
    /// parameter and leaves at the smallest leaving one; each end point is then computed exactly from the plane
    /// that made it.
    pub fn clip_segment(&self, a: Vec4, b: Vec4) -> Option<(Vec4, Vec4)> {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let (mut enter, mut leave) = (None, None);
        for plane in &self.planes {
            let (da, db) = (plane.distance(a), plane.distance(b));
            match (da.signum() < 0, db.signum() < 0) {
                (true, true) => return None,
                (true, false) => {
                    let t = da.value() / da.sub(&db).value();
                    if t > t0 {
                        (t0, enter) = (t, Some((da, db)));
                    }
                }
                (false, true) => {
                    let t = da.value() / da.sub(&db).value();
                    if t < t1 {
                        (t1, leave) = (t, Some((da, db)));
                    }
                }
                (false, false) => {}
            }
        }
        if t0 > t1 {
            return None;
        }
        let start = enter.map_or(a, |(da, db)| Plane::meet(a, &da, b, &db));
        let end = leave.map_or(b, |(da, db)| Plane::meet(a, &da, b, &db));
        Some((start, end))
    }
}

/// A convex polygon of at most [`MAX_CLIPPED`] vertices.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Polygon<V> {
    verts: [ClipVertex<V>; MAX_CLIPPED],
    len: usize,
}

impl<V> Polygon<V> {
    /// The vertices, in order.
    pub fn vertices(&self) -> &[ClipVertex<V>] {
        &self.verts[..self.len]
    }

    fn push(&mut self, v: ClipVertex<V>) {
        // A convex polygon cannot overflow; a rounding-twisted one loses the extra vertex instead of panicking.
        if let Some(slot) = self.verts.get_mut(self.len) {
            *slot = v;
            self.len += 1;
        }
    }
}

/// One Sutherland-Hodgman pass: the part of `src` on the inner side of `plane` into `dst`.
fn clip_against<V: Varyings>(plane: &Plane, src: &Polygon<V>, dst: &mut Polygon<V>) {
    dst.len = 0;
    let verts = src.vertices();
    let Some(&last) = verts.last() else { return };
    let mut prev = last;
    let mut d_prev = plane.distance(prev.pos);
    for &cur in verts {
        let d_cur = plane.distance(cur.pos);
        if d_cur.signum() >= 0 {
            if d_prev.signum() < 0 {
                dst.push(intersect(&cur, &d_cur, &prev, &d_prev));
            }
            dst.push(cur);
        } else if d_prev.signum() >= 0 {
            dst.push(intersect(&prev, &d_prev, &cur, &d_cur));
        }
        prev = cur;
        d_prev = d_cur;
    }
}

/// The point where the segment from `inside` (distance `d_in >= 0`) to `outside` (`d_out < 0`) meets the plane,
/// with its varyings interpolated at the same parameter.
fn intersect<V: Varyings>(
    inside: &ClipVertex<V>,
    d_in: &Expansion,
    outside: &ClipVertex<V>,
    d_out: &Expansion,
) -> ClipVertex<V> {
    let t = d_in.value() / d_in.sub(d_out).value();
    ClipVertex { pos: Plane::meet(inside.pos, d_in, outside.pos, d_out), var: inside.var.lerp(&outside.var, t as f32) }
}
