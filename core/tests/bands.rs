//! Band rendering: a frame drawn as bands of rows equals the frame drawn whole, bit for bit: colours, depths and
//! fragment counts.
//!
//! Every band of every split is checked. The bands are drawn into buffers of the caller's own (`PlainDepth`,
//! `PlainDepth16`: they store what they are given, pixel by pixel) and compared with the frame drawn into the
//! library's `&mut [f32]` and `&mut [u16]` (lane-wise where they can be), so neither where a band starts nor which
//! buffer stores the depths may change a pixel. The scenes reach depths outside `[0, 1]`: the near plane cuts the
//! torus, and wireframe lines carry depth biases past both ends of the range. Every draw path is covered: the
//! specialised and general shading pipelines with the depth test on and off, wireframe lines, depth-only passes,
//! and the batched fragment path of mapped surfaces (maps, a point light, a shadowed sun).

use crate::common;

use common::{ExactColor, Frame, PlainDepth, PlainDepth16, Torus, Transformed, assert_same_depths, checker_texels};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Mesh, compute_tangents};
use rastty_core::pipeline::{
    DepthTest, DrawState, DrawStats, EdgeArithmetic, Fragment, LineStyle, Shader, Slopes, draw, draw_wireframe,
};
use rastty_core::shading::{
    Light, Lighting, Material, NormalMap, NormalSpace, Object, ShadingModel, Transforms, draw_mesh,
};
use rastty_core::shadow::{ShadowBias, ShadowMap, ShadowView, clear_shadow_depth, draw_shadow_caster};
use rastty_core::target::{NoColor, Rgb565, Target};
use rastty_core::testing::draw_mesh_general;
use rastty_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 37;
const H: u32 = 23;
const BACKGROUND: Vec3 = Vec3::new(0.05, 0.1, 0.15);

/// The torus seen at an angle, so close that the near plane cuts it.
fn transforms() -> Transforms {
    common::near_cut_torus_transforms(W, H)
}

/// Lines 0.35 nearer than their edges (those near the near plane go below depth 0), then lines 2 farther (all of
/// them beyond depth 1: drawn only with the depth test off).
const WIREFRAMES: [LineStyle; 2] = [
    LineStyle { color: Vec3::new(1.0, 1.0, 0.0), depth_bias: 0.35 },
    LineStyle { color: Vec3::new(0.0, 1.0, 1.0), depth_bias: -2.0 },
];

/// Draws a scene (`draw` clears a target, draws and returns the fragments drawn) whole into the library's buffers, then every band `y0..y1` of the frame into the
/// caller's own, and compares each band with the frame's rows; checks that the bands of every height add up to
/// the frame's fragments. Returns the frame's `f32` depths.
fn assert_every_band_equals_the_frame(name: &str, draw: impl Fn(&mut Frame<'_, '_>) -> u64) -> Vec<f32> {
    let n = (W * H) as usize;
    let (mut color, mut depth) = (vec![[0u32; 3]; n], vec![0f32; n]);
    let frame = draw(&mut common::frame(ExactColor(&mut color), &mut depth[..], W, H));
    let (mut color16, mut depth16) = (vec![[0u32; 3]; n], vec![0u16; n]);
    let frame16 = draw(&mut common::frame(ExactColor(&mut color16), &mut depth16[..], W, H));

    // fragments[y0][y1] and fragments16[y0][y1]: the band y0..y1's.
    let mut fragments = vec![vec![0; H as usize + 1]; H as usize];
    let mut fragments16 = fragments.clone();
    for y0 in 0..H {
        for y1 in y0 + 1..=H {
            let rows = (y0 * W) as usize..(y1 * W) as usize;
            let what = format!("{name}, band {y0}..{y1}");
            let (mut band_color, mut band_depth) = (vec![[0u32; 3]; rows.len()], vec![0f32; rows.len()]);
            let plain = PlainDepth(&mut band_depth);
            fragments[y0 as usize][y1 as usize] =
                draw(&mut common::band(ExactColor(&mut band_color), plain, W, H, y0..y1));
            assert_same_colors(&what, &band_color, &color[rows.clone()], y0);
            assert_same_depths(&what, &band_depth, &depth[rows.clone()], W as usize, y0 as usize);

            let (mut band_color, mut band_depth) = (vec![[0u32; 3]; rows.len()], vec![0u16; rows.len()]);
            let plain = PlainDepth16(&mut band_depth);
            fragments16[y0 as usize][y1 as usize] =
                draw(&mut common::band(ExactColor(&mut band_color), plain, W, H, y0..y1));
            let what = format!("{what}, u16 depth");
            assert_same_colors(&what, &band_color, &color16[rows.clone()], y0);
            assert_same_depths(&what, &band_depth, &depth16[rows], W as usize, y0 as usize);
        }
    }
    for height in 1..=H {
        let split = |counts: &[Vec<u64>]| -> u64 {
            (0..H).step_by(height as usize).map(|y0| counts[y0 as usize][(y0 + height).min(H) as usize]).sum()
        };
        assert_eq!(split(&fragments), frame, "{name}: bands of {height} rows, fragments");
        assert_eq!(split(&fragments16), frame16, "{name}: bands of {height} rows, fragments with u16 depth");
    }
    assert!(frame > 0, "{name}: something is drawn");
    depth
}

