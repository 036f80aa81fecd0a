//! Fragments gathered for shaders that shade several at once.
//!
//! A shader with [`Shader::BATCHED`](super::Shader::BATCHED) set gets the covered, depth-tested fragments of a
//! triangle in groups of up to [`BATCH_SIZE`] instead of one at a time. Work that varies per draw but not per pixel
//! (which maps a material has, which lights cast shadows) can then be decided once per group and run as a tight
//! loop over it, so the choice costs nothing per pixel and the number of compiled loops is a sum over the effects,
//! not a product.
//!
//! A batch does not hold interpolated varyings: it holds its triangle's varyings once (at the first vertex, and
//! the differences to the other two) and each fragment's two interpolation weights. A shader interpolates what
//! it needs lane by lane, over whole columns of weights, instead of the pixel loop interpolating every varying one
//! fragment at a time; both compute `v0 + d1 * w1 + d2 * w2` in that order, so the values are the same.

use super::{Fragment, Varyings};

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

/// Up to [`BATCH_SIZE`] fragments of one triangle, in the order the pixel loop found them, with their triangle's
/// varyings and their weights.
#[derive(Clone, Debug)]
pub struct FragmentBatch<V> {
    len: usize,
    front_facing: bool,
    /// The varyings at the triangle's first vertex and their differences to the second and the third.
    triangle: [V; 3],
    /// The weights of the second and third vertex: numerators as pushed, then, once [`Self::resolve`] has run,
    /// the weights themselves.
    w1: Lanes,
    w2: Lanes,
    /// The weights' common denominator per fragment, until resolved.
    denominator: Lanes,
    x: [u32; BATCH_SIZE],
    y: [u32; BATCH_SIZE],
    depth: Lanes,
    indices: [usize; BATCH_SIZE],
}

impl<V: Varyings> FragmentBatch<V> {
    /// An empty batch for a triangle whose varyings are `v0` at its first vertex and `v0 + d1`, `v0 + d2` at the
    /// others.
    #[inline(always)]
    pub(crate) fn new(v0: V, d1: V, d2: V, front_facing: bool) -> Self {
        Self {
            len: 0,
            front_facing,
            triangle: [v0, d1, d2],
            w1: [0.0; BATCH_SIZE],
            w2: [0.0; BATCH_SIZE],
            denominator: [1.0; BATCH_SIZE],
            x: [0; BATCH_SIZE],
            y: [0; BATCH_SIZE],
            depth: [0.0; BATCH_SIZE],
            indices: [0; BATCH_SIZE],
        }
    }

    /// A batch of one fragment with `varyings` (a triangle whose three vertices carry them): for shading a single
    /// fragment through a shader's batch stage, as its own [`Shader::fragment`](super::Shader::fragment) may.
    pub fn single(fragment: &Fragment, varyings: V) -> Self {
        let zero = varyings.sub(&varyings);
        let mut batch = Self::new(varyings, zero, zero, fragment.front_facing);
        batch.push(fragment.x, fragment.y, fragment.depth, [0.0, 0.0, 1.0], 0);
        batch.resolve();
        batch
    }

    /// Adds the fragment at `(x, y)` with `depth` and the weights `n1 / d`, `n2 / d` of the second and third
    /// vertex given as `[n1, n2, d]`, to be written to buffer position `index`; true when the batch is now full.
    /// The weights are divided out for the whole batch by [`Self::resolve`].
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
        self.len = i + 1;
        self.len == BATCH_SIZE
    }

    /// Turns the pushed fractions into weights, `n * (1 / d)` in every lane at once (as
    /// [`super::interpolator::Interpolator::weights`] computes one); before shading, once.
    #[inline(always)]
    pub(crate) fn resolve(&mut self) {
        for i in 0..lanes(self.len) {
            let r = 1.0 / self.denominator[i];
            self.w1[i] *= r;
            self.w2[i] *= r;
            self.denominator[i] = 1.0;
        }
    }

    /// Forgets the fragments.
    #[inline(always)]
    pub(crate) fn clear(&mut self) {
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
        Fragment { x: self.x[i], y: self.y[i], depth: self.depth[i], front_facing: self.front_facing }
    }

    /// The interpolated varyings of fragment `i` (`i < len`).
    #[inline(always)]
    pub fn varyings(&self, i: usize) -> V {
        let [v0, d1, d2] = &self.triangle;
        v0.interpolate(d1, self.w1[i], d2, self.w2[i])
    }

    /// The triangle's varyings at its first vertex and their differences to the second and the third: with
    /// [`Self::weights`], what a shader interpolates lane by lane.
    #[inline(always)]
    pub fn triangle(&self) -> &[V; 3] {
        &self.triangle
    }

    /// The weights of the second and the third vertex, one lane per fragment (all [`BATCH_SIZE`] lanes; those
    /// past [`Self::len`] are finite).
    #[inline(always)]
    pub fn weights(&self) -> (&Lanes, &Lanes) {
        (&self.w1, &self.w2)
    }

    /// Each fragment's depth (as the depth test saw it), one lane per fragment (all [`BATCH_SIZE`] lanes; those
    /// past [`Self::len`] are finite).
    #[inline(always)]
    pub fn depths(&self) -> &Lanes {
        &self.depth
    }

    /// Where each fragment goes in the target's buffers.
    #[inline(always)]
    pub(crate) fn indices(&self) -> &[usize] {
        &self.indices[..self.len]
    }
}
