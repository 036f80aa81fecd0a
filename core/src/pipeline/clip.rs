//! Homogeneous clipping: near and far planes, and a guard band for x and y.
//!
//! Clipping happens in clip space, before the perspective division, so no vertex is ever divided by `w <= 0`.
//! A triangle whose vertices lie inside the near and far planes and inside the guard band (a square of
//! ±[`GUARD_BAND`] pixels around the frame origin) goes to the rasterizer unclipped: its edges are exact there and
//! only the pixels inside the frame are visited. Anything larger is cut to the guard band, which keeps every
//! coordinate far inside the fixed-point range.
//!
//! Intersections are computed in `f64` from the inside vertex toward the outside one, so the two triangles that
//! share an edge cut it at bit-identical points and stay watertight (Sutherland and Hodgman, "Reentrant Polygon
//! Clipping", CACM 1974; Blinn and Newell, "Clipping using homogeneous coordinates", SIGGRAPH 1978).

use super::Varyings;
use crate::math::Vec4;

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
    /// The distance in `f64`; every product of two `f32`s is exact there.
    fn distance_f64(&self, p: Vec4) -> f64 {
        let a = self.0;
        f64::from(a[0]) * f64::from(p.x)
            + f64::from(a[1]) * f64::from(p.y)
            + f64::from(a[2]) * f64::from(p.z)
            + f64::from(a[3]) * f64::from(p.w)
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
    /// Each test has the sign of the plane's distance: `x < k w` exactly when `x - k w < 0`, because IEEE
    /// subtraction of two different floats is never zero.
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
    /// ("A new concept and method for line clipping", ACM TOG 1984), in `f64`.
    pub fn clip_segment(&self, a: Vec4, b: Vec4) -> Option<(Vec4, Vec4)> {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for plane in &self.planes {
            let (da, db) = (plane.distance_f64(a), plane.distance_f64(b));
            if da < 0.0 && db < 0.0 {
                return None;
            }
            if da < 0.0 {
                t0 = t0.max(da / (da - db));
            } else if db < 0.0 {
                t1 = t1.min(da / (da - db));
            }
        }
        if t0 > t1 {
            return None;
        }
        let at = |t: f64| {
            let lerp = |p: f32, q: f32| (f64::from(p) + (f64::from(q) - f64::from(p)) * t) as f32;
            Vec4::new(lerp(a.x, b.x), lerp(a.y, b.y), lerp(a.z, b.z), lerp(a.w, b.w))
        };
        Some((if t0 > 0.0 { at(t0) } else { a }, if t1 < 1.0 { at(t1) } else { b }))
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
    let mut d_prev = plane.distance_f64(prev.pos);
    for &cur in verts {
        let d_cur = plane.distance_f64(cur.pos);
        if d_cur >= 0.0 {
            if d_prev < 0.0 {
                dst.push(intersect(&cur, d_cur, &prev, d_prev));
            }
            dst.push(cur);
        } else if d_prev >= 0.0 {
            dst.push(intersect(&prev, d_prev, &cur, d_cur));
        }
        prev = cur;
        d_prev = d_cur;
    }
}

/// The point where the segment from `inside` (distance `d_in >= 0`) to `outside` (`d_out < 0`) meets the plane.
fn intersect<V: Varyings>(inside: &ClipVertex<V>, d_in: f64, outside: &ClipVertex<V>, d_out: f64) -> ClipVertex<V> {
    let t = d_in / (d_in - d_out);
    let lerp = |a: f32, b: f32| (f64::from(a) + (f64::from(b) - f64::from(a)) * t) as f32;
    let (a, b) = (inside.pos, outside.pos);
    ClipVertex {
        pos: Vec4::new(lerp(a.x, b.x), lerp(a.y, b.y), lerp(a.z, b.z), lerp(a.w, b.w)),
        var: inside.var.lerp(&outside.var, t as f32),
    }
}
