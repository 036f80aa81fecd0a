//! The fragment stages of a surface, over a batch's columns: what [`super::SurfaceShader`] runs once it has
//! gathered the varyings of its layout into a [`Scratch`].
//!
//! Nothing here depends on the varyings layout, so each stage is compiled once per set of [`capabilities`], per
//! filter and wrap mode of the maps, and for shaders with and without texture coordinates (`MAPS`: without them no
//! map is read, and none of the code that reads maps is compiled in), not once more for every layout of varyings
//! a program draws with.

use super::capabilities::{self, has};
use super::coarse;
use super::maps::{
    self, MapReader, Texels, albedo, glow, metallic_roughness, occluded_ambient, specular_color, stored,
};
use super::normals::{self, object_map, tangent_map};
use super::scratch::{Coordinates, Scratch};
use super::{Cutout, Layout, Lighting, Material, NormalSource, ShadingModel, SpecularSource, Variant, lighting};
use crate::color::{ShadingSpace, texel_alpha};
use crate::math::Vec3;
use crate::math::float::Exponent;
use crate::pipeline::BATCH_SIZE;
use crate::pipeline::columns::{Column, Column3};
use crate::shading::Transforms;
use crate::texture::{Bilinear, Clamp, Filter, FilterMode, MipFilter, Nearest, Repeat, Wrap, WrapMode};

/// What a surface's fragment stages read, decided once per draw: its variant, matrices, material and lights, for
/// a shader compiled with the capabilities `CAPS`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Surface<'a, const CAPS: u32> {
    pub transforms: Transforms,
    pub material: Material<'a>,
    /// The material's shininess, sorted once for the highlights.
    pub shininess: Exponent,
    pub lights: Lighting<'a>,
    pub variant: Variant,
    /// The slots the variant fills (a general draw may carry more, which then hold zeros).
    pub layout: Layout,
}

