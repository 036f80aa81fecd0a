//! Environment light drawn: known answers for glTF's metallic-roughness model lit by an environment alone.
//!
//! - The white furnace: under a uniform white environment a white surface, metal or dielectric, rough or smooth,
//!   reflects exactly the light it receives, more than single scattering (the split-sum table's `A + B`) gives.
//! - A mirror-smooth white metal shows the environment's texel in the mirror direction.
//! - The occlusion map scales the light from the environment.

use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::environment::panorama::{Panorama, texel_direction};
use rastty_core::environment::{Environment, Prefiltering};
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::DrawState;
use rastty_core::shading::{Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Samples, Target};
use rastty_core::texture::Texture;

use crate::common::{ExactColor, Prepared, Torus, blocks, multisampled};

const SIZE: u32 = 96;

/// The torus without its vertex colours: white where the material is.
fn white_torus(torus: &Torus) -> Mesh<'_> {
    let mesh = Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap();
    mesh.with_normals(&torus.normals).unwrap().with_uvs(&torus.uvs).unwrap()
}

/// Every covered pixel of `mesh` drawn with the metallic-roughness model and `material`, lit by `environment`
/// alone, seen from `eye`: exact `f32` values, as computed.
fn draw(mesh: Mesh<'_>, material: Material<'_>, environment: &Environment<'_>, eye: Vec3) -> Vec<Vec3> {
    let view = look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, perspective(0.9, 1.0, 0.5, 10.0).unwrap());
    let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::MetallicRoughness, material };
    let lighting =
        Lighting { ambient: Vec3::ZERO, lights: &[], environment: Some(environment), space: ShadingSpace::Encoded };
    let mut color = vec![[0u32; 3]; (SIZE * SIZE) as usize];
    let mut depth = vec![1f32; color.len()];
    let mut target = Target::new(ExactColor(&mut color), &mut depth[..], SIZE, SIZE).unwrap();
    let nothing = Vec3::splat(-1.0);
    target.clear(nothing);
    let (variant, stats) = draw_mesh(&mut target, &object, &lighting, &DrawState::DEFAULT).unwrap();
    assert!(variant.environment && variant.world, "{variant}");
    assert!(variant.to_string().contains("lights the environment"), "{variant}");
    assert!(stats.fragments > 100);
    color
        .iter()
        .map(|c| Vec3::new(f32::from_bits(c[0]), f32::from_bits(c[1]), f32::from_bits(c[2])))
        .filter(|c| *c != nothing)
        .collect()
}

#[test]
fn a_white_surface_in_a_white_furnace_reflects_what_it_receives() {
    let white = vec![Vec3::ONE; 256 * 128];
    let prepared = Prepared::new(&Panorama::new(256, 128, &white).unwrap(), Prefiltering::DEFAULT);
    let environment = prepared.environment();
    let torus = Torus::new(1.0, 0.45, 48, 24);
    for metallic in [0.0, 1.0] {
        for roughness in [0.0, 0.3, 0.6, 1.0] {
            let material = Material { metallic, roughness, ..Material::plain(Vec3::ONE) };
            let pixels = draw(white_torus(&torus), material, &environment, Vec3::new(0.0, 1.2, 3.0));
            for p in &pixels {
                // 1 within the error of the irradiance's sums over a 256x128 panorama and of `f32`.
                assert!((p.max_elem() - 1.0).abs() < 1e-4 && (p.x - p.z).abs() < 1e-6, "{metallic} {roughness}: {p:?}");
            }
            // Single scattering alone reflects A + B of it: less for a rough metal seen head-on (1 - ln 2 at
            // roughness 1).
            let (a, b) = prepared.split_sum.at(1.0, roughness);
            if metallic == 1.0 && roughness == 1.0 {
                assert!(a + b < 0.31, "{}", a + b);
            }
            let least = pixels.iter().map(|p| p.x).fold(f32::INFINITY, f32::min);
            assert!(least > a + b - 1e-4, "{metallic} {roughness}: {least} against {}", a + b);
        }
    }
}

