//! Rendering benchmarks: whole meshes at typical sizes, and large-triangle fill rate.
//!
//! Run with `cargo bench -p rastty-bench --bench render`. Meshes are generated here, so the figures need nothing
//! outside the repository.

use divan::{Bencher, black_box};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::DrawState;
use rastty_core::shading::{Light, LightKind, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};
use rastty_core::testing::draw_mesh_general;
use rastty_core::texture::{FilterMode, Texture, WrapMode};

fn main() {
    divan::main();
}

/// A UV sphere of radius 1 with `rings * segments * 2` triangles (less the degenerate ones at the poles).
struct Sphere {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<Vec2>,
    indices: Vec<u32>,
}

impl Sphere {
    fn new(rings: u32, segments: u32) -> Self {
        let mut s = Sphere { positions: vec![], normals: vec![], uvs: vec![], indices: vec![] };
        for r in 0..=rings {
            let theta = std::f32::consts::PI * r as f32 / rings as f32;
            for g in 0..=segments {
                let phi = std::f32::consts::TAU * g as f32 / segments as f32;
                let n = Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
                s.positions.push(n);
                s.normals.push(n);
                s.uvs.push(Vec2::new(g as f32 / segments as f32, 1.0 - r as f32 / rings as f32));
            }
        }
        let row = segments + 1;
        for r in 0..rings {
            for g in 0..segments {
                let (a, b) = (r * row + g, (r + 1) * row + g);
                // Counter-clockwise seen from outside.
                s.indices.extend_from_slice(&[a, a + 1, b, a + 1, b + 1, b]);
            }
        }
        s
    }

    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, Indices::U32(&self.indices))
            .unwrap()
            .with_normals(&self.normals)
            .unwrap()
            .with_uvs(&self.uvs)
            .unwrap()
    }
}

fn checker(size: u32) -> Vec<u32> {
    (0..size * size).map(|i| if ((i % size) / 8 + (i / size) / 8) % 2 == 0 { 0xE0C090 } else { 0x304060 }).collect()
}

struct Frame {
    width: u32,
    height: u32,
    color: Vec<u32>,
    depth: Vec<f32>,
}

impl Frame {
    fn new(width: u32, height: u32) -> Self {
        let n = (width * height) as usize;
        Frame { width, height, color: vec![0; n], depth: vec![0.0; n] }
    }
}

fn transforms(width: u32, height: u32, distance: f32) -> Transforms {
    let view = look_at(Vec3::new(0.0, 0.3, distance), Vec3::ZERO, Vec3::Y).unwrap();
    let projection = perspective(0.9, width as f32 / height as f32, 0.1, 100.0).unwrap();
    Transforms::new(Mat4::from_axis_angle(Vec3::Y, 0.4), view, projection)
}

/// One white directional light, already unit length (so built as is rather than normalised again).
const LIGHTS: [Light<'static>; 1] = [Light {
    kind: LightKind::Directional { to_light: Vec3::new(0.408_248_3, 0.816_496_6, 0.408_248_3) },
    color: Vec3::ONE,
    shadow: None,
}];

const LIGHTING: Lighting<'static> =
    Lighting { ambient: Vec3::splat(0.1), lights: &LIGHTS, environment: None, space: ShadingSpace::Linear };

/// `mesh` under `shading` in a plain warm grey without highlights, textured by `texture` (bilinear, repeating)
/// when given.
fn object<'a>(mesh: Mesh<'a>, t: Transforms, shading: ShadingModel, texture: Option<Texture<'a>>) -> Object<'a> {
    let material = Material {
        diffuse: texture,
        filter: FilterMode::Bilinear,
        wrap: WrapMode::Repeat,
        ..Material::plain(Vec3::new(0.9, 0.8, 0.7))
    };
    Object { mesh, tangents: None, transforms: t, shading, material }
}

fn render(bencher: Bencher, sphere: &Sphere, width: u32, height: u32, distance: f32, shading: ShadingModel) {
    let mut frame = Frame::new(width, height);
    let o = object(sphere.mesh(), transforms(width, height, distance), shading, None);
    bencher.bench_local(|| {
        let mut target =
            Target::new(Rgb888(&mut frame.color), &mut frame.depth[..], frame.width, frame.height).unwrap();
        target.clear(Vec3::ZERO);
        black_box(draw_mesh(&mut target, &o, &LIGHTING, &DrawState::default()).unwrap());
    });
}

