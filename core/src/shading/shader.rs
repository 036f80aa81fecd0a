//! The surface shader: the vertex stage of the draw's variant, and its fragment stages over batches.

use core::cell::RefCell;
use core::fmt;
use core::marker::PhantomData;

use super::capabilities::{self, has};
use super::light_terms::{face_light, vertex_light};
use super::scratch::{Coordinates, Scratch};
use super::surface::Surface;
use super::varyings::{Absent, Slot, SurfaceVaryings};
use super::{Cutout, Lighting, Material, NormalSource, ShadingError, Variant, coarse, views};
use crate::color::ShadingSpace;
use crate::math::float::Exponent;
use crate::math::{Mat4, Vec2, Vec3, Vec4};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::columns::{self, Column3};
use crate::pipeline::{BATCH_SIZE, Fragment, FragmentBatch, OneFragment, Shader, Slopes};
use crate::shading::{LightTerms, ShadingModel, TangentFrame, Transforms, world_normal};
use crate::texture::MipFilter;

/// Working columns a shader keeps for its draw's batches: one set where the target has SIMD registers (32 lanes of
/// every column, 5.7 KB: cleared for each batch, they took 53.3 of the 175.0 million instructions of a frame of the
/// head, callgrind), none elsewhere, where a batch's fresh set is one fragment's columns, which the compiler keeps
/// in registers (kept in the shader, the firmware's frame 0 at 16 KiB took 25,054,000 instructions, 3.6 % more).
const KEPT_SCRATCH: usize = if BATCH_SIZE > 1 { 1 } else { 0 };

/// Shades a mesh with a [`Material`] under [`Lighting`], computing what its [`Variant`] says:
/// its shading model, maps and lights.
///
/// The varyings it carries are fixed by its type (`A` and `B`: the two `Vec3` slots of the variant's
/// [`Layout`](super::Layout), `U`: texture coordinates, `T`: tangent, `C`: vertex colour; each the value's type or
/// [`Absent`]). Everything else, the shading model, which maps are sampled and how each light is applied, is
/// decided once per batch of fragments and runs as a loop compiled for that choice, so the number of compiled
/// loops is the sum of the choices, not their product. Only the vertex stage and the gathering of a batch's
/// varyings depend on the slots: the stages that follow are compiled once for every layout.
#[derive(Clone)]
pub struct SurfaceShader<'a, A, B, U, T, C = Absent, const CAPS: u32 = { capabilities::ALL }> {
    surface: Surface<'a, CAPS>,
    tangent_frame: TangentFrame,
    tangents: &'a [Vec4],
    /// The batches' working columns, one set for the whole draw where the target keeps one ([`KEPT_SCRATCH`]):
    /// [`Shader::shade_batch`] takes `&self`, so they are borrowed for the length of one batch, which calls
    /// nothing that borrows them again.
    scratch: RefCell<[Scratch; KEPT_SCRATCH]>,
    /// Each fragment is lit per pixel in scalar maths ([`Surface::per_pixel_one`]) rather than as a batch of one:
    /// decided once, for the draw.
    one_fragment: bool,
    _varyings: PhantomData<(A, B, U, T, C)>,
}

