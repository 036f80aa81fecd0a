//! The view space around one surface point, linearised in pixel steps and scaled to the radius, so elevations
//! and distances need no division per sample and keep their precision at any scale of scene.

use crate::math::{Vec3, Vec4};

/// The view space around one pixel's surface point `p`, in steps from its pixel: a point `dx` pixels across,
/// `dy` down and `dd` deeper in NDC is `q`, with `v = (q - p) rho / radius` linear in the steps
/// ([`Around::offset`]) and `rho = w_q / w` (the ratio of the inverse projection's `w` at `q` and at `p`) affine
/// in them, `1 + (dx, dy, dd) . rho_per`: the inverse projection is linear in homogeneous coordinates. `rho` is
/// positive in front of the camera, so `v` points from `p` towards `q`; `|q - p| / radius = |v| / rho`.
/// Differences in units of the radius stay near 1 however large or small the scene, and need no division per
/// point.
pub(super) struct Around {
    /// The inverse projection's `w` at the pixel (`1 / clip w`).
    pub(super) w: f32,
    /// The view-space depth coordinate of `p`.
    pub(super) z: f32,
    /// `v` per pixel across.
    pub(super) per_x: Vec3,
    /// `v` per pixel down.
    pub(super) per_y: Vec3,
    /// `v` per unit of NDC depth.
    pub(super) per_depth: Vec3,
    /// `rho - 1` per pixel across, per pixel down and per unit of NDC depth.
    pub(super) rho_per: Vec3,
}

impl Around {
    /// The view space around homogeneous view position `h` (`w > 0`), whose homogeneous position moves by
    /// `per_x`, `per_y` and `per_depth` a pixel across, a pixel down and a unit of NDC depth; distances in units
    /// of `radius` (`1 / radius` is `inv_radius`).
    ///
    /// With `h_q = h + dx per_x + dy per_y + dd per_depth`, `(q - p) w_q w = h_q.xyz w - h.xyz w_q`: each column is
    /// a column of the map times `w`, less `h.xyz` times its `w`; dividing by `w^2 radius` (once per point) gives
    /// `v`.
    #[inline(always)]
    pub(super) fn new(h: Vec4, per_x: Vec4, per_y: Vec4, per_depth: Vec4, inv_radius: f32) -> Self {
        let inv_w = 1.0 / h.w;
        let scale = inv_w * inv_w * inv_radius;
        let column = |c: Vec4| (c.truncate() * h.w - h.truncate() * c.w) * scale;
        Self {
            w: h.w,
            z: h.z * inv_w,
            per_x: column(per_x),
            per_y: column(per_y),
            per_depth: column(per_depth),
            rho_per: Vec3::new(per_x.w, per_y.w, per_depth.w) * inv_w,
        }
    }

    /// `v` for the point `(dx, dy, dd)` away.
    #[inline(always)]
    pub(super) fn offset(&self, dx: f32, dy: f32, dd: f32) -> Vec3 {
        self.per_x * dx + self.per_y * dy + self.per_depth * dd
    }
}
