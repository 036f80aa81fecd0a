//! Triangles sorted into the frame's bands of rows, so that each band's draw meets only the triangles that can
//! reach its rows instead of running the vertex stage of the whole mesh again.
//!
//! The sorting is conservative and leaves every decision to the core: a triangle goes to each band its screen
//! rows (from its vertices' clip-space positions, widened by [`MARGIN_ROWS`]) overlap, and one whose rows are
//! uncertain (a vertex behind the eye, on the eye plane, or not finite, or an index out of range) goes to every
//! band. Each band keeps the mesh's order, so its pixels are those of drawing the whole mesh into it.

use std::ops::Range;

use rastty_core::camera::Viewport;
use rastty_core::math::Mat4;
use rastty_core::mesh::Mesh;

/// Rows added on each side of a triangle's rows: more than rounding and sub-pixel snapping can move an edge.
pub const MARGIN_ROWS: f32 = 2.0;

/// The triangles of one draw sorted into bands: for each band, the vertex indices of its triangles, three per
/// triangle, in the mesh's order.
#[derive(Debug, Default)]
pub struct TriangleBins {
    bands: Vec<Vec<u32>>,
}

impl TriangleBins {
    /// Sorts the triangles of `mesh`, drawn with `clip_from_object` into a `width x height` frame, into `bands`
    /// (row ranges, top first, in order).
    pub fn new(mesh: &Mesh<'_>, clip_from_object: &Mat4, (width, height): (u32, u32), bands: &[Range<u32>]) -> Self {
        let viewport = Viewport::full(width, height);
        // The screen row of each vertex, as the rasterizer maps it, NaN where it is uncertain.
        let rows: Vec<f32> = mesh
            .positions()
            .iter()
            .map(|&p| {
                let clip = clip_from_object.project_point(p);
                if clip.w > 0.0 { viewport.clip_to_screen(clip).y } else { f32::NAN }
            })
            .collect();
        let mut sorted = TriangleBins { bands: vec![Vec::new(); bands.len()] };
        for t in 0..mesh.triangle_count() {
            // Out-of-range indices stay out of range (`u32::MAX`), for the core to count as invalid in every band.
            let triangle = mesh.triangle(t).unwrap_or([u32::MAX as usize; 3]);
            let y = triangle.map(|i| rows.get(i).copied().unwrap_or(f32::NAN));
            let (top, bottom) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
            let reach = if y.iter().all(|r| r.is_finite()) {
                top - MARGIN_ROWS..bottom + MARGIN_ROWS
            } else {
                f32::NEG_INFINITY..f32::INFINITY
            };
            for (list, band) in sorted.bands.iter_mut().zip(bands) {
                if reach.start < band.end as f32 && reach.end >= band.start as f32 {
                    list.extend(triangle.map(|i| i as u32));
                }
            }
        }
        sorted
    }

    /// The vertex indices of the triangles that can reach band `band`, three per triangle.
    pub fn band(&self, band: usize) -> &[u32] {
        self.bands.get(band).map_or(&[], Vec::as_slice)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rastty_core::pipeline::Cull;
    use rastty_core::{
        DrawState, DrawStats, Indices, Lighting, Material, Object, Rgb888, ShadingModel, Target, Transforms, Vec3,
        draw_mesh, look_at, perspective,
    };

    /// A triangle soup around the camera: most triangles in view, some crossing the eye plane or behind it, some
    /// huge, some slivers, and one with an index out of range.
    fn soup() -> (Vec<Vec3>, Vec<u32>) {
        let mut seed = 0x2545_F491_u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1 << 24) as f32 * 2.0 - 1.0
        };
        let mut positions = Vec::new();
        for t in 0..400 {
            let scale = if t % 37 == 0 { 40.0 } else { 1.0 };
            let centre = Vec3::new(next() * 2.0, next() * 2.0, next() * 3.0);
            for _ in 0..3 {
                positions.push(centre + Vec3::new(next(), next(), next()) * (0.4 * scale));
            }
        }
        let mut indices: Vec<u32> = (0..positions.len() as u32).collect();
        indices.extend([0, 1, positions.len() as u32 + 5]);
        (positions, indices)
    }

    /// Drawing each band with the triangles sorted into it gives the pixels of drawing the whole mesh into the
    /// whole frame, for bands of one row, uneven bands and a single band.
    #[test]
    fn banded_draws_of_the_sorted_triangles_match_one_whole_draw() {
        let (positions, indices) = soup();
        let mesh = Mesh::new(&positions, Indices::U32(&indices)).unwrap();
        let (w, h) = (64u32, 48u32);
        let eye = Vec3::new(0.0, 0.0, 4.0);
        let view = look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
        let transforms =
            Transforms::new(Mat4::IDENTITY, view, perspective(1.2, w as f32 / h as f32, 0.1, 20.0).unwrap());
        let clip = transforms.clip_from_object;
        let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
        // The depth view: grey levels from the depth buffer.
        let draw = |target: &mut Target<Rgb888<'_>, &mut [f32]>, mesh: Mesh<'_>| -> DrawStats {
            let shading = ShadingModel::Depth { near: 0.0, far: 1.0 };
            let object = Object { mesh, tangents: None, transforms, shading, material: Material::default() };
            draw_mesh(target, &object, &Lighting { ambient: Vec3::ZERO, lights: &[] }, &state).unwrap().1
        };
        let (mut whole, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
        let mut target = Target::new(Rgb888(&mut whole), &mut depth[..], w, h).unwrap();
        target.clear(Vec3::ZERO);
        let all = draw(&mut target, mesh);
        assert!(all.fragments > 1000 && all.clipped > 0 && all.invalid == 1, "{all:?}");

        for cuts in [vec![0, 48], vec![0, 1, 2, 17, 30, 47, 48], (0..=48).collect::<Vec<u32>>()] {
            let bands: Vec<Range<u32>> = cuts.windows(2).map(|c| c[0]..c[1]).collect();
            let bins = TriangleBins::new(&mesh, &clip, (w, h), &bands);
            let (mut banded, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
            let mut sorted = 0;
            for (i, rows) in bands.iter().enumerate() {
                let span = (rows.start * w) as usize..(rows.end * w) as usize;
                let (color, depth) = (&mut banded[span.clone()], &mut depth[span]);
                let mut target = Target::band(Rgb888(color), depth, w, h, rows.clone()).unwrap();
                target.clear(Vec3::ZERO);
                let triangles = mesh.with_indices(Indices::U32(bins.band(i))).unwrap();
                draw(&mut target, triangles);
                sorted += bins.band(i).len() / 3;
            }
            assert!(whole == banded, "bands {bands:?}");
            if bands.len() > 1 {
                // Each band met far fewer triangles than the whole mesh.
                assert!(
                    sorted < bands.len() * mesh.triangle_count() / 2,
                    "{sorted} triangles in {} bands",
                    bands.len()
                );
            }
        }
    }
}
