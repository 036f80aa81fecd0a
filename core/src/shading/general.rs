//! One shader that does every shading model, deciding per vertex and per pixel: the general path that the
//! specialised shaders are proven equal to.

use super::flat::face_light;
use super::light::LightTerms;
use super::{DepthShader, ShadingModel, Surface, Variant};
use crate::math::{Vec2, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader};

/// Everything any shading model interpolates. Fields a model does not use stay zero.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GeneralVaryings {
    /// Vertex colour (unlit with vertex colours).
    pub color: Vec3,
    /// Unit world normal (Gouraud, Phong, normals view).
    pub normal: Vec3,
    /// World position (Phong with highlights).
    pub world: Vec3,
    /// Texture coordinates (textured).
    pub uv: Vec2,
    /// Per-vertex diffuse light (Gouraud).
    pub diffuse: Vec3,
    /// Per-vertex specular light (Gouraud with highlights).
    pub specular: Vec3,
}

crate::impl_varyings!(GeneralVaryings { color, normal, world, uv, diffuse, specular });

/// A shader that runs any [`Variant`], branching on it at run time.
#[derive(Clone, Copy, Debug)]
pub struct GeneralShader<'a> {
    variant: Variant<'a>,
    surface: Surface<'a>,
    depth_view: DepthShader,
}

impl<'a> GeneralShader<'a> {
    /// A general shader for a resolved variant.
    pub fn new(variant: Variant<'a>, surface: Surface<'a>) -> Self {
        let (near, far) = match variant.shading {
            ShadingModel::Depth { near, far } => (near, far),
            _ => (0.0, 1.0),
        };
        let depth_view = DepthShader::new(surface.transforms.clip_from_object, near, far);
        Self { variant, surface, depth_view }
    }

    fn albedo(&self, base: Vec3, uv: Vec2) -> Vec3 {
        match &self.variant.texture {
            Some(t) => base.mul_elem(t.texture.sample_with(t.filter, t.wrap, uv)),
            None => base,
        }
    }
}

impl Shader for GeneralShader<'_> {
    type Varyings = GeneralVaryings;
    type Face = LightTerms;
    const ATTRIBUTES: Attributes = Attributes::NONE;

    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.surface.clip(mesh, i)
    }

    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> GeneralVaryings {
        let s = &self.surface;
        let v = &self.variant;
        let mut out = GeneralVaryings::default();
        if v.texture.is_some() {
            out.uv = mesh.uv(i);
        }
        match v.shading {
            ShadingModel::Unlit if v.vertex_colors => out.color = mesh.color(i),
            ShadingModel::Gouraud => {
                out.normal = s.normal(mesh, i);
                out.diffuse = s.lighting.diffuse(out.normal);
                if v.specular {
                    out.specular =
                        s.lighting.specular(out.normal, s.eye_direction(s.world(mesh, i)), s.material.shininess);
                }
            }
            ShadingModel::Phong => {
                out.normal = s.normal(mesh, i);
                if v.specular {
                    out.world = s.world(mesh, i);
                }
            }
            ShadingModel::Normals => out.normal = s.normal(mesh, i),
            _ => {}
        }
        out
    }

    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> LightTerms {
        match self.variant.shading {
            ShadingModel::Flat => face_light(&self.surface, mesh, triangle),
            _ => LightTerms { diffuse: Vec3::ZERO, specular: Vec3::ZERO },
        }
    }

    fn fragment(&self, f: &Fragment, face: &LightTerms, v: &GeneralVaryings) -> Vec3 {
        let s = &self.surface;
        let m = &s.material;
        match self.variant.shading {
            ShadingModel::Unlit if self.variant.vertex_colors => self.albedo(v.color, v.uv),
            ShadingModel::Unlit => self.albedo(m.color, v.uv),
            ShadingModel::Flat => face.shade(self.albedo(m.color, v.uv), m.specular),
            ShadingModel::Gouraud => {
                let lit = self.albedo(m.color, v.uv).mul_elem(v.diffuse);
                if self.variant.specular { lit + m.specular.mul_elem(v.specular) } else { lit }
            }
            ShadingModel::Phong => {
                let n = v.normal.normalize_or_zero();
                let lit = self.albedo(m.color, v.uv).mul_elem(s.lighting.diffuse(n));
                if self.variant.specular { lit + s.highlight(n, v.world) } else { lit }
            }
            ShadingModel::Depth { .. } => self.depth_view.fragment(f, &(), &()),
            ShadingModel::Normals => v.normal.normalize_or_zero() * 0.5 + Vec3::splat(0.5),
        }
    }
}
