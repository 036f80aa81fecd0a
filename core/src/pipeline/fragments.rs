//! What the pixel loops gather for the fragment stage: each covered, depth-tested fragment's place, depth and
//! interpolation weights, and which triangle it belongs to.
//!
//! Nothing here depends on the shader: a batch's varyings and faces are kept beside it, by the shader's side of the
//! draw ([`super::batch::Triangles`]), in the slots these fragments name. So the pixel loops that fill it are
//! compiled once for every shader, varyings layout and buffer type, and hand each full batch to the fragment stage
//! ([`super::fragment_stage`]).
//!
//! A batch spans triangles: a dense mesh whose triangles cover a pixel or two each still shades full batches, so
//! the per-batch work is paid per [`BATCH_SIZE`] fragments, not per triangle. A triangle takes a slot once it has
//! a fragment in the batch, so there are never more triangles than fragments; a triangle still being rasterized
//! when its batch is shaded goes on in slot 0 of the emptied batch.

use super::columns::{BATCH_SIZE, Column, lanes};
use super::slopes::FractionSteps;
use crate::target::SAMPLE_COUNT;

// A fragment names its triangle's slot in a `u8`.
const _: () = assert!(BATCH_SIZE <= 256);

/// Up to [`BATCH_SIZE`] fragments of one draw, in the order the pixel loop found them.
#[derive(Clone, Debug)]
pub(crate) struct Fragments {
    len: usize,
    /// The slot of the triangle being rasterized.
    current: usize,
    /// Whether slot `current` has fragments in the batch.
    current_used: bool,
    /// Per slot: whether its triangle faces the camera, and how its weight fractions change per pixel (zero when
    /// the draw asks for no slopes).
    front_facing: [bool; BATCH_SIZE],
    steps: [FractionSteps; BATCH_SIZE],
    /// Each fragment's triangle slot.
    triangle: [u8; BATCH_SIZE],
    /// The weights of each fragment's triangle's second and third vertex: numerators as pushed, then, once
    /// [`Self::resolve`] has run, the weights themselves.
    w1: Column,
    w2: Column,
    /// The weights' common denominator per fragment, until resolved; then its reciprocal.
    denominator: Column,
    x: [u32; BATCH_SIZE],
    y: [u32; BATCH_SIZE],
    depth: Column,
    indices: [usize; BATCH_SIZE],
    /// On a multisampled target: each fragment's samples (bit `s` for sample `s`) and their depths.
    samples: [u8; BATCH_SIZE],
    sample_depths: [[f32; SAMPLE_COUNT]; BATCH_SIZE],
}

impl Fragments {
    /// An empty batch whose lanes all hold finite values (lane loops read every lane).
    pub fn new() -> Self {
        Self {
            len: 0,
            current: 0,
            current_used: false,
            front_facing: [true; BATCH_SIZE],
            steps: [FractionSteps::default(); BATCH_SIZE],
            triangle: [0; BATCH_SIZE],
            w1: Column::ZERO,
            w2: Column::ZERO,
            denominator: Column::splat(1.0),
            x: [0; BATCH_SIZE],
            y: [0; BATCH_SIZE],
            depth: Column::ZERO,
            indices: [0; BATCH_SIZE],
            samples: [0; BATCH_SIZE],
            sample_depths: [[0.0; SAMPLE_COUNT]; BATCH_SIZE],
        }
    }

    /// The slot that the next triangle started takes: where its varyings go before its fragments are pushed.
    #[inline(always)]
    pub fn next_slot(&self) -> usize {
        // Below `len` (each used slot has a fragment), which is below `BATCH_SIZE` between pushes.
        if self.current_used { (self.current + 1).min(BATCH_SIZE - 1) } else { self.current }
    }

    /// Makes the fragments pushed next belong to a new triangle, in slot [`Self::next_slot`].
    #[inline(always)]
    pub fn start_triangle(&mut self, front_facing: bool, steps: FractionSteps) {
        self.current = self.next_slot();
        self.current_used = false;
        self.front_facing[self.current] = front_facing;
        self.steps[self.current] = steps;
    }

    /// Adds a fragment of the current triangle at `(x, y)` with `depth` and the weights `n1 / d`, `n2 / d` of the
    /// second and third vertex given as `[n1, n2, d]`, to be written to buffer position `index`; true when the
    /// batch is now full. The weights are divided out for the whole batch by [`Self::resolve`].
    #[inline(always)]
    pub fn push(&mut self, x: u32, y: u32, depth: f32, [w1, w2, d]: [f32; 3], index: usize) -> bool {
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
    pub fn push_samples(
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

    /// Turns the pushed fractions into weights, `n * (1 / d)`, in every lane at once; before shading, once.
    #[inline(always)]
    pub fn resolve(&mut self) {
        for i in 0..lanes(self.len) {
            let r = 1.0 / self.denominator[i];
            self.w1[i] *= r;
            self.w2[i] *= r;
            self.denominator[i] = r;
        }
    }

    /// Forgets the fragments; the current triangle goes on in slot 0. Returns the slot it was in, for the
    /// varyings kept beside the batch to follow it.
    #[inline(always)]
    pub fn clear(&mut self) -> usize {
        let current = self.current;
        // Often there already (always, with one slot).
        if current != 0 {
            self.front_facing[0] = self.front_facing[current];
            self.steps[0] = self.steps[current];
        }
        self.current = 0;
        self.current_used = false;
        self.len = 0;
        current
    }

    /// Number of fragments held.
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Fragment `i`'s triangle slot.
    #[inline(always)]
    pub fn triangle(&self, i: usize) -> usize {
        usize::from(self.triangle[i])
    }

    /// Fragment `i`'s column and row in the frame.
    #[inline(always)]
    pub fn place(&self, i: usize) -> (u32, u32) {
        (self.x[i], self.y[i])
    }

    /// Whether fragment `i`'s triangle faces the camera.
    #[inline(always)]
    pub fn front_facing(&self, i: usize) -> bool {
        self.front_facing[self.triangle(i)]
    }

    /// Fragment `i`'s weights of its triangle's second and third vertex and the reciprocal of their denominator,
    /// once resolved.
    #[inline(always)]
    pub fn weights(&self, i: usize) -> [f32; 3] {
        [self.w1[i], self.w2[i], self.denominator[i]]
    }

    /// How fragment `i`'s weight fractions change per pixel.
    #[inline(always)]
    pub fn steps(&self, i: usize) -> &FractionSteps {
        &self.steps[self.triangle(i)]
    }

    /// Each fragment's depth (as the depth test saw it), one lane per fragment (all [`BATCH_SIZE`] lanes; those
    /// past [`Self::len`] are finite).
    #[inline(always)]
    pub fn depths(&self) -> &Column {
        &self.depth
    }

    /// Where each fragment goes in the target's buffers (on a multisampled target, its first sample).
    #[inline(always)]
    pub fn indices(&self) -> &[usize] {
        &self.indices[..self.len]
    }

    /// Each fragment's samples and their depths, as [`Self::push_samples`] gave them.
    #[inline(always)]
    pub fn samples(&self) -> impl Iterator<Item = (u8, &[f32; SAMPLE_COUNT])> {
        self.samples[..self.len].iter().copied().zip(&self.sample_depths[..self.len])
    }
}
