//! The surface shader: the vertex stage of the draw's variant, and its fragment stages over batches.

use core::marker::PhantomData;

use super::capabilities::{self, has};
use super::columns::{self, Column3};
use super::light_terms::{face_light, vertex_light};
use super::maps::{Coordinates, MapReader, Texels, albedo, glow, occluded_ambient, specular_color, stored};
use super::normals::{self, object_map, tangent_map};
use super::scratch::Scratch;
use super::varyings::{Absent, Slot, SurfaceVaryings};
use super::{Cutout, ShadingError, coarse, views};
use super::{Layout, Lighting, Material, NormalSource, SpecularSource, Variant, lighting};
use crate::color::{ShadingSpace, texel_alpha};
use crate::math::float::Exponent;
use crate::math::{Mat4, Vec2, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{BATCH_SIZE, Fragment, FragmentBatch, Shader, Slopes};
use crate::shading::{LightTerms, ShadingModel, TangentFrame, Transforms, world_normal};
use crate::texture::{Bilinear, Clamp, Filter, FilterMode, MipFilter, Nearest, Repeat, Wrap, WrapMode};

/// Shades a mesh with a [`Material`] under [`Lighting`], computing what its [`Variant`] says:
/// its shading model, maps and lights.
///
/// The varyings it carries are fixed by its type (`A` and `B`: the two `Vec3` slots of the variant's
/// [`Layout`], `U`: texture coordinates, `T`: tangent, `C`: vertex colour; each the value's type or
/// [`Absent`]). Everything else, the shading model, which maps are sampled and how each light is applied, is
/// decided once per batch of fragments and runs as a loop compiled for that choice, so the number of compiled
/// loops is the sum of the choices, not their product.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceShader<'a, A, B, U, T, C = Absent, const CAPS: u32 = { capabilities::ALL }> {
    transforms: Transforms,
    tangent_frame: TangentFrame,
    tangents: &'a [Vec4],
    material: Material<'a>,
    /// The material's shininess, sorted once for the highlights.
    shininess: Exponent,
    lights: Lighting<'a>,
    variant: Variant,
    /// The slots the variant fills (a general draw may carry more, which then hold zeros).
    layout: Layout,
    _varyings: PhantomData<(A, B, U, T, C)>,
}

