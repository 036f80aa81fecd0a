//! The pixel loop of a multisampled target: coverage and depth at four samples per pixel, one shading per pixel.
//!
//! Each row of the triangle's box (widened by the samples' reach) skips to its first pixel with a covered sample,
//! testing each edge's largest sample value (`Edges::sample_reach`), and is left at the first pixel past the
//! covered ones (`Edges::closed`); each pixel between has its edge functions evaluated at the four
//! [`SAMPLE_POSITIONS`](crate::target::SAMPLE_POSITIONS) from their values at its centre: fixed-point edges as
//! eight times their value (the positions are eighths of a pixel), whole numbers, so coverage is exact and the
//! top-left rule gives each sample on a shared edge to exactly one triangle. Each covered sample is tested at its
//! own depth. A pixel with a sample that passes is shaded once, at its centre when the triangle covers the
//! centre and otherwise at its first covered sample, so that its varyings are never extrapolated beyond the
//! triangle (what GPUs call centroid sampling); its colour goes to the samples that passed.
//!
//! A band of rows gets the frame's samples, as a band gets the frame's pixels: every value is computed from frame
//! coordinates.

use super::{Coverage, Stages, shade_batch};
use crate::math::Vec3;
use crate::pipeline::batch::{BATCH_SIZE, FragmentBatch};
use crate::pipeline::depth_stage::DepthStage;
use crate::pipeline::edges::Edges;
use crate::pipeline::interpolator::Interpolator;
use crate::pipeline::{Fragment, Shader, Varyings};
use crate::target::{ColorBuffer, DepthBuffer, SAMPLE_COUNT, Target, VertexMemory};

impl<E: Edges> Coverage<E> {
    /// Whether any sample of the box's pixels is covered: [`Coverage::covers_a_centre`] on a multisampled target.
    #[inline(always)]
    pub(super) fn covers_a_sample(&self) -> bool {
        let (f, edges) = (&self.frame, &self.edges);
        let offsets = edges.sample_offsets();
        for y in f.y0..=f.y1 {
            let mut centre = edges.at(f.x0, y);
            for _ in f.x0..=f.x1 {
                let at = offsets.map(|o| edges.at_sample(&centre, &o));
                if at.iter().any(|a| edges.covered(a)) {
                    return true;
                }
                if at.iter().all(|a| edges.closed(a)) {
                    break;
                }
                centre = edges.step(centre);
            }
        }
        false
    }