/// Panics at the first pixel where a band whose first row is `y0` differs from the frame's rows.
fn assert_same_colors(what: &str, band: &[[u32; 3]], frame: &[[u32; 3]], y0: u32) {
    if let Some(i) = (0..band.len()).find(|&i| band[i] != frame[i]) {
        let (x, y) = (i % W as usize, y0 as usize + i / W as usize);
        panic!("{what}: pixel ({x}, {y}) has colour bits {:x?}, the whole frame {:x?}", band[i], frame[i]);
    }
}

/// Draws the [`WIREFRAMES`] of `mesh` over `target`.
fn wireframes(target: &mut Frame<'_, '_>, mesh: &Mesh<'_>, clip_from_object: &Mat4, state: &DrawState) -> u64 {
    WIREFRAMES.iter().map(|style| draw_wireframe(target, mesh, clip_from_object, style, state).fragments).sum()
}

#[test]
fn every_band_of_a_shaded_frame_with_its_wireframe_equals_the_frame() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let texels = checker_texels();
    let texture = Texture::new(&texels, 8, 8).unwrap();
    let lights = [Light::directional(Vec3::new(0.3, 1.0, 0.6), Vec3::ONE)];
    let clipped = draw(
        &mut Target::new(NoColor, &mut vec![1.0; (W * H) as usize][..], W, H).unwrap(),
        &torus.mesh(),
        &Transformed { clip_from_object: transforms().clip_from_object },
        &DrawState::default(),
    )
    .unwrap()
    .clipped;
    assert!(clipped > 0, "the near plane cuts the torus");
    for (shading, filter) in [
        (ShadingModel::Phong, Some(FilterMode::Bilinear)),
        (ShadingModel::Gouraud, Some(FilterMode::Nearest)),
        (ShadingModel::Flat, None),
        (ShadingModel::Depth { near: 0.3, far: 0.95 }, None),
    ] {
        let material = Material {
            specular: Vec3::splat(0.5),
            diffuse: filter.map(|_| texture),
            filter: filter.unwrap_or_default(),
            wrap: WrapMode::Repeat,
            ..Material::default()
        };
        let lighting =
            Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
        for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
            for depth_test in [DepthTest::Less, DepthTest::Off] {
                for general in [false, true] {
                    let state = DrawState { edges, depth_test, ..DrawState::default() };
                    let name = format!("{shading:?}, {edges:?}, {depth_test:?}, general {general}");
                    let depth = assert_every_band_equals_the_frame(&name, |target| {
                        target.clear(BACKGROUND);
                        let (mesh, transforms) = (torus.mesh(), transforms());
                        let object = Object { mesh, tangents: None, transforms, shading, material };
                        let drawn = if general {
                            draw_mesh_general(target, &object, &lighting, &state)
                        } else {
                            draw_mesh(target, &object, &lighting, &state)
                        };
                        let (_, stats) = drawn.unwrap();
                        stats.fragments + wireframes(target, &mesh, &transforms.clip_from_object, &state)
                    });
                    match depth_test {
                        // Lines biased past the near plane store exactly 0 (and never -0 or below).
                        DepthTest::Less => assert!(depth.iter().any(|&z| z.to_bits() == 0), "{name}"),
                        DepthTest::Off => assert!(depth.iter().all(|&z| z == 1.0), "{name}: nothing stored"),
                    }
                }
            }
        }
    }
}

/// [`Transformed`] without its fragment stage: a depth-only shader.
struct DepthOnly(Transformed);

impl Shader for DepthOnly {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: rastty_core::mesh::Attributes = rastty_core::mesh::Attributes::NONE;
    const FRAGMENT_STAGE: bool = false;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.0.position(mesh, i)
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        unreachable!("a depth-only shader's fragment stage never runs")
    }
}

#[test]
fn every_band_of_a_depth_only_pass_equals_the_frame() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
        for depth_test in [DepthTest::Less, DepthTest::Off] {
            let state = DrawState { edges, depth_test, ..DrawState::default() };
            let shader = DepthOnly(Transformed { clip_from_object: transforms().clip_from_object });
            // Lane-wise into the library's `f32` buffer where the edge values fit `i32`, pixel by pixel otherwise.
            assert_every_band_equals_the_frame(&format!("depth only, {edges:?}, {depth_test:?}"), |target| {
                target.clear(BACKGROUND);
                draw(target, &torus.mesh(), &shader, &state).unwrap().fragments
            });
        }
    }
}