impl<A, B, U, T, C, const CAPS: u32> fmt::Debug for SurfaceShader<'_, A, B, U, T, C, CAPS> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SurfaceShader")
            .field("surface", &self.surface)
            .field("tangent_frame", &self.tangent_frame)
            .field("tangents", &self.tangents.len())
            .finish_non_exhaustive()
    }
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
    /// (they may carry more), `CAPS` ([`capabilities`]) leaves out its shading model, point lights, shadow
    /// maps, two-sided lighting, cut-outs, mipmaps, linear light or lighting maps, or its per-pixel lighting takes
    /// normals from anything but the interpolated ones or a map read through texture coordinates (no resolved
    /// variant does).
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
            ShadingModel::MetallicRoughness => capabilities::METALLIC_ROUGHNESS,
            ShadingModel::Depth { .. } | ShadingModel::Normals => capabilities::VIEWS,
        };
        let compiled = has(CAPS, model)
            && (variant.point_lights == 0 || has(CAPS, capabilities::POINT_LIGHTS))
            && (variant.shadowed_lights == 0 || has(CAPS, capabilities::SHADOWS))
            && (!variant.two_sided || has(CAPS, capabilities::TWO_SIDED))
            && (variant.cutout == Cutout::None || has(CAPS, capabilities::CUTOUT))
            && (variant.mip_filter == MipFilter::Off || has(CAPS, capabilities::MIPMAPS))
            && (variant.space == ShadingSpace::Encoded || has(CAPS, capabilities::LINEAR_LIGHT))
            && (!variant.lighting_maps() || has(CAPS, capabilities::LIGHTING_MAPS));
        // A normal map is read through texture coordinates: without them, per-pixel lighting has interpolated
        // normals (as every resolved variant does), which `ALWAYS_ONE_FRAGMENT` relies on.
        let normals = !variant.shading.per_pixel()
            || variant.normals == NormalSource::Interpolated
            || (layout.uvs && matches!(variant.normals, NormalSource::TangentMap | NormalSource::ObjectMap));
        if !(carried && compiled && normals) {
            return Err(ShadingError::Unsupported);
        }
        let shininess = Exponent::new(material.shininess);
        let surface = Surface { transforms, material, shininess, lights, variant, layout };
        let per_pixel = variant.shading == ShadingModel::Phong && has(CAPS, capabilities::PER_PIXEL);
        let one_fragment = per_pixel && surface.one_fragment(U::PRESENT && layout.uvs);
        Ok(Self {
            surface,
            tangent_frame: TangentFrame::new(&transforms),
            tangents,
            scratch: RefCell::new(core::array::from_fn(|_| Scratch::new())),
            one_fragment,
            _varyings: PhantomData,
        })
    }

    /// Runs `stages` over working columns for a batch of `len`: the draw's own where the target keeps them
    /// ([`KEPT_SCRATCH`]), otherwise a fresh set.
    #[inline(always)]
    fn with_scratch(&self, len: usize, stages: impl FnOnce(&mut Scratch)) {
        if KEPT_SCRATCH > 0 {
            let mut kept = self.scratch.borrow_mut();
            if let Some(s) = kept.first_mut() {
                s.len = len;
                return stages(s);
            }
        }
        let mut fresh = Scratch::new();
        fresh.len = len;
        stages(&mut fresh);
    }

    /// Whether every fragment this shader lights per pixel goes through [`Self::lit_one`], known from its type:
    /// where batches hold one fragment, for a shader compiled without shadow maps that carries no texture
    /// coordinates (so reads no map, and [`Self::new`] accepts no normal map) or reads at most a diffuse map
    /// without levels of detail (compiled without [`capabilities::LIGHTING_MAPS`] and [`capabilities::MIPMAPS`]).
    /// Then its batch stages for per-pixel lighting are not compiled in (on the firmware, most of the core's code
    /// they would add).
    const ALWAYS_ONE_FRAGMENT: bool = BATCH_SIZE == 1
        && !has(CAPS, capabilities::SHADOWS)
        && (!U::PRESENT || !has(CAPS, capabilities::LIGHTING_MAPS | capabilities::MIPMAPS));

    /// Whether this shader lights fragments of `model` per pixel: [`ShadingModel::Phong`] or
    /// [`ShadingModel::MetallicRoughness`], where it is compiled for it.
    #[inline(always)]
    fn lights_per_pixel(model: ShadingModel) -> bool {
        match model {
            ShadingModel::Phong => has(CAPS, capabilities::PER_PIXEL),
            ShadingModel::MetallicRoughness => has(CAPS, capabilities::METALLIC_ROUGHNESS),
            _ => false,
        }
    }

    /// Whether this draw lights its fragments per pixel one at a time, in scalar maths ([`Self::lit_one`]).
    #[inline(always)]
    fn lights_one_fragment(&self) -> bool {
        BATCH_SIZE == 1 && (Self::ALWAYS_ONE_FRAGMENT || self.one_fragment)
    }

    /// One fragment of a draw lit per pixel in scalar maths ([`Surface::per_pixel_one`]): its albedo (times the
    /// diffuse map's texel, [`Surface::albedo_one`]), facing and varyings as the batch's stages gather them.
    #[inline(always)]
    fn lit_one(&self, fragment: &Fragment, varyings: &SurfaceVaryings<A, B, U, T, C>) -> Vec3 {
        let (m, v, layout) = (&self.surface.material, &self.surface.variant, &self.surface.layout);
        let albedo = match varyings.color.get() {
            Some(color) if v.vertex_colors => m.color.mul_elem(color),
            _ => m.color,
        };
        let albedo = match varyings.uv.get() {
            Some(uv) if layout.uvs && v.albedo_map => self.surface.albedo_one(albedo, uv),
            _ => albedo,
        };
        let two_sided = has(CAPS, capabilities::TWO_SIDED) && v.two_sided;
        let facing = two_sided.then(|| if fragment.front_facing { 1.0 } else { -1.0 });
        let normal = varyings.first.get().unwrap_or(Vec3::ZERO);
        let world = if layout.second { varyings.second.get().unwrap_or(Vec3::ZERO) } else { Vec3::ZERO };
        self.surface.per_pixel_one(normal, world, albedo, facing)
    }

    /// The batch's texture coordinates, with their slopes when the variant mipmaps.
    #[inline(always)]
    fn coordinates(&self, batch: &FragmentBatch<'_, SurfaceVaryings<A, B, U, T, C>, LightTerms>) -> Coordinates {
        let uv = |v: &SurfaceVaryings<A, B, U, T, C>| v.uv.get().unwrap_or(Vec2::ZERO);
        let mipmaps = U::PRESENT && self.surface.mipmaps();
        Coordinates::gather(batch.len(), |i| uv(batch.varyings(i)), mipmaps, |i| batch.slopes_of(i, uv))
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
    const CUTOUT: bool = has(CAPS, capabilities::CUTOUT);

    /// A cut-off tested against the diffuse map's alpha ([`Cutout::Map`]), or a draw cut out whole
    /// ([`Cutout::Everything`]: counted like any draw, every fragment discarded).
    #[inline(always)]
    fn cutout(&self) -> bool {
        self.surface.variant.cutout != Cutout::None
    }

    /// The maps are read with slopes when the variant mipmaps.
    #[inline(always)]
    fn slopes(&self) -> bool {
        U::PRESENT && self.surface.mipmaps()
    }

    /// One fragment as a batch of one.
    fn kept(&self, f: &Fragment, face: &LightTerms, v: &Self::Varyings, slopes: &Slopes<Self::Varyings>) -> bool {
        let mut keep = [false; BATCH_SIZE];
        self.kept_batch(&OneFragment::new(f, *face, *v, slopes).batch(), &mut keep);
        keep[0]
    }

    /// Reads the diffuse map's alpha at the fragments' texture coordinates, with the draw's filter and wrap mode.
    #[inline(always)]
    fn kept_batch(&self, batch: &FragmentBatch<'_, Self::Varyings, LightTerms>, keep: &mut [bool; BATCH_SIZE]) {
        let map = matches!(self.surface.variant.cutout, Cutout::Map(_));
        let at = if U::PRESENT && map { self.coordinates(batch) } else { Coordinates::ZERO };
        if U::PRESENT {
            self.surface.kept::<true>(&at, batch.len(), keep);
        } else {
            self.surface.kept::<false>(&at, batch.len(), keep);
        }
    }

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.surface.transforms.clip_from_object.project_point(mesh.position(i))
    }

    #[inline(always)]
    fn clip_from_object(&self) -> Option<&Mat4> {
        Some(&self.surface.transforms.clip_from_object)
    }

    /// The slots the variant reads, for vertex `i`; a slot carried but not read holds zero (so that it never
    /// makes the pipeline skip a triangle).
    #[inline(always)]
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Self::Varyings {
        let (t, v, layout) = (&self.surface.transforms, &self.surface.variant, &self.surface.layout);
        let (first, second) = match v.shading {
            model if Self::lights_per_pixel(model) => (
                A::capture(|| world_normal(&t.normal, mesh.normal(i))),
                B::capture(|| if layout.second { t.model.transform_point(mesh.position(i)) } else { Vec3::ZERO }),
            ),
            ShadingModel::Normals => {
                (A::capture(|| world_normal(&t.normal, mesh.normal(i))), B::capture(|| Vec3::ZERO))
            }
            ShadingModel::Gouraud if has(CAPS, capabilities::GOURAUD) => {
                let light = vertex_light(t, &self.surface.lights, self.surface.material.shininess, v, mesh, i);
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
        if !has(CAPS, capabilities::FLAT) || self.surface.variant.shading != ShadingModel::Flat {
            return LightTerms { diffuse: Vec3::ZERO, specular: Vec3::ZERO };
        }
        let f = &self.surface;
        face_light(&f.transforms, &f.lights, f.material.shininess, &f.variant, mesh, triangle)
    }

    /// One fragment: lit per pixel in scalar maths where batches hold one fragment and the draw allows it
    /// (`core/src/shading/one_fragment.rs`), else as a batch of one.
    ///
    /// Inlined where there is no SIMD, into the pixel loops' one-at-a-time calls, which hand over slopes only
    /// because the signature has them: then the slopes, unread, are not computed (on the firmware 8 instructions a
    /// fragment, and 760 bytes of the core's code).
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(always))]
    fn fragment(&self, f: &Fragment, face: &LightTerms, v: &Self::Varyings, slopes: &Slopes<Self::Varyings>) -> Vec3 {
        if self.surface.variant.shading == ShadingModel::Phong && self.lights_one_fragment() {
            return self.lit_one(f, v);
        }
        let mut colors = [Vec3::ZERO; BATCH_SIZE];
        self.shade_batch(&OneFragment::new(f, *face, *v, slopes).batch(), &mut colors);
        colors[0]
    }

    /// Gathers the slots the model reads from the fragments' varyings into columns and runs its stages over them.
    #[inline(always)]
    fn shade_batch(&self, batch: &FragmentBatch<'_, Self::Varyings, LightTerms>, colors: &mut [Vec3; BATCH_SIZE]) {
        let len = batch.len();
        let first = || Column3::gather(len, |i| batch.varyings(i).first.get().unwrap_or(Vec3::ZERO));
        let second = || Column3::gather(len, |i| batch.varyings(i).second.get().unwrap_or(Vec3::ZERO));
        let (m, v, layout) = (&self.surface.material, &self.surface.variant, &self.surface.layout);
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
            // Where batches hold one fragment (a constant: elsewhere this is not compiled), if the draw said so.
            ShadingModel::Phong if self.lights_one_fragment() => {
                colors[0] = self.lit_one(&batch.fragment(0), batch.varyings(0));
            }
            model if Self::lights_per_pixel(model) => {
                self.with_scratch(len, |s| {
                    s.albedo = base_albedo();
                    s.normal = first();
                    if layout.second {
                        s.world = second();
                    }
                    if layout.uvs {
                        s.at = self.coordinates(batch);
                    }
                    if layout.tangents && T::PRESENT {
                        let tangent = |i| batch.varyings(i).tangent.get().unwrap_or(Vec4::ZERO);
                        s.tangent = Column3::gather(len, |i| tangent(i).truncate());
                        s.handedness = columns::gather(len, |i| tangent(i).w);
                    }
                    if has(CAPS, capabilities::TWO_SIDED) && v.two_sided {
                        s.facing = columns::gather(len, |i| if batch.fragment(i).front_facing { 1.0 } else { -1.0 });
                    }
                    // Without texture coordinates, the stages compiled without maps.
                    if U::PRESENT {
                        self.surface.per_pixel::<true>(s, colors);
                    } else {
                        self.surface.per_pixel::<false>(s, colors);
                    }
                });
            }
            ShadingModel::Depth { near, far } if has(CAPS, capabilities::VIEWS) => {
                views::depth(batch.depths(), len, near, far, colors);
            }
            ShadingModel::Normals if has(CAPS, capabilities::VIEWS) => views::normals(first(), len, colors),
            ShadingModel::Unlit | ShadingModel::Flat | ShadingModel::Gouraud if has(CAPS, COARSE) => {
                let albedo = base_albedo();
                let at = if layout.uvs { self.coordinates(batch) } else { Coordinates::ZERO };
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
                if U::PRESENT {
                    self.surface.coarse::<true>(albedo, &at, &light, len, colors);
                } else {
                    self.surface.coarse::<false>(albedo, &at, &light, len, colors);
                }
            }
            // A model this shader leaves out: `new` refuses its variant.
            _ => {}
        }
    }
}
