//! Fragments gathered for shaders that shade several at once.
//!
//! A shader with [`Shader::BATCHED`](super::Shader::BATCHED) set gets the covered, depth-tested fragments of a
//! draw in groups of up to [`BATCH_SIZE`] instead of one at a time. Work that varies per draw but not per pixel
//! (which maps a material has, which lights cast shadows) can then be decided once per group and run as a tight
//! loop over it, so the choice costs nothing per pixel and the number of compiled loops is a sum over the effects,
//! not a product.
//!
//! A batch spans triangles: a dense mesh whose triangles cover a pixel or two each still shades full batches, so
//! the per-batch work (deciding, resolving, the lane loops) is paid per [`BATCH_SIZE`] fragments, not per
//! triangle. It holds each triangle's varyings once (at its first vertex, and the differences to the other two),
//! and per fragment the triangle it belongs to and its two interpolation weights; [`FragmentBatch::resolve`]
//! interpolates them with [`Varyings::interpolate`], `v0 + d1 * w1 + d2 * w2`, the arithmetic of the per-pixel
//! loop, so the values are the same.
//!
//! Depth is tested and written when a fragment is pushed, colour when its batch is shaded: the colours are written
//! in the order the fragments were pushed, so a later fragment over the same pixel still wins. In a draw that
//! discards fragments (an alpha cut-out) depth is only compared when a fragment is pushed, and tested and written
//! with its colour, in the same order, if it is kept.
//!
//! On a multisampled target a fragment is a pixel with the samples it covers: it carries their mask and depths, and
//! its colour is written to the samples whose depth test passed.

use super::slopes::{FractionSteps, Slopes};
use super::{Fragment, Varyings};
use crate::target::SAMPLE_COUNT;

