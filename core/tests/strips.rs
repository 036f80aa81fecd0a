//! Strip rendering: a frame drawn as bands of rows, each into the same small buffers, equals the whole frame
//! bit for bit.

mod common;

use common::{ExactColor, Torus, checker_texels};
use rasterm_core::camera::{look_at, perspective};
use rasterm_core::math::{Mat4, Vec3};
use rasterm_core::pipeline::{DrawState, DrawStats, EdgeArithmetic, LineStyle, draw_wireframe};
use rasterm_core::shading::{Effects, Light, Lighting, Material, ShadingModel, TextureBinding, Transforms, draw_mesh};
use rasterm_core::target::{ColorBuffer, DepthBuffer, Rgb565, Target};
use rasterm_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 61;
const H: u32 = 47;

struct Scene<'a> {
    torus: &'a Torus,
    transforms: Transforms,
    effects: Effects<'a>,
    state: DrawState,
}

impl Scene<'_> {
    fn draw<C: ColorBuffer, D: DepthBuffer>(&self, target: &mut Target<C, D>) -> DrawStats {
        target.clear(Vec3::new(0.05, 0.1, 0.15));
        let mesh = self.torus.mesh();
        let mut stats = draw_mesh(target, &mesh, &self.transforms, &self.effects, &self.state).unwrap();
        let style = LineStyle { color: Vec3::new(1.0, 1.0, 0.0), depth_bias: 1e-3 };
        stats += draw_wireframe(target, &mesh, &self.transforms.clip_from_object, &style, &self.state);
        stats
    }
}

/// Renders the scene whole and in bands of `band` rows (f32 depth, exact colours) and compares.
fn assert_bands_equal_frame(scene: &Scene<'_>, band: u32) {
    let n = (W * H) as usize;
    let (mut whole, mut whole_depth) = (vec![[0u32; 3]; n], vec![0f32; n]);
    let full_stats = scene.draw(&mut Target::new(ExactColor(&mut whole), &mut whole_depth[..], W, H).unwrap());

    let mut assembled = Vec::with_capacity(n);
    let (mut color, mut depth) = (vec![[0u32; 3]; (W * band) as usize], vec![0f32; (W * band) as usize]);
    let mut fragments = 0;
    for y0 in (0..H).step_by(band as usize) {
        let y1 = (y0 + band).min(H);
        let len = (W * (y1 - y0)) as usize;
        let mut target = Target::band(ExactColor(&mut color[..len]), &mut depth[..len], W, H, y0..y1).unwrap();
        fragments += scene.draw(&mut target).fragments;
        assembled.extend_from_slice(&color[..len]);
    }
    let differing = whole.iter().zip(&assembled).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "bands of {band} rows: {differing} pixels differ");
    assert_eq!(fragments, full_stats.fragments, "bands of {band} rows shade the same fragments");
}

#[test]
fn bands_of_1_7_16_rows_equal_the_whole_frame() {
    let torus = Torus::new(1.0, 0.45, 40, 20);
    let texels = checker_texels();
    let texture = Texture::new(&texels, 8, 8).unwrap();
    let lights = [Light::directional(Vec3::new(0.3, 1.0, 0.6), Vec3::ONE)];
    let view = look_at(Vec3::new(0.2, 0.9, 1.9), Vec3::ZERO, Vec3::Y).unwrap();
    let projection = perspective(1.2, W as f32 / H as f32, 0.5, 20.0).unwrap();
    let transforms = Transforms::new(Mat4::from_axis_angle(Vec3::X, 0.7), view, projection);
    for (shading, filter) in [
        (ShadingModel::Phong, Some(FilterMode::Bilinear)),
        (ShadingModel::Gouraud, Some(FilterMode::Nearest)),
        (ShadingModel::Flat, None),
        (ShadingModel::Depth { near: 0.3, far: 0.95 }, None),
    ] {
        let effects = Effects {
            shading,
            material: Material { specular: Vec3::splat(0.5), ..Material::default() },
            lighting: Lighting { ambient: Vec3::splat(0.1), lights: &lights },
            texture: filter.map(|filter| TextureBinding { texture, filter, wrap: WrapMode::Repeat }),
        };
        // Float edge functions too: they are evaluated from frame coordinates as well.
        for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
            let scene =
                Scene { torus: &torus, transforms, effects, state: DrawState { edges, ..DrawState::default() } };
            for band in [1, 7, 16] {
                assert_bands_equal_frame(&scene, band);
            }
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
    let effects = Effects {
        shading: ShadingModel::Gouraud,
        material: Material::default(),
        lighting: Lighting { ambient: Vec3::splat(0.1), lights: &lights },
        texture: None,
    };
    let mesh = torus.mesh();
    let render = |target: &mut Target<Rgb565<'_>, &mut [u16]>| {
        target.clear(Vec3::ZERO);
        draw_mesh(target, &mesh, &transforms, &effects, &DrawState::default()).unwrap()
    };
    let (mut whole, mut whole_depth) = (vec![0u16; (BW * BH) as usize], vec![0u16; (BW * BH) as usize]);
    render(&mut Target::new(Rgb565(&mut whole), &mut whole_depth[..], BW, BH).unwrap());

    let mut color = [0u16; (BW * 16) as usize];
    let mut depth = [0u16; (BW * 16) as usize];
    assert_eq!(core::mem::size_of_val(&color) + core::mem::size_of_val(&depth), 20 * 1024);
    let mut assembled = Vec::new();
    for y0 in (0..BH).step_by(16) {
        render(&mut Target::band(Rgb565(&mut color), &mut depth[..], BW, BH, y0..y0 + 16).unwrap());
        assembled.extend_from_slice(&color);
    }
    assert!(whole == assembled, "bands differ from the whole frame");
    assert!(whole.iter().filter(|&&p| p != 0).count() > 10_000, "the torus is drawn");
}
