//! Views for debugging a model or a camera: the depth buffer as grey levels, normals as colours.

use super::surface::world_normal;
use crate::math::{Mat3, Mat4, Vec3, Vec4, float};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Shows NDC depth as grey: white at `near`, black at `far` (both NDC depths in `[0, 1]`), clamped outside.
///
/// NDC depth is not linear in distance under a perspective projection; pass the depth range the model actually
/// spans to see it with full contrast.
#[derive(Clone, Copy, Debug)]
pub struct DepthShader {
    clip_from_object: Mat4,
    near: f32,
    scale: f32,
}

impl DepthShader {
    /// A depth view through `clip_from_object`, mapping NDC depths `near..far` to white..black.
    pub fn new(clip_from_object: Mat4, near: f32, far: f32) -> Self {
        let scale = 1.0 / (far - near);
        Self { clip_from_object, near, scale: if scale.is_finite() { scale } else { 0.0 } }
    }
}

impl Shader for DepthShader {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, f: &Fragment, _: &(), _: &()) -> Vec3 {
        Vec3::splat(1.0 - float::clamp((f.depth - self.near) * self.scale, 0.0, 1.0))
    }
}

/// Shows the interpolated world-space normal as a colour: `(n + 1) / 2`, so +x is red, +y green, +z blue.
#[derive(Clone, Copy, Debug)]
pub struct NormalShader {
    clip_from_object: Mat4,
    normal: Mat3,
}

impl NormalShader {
    /// A normal view through `clip_from_object`, with `normal` taking object-space normals to world space.
    pub fn new(clip_from_object: Mat4, normal: Mat3) -> Self {
        Self { clip_from_object, normal }
    }
}

impl Shader for NormalShader {
    type Varyings = Vec3;
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes { normals: true, uvs: false, colors: false };

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        world_normal(&self.normal, mesh.normal(i))
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), n: &Vec3) -> Vec3 {
        n.normalize_or_zero() * 0.5 + Vec3::splat(0.5)
    }
}
