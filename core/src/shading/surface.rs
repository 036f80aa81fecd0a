//! What every lit shader knows about the surface it shades.

use super::{Lighting, Material, Transforms};
use crate::math::{Mat3, Vec3, Vec4};
use crate::mesh::Mesh;

/// Transforms, material and lights of a lit draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface<'a> {
    /// The draw's matrices.
    pub transforms: Transforms,
    /// The surface material.
    pub material: Material,
    /// The scene's lights.
    pub lighting: Lighting<'a>,
}

impl Surface<'_> {
    /// Clip-space position of a vertex.
    #[inline(always)]
    pub(crate) fn clip(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.transforms.clip_from_object.project_point(mesh.position(i))
    }

    /// World-space position of a vertex.
    #[inline(always)]
    pub(crate) fn world(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        self.transforms.model.transform_point(mesh.position(i))
    }

    /// Unit world-space normal of a vertex: see [`world_normal`].
    #[inline(always)]
    pub(crate) fn normal(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        world_normal(&self.transforms.normal, mesh.normal(i))
    }

    /// Unit vector from a world-space point toward the camera.
    #[inline(always)]
    pub(crate) fn eye_direction(&self, world: Vec3) -> Vec3 {
        (self.transforms.eye - world).normalize_or_zero()
    }

    /// The specular highlight at a point with unit normal `n`, times the material's specular colour.
    #[inline(always)]
    pub(crate) fn highlight(&self, n: Vec3, world: Vec3) -> Vec3 {
        let m = &self.material;
        m.specular.mul_elem(self.lighting.specular(n, self.eye_direction(world), m.shininess))
    }
}

/// An object-space normal in world space, unit length; zero stays zero, and a NaN or infinite normal stays
/// non-finite so that its triangle is skipped rather than drawn black.
#[inline(always)]
pub(crate) fn world_normal(normal_matrix: &Mat3, n: Vec3) -> Vec3 {
    let n = *normal_matrix * n;
    if n.is_finite() { n.normalize_or_zero() } else { n }
}
