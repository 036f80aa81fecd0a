//! Per-pixel lighting of one fragment in scalar maths: what a target without SIMD registers runs in place of its
//! batch of one ([`BATCH_SIZE`] is 1 there) for the draws it covers ([`Surface::one_fragment`]: lit per pixel, no
//! map but a diffuse map without levels of detail, no shadow maps).
//!
//! The batch's stages ([`super::surface`], [`super::lighting`]) fill working columns, loop over lanes and decide,
//! for each batch, which stages run; with one fragment a batch, each of those costs as much as the arithmetic
//! (on the firmware's frame, 528 instructions a fragment). Here the decision is made once per draw, and the
//! fragment's values stay in registers. The operations are the batch's, in the same order, so the bits are the
//! same: the tests below compare the two over every variant covered, and the firmware's checksums compare this
//! path (the target's) with the batch's (the host's).

use super::capabilities::{self, has};
use super::surface::Surface;
use super::{LightKind, NormalSource, SpecularSource};
use crate::color::{ShadingSpace, encode_srgb, unpack_rgb888};
use crate::math::float;
use crate::math::{Vec2, Vec3};
use crate::pipeline::BATCH_SIZE;
use crate::texture::{Bilinear, Clamp, Filter, FilterMode, MipFilter, Nearest, Repeat, Texture, Wrap, WrapMode};

impl<const CAPS: u32> Surface<'_, CAPS> {
    /// Whether the draw's per-pixel fragments go through [`Self::per_pixel_one`], decided once per draw: where a
    /// batch holds one fragment, for a draw with interpolated normals that reads no shadow map and no map, or a
    /// diffuse map alone without levels of detail (`maps`: its shader carries texture coordinates and the variant
    /// reads them).
    pub fn one_fragment(&self, maps: bool) -> bool {
        let v = &self.variant;
        let maps_covered = !maps || (!v.lighting_maps() && v.mip_filter == MipFilter::Off);
        BATCH_SIZE == 1 && maps_covered && v.normals == NormalSource::Interpolated && v.shadowed_lights == 0
    }

    /// The albedo `base` (the material colour, times the vertex colour) times the diffuse map at `uv`, as the
    /// batch's stage computes it ([`super::maps::albedo`] without levels of detail): the texel filtered as stored
    /// and unpacked, or, in linear light, its texels decoded and then filtered. `base` without a diffuse map.
    #[inline(always)]
    pub fn albedo_one(&self, base: Vec3, uv: Vec2) -> Vec3 {
        let Some(map) = &self.material.diffuse else { return base };
        let linear = self.space() == ShadingSpace::Linear;
        let sample = |map: &Texture<'_>| match (self.variant.filter, self.variant.wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => texel::<Nearest, Repeat>(map, uv, linear),
            (FilterMode::Nearest, WrapMode::Clamp) => texel::<Nearest, Clamp>(map, uv, linear),
            (FilterMode::Bilinear, WrapMode::Repeat) => texel::<Bilinear, Repeat>(map, uv, linear),
            (FilterMode::Bilinear, WrapMode::Clamp) => texel::<Bilinear, Clamp>(map, uv, linear),
        };
        base.mul_elem(sample(map))
    }

    /// The colour of one fragment lit per pixel, as the draw stores it ([`Self::one_fragment`] must hold):
    /// `normal` and `world` as interpolated, `albedo` the material colour (times the vertex colour), and `facing`
    /// its sign under two-sided lighting (`None` without). The batch's stages, operation for operation:
    /// [`super::normals::interpolated`], [`super::normals::face_the_viewer`], [`super::lighting::light`], the
    /// sum of the lit albedo and highlights, [`super::maps::stored`].
    #[inline(always)]
    pub fn per_pixel_one(&self, normal: Vec3, world: Vec3, albedo: Vec3, facing: Option<f32>) -> Vec3 {
        let n = normal.normalize_or_zero();
        let n = match facing {
            Some(sign) if has(CAPS, capabilities::TWO_SIDED) => n * sign,
            _ => n,
        };
        let specular = self.variant.specular != SpecularSource::None;
        // Toward the eye: worked out for the first light that lights the fragment, and not at all when none does.
        let mut view = None;
        let mut diffuse = self.lights.ambient;
        let mut highlights = Vec3::ZERO;
        for light in self.lights.lights {
            let (to_light, share) = match light.kind {
                LightKind::Directional { to_light } => (to_light, None),
                _ if has(CAPS, capabilities::POINT_LIGHTS) => light.kind.toward(world),
                // A shader compiled without point lights has had its variant checked to have none.
                _ => (Vec3::ZERO, None),
            };
            let n_dot_l = n.dot(to_light);
            let mut arriving = float::max(n_dot_l, 0.0);
            if let Some(share) = share {
                arriving *= share;
            }
            diffuse += light.color * arriving;
            // Unlit, the batch adds +0.0 (its highlight times zero), which leaves the sum as it was: so the
            // highlight is worked out only where the light arrives.
            if specular && n_dot_l > 0.0 {
                let view = *view.get_or_insert_with(|| (self.transforms.eye - world).normalize_or_zero());
                let h = (to_light + view).normalize_or_zero();
                let mut k = self.shininess.raise(float::max(n.dot(h), 0.0));
                if let Some(share) = share {
                    k *= share;
                }
                highlights += light.color * k;
            }
        }
        let lit = albedo.mul_elem(diffuse);
        let color = if specular { lit + self.material.specular.mul_elem(highlights) } else { lit };
        match self.space() {
            ShadingSpace::Linear => encode_srgb(color),
            ShadingSpace::Encoded => color,
        }
    }
}

