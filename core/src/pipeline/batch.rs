//! A batch of fragments as a shader sees it: up to [`BATCH_SIZE`] covered, depth-tested fragments of a draw, with
//! their triangles' varyings and faces.
//!
//! A shader's [`Shader::shade_batch`](super::Shader::shade_batch) gets the fragments of a draw in groups instead of
//! one at a time. Work that varies per draw but not per pixel (which maps a material has, which lights cast
//! shadows) can then be decided once per group and run as a tight loop over it, so the choice costs nothing per
//! pixel and the number of compiled loops is a sum over the effects, not a product.
//!
//! The pixel loops gather the fragments ([`super::fragments::Fragments`]: place, depth, weights, triangle slot),
//! and the shader's side of the draw keeps each triangle's varyings once, at its first vertex and as the
//! differences to the other two ([`Triangles`]); [`Triangles::resolve`] interpolates them with
//! [`Varyings::interpolate`], `v0 + d1 * w1 + d2 * w2`, the arithmetic of one fragment at a time, so the values are
//! the same.
//!
//! Depth is tested and written when a fragment is pushed, colour when its batch is shaded: the colours are written
//! in the order the fragments were pushed, so a later fragment over the same pixel still wins. In a draw that
//! discards fragments (an alpha cut-out) depth is only compared when a fragment is pushed, and tested and written
//! with its colour, in the same order, if it is kept.
//!
//! On a multisampled target a fragment is a pixel with the samples it covers: it carries their mask and depths, and
//! its colour is written to the samples whose depth test passed.

use super::fragments::Fragments;
use super::slopes::{FractionSteps, Slopes};
use super::{BATCH_SIZE, Column, Fragment, Varyings};

/// The varyings and faces of the triangles whose fragments a batch holds, slot by slot as
/// [`Fragments`] names them, and the fragments' interpolated varyings (`V` and `F`: the shader's
/// [`Varyings`](super::Shader::Varyings) and [`Face`](super::Shader::Face)).
#[derive(Clone, Debug)]
pub(crate) struct Triangles<V, F> {
    /// Per slot: the varyings at the triangle's first vertex and their differences to the second and the third.
    varyings: [[V; 3]; BATCH_SIZE],
    faces: [F; BATCH_SIZE],
    /// The interpolated varyings, once resolved.
    resolved: [V; BATCH_SIZE],
}

impl<V: Varyings, F: Copy> Triangles<V, F> {
    /// Slots whose triangles all have varyings `v` (at every vertex) and face `face`, so that lanes never filled
    /// hold finite values (when these are).
    #[inline(always)]
    pub fn new(v: V, face: F) -> Self {
        let zero = v.sub(&v);
        Self { varyings: [[v, zero, zero]; BATCH_SIZE], faces: [face; BATCH_SIZE], resolved: [v; BATCH_SIZE] }
    }

    /// Puts a triangle into `slot`: its varyings `v0` at its first vertex and `v0 + d1`, `v0 + d2` at the others.
    #[inline(always)]
    pub fn set(&mut self, slot: usize, varyings: [V; 3], face: F) {
        self.varyings[slot] = varyings;
        self.faces[slot] = face;
    }

    /// Moves the triangle in slot `from` to slot 0, as [`Fragments::clear`] moves the current one.
    #[inline(always)]
    pub fn keep_current(&mut self, from: usize) {
        if from != 0 {
            self.varyings[0] = self.varyings[from];
            self.faces[0] = self.faces[from];
        }
    }

    /// Interpolates each fragment's varyings, once its weights are resolved ([`Fragments::resolve`]).
    #[inline(always)]
    pub fn resolve(&mut self, fragments: &Fragments) {
        for i in 0..fragments.len() {
            let [v0, d1, d2] = &self.varyings[fragments.triangle(i)];
            let [w1, w2, _] = fragments.weights(i);
            self.resolved[i] = v0.interpolate(d1, w1, d2, w2);
        }
    }

    /// The varyings of the triangle in slot 0 (where a batch holds one fragment, the one being rasterized: the pixel
    /// loops hand its fragments over one at a time, [`super::fragment_stage::FragmentStage::one`]), at a fragment of
    /// weight fractions `[n1, n2, d]`, their screen-space slopes (zero, in a draw that reads none), and its face:
    /// [`super::fragments::Fragments::resolve`] and [`Self::resolve`]'s arithmetic, and [`FragmentBatch::slopes`]'.
    #[inline(always)]
    pub fn one(&self, [n1, n2, d]: [f32; 3]) -> (V, Slopes<V>, &F) {
        let r = 1.0 / d;
        let (w1, w2) = (n1 * r, n2 * r);
        let [v0, d1, d2] = &self.varyings[0];
        let slopes = Slopes::of(d1, d2, FractionSteps::default().weight_slopes(w1, w2, r));
        (v0.interpolate(d1, w1, d2, w2), slopes, &self.faces[0])
    }

    /// The batch of `fragments` as a shader sees it.
    #[inline(always)]
    pub fn batch<'b>(&'b self, fragments: &'b Fragments) -> FragmentBatch<'b, V, F> {
        FragmentBatch { fragments, triangles: self }
    }
}

/// Up to [`BATCH_SIZE`] fragments of one draw, in the order the pixel loop found them, with their triangles'
/// varyings and faces (`V` and `F`: the shader's [`Varyings`](super::Shader::Varyings) and
/// [`Face`](super::Shader::Face)).
#[derive(Clone, Copy, Debug)]
pub struct FragmentBatch<'b, V, F> {
    fragments: &'b Fragments,
    triangles: &'b Triangles<V, F>,
}

