//! The surface colour of a shader: a material colour, optionally multiplied by a texture.
//!
//! A shader is generic over its texture stage, so an untextured draw has no texture coordinates in its varyings and
//! never samples.

use crate::math::{Vec2, Vec3};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::Varyings;
use crate::texture::{Filter, Texture, Wrap};

/// Supplies a shader's albedo (base colour) per pixel.
pub trait TextureStage: Copy {
    /// What the stage interpolates: texture coordinates, or nothing.
    type Varyings: Varyings;
    /// Mesh attributes the stage reads.
    const ATTRIBUTES: Attributes;
    /// Reads the stage's per-vertex values.
    fn vertex(&self, mesh: &Mesh<'_>, index: usize) -> Self::Varyings;
    /// The albedo at a pixel: `base`, or `base` times the texture.
    fn albedo(&self, base: Vec3, varyings: &Self::Varyings) -> Vec3;
}

/// No texture: the albedo is the material colour.
#[derive(Clone, Copy, Debug, Default)]
pub struct Untextured;

impl TextureStage for Untextured {
    type Varyings = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    #[inline(always)]
    fn vertex(&self, _: &Mesh<'_>, _: usize) {}
    #[inline(always)]
    fn albedo(&self, base: Vec3, _: &()) -> Vec3 {
        base
    }
}

/// A diffuse texture sampled with filter `F` and wrap mode `W`.
#[derive(Clone, Copy, Debug)]
pub struct Textured<'t, F, W> {
    texture: Texture<'t>,
    _mode: core::marker::PhantomData<(F, W)>,
}

impl<'t, F: Filter, W: Wrap> Textured<'t, F, W> {
    /// Samples `texture`.
    pub fn new(texture: Texture<'t>) -> Self {
        Self { texture, _mode: core::marker::PhantomData }
    }
}

impl<F: Filter + Copy, W: Wrap + Copy> TextureStage for Textured<'_, F, W> {
    type Varyings = Vec2;
    const ATTRIBUTES: Attributes = Attributes { normals: false, uvs: true, colors: false };
    #[inline(always)]
    fn vertex(&self, mesh: &Mesh<'_>, index: usize) -> Vec2 {
        mesh.uv(index)
    }
    #[inline(always)]
    fn albedo(&self, base: Vec3, uv: &Vec2) -> Vec3 {
        base.mul_elem(self.texture.sample::<F, W>(*uv))
    }
}
