//! "Simulate only what a scene calls for", for the effects: each effect switched off by data (a white map, a flat
//! normal map, a black glow or specular map, a zero-strength light, an empty shadow map) gives exactly the pixels
//! of the draw that leaves it out, and the leaner draw computes only what it needs: colours and depths. The general
//! path draws into a caller's own depth buffer (`PlainDepth`), every other draw into the library's `&mut [f32]`.

use crate::common;

use common::{ExactColor, PlainDepth, Torus, assert_same_depths, checker_texels};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Indices, Mesh, compute_tangents};
use rastty_core::pipeline::{DrawState, DrawStats};
use rastty_core::shading::{
    Light, Lighting, Material, NormalMap, NormalSource, NormalSpace, Object, ShadingError, ShadingModel,
    SpecularSource, Transforms, Variant, draw_mesh,
};
use rastty_core::shadow::{ShadowBias, ShadowMap, ShadowView, clear_shadow_depth};
use rastty_core::testing::draw_mesh_general;
use rastty_core::texture::{FilterMode, Texture};

const W: u32 = 64;
const H: u32 = 48;

/// The torus seen at an angle, close enough for the near plane to cut it (so clipped varyings count too).
fn transforms() -> Transforms {
    let model = Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.0), 1.1);
    let view = look_at(Vec3::new(0.3, 0.5, 1.6), Vec3::ZERO, Vec3::Y).unwrap();
    Transforms::new(model, view, perspective(1.2, W as f32 / H as f32, 0.5, 10.0).unwrap())
}

struct Fixture {
    torus: Torus,
    tangents: Vec<Vec4>,
    checker: Vec<u32>,
}

impl Fixture {
    fn new() -> Self {
        let torus = Torus::new(1.0, 0.4, 24, 12);
        let mut tangents = vec![Vec4::ZERO; torus.positions.len()];
        compute_tangents(&torus.mesh(), &mut tangents).unwrap();
        Self { torus, tangents, checker: checker_texels() }
    }

    fn checker(&self) -> Texture<'_> {
        Texture::new(&self.checker, 8, 8).unwrap()
    }
}

/// A 1x1 texture of one texel.
fn solid(texel: &[u32; 1]) -> Texture<'_> {
    Texture::new(texel, 1, 1).unwrap()
}

fn base_material(f: &Fixture) -> Material<'_> {
    Material {
        color: Vec3::new(0.9, 0.8, 0.7),
        specular: Vec3::splat(0.4),
        shininess: 24.0,
        diffuse: Some(f.checker()),
        ..Material::plain(Vec3::ONE)
    }
}

fn sun() -> Light<'static> {
    Light::directional(Vec3::new(0.5, 1.0, 0.8), Vec3::new(0.9, 0.85, 0.8))
}

/// A frame's exact colours and depths.
struct Picture {
    color: Vec<[u32; 3]>,
    depth: Vec<f32>,
}

fn render(f: &Fixture, material: Material<'_>, lights: &[Light<'_>], general: bool) -> (Picture, Variant, DrawStats) {
    let mut color = vec![[0u32; 3]; (W * H) as usize];
    let mut depth = vec![0f32; (W * H) as usize];
    let object = Object {
        mesh: f.torus.mesh(),
        tangents: Some(&f.tangents),
        transforms: transforms(),
        shading: ShadingModel::Phong,
        material,
    };
    let lights = Lighting { ambient: Vec3::splat(0.08), lights, environment: None, space: ShadingSpace::Linear };
    let background = Vec3::new(0.1, 0.2, 0.3);
    let state = DrawState::default();
    let (variant, stats) = if general {
        let mut target = common::frame(ExactColor(&mut color), PlainDepth(&mut depth), W, H);
        target.clear(background);
        draw_mesh_general(&mut target, &object, &lights, &state)
    } else {
        let mut target = common::frame(ExactColor(&mut color), &mut depth[..], W, H);
        target.clear(background);
        draw_mesh(&mut target, &object, &lights, &state)
    }
    .unwrap();
    (Picture { color, depth }, variant, stats)
}

fn assert_same(a: &Picture, b: &Picture, what: &str) {
    let differing = a.color.iter().zip(&b.color).filter(|(p, q)| p != q).count();
    assert_eq!(differing, 0, "{what}: {differing} pixels differ");
    assert_same_depths(what, &a.depth, &b.depth, W as usize, 0);
}

#[test]
fn a_white_diffuse_map_changes_nothing() {
    let f = Fixture::new();
    let white = [0xFFFFFF];
    let (plain, v, _) = render(&f, Material { diffuse: None, ..base_material(&f) }, &[sun()], false);
    assert!(!v.albedo_map && !v.uvs);
    let (mapped, v, _) = render(&f, Material { diffuse: Some(solid(&white)), ..base_material(&f) }, &[sun()], false);
    assert!(v.albedo_map && v.uvs);
    assert_same(&plain, &mapped, "white diffuse map");
}

