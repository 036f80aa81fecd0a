//! The depth of some rows of a frame, read back as view-space geometry: homogeneous positions, the view space
//! around a surface point, and the samples of a search gathered four at a time.

use core::ops::Range;

use super::around::Around;
use super::{F4, LANES};
use crate::math::Lanes;
use crate::math::{Mat4, Vec4};

/// The depth of some rows of a frame, and how to bring a pixel back to view space.
pub(super) struct DepthFrame<'a> {
    /// NDC depth of the stored rows, row `first_row` first.
    depth: &'a [f32],
    /// The first stored row.
    first_row: i32,
    /// The row after the last stored one.
    end_row: i32,
    /// The frame's width in pixels (and the length of a stored row).
    pub(super) width: i32,
    /// The frame's height in pixels.
    height: i32,
    /// The inverse projection composed with the map from pixel `(x, y)` and depth `d` to NDC, by columns: the
    /// homogeneous view position of `(x, y, d)` is `x * per_x + y * per_y + d * per_depth + at_origin`.
    per_x: Vec4,
    /// See [`DepthFrame::per_x`]: the column for `y`.
    per_y: Vec4,
    /// See [`DepthFrame::per_x`]: the column for `d`.
    per_depth: Vec4,
    /// See [`DepthFrame::per_x`]: the homogeneous view position of pixel `(0, 0)` at depth 0.
    at_origin: Vec4,
}

impl<'a> DepthFrame<'a> {
    /// The rows `rows` of a `width x height` frame, `depth` holding their NDC depth, seen through the inverse
    /// projection `inverse`.
    pub(super) fn new(depth: &'a [f32], rows: Range<u32>, width: u32, height: u32, inverse: &Mat4) -> Self {
        // NDC x = (x + 0.5) * 2 / width - 1 and y = 1 - (y + 0.5) * 2 / height, folded into the matrix once.
        let [a, b, c, t] = inverse.cols;
        let (sx, sy) = (2.0 / width as f32, 2.0 / height as f32);
        Self {
            depth,
            first_row: rows.start as i32,
            end_row: rows.end as i32,
            width: width as i32,
            height: height as i32,
            per_x: a * sx,
            per_y: b * -sy,
            per_depth: c,
            at_origin: t + a * (0.5 * sx - 1.0) + b * (1.0 - 0.5 * sy),
        }
    }

    /// The depth at pixel `(x, y)`, or `None` outside the stored rows or where nothing was drawn.
    #[inline(always)]
    pub(super) fn depth_at(&self, x: i32, y: i32) -> Option<f32> {
        let d = self.depth_or_far(x, y);
        (d < 1.0).then_some(d)
    }

    /// The depths of row `y`, one of the stored rows.
    #[inline(always)]
    pub(super) fn row(&self, y: i32) -> &[f32] {
        let start = (y - self.first_row) as usize * self.width as usize;
        &self.depth[start..start + self.width as usize]
    }

    /// The depth at pixel `(x, y)`; 1 (the far plane: nothing drawn) outside the frame or the stored rows.
    #[inline(always)]
    fn depth_or_far(&self, x: i32, y: i32) -> f32 {
        if x < 0 || x >= self.width || y < self.first_row || y >= self.end_row {
            return 1.0;
        }
        self.depth[(y - self.first_row) as usize * self.width as usize + x as usize]
    }

    /// The homogeneous view position of depth `d` at the centre of pixel `(x, y)`: `w` is the inverse
    /// projection's (`1 / clip w`), positive in front of the camera.
    #[inline(always)]
    fn homogeneous(&self, x: i32, y: i32, d: f32) -> Vec4 {
        self.per_x * x as f32 + self.per_y * y as f32 + self.per_depth * d + self.at_origin
    }

    /// What the view-space depth coordinate `z` and the inverse projection's `w` of row `y` share, for
    /// [`DepthFrame::z_w`].
    #[inline(always)]
    pub(super) fn row_z_w(&self, y: i32) -> (f32, f32) {
        let y = y as f32;
        (self.per_y.z * y + self.at_origin.z, self.per_y.w * y + self.at_origin.w)
    }

