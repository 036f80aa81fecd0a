//! A draw's geometry for one frame: the screen vertices of its mesh, computed once on the renderer's threads and
//! shared by every band's draw, and its triangles sorted into the frame's bands of rows, so that each band's draw
//! meets only the triangles that can reach its rows and runs no vertex position stage of its own.
//!
//! The sorting is conservative and leaves every decision to the core: a triangle goes to each band its screen
//! rows (from its vertices' screen rows, widened by [`MARGIN_ROWS`]) overlap, and one whose rows are uncertain (a
//! vertex behind the eye, beyond the near or far plane or the guard band, or not finite, or an index out of range)
//! goes to every band. Each band keeps the mesh's order, so its pixels are those of drawing the whole mesh into it.

use std::ops::Range;

use rastty_core::math::Mat4;
use rastty_core::mesh::Mesh;
use rastty_core::pipeline::{DrawError, DrawState, ScreenVertex};
use rastty_core::target::SharedScreenVertices;

use super::workers::Workers;

/// Rows added on each side of a triangle's rows: more than rounding and sub-pixel snapping can move an edge.
pub const MARGIN_ROWS: f32 = 2.0;

/// A mesh is sorted in one piece below this many triangles a thread: the threads' hand-over costs more than it
/// saves.
pub const TRIANGLES_PER_PIECE: usize = 16_384;

/// The sub-pixel bits the forward pass draws with, and so computes its screen vertices for.
pub const SUBPIXEL_BITS: u8 = DrawState::DEFAULT.subpixel_bits;

/// The screen vertices and the triangles of one draw sorted into bands, kept from frame to frame: sorting again
/// reuses their memory, so a frame allocates nothing in proportion to the mesh once they have grown to it.
///
/// The vertices are computed, and the triangles sorted, in pieces (consecutive runs, one per thread for a large
/// mesh), each piece on a thread of its own; a band's triangles are its lists of every piece in turn
/// ([`Self::band`]), which keeps the mesh's order.
#[derive(Debug, Default)]
pub struct TriangleBins {
    /// The screen vertex of each vertex of the mesh last sorted.
    vertices: Vec<ScreenVertex>,
    /// For each piece of the mesh, for each band, the vertex indices of the piece's triangles that can reach the
    /// band, three per triangle. Only the first `pieces` are in use; the others keep their memory.
    pieces: Vec<Vec<Vec<u32>>>,
    /// How many of `pieces` hold the last sort.
    used: usize,
}

impl TriangleBins {
    /// Computes the screen vertices of `mesh` drawn with `clip_from_object` into a `width x height` frame with
    /// [`SUBPIXEL_BITS`], and sorts its triangles into `bands` (row ranges, top first, in order), on `workers`'
    /// threads.
    ///
    /// # Errors
    /// Never for [`SUBPIXEL_BITS`]: the core's refusal of sub-pixel bits it does not support.
    pub fn sort(
        &mut self,
        mesh: &Mesh<'_>,
        clip_from_object: &Mat4,
        frame: (u32, u32),
        bands: &[Range<u32>],
        workers: &Workers,
    ) -> Result<(), DrawError> {
        let positions = mesh.positions();
        let triangles = mesh.triangle_count();
        let pieces = workers.threads().min(triangles / TRIANGLES_PER_PIECE).max(1);

        self.vertices.clear();
        self.vertices.resize(positions.len(), ScreenVertex::UNSET);
        let per_piece = positions.len().div_ceil(pieces).max(1);
        let jobs: Vec<_> = self.vertices.chunks_mut(per_piece).enumerate().collect();
        let computed = workers.run(jobs, |(i, out)| {
            SharedScreenVertices::compute(positions, clip_from_object, frame, SUBPIXEL_BITS, i * per_piece, out)
        });
        computed.into_iter().collect::<Result<(), _>>()?;

        if self.pieces.len() < pieces {
            self.pieces.resize_with(pieces, Vec::new);
        }
        self.used = pieces;
        let vertices = &self.vertices;
        // A vertex's screen row, NaN where it is uncertain (as for an index out of range).
        let row = |i: usize| vertices.get(i).and_then(ScreenVertex::screen_row).unwrap_or(f32::NAN);
        let jobs: Vec<_> = self.pieces[..pieces]
            .iter_mut()
            .enumerate()
            .map(|(i, lists)| (triangles * i / pieces..triangles * (i + 1) / pieces, lists))
            .collect();
        workers.run(jobs, |(run, lists)| {
            if lists.len() < bands.len() {
                lists.resize_with(bands.len(), Vec::new);
            }
            lists.iter_mut().for_each(Vec::clear);
            for t in run {
                // Out-of-range indices stay out of range (`u32::MAX`), for the core to count as invalid in every
                // band.
                let triangle = mesh.triangle(t).unwrap_or([u32::MAX as usize; 3]);
                let y = triangle.map(row);
                let (top, bottom) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
                let reach = if y.iter().all(|r| r.is_finite()) {
                    top - MARGIN_ROWS..bottom + MARGIN_ROWS
                } else {
                    f32::NEG_INFINITY..f32::INFINITY
                };
                for (list, band) in lists.iter_mut().zip(bands) {
                    if reach.start < band.end as f32 && reach.end >= band.start as f32 {
                        list.extend(triangle.map(|i| i as u32));
                    }
                }
            }
        });
        Ok(())
    }