/// ~2.5k triangles filling most of an 800x800 frame, per-pixel Lambert (Phong model, no specular).
#[divan::bench]
fn sphere_2_5k_phong_lambert_800x800(bencher: Bencher) {
    render(bencher, &Sphere::new(35, 36), 800, 800, 2.6, ShadingModel::Phong);
}

/// ~100k triangles at 640x480, per-pixel Lambert.
#[divan::bench]
fn sphere_100k_phong_lambert_640x480(bencher: Bencher) {
    render(bencher, &Sphere::new(224, 224), 640, 480, 2.6, ShadingModel::Phong);
}

/// ~1M triangles at 640x480, per-pixel Lambert.
#[divan::bench(sample_count = 20)]
fn sphere_1m_phong_lambert_640x480(bencher: Bencher) {
    render(bencher, &Sphere::new(707, 707), 640, 480, 2.6, ShadingModel::Phong);
}

/// The 2.5k sphere through the general path (`rastty_core::testing::draw_mesh_general`: one scalar shader deciding
/// everything per fragment, through the general pixel loop), for comparison with the specialised one. The pixels
/// are the same.
#[divan::bench]
fn sphere_2_5k_phong_lambert_800x800_unspecialised(bencher: Bencher) {
    let sphere = Sphere::new(35, 36);
    let mut frame = Frame::new(800, 800);
    let o = object(sphere.mesh(), transforms(800, 800, 2.6), ShadingModel::Phong, None);
    bencher.bench_local(|| {
        let mut target = Target::new(Rgb888(&mut frame.color), &mut frame.depth[..], 800, 800).unwrap();
        target.clear(Vec3::ZERO);
        black_box(draw_mesh_general(&mut target, &o, &LIGHTING, &DrawState::default()).unwrap());
    });
}

/// The 2.5k sphere at 800x800 under one light of each kind, per-pixel Lambert: what a light costs that is worked
/// out per fragment (a point light's direction), weakens with distance (the inverse square within a range), or has
/// a cone (a spot lighting part of the sphere), against the directional light of the benchmarks above.
mod lights {
    use super::*;
    use rastty_core::shading::{Cone, Falloff};

    /// Where the point and spot lights are: up, right and in front of the sphere, 3 units from its centre.
    const PLACE: Vec3 = Vec3::new(1.0, 2.0, 2.0);

    fn lit(bencher: Bencher, kind: LightKind, color: Vec3) {
        let sphere = Sphere::new(35, 36);
        let mut frame = Frame::new(800, 800);
        let o = object(sphere.mesh(), transforms(800, 800, 2.6), ShadingModel::Phong, None);
        let lights = [Light { kind, color, shadow: None }];
        let lighting =
            Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
        bencher.bench_local(|| {
            let mut target = Target::new(Rgb888(&mut frame.color), &mut frame.depth[..], 800, 800).unwrap();
            target.clear(Vec3::ZERO);
            black_box(draw_mesh(&mut target, &o, &lighting, &DrawState::default()).unwrap());
        });
    }

    #[divan::bench]
    fn directional(bencher: Bencher) {
        lit(bencher, LIGHTS[0].kind, Vec3::ONE);
    }

    #[divan::bench]
    fn point(bencher: Bencher) {
        lit(bencher, LightKind::point(PLACE), Vec3::ONE);
    }

    #[divan::bench]
    fn point_inverse_square_range(bencher: Bencher) {
        let kind = LightKind::Point { position: PLACE, falloff: Falloff::inverse_square(Some(6.0)) };
        lit(bencher, kind, Vec3::splat(9.0));
    }

    #[divan::bench]
    fn spot_inverse_square_range(bencher: Bencher) {
        let cone = Cone::new(-PLACE, 0.2, 0.35);
        let kind = LightKind::Spot { position: PLACE, falloff: Falloff::inverse_square(Some(6.0)), cone };
        lit(bencher, kind, Vec3::splat(9.0));
    }
}

