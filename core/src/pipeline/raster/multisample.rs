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

use super::{Covered, Pass};
use crate::pipeline::edges::Edges;
use crate::pipeline::fragment_stage::{FragmentStage, Writes};
use crate::pipeline::interpolator::Interpolator;
use crate::target::{DepthBuffer, DepthView, SAMPLE_COUNT};

impl<E: Edges> Covered<'_, E> {
    /// Whether any sample of the box's pixels is covered: [`Covered::covers_a_centre`] on a multisampled target.
    #[inline(always)]
    pub(super) fn covers_a_sample(self) -> bool {
        let (f, edges) = (self.frame, self.edges);
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
}

/// The pixel loop of a multisampled target: the same fragments and counts as the single-sample loops (a fragment is
/// a pixel with a sample that passed), with coverage and depth per sample. A depth-only draw tests depth alone.
#[inline(always)]
pub(in crate::pipeline) fn fill_multisample<E: Edges, I: Interpolator, St: FragmentStage + ?Sized>(
    c: Covered<'_, E>,
    pass: &mut Pass<'_, St>,
) -> u64 {
    let interpolator = I::new(pass.interpolation);
    let setup = c.start(&interpolator, pass);
    let (f, edges) = (c.frame, c.edges);
    let (offsets, reach) = (edges.sample_offsets(), edges.sample_reach());
    // A draw that may discard fragments compares depths first and tests them once a fragment is kept.
    let cutout = pass.cutout;
    let Pass { target, fragments, stage, .. } = pass;
    let width = target.width() as usize;
    let row0 = target.rows().start as i32;
    let samples = target.samples();
    // Held here for the walk, lent to the fragment stage only by a cut-out draw (`Writes`).
    let mut depth = core::mem::replace(&mut target.depth, DepthView::Off);
    // At most one fragment per pixel of the frame, which has fewer than 2^32.
    let mut shaded = 0u32;
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
                let pass =
                    if cutout { depth.nearer(first + s, depths[s]) } else { depth.test_and_set(first + s, depths[s]) };
                passed |= u8::from(pass) << s;
            }
            if passed == 0 {
                continue;
            }
            if !cutout {
                shaded += 1;
            }
            let Some(fragments) = fragments else { continue };
            // Shaded at the centre when it is covered, else at the first covered sample.
            let ef = if edges.covered(&centre) {
                edges.weights(&centre)
            } else {
                edges.sample_weights(&at[covered.trailing_zeros() as usize])
            };
            let z = f.depth(ef[1], ef[2]);
            let fractions = interpolator.fractions(&setup, ef);
            if fragments.push_samples(x as u32, y as u32, z, fractions, first, (passed, depths)) {
                // A cut-out draw counts its fragments as written.
                let lent = if cutout { Some(&mut depth.view()) } else { None };
                let written = stage.flush(fragments, Writes { color: &mut target.color, depth: lent, samples });
                if cutout {
                    shaded += written as u32;
                }
            }
        }
    }
    target.depth = depth;
    u64::from(shaded)
}