#[test]
fn a_flat_tangent_space_normal_map_changes_nothing() {
    let f = Fixture::new();
    let flat = [0x8080FF];
    let (plain, v, _) = render(&f, base_material(&f), &[sun()], false);
    assert_eq!(v.normals, NormalSource::Interpolated);
    assert!(!v.tangents);
    let normal_map = Some(NormalMap { texture: solid(&flat), space: NormalSpace::Tangent });
    let (mapped, v, _) = render(&f, Material { normal_map, ..base_material(&f) }, &[sun()], false);
    assert_eq!(v.normals, NormalSource::TangentMap);
    assert!(v.tangents);
    assert_same(&plain, &mapped, "flat tangent-space normal map");
}

#[test]
fn a_normal_map_changes_the_picture() {
    // The counterpart of the test above: a bumpy map must show, or the equality proves nothing.
    let f = Fixture::new();
    let bumps: Vec<u32> = (0..64).map(|i| if (i % 8 + i / 8) % 2 == 0 { 0xC080E0 } else { 0x4080E0 }).collect();
    let (plain, _, _) = render(&f, base_material(&f), &[sun()], false);
    for space in [NormalSpace::Tangent, NormalSpace::Object] {
        let normal_map = Some(NormalMap { texture: Texture::new(&bumps, 8, 8).unwrap(), space });
        let (mapped, _, _) = render(&f, Material { normal_map, ..base_material(&f) }, &[sun()], false);
        let differing = plain.color.iter().zip(&mapped.color).filter(|(p, q)| p != q).count();
        let covered = plain.color.iter().filter(|p| **p != plain.color[0]).count();
        assert!(differing > covered / 2, "{space:?}: only {differing} of {covered} pixels changed");
    }
}

#[test]
fn a_white_specular_map_equals_the_constant_and_a_black_one_no_highlights() {
    let f = Fixture::new();
    let (white, black) = ([0xFFFFFF], [0x000000]);
    let (constant, v, _) = render(&f, base_material(&f), &[sun()], false);
    assert_eq!(v.specular, SpecularSource::Constant);
    let (mapped, v, _) =
        render(&f, Material { specular_map: Some(solid(&white)), ..base_material(&f) }, &[sun()], false);
    assert_eq!(v.specular, SpecularSource::Map);
    assert_same(&constant, &mapped, "white specular map");

    let (none, v, _) = render(&f, Material { specular: Vec3::ZERO, ..base_material(&f) }, &[sun()], false);
    assert_eq!(v.specular, SpecularSource::None);
    assert!(!v.world, "no highlights, no point lights, no shadows: no world position");
    let (blackened, _, _) =
        render(&f, Material { specular_map: Some(solid(&black)), ..base_material(&f) }, &[sun()], false);
    assert_same(&none, &blackened, "black specular map");
    assert!(none.color != constant.color, "highlights must show");
}

#[test]
fn a_black_glow_map_changes_nothing() {
    let f = Fixture::new();
    let black = [0x000000];
    let (plain, v, _) = render(&f, base_material(&f), &[sun()], false);
    assert!(!v.glow_map);
    let (glowing, v, _) = render(&f, Material { glow_map: Some(solid(&black)), ..base_material(&f) }, &[sun()], false);
    assert!(v.glow_map);
    assert_same(&plain, &glowing, "black glow map");
}

#[test]
fn a_white_occlusion_map_changes_nothing_and_a_black_one_takes_the_ambient_light() {
    let f = Fixture::new();
    let (white, black) = ([0xFFFFFF], [0x000000]);
    let (plain, v, _) = render(&f, base_material(&f), &[sun()], false);
    assert!(!v.occlusion_map);
    let occluded = |map| Material { occlusion_map: Some(solid(map)), ..base_material(&f) };
    let (mapped, v, _) = render(&f, occluded(&white), &[sun()], false);
    assert!(v.occlusion_map);
    assert_same(&plain, &mapped, "white occlusion map");
    // No lights but the ambient: a black map leaves every pixel drawn exactly black.
    let (ambient_only, _, _) = render(&f, base_material(&f), &[], false);
    let (dark, v, _) = render(&f, occluded(&black), &[], false);
    assert!(v.occlusion_map);
    let background = ambient_only.color[0];
    let drawn: Vec<usize> = (0..ambient_only.color.len()).filter(|&i| ambient_only.color[i] != background).collect();
    assert!(drawn.len() > 500, "the torus covers pixels");
    assert!(drawn.iter().all(|&i| dark.color[i] == [0; 3]), "occluded ambient light");
    assert!(dark.color.iter().enumerate().all(|(i, c)| drawn.contains(&i) || *c == background));
}