/// True where the target has SIMD registers (x86-64, AArch64, WebAssembly with `simd128`): lane loops then run
/// over every lane, a constant count the compiler widens to SIMD instructions.
const SIMD: bool = cfg!(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"));

/// The most fragments a [`FragmentBatch`] holds: 32 where the target has SIMD registers, 1 elsewhere.
///
/// A target without SIMD (a Cortex-M4) computes one lane at a time, so a larger batch saves no instruction per
/// fragment and costs stack and code: on the firmware's frame (`core/firmware/measure.sh`, 2026-11-26), batches of
/// 8 took 40,652 bytes of the core's code and 91.7 million instructions, batches of 1 25,084 bytes and 88.6
/// million: the lane loops compile to the code of one fragment.
pub const BATCH_SIZE: usize = if SIMD { 32 } else { 1 };
// A fragment names its triangle's slot in a `u8`.
const _: () = assert!(BATCH_SIZE <= 256);

/// The lanes a lane-wise loop over a batch of `len` fragments runs over: all [`BATCH_SIZE`] where the target has
/// SIMD registers (a constant count, which the compiler widens; the lanes past `len` hold finite values nobody
/// reads), the first `len` elsewhere. Either way lane `i < len` computes the same value.
#[must_use]
#[inline(always)]
pub const fn lanes(len: usize) -> usize {
    if SIMD || len > BATCH_SIZE { BATCH_SIZE } else { len }
}

/// One `f32` per fragment of a batch: lanes past the batch's length hold finite values nobody should read.
pub type Lanes = [f32; BATCH_SIZE];

/// What a batch keeps of one triangle whose fragments it holds.
#[derive(Clone, Copy, Debug)]
struct Triangle<V, F> {
    /// The varyings at its first vertex and their differences to the second and the third.
    varyings: [V; 3],
    face: F,
    front_facing: bool,
    /// How its weight fractions change per pixel (zero when the draw asks for no [`Slopes`]).
    steps: FractionSteps,
}

/// Up to [`BATCH_SIZE`] fragments of one draw, in the order the pixel loop found them, with their triangles'
/// varyings and faces (`V` and `F`: the shader's [`Varyings`](super::Shader::Varyings) and
/// [`Face`](super::Shader::Face)).
#[derive(Clone, Debug)]
pub struct FragmentBatch<V, F> {
    len: usize,
    /// The triangles the fragments belong to; slot `current` is the one being rasterized.
    triangles: [Triangle<V, F>; BATCH_SIZE],
    current: usize,
    /// Whether slot `current` has fragments in the batch (a triangle takes a slot only once it has one, so
    /// there are never more triangles than fragments).
    current_used: bool,
    /// Each fragment's triangle slot.
    triangle: [u8; BATCH_SIZE],
    /// The weights of each fragment's triangle's second and third vertex: numerators as pushed, then, once
    /// [`Self::resolve`] has run, the weights themselves.
    w1: Lanes,
    w2: Lanes,
    /// The weights' common denominator per fragment, until resolved; then its reciprocal.
    denominator: Lanes,
    x: [u32; BATCH_SIZE],
    y: [u32; BATCH_SIZE],
    depth: Lanes,
    indices: [usize; BATCH_SIZE],
    /// On a multisampled target: each fragment's samples (bit `s` for sample `s`) and their depths.
    samples: [u8; BATCH_SIZE],
    sample_depths: [[f32; SAMPLE_COUNT]; BATCH_SIZE],
    /// The interpolated varyings, once resolved.
    varyings: [V; BATCH_SIZE],
}

impl<V: Varyings, F: Copy> FragmentBatch<V, F> {
    /// An empty batch. Every lane starts as a fragment with varyings `v` and face `face`, so lanes never filled
    /// hold finite values (when these are).
    #[inline(always)]
    pub(crate) fn new(v: V, face: F) -> Self {
        let zero = v.sub(&v);
        Self {
            len: 0,
            triangles: [Triangle {
                varyings: [v, zero, zero],
                face,
                front_facing: true,
                steps: FractionSteps::default(),
            }; BATCH_SIZE],
            current: 0,
            current_used: false,
            triangle: [0; BATCH_SIZE],
            w1: [0.0; BATCH_SIZE],
            w2: [0.0; BATCH_SIZE],
            denominator: [1.0; BATCH_SIZE],
            x: [0; BATCH_SIZE],
            y: [0; BATCH_SIZE],
            depth: [0.0; BATCH_SIZE],
            indices: [0; BATCH_SIZE],
            samples: [0; BATCH_SIZE],
            sample_depths: [[0.0; SAMPLE_COUNT]; BATCH_SIZE],
            varyings: [v; BATCH_SIZE],
        }
    }

    /// A batch of one fragment with `varyings` changing by `slopes` and `face`: for shading a single fragment
    /// through a shader's batch stage, as its own [`Shader::fragment`](super::Shader::fragment) may. Its
    /// triangle carries `varyings` plus `slopes.dx` and `slopes.dy` at its other vertices, with weights 0, and
    /// weight slopes `(1, 0)` and `(0, 1)`: [`Self::varyings`] and [`Self::slopes`] give back what was passed
    /// (finite slopes; a zero's sign may change).
    pub fn single(fragment: &Fragment, face: F, varyings: V, slopes: &Slopes<V>) -> Self {
        let mut batch = Self::new(varyings, face);
        let steps = FractionSteps { dx: [1.0, 0.0, 0.0], dy: [0.0, 1.0, 0.0] };
        batch.start_triangle([varyings, slopes.dx, slopes.dy], face, fragment.front_facing, steps);
        batch.push(fragment.x, fragment.y, fragment.depth, [0.0, 0.0, 1.0], 0);
        batch.resolve();
        batch
    }

    /// Makes the fragments pushed next belong to a triangle whose varyings are `v0` at its first vertex and
    /// `v0 + d1`, `v0 + d2` at the others, and whose weight fractions change by `steps` per pixel.
    #[inline(always)]
    pub(crate) fn start_triangle(&mut self, [v0, d1, d2]: [V; 3], face: F, front_facing: bool, steps: FractionSteps) {
        if self.current_used {
            // Below `len` (each used slot has a fragment), which is below `BATCH_SIZE` between pushes.
            self.current = (self.current + 1).min(BATCH_SIZE - 1);
            self.current_used = false;
        }
        self.triangles[self.current] = Triangle { varyings: [v0, d1, d2], face, front_facing, steps };
    }

    /// Adds a fragment of the current triangle at `(x, y)` with `depth` and the weights `n1 / d`, `n2 / d` of the
    /// second and third vertex given as `[n1, n2, d]`, to be written to buffer position `index`; true when the
    /// batch is now full. The weights are divided out for the whole batch by [`Self::resolve`].
    #[inline(always)]
    pub(crate) fn push(&mut self, x: u32, y: u32, depth: f32, [w1, w2, d]: [f32; 3], index: usize) -> bool {
        // `len < BATCH_SIZE` always holds here: the pixel loop empties a full batch before pushing again.
        let i = self.len.min(BATCH_SIZE - 1);
        self.x[i] = x;
        self.y[i] = y;
        self.depth[i] = depth;
        self.w1[i] = w1;
        self.w2[i] = w2;
        self.denominator[i] = d;
        self.indices[i] = index;
        self.triangle[i] = self.current as u8;
        self.current_used = true;
        self.len = i + 1;
        self.len == BATCH_SIZE
    }

    /// [`Self::push`] for a pixel of a multisampled target, `index` its first sample: its colour goes to the
    /// samples in `mask`, whose depths are `depths`.
    #[inline(always)]
    pub(crate) fn push_samples(
        &mut self,
        x: u32,
        y: u32,
        depth: f32,
        fractions: [f32; 3],
        index: usize,
        (mask, depths): (u8, [f32; SAMPLE_COUNT]),
    ) -> bool {
        let i = self.len.min(BATCH_SIZE - 1);
        self.samples[i] = mask;
        self.sample_depths[i] = depths;
        self.push(x, y, depth, fractions, index)
    }

    /// Turns the pushed fractions into weights, `n * (1 / d)` in every lane at once (as
    /// [`super::interpolator::Interpolator::weights`] computes one), and interpolates each fragment's varyings;
    /// before shading, once.
    #[inline(always)]
    pub(crate) fn resolve(&mut self) {
        for i in 0..lanes(self.len) {
            let r = 1.0 / self.denominator[i];
            self.w1[i] *= r;
            self.w2[i] *= r;
            self.denominator[i] = r;
        }
        for i in 0..self.len {
            let [v0, d1, d2] = &self.triangles[usize::from(self.triangle[i])].varyings;
            self.varyings[i] = v0.interpolate(d1, self.w1[i], d2, self.w2[i]);
        }
    }

    /// Forgets the fragments. The current triangle stays current: its next fragments go into the emptied batch.
    #[inline(always)]
    pub(crate) fn clear(&mut self) {
        self.triangles[0] = self.triangles[self.current];
        self.current = 0;
        self.current_used = false;
        self.len = 0;
    }

    /// Number of fragments held.
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when no fragment is held.
    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Fragment `i` (`i < len`).
    #[inline(always)]
    pub fn fragment(&self, i: usize) -> Fragment {
        let front_facing = self.triangles[usize::from(self.triangle[i])].front_facing;
        Fragment { x: self.x[i], y: self.y[i], depth: self.depth[i], front_facing }
    }

    /// The interpolated varyings of fragment `i` (`i < len`; any lane holds finite values when the triangles'
    /// varyings are finite).
    #[inline(always)]
    pub fn varyings(&self, i: usize) -> &V {
        &self.varyings[i]
    }

    /// The screen-space slopes of fragment `i`'s varyings (`i < len`; zero in a draw that asks for none,
    /// [`Shader::slopes`](super::Shader::slopes)).
    #[inline(always)]
    pub fn slopes(&self, i: usize) -> Slopes<V> {
        self.slopes_of(i, |v| *v)
    }

    /// The screen-space slopes of one part of fragment `i`'s varyings, `part` of them (`i < len`): the
    /// arithmetic of [`Self::slopes`] on that part alone.
    #[inline(always)]
    pub fn slopes_of<T: Varyings>(&self, i: usize, part: impl Fn(&V) -> T) -> Slopes<T> {
        let triangle = &self.triangles[usize::from(self.triangle[i])];
        let weight_slopes = triangle.steps.weight_slopes(self.w1[i], self.w2[i], self.denominator[i]);
        Slopes::of(&part(&triangle.varyings[1]), &part(&triangle.varyings[2]), weight_slopes)
    }

    /// The face of fragment `i`'s triangle (`i < BATCH_SIZE`).
    #[inline(always)]
    pub fn face(&self, i: usize) -> &F {
        &self.triangles[usize::from(self.triangle[i])].face
    }

    /// Each fragment's depth (as the depth test saw it), one lane per fragment (all [`BATCH_SIZE`] lanes; those
    /// past [`Self::len`] are finite).
    #[inline(always)]
    pub fn depths(&self) -> &Lanes {
        &self.depth
    }

    /// Where each fragment goes in the target's buffers (on a multisampled target, its first sample).
    #[inline(always)]
    pub(crate) fn indices(&self) -> &[usize] {
        &self.indices[..self.len]
    }

    /// Each fragment's samples and their depths, as [`Self::push_samples`] gave them.
    #[inline(always)]
    pub(crate) fn samples(&self) -> impl Iterator<Item = (u8, &[f32; SAMPLE_COUNT])> {
        self.samples[..self.len].iter().copied().zip(&self.sample_depths[..self.len])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fragments of several triangles keep their own triangle's varyings, face and facing, also for the triangle
    /// that spans a full batch and goes on in the emptied one.
    #[test]
    fn a_batch_spans_triangles() {
        let mut batch = FragmentBatch::new(0.0f32, 0u32);
        let mut expected = [(0u32, 0.0f32); 3 * BATCH_SIZE];
        let mut fragments = 0;
        // Triangle t: varyings 10 t at its first vertex, +1 and +2 at the others; face t; front-facing when even.
        for (t, count) in [(1u32, 1), (2, 0), (3, 2), (4, BATCH_SIZE + 3), (5, 1)] {
            let v0 = 10.0 * t as f32;
            batch.start_triangle([v0, 1.0, 2.0], t, t % 2 == 0, FractionSteps::default());
            for k in 0..count {
                // Weights 0.25 and 0.5 as fractions over 2.
                let full = batch.push(k as u32, t, 0.5, [0.5, 1.0, 2.0], fragments);
                expected[fragments] = (t, v0 + 0.25 + 1.0);
                fragments += 1;
                if full {
                    batch.resolve();
                    for i in 0..batch.len() {
                        let (face, value) = expected[fragments - batch.len() + i];
                        assert_eq!((*batch.face(i), *batch.varyings(i)), (face, value));
                        assert_eq!(batch.fragment(i).front_facing, face % 2 == 0);
                    }
                    batch.clear();
                }
            }
        }
        batch.resolve();
        let len = batch.len();
        assert_eq!(len, (1 + 2 + BATCH_SIZE + 3 + 1) % BATCH_SIZE);
        for i in 0..len {
            let (face, value) = expected[fragments - len + i];
            assert_eq!((*batch.face(i), *batch.varyings(i)), (face, value));
            assert_eq!(batch.indices()[i], fragments - len + i);
        }
    }
}
