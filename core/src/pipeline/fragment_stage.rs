//! The fragment stage of a draw: shading a full batch with the draw's shader and writing it into the target.
//!
//! The pixel loops do not know the shader: they hand each full batch to the draw's [`FragmentStage`], one call
//! through a `dyn` reference per batch. [`ShaderStage`] is the one implementation, for each shader type: it keeps
//! the varyings and faces of the batch's triangles ([`Triangles`]), interpolates them, runs
//! [`Shader::shade_batch`] (and, in a draw that discards fragments, [`Shader::kept_batch`]), and writes the
//! colours with [`write_batch`], which is compiled once for every shader. Where a batch holds one fragment, most
//! draws skip the batch: [`FragmentStage::one`] shades each fragment as the pixel loop finds it.

use super::BATCH_SIZE;
use super::batch::Triangles;
use super::fragments::Fragments;
use super::{Fragment, Shader, Varyings};
use crate::math::Vec3;
use crate::target::{ColorBuffer, ColorView, DepthBuffer, DepthView, SAMPLE_COUNT, Samples};

/// Where a shaded batch goes: the target's colour, its depth for a cut-out draw (which tests depth again as it
/// writes), and its samples per pixel.
///
/// The pixel loops hold the depth buffer themselves while they walk a triangle (the loop compiled into a draw loop
/// as its [`crate::pipeline::raster::InlineDepth`] slice, tested without a branch on the format), and lend it only
/// to a cut-out draw's batches, as a view.
pub(crate) struct Writes<'w, 'b> {
    pub color: &'w mut ColorView<'b>,
    pub depth: Option<&'w mut DepthView<'w>>,
    pub samples: Samples,
}

/// Shades and writes a draw's full batches.
pub(crate) trait FragmentStage {
    /// Shades `fragments`, writes their colours in the order they were pushed, and empties the batch (the triangle
    /// being rasterized goes on in it). In a cut-out draw, only the fragments kept that still pass the depth test
    /// are written, depth and colour, and their number is returned; 0 otherwise (the pixel loops count those when
    /// they push them).
    fn flush(&mut self, fragments: &mut Fragments, writes: Writes<'_, '_>) -> u64;

    /// Shades `fragment`, of weight fractions `fractions`, and writes its colour at `index` of `color`, without
    /// the batch: where a batch holds one fragment ([`BATCH_SIZE`] is 1), in a draw of one sample per pixel that
    /// neither discards fragments nor reads slopes ([`one_at_a_time`]), the pixel loops hand each fragment over as
    /// it passes the depth test, so that its place, weights and index are not stored in the batch and read back.
    /// The arithmetic of a batch of it ([`Triangles::one`], the shader's [`Shader::fragment`], the colour view's
    /// write).
    fn one(&mut self, fragment: &Fragment, fractions: [f32; 3], index: usize, color: &mut ColorView<'_>);
}

/// Whether the pixel loops hand fragments to the fragment stage one at a time ([`FragmentStage::one`]) in a draw
/// that discards fragments (`cutout`) or not and reads slopes or not: a constant false where batches hold more
/// than one fragment.
#[inline(always)]
pub(crate) const fn one_at_a_time(cutout: bool, slopes: bool) -> bool {
    BATCH_SIZE == 1 && !cutout && !slopes
}

/// The fragment stage of a draw with shader `S`.
pub(crate) struct ShaderStage<'s, S: Shader> {
    shader: &'s S,
    /// The batch's triangles; made with the first triangle that reaches the pixel loop (so that every lane holds
    /// its finite values).
    triangles: Option<Triangles<S::Varyings, S::Face>>,
    /// The draw discards fragments: [`Shader::CUTOUT`] and [`Shader::cutout`], asked once.
    cutout: bool,
}

impl<'s, S: Shader> ShaderStage<'s, S> {
    /// The fragment stage of a draw with `shader`.
    #[inline(always)]
    pub fn new(shader: &'s S) -> Self {
        Self { shader, triangles: None, cutout: S::CUTOUT && shader.cutout() }
    }

    /// Whether the draw discards fragments.
    #[inline(always)]
    pub fn cutout(&self) -> bool {
        self.cutout
    }

