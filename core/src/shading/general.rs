//! The general path: one shader for every variant, deciding at run time, per vertex and per fragment, in scalar
//! maths one fragment at a time. The batched [`super::SurfaceShader`] is proven to give its pixels bit for bit
//! (`core/tests/specialisation.rs`), so this is a test oracle, reached through [`crate::testing`].
//!
//! It is written from the maths each stage documents, not from the lane code: `Vec3` operations in the order the
//! lane loops promise to keep ([`super::columns`]), scalar texture samples, and the scalar shadow lookup
//! ([`crate::shadow::ShadowMap::light_reaching`]). It shares with the surface shader only the per-vertex and
//! per-triangle light (`light_terms.rs`: `vertex_light`, `face_light`), which is scalar already.

use super::TangentFrame;
use super::brdf::MetallicRoughness;
use super::light_terms::{face_light, vertex_light};
use super::material::{decode_normal, metallic_roughness};
use super::{
    Cutout, Light, LightTerms, Lighting, Material, NormalSource, ShadingModel, SpecularSource, Transforms, Variant,
    world_normal,
};
use crate::color::{ShadingSpace, texel_alpha, unpack_rgb888};
use crate::math::{Vec2, Vec3, Vec4, float};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{Fragment, Shader, Slopes};
use crate::texture::{Bilinear, Clamp, FilterMode, MipFilter, Nearest, Repeat, Texture, WrapMode};

/// Everything any variant interpolates. Fields a variant does not use stay zero (so that they never make the
/// pipeline skip a triangle).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GeneralVaryings {
    /// Vertex colour (any model that colours, on a mesh with colours).
    pub color: Vec3,
    /// World normal, unit length at the vertices (Gouraud, per-pixel, the normals view).
    pub normal: Vec3,
    /// World position (per-pixel lighting with highlights, point or spot lights or shadows).
    pub world: Vec3,
    /// Texture coordinates (any map).
    pub uv: Vec2,
    /// World tangent and handedness (a tangent-space normal map).
    pub tangent: Vec4,
    /// Per-vertex diffuse light (Gouraud).
    pub diffuse: Vec3,
    /// Per-vertex specular light (Gouraud with highlights).
    pub specular: Vec3,
}

crate::impl_varyings!(GeneralVaryings { color, normal, world, uv, tangent, diffuse, specular });

/// Where a fragment reads its maps: its texture coordinates and their slopes.
struct MapPoint {
    uv: Vec2,
    slopes: Slopes<Vec2>,
}

impl MapPoint {
    /// Of a fragment with varyings `v` changing by `slopes`.
    fn of(v: &GeneralVaryings, slopes: &Slopes<GeneralVaryings>) -> Self {
        Self { uv: v.uv, slopes: Slopes { dx: slopes.dx.uv, dy: slopes.dy.uv } }
    }
}

/// A shader that runs any resolved [`Variant`], branching on it for every vertex and fragment.
#[derive(Clone, Copy, Debug)]
pub struct GeneralShader<'a> {
    variant: Variant,
    transforms: Transforms,
    tangent_frame: TangentFrame,
    tangents: &'a [Vec4],
    material: Material<'a>,
    lights: Lighting<'a>,
}

impl<'a> GeneralShader<'a> {
    /// A general shader for a resolved `variant` (`tangents`: one per vertex when it reads tangents).
    pub fn new(
        variant: Variant,
        transforms: Transforms,
        tangents: &'a [Vec4],
        material: Material<'a>,
        lights: Lighting<'a>,
    ) -> Self {
        Self { variant, transforms, tangent_frame: TangentFrame::new(&transforms), tangents, material, lights }
    }

