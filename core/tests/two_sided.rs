//! Two-sided lighting with known answers: a draw that keeps back faces lights them per pixel with their normal
//! turned round, so a surface seen from behind is lit by a light on the viewer's side.

use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};

const W: u32 = 4;
const H: u32 = 4;

/// A quad over the whole frame whose normals point along `normal`, wound counter-clockwise (front-facing) or
/// clockwise, drawn white under an ambient 0.25 and a light of 0.5 toward +z with `shading` and `cull`: the
/// frame's colours, and whether the variant is two-sided (`None` when nothing was drawn).
fn quad(normal: Vec3, front: bool, shading: ShadingModel, cull: Cull) -> (Vec<u32>, bool) {
    let positions = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| Vec3::new(x, y, 0.5));
    let normals = [normal; 4];
    let indices: [u16; 6] = if front { [0, 1, 2, 0, 2, 3] } else { [0, 2, 1, 0, 3, 2] };
    let mesh = Mesh::new(&positions, Indices::U16(&indices)).unwrap().with_normals(&normals).unwrap();
    let mut color = vec![0u32; (W * H) as usize];
    let mut depth = vec![0f32; (W * H) as usize];
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], W, H).unwrap();
    target.clear(Vec3::ZERO);
    let transforms = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY);
    let object = Object { mesh, tangents: None, transforms, shading, material: Material::plain(Vec3::ONE) };
    let light = [Light::directional(Vec3::Z, Vec3::splat(0.5))];
    let lights =
        Lighting { ambient: Vec3::splat(0.25), lights: &light, environment: None, space: ShadingSpace::Linear };
    let (variant, _) = draw_mesh(&mut target, &object, &lights, &DrawState { cull, ..DrawState::default() }).unwrap();
    (color, variant.two_sided)
}

/// In linear light `0.25 + 0.5 = 0.75` of white encodes to 224.61 / 255, code 225; `0.25` alone to 136.96, 137.
const LIT: u32 = 0xE1_E1E1;
const AMBIENT: u32 = 0x89_8989;

#[test]
fn a_back_face_is_lit_with_its_normal_turned_round() {
    let away = Vec3::new(0.0, 0.0, -1.0);
    // Front-facing, its normal away from the light: ambient only.
    assert_eq!(quad(away, true, ShadingModel::Phong, Cull::None), (vec![AMBIENT; 16], true));
    // Back-facing, the same normal: turned round, toward the light, whether culling is off or culls the front.
    assert_eq!(quad(away, false, ShadingModel::Phong, Cull::None), (vec![LIT; 16], true));
    assert_eq!(quad(away, false, ShadingModel::Phong, Cull::Front), (vec![LIT; 16], true));
    // Culling back faces: one-sided, and the back face is not drawn.
    assert_eq!(quad(away, false, ShadingModel::Phong, Cull::Back), (vec![0; 16], false));
    assert_eq!(quad(Vec3::Z, true, ShadingModel::Phong, Cull::Back), (vec![LIT; 16], false));
    // Gouraud lights per vertex, before facing is known: both faces alike.
    assert_eq!(quad(away, false, ShadingModel::Gouraud, Cull::None), (vec![AMBIENT; 16], false));
}