    /// Puts a triangle that reaches the pixel loop into the batch's next slot (slot 0 where fragments go one at a
    /// time: none is pushed), before its fragments: its
    /// varyings given in its oriented order, and its face.
    #[inline(always)]
    pub fn start_triangle(&mut self, fragments: &Fragments, [v0, v1, v2]: [&S::Varyings; 3], face: S::Face) {
        let triangles = self.triangles.get_or_insert_with(|| Triangles::new(*v0, face));
        triangles.set(fragments.next_slot(), [*v0, v1.sub(v0), v2.sub(v0)], face);
    }
}

impl<S: Shader> FragmentStage for ShaderStage<'_, S> {
    /// Out of line: the draw loop also calls it once, at its end, and would otherwise hold a second copy of the
    /// shading.
    #[inline(never)]
    fn flush(&mut self, fragments: &mut Fragments, writes: Writes<'_, '_>) -> u64 {
        // A batch has fragments only once a triangle was started.
        let Some(triangles) = &mut self.triangles else { return 0 };
        fragments.resolve();
        triangles.resolve(fragments);
        let batch = triangles.batch(fragments);
        let mut colors = [Vec3::ZERO; BATCH_SIZE];
        let written = if S::CUTOUT && self.cutout {
            let mut keep = [false; BATCH_SIZE];
            self.shader.kept_batch(&batch, &mut keep);
            // A batch with nothing kept (a draw cut out whole, a clear stretch of the map) is not shaded.
            if keep[..batch.len()].contains(&true) {
                self.shader.shade_batch(&batch, &mut colors);
            }
            write_batch(fragments, &colors, Some(&keep), writes)
        } else {
            self.shader.shade_batch(&batch, &mut colors);
            write_batch(fragments, &colors, None, writes)
        };
        let current = fragments.clear();
        triangles.keep_current(current);
        written
    }

    /// Out of line, as [`Self::flush`].
    #[inline(never)]
    fn one(&mut self, fragment: &Fragment, fractions: [f32; 3], index: usize, color: &mut ColorView<'_>) {
        let Some(triangles) = &self.triangles else { return };
        let (varyings, slopes, face) = triangles.one(fractions);
        color.write(index, self.shader.fragment(fragment, face, &varyings, &slopes));
    }
}

/// Writes a shaded batch: `colors[i]` for fragment `i` of `fragments`, in order. With `kept` (a cut-out draw),
/// only the fragments kept that pass the depth test now (against the depths written by those before them), depth
/// and colour; their number is returned, 0 otherwise. On a multisampled target a fragment's colour goes to its
/// samples (in a cut-out draw, to those that pass).
///
/// Compiled once: whatever the shader, its colours reach the buffer through this function, with one branch per
/// batch on the buffer's format ([`crate::target::ColorView`]).
pub(crate) fn write_batch(
    fragments: &Fragments,
    colors: &[Vec3; BATCH_SIZE],
    kept: Option<&[bool; BATCH_SIZE]>,
    writes: Writes<'_, '_>,
) -> u64 {
    let Writes { color, depth, samples } = writes;
    let len = fragments.len();
    let (Some(kept), Some(depth)) = (kept, depth) else {
        if samples == Samples::One {
            color.write_batch(fragments.indices(), &colors[..len]);
        } else {
            for ((&first, (mask, _)), &c) in fragments.indices().iter().zip(fragments.samples()).zip(colors) {
                color.write_samples(first, mask, c);
            }
        }
        return 0;
    };
    let mut written = 0;
    if samples != Samples::One {
        let fragments = fragments.indices().iter().zip(fragments.samples()).zip(colors).enumerate();
        for (i, ((&first, (mask, depths)), &c)) in fragments {
            if kept[i] {
                written += u64::from(write_tested(color, depth, first, (mask, depths), c));
            }
        }
        return written;
    }
    let depths = fragments.depths();
    for (i, &index) in fragments.indices().iter().enumerate() {
        if kept[i] && depth.test_and_set(index, depths[i]) {
            color.write(index, colors[i]);
            written += 1;
        }
    }
    written
}

/// Tests the samples in `mask` from sample index `first` at their `depths` and writes `color` to those that pass:
/// whether any did.
#[inline(always)]
fn write_tested(
    color: &mut ColorView<'_>,
    depth: &mut DepthView<'_>,
    first: usize,
    (mask, depths): (u8, &[f32; SAMPLE_COUNT]),
    c: Vec3,
) -> bool {
    let mut passed = 0u8;
    for s in (0..SAMPLE_COUNT).filter(|s| mask >> s & 1 == 1) {
        passed |= u8::from(depth.test_and_set(first + s, depths[s])) << s;
    }
    color.write_samples(first, passed, c);
    passed != 0
}