/// `map`'s value at `uv` with filter `F` and wrap mode `W`: in linear light when `linear`, else as stored.
#[inline(always)]
fn texel<F: Filter, W: Wrap>(map: &Texture<'_>, uv: Vec2, linear: bool) -> Vec3 {
    if linear { F::sample_light::<W>(map, uv) } else { unpack_rgb888(F::sample_packed::<W>(map, uv)) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Mat4;
    use crate::math::float::Exponent;
    use crate::pipeline::DrawState;
    use crate::pipeline::columns::{Column, Column2, Column3};
    use crate::shading::scratch::Scratch;
    use crate::shading::{Cone, Falloff, Layout, Light, Lighting, Material, Transforms, Variant};
    use crate::shading::{Cutout, ShadingModel, capabilities::ALL};
    use crate::texture::{FilterMode, MipFilter, WrapMode};

    /// A per-pixel variant lit by `lights` in `space`, with or without highlights, vertex colours and two sides.
    fn variant(specular: bool, colors: bool, two_sided: bool, space: ShadingSpace, lights: &[Light<'_>]) -> Variant {
        let points = lights.iter().filter(|l| !matches!(l.kind, LightKind::Directional { .. })).count();
        Variant {
            shading: ShadingModel::Phong,
            vertex_colors: colors,
            world: true,
            uvs: false,
            tangents: false,
            albedo_map: false,
            normals: NormalSource::Interpolated,
            specular: if specular { SpecularSource::Constant } else { SpecularSource::None },
            glow_map: false,
            occlusion_map: false,
            metallic_roughness_map: false,
            environment: false,
            cutout: Cutout::None,
            two_sided,
            space,
            filter: FilterMode::Nearest,
            wrap: WrapMode::Repeat,
            mip_filter: MipFilter::Off,
            directional_lights: lights.len() - points,
            point_lights: points,
            shadowed_lights: 0,
            pcf_radius: 0,
            state: DrawState::DEFAULT,
        }
    }

    /// The batch's colour of one fragment: its stages over working columns of one filled lane.
    fn batch_color(surface: &Surface<'_, ALL>, normal: Vec3, world: Vec3, albedo: Vec3, facing: f32) -> Vec3 {
        let mut s = Scratch::new();
        s.len = 1;
        s.normal = Column3::splat(normal);
        s.world = Column3::splat(world);
        s.albedo = Column3::splat(albedo);
        s.facing = Column::splat(facing);
        let mut colors = [Vec3::ZERO; BATCH_SIZE];
        surface.per_pixel::<false>(&mut s, &mut colors);
        colors[0]
    }

    /// Every covered variant, over normals, points and albedos that include the degenerate ones (a zero normal, a
    /// point at the eye, a light at the point), gives the batch's bits.
    #[test]
    fn one_fragment_gives_the_batch_bits() {
        let cone = Cone::new(Vec3::new(0.0, -1.0, 0.2), 0.3, 0.7);
        let light_sets: [&[Light<'_>]; 4] = [
            &[Light::directional(Vec3::new(0.3, 0.8, 0.5), Vec3::new(1.0, 0.95, 0.9))],
            &[
                Light::directional(Vec3::new(-0.6, 0.2, 0.7), Vec3::splat(0.6)),
                Light::directional(Vec3::new(0.1, -0.9, 0.3), Vec3::new(0.2, 0.3, 0.9)),
            ],
            &[Light { kind: LightKind::point(Vec3::new(1.0, 2.0, 1.5)), ..Light::directional(Vec3::Y, Vec3::ONE) }],
            &[Light {
                kind: LightKind::Spot {
                    position: Vec3::new(0.2, 3.0, 0.4),
                    falloff: Falloff::inverse_square(Some(6.0)),
                    cone,
                },
                ..Light::directional(Vec3::Y, Vec3::new(2.0, 1.5, 1.0))
            }],
        ];
        let normals = [Vec3::new(0.2, 0.9, 0.1), Vec3::new(-3.0, 0.5, 2.0), Vec3::ZERO, Vec3::new(1e-30, 0.0, 0.0)];
        let worlds = [Vec3::new(0.1, 0.2, 0.3), Vec3::new(-1.0, 0.0, 2.5), Vec3::new(0.0, 0.0, 5.0)];
        let identity = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY);
        let transforms = Transforms { eye: Vec3::new(0.0, 0.0, 5.0), ..identity };
        let mut compared = 0;
        for lights in light_sets {
            for (specular, colors, two_sided) in
                [(true, false, false), (false, false, false), (true, true, false), (true, false, true)]
            {
                for space in [ShadingSpace::Encoded, ShadingSpace::Linear] {
                    let variant = variant(specular, colors, two_sided, space, lights);
                    let material =
                        Material { specular: Vec3::splat(0.35), shininess: 24.0, ..Material::plain(Vec3::splat(0.8)) };
                    let surface = Surface::<ALL> {
                        transforms,
                        material,
                        shininess: Exponent::new(material.shininess),
                        lights: Lighting { ambient: Vec3::splat(0.1), lights, environment: None, space },
                        variant,
                        layout: Layout { first: true, second: true, uvs: false, tangents: false, colors },
                    };
                    assert!(surface.one_fragment(false) == (BATCH_SIZE == 1));
                    for (&normal, &world) in normals.iter().zip(worlds.iter().cycle()) {
                        for facing in [1.0, -1.0] {
                            let albedo = if colors { Vec3::new(0.8, 0.4, 0.2) } else { material.color };
                            let sign = two_sided.then_some(facing);
                            let one = surface.per_pixel_one(normal, world, albedo, sign);
                            let batch =
                                batch_color(&surface, normal, world, albedo, if two_sided { facing } else { 1.0 });
                            let bits = |c: Vec3| [c.x, c.y, c.z].map(f32::to_bits);
                            assert_eq!(bits(one), bits(batch), "{variant:?} n {normal:?} world {world:?} {facing}");
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert_eq!(compared, 4 * 4 * 2 * 4 * 2);
    }

    /// The albedo times a diffuse map, for both filters, wrap modes and spaces, at coordinates inside, on the
    /// edges of and outside the map, gives the batch's bits; a map beyond it, or levels of detail, leave the
    /// one-fragment path.
    #[test]
    fn a_diffuse_map_gives_the_batch_bits() {
        let texels: [u32; 20] = core::array::from_fn(|i| (i as u32).wrapping_mul(0x0931_5F27) & 0xFF_FFFF);
        let map = Texture::new(&texels, 5, 4).unwrap();
        let lights = [Light::directional(Vec3::new(0.3, 0.8, 0.5), Vec3::new(1.0, 0.95, 0.9))];
        let identity = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY);
        let transforms = Transforms { eye: Vec3::new(0.0, 0.0, 5.0), ..identity };
        let uvs = [(0.31, 0.77), (0.0, 0.0), (1.0, 1.0), (-0.052, 1.0007), (2.6, -3.1), (0.5, 0.5)];
        let mut compared = 0;
        for filter in [FilterMode::Nearest, FilterMode::Bilinear] {
            for wrap in [WrapMode::Repeat, WrapMode::Clamp] {
                for space in [ShadingSpace::Encoded, ShadingSpace::Linear] {
                    let variant = Variant {
                        uvs: true,
                        albedo_map: true,
                        filter,
                        wrap,
                        ..variant(true, false, false, space, &lights)
                    };
                    let material = Material {
                        specular: Vec3::splat(0.35),
                        shininess: 24.0,
                        diffuse: Some(map),
                        filter,
                        wrap,
                        ..Material::plain(Vec3::new(0.9, 0.8, 1.0))
                    };
                    let surface = Surface::<ALL> {
                        transforms,
                        material,
                        shininess: Exponent::new(material.shininess),
                        lights: Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space },
                        variant,
                        layout: Layout { first: true, second: true, uvs: true, tangents: false, colors: false },
                    };
                    assert!(surface.one_fragment(true) == (BATCH_SIZE == 1));
                    for &(u, v) in &uvs {
                        let (normal, world) = (Vec3::new(0.2, 0.9, 0.1), Vec3::new(0.1, 0.2, 0.3));
                        let one = surface.per_pixel_one(
                            normal,
                            world,
                            surface.albedo_one(material.color, Vec2::new(u, v)),
                            None,
                        );
                        let mut s = Scratch::new();
                        s.len = 1;
                        s.normal = Column3::splat(normal);
                        s.world = Column3::splat(world);
                        s.albedo = Column3::splat(material.color);
                        s.at.uv = Column2 { x: Column::splat(u), y: Column::splat(v) };
                        let mut colors = [Vec3::ZERO; BATCH_SIZE];
                        surface.per_pixel::<true>(&mut s, &mut colors);
                        let bits = |c: Vec3| [c.x, c.y, c.z].map(f32::to_bits);
                        assert_eq!(bits(one), bits(colors[0]), "{filter:?} {wrap:?} {space:?} at ({u}, {v})");
                        compared += 1;
                    }
                    let with = |variant: Variant| Surface { variant, ..surface }.one_fragment(true);
                    assert!(!with(Variant { specular: SpecularSource::Map, ..variant }));
                    assert!(!with(Variant { glow_map: true, ..variant }));
                    assert!(!with(Variant { occlusion_map: true, ..variant }));
                    assert!(!with(Variant { mip_filter: MipFilter::Linear, ..variant }));
                }
            }
        }
        assert_eq!(compared, 2 * 2 * 2 * uvs.len());
    }
}
