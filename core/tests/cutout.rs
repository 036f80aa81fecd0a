//! Alpha cut-outs with known answers: a fragment whose alpha is below the cut-off leaves colour and depth as they
//! were, so a surface drawn later behind it shows through; a surface below its cut-off draws nothing.

use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState};
use rastty_core::shading::{Cutout, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};
use rastty_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 8;
const H: u32 = 4;
const RED: u32 = 0xFF_0000;
const GREEN: u32 = 0x00_FF00;
const BLUE: u32 = 0x00_00FF;

/// A quad over the whole frame at NDC depth `z`, `u` from 0 at the left edge to 1 at the right.
fn quad(z: f32) -> ([Vec3; 4], [Vec2; 4]) {
    let positions = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| Vec3::new(x, y, z));
    let uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(u, v)| Vec2::new(u, v));
    (positions, uvs)
}

/// Draws a front quad (depth 0.25) with `front`, then a blue back quad (depth 0.75) behind it; the colours and
/// depths of the frame, and the front draw's cut-out.
fn front_then_back(front: Material<'_>) -> (Vec<u32>, Vec<f32>, Cutout) {
    const INDICES: [u16; 6] = [0, 1, 2, 0, 2, 3];
    let (mut color, mut depth) = (vec![0u32; (W * H) as usize], vec![0f32; (W * H) as usize]);
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], W, H).unwrap();
    target.clear(Vec3::ZERO);
    // Clip space is NDC: every matrix the identity.
    let transforms = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY);
    let state = DrawState { cull: Cull::None, ..DrawState::default() };
    let lights = Lighting { ambient: Vec3::ZERO, lights: &[], environment: None, space: ShadingSpace::Linear };
    let mut cutout = Cutout::None;
    for (z, material) in [(0.25, front), (0.75, Material::plain(Vec3::new(0.0, 0.0, 1.0)))] {
        let (positions, uvs) = quad(z);
        let mesh = Mesh::new(&positions, Indices::U16(&INDICES)).unwrap().with_uvs(&uvs).unwrap();
        let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::Unlit, material };
        let (variant, _) = draw_mesh(&mut target, &object, &lights, &state).unwrap();
        if z == 0.25 {
            cutout = variant.cutout;
        }
    }
    (color, depth, cutout)
}

/// A 2x1 texture: opaque red on the left, fully transparent green on the right; read texel by texel.
fn red_and_clear(texels: &[u32; 2], opacity: f32, alpha_cutoff: Option<f32>) -> Material<'_> {
    Material {
        diffuse: Some(Texture::new(texels, 2, 1).unwrap()),
        filter: FilterMode::Nearest,
        wrap: WrapMode::Clamp,
        opacity,
        alpha_cutoff,
        ..Material::plain(Vec3::ONE)
    }
}

/// Columns 0..4 read the left texel, 4..8 the right one.
fn halves(left: u32, right: u32) -> Vec<u32> {
    (0..W * H).map(|i| if i % W < W / 2 { left } else { right }).collect()
}

#[test]
fn a_cut_out_texel_leaves_colour_and_depth_for_what_is_behind() {
    let texels = [RED, 0xFF00_0000 | GREEN];
    let (color, depth, cutout) = front_then_back(red_and_clear(&texels, 1.0, Some(0.5)));
    assert_eq!(cutout, Cutout::Map(0.5));
    assert_eq!(color, halves(RED, BLUE));
    let expected: Vec<f32> = halves(1, 3).iter().map(|&q| q as f32 * 0.25).collect();
    assert_eq!(depth, expected);
}

#[test]
fn without_a_cut_off_alpha_is_not_read() {
    let texels = [RED, 0xFF00_0000 | GREEN];
    let (color, depth, cutout) = front_then_back(red_and_clear(&texels, 0.2, None));
    assert_eq!(cutout, Cutout::None);
    assert_eq!(color, halves(RED, GREEN));
    assert!(depth.iter().all(|&d| d == 0.25));
}

/// The cut-off compares `opacity * alpha / 255`: alpha 128 at opacity 1 is 0.50196 (kept at 0.5, not at 0.51);
/// opacity 0.4 cuts even an opaque texel under 0.5.
#[test]
fn the_cut_off_weighs_opacity_and_texel_alpha() {
    let half = [RED, 0x7F00_0000 | GREEN];
    assert_eq!(front_then_back(red_and_clear(&half, 1.0, Some(0.5))).0, halves(RED, GREEN));
    assert_eq!(front_then_back(red_and_clear(&half, 1.0, Some(0.51))).0, halves(RED, BLUE));
    let opaque = [RED, GREEN];
    assert_eq!(front_then_back(red_and_clear(&opaque, 0.4, Some(0.5))).0, halves(BLUE, BLUE));
}

/// Without a diffuse map the opacity decides for the whole draw, once: below the cut-off nothing is drawn.
#[test]
fn a_surface_below_its_cut_off_is_not_drawn() {
    let hidden = Material { opacity: 0.3, alpha_cutoff: Some(0.5), ..Material::plain(Vec3::ONE) };
    let (color, depth, cutout) = front_then_back(hidden);
    assert_eq!(cutout, Cutout::Everything);
    assert_eq!(color, halves(BLUE, BLUE));
    assert!(depth.iter().all(|&d| d == 0.75));
    let shown = Material { opacity: 0.5, ..hidden };
    let (color, _, cutout) = front_then_back(shown);
    assert_eq!(cutout, Cutout::None);
    assert_eq!(color, halves(0xFF_FFFF, 0xFF_FFFF));
}
