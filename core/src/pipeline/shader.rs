//! The programmable stages: what a draw computes per vertex, per triangle and per pixel.

use super::BATCH_SIZE;
use super::batch::FragmentBatch;
use super::{Slopes, Varyings};
use crate::math::{Mat4, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};

/// A pixel being shaded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// Column in the frame.
    pub x: u32,
    /// Row in the frame (0 at the top), not in the band.
    pub y: u32,
    /// NDC depth in `[0, 1]`, 0 at the near plane: the depth it was tested with (see
    /// [`clamp_depth`](crate::target::clamp_depth)).
    pub depth: f32,
    /// Whether the triangle faces the camera (see [`super::DrawState::front_face`]).
    pub front_facing: bool,
}

/// A shader: the vertex, per-triangle and fragment stages of a draw.
///
/// The vertex stage comes in two parts, [`Shader::position`] and [`Shader::varyings`], so that the pipeline can
/// clip and cull with positions alone and compute varyings only where they are used. The associated [`Shader::Varyings`] type is exactly what gets interpolated. A shader without texture
/// coordinates in its varyings cannot interpolate them, so "an untextured draw never touches UVs" holds by
/// construction, and each shader type compiles to its own specialised pixel loop.
pub trait Shader {
    /// Values computed per vertex and interpolated per pixel.
    type Varyings: Varyings;
    /// Values computed once per triangle (for example a flat-shaded colour); `()` when there are none.
    type Face: Copy;
    /// Mesh attributes the vertex stage reads; a draw with a mesh that lacks one is refused.
    const ATTRIBUTES: Attributes;

    /// Vertex stage, position: the clip-space position of vertex `index` of `mesh`.
    ///
    /// Like [`Shader::varyings`] it must depend on `mesh` and `index` alone: the pipeline reuses one result for
    /// all the triangles that share the vertex.
    fn position(&self, mesh: &Mesh<'_>, index: usize) -> Vec4;

    /// The matrix `m` when [`Shader::position`] is `m.project_point(mesh.position(index))` and nothing else: a
    /// draw may then read its vertices from screen vertices computed beforehand for `m`
    /// ([`crate::target::SharedScreenVertices`]). `None`, the default, for any other position stage.
    #[inline(always)]
    fn clip_from_object(&self) -> Option<&Mat4> {
        None
    }

    /// Vertex stage, varyings: what vertex `index` passes to the fragment stage.
    ///
    /// Called only for vertices of triangles that reach the pixel loop (not culled, bounding box holding a pixel
    /// centre; a box of up to four centres must have one of them covered), and of triangles that must be clipped (before their culling: clipping cuts varyings too), so a
    /// vertex seen only by culled or off-screen triangles that need no clipping is never lit or textured.
    fn varyings(&self, mesh: &Mesh<'_>, index: usize) -> Self::Varyings;

    /// Triangle stage: computed once for each triangle that reaches the rasterizer.
    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> Self::Face;

    /// Fragment stage: the colour of one covered pixel that passed the depth test, whose varyings change by
    /// `slopes` per pixel (zero unless [`Shader::slopes`]).
    fn fragment(
        &self,
        fragment: &Fragment,
        face: &Self::Face,
        varyings: &Self::Varyings,
        slopes: &Slopes<Self::Varyings>,
    ) -> Vec3;

    /// Whether this draw's fragment stage reads the varyings' screen-space [`Slopes`] (to choose a texture's level
    /// of detail), asked once per draw: the pipeline then works them out per fragment, exactly, from the
    /// triangle's set-up (`pipeline/slopes.rs`), and hands over zeros otherwise.
    #[inline(always)]
    fn slopes(&self) -> bool {
        false
    }

    /// False for a depth-only shader (a shadow map's caster pass, a depth pre-pass): it has no fragment stage, so a
    /// draw with it runs the depth test alone, [`DEPTH_LANES`](crate::target::DEPTH_LANES) pixels of a row at a
    /// time, and writes no colour; [`Shader::fragment`] is never called. A constant, so that its draws compile
    /// without a fragment stage.
    const FRAGMENT_STAGE: bool = true;

    /// True for a shader that may discard fragments ([`Shader::cutout`]): a constant, so that the pixel loops of
    /// the others compile without the discard.
    const CUTOUT: bool = false;

    /// Whether this draw discards fragments ([`Shader::kept`]), asked once per draw and only when
    /// [`Shader::CUTOUT`] is set. A draw that does tests depth before shading without writing it, and writes depth
    /// and colour only for the fragments kept, in the order the pixel loop found them: the pixels and depths of
    /// drawing the kept fragments alone.
    #[inline(always)]
    fn cutout(&self) -> bool {
        false
    }

    /// Whether a fragment of a [`Shader::cutout`] draw is kept (true by default).
    #[inline(always)]
    fn kept(
        &self,
        fragment: &Fragment,
        face: &Self::Face,
        varyings: &Self::Varyings,
        slopes: &Slopes<Self::Varyings>,
    ) -> bool {
        let _ = (fragment, face, varyings, slopes);
        true
    }

    /// [`Shader::kept`] for a batch, into `keep[..batch.len()]`; by default fragment by fragment.
    #[inline(always)]
    fn kept_batch(&self, batch: &FragmentBatch<'_, Self::Varyings, Self::Face>, keep: &mut [bool; BATCH_SIZE]) {
        for (i, k) in keep.iter_mut().enumerate().take(batch.len()) {
            *k = self.kept(&batch.fragment(i), batch.face(i), batch.varyings(i), &batch.slopes(i));
        }
    }

    /// Fragment stage for a batch: the colours of `batch`'s fragments into `colors[..batch.len()]`. A batch may
    /// hold fragments of several triangles: [`FragmentBatch::face`] and [`FragmentBatch::fragment`] give each
    /// fragment's. By default it calls [`Shader::fragment`] for each; a shader that decides per batch what it runs
    /// (as [`crate::shading::SurfaceShader`] does) overrides it.
    #[inline(always)]
    fn shade_batch(&self, batch: &FragmentBatch<'_, Self::Varyings, Self::Face>, colors: &mut [Vec3; BATCH_SIZE]) {
        for (i, c) in colors.iter_mut().enumerate().take(batch.len()) {
            *c = self.fragment(&batch.fragment(i), batch.face(i), batch.varyings(i), &batch.slopes(i));
        }
    }
}

/// A depth-only shader whose position stage is a matrix, and nothing else: the shadow pass's (into the light's clip
/// space), and the one binning places vertices with.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PositionShader {
    pub(crate) clip_from_object: Mat4,
}

impl Shader for PositionShader {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const FRAGMENT_STAGE: bool = false;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }
    fn clip_from_object(&self) -> Option<&Mat4> {
        Some(&self.clip_from_object)
    }
    #[inline(always)]
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ZERO
    }
}
