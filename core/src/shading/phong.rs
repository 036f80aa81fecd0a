//! Phong shading: the normal interpolated and lighting evaluated per pixel.

use super::{Highlights, Surface, TextureStage};
use crate::math::{Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Interpolates the normal and lights every pixel with ambient, Lambert diffuse and (when the material has them)
/// Blinn-Phong highlights (Phong, "Illumination for computer generated pictures", CACM 1975).
#[derive(Clone, Copy, Debug)]
pub struct PhongShader<'a, T, H> {
    surface: Surface<'a>,
    texture: T,
    _highlights: H,
}

impl<'a, T: TextureStage, H: Highlights> PhongShader<'a, T, H> {
    /// A per-pixel lighting shader for `surface`, coloured by `texture`.
    pub fn new(surface: Surface<'a>, texture: T) -> Self {
        Self { surface, texture, _highlights: H::default() }
    }
}

impl<T: TextureStage, H: Highlights> Shader for PhongShader<'_, T, H> {
    /// World normal, world position (only with highlights), texture varyings.
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
        (s.normal(mesh, i), H::capture(|| s.world(mesh, i)), self.texture.vertex(mesh, i))
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), v: &Self::Varyings) -> Vec3 {
        let s = &self.surface;
        let n = v.0.normalize_or_zero();
        let lit = self.texture.albedo(s.material.color, &v.2).mul_elem(s.lighting.diffuse(n));
        H::apply(lit, &v.1, |world| s.highlight(n, world))
    }
}
