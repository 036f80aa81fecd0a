//! glTF's metallic-roughness model drawn: known answers at the pixel on the camera's axis of a square that faces
//! the camera, lit head-on (light, normal and view along +z). There `n . v = n . l = n . h = v . h = 1`, so Fresnel
//! is `F0`, and at roughness 1 the distribution is `1 / pi` and the visibility term `1 / 4`: the pixel is
//! `pi ((1 - F0) c_diff / pi + F0 / (4 pi)) = (1 - F0) c_diff + F0 / 4` for a light of colour 1, and the ambient
//! light times the diffuse colour.

use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::DrawState;
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::Target;
use rastty_core::texture::Texture;

use crate::common::ExactColor;

/// An odd size: the middle pixel's centre is on the camera's axis.
const SIZE: u32 = 33;

/// A square of `material` facing a camera on +z, lit head-on by a light of colour 1 and by `ambient`: every
/// pixel, in `f32` as the draw computes it.
fn square(material: Material<'_>, ambient: Vec3) -> Vec<[u32; 3]> {
    let positions =
        [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(-1.0, 1.0, 0.0)];
    let normals = [Vec3::Z; 4];
    let uvs = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0)];
    let indices = [0u16, 1, 2, 0, 2, 3];
    let mesh = Mesh::new(&positions, Indices::U16(&indices)).unwrap().with_normals(&normals).unwrap();
    let mesh = mesh.with_uvs(&uvs).unwrap();
    let view = look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, perspective(0.8, 1.0, 0.5, 10.0).unwrap());
    let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::MetallicRoughness, material };
    let lights = [Light::directional(Vec3::Z, Vec3::ONE)];
    let lighting = Lighting { ambient, lights: &lights, environment: None, space: ShadingSpace::Encoded };
    let mut color = vec![[0u32; 3]; (SIZE * SIZE) as usize];
    let mut depth = vec![1f32; color.len()];
    let mut target = Target::new(ExactColor(&mut color), &mut depth[..], SIZE, SIZE).unwrap();
    target.clear(Vec3::ZERO);
    let (variant, stats) = draw_mesh(&mut target, &object, &lighting, &DrawState::DEFAULT).unwrap();
    assert_eq!(variant.shading, ShadingModel::MetallicRoughness);
    assert_eq!(variant.metallic_roughness_map, material.metallic_roughness_map.is_some());
    assert!(stats.fragments > 100);
    color
}

/// The middle pixel of [`square`].
fn centre(material: Material<'_>, ambient: Vec3) -> Vec3 {
    let [r, g, b] = square(material, ambient)[(SIZE * SIZE / 2) as usize].map(f32::from_bits);
    Vec3::new(r, g, b)
}

fn assert_close(actual: Vec3, expected: Vec3, what: &str) {
    let gap = (actual - expected).map(f32::abs).max_elem();
    assert!(gap < 2e-6, "{what}: {actual:?}, expected {expected:?}");
}

#[test]
fn a_rough_dielectric_lit_head_on_reflects_its_diffuse_colour_and_a_quarter_of_f0() {
    let c = Vec3::new(0.5, 0.25, 1.0);
    let dielectric = Material { metallic: 0.0, roughness: 1.0, ..Material::plain(c) };
    assert_close(centre(dielectric, Vec3::ZERO), c * 0.96 + Vec3::splat(0.01), "dielectric");
}

#[test]
fn a_rough_metal_lit_head_on_reflects_a_quarter_of_its_colour() {
    let c = Vec3::new(0.95, 0.64, 0.54);
    let metal = Material { metallic: 1.0, roughness: 1.0, ..Material::plain(c) };
    assert_close(centre(metal, Vec3::ZERO), c * 0.25, "metal");
}

#[test]
fn the_ambient_light_reaches_the_diffuse_lobe_alone() {
    let c = Vec3::new(0.5, 0.25, 1.0);
    let ambient = Vec3::new(0.2, 0.3, 0.4);
    let lit = |metallic, ambient| centre(Material { metallic, roughness: 1.0, ..Material::plain(c) }, ambient);
    // What the ambient light adds, over the light alone: the diffuse colour times it, nothing from a metal.
    assert_close(lit(0.0, ambient) - lit(0.0, Vec3::ZERO), c.mul_elem(ambient), "dielectric");
    assert_eq!(lit(1.0, ambient), lit(1.0, Vec3::ZERO), "metal");
}

#[test]
fn the_specular_lobe_narrows_and_brightens_as_roughness_falls() {
    // Head-on, the highlight's peak D V grows as the roughness falls: 1 / (4 pi alpha^2) for small alpha.
    let metal = |roughness| centre(Material { metallic: 1.0, roughness, ..Material::plain(Vec3::ONE) }, Vec3::ZERO);
    let peaks = [1.0, 0.5, 0.25, 0.1].map(|roughness| metal(roughness).x);
    assert!(peaks.windows(2).all(|p| p[1] > p[0]), "{peaks:?}");
    // Roughness 0.5: alpha = 0.25, D = 1 / (pi alpha^2), V = 1 / 4: pi D V = 4.
    assert!((peaks[1] - 4.0).abs() < 1e-5, "{peaks:?}");
}

/// The metallic-roughness map scales the factors by its blue (metallic) and green (roughness) channels: a white map
/// changes no pixel, and a map of no blue makes a metal a dielectric, pixel for pixel.
#[test]
fn the_metallic_roughness_map_scales_metallic_by_blue_and_roughness_by_green() {
    let c = Vec3::new(0.9, 0.6, 0.3);
    let metal = Material { metallic: 1.0, roughness: 0.6, ..Material::plain(c) };
    let (white, green) = ([0xFF_FFFF], [0x00_FF00]);
    let white = Texture::new(&white, 1, 1).unwrap();
    let green = Texture::new(&green, 1, 1).unwrap();
    let plain = square(metal, Vec3::splat(0.1));
    assert_eq!(square(Material { metallic_roughness_map: Some(white), ..metal }, Vec3::splat(0.1)), plain);
    let dielectric = square(Material { metallic: 0.0, ..metal }, Vec3::splat(0.1));
    assert_ne!(dielectric, plain);
    assert_eq!(square(Material { metallic_roughness_map: Some(green), ..metal }, Vec3::splat(0.1)), dielectric);
    // Half the green: the roughness times 128 / 255.
    let half = [0x00_8000];
    let half = Texture::new(&half, 1, 1).unwrap();
    // The texel unpacked as the core unpacks it: 128 times 1 / 255.
    let smoother = Material { roughness: 0.6 * (128.0 * (1.0 / 255.0)), ..metal };
    assert_eq!(
        square(Material { metallic_roughness_map: Some(half), ..metal }, Vec3::ZERO)[(SIZE * SIZE / 2) as usize],
        square(Material { metallic: 0.0, ..smoother }, Vec3::ZERO)[(SIZE * SIZE / 2) as usize],
    );
}