impl<V: Varyings, F: Copy> FragmentBatch<'_, V, F> {
    /// Number of fragments held.
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.fragments.len()
    }

    /// True when no fragment is held.
    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Fragment `i` (`i < len`).
    #[inline(always)]
    pub fn fragment(&self, i: usize) -> Fragment {
        let (x, y) = self.fragments.place(i);
        Fragment { x, y, depth: self.fragments.depths()[i], front_facing: self.fragments.front_facing(i) }
    }

    /// The interpolated varyings of fragment `i` (`i < len`; any lane holds finite values when the triangles'
    /// varyings are finite).
    #[inline(always)]
    pub fn varyings(&self, i: usize) -> &V {
        &self.triangles.resolved[i]
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
        let [_, d1, d2] = &self.triangles.varyings[self.fragments.triangle(i)];
        let [w1, w2, r] = self.fragments.weights(i);
        let weight_slopes = self.fragments.steps(i).weight_slopes(w1, w2, r);
        Slopes::of(&part(d1), &part(d2), weight_slopes)
    }

    /// The face of fragment `i`'s triangle (`i < BATCH_SIZE`).
    #[inline(always)]
    pub fn face(&self, i: usize) -> &F {
        &self.triangles.faces[self.fragments.triangle(i)]
    }

    /// Each fragment's depth (as the depth test saw it), one lane per fragment (all [`BATCH_SIZE`] lanes; those
    /// past [`Self::len`] are finite).
    #[inline(always)]
    pub fn depths(&self) -> &Column {
        self.fragments.depths()
    }
}

/// One fragment as a batch of one: for shading a single fragment through a shader's batch stage, as its own
/// [`Shader::fragment`](super::Shader::fragment) may.
#[derive(Clone, Debug)]
pub struct OneFragment<V, F> {
    fragments: Fragments,
    triangles: Triangles<V, F>,
}

impl<V: Varyings, F: Copy> OneFragment<V, F> {
    /// `fragment` with `varyings` changing by `slopes` and `face`. Its triangle carries `varyings` plus
    /// `slopes.dx` and `slopes.dy` at its other vertices, with weights 0, and weight slopes `(1, 0)` and `(0, 1)`:
    /// the batch's [`FragmentBatch::varyings`] and [`FragmentBatch::slopes`] give back what was passed (finite
    /// slopes; a zero's sign may change).
    pub fn new(fragment: &Fragment, face: F, varyings: V, slopes: &Slopes<V>) -> Self {
        let mut fragments = Fragments::new();
        let mut triangles = Triangles::new(varyings, face);
        let steps = FractionSteps { dx: [1.0, 0.0, 0.0], dy: [0.0, 1.0, 0.0] };
        triangles.set(fragments.next_slot(), [varyings, slopes.dx, slopes.dy], face);
        fragments.start_triangle(fragment.front_facing, steps);
        fragments.push(fragment.x, fragment.y, fragment.depth, [0.0, 0.0, 1.0], 0);
        fragments.resolve();
        triangles.resolve(&fragments);
        Self { fragments, triangles }
    }

    /// The batch of the one fragment.
    pub fn batch(&self) -> FragmentBatch<'_, V, F> {
        self.triangles.batch(&self.fragments)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fragments of several triangles keep their own triangle's varyings, face and facing, also for the triangle
    /// that spans a full batch and goes on in the emptied one.
    #[test]
    fn a_batch_spans_triangles() {
        let mut fragments = Fragments::new();
        let mut triangles = Triangles::new(0.0f32, 0u32);
        let mut expected = [(0u32, 0.0f32); 3 * BATCH_SIZE];
        let mut pushed = 0;
        // Triangle t: varyings 10 t at its first vertex, +1 and +2 at the others; face t; front-facing when even.
        for (t, count) in [(1u32, 1), (2, 0), (3, 2), (4, BATCH_SIZE + 3), (5, 1)] {
            let v0 = 10.0 * t as f32;
            triangles.set(fragments.next_slot(), [v0, 1.0, 2.0], t);
            fragments.start_triangle(t % 2 == 0, FractionSteps::default());
            for k in 0..count {
                // Weights 0.25 and 0.5 as fractions over 2.
                let full = fragments.push(k as u32, t, 0.5, [0.5, 1.0, 2.0], pushed);
                expected[pushed] = (t, v0 + 0.25 + 1.0);
                pushed += 1;
                if full {
                    fragments.resolve();
                    triangles.resolve(&fragments);
                    let batch = triangles.batch(&fragments);
                    for i in 0..batch.len() {
                        let (face, value) = expected[pushed - batch.len() + i];
                        assert_eq!((*batch.face(i), *batch.varyings(i)), (face, value));
                        assert_eq!(batch.fragment(i).front_facing, face % 2 == 0);
                    }
                    let current = fragments.clear();
                    triangles.keep_current(current);
                }
            }
        }
        fragments.resolve();
        triangles.resolve(&fragments);
        let batch = triangles.batch(&fragments);
        let len = batch.len();
        assert_eq!(len, (1 + 2 + BATCH_SIZE + 3 + 1) % BATCH_SIZE);
        for i in 0..len {
            let (face, value) = expected[pushed - len + i];
            assert_eq!((*batch.face(i), *batch.varyings(i)), (face, value));
            assert_eq!(fragments.indices()[i], pushed - len + i);
        }
    }
}