impl<'a, A, B, U, T, C, const CAPS: u32> SurfaceShader<'a, A, B, U, T, C, CAPS>
where
    A: Slot<Vec3>,
    B: Slot<Vec3>,
    U: Slot<Vec2>,
    T: Slot<Vec4>,
    C: Slot<Vec3>,
{
    /// A shader for a resolved `variant`. `tangents` holds one per vertex when the variant reads tangents (may be
    /// empty otherwise).
    ///
    /// # Errors
    /// [`ShadingError::Unsupported`] when the slot types do not carry the variant's [`Variant::layout`]
    /// (they may carry more), or `CAPS` ([`capabilities`]) leaves out its shading model, point lights, shadow
    /// maps, two-sided lighting, cut-outs, mipmaps or linear light.
    pub fn new(
        variant: Variant,
        transforms: Transforms,
        tangents: &'a [Vec4],
        material: Material<'a>,
        lights: Lighting<'a>,
    ) -> Result<Self, ShadingError> {
        let layout = variant.layout();
        let carried = (!layout.first || A::PRESENT)
            && (!layout.second || B::PRESENT)
            && (!layout.uvs || U::PRESENT)
            && (!layout.tangents || T::PRESENT)
            && (!layout.colors || C::PRESENT);
        let model = match variant.shading {
            ShadingModel::Unlit => capabilities::UNLIT,
            ShadingModel::Flat => capabilities::FLAT,
            ShadingModel::Gouraud => capabilities::GOURAUD,
            ShadingModel::Phong => capabilities::PER_PIXEL,
            ShadingModel::Depth { .. } | ShadingModel::Normals => capabilities::VIEWS,
        };
        let compiled = has(CAPS, model)
            && (variant.point_lights == 0 || has(CAPS, capabilities::POINT_LIGHTS))
            && (variant.shadowed_lights == 0 || has(CAPS, capabilities::SHADOWS))
            && (!variant.two_sided || has(CAPS, capabilities::TWO_SIDED))
            && (variant.cutout == Cutout::None || has(CAPS, capabilities::CUTOUT))
            && (variant.mip_filter == MipFilter::Off || has(CAPS, capabilities::MIPMAPS))
            && (variant.space == ShadingSpace::Encoded || has(CAPS, capabilities::LINEAR_LIGHT));
        if !(carried && compiled) {
            return Err(ShadingError::Unsupported);
        }
        Ok(Self {
            transforms,
            tangent_frame: TangentFrame::new(&transforms),
            tangents,
            material,
            shininess: Exponent::new(material.shininess),
            lights,
            variant,
            layout,
            _varyings: PhantomData,
        })
    }

    /// The batch's texture coordinates, with their slopes when the variant mipmaps.
    #[inline(always)]
    fn coordinates(&self, batch: &FragmentBatch<SurfaceVaryings<A, B, U, T, C>, LightTerms>) -> Coordinates {
        let uv = |v: &SurfaceVaryings<A, B, U, T, C>| v.uv.get().unwrap_or(Vec2::ZERO);
        Coordinates::gather(batch.len(), |i| uv(batch.varyings(i)), self.mipmaps(), |i| batch.slopes_of(i, uv))
    }

    /// Whether the draw reads mipmapped maps: a constant false for a shader compiled without texture coordinates
    /// or [`capabilities::MIPMAPS`].
    #[inline(always)]
    fn mipmaps(&self) -> bool {
        U::PRESENT && has(CAPS, capabilities::MIPMAPS) && self.variant.mip_filter != MipFilter::Off
    }

    /// The filter between levels the draw's maps are read with.
    #[inline(always)]
    fn mip_filter(&self) -> MipFilter {
        if self.mipmaps() { self.variant.mip_filter } else { MipFilter::Off }
    }

    /// The space the draw lights in: a constant [`ShadingSpace::Encoded`] for a shader compiled without
    /// [`capabilities::LINEAR_LIGHT`].
    #[inline(always)]
    fn space(&self) -> ShadingSpace {
        if has(CAPS, capabilities::LINEAR_LIGHT) { self.variant.space } else { ShadingSpace::Encoded }
    }

    /// Runs the per-pixel lighting stages of the variant over `s`, whose varyings columns and base albedo are
    /// filled, into `colors`.
    fn shade(&self, s: &mut Scratch, colors: &mut [Vec3; BATCH_SIZE]) {
        // One decision per batch: every map of a draw is read with the draw's filter and wrap mode. Without texture
        // coordinates no map is read, and one instance of the stages is compiled.
        if !U::PRESENT {
            return self.stages::<Nearest, Clamp>(s, colors);
        }
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => self.stages::<Nearest, Repeat>(s, colors),
            (FilterMode::Nearest, WrapMode::Clamp) => self.stages::<Nearest, Clamp>(s, colors),
            (FilterMode::Bilinear, WrapMode::Repeat) => self.stages::<Bilinear, Repeat>(s, colors),
            (FilterMode::Bilinear, WrapMode::Clamp) => self.stages::<Bilinear, Clamp>(s, colors),
        }
    }

    /// [`Self::shade`] with the maps read with filter `F` and wrap mode `Wr`, through one [`MapReader`]: maps of
    /// one size share their texel addresses.
    #[inline(always)]
    fn stages<F: Filter, Wr: Wrap>(&self, s: &mut Scratch, colors: &mut [Vec3; BATCH_SIZE]) {
        let maps = &mut MapReader::<F, Wr>::new(self.mip_filter());
        let v = &self.variant;
        let m = &self.material;
        let texels = Texels::of_color(self.space());
        // The geometric normal is the shading normal without a normal map, and offsets shadow lookups: with a map
        // and no shadows, nothing reads it.
        let interpolated_shading = v.normals == NormalSource::Interpolated;
        if interpolated_shading || v.shadowed_lights > 0 {
            normals::interpolated(s, interpolated_shading);
        }
        match (v.normals, m.normal_map) {
            (NormalSource::TangentMap, Some(map)) if T::PRESENT => tangent_map(s, maps, &map.texture),
            (NormalSource::ObjectMap, Some(map)) if U::PRESENT => {
                object_map(s, maps, &map.texture, &self.transforms.normal);
            }
            _ => {}
        }
        if has(CAPS, capabilities::TWO_SIDED) && v.two_sided {
            normals::face_the_viewer(s);
        }
        if let (true, true, Some(map)) = (U::PRESENT, v.albedo_map, m.diffuse) {
            albedo(s, maps, &map, texels);
        }
        let specular = v.specular != SpecularSource::None;
        let occluded = match m.occlusion_map {
            Some(map) if U::PRESENT && v.occlusion_map => {
                occluded_ambient(s, maps, &map, self.lights.ambient);
                true
            }
            _ => false,
        };
        lighting::light::<CAPS>(s, &self.lights, self.transforms.eye, self.shininess, specular, occluded);
        match (v.specular, m.specular_map) {
            (SpecularSource::Map, Some(map)) if U::PRESENT => specular_color(s, maps, &map, texels, m.specular),
            _ => s.specular_color = Column3::splat(m.specular),
        }
        if let (true, true, Some(map)) = (U::PRESENT, v.glow_map, m.glow_map) {
            glow(s, maps, &map, texels);
        }
        let out = &mut colors[..s.len];
        match (specular, v.glow_map) {
            (false, false) => {
                for (i, c) in out.iter_mut().enumerate() {
                    *c = s.albedo.get(i).mul_elem(s.diffuse.get(i));
                }
            }
            (true, false) => {
                for (i, c) in out.iter_mut().enumerate() {
                    *c = s.albedo.get(i).mul_elem(s.diffuse.get(i))
                        + s.specular_color.get(i).mul_elem(s.specular.get(i));
                }
            }
            (false, true) => {
                for (i, c) in out.iter_mut().enumerate() {
                    *c = s.albedo.get(i).mul_elem(s.diffuse.get(i)) + s.emission.get(i);
                }
            }
            (true, true) => {
                for (i, c) in out.iter_mut().enumerate() {
                    let lit = s.albedo.get(i).mul_elem(s.diffuse.get(i))
                        + s.specular_color.get(i).mul_elem(s.specular.get(i));
                    *c = lit + s.emission.get(i);
                }
            }
        }
        stored(out, self.space());
    }
}

