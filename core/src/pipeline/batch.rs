//! Fragments gathered for shaders that shade several at once.
//!
//! A shader with [`Shader::BATCHED`](super::Shader::BATCHED) set gets the covered, depth-tested fragments of a
//! triangle in groups of up to [`BATCH_SIZE`] instead of one at a time. Work that varies per draw but not per pixel
//! (which maps a material has, which lights cast shadows) can then be decided once per group and run as a tight
//! loop over it, so the choice costs nothing per pixel and the number of compiled loops is a sum over the effects,
//! not a product.

use super::Fragment;

/// The most fragments a [`FragmentBatch`] holds.
pub const BATCH_SIZE: usize = 32;

/// Up to [`BATCH_SIZE`] fragments of one triangle with their interpolated varyings, in the order the pixel loop
/// found them.
#[derive(Clone, Debug)]
pub struct FragmentBatch<V> {
    len: usize,
    fragments: [Fragment; BATCH_SIZE],
    varyings: [V; BATCH_SIZE],
    indices: [usize; BATCH_SIZE],
}

impl<V: Copy> FragmentBatch<V> {
    /// An empty batch; `fill` is a placeholder for the unused slots.
    pub(crate) fn new(fill: V) -> Self {
        let fragment = Fragment { x: 0, y: 0, depth: 0.0, front_facing: true };
        Self { len: 0, fragments: [fragment; BATCH_SIZE], varyings: [fill; BATCH_SIZE], indices: [0; BATCH_SIZE] }
    }

    /// A batch holding `fragments` with `varyings` (the shorter of the two decides the length, at most
    /// [`BATCH_SIZE`]): for shading fragments without a draw, as tests and a shader's own
    /// [`Shader::fragment`](super::Shader::fragment) do.
    pub fn from_fragments(fragments: &[Fragment], varyings: &[V]) -> Option<Self> {
        let first = *varyings.first()?;
        let mut batch = Self::new(first);
        for (f, v) in fragments.iter().zip(varyings).take(BATCH_SIZE) {
            batch.push(*f, *v, 0);
        }
        Some(batch)
    }

    /// Adds a fragment that will be written to buffer position `index`; true when the batch is now full.
    #[inline(always)]
    pub(crate) fn push(&mut self, fragment: Fragment, varyings: V, index: usize) -> bool {
        // `len < BATCH_SIZE` always holds here: the pixel loop empties a full batch before pushing again.
        let i = self.len.min(BATCH_SIZE - 1);
        self.fragments[i] = fragment;
        self.varyings[i] = varyings;
        self.indices[i] = index;
        self.len = i + 1;
        self.len == BATCH_SIZE
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

    /// The fragments.
    #[inline(always)]
    pub fn fragments(&self) -> &[Fragment] {
        &self.fragments[..self.len]
    }

    /// Their interpolated varyings, one per fragment.
    #[inline(always)]
    pub fn varyings(&self) -> &[V] {
        &self.varyings[..self.len]
    }

    /// Where each fragment goes in the target's buffers.
    #[inline(always)]
    pub(crate) fn indices(&self) -> &[usize] {
        &self.indices[..self.len]
    }
}