/// Fill rate: two triangles covering a 1024x1024 frame, in Mpx/s.
mod fill_rate {
    use super::*;

    const SIZE: u32 = 1024;

    /// A quad covering the whole frame, facing the camera, with normals and texture coordinates.
    fn quad() -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec2>, Vec<u32>) {
        let p = vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ];
        let n = vec![
            Vec3::new(-0.3, -0.3, 0.9),
            Vec3::new(0.3, -0.3, 0.9),
            Vec3::new(0.3, 0.3, 0.9),
            Vec3::new(-0.3, 0.3, 0.9),
        ];
        let uv = vec![Vec2::new(0.0, 0.0), Vec2::new(4.0, 0.0), Vec2::new(4.0, 4.0), Vec2::new(0.0, 4.0)];
        (p, n, uv, vec![0, 1, 2, 0, 2, 3])
    }

    fn fill(bencher: Bencher, shading: ShadingModel, textured: bool, band: u32) {
        let (p, n, uv, ix) = quad();
        let mesh = Mesh::new(&p, Indices::U32(&ix)).unwrap().with_normals(&n).unwrap().with_uvs(&uv).unwrap();
        let texels = checker(256);
        let texture = Texture::new(&texels, 256, 256).unwrap();
        // An orthographic-like framing through a perspective camera at distance: the quad fills the frame.
        let view = look_at(Vec3::new(0.0, 0.0, 1.0 / (0.45f32).tan()), Vec3::ZERO, Vec3::Y).unwrap();
        let t = Transforms::new(Mat4::IDENTITY, view, perspective(0.9, 1.0, 0.1, 100.0).unwrap());
        let o = object(mesh, t, shading, textured.then_some(texture));
        let mut color = vec![0u32; (SIZE * band) as usize];
        let mut depth = vec![0f32; (SIZE * band) as usize];
        bencher.counter(divan::counter::ItemsCount::new((SIZE * SIZE) as usize)).bench_local(|| {
            for y0 in (0..SIZE).step_by(band as usize) {
                let mut target = Target::band(Rgb888(&mut color), &mut depth[..], SIZE, SIZE, y0..y0 + band).unwrap();
                target.clear(Vec3::ZERO);
                black_box(draw_mesh(&mut target, &o, &LIGHTING, &DrawState::default()).unwrap());
            }
        });
    }

    #[divan::bench(args = [SIZE, 16])]
    fn flat(bencher: Bencher, band: u32) {
        fill(bencher, ShadingModel::Flat, false, band);
    }

    #[divan::bench(args = [SIZE, 16])]
    fn gouraud(bencher: Bencher, band: u32) {
        fill(bencher, ShadingModel::Gouraud, false, band);
    }

    #[divan::bench(args = [SIZE, 16])]
    fn textured_bilinear_gouraud(bencher: Bencher, band: u32) {
        fill(bencher, ShadingModel::Gouraud, true, band);
    }

    #[divan::bench(args = [SIZE, 16])]
    fn phong(bencher: Bencher, band: u32) {
        fill(bencher, ShadingModel::Phong, false, band);
    }
}

/// Texture sampling alone, 1024 samples along a diagonal.
mod sampling {
    use super::*;
    use rastty_core::texture::{Bilinear, Nearest, Repeat};

    #[divan::bench]
    fn bilinear_repeat(bencher: Bencher) {
        let texels = checker(256);
        let t = Texture::new(&texels, 256, 256).unwrap();
        bencher.counter(divan::counter::ItemsCount::new(1024usize)).bench_local(|| {
            let mut acc = Vec3::ZERO;
            for i in 0..1024 {
                let f = i as f32 / 256.0;
                acc += t.sample::<Bilinear, Repeat>(Vec2::new(black_box(f), f * 0.7));
            }
            acc
        });
    }

    #[divan::bench]
    fn nearest_repeat(bencher: Bencher) {
        let texels = checker(256);
        let t = Texture::new(&texels, 256, 256).unwrap();
        bencher.counter(divan::counter::ItemsCount::new(1024usize)).bench_local(|| {
            let mut acc = Vec3::ZERO;
            for i in 0..1024 {
                let f = i as f32 / 256.0;
                acc += t.sample::<Nearest, Repeat>(Vec2::new(black_box(f), f * 0.7));
            }
            acc
        });
    }
}