#[test]
fn every_band_of_a_mapped_surface_with_shadows_equals_the_frame() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let mut tangents = vec![Vec4::ZERO; torus.positions.len()];
    compute_tangents(&torus.mesh(), &mut tangents).unwrap();
    let checker = checker_texels();
    let bumps: Vec<u32> = (0..64).map(|i| if i % 3 == 0 { 0x60A0F0 } else { 0x8080FF }).collect();
    let material = Material {
        color: Vec3::new(0.9, 0.8, 0.7),
        specular: Vec3::splat(0.4),
        shininess: 24.0,
        diffuse: Some(Texture::new(&checker, 8, 8).unwrap()),
        normal_map: Some(NormalMap { texture: Texture::new(&bumps, 8, 8).unwrap(), space: NormalSpace::Tangent }),
        specular_map: Some(Texture::new(&checker, 8, 8).unwrap()),
        glow_map: Some(Texture::new(&bumps, 8, 8).unwrap()),
        ..Material::plain(Vec3::ONE)
    };
    let object = Object {
        mesh: torus.mesh(),
        tangents: Some(&tangents),
        transforms: transforms(),
        shading: ShadingModel::Phong,
        material,
    };

    // The torus casts its own shadow from the sun.
    let mut sun = Light::directional(Vec3::new(0.5, 1.0, 0.8), Vec3::new(0.9, 0.85, 0.8));
    let view = ShadowView::fit(sun.kind, BoundingSphere { centre: Vec3::ZERO, radius: 1.5 }, 64).unwrap();
    let mut map = vec![0.0; 64 * 64];
    clear_shadow_depth(&mut map);
    let cast = draw_shadow_caster(&view, &mut map, &object.mesh, &object.transforms.model).unwrap();
    assert!(cast.fragments > 0);
    sun.shadow = Some(ShadowMap::new(view, &map, ShadowBias::DEFAULT, 1).unwrap());
    let lamp = Light::point(Vec3::new(0.0, 2.0, 1.0), Vec3::new(0.5, 0.4, 0.3));
    let lights = [sun, lamp];
    let lights =
        Lighting { ambient: Vec3::splat(0.08), lights: &lights, environment: None, space: ShadingSpace::Linear };
    for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
        for general in [false, true] {
            let state = DrawState { edges, ..DrawState::default() };
            assert_every_band_equals_the_frame(&format!("mapped surface, {edges:?}, general {general}"), |target| {
                target.clear(BACKGROUND);
                let drawn = if general {
                    draw_mesh_general(target, &object, &lights, &state)
                } else {
                    draw_mesh(target, &object, &lights, &state)
                };
                let (_, stats) = drawn.unwrap();
                stats.fragments + wireframes(target, &object.mesh, &object.transforms.clip_from_object, &state)
            });
        }
    }
}

#[test]
fn a_320x240_rgb565_frame_in_16_row_bands_uses_20_kib() {
    // The microcontroller case: RGB565 colour and u16 depth, 320x16 band buffers.
    const BW: u32 = 320;
    const BH: u32 = 240;
    let torus = Torus::new(1.0, 0.45, 24, 12);
    let lights = [Light::directional(Vec3::new(0.3, 1.0, 0.6), Vec3::ONE)];
    let view = look_at(Vec3::new(0.0, 1.2, 2.6), Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, perspective(1.0, BW as f32 / BH as f32, 0.5, 20.0).unwrap());
    let object = Object {
        mesh: torus.mesh(),
        tangents: None,
        transforms,
        shading: ShadingModel::Gouraud,
        material: Material::default(),
    };
    let lighting =
        Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
    let render = |target: &mut Frame<'_, '_>| {
        target.clear(Vec3::ZERO);
        draw_mesh(target, &object, &lighting, &DrawState::default()).unwrap().1
    };
    let (mut whole, mut whole_depth) = (vec![0u16; (BW * BH) as usize], vec![0u16; (BW * BH) as usize]);
    let full: DrawStats = render(&mut common::frame(Rgb565(&mut whole), &mut whole_depth[..], BW, BH));

    let mut color = [0u16; (BW * 16) as usize];
    let mut depth = [0u16; (BW * 16) as usize];
    assert_eq!(core::mem::size_of_val(&color) + core::mem::size_of_val(&depth), 20 * 1024);
    let (mut assembled, mut assembled_depth, mut fragments) = (Vec::new(), Vec::new(), 0);
    for y0 in (0..BH).step_by(16) {
        fragments += render(&mut common::band(Rgb565(&mut color), &mut depth[..], BW, BH, y0..y0 + 16)).fragments;
        assembled.extend_from_slice(&color);
        assembled_depth.extend_from_slice(&depth);
    }
    assert!(whole == assembled, "bands differ from the whole frame");
    assert_same_depths("16-row bands", &assembled_depth, &whole_depth, BW as usize, 0);
    assert_eq!(fragments, full.fragments);
    assert!(whole.iter().filter(|&&p| p != 0).count() > 10_000, "the torus is drawn");
}