    /// The packed texel of `map` at `at` as stored, with the variant's filter, wrap mode and filter between
    /// levels.
    fn texel(&self, map: &Texture<'_>, at: &MapPoint) -> u32 {
        let (chain, mip) = (map.mip_chain(), self.variant.mip_filter);
        let (uv, footprint) = (at.uv, &chain.footprint(&at.slopes, mip));
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => chain.sample_packed::<Nearest, Repeat>(uv, footprint, mip),
            (FilterMode::Nearest, WrapMode::Clamp) => chain.sample_packed::<Nearest, Clamp>(uv, footprint, mip),
            (FilterMode::Bilinear, WrapMode::Repeat) => chain.sample_packed::<Bilinear, Repeat>(uv, footprint, mip),
            (FilterMode::Bilinear, WrapMode::Clamp) => chain.sample_packed::<Bilinear, Clamp>(uv, footprint, mip),
        }
    }

    /// The colour of the colour map `map` at `at`: in linear light, every texel decoded from sRGB before it is
    /// blended, when the draw lights in linear light; else the blended codes over 255.
    fn color(&self, map: &Texture<'_>, at: &MapPoint) -> Vec3 {
        if self.variant.space == ShadingSpace::Encoded {
            return unpack_rgb888(self.texel(map, at));
        }
        let (chain, mip) = (map.mip_chain(), self.variant.mip_filter);
        let (uv, footprint) = (at.uv, &chain.footprint(&at.slopes, mip));
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => chain.sample_light::<Nearest, Repeat>(uv, footprint, mip),
            (FilterMode::Nearest, WrapMode::Clamp) => chain.sample_light::<Nearest, Clamp>(uv, footprint, mip),
            (FilterMode::Bilinear, WrapMode::Repeat) => chain.sample_light::<Bilinear, Repeat>(uv, footprint, mip),
            (FilterMode::Bilinear, WrapMode::Clamp) => chain.sample_light::<Bilinear, Clamp>(uv, footprint, mip),
        }
    }

    /// A shaded colour as the draw stores it: encoded to sRGB from linear light, or as it is.
    fn stored(&self, color: Vec3) -> Vec3 {
        self.variant.space.stored(color)
    }

    /// The material colour, times the vertex colour `color` when the variant reads it, times the diffuse map at
    /// `uv` when it reads that.
    fn albedo(&self, color: Vec3, uv: &MapPoint) -> Vec3 {
        let m = &self.material;
        let base = if self.variant.vertex_colors { m.color.mul_elem(color) } else { m.color };
        match m.diffuse {
            Some(map) if self.variant.albedo_map => base.mul_elem(self.color(&map, uv)),
            _ => base,
        }
    }

    /// The specular colour: the material's, times the specular map when the variant reads it.
    fn specular_color(&self, uv: &MapPoint) -> Vec3 {
        let m = &self.material;
        match m.specular_map {
            Some(map) if self.variant.specular == SpecularSource::Map => m.specular.mul_elem(self.color(&map, uv)),
            _ => m.specular,
        }
    }

    /// `lit` plus the highlight (when the variant has one) and the glow map (when it reads it).
    fn finish(&self, lit: Vec3, specular_light: Vec3, uv: &MapPoint) -> Vec3 {
        let mut color = lit;
        if self.variant.specular != SpecularSource::None {
            color += self.specular_color(uv).mul_elem(specular_light);
        }
        match self.material.glow_map {
            Some(map) if self.variant.glow_map => color + self.color(&map, uv),
            _ => color,
        }
    }

    /// The direction toward `light` from the point `world` of geometric normal `geometric`, and the share of its
    /// colour arriving (`None`: all of it): the share that reaches the point times the share its shadow map lets
    /// through, from the geometric normal's offset.
    fn share(&self, light: &Light<'_>, world: Vec3, geometric: Vec3) -> (Vec3, Option<f32>) {
        let (to_light, reaching) = light.kind.toward(world);
        let shadowed = light.shadow.as_ref().map(|map| map.light_reaching(world, geometric, geometric.dot(to_light)));
        let share = match (reaching, shadowed) {
            (Some(r), Some(s)) => Some(r * s),
            (reaching, shadowed) => reaching.or(shadowed),
        };
        (to_light, share)
    }

    /// Per-pixel lighting: the shading normal (interpolated or from a map), then each light with its shadow map.
    ///
    /// Two-sided, a back-facing fragment's geometric and shading normals are turned round.
    fn per_pixel(&self, v: &GeneralVaryings, uv: &MapPoint, front_facing: bool) -> Vec3 {
        let (variant, m) = (&self.variant, &self.material);
        let (normal, tangent) = (v.normal, v.tangent);
        let geometric = normal.normalize_or_zero();
        let shading = match (variant.normals, m.normal_map) {
            (NormalSource::TangentMap, Some(map)) => {
                let (n, t) = (normal, tangent.truncate());
                let b = n.cross(t) * tangent.w;
                let d = decode_normal(self.texel(&map.texture, uv));
                (t * d.x + b * d.y + n * d.z).normalize_or_zero()
            }
            (NormalSource::ObjectMap, Some(map)) => {
                (self.transforms.normal * decode_normal(self.texel(&map.texture, uv))).normalize_or_zero()
            }
            _ => geometric,
        };
        let (geometric, shading) =
            if variant.two_sided && !front_facing { (geometric * -1.0, shading * -1.0) } else { (geometric, shading) };
        let highlights = variant.specular != SpecularSource::None;
        let to_eye = if highlights { (self.transforms.eye - v.world).normalize_or_zero() } else { Vec3::ZERO };
        let occlusion = match m.occlusion_map {
            Some(map) if variant.occlusion_map => Some(unpack_rgb888(self.texel(&map, uv))),
            _ => None,
        };
        if variant.shading == ShadingModel::MetallicRoughness {
            // The BRDF's reflected light, the base colour in it, and the glow. The indirect light (ambient and
            // environment) is scaled by the occlusion map.
            let texel = match m.metallic_roughness_map {
                Some(map) if variant.metallic_roughness_map => Some(self.texel(&map, uv)),
                _ => None,
            };
            let (metallic, roughness) = metallic_roughness(m.metallic, m.roughness, texel);
            let surface = MetallicRoughness { base_color: self.albedo(v.color, uv), metallic, roughness };
            let mut reflected = surface.ambient(self.lights.ambient);
            if let (Some(environment), true) = (self.lights.environment, variant.environment) {
                reflected += environment.reflected(&surface, shading, to_eye);
            }
            if let Some(occlusion) = occlusion {
                reflected = reflected.mul_elem(occlusion);
            }
            for light in self.lights.lights {
                let (to_light, share) = self.share(light, v.world, geometric);
                reflected += surface.lit_by(shading, to_eye, to_light, light.color, share.unwrap_or(1.0));
            }
            return match self.material.glow_map {
                Some(map) if self.variant.glow_map => reflected + self.color(&map, uv),
                _ => reflected,
            };
        }
        let mut diffuse = match occlusion {
            Some(occlusion) => self.lights.ambient.mul_elem(occlusion),
            None => self.lights.ambient,
        };
        let mut specular = Vec3::ZERO;
        for light in self.lights.lights {
            let (to_light, share) = self.share(light, v.world, geometric);
            let n_dot_l = shading.dot(to_light);
            let arriving = float::max(n_dot_l, 0.0);
            diffuse += light.color * share.map_or(arriving, |s| arriving * s);
            if highlights && n_dot_l > 0.0 {
                let h = (to_light + to_eye).normalize_or_zero();
                let k = float::pow(float::max(shading.dot(h), 0.0), m.shininess);
                specular += light.color * share.map_or(k, |s| k * s);
            }
        }
        self.finish(self.albedo(v.color, uv).mul_elem(diffuse), specular, uv)
    }
}