/// What a mapped draw of the 2.5k sphere at 800x800 uses (see [`surface`]).
#[derive(Clone, Copy)]
enum Maps {
    /// No maps, no highlights: the counterpart of `sphere_2_5k_phong_lambert_800x800`.
    None,
    /// Diffuse, tangent-space normal and specular maps (1024x1024, bilinear), a shadow-casting light with a
    /// 2048x2048 map (its depth pass included): the shading of the tinyrenderer comparison.
    DiffuseNormalSpecularShadow,
}

fn surface(bencher: Bencher, maps: Maps) {
    use rastty_core::math::BoundingSphere;
    use rastty_core::math::Vec4;
    use rastty_core::shading::{NormalMap, NormalSpace};
    use rastty_core::shadow::{ShadowBias, ShadowMap, ShadowView, clear_shadow_depth, draw_shadow_caster};
    let sphere = Sphere::new(35, 36);
    let mesh = sphere.mesh();
    let mut tangents = vec![Vec4::ZERO; sphere.positions.len()];
    rastty_core::mesh::compute_tangents(&mesh, &mut tangents).unwrap();
    let texels = checker(1024);
    let bumps: Vec<u32> = texels.iter().map(|t| if *t == 0xE0C090 { 0xA080F0 } else { 0x8080FF }).collect();
    let (diffuse, normal) = (Texture::new(&texels, 1024, 1024).unwrap(), Texture::new(&bumps, 1024, 1024).unwrap());
    let mut frame = Frame::new(800, 800);
    let t = transforms(800, 800, 2.6);
    let light = Light::directional(Vec3::new(0.408_248_3, 0.816_496_6, 0.408_248_3), Vec3::ONE);
    let material = match maps {
        Maps::None => Material::plain(Vec3::new(0.9, 0.8, 0.7)),
        Maps::DiffuseNormalSpecularShadow => Material {
            specular: Vec3::splat(0.5),
            diffuse: Some(diffuse),
            normal_map: Some(NormalMap { texture: normal, space: NormalSpace::Tangent }),
            specular_map: Some(diffuse),
            ..Material::plain(Vec3::new(0.9, 0.8, 0.7))
        },
    };
    let object = Object { mesh, tangents: Some(&tangents), transforms: t, shading: ShadingModel::Phong, material };
    let shadowed = matches!(maps, Maps::DiffuseNormalSpecularShadow);
    let view = ShadowView::fit(light.kind, BoundingSphere { centre: Vec3::ZERO, radius: 1.0 }, 2048).unwrap();
    let mut shadow_depth = vec![0.0; 2048 * 2048];
    bencher.bench_local(|| {
        let mut light = light;
        if shadowed {
            clear_shadow_depth(&mut shadow_depth);
            draw_shadow_caster(&view, &mut shadow_depth, &mesh, &t.model).unwrap();
            light.shadow = Some(ShadowMap::new(view, &shadow_depth, ShadowBias::DEFAULT, 1).unwrap());
        }
        let lights = [light];
        let scene =
            Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
        let mut target = Target::new(Rgb888(&mut frame.color), &mut frame.depth[..], 800, 800).unwrap();
        target.clear(Vec3::ZERO);
        black_box(draw_mesh(&mut target, &object, &scene, &DrawState::default()).unwrap());
    });
}

/// The 2.5k sphere with nothing to map, tangents given: since the two shading systems became one, the same draw as
/// `sphere_2_5k_phong_lambert_800x800` (kept so that earlier figures stay comparable).
#[divan::bench]
fn sphere_2_5k_surface_plain_800x800(bencher: Bencher) {
    surface(bencher, Maps::None);
}

/// Diffuse + tangent-space normal + specular maps and a shadow-casting light, shadow pass included.
#[divan::bench]
fn sphere_2_5k_surface_maps_shadow_800x800(bencher: Bencher) {
    surface(bencher, Maps::DiffuseNormalSpecularShadow);
}