#[test]
fn a_mirror_smooth_metal_reflects_the_texel_in_the_mirror_direction() {
    let texels = blocks();
    let panorama = Panorama::new(64, 32, &texels).unwrap();
    // The first level is the panorama itself (the same size): a mirror reads its texels.
    let prepared = Prepared::new(&panorama, Prefiltering { height: 32, ..Prefiltering::DEFAULT });
    let environment = prepared.environment();
    // A square facing the camera on +z whose normals mirror the view (+z) into the centre of texel (19, 11), inside
    // the block of texels 16-23 and 8-15.
    let target = texel_direction(19, 11, 64, 32);
    let n = (target + Vec3::Z).normalize_or_zero();
    let positions =
        [Vec3::new(-0.3, -0.3, 0.0), Vec3::new(0.3, -0.3, 0.0), Vec3::new(0.3, 0.3, 0.0), Vec3::new(-0.3, 0.3, 0.0)];
    let normals = [n; 4];
    let indices = [0u16, 1, 2, 0, 2, 3];
    let mesh = Mesh::new(&positions, Indices::U16(&indices)).unwrap().with_normals(&normals).unwrap();
    let mirror = Material { metallic: 1.0, roughness: 0.0, ..Material::plain(Vec3::ONE) };
    let pixels = draw(mesh, mirror, &environment, Vec3::new(0.0, 0.0, 3.0));
    let texel = panorama.texel(19, 11);
    assert_ne!(texel, panorama.texel(24, 11));
    assert_ne!(texel, panorama.texel(19, 16));
    // Every pixel sees the square from near +z, so mirrors a direction in the same block: the block's colour, times
    // the white metal's reflectance at roughness 0 (A + B = 1 within the table's sums).
    for p in &pixels {
        let gap = (*p - texel).map(f32::abs).max_elem();
        assert!(gap < 1e-5, "{p:?} against {texel:?}");
    }
}

#[test]
fn the_occlusion_map_scales_the_environment_light() {
    let white = vec![Vec3::ONE; 256 * 128];
    let prepared = Prepared::new(&Panorama::new(256, 128, &white).unwrap(), Prefiltering::DEFAULT);
    let environment = prepared.environment();
    let torus = Torus::new(1.0, 0.45, 48, 24);
    // One texel of 128: a share of 128 / 255 (occlusion maps are data, not sRGB).
    let occlusion = [0x0080_8080u32];
    let map = Texture::new(&occlusion, 1, 1).unwrap();
    let material = Material { metallic: 0.0, roughness: 0.5, occlusion_map: Some(map), ..Material::plain(Vec3::ONE) };
    let pixels = draw(white_torus(&torus), material, &environment, Vec3::new(0.0, 1.2, 3.0));
    for p in &pixels {
        assert!((p.y - 128.0 / 255.0).abs() < 1e-4, "{p:?}");
    }
}

#[test]
fn a_turned_environment_is_seen_turned() {
    let texels = blocks();
    let prepared =
        Prepared::new(&Panorama::new(64, 32, &texels).unwrap(), Prefiltering { height: 32, ..Prefiltering::DEFAULT });
    let environment = prepared.environment();
    // Turned a quarter turn counter-clockwise seen from above: what was seen along -z is seen along -x.
    let turned = environment.turned(core::f32::consts::FRAC_PI_2);
    for d in [Vec3::new(0.3, 0.2, -0.9), Vec3::new(-0.5, -0.4, 0.2)] {
        let d = d.normalize_or_zero();
        // -z to -x: (x, y, z) to (z, y, -x).
        let seen = turned.radiance(Vec3::new(d.z, d.y, -d.x));
        assert!((seen - environment.radiance(d)).length() < 1e-5, "{d:?}");
    }
}

#[test]
fn a_frame_cleared_pixel_by_pixel_holds_each_pixels_colour_in_every_sample() {
    // Rows 1 and 2 of a 6x4 frame, four samples a pixel.
    let (width, rows) = (6usize, 1..3u32);
    let mut color = vec![[0u32; 3]; width * 2 * 4];
    let mut depth = vec![0f32; color.len()];
    let mut target = multisampled(ExactColor(&mut color), &mut depth[..], 6, 4, rows, Samples::Four);
    target.clear_with(|x, y| Vec3::new(x as f32, y as f32, 0.5));
    for (i, c) in color.iter().enumerate() {
        let (pixel, _sample) = (i / 4, i % 4);
        let (x, y) = (pixel % width, 1 + pixel / width);
        assert_eq!(*c, [(x as f32).to_bits(), (y as f32).to_bits(), 0.5f32.to_bits()], "sample {i}");
    }
    assert!(depth.iter().all(|&d| d == 1.0), "the depth is cleared to the far plane");
}
