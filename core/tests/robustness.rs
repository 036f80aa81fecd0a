//! Bad input never panics: out-of-range indices and non-finite values skip their triangle only, and buffers of
//! the wrong size are refused with an error value.

use crate::common;

use common::{Count, ScreenSpace, Torus, coverage};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Attributes, Indices, Mesh, MeshError};
use rastty_core::pipeline::{DrawError, DrawState, DrawStats, Slopes, draw};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{MAX_DIMENSION, NoColor, NoDepth, Rgb888, Target, TargetError};
use rastty_core::testing::draw_mesh_general;
use rastty_core::texture::{FilterMode, Texture, WrapMode};

fn quad_positions() -> Vec<Vec3> {
    // Two triangles side by side on an 8x4 frame, plus a spare vertex.
    [(0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (4.0, 0.0), (8.0, 4.0), (8.0, 0.0), (1.0, 1.0)]
        .map(|(x, y)| Vec3::new(x, y, 0.5))
        .to_vec()
}

fn render(positions: &[Vec3], indices: &[u32]) -> (Vec<u32>, DrawStats) {
    let mesh = Mesh::new(positions, Indices::U32(indices)).unwrap();
    let mut counts = vec![0u32; 32];
    let mut target = Target::new(Count(&mut counts), NoDepth, 8, 4).unwrap();
    let state = DrawState { cull: rastty_core::pipeline::Cull::None, ..DrawState::default() };
    let stats = draw(&mut target, &mesh, &ScreenSpace { width: 8.0, height: 4.0 }, &state).unwrap();
    (counts, stats)
}

#[test]
fn an_index_out_of_range_skips_only_its_triangle() {
    let p = quad_positions();
    let (good, _) = render(&p, &[0, 1, 2, 3, 4, 5]);
    let (only_second, _) = render(&p, &[3, 4, 5]);
    let (c, stats) = render(&p, &[0, 1, 99, 3, 4, 5]);
    assert_eq!(c, only_second);
    assert_ne!(c, good);
    assert_eq!((stats.triangles_in, stats.invalid, stats.rasterized), (2, 1, 1));
    let (_, stats) = render(&p, &[u32::MAX, 0, 1]);
    assert_eq!(stats.invalid, 1);
}

#[test]
fn a_non_finite_position_skips_only_its_triangle() {
    let (only_second, _) = render(&quad_positions(), &[3, 4, 5]);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let mut p = quad_positions();
        p[1].y = bad;
        let (c, stats) = render(&p, &[0, 1, 2, 3, 4, 5]);
        assert_eq!(c, only_second, "{bad}");
        assert_eq!((stats.invalid, stats.rasterized), (1, 1));
    }
}

/// A NaN normal or UV skips its triangles only in draws that read it: the picture is exactly the one drawn
/// without those triangles, and they are counted as invalid (when they would have covered a pixel).
#[test]
fn non_finite_attributes_skip_triangles_only_where_used() {
    let torus = Torus::new(1.0, 0.4, 12, 8);
    let (bad_normal, bad_uv) = (5u16, 40u16);
    let mut normals = torus.normals.clone();
    let mut uvs = torus.uvs.clone();
    normals[bad_normal as usize] = Vec3::new(f32::NAN, 0.0, 1.0);
    uvs[bad_uv as usize] = Vec2::new(f32::INFINITY, 0.0);
    let without = |bad: &[u16]| -> Vec<u16> {
        torus.indices.chunks(3).filter(|t| !t.iter().any(|i| bad.contains(i))).flatten().copied().collect()
    };
    let texels = common::checker_texels();
    let texture = Material {
        diffuse: Some(Texture::new(&texels, 8, 8).unwrap()),
        filter: FilterMode::Nearest,
        wrap: WrapMode::Repeat,
        ..Material::default()
    };
    let view = look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, perspective(1.0, 1.0, 0.1, 10.0).unwrap());
    let render = |indices: &[u16], shading, material: Option<Material<'_>>| {
        let mesh = Mesh::new(&torus.positions, Indices::U16(indices))
            .unwrap()
            .with_normals(&normals)
            .unwrap()
            .with_uvs(&uvs)
            .unwrap();
        let lights = [Light::directional(Vec3::new(1.0, 1.0, 1.0), Vec3::splat(0.7))];
        let lighting =
            Lighting { ambient: Vec3::splat(0.3), lights: &lights, environment: None, space: ShadingSpace::Linear };
        let material = material.unwrap_or_default();
        let object = Object { mesh, tangents: None, transforms, shading, material };
        let state = DrawState { cull: rastty_core::pipeline::Cull::None, ..DrawState::default() };
        let [(color, stats), (general_color, general_stats)] = [false, true].map(|general| {
            let mut color = vec![0u32; 48 * 48];
            let mut depth = vec![0f32; 48 * 48];
            let mut target = common::frame(Rgb888(&mut color), &mut depth[..], 48, 48);
            target.clear(Vec3::ZERO);
            let draw = if general { draw_mesh_general } else { draw_mesh };
            let (_, stats) = draw(&mut target, &object, &lighting, &state).unwrap();
            (color, stats)
        });
        assert!(color == general_color, "{shading:?}: the specialised and general draws differ");
        assert_eq!(stats, general_stats, "{shading:?}");
        (color, stats.invalid)
    };
    for (shading, texture, reads) in [
        (ShadingModel::Unlit, None, vec![]),
        (ShadingModel::Flat, None, vec![]), // flat shading reads no vertex normals
        (ShadingModel::Gouraud, None, vec![bad_normal]),
        (ShadingModel::Phong, None, vec![bad_normal]),
        (ShadingModel::Normals, None, vec![bad_normal]),
        (ShadingModel::Depth { near: 3.0, far: 5.0 }, None, vec![]),
        (ShadingModel::Unlit, Some(texture), vec![bad_uv]),
        (ShadingModel::Phong, Some(texture), vec![bad_normal, bad_uv]),
    ] {
        let (image, invalid) = render(&torus.indices, shading, texture);
        let (expected, _) = render(&without(&reads), shading, texture);
        assert!(image == expected, "{shading:?}: the picture differs from the one without the bad triangles");
        let uses = (torus.indices.len() - without(&reads).len()) as u64 / 3;
        assert!(invalid <= uses, "{shading:?}: {invalid} invalid of {uses}");
        assert_eq!(invalid > 0, !reads.is_empty(), "{shading:?}: counted as invalid only where read");
    }
}

