//! Each draw's geometry for one frame, computed once on the renderer's threads and lent to every band's draw as the
//! core's [`FrameGeometry`]: the screen vertices of its mesh ([`SharedScreenVertices`]) and its triangles binned by
//! band ([`BandBins`]), so that each band's draw runs no position stage of its own and meets only the triangles that
//! can reach its rows. The binning is the core's; this module runs it in parts on the threads and keeps its memory.

use std::ops::Range;

use rastty_core::math::Mat4;
use rastty_core::mesh::Mesh;
use rastty_core::pipeline::{
    BandBins, Bands, BinnedTriangle, DrawError, DrawState, DrawStats, MAX_PART_TRIANGLES, ScreenVertex,
};
use rastty_core::target::{FrameGeometry, SharedScreenVertices};

use super::workers::Workers;

/// A mesh is computed in one part below this many triangles a thread: the threads' hand-over costs more than it
/// saves.
pub(crate) const TRIANGLES_PER_PART: usize = 16_384;

/// The memory of one draw's geometry, kept from frame to frame: computing it again reuses it, so that a frame
/// allocates nothing in proportion to the mesh once it has grown to it.
#[derive(Debug, Default)]
pub(crate) struct GeometryMemory {
    /// The screen vertex of each vertex of the mesh.
    vertices: Vec<ScreenVertex>,
    /// The entries of each part's bins; only as many as the last computation's parts are in use.
    parts: Vec<Vec<BinnedTriangle>>,
}

/// One draw's geometry for one frame, in a [`GeometryMemory`]: see the module docs.
#[derive(Debug)]
pub(crate) struct DrawGeometry<'a> {
    vertices: SharedScreenVertices<'a>,
    /// The bins of each part of the mesh, in its order.
    bins: Vec<BandBins<'a>>,
}

impl GeometryMemory {
    /// Computes, on `workers`' threads, the screen vertices of `mesh` drawn with `clip_from_object` and `state` into
    /// the frame of `bands`, then bins its triangles by those bands, in parts (consecutive runs of triangles, one per
    /// thread for a large mesh, at most [`MAX_PART_TRIANGLES`] each).
    ///
    /// # Errors
    /// The core's refusal of the state's sub-pixel bits.
    pub fn compute<'a>(
        &'a mut self,
        mesh: &Mesh<'_>,
        clip_from_object: &Mat4,
        state: &DrawState,
        bands: Bands,
        workers: &Workers,
    ) -> Result<DrawGeometry<'a>, DrawError> {
        let positions = mesh.positions();
        let (frame, bits) = (bands.size(), state.subpixel_bits);
        let pieces = workers.threads().min(mesh.triangle_count() / TRIANGLES_PER_PART).max(1);
        self.vertices.clear();
        self.vertices.resize(positions.len(), ScreenVertex::UNSET);
        let per_piece = positions.len().div_ceil(pieces).max(1);
        let jobs: Vec<_> = self.vertices.chunks_mut(per_piece).enumerate().collect();
        let computed = workers.run(jobs, |(i, out)| {
            SharedScreenVertices::compute(positions, clip_from_object, frame, bits, i * per_piece, out)
        });
        computed.into_iter().collect::<Result<(), _>>()?;
        let vertices = SharedScreenVertices::new(&self.vertices, positions, clip_from_object, frame, bits);

        let triangles = mesh.triangle_count();
        let parts =
            triangles.div_ceil(MAX_PART_TRIANGLES).max(workers.threads().min(triangles / TRIANGLES_PER_PART)).max(1);
        if self.parts.len() < parts {
            self.parts.resize_with(parts, Vec::new);
        }
        let jobs: Vec<(Range<usize>, &mut Vec<BinnedTriangle>)> = self.parts[..parts]
            .iter_mut()
            .enumerate()
            .map(|(i, memory)| {
                let run = triangles * i / parts..triangles * (i + 1) / parts;
                // Room for every triangle of the part and its blocks: none is left to every band.
                memory.resize(BandBins::entries_for(run.len()), BinnedTriangle::UNSET);
                (run, memory)
            })
            .collect();
        let binned = workers.run(jobs, |(run, memory)| {
            BandBins::bin(memory, mesh, clip_from_object, state, bands, run, Some(&vertices))
        });
        let bins = binned.into_iter().collect::<Result<Vec<_>, _>>()?;
        Ok(DrawGeometry { vertices, bins })
    }
}