    /// [`Coverage::fill`] on a multisampled target: the same stages, shaders and counts (a fragment is a pixel with
    /// a sample that passed), with coverage and depth per sample.
    #[inline(always)]
    pub(super) fn fill_multisample<S, I, Z, C, D, M>(
        &self,
        stages: &Stages<'_, S, I, Z>,
        face: &S::Face,
        varyings: [&S::Varyings; 3],
        batch: &mut FragmentBatch<S::Varyings, S::Face>,
        target: &mut Target<C, D, M>,
    ) -> u64
    where
        S: Shader,
        I: Interpolator,
        Z: DepthStage,
        C: ColorBuffer,
        D: DepthBuffer,
        M: VertexMemory,
    {
        let (f, edges) = (&self.frame, &self.edges);
        let (offsets, reach) = (edges.sample_offsets(), edges.sample_reach());
        let triangle = stages.triangle_varyings(f, edges, varyings);
        let batched = S::FRAGMENT_STAGE && S::BATCHED;
        if batched {
            batch.start_triangle([triangle.v0, triangle.d1, triangle.d2], *face, f.front_facing, triangle.steps);
        }
        // A draw that may discard fragments compares depths first and tests them once a fragment is kept.
        let cutout = S::CUTOUT && stages.cutout;
        let width = target.width() as usize;
        let row0 = target.rows().start as i32;
        let mut shaded = 0u64;
        for y in f.y0..=f.y1 {
            // Skip the pixels left of the covered ones with one test per pixel, at each edge's largest sample
            // value, as the single-sample loop skips with its centre's; and leave the row if that fails an edge
            // that only falls to the right.
            let (mut next, mut x0) = (edges.at(f.x0, y), f.x0);
            while x0 <= f.x1 {
                let largest = edges.at_sample(&next, &reach);
                if edges.covered(&largest) {
                    break;
                }
                if edges.closed(&largest) {
                    x0 = f.x1 + 1;
                    break;
                }
                next = edges.step(next);
                x0 += 1;
            }
            for x in x0..=f.x1 {
                let centre = next;
                next = edges.step(next);
                let at: [E::At; SAMPLE_COUNT] = core::array::from_fn(|s| edges.at_sample(&centre, &offsets[s]));
                let covered = (0..SAMPLE_COUNT).fold(0u8, |m, s| m | (u8::from(edges.covered(&at[s])) << s));
                if covered == 0 {
                    // Past the covered pixels once every sample has failed an edge that only falls to the right.
                    if at.iter().all(|a| edges.closed(a)) {
                        break;
                    }
                    continue;
                }
                let first = ((y - row0) as usize * width + x as usize) * SAMPLE_COUNT;
                let mut depths = [0.0f32; SAMPLE_COUNT];
                let mut passed = 0u8;
                for s in (0..SAMPLE_COUNT).filter(|s| covered >> s & 1 == 1) {
                    let w = edges.sample_weights(&at[s]);
                    depths[s] = f.depth(w[1], w[2]);
                    let pass = if cutout {
                        stages.depth.nearer(&target.depth, first + s, depths[s])
                    } else {
                        stages.depth.test(&mut target.depth, first + s, depths[s])
                    };
                    passed |= u8::from(pass) << s;
                }
                if passed == 0 {
                    continue;
                }
                let ef = if edges.covered(&centre) {
                    edges.weights(&centre)
                } else {
                    edges.sample_weights(&at[covered.trailing_zeros() as usize])
                };
                let z = f.depth(ef[1], ef[2]);
                if batched {
                    if !cutout {
                        shaded += 1;
                    }
                    let fractions = stages.interpolator.fractions(&triangle.setup, ef);
                    if batch.push_samples(x as u32, y as u32, z, fractions, first, (passed, depths)) {
                        shaded += shade_batch(stages, batch, target);
                    }
                    continue;
                }
                let fragment = Fragment { x: x as u32, y: y as u32, depth: z, front_facing: f.front_facing };
                if cutout {
                    let (var, slopes) = stages.interpolate(&triangle, ef);
                    if stages.shader.kept(&fragment, face, &var, &slopes) {
                        let color = stages.shader.fragment(&fragment, face, &var, &slopes);
                        let written = write_tested(&stages.depth, target, first, (passed, &depths), color);
                        shaded += u64::from(written);
                    }
                } else {
                    // A constant: a depth-only shader compiles without the fragment stage.
                    if S::FRAGMENT_STAGE {
                        let (var, slopes) = stages.interpolate(&triangle, ef);
                        target.color.write_samples(
                            first,
                            passed,
                            stages.shader.fragment(&fragment, face, &var, &slopes),
                        );
                    }
                    shaded += 1;
                }
            }
        }
        shaded
    }
}

/// Tests the samples in `mask` from sample index `first` at their `depths` and writes `color` to those that pass:
/// whether any did.
#[inline(always)]
fn write_tested<Z: DepthStage, C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
    depth: &Z,
    target: &mut Target<C, D, M>,
    first: usize,
    (mask, depths): (u8, &[f32; SAMPLE_COUNT]),
    color: Vec3,
) -> bool {
    let mut passed = 0u8;
    for s in (0..SAMPLE_COUNT).filter(|s| mask >> s & 1 == 1) {
        passed |= u8::from(depth.test(&mut target.depth, first + s, depths[s])) << s;
    }
    target.color.write_samples(first, passed, color);
    passed != 0
}

/// [`shade_batch`]'s writes on a multisampled target: each fragment's colour to its samples; in a cut-out draw
/// those of the kept fragments that pass the depth test now. Returns the fragments written in a cut-out draw (with
/// a sample that passed), 0 otherwise.
#[inline(always)]
pub(super) fn write_batch<Z: DepthStage, V: Varyings, F: Copy, C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
    depth: &Z,
    batch: &FragmentBatch<V, F>,
    kept: Option<&[bool; BATCH_SIZE]>,
    colors: &[Vec3; BATCH_SIZE],
    target: &mut Target<C, D, M>,
) -> u64 {
    let fragments = batch.indices().iter().zip(batch.samples()).zip(colors).enumerate();
    let mut written = 0;
    for (i, ((&first, (mask, depths)), &color)) in fragments {
        match kept {
            Some(kept) => written += u64::from(kept[i] && write_tested(depth, target, first, (mask, depths), color)),
            None => target.color.write_samples(first, mask, color),
        }
    }
    written
}
