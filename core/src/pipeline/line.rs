//! Wireframe: the edges of a mesh's triangles as one-pixel lines, clipped like triangles.

use super::clip::ClipVolume;
use super::{Cull, DrawState, DrawStats, Winding};
use crate::camera::Viewport;
use crate::math::{Mat4, Vec3, Vec4, float};
use crate::mesh::Mesh;
use crate::target::{ColorBuffer, DepthBuffer, Target, TargetView, VertexMemory, clamp_depth};

/// How wireframe lines look.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineStyle {
    /// Line colour.
    pub color: Vec3,
    /// Subtracted from a line's NDC depth before the depth test, so lines on a surface drawn earlier stay visible.
    pub depth_bias: f32,
}

impl Default for LineStyle {
    fn default() -> Self {
        Self { color: Vec3::ONE, depth_bias: 1e-4 }
    }
}

/// Draws the edges of `mesh`'s triangles, transformed to clip space by `clip_from_object`.
///
/// Edges are clipped in homogeneous space against the near and far planes and the guard band. Each line lights one
/// pixel per column (if mostly horizontal) or per row (if mostly vertical), from the pixel containing one end point
/// to the pixel containing the other: in each column (row), the pixel containing the line at that column's (row's)
/// centre. A pixel's depth is that of the line's point at the centre's column (row), or of the nearer end point
/// where that lies beyond the line, never extrapolated past the ends. Each pixel is computed from frame
/// coordinates alone, so bands give the same pixels as a whole frame. An edge shared by two triangles is drawn
/// from its lower-numbered vertex, so both draws light the same pixels.
/// On a multisampled target each sample of a lit pixel is tested and written: lines are not anti-aliased.
///
/// `state` supplies the depth test (with [`LineStyle::depth_bias`]) and face culling: the edges of a culled
/// triangle (judged when all its vertices are in front of the camera) are not drawn. In the returned statistics a
/// triangle counts as rasterized when any of its edges was, and `fragments` counts pixels written.
pub fn draw_wireframe<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    clip_from_object: &Mat4,
    style: &LineStyle,
    state: &DrawState,
) -> DrawStats {
    let (mut view, _, _) = target.views(state.depth_test);
    draw_lines(&mut view, mesh, clip_from_object, style, state)
}

/// [`draw_wireframe`] into the target's views: compiled once, whatever its buffers.
fn draw_lines(
    target: &mut TargetView<'_>,
    mesh: &Mesh<'_>,
    clip_from_object: &Mat4,
    style: &LineStyle,
    state: &DrawState,
) -> DrawStats {
    let rows = target.rows();
    let volume = ClipVolume::new(target.width(), target.height(), rows.start, rows.end);
    let pen = Pen {
        viewport: Viewport::full(target.width(), target.height()),
        width: target.width() as i32,
        row0: rows.start as i32,
        row1: rows.end as i32,
        style: *style,
    };
    let mut stats = DrawStats::default();
    for t in 0..mesh.triangle_count() {
        stats.triangles_in += 1;
        let Some(tri) = mesh.triangle(t) else {
            stats.invalid += 1;
            continue;
        };
        let clip = tri.map(|i| clip_from_object.project_point(mesh.position(i)));
        if !clip.iter().all(|p| p.is_finite()) {
            stats.invalid += 1;
            continue;
        }
        let codes = clip.map(|p| volume.outcode(p));
        if codes[0] & codes[1] & codes[2] != 0 {
            stats.outside += 1;
            continue;
        }
        if is_culled(&clip, state) {
            stats.culled += 1;
            continue;
        }
        let mut drawn = false;
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            let (a, b) = if tri[a] <= tri[b] { (a, b) } else { (b, a) };
            if let Some((p, q)) = volume.clip_segment(clip[a], clip[b]) {
                drawn = true;
                stats.fragments += pen.line(target, p, q);
            }
        }
        if drawn {
            stats.rasterized += 1;
        } else {
            stats.outside += 1;
        }
    }
    stats
}

/// Facing from the signed area of the projected triangle, when all of it is in front of the camera.
fn is_culled(clip: &[Vec4; 3], state: &DrawState) -> bool {
    if state.cull == Cull::None || !clip.iter().all(|p| p.w > 0.0) {
        return false;
    }
    let ndc = clip.map(|p| (p.x / p.w, p.y / p.w));
    let area = (ndc[1].0 - ndc[0].0) * (ndc[2].1 - ndc[0].1) - (ndc[1].1 - ndc[0].1) * (ndc[2].0 - ndc[0].0);
    let front = (area > 0.0) == (state.front_face == Winding::CounterClockwise);
    match state.cull {
        Cull::Back => !front && area != 0.0,
        Cull::Front => front,
        Cull::None => false,
    }
}

