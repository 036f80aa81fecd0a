//! Gouraud shading: lighting evaluated per vertex and interpolated.

use super::{Highlights, Surface, TextureStage};
use crate::math::{Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Lights each vertex with its normal and interpolates the light (Gouraud, "Continuous shading of curved
/// surfaces", IEEE Trans. Computers, 1971). Highlights between vertices are missed; that is the price of
/// lighting three points per triangle instead of every pixel.
#[derive(Clone, Copy, Debug)]
pub struct GouraudShader<'a, T, H> {
    surface: Surface<'a>,
    texture: T,
    _highlights: H,
}

impl<'a, T: TextureStage, H: Highlights> GouraudShader<'a, T, H> {
    /// A Gouraud shader for `surface`, coloured by `texture`.
    pub fn new(surface: Surface<'a>, texture: T) -> Self {
        Self { surface, texture, _highlights: H::default() }
    }
}

impl<T: TextureStage, H: Highlights> Shader for GouraudShader<'_, T, H> {
    /// Diffuse light, specular light (if on), texture varyings.
    type Varyings = (Vec3, H::Value, T::Varyings);
    type Face = ();
    const ATTRIBUTES: Attributes = T::ATTRIBUTES.union(Attributes { normals: true, uvs: false, colors: false });

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.surface.clip(mesh, i)
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Self::Varyings {
        let s = &self.surface;
        let n = s.normal(mesh, i);
        // A non-finite normal must reach the varyings, so that the pipeline skips its triangle: the light alone
        // would hide it (`max(NaN, 0)` is 0) and draw the triangle unlit.
        let diffuse = if n.is_finite() { s.lighting.diffuse(n) } else { n };
        let specular = H::capture(|| s.lighting.specular(n, s.eye_direction(s.world(mesh, i)), s.material.shininess));
        (diffuse, specular, self.texture.vertex(mesh, i))
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), v: &Self::Varyings) -> Vec3 {
        let m = &self.surface.material;
        let lit = self.texture.albedo(m.color, &v.2).mul_elem(v.0);
        H::apply(lit, &v.1, |specular| m.specular.mul_elem(specular))
    }
}