#[test]
fn a_zero_strength_point_light_changes_nothing() {
    let f = Fixture::new();
    let (one, v, _) = render(&f, Material { specular: Vec3::ZERO, ..base_material(&f) }, &[sun()], false);
    assert_eq!((v.directional_lights, v.point_lights, v.world), (1, 0, false));
    let dark = Light::point(Vec3::new(0.0, 2.0, 1.0), Vec3::ZERO);
    let (two, v, _) = render(&f, Material { specular: Vec3::ZERO, ..base_material(&f) }, &[sun(), dark], false);
    assert_eq!((v.directional_lights, v.point_lights, v.world), (1, 1, true));
    assert_same(&one, &two, "zero-strength point light");
}

#[test]
fn an_empty_shadow_map_changes_nothing() {
    let f = Fixture::new();
    let mut sun_with_shadow = sun();
    let bounds = BoundingSphere { centre: Vec3::ZERO, radius: 1.5 };
    let view = ShadowView::fit(sun_with_shadow.kind, bounds, 64).unwrap();
    let mut depth = vec![0.0; 64 * 64];
    clear_shadow_depth(&mut depth);
    for pcf in [0, 1, 2] {
        sun_with_shadow.shadow = Some(ShadowMap::new(view, &depth, ShadowBias::DEFAULT, pcf).unwrap());
        let (plain, _, _) = render(&f, base_material(&f), &[sun()], false);
        let (shadowed, v, _) = render(&f, base_material(&f), &[sun_with_shadow], false);
        assert_eq!((v.shadowed_lights, v.pcf_radius), (1, pcf));
        assert_same(&plain, &shadowed, "empty shadow map");
    }
}

#[test]
fn every_effect_off_by_data_equals_none_through_the_general_path_too() {
    let f = Fixture::new();
    let (white, flat, black) = ([0xFFFFFF], [0x8080FF], [0x000000]);
    let mut depth = vec![0.0; 64 * 64];
    clear_shadow_depth(&mut depth);
    let mut shadowed_sun = sun();
    let view = ShadowView::fit(shadowed_sun.kind, BoundingSphere { centre: Vec3::ZERO, radius: 1.5 }, 64).unwrap();
    shadowed_sun.shadow = Some(ShadowMap::new(view, &depth, ShadowBias::DEFAULT, 1).unwrap());
    let dark_point = Light::point(Vec3::new(0.0, 2.0, 1.0), Vec3::ZERO);
    let everything = Material {
        diffuse: Some(solid(&white)),
        normal_map: Some(NormalMap { texture: solid(&flat), space: NormalSpace::Tangent }),
        specular_map: Some(solid(&white)),
        glow_map: Some(solid(&black)),
        ..base_material(&f)
    };
    let leanest = Material { diffuse: None, ..base_material(&f) };
    let (none, lean, lean_stats) = render(&f, leanest, &[sun()], false);
    for general in [false, true] {
        let (all, v, stats) = render(&f, everything, &[shadowed_sun, dark_point], general);
        assert!(v.uvs && v.tangents && v.world && v.glow_map);
        assert_eq!(stats, lean_stats);
        assert_same(&none, &all, &format!("every effect off by data (general path: {general})"));
    }
    assert!(!lean.uvs && !lean.tangents);
}

#[test]
fn the_explanation_lists_only_what_is_used() {
    let f = Fixture::new();
    let (_, lean, _) =
        render(&f, Material { diffuse: None, specular: Vec3::ZERO, ..base_material(&f) }, &[sun()], false);
    // The torus has vertex colours: every model that colours reads them.
    assert_eq!(
        lean.to_string(),
        "phong; varyings colour+normal; albedo colour x vertex colours; linear light; normals interpolated; no \
         specular; lights 1 directional; perspective-correct, depth less, cull back"
    );
    let flat = [0x8080FF];
    let material = Material {
        normal_map: Some(NormalMap { texture: solid(&flat), space: NormalSpace::Tangent }),
        specular_map: Some(f.checker()),
        glow_map: Some(f.checker()),
        filter: FilterMode::Nearest,
        ..base_material(&f)
    };
    let mut depth = vec![1.0; 16 * 16];
    clear_shadow_depth(&mut depth);
    let mut shadowed = sun();
    let view = ShadowView::fit(shadowed.kind, BoundingSphere { centre: Vec3::ZERO, radius: 1.5 }, 16).unwrap();
    shadowed.shadow = Some(ShadowMap::new(view, &depth, ShadowBias::DEFAULT, 1).unwrap());
    let lamp = Light::point(Vec3::new(0.0, 3.0, 0.0), Vec3::ONE);
    let (_, full, _) = render(&f, material, &[shadowed, lamp], false);
    assert_eq!(
        full.to_string(),
        "phong; varyings colour+normal+world+uv+tangent; albedo colour x vertex colours x texture; linear light; \
         normals tangent-space map; specular map; glow map; maps nearest/repeat; lights 1 directional + 1 point (1 with \
         shadows, pcf 3x3); perspective-correct, depth less, cull back"
    );
}

