//! The mapped shader: vertex stage per draw variant, fragment stages over batches.

use core::marker::PhantomData;

use super::columns::{self, Column2, Column3};
use super::maps::{MapReader, albedo, glow, specular_color};
use super::normals::{self, object_map, tangent_map};
use super::scratch::Scratch;
use super::varyings::{Slot, SurfaceVaryings};
use super::{NormalSource, SceneLights, SpecularSource, SurfaceMaterial, SurfaceVariant, lighting};
use crate::math::{Mat3, Vec2, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{BATCH_SIZE, Fragment, FragmentBatch, Shader};
use crate::shading::Transforms;
use crate::texture::{Bilinear, Clamp, Filter, FilterMode, Nearest, Repeat, Wrap, WrapMode};

/// Shades a mesh with a [`SurfaceMaterial`] under [`SceneLights`], computing what its [`SurfaceVariant`] says.
///
/// The varyings it carries are fixed by its type (`W`: world position, `U`: texture coordinates, `T`: tangent;
/// each the value's type or [`super::Absent`]). Everything else, which maps are sampled and how each light is
/// applied, is decided once per batch of fragments and runs as a loop compiled for that choice, so the number of
/// compiled loops is the sum of the choices, not their product.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceShader<'a, W, U, T> {
    transforms: Transforms,
    /// Object to world for tangents (the model's upper 3x3).
    tangent_matrix: Mat3,
    /// -1 when the model matrix mirrors (which flips the bitangent), else 1.
    handedness: f32,
    tangents: &'a [Vec4],
    material: SurfaceMaterial<'a>,
    lights: SceneLights<'a>,
    variant: SurfaceVariant,
    _varyings: PhantomData<(W, U, T)>,
}

impl<'a, W, U, T> SurfaceShader<'a, W, U, T>
where
    W: Slot<Vec3>,
    U: Slot<Vec2>,
    T: Slot<Vec4>,
{
    /// A shader for a resolved `variant`. `tangents` holds one per vertex when `T` is carried (may be empty
    /// otherwise).
    pub fn new(
        variant: SurfaceVariant,
        transforms: Transforms,
        tangents: &'a [Vec4],
        material: SurfaceMaterial<'a>,
        lights: SceneLights<'a>,
    ) -> Self {
        let handedness = if transforms.mirrors() { -1.0 } else { 1.0 };
        Self {
            transforms,
            tangent_matrix: transforms.model.to_mat3(),
            handedness,
            tangents,
            material,
            lights,
            variant,
            _varyings: PhantomData,
        }
    }

    /// Runs the stages of the variant over `s`, whose varyings columns are filled, into `colors`.
    fn shade(&self, s: &mut Scratch, colors: &mut [Vec3; BATCH_SIZE]) {
        // One decision per batch: every map of a draw is read with the draw's filter and wrap mode.
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
        let maps = &mut MapReader::<F, Wr>::new();
        let v = &self.variant;
        let m = &self.material;
        // The geometric normal is the shading normal without a normal map, and offsets shadow lookups: with a map
        // and no shadows, nothing reads it.
        let interpolated_shading = v.normals == NormalSource::Interpolated;
        if interpolated_shading || v.shadowed_lights > 0 {
            normals::interpolated(s, interpolated_shading);
        }
        match (v.normals, m.normal_map) {
            (NormalSource::TangentMap, Some(map)) => tangent_map(s, maps, &map.texture),
            (NormalSource::ObjectMap, Some(map)) => object_map(s, maps, &map.texture, &self.transforms.normal),
            _ => {}
        }
        match m.diffuse {
            Some(map) if v.albedo_map => albedo(s, maps, &map, m.color),
            _ => s.albedo = Column3::splat(m.color),
        }
        let specular = v.specular != SpecularSource::None;
        lighting::light(s, &self.lights, self.transforms.eye, m.shininess, specular);
        match (v.specular, m.specular_map) {
            (SpecularSource::Map, Some(map)) => specular_color(s, maps, &map, m.specular),
            _ => s.specular_color = Column3::splat(m.specular),
        }
        if let (true, Some(map)) = (v.glow_map, m.glow_map) {
            glow(s, maps, &map);
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
    }
}

impl<W, U, T> Shader for SurfaceShader<'_, W, U, T>
where
    W: Slot<Vec3>,
    U: Slot<Vec2>,
    T: Slot<Vec4>,
{
    type Varyings = SurfaceVaryings<W, U, T>;
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes { normals: true, uvs: U::PRESENT, colors: false };
    const BATCHED: bool = true;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.transforms.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Self::Varyings {
        let t = &self.transforms;
        SurfaceVaryings {
            normal: crate::shading::world_normal(&t.normal, mesh.normal(i)),
            world: W::capture(|| t.model.transform_point(mesh.position(i))),
            uv: U::capture(|| mesh.uv(i)),
            tangent: T::capture(|| {
                // A tangent slice shorter than the mesh cannot happen (the variant checks it); NaN would skip the
                // triangle rather than panic.
                let tangent = self.tangents.get(i).copied().unwrap_or(Vec4::new(f32::NAN, 0.0, 0.0, 0.0));
                (self.tangent_matrix * tangent.truncate()).extend(tangent.w * self.handedness)
            }),
        }
    }

    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}

    /// One fragment as a batch of one.
    fn fragment(&self, f: &Fragment, _: &(), v: &Self::Varyings) -> Vec3 {
        let mut colors = [Vec3::ZERO; BATCH_SIZE];
        self.shade_batch(&(), &FragmentBatch::single(f, *v), &mut colors);
        colors[0]
    }

    /// Interpolates the carried varyings into columns, lane by lane, and runs the variant's stages over them.
    #[inline(always)]
    fn shade_batch(&self, _: &(), batch: &FragmentBatch<Self::Varyings>, colors: &mut [Vec3; BATCH_SIZE]) {
        let mut s = Scratch::new(batch.len());
        let [v0, d1, d2] = batch.triangle();
        let w = batch.weights();
        s.normal = Column3::interpolated(v0.normal, d1.normal, d2.normal, w);
        if let (Some(v0), Some(d1), Some(d2)) = (v0.world.get(), d1.world.get(), d2.world.get()) {
            s.world = Column3::interpolated(v0, d1, d2, w);
        }
        if let (Some(v0), Some(d1), Some(d2)) = (v0.uv.get(), d1.uv.get(), d2.uv.get()) {
            s.uv = Column2::interpolated(v0, d1, d2, w);
        }
        if let (Some(v0), Some(d1), Some(d2)) = (v0.tangent.get(), d1.tangent.get(), d2.tangent.get()) {
            s.tangent = Column3::interpolated(v0.truncate(), d1.truncate(), d2.truncate(), w);
            s.handedness = columns::interpolated(v0.w, d1.w, d2.w, w);
        }
        self.shade(&mut s, colors);
    }
}