impl<const CAPS: u32> Surface<'_, CAPS> {
    /// Whether the draw reads mipmapped maps: a constant false for a shader compiled without
    /// [`capabilities::MIPMAPS`].
    #[inline(always)]
    pub fn mipmaps(&self) -> bool {
        self.layout.uvs && has(CAPS, capabilities::MIPMAPS) && self.variant.mip_filter != MipFilter::Off
    }

    /// The filter between levels the draw's maps are read with.
    #[inline(always)]
    pub fn mip_filter(&self) -> MipFilter {
        if self.mipmaps() { self.variant.mip_filter } else { MipFilter::Off }
    }

    /// The space the draw lights in: a constant [`ShadingSpace::Encoded`] for a shader compiled without
    /// [`capabilities::LINEAR_LIGHT`].
    #[inline(always)]
    pub fn space(&self) -> ShadingSpace {
        if has(CAPS, capabilities::LINEAR_LIGHT) { self.variant.space } else { ShadingSpace::Encoded }
    }

    /// Runs the per-pixel lighting stages of the variant over `s`, whose varyings columns and base albedo are
    /// filled, into `colors`; with `MAPS`, for a shader that carries texture coordinates.
    pub fn per_pixel<const MAPS: bool>(&self, s: &mut Scratch, colors: &mut [Vec3; BATCH_SIZE]) {
        // One decision per batch: every map of a draw is read with the draw's filter and wrap mode. Without texture
        // coordinates no map is read.
        if !(MAPS && self.layout.uvs) {
            return self.stages::<Nearest, Clamp, false>(s, colors);
        }
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => self.stages::<Nearest, Repeat, true>(s, colors),
            (FilterMode::Nearest, WrapMode::Clamp) => self.stages::<Nearest, Clamp, true>(s, colors),
            (FilterMode::Bilinear, WrapMode::Repeat) => self.stages::<Bilinear, Repeat, true>(s, colors),
            (FilterMode::Bilinear, WrapMode::Clamp) => self.stages::<Bilinear, Clamp, true>(s, colors),
        }
    }

    /// [`Self::per_pixel`] with the maps read with filter `F` and wrap mode `Wr`, through one [`MapReader`]: maps of
    /// one size share their texel addresses.
    #[inline(always)]
    fn stages<F: Filter, Wr: Wrap, const MAPS: bool>(&self, s: &mut Scratch, colors: &mut [Vec3; BATCH_SIZE]) {
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
            (NormalSource::TangentMap, Some(map)) if MAPS => tangent_map(s, maps, &map.texture),
            (NormalSource::ObjectMap, Some(map)) if MAPS => {
                object_map(s, maps, &map.texture, &self.transforms.normal);
            }
            _ => {}
        }
        if has(CAPS, capabilities::TWO_SIDED) && v.two_sided {
            normals::face_the_viewer(s);
        }
        if let (true, true, Some(map)) = (MAPS, v.albedo_map, m.diffuse) {
            albedo(s, maps, &map, texels);
        }
        let occlusion = match m.occlusion_map {
            Some(map) if MAPS && v.occlusion_map => Some(map),
            _ => None,
        };
        if has(CAPS, capabilities::METALLIC_ROUGHNESS) && v.shading == ShadingModel::MetallicRoughness {
            // Each fragment's metallic factor and roughness and the occlusion of its indirect light, then the
            // reflected light, the base colour in it: plus the glow, and stored.
            let mut surface = [Column::splat(m.metallic), Column::splat(m.roughness)];
            if let (true, true, Some(map)) = (MAPS, v.metallic_roughness_map, m.metallic_roughness_map) {
                metallic_roughness(s, maps, &map, m.metallic, m.roughness, &mut surface);
            }
            if let Some(map) = occlusion {
                maps::occlusion(s, maps, &map);
            }
            let environment = self.lights.environment.filter(|_| v.environment);
            let indirect = lighting::Indirect { occluded: occlusion.is_some(), environment };
            lighting::light_metallic_roughness::<CAPS>(s, &self.lights, self.transforms.eye, &surface, indirect);
            if let (true, true, Some(map)) = (MAPS, v.glow_map, m.glow_map) {
                glow(s, maps, &map, texels);
            }
            let out = &mut colors[..s.len];
            for (i, c) in out.iter_mut().enumerate() {
                *c = if v.glow_map { s.diffuse.get(i) + s.emission.get(i) } else { s.diffuse.get(i) };
            }
            return stored(out, self.space());
        }
        let specular = v.specular != SpecularSource::None;
        if let Some(map) = occlusion {
            occluded_ambient(s, maps, &map, self.lights.ambient);
        }
        let occluded = occlusion.is_some();
        lighting::light::<CAPS>(s, &self.lights, self.transforms.eye, self.shininess, specular, occluded);
        match (v.specular, m.specular_map) {
            (SpecularSource::Map, Some(map)) if MAPS => specular_color(s, maps, &map, texels, m.specular),
            _ => s.specular_color = Column3::splat(m.specular),
        }
        if let (true, true, Some(map)) = (MAPS, v.glow_map, m.glow_map) {
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

    /// Colours a batch of the unlit, flat and Gouraud models ([`coarse::shade`]): `albedo` per fragment, texture
    /// coordinates `at` (with `MAPS`), under `light`.
    pub fn coarse<const MAPS: bool>(
        &self,
        albedo: Column3,
        at: &Coordinates,
        light: &coarse::Light<'_>,
        len: usize,
        colors: &mut [Vec3; BATCH_SIZE],
    ) {
        let (v, m) = (&self.variant, &self.material);
        let reads = coarse::Reads { maps: MAPS, mip_filter: self.mip_filter(), space: self.space() };
        match (v.filter, v.wrap) {
            _ if !(MAPS && self.layout.uvs) => {
                coarse::shade::<Nearest, Clamp>(v, m, albedo, at, light, len, colors, reads);
            }
            (FilterMode::Nearest, WrapMode::Repeat) => {
                coarse::shade::<Nearest, Repeat>(v, m, albedo, at, light, len, colors, reads);
            }
            (FilterMode::Nearest, WrapMode::Clamp) => {
                coarse::shade::<Nearest, Clamp>(v, m, albedo, at, light, len, colors, reads);
            }
            (FilterMode::Bilinear, WrapMode::Repeat) => {
                coarse::shade::<Bilinear, Repeat>(v, m, albedo, at, light, len, colors, reads);
            }
            (FilterMode::Bilinear, WrapMode::Clamp) => {
                coarse::shade::<Bilinear, Clamp>(v, m, albedo, at, light, len, colors, reads);
            }
        }
    }

    /// Which of a batch's `len` fragments, at texture coordinates `at` (with `MAPS`), the draw keeps ([`Cutout`]): a
    /// cut-off tested against the diffuse map's alpha, read with the draw's filter and wrap mode, or none at all for
    /// a draw cut out whole.
    pub fn kept<const MAPS: bool>(&self, at: &Coordinates, len: usize, keep: &mut [bool; BATCH_SIZE]) {
        let (Cutout::Map(cutoff), Some(map), true) = (self.variant.cutout, self.material.diffuse, MAPS) else {
            // Cut out whole: nothing kept.
            *keep = [false; BATCH_SIZE];
            return;
        };
        // Only the transparency byte is read: as stored.
        let mut texels = [0; BATCH_SIZE];
        let mip = self.mip_filter();
        match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => {
                MapReader::<Nearest, Repeat>::new(mip).read(&map, at, &mut texels)
            }
            (FilterMode::Nearest, WrapMode::Clamp) => MapReader::<Nearest, Clamp>::new(mip).read(&map, at, &mut texels),
            (FilterMode::Bilinear, WrapMode::Repeat) => {
                MapReader::<Bilinear, Repeat>::new(mip).read(&map, at, &mut texels);
            }
            (FilterMode::Bilinear, WrapMode::Clamp) => {
                MapReader::<Bilinear, Clamp>::new(mip).read(&map, at, &mut texels);
            }
        }
        for (k, &texel) in keep.iter_mut().zip(&texels).take(len) {
            *k = self.material.keeps(texel_alpha(texel), cutoff);
        }
    }
}