#[test]
fn a_tangent_space_map_without_tangents_is_refused() {
    let f = Fixture::new();
    let flat = [0x8080FF];
    let material = Material {
        normal_map: Some(NormalMap { texture: solid(&flat), space: NormalSpace::Tangent }),
        ..base_material(&f)
    };
    let mesh: Mesh<'_> = f.torus.mesh();
    for tangents in [None, Some(&f.tangents[1..])] {
        let object = Object { mesh, tangents, transforms: transforms(), shading: ShadingModel::Phong, material };
        let result = Variant::resolve(&object, [], ShadingSpace::Linear, &DrawState::default());
        let expected = rastty_core::shading::ShadingError::Tangents {
            expected: mesh.vertex_count(),
            actual: tangents.map_or(0, <[Vec4]>::len),
        };
        assert_eq!(result, Err(expected));
    }
}

#[test]
fn a_surface_shader_refuses_a_variant_it_was_not_compiled_for() {
    use rastty_core::shading::{Absent, LightUse, SurfaceShader, capabilities};
    let f = Fixture::new();
    let material = Material { specular: Vec3::splat(0.3), ..Material::plain(Vec3::ONE) };
    let sources = [Light::directional(Vec3::Z, Vec3::ONE), Light::point(Vec3::new(0.0, 2.0, 2.0), Vec3::ONE)];
    let lights = Lighting { ambient: Vec3::ZERO, lights: &sources, environment: None, space: ShadingSpace::Linear };
    let uncoloured =
        Mesh::new(&f.torus.positions, Indices::U16(&f.torus.indices)).unwrap().with_normals(&f.torus.normals).unwrap();
    let resolve = |mesh, shading, lights: &[Light<'_>], space| {
        let object = Object { mesh, tangents: None, transforms: transforms(), shading, material };
        Variant::resolve(&object, lights.iter().map(LightUse::from), space, &DrawState::default()).unwrap()
    };
    let variant_of = |mesh, shading, lights: &[Light<'_>]| resolve(mesh, shading, lights, ShadingSpace::Linear);
    let variant = |shading, lights: &[Light<'_>]| variant_of(uncoloured, shading, lights);
    type PerPixel<'a, const CAPS: u32> = SurfaceShader<'a, Vec3, Vec3, Absent, Absent, Absent, CAPS>;
    const LINEAR_PER_PIXEL: u32 = capabilities::PER_PIXEL | capabilities::LINEAR_LIGHT;
    let new = |v| PerPixel::<LINEAR_PER_PIXEL>::new(v, transforms(), &[], material, lights).map(|_| ());
    assert_eq!(new(variant(ShadingModel::Phong, &sources[..1])), Ok(()));
    // Linear light is a capability of its own: without it only the stored values can be lit.
    let stored = |v| PerPixel::<{ capabilities::PER_PIXEL }>::new(v, transforms(), &[], material, lights).map(|_| ());
    assert_eq!(stored(variant(ShadingModel::Phong, &sources[..1])), Err(ShadingError::Unsupported));
    let encoded = resolve(uncoloured, ShadingModel::Phong, &sources[..1], ShadingSpace::Encoded);
    assert_eq!(stored(encoded), Ok(()));
    // Another model, or a point light, is not compiled in.
    assert_eq!(new(variant(ShadingModel::Flat, &sources[..1])), Err(ShadingError::Unsupported));
    assert_eq!(new(variant(ShadingModel::Phong, &sources)), Err(ShadingError::Unsupported));
    let all = |v| PerPixel::<{ capabilities::ALL }>::new(v, transforms(), &[], material, lights).map(|_| ());
    assert_eq!(all(variant(ShadingModel::Phong, &sources)), Ok(()));
    // Vertex colours need the colour slot.
    assert_eq!(all(variant_of(f.torus.mesh(), ShadingModel::Phong, &sources)), Err(ShadingError::Unsupported));
    // Slots that do not carry the layout: per-pixel lighting needs the normal.
    let bare = SurfaceShader::<Absent, Absent, Absent, Absent>::new(
        variant(ShadingModel::Phong, &sources[..1]),
        transforms(),
        &[],
        material,
        lights,
    );
    assert_eq!(bare.map(|_| ()), Err(ShadingError::Unsupported));
}