impl<'a> DrawGeometry<'a> {
    /// The geometry as a band's target borrows it for the draw ([`rastty_core::target::Target::for_draw`]).
    pub(crate) fn lend(&self) -> FrameGeometry<'_> {
        FrameGeometry { vertices: Some(self.vertices), bins: &self.bins }
    }

    /// Adds to `counts[b]` the triangles band `b`'s draw takes.
    pub(crate) fn count_by_band(&self, counts: &mut [usize]) {
        self.bins.iter().for_each(|part| part.count_by_band(counts));
    }

    /// What binning counted, each triangle once for the frame (no fragments: the bands' draws count those).
    pub fn stats(&self) -> DrawStats {
        let mut sum = DrawStats::default();
        self.bins.iter().for_each(|part| sum += part.stats());
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rastty_core::color::ShadingSpace;
    use rastty_core::pipeline::{Cull, DepthTest};
    use rastty_core::target::{ColorBuffer, DepthBuffer, Samples, VertexMemory};
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

    /// Drawing each band lent the frame's geometry gives the pixels of drawing the whole mesh into the whole frame,
    /// for bands of one row, of seven and a single band, computed on one thread and in parts on three, the same
    /// memory reused each time; with the depth test off, where the last triangle drawn over a pixel shows, the mesh's
    /// order is kept too. Each band takes fewer triangles than the mesh has, and binning counts each triangle once.
    #[test]
    fn banded_draws_lent_the_frame_geometry_match_one_whole_draw() {
        for (triangles, threads) in [(401, 1), (401, 3), (3 * TRIANGLES_PER_PART + 1, 3)] {
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
        fn depth_view<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
            target: &mut Target<C, D, M>,
            mesh: Mesh<'_>,
            transforms: Transforms,
            state: &DrawState,
        ) -> DrawStats {
            let shading = ShadingModel::Depth { near: 0.0, far: 1.0 };
            let object = Object { mesh, tangents: None, transforms, shading, material: Material::default() };
            let lights = Lighting { ambient: Vec3::ZERO, lights: &[], environment: None, space: ShadingSpace::Linear };
            draw_mesh(target, &object, &lights, state).unwrap().1
        }
        let (mut whole, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
        let mut target = Target::new(Rgb888(&mut whole), &mut depth[..], w, h).unwrap();
        target.clear(Vec3::ZERO);
        let all = depth_view(&mut target, mesh, transforms, &state);
        assert!(all.fragments > 1000 && all.clipped > 0 && all.invalid == 1, "{all:?}");

        let mut memory = GeometryMemory::default();
        for rows in [1, 7, h] {
            let bands = Bands::new(w, h, rows, Samples::One).unwrap();
            let geometry = memory.compute(&mesh, &clip, &state, bands, workers).unwrap();
            let expected = mesh.triangle_count().div_ceil(MAX_PART_TRIANGLES);
            let expected = expected.max(workers.threads().min(mesh.triangle_count() / TRIANGLES_PER_PART)).max(1);
            assert_eq!(geometry.bins.len(), expected);
            // Binning counts each triangle once, a clipped one by what its pieces come to, as the whole draw does.
            let binned = DrawStats { fragments: all.fragments, ..geometry.stats() };
            assert_eq!(binned, all, "binning counts each triangle once");
            let mut counts = vec![0; bands.count() as usize];
            geometry.count_by_band(&mut counts);
            let (mut banded, mut depth) = (vec![0u32; (w * h) as usize], vec![0f32; (w * h) as usize]);
            let mut fragments = 0;
            for b in 0..bands.count() {
                let rows = bands.rows(b);
                let span = (rows.start * w) as usize..(rows.end * w) as usize;
                let (color, depth) = (&mut banded[span.clone()], &mut depth[span]);
                let mut band = Target::band(Rgb888(color), depth, w, h, rows.clone()).unwrap();
                band.clear(Vec3::ZERO);
                let stats = depth_view(&mut band.for_draw(geometry.lend()), mesh, transforms, &state);
                assert_eq!(stats.triangles_in, counts[b as usize] as u64, "band {b} takes what was counted for it");
                if bands.count() > 1 {
                    assert!(stats.triangles_in < mesh.triangle_count() as u64 / 2, "band {b}: {stats:?}");
                }
                fragments += stats.fragments;
            }
            assert!(whole == banded, "bands of {rows} rows, {depth_test:?}");
            assert_eq!(fragments, all.fragments);
        }
    }
}