impl Shader for GeneralShader<'_> {
    type Varyings = GeneralVaryings;
    /// Flat shading's light for the whole triangle (zero for the other models).
    type Face = LightTerms;
    // The variant checked the mesh has what it reads.
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const CUTOUT: bool = true;

    fn cutout(&self) -> bool {
        self.variant.cutout != Cutout::None
    }

    /// The diffuse map's alpha at the fragment against the cut-off; nothing is kept when the whole draw is cut
    /// out.
    fn kept(&self, _: &Fragment, _: &LightTerms, v: &GeneralVaryings, slopes: &Slopes<GeneralVaryings>) -> bool {
        match (self.variant.cutout, self.material.diffuse) {
            (Cutout::Map(cutoff), Some(map)) => {
                self.material.keeps(texel_alpha(self.texel(&map, &MapPoint::of(v, slopes))), cutoff)
            }
            (Cutout::Everything, _) => false,
            _ => true,
        }
    }

    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.transforms.clip_from_object.project_point(mesh.position(i))
    }

    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> GeneralVaryings {
        let (t, v) = (&self.transforms, &self.variant);
        let mut out = GeneralVaryings::default();
        if v.uvs {
            out.uv = mesh.uv(i);
        }
        if v.tangents {
            out.tangent = self.tangent_frame.world_tangent(self.tangents, i);
        }
        if v.vertex_colors {
            out.color = mesh.color(i);
        }
        match v.shading {
            ShadingModel::Gouraud => {
                let light = vertex_light(t, &self.lights, self.material.shininess, v, mesh, i);
                (out.diffuse, out.specular) = (light.diffuse, light.specular);
            }
            ShadingModel::Phong | ShadingModel::MetallicRoughness => {
                out.normal = world_normal(&t.normal, mesh.normal(i));
                if v.world {
                    out.world = t.model.transform_point(mesh.position(i));
                }
            }
            ShadingModel::Normals => out.normal = world_normal(&t.normal, mesh.normal(i)),
            _ => {}
        }
        out
    }

    /// Flat shading's light: the face normal (through the normal matrix), the highlight at the world centroid.
    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> LightTerms {
        if self.variant.shading != ShadingModel::Flat {
            return LightTerms { diffuse: Vec3::ZERO, specular: Vec3::ZERO };
        }
        face_light(&self.transforms, &self.lights, self.material.shininess, &self.variant, mesh, triangle)
    }

    /// Reads slopes when the variant mipmaps.
    fn slopes(&self) -> bool {
        self.variant.mip_filter != MipFilter::Off
    }

    fn fragment(&self, f: &Fragment, face: &LightTerms, v: &GeneralVaryings, slopes: &Slopes<GeneralVaryings>) -> Vec3 {
        let uv = &MapPoint::of(v, slopes);
        match self.variant.shading {
            ShadingModel::Unlit => self.stored(self.albedo(v.color, uv)),
            ShadingModel::Flat => {
                self.stored(self.finish(self.albedo(v.color, uv).mul_elem(face.diffuse), face.specular, uv))
            }
            ShadingModel::Gouraud => {
                self.stored(self.finish(self.albedo(v.color, uv).mul_elem(v.diffuse), v.specular, uv))
            }
            ShadingModel::Phong | ShadingModel::MetallicRoughness => self.stored(self.per_pixel(v, uv, f.front_facing)),
            ShadingModel::Depth { near, far } => {
                let scale = 1.0 / (far - near);
                let scale = if scale.is_finite() { scale } else { 0.0 };
                Vec3::splat(1.0 - float::clamp((f.depth - near) * scale, 0.0, 1.0))
            }
            ShadingModel::Normals => v.normal.normalize_or_zero() * 0.5 + Vec3::splat(0.5),
        }
    }
}
