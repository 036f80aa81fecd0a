//! Unlit shading: the material colour, or the mesh's vertex colours, times the texture. No lighting at all.

use super::TextureStage;
use crate::math::{Mat4, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Every pixel is the material colour times the texture.
#[derive(Clone, Copy, Debug)]
pub struct UnlitShader<T> {
    clip_from_object: Mat4,
    color: Vec3,
    texture: T,
}

impl<T: TextureStage> UnlitShader<T> {
    /// A shader drawing `color` (times `texture`) through `clip_from_object`.
    pub fn new(clip_from_object: Mat4, color: Vec3, texture: T) -> Self {
        Self { clip_from_object, color, texture }
    }
}

impl<T: TextureStage> Shader for UnlitShader<T> {
    type Varyings = T::Varyings;
    type Face = ();
    const ATTRIBUTES: Attributes = T::ATTRIBUTES;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> T::Varyings {
        self.texture.vertex(mesh, i)
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), v: &T::Varyings) -> Vec3 {
        self.texture.albedo(self.color, v)
    }
}

/// The mesh's per-vertex colours, interpolated, times the texture.
#[derive(Clone, Copy, Debug)]
pub struct VertexColorShader<T> {
    clip_from_object: Mat4,
    texture: T,
}

impl<T: TextureStage> VertexColorShader<T> {
    /// A shader drawing vertex colours (times `texture`) through `clip_from_object`.
    pub fn new(clip_from_object: Mat4, texture: T) -> Self {
        Self { clip_from_object, texture }
    }
}

impl<T: TextureStage> Shader for VertexColorShader<T> {
    type Varyings = (Vec3, T::Varyings);
    type Face = ();
    const ATTRIBUTES: Attributes = T::ATTRIBUTES.union(Attributes { normals: false, uvs: false, colors: true });

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Self::Varyings {
        (mesh.color(i), self.texture.vertex(mesh, i))
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), v: &Self::Varyings) -> Vec3 {
        self.texture.albedo(v.0, &v.1)
    }
}