impl<A, B, U, T, C, const CAPS: u32> Shader for SurfaceShader<'_, A, B, U, T, C, CAPS>
where
    A: Slot<Vec3>,
    B: Slot<Vec3>,
    U: Slot<Vec2>,
    T: Slot<Vec4>,
    C: Slot<Vec3>,
{
    type Varyings = SurfaceVaryings<A, B, U, T, C>;
    /// Flat shading's light for the whole triangle (zero for the other models).
    type Face = LightTerms;
    // Normals, texture coordinates and colours are read only where the variant says, and it checks the mesh has
    // them (a vertex-coloured draw carries texture coordinates, as zeros, for a mesh without).
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const BATCHED: bool = true;
    const CUTOUT: bool = has(CAPS, capabilities::CUTOUT);

    /// A cut-off tested against the diffuse map's alpha ([`Cutout::Map`]), or a draw cut out whole
    /// ([`Cutout::Everything`]: counted like any draw, every fragment discarded).
    #[inline(always)]
    fn cutout(&self) -> bool {
        self.variant.cutout != Cutout::None
    }

    /// The maps are read with slopes when the variant mipmaps.
    #[inline(always)]
    fn slopes(&self) -> bool {
        self.mipmaps()
    }

    /// One fragment as a batch of one.
    fn kept(&self, f: &Fragment, face: &LightTerms, v: &Self::Varyings, slopes: &Slopes<Self::Varyings>) -> bool {
        let mut keep = [false; BATCH_SIZE];
        self.kept_batch(&FragmentBatch::single(f, *face, *v, slopes), &mut keep);
        keep[0]
    }

    /// Reads the diffuse map's alpha at the fragments' texture coordinates, with the draw's filter and wrap mode.
    #[inline(always)]
    fn kept_batch(&self, batch: &FragmentBatch<Self::Varyings, LightTerms>, keep: &mut [bool; BATCH_SIZE]) {
        let (Cutout::Map(cutoff), Some(map), true) = (self.variant.cutout, self.material.diffuse, U::PRESENT) else {
            // Cut out whole: nothing kept.
            *keep = [false; BATCH_SIZE];
            return;
        };
        let at = self.coordinates(batch);
        // Only the transparency byte is read: as stored.
        let mut texels = [0; BATCH_SIZE];
        let mip = self.mip_filter();
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => {
                MapReader::<Nearest, Repeat>::new(mip).read(&map, &at, &mut texels)
            }
            (FilterMode::Nearest, WrapMode::Clamp) => {
                MapReader::<Nearest, Clamp>::new(mip).read(&map, &at, &mut texels)
            }
            (FilterMode::Bilinear, WrapMode::Repeat) => {
                MapReader::<Bilinear, Repeat>::new(mip).read(&map, &at, &mut texels);
            }
            (FilterMode::Bilinear, WrapMode::Clamp) => {
                MapReader::<Bilinear, Clamp>::new(mip).read(&map, &at, &mut texels);
            }
        }
        for (k, &texel) in keep.iter_mut().zip(&texels).take(batch.len()) {
            *k = self.material.keeps(texel_alpha(texel), cutoff);
        }
    }

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.transforms.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn clip_from_object(&self) -> Option<&Mat4> {
        Some(&self.transforms.clip_from_object)
    }

    /// The slots the variant reads, for vertex `i`; a slot carried but not read holds zero (so that it never
    /// makes the pipeline skip a triangle).
    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Self::Varyings {
        let (t, v, layout) = (&self.transforms, &self.variant, &self.layout);
        let (first, second) = match v.shading {
            ShadingModel::Phong if has(CAPS, capabilities::PER_PIXEL) => (
                A::capture(|| world_normal(&t.normal, mesh.normal(i))),
                B::capture(|| if layout.second { t.model.transform_point(mesh.position(i)) } else { Vec3::ZERO }),
            ),
            ShadingModel::Normals => {
                (A::capture(|| world_normal(&t.normal, mesh.normal(i))), B::capture(|| Vec3::ZERO))
            }
            ShadingModel::Gouraud if has(CAPS, capabilities::GOURAUD) => {
                let light = vertex_light(t, &self.lights, self.material.shininess, v, mesh, i);
                (A::capture(|| light.diffuse), B::capture(|| light.specular))
            }
            // Unlit and flat shading and the depth view read neither slot (nor do models this shader leaves out: `new`
            // refuses them).
            _ => (A::capture(|| Vec3::ZERO), B::capture(|| Vec3::ZERO)),
        };
        SurfaceVaryings {
            first,
            second,
            uv: U::capture(|| if layout.uvs { mesh.uv(i) } else { Vec2::ZERO }),
            tangent: T::capture(|| {
                if !layout.tangents {
                    return Vec4::ZERO;
                }
                self.tangent_frame.world_tangent(self.tangents, i)
            }),
            color: C::capture(|| if layout.colors { mesh.color(i) } else { Vec3::ZERO }),
        }
    }

    /// Flat shading's light: the face normal (through the normal matrix), the highlight at the world centroid.
    #[inline(always)]
    fn face(&self, mesh: &Mesh<'_>, triangle: [usize; 3]) -> LightTerms {
        if !has(CAPS, capabilities::FLAT) || self.variant.shading != ShadingModel::Flat {
            return LightTerms { diffuse: Vec3::ZERO, specular: Vec3::ZERO };
        }
        face_light(&self.transforms, &self.lights, self.material.shininess, &self.variant, mesh, triangle)
    }

    /// One fragment as a batch of one.
    fn fragment(&self, f: &Fragment, face: &LightTerms, v: &Self::Varyings, slopes: &Slopes<Self::Varyings>) -> Vec3 {
        let mut colors = [Vec3::ZERO; BATCH_SIZE];
        self.shade_batch(&FragmentBatch::single(f, *face, *v, slopes), &mut colors);
        colors[0]
    }

    /// Gathers the slots the model reads from the fragments' varyings into columns and runs its stages over them.
    #[inline(always)]
    fn shade_batch(&self, batch: &FragmentBatch<Self::Varyings, LightTerms>, colors: &mut [Vec3; BATCH_SIZE]) {
        let len = batch.len();
        let first = || Column3::gather(len, |i| batch.varyings(i).first.get().unwrap_or(Vec3::ZERO));
        let second = || Column3::gather(len, |i| batch.varyings(i).second.get().unwrap_or(Vec3::ZERO));
        let (m, v) = (&self.material, &self.variant);
        // The albedo before the diffuse map: the material colour, times the vertex colours.
        let base_albedo = || {
            if C::PRESENT && v.vertex_colors {
                Column3::gather(len, |i| m.color.mul_elem(batch.varyings(i).color.get().unwrap_or(Vec3::ZERO)))
            } else {
                Column3::splat(m.color)
            }
        };
        const COARSE: u32 = capabilities::UNLIT | capabilities::FLAT | capabilities::GOURAUD;
        match v.shading {
            ShadingModel::Phong if has(CAPS, capabilities::PER_PIXEL) => {
                let mut s = Scratch::new(len);
                s.albedo = base_albedo();
                s.normal = first();
                if self.layout.second {
                    s.world = second();
                }
                if self.layout.uvs {
                    s.at = self.coordinates(batch);
                }
                if self.layout.tangents && T::PRESENT {
                    let tangent = |i| batch.varyings(i).tangent.get().unwrap_or(Vec4::ZERO);
                    s.tangent = Column3::gather(len, |i| tangent(i).truncate());
                    s.handedness = columns::gather(len, |i| tangent(i).w);
                }
                if has(CAPS, capabilities::TWO_SIDED) && v.two_sided {
                    s.facing = columns::gather(len, |i| if batch.fragment(i).front_facing { 1.0 } else { -1.0 });
                }
                self.shade(&mut s, colors);
            }
            ShadingModel::Depth { near, far } if has(CAPS, capabilities::VIEWS) => {
                views::depth(batch.depths(), len, near, far, colors);
            }
            ShadingModel::Normals if has(CAPS, capabilities::VIEWS) => views::normals(first(), len, colors),
            ShadingModel::Unlit | ShadingModel::Flat | ShadingModel::Gouraud if has(CAPS, COARSE) => {
                let albedo = base_albedo();
                let at = if self.layout.uvs { self.coordinates(batch) } else { Coordinates::ZERO };
                let (diffuse, specular) = match v.shading {
                    ShadingModel::Gouraud => (first(), second()),
                    ShadingModel::Flat => (
                        Column3::gather(len, |i| batch.face(i).diffuse),
                        Column3::gather(len, |i| batch.face(i).specular),
                    ),
                    _ => (Column3::ZERO, Column3::ZERO),
                };
                let light = match v.shading {
                    ShadingModel::Flat | ShadingModel::Gouraud => {
                        coarse::Light::Lit { diffuse: &diffuse, specular: &specular }
                    }
                    _ => coarse::Light::None,
                };
                let reads = coarse::Reads { maps: U::PRESENT, mip_filter: self.mip_filter(), space: self.space() };
                match (v.filter, v.wrap) {
                    (_, _) if !U::PRESENT => {
                        coarse::shade::<Nearest, Clamp>(v, m, albedo, &at, &light, len, colors, reads);
                    }
                    (FilterMode::Nearest, WrapMode::Repeat) => {
                        coarse::shade::<Nearest, Repeat>(v, m, albedo, &at, &light, len, colors, reads);
                    }
                    (FilterMode::Nearest, WrapMode::Clamp) => {
                        coarse::shade::<Nearest, Clamp>(v, m, albedo, &at, &light, len, colors, reads);
                    }
                    (FilterMode::Bilinear, WrapMode::Repeat) => {
                        coarse::shade::<Bilinear, Repeat>(v, m, albedo, &at, &light, len, colors, reads);
                    }
                    (FilterMode::Bilinear, WrapMode::Clamp) => {
                        coarse::shade::<Bilinear, Clamp>(v, m, albedo, &at, &light, len, colors, reads);
                    }
                }
            }
            // A model this shader leaves out: `new` refuses its variant.
            _ => {}
        }
    }
}