/// Per-draw line settings.
struct Pen {
    viewport: Viewport,
    width: i32,
    row0: i32,
    row1: i32,
    style: LineStyle,
}

impl Pen {
    /// Draws one clipped segment (both ends have `w > 0`); returns the pixels written.
    fn line(&self, target: &mut TargetView<'_>, p: Vec4, q: Vec4) -> u64 {
        if !(p.w > 0.0 && q.w > 0.0) {
            return 0;
        }
        let (a, b) = (self.viewport.clip_to_screen(p), self.viewport.clip_to_screen(q));
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        if float::abs(dx) >= float::abs(dy) {
            if dx == 0.0 {
                return 0;
            }
            // Mostly horizontal: one pixel per column, `major` = x.
            let (a, b) = if dx > 0.0 { (a, b) } else { (b, a) };
            let slope = (b.y - a.y) / (b.x - a.x);
            let (lo, hi) = self.major_range(a.x, b.x, 0, self.width);
            // Columns where the line can reach the target's rows, with a column of margin for rounding.
            let (lo, hi) = if slope == 0.0 {
                (lo, hi)
            } else {
                let c0 = a.x + (self.row0 as f32 - a.y) / slope;
                let c1 = a.x + (self.row1 as f32 - a.y) / slope;
                // A nearly horizontal line crosses the rows far outside `i32`: the conversions saturate.
                let (c0, c1) = (float::min(c0, c1), float::max(c0, c1));
                (lo.max(float::floor_to_i32(c0).saturating_sub(1)), hi.min(float::floor_to_i32(c1).saturating_add(2)))
            };
            self.plot_span(target, lo, hi, &a, &b, slope, |major, minor| (major, minor))
        } else {
            // Mostly vertical: one pixel per row, `major` = y.
            let (a, b) = if dy > 0.0 { (a, b) } else { (b, a) };
            let slope = (b.x - a.x) / (b.y - a.y);
            let (lo, hi) = self.major_range(a.y, b.y, self.row0, self.row1);
            let swap = |v: &Vec3| Vec3::new(v.y, v.x, v.z);
            self.plot_span(target, lo, hi, &swap(&a), &swap(&b), slope, |major, minor| (minor, major))
        }
    }

    /// Pixel indices from the one containing `from` to the one containing `to` (`from <= to`), as a half-open
    /// range limited to `[min, max)`.
    fn major_range(&self, from: f32, to: f32, min: i32, max: i32) -> (i32, i32) {
        (float::floor_to_i32(from).max(min), float::floor_to_i32(to).saturating_add(1).min(max))
    }

    /// Plots the pixels of major coordinates `lo..hi` along the line from `a` (major axis in `x`) with the given
    /// minor-per-major slope; `to_xy` maps (major, minor) to (column, row).
    #[allow(clippy::too_many_arguments)]
    fn plot_span(
        &self,
        target: &mut TargetView<'_>,
        lo: i32,
        hi: i32,
        a: &Vec3,
        b: &Vec3,
        slope: f32,
        to_xy: impl Fn(i32, i32) -> (i32, i32),
    ) -> u64 {
        let (length, dz) = (b.x - a.x, b.z - a.z);
        let width = target.width() as usize;
        let samples = target.samples().count();
        let mut written = 0;
        for major in lo..hi {
            let along = major as f32 + 0.5 - a.x;
            let minor = float::floor_to_i32(a.y + along * slope);
            let (x, y) = to_xy(major, minor);
            if x < 0 || x >= self.width || y < self.row0 || y >= self.row1 {
                continue;
            }
            // The end pixels' centres can lie up to half a pixel beyond the ends: their depth is the end's.
            let t = float::clamp(along / length, 0.0, 1.0);
            let z = clamp_depth(a.z + t * dz - self.style.depth_bias);
            // A line covers its pixels whole: every sample of a multisampled target's pixel.
            let first = ((y - self.row0) as usize * width + x as usize) * samples;
            let mut any = false;
            for index in first..first + samples {
                if target.depth.test_and_set(index, z) {
                    target.color.write(index, self.style.color);
                    any = true;
                }
            }
            written += u64::from(any);
        }
        written
    }
}
