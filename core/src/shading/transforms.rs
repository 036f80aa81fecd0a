//! The matrices a lit draw needs, derived once per draw.

use crate::math::{Mat3, Mat4, Vec3, Vec4};
use crate::pipeline::{DrawState, Interpolation};

/// Object-to-world, object-to-clip and normal transforms, and the camera position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transforms {
    /// Object space to world space.
    pub model: Mat4,
    /// Object space to clip space: `projection * view * model`.
    pub clip_from_object: Mat4,
    /// Object-space normals to world space: the model's [`Mat4::normal_matrix`].
    pub normal: Mat3,
    /// Camera position in world space (for specular highlights).
    pub eye: Vec3,
    /// True when the projection is orthographic (`w` is the same everywhere).
    pub orthographic: bool,
}

impl Transforms {
    /// Derives the transforms from model, view and projection matrices.
    ///
    /// The eye is the view matrix's inverse applied to the origin; a singular view matrix puts it at the origin.
    pub fn new(model: Mat4, view: Mat4, projection: Mat4) -> Self {
        let eye = view.inverse().map_or(Vec3::ZERO, |inv| inv.transform_point(Vec3::ZERO));
        Self {
            model,
            clip_from_object: projection * view * model,
            normal: model.normal_matrix(),
            eye,
            orthographic: projection.is_affine(),
        }
    }

    /// True when the model matrix mirrors (negative determinant), which turns counter-clockwise triangles into
    /// clockwise ones.
    pub fn mirrors(&self) -> bool {
        self.model.to_mat3().determinant() < 0.0
    }

    /// `state` as a draw with these transforms runs it: affine interpolation under an orthographic projection
    /// (exact there, and no division per pixel), and the front face flipped when the model matrix mirrors, so
    /// culling still removes the back.
    pub fn adapt(&self, state: &DrawState) -> DrawState {
        let mut state = *state;
        if self.orthographic {
            state.interpolation = Interpolation::Affine;
        }
        if self.mirrors() {
            state.front_face = state.front_face.flipped();
        }
        state
    }
}

/// Object-space tangents to world space: the model's upper 3x3 and the sign a mirroring model matrix gives the
/// bitangent. Derived once per draw by the shaders that read tangents.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TangentFrame {
    matrix: Mat3,
    /// -1 when the model matrix mirrors (which flips the bitangent), else 1.
    handedness: f32,
}

impl TangentFrame {
    pub(crate) fn new(transforms: &Transforms) -> Self {
        let handedness = if transforms.mirrors() { -1.0 } else { 1.0 };
        Self { matrix: transforms.model.to_mat3(), handedness }
    }

    /// `tangents[i]` (direction and handedness `w`) in world space; a missing tangent is NaN, so that its
    /// triangle is skipped rather than the draw panicking (the variant checks the slice's length first).
    #[inline(always)]
    pub(crate) fn world_tangent(&self, tangents: &[Vec4], i: usize) -> Vec4 {
        let tangent = tangents.get(i).copied().unwrap_or(Vec4::new(f32::NAN, 0.0, 0.0, 0.0));
        (self.matrix * tangent.truncate()).extend(tangent.w * self.handedness)
    }
}

/// An object-space normal in world space, unit length; zero stays zero, and a NaN or infinite normal stays
/// non-finite so that its triangle is skipped rather than drawn black.
#[inline(always)]
pub(crate) fn world_normal(normal_matrix: &Mat3, n: Vec3) -> Vec3 {
    let n = *normal_matrix * n;
    if n.is_finite() { n.normalize_or_zero() } else { n }
}
