//! The programmable stages: what a draw computes per vertex, per triangle and per pixel.

use super::Varyings;
use crate::math::{Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};

/// A pixel being shaded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// Column in the frame.
    pub x: u32,
    /// Row in the frame (0 at the top), not in the band.
    pub y: u32,
    /// NDC depth in `[0, 1]`, 0 at the near plane.
    pub depth: f32,
    /// Whether the triangle faces the camera (see [`super::DrawState::front_face`]).
    pub front_facing: bool,
}

/// A shader: the vertex, per-triangle and fragment stages of a draw.
///
/// The associated [`Shader::Varyings`] type is exactly what gets interpolated. A shader without texture
/// coordinates in its varyings cannot interpolate them, so "an untextured draw never touches UVs" holds by
/// construction, and each shader type compiles to its own specialised pixel loop.
pub trait Shader {
    /// Values computed per vertex and interpolated per pixel.
    type Varyings: Varyings;
    /// Values computed once per triangle (for example a flat-shaded colour); `()` when there are none.
    type Face: Copy;
    /// Mesh attributes the vertex stage reads; a draw with a mesh that lacks one is refused.
    const ATTRIBUTES: Attributes;

    /// Vertex stage: the clip-space position of vertex `index` of `mesh` and its varyings.
    fn vertex(&self, mesh: &Mesh<'_>, index: usize) -> (Vec4, Self::Varyings);

    /// Triangle stage: computed once for each triangle that reaches the rasterizer.
    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> Self::Face;

    /// Fragment stage: the colour of one covered pixel that passed the depth test.
    fn fragment(&self, fragment: &Fragment, face: &Self::Face, varyings: &Self::Varyings) -> Vec3;
}
