//! Flat shading: lighting evaluated once per triangle, with the face normal.

use super::light::LightTerms;
use super::{Surface, TextureStage};
use crate::math::{Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Lights each triangle once, with its geometric normal at its centroid; the texture (if any) still varies per
/// pixel. Needs no vertex normals.
#[derive(Clone, Copy, Debug)]
pub struct FlatShader<'a, T> {
    surface: Surface<'a>,
    texture: T,
}

impl<'a, T: TextureStage> FlatShader<'a, T> {
    /// A flat shader for `surface`, coloured by `texture`.
    pub fn new(surface: Surface<'a>, texture: T) -> Self {
        Self { surface, texture }
    }
}

/// The light terms of a triangle: its face normal (the object-space cross product of two edges, through the
/// normal matrix) lit at its centroid.
#[inline(always)]
pub(crate) fn face_light(surface: &Surface<'_>, mesh: &Mesh<'_>, [a, b, c]: [usize; 3]) -> LightTerms {
    let (p0, p1, p2) = (mesh.position(a), mesh.position(b), mesh.position(c));
    let n = (surface.transforms.normal * (p1 - p0).cross(p2 - p0)).normalize_or_zero();
    let specular = if surface.material.has_specular() {
        let centroid = surface.transforms.model.transform_point((p0 + p1 + p2) * (1.0 / 3.0));
        surface.lighting.specular(n, surface.eye_direction(centroid), surface.material.shininess)
    } else {
        Vec3::ZERO
    };
    LightTerms { diffuse: surface.lighting.diffuse(n), specular }
}

impl<T: TextureStage> Shader for FlatShader<'_, T> {
    type Varyings = T::Varyings;
    type Face = LightTerms;
    const ATTRIBUTES: Attributes = T::ATTRIBUTES;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.surface.clip(mesh, i)
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> T::Varyings {
        self.texture.vertex(mesh, i)
    }

    #[inline(always)]
    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> LightTerms {
        face_light(&self.surface, mesh, triangle)
    }

    #[inline(always)]
    fn fragment(&self, _: &Fragment, face: &LightTerms, v: &T::Varyings) -> Vec3 {
        let m = &self.surface.material;
        face.shade(self.texture.albedo(m.color, v), m.specular)
    }
}