#[test]
fn every_triangle_is_counted_exactly_once() {
    let torus = Torus::new(1.0, 0.4, 16, 10);
    // Close enough that the near plane cuts the ring.
    let view = look_at(Vec3::new(0.0, 0.9, 0.5), Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, perspective(1.4, 1.0, 0.8, 10.0).unwrap());
    let object = Object {
        mesh: torus.mesh(),
        tangents: None,
        transforms,
        shading: ShadingModel::Flat,
        material: Material::default(),
    };
    let lighting = Lighting { ambient: Vec3::ONE, lights: &[], environment: None, space: ShadingSpace::Linear };
    let (mut color, mut depth) = (vec![0u32; 24 * 24], vec![0f32; 24 * 24]);
    let mut target = common::frame(Rgb888(&mut color), &mut depth[..], 24, 24);
    let (_, s) = draw_mesh(&mut target, &object, &lighting, &DrawState::default()).unwrap();
    assert_eq!(s.triangles_in, torus.indices.len() as u64 / 3);
    assert_eq!(s.invalid + s.outside + s.culled + s.degenerate + s.rasterized, s.triangles_in, "{s:?}");
    assert!(s.culled > 0 && s.rasterized > 0 && s.clipped > 0 && s.outside > 0, "{s:?}");
}

#[test]
fn buffers_of_the_wrong_size_are_refused() {
    let mut c = [0u32; 12];
    let mut d = [0f32; 12];
    assert!(Target::new(Rgb888(&mut c), &mut d[..], 4, 3).is_ok());
    assert_eq!(
        Target::new(Rgb888(&mut c), &mut d[..], 3, 3).unwrap_err(),
        TargetError::ColorLength { expected: 9, actual: 12 }
    );
    assert_eq!(
        Target::new(Rgb888(&mut c), &mut d[..2], 4, 3).unwrap_err(),
        TargetError::DepthLength { expected: 12, actual: 2 }
    );
    assert_eq!(Target::new(NoColor, NoDepth, 0, 3).unwrap_err(), TargetError::Empty);
    assert_eq!(
        Target::new(NoColor, NoDepth, MAX_DIMENSION + 1, 3).unwrap_err(),
        TargetError::TooLarge { width: MAX_DIMENSION + 1, height: 3 }
    );
    assert_eq!(Target::band(NoColor, NoDepth, 4, 3, 2..4).unwrap_err(), TargetError::Rows { rows: 2..4, height: 3 });
    assert_eq!(Target::band(NoColor, NoDepth, 4, 3, 2..2).unwrap_err(), TargetError::Rows { rows: 2..2, height: 3 });
    assert!(Target::band(Rgb888(&mut c[..4]), NoDepth, 4, 3, 2..3).is_ok());
}

#[test]
fn malformed_meshes_and_states_are_refused() {
    let p = quad_positions();
    assert_eq!(Mesh::new(&p, Indices::U16(&[0, 1])).unwrap_err(), MeshError::IndexCount(2));
    assert_eq!(Mesh::new(&p, Indices::Sequential).unwrap_err(), MeshError::IndexCount(7));
    let short = [Vec3::Z; 3];
    let err = Mesh::new(&p, Indices::U16(&[0, 1, 2])).unwrap().with_normals(&short).unwrap_err();
    assert_eq!(err, MeshError::AttributeLength { attribute: "normals", expected: 7, actual: 3 });

    let mesh = Mesh::new(&p, Indices::U16(&[0, 1, 2])).unwrap();
    let mut target = Target::new(NoColor, NoDepth, 8, 4).unwrap();
    let shader = ScreenSpace { width: 8.0, height: 4.0 };
    let nine_bits = DrawState { subpixel_bits: 9, ..DrawState::default() };
    assert_eq!(draw(&mut target, &mesh, &shader, &nine_bits).unwrap_err(), DrawError::SubpixelBits(9));
    struct NeedsUv;
    impl rastty_core::pipeline::Shader for NeedsUv {
        type Varyings = ();
        type Face = ();
        const ATTRIBUTES: Attributes = Attributes { normals: false, uvs: true, colors: false };
        fn position(&self, m: &Mesh<'_>, i: usize) -> rastty_core::math::Vec4 {
            m.position(i).extend(1.0)
        }
        fn varyings(&self, _: &Mesh<'_>, _: usize) {}
        fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
        fn fragment(&self, _: &rastty_core::pipeline::Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
            Vec3::ONE
        }
    }
    assert!(matches!(
        draw(&mut target, &mesh, &NeedsUv, &DrawState::default()),
        Err(DrawError::MissingAttributes { .. })
    ));
}

#[test]
fn coverage_helper_counts_once_per_pixel() {
    // Sanity check of the test helper itself: one triangle, no overlaps.
    let (c, _) = coverage(4, 4, &[[(0.0, 0.0), (0.0, 4.0), (4.0, 4.0)]], &common::both_sides());
    assert!(c.iter().all(|&n| n <= 1));
}