    /// `z * w` and `w` of depth `d` at pixel `x` of the row that `row` ([`DepthFrame::row_z_w`]) came from: the
    /// view-space depth coordinate without its division.
    #[inline(always)]
    pub(super) fn z_w(&self, row: (f32, f32), x: i32, d: f32) -> (f32, f32) {
        let x = x as f32;
        (self.per_x.z * x + self.per_depth.z * d + row.0, self.per_x.w * x + self.per_depth.w * d + row.1)
    }

    /// The view space around the surface at pixel `(x, y)`, depth `d`, in units of the radius (`1 / radius` is
    /// `inv_radius`); `None` behind the camera.
    #[inline(always)]
    pub(super) fn around(&self, x: i32, y: i32, d: f32, inv_radius: f32) -> Option<Around> {
        let h = self.homogeneous(x, y, d);
        (h.w > 0.0).then(|| Around::new(h, self.per_x, self.per_y, self.per_depth, inv_radius))
    }

    /// The offsets from pixel `(x, y)` that stay within the frame and within the stored rows, and where its depth
    /// is.
    #[inline(always)]
    pub(super) fn window(&self, x: i32, y: i32) -> Window {
        Window {
            low: ((-x) as f32, (-y) as f32),
            high: ((self.width - 1 - x) as f32, (self.height - 1 - y) as f32),
            stored: ((self.first_row - y) as f32, (self.end_row - 1 - y) as f32),
            at: (y - self.first_row) * self.width + x,
        }
    }

    /// The pixels `(dx, dy)` (whole numbers below 2^22) from the pixel of `window`, moved onto the frame's nearest
    /// edge pixel where they leave it; their depths; and 1 where they are within the stored rows and drawn, 0
    /// elsewhere. Rows beyond the stored ones are clamped for the load, so it never fails and needs no branch.
    #[inline(always)]
    pub(super) fn gather(&self, window: &Window, dx: F4, dy: F4) -> (F4, F4, F4, F4) {
        let cx = dx.clamp(window.low.0, window.high.0);
        let cy = dy.clamp(window.low.1, window.high.1);
        let stored = cy.clamp(window.stored.0, window.stored.1);
        let (ix, iy) = (cx.small_to_i32(), stored.small_to_i32());
        // Below 2^26 (MAX_DIMENSION squared), so i32 holds it.
        let index: [i32; LANES] = core::array::from_fn(|k| window.at + iy[k] * self.width + ix[k]);
        let depth = Lanes(index.map(|i| self.depth[i as usize]));
        let drawn = stored.equal(cy).where_less(depth, F4::splat(1.0));
        (cx, cy, depth, drawn)
    }

    /// The depths of the five pixels across the frame through `(x, y)` and of the five down it, `(x, y)` in the
    /// middle of each; 1 (nothing drawn) outside the frame or the stored rows.
    #[inline(always)]
    pub(super) fn lines_through(&self, x: i32, y: i32) -> ([f32; 5], [f32; 5]) {
        if x >= 2 && x + 2 < self.width && y - 2 >= self.first_row && y + 2 < self.end_row {
            let w = self.width as usize;
            let i = (y - self.first_row) as usize * w + x as usize;
            let d = self.depth;
            ([d[i - 2], d[i - 1], d[i], d[i + 1], d[i + 2]], [d[i - 2 * w], d[i - w], d[i], d[i + w], d[i + 2 * w]])
        } else {
            let k = |k: usize| k as i32 - 2;
            (
                core::array::from_fn(|i| self.depth_or_far(x + k(i), y)),
                core::array::from_fn(|i| self.depth_or_far(x, y + k(i))),
            )
        }
    }
}

/// The offsets from one pixel that stay within the frame (across and down) and within the stored rows, and its
/// index in the depth.
pub(super) struct Window {
    /// The smallest offsets across and down that stay within the frame.
    low: (f32, f32),
    /// The largest offsets across and down that stay within the frame.
    high: (f32, f32),
    /// The smallest and the largest offset down that stay within the stored rows.
    stored: (f32, f32),
    /// The pixel's index in the stored depth.
    at: i32,
}