    /// The screen vertices of the last sort, for the draws of `mesh` with `clip_from_object` into a frame of
    /// `frame` pixels (a draw of anything else ignores them).
    pub fn shared(&self, mesh: &Mesh<'_>, clip_from_object: &Mat4, frame: (u32, u32)) -> SharedScreenVertices<'_> {
        SharedScreenVertices::new(&self.vertices, mesh.positions(), clip_from_object, frame, SUBPIXEL_BITS)
    }

    /// The vertex indices of the triangles that can reach band `band`, three per triangle: one list per piece of
    /// the mesh, in the mesh's order.
    pub fn band(&self, band: usize) -> impl Iterator<Item = &[u32]> {
        self.pieces[..self.used].iter().map(move |lists| lists.get(band).map_or(&[][..], Vec::as_slice))
    }

    /// How many triangles can reach band `band`.
    pub fn band_triangles(&self, band: usize) -> usize {
        self.band(band).map(|list| list.len() / 3).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rastty_core::color::ShadingSpace;
    use rastty_core::pipeline::{Cull, DepthTest};
    use rastty_core::target::VertexMemory;
    use rastty_core::{
        DrawState, DrawStats, Indices, Lighting, Material, Object, Rgb888, ShadingModel, Target, Transforms, Vec3,
        draw_mesh, look_at, perspective,
    };

    /// A soup of `triangles` triangles around the camera: most in view, some crossing the eye plane or behind it,
    /// some huge, some slivers, and the last with an index out of range.
    fn soup(triangles: usize) -> (Vec<Vec3>, Vec<u32>) {
        let mut seed = 0x2545_F491_u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1 << 24) as f32 * 2.0 - 1.0
        };
        let mut positions = Vec::new();
        for t in 0..triangles - 1 {
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
    /// whole frame, for bands of one row, uneven bands and a single band, sorted on one thread and in pieces on
    /// three, the same bins sorted again each time; with the depth test off, where the last triangle drawn over a
    /// pixel shows, the mesh's order is kept too.
    #[test]
    fn banded_draws_of_the_sorted_triangles_match_one_whole_draw() {
        for (triangles, threads) in [(401, 1), (401, 3), (3 * TRIANGLES_PER_PIECE + 1, 3)] {
            for depth_test in [DepthTest::Less, DepthTest::Off] {
                banded_draws_match_one_whole_draw(triangles, &Workers::new(threads), depth_test);
            }
        }
    }

    fn banded_draws_match_one_whole_draw(triangles: usize, workers: &Workers, depth_test: DepthTest) {
        let (positions, indices) = soup(triangles);
        let mesh = Mesh::new(&positions, Indices::U32(&indices)).unwrap();
        let (w, h) = (64u32, 48u32);
        let eye = Vec3::new(0.0, 0.0, 4.0);
        let view = look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
        let transforms =
            Transforms::new(Mat4::IDENTITY, view, perspective(1.2, w as f32 / h as f32, 0.1, 20.0).unwrap());
        let clip = transforms.clip_from_object;
        let state = DrawState { cull: Cull::None, depth_test, ..DrawState::DEFAULT };
        // The depth view: grey levels from the depth buffer.
        fn depth_view<M: VertexMemory>(
            target: &mut Target<Rgb888<'_>, &mut [f32], M>,
            mesh: Mesh<'_>,
            transforms: Transforms,
            state: &DrawState,
        ) -> DrawStats {
            let shading = ShadingModel::Depth { near: 0.0, far: 1.0 };
            let object = Object { mesh, tangents: None, transforms, shading, material: Material::default() };
            let lights = Lighting { ambient: Vec3::ZERO, lights: &[], space: ShadingSpace::Linear };
            draw_mesh(target, &object, &lights, state).unwrap().1
        }
        let draw =
            |target: &mut Target<Rgb888<'_>, &mut [f32]>, mesh: Mesh<'_>| depth_view(target, mesh, transforms, &state);
        let (mut whole, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
        let mut target = Target::new(Rgb888(&mut whole), &mut depth[..], w, h).unwrap();
        target.clear(Vec3::ZERO);
        let all = draw(&mut target, mesh);
        assert!(all.fragments > 1000 && all.clipped > 0 && all.invalid == 1, "{all:?}");

        let mut bins = TriangleBins::default();
        for cuts in [(0..=48).collect::<Vec<u32>>(), vec![0, 48], vec![0, 1, 2, 17, 30, 47, 48]] {
            let bands: Vec<Range<u32>> = cuts.windows(2).map(|c| c[0]..c[1]).collect();
            bins.sort(&mesh, &clip, (w, h), &bands, workers).unwrap();
            let pieces = bins.band(0).count();
            let expected = workers.threads().min(mesh.triangle_count() / TRIANGLES_PER_PIECE).max(1);
            assert_eq!(pieces, expected);
            let (mut banded, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
            let mut sorted = 0;
            for (i, rows) in bands.iter().enumerate() {
                let span = (rows.start * w) as usize..(rows.end * w) as usize;
                let (color, depth) = (&mut banded[span.clone()], &mut depth[span]);
                let shared = bins.shared(&mesh, &clip, (w, h));
                let target = Target::band(Rgb888(color), depth, w, h, rows.clone()).unwrap();
                let mut target = target.with_shared_vertices(shared);
                target.clear(Vec3::ZERO);
                for list in bins.band(i) {
                    depth_view(&mut target, mesh.with_indices(Indices::U32(list)).unwrap(), transforms, &state);
                }
                sorted += bins.band_triangles(i);
            }
            assert!(whole == banded, "bands {bands:?}, {depth_test:?}");
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
