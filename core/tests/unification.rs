//! The surface shader draws every shading model the older shaders of `shading` draw, bit for bit: the same
//! `f32` colours, depths and statistics for every combination of model, texture mode, highlights, vertex colours,
//! projection and fixed-function state (the matrix of `specialisation.rs`). While both exist, this proves the
//! batched path can replace the per-pixel one.

use crate::common;

use common::{ExactColor, Torus, assert_same_depths, checker_texels};
use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::effects::{LightSource, SceneLights, SurfaceDraw, SurfaceMaterial, draw_surface};
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DepthTest, DrawState, DrawStats, EdgeArithmetic, Interpolation};
use rastty_core::shading::{Effects, Light, Lighting, Material, ShadingModel, TextureBinding, Transforms, draw_mesh};
use rastty_core::target::Target;
use rastty_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 48;
const H: u32 = 40;

/// The exact colours, the depths and the statistics of one draw.
type Rendered = (Vec<[u32; 3]>, Vec<f32>, DrawStats);

fn target_for<'a>(color: &'a mut [[u32; 3]], depth: &'a mut [f32]) -> Target<ExactColor<'a>, &'a mut [f32]> {
    let mut target = Target::new(ExactColor(color), depth, W, H).unwrap();
    target.clear(Vec3::new(0.1, 0.2, 0.3));
    target
}

fn old(mesh: &Mesh<'_>, transforms: &Transforms, effects: &Effects<'_>, state: &DrawState) -> Rendered {
    let (mut color, mut depth) = (vec![[0u32; 3]; (W * H) as usize], vec![0f32; (W * H) as usize]);
    let stats = draw_mesh(&mut target_for(&mut color, &mut depth), mesh, transforms, effects, state).unwrap();
    (color, depth, stats)
}

fn new(object: &SurfaceDraw<'_>, lights: &SceneLights<'_>, state: &DrawState) -> Rendered {
    let (mut color, mut depth) = (vec![[0u32; 3]; (W * H) as usize], vec![0f32; (W * H) as usize]);
    let (_, stats) = draw_surface(&mut target_for(&mut color, &mut depth), object, lights, state).unwrap();
    (color, depth, stats)
}

#[test]
fn the_surface_shader_draws_every_model_as_the_older_shaders_do() {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let with_colors = torus.mesh();
    let positions_only = Mesh::new(&torus.positions, Indices::U16(&torus.indices))
        .unwrap()
        .with_normals(&torus.normals)
        .unwrap()
        .with_uvs(&torus.uvs)
        .unwrap();
    let texels = checker_texels();
    let texture = Texture::new(&texels, 8, 8).unwrap();
    let (key, fill) = (
        (Vec3::new(0.5, 1.0, 0.8), Vec3::new(0.9, 0.85, 0.8)),
        (Vec3::new(-1.0, -0.2, 0.3), Vec3::new(0.2, 0.25, 0.4)),
    );
    let lights = [Light::directional(key.0, key.1), Light::directional(fill.0, fill.1)];
    let sources = [LightSource::directional(key.0, key.1), LightSource::directional(fill.0, fill.1)];
    let ambient = Vec3::splat(0.08);
    let lighting = Lighting { ambient, lights: &lights };
    let scene_lights = SceneLights { ambient, lights: &sources };
    let model = Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.0), 1.1);
    // A camera close enough that the near plane cuts the torus, so clipped varyings are compared too.
    let view = look_at(Vec3::new(0.3, 0.5, 1.6), Vec3::ZERO, Vec3::Y).unwrap();
    let projections = [
        perspective(1.3, W as f32 / H as f32, 0.6, 10.0).unwrap(),
        orthographic(-1.6, 1.6, -1.3, 1.3, 0.1, 10.0).unwrap(),
    ];
    let shadings = [
        ShadingModel::Unlit,
        ShadingModel::Flat,
        ShadingModel::Gouraud,
        ShadingModel::Phong,
        ShadingModel::Depth { near: 0.2, far: 0.9 },
        ShadingModel::Normals,
    ];
    let textures = [
        None,
        Some((FilterMode::Nearest, WrapMode::Repeat)),
        Some((FilterMode::Nearest, WrapMode::Clamp)),
        Some((FilterMode::Bilinear, WrapMode::Repeat)),
        Some((FilterMode::Bilinear, WrapMode::Clamp)),
    ];
    let mut combinations = 0;
    for projection in projections {
        let transforms = Transforms::new(model, view, projection);
        for shading in shadings {
            for texture_mode in textures {
                for specular in [Vec3::ZERO, Vec3::splat(0.6)] {
                    for mesh in [&with_colors, &positions_only] {
                        for (interpolation, depth_test, cull, edges) in [
                            (
                                Interpolation::PerspectiveCorrect,
                                DepthTest::Less,
                                Cull::Back,
                                EdgeArithmetic::FixedPoint,
                            ),
                            (Interpolation::Affine, DepthTest::Less, Cull::None, EdgeArithmetic::Float),
                            (Interpolation::PerspectiveCorrect, DepthTest::Off, Cull::None, EdgeArithmetic::Float),
                            (Interpolation::Affine, DepthTest::Off, Cull::Front, EdgeArithmetic::FixedPoint),
                            (Interpolation::PerspectiveCorrect, DepthTest::Less, Cull::Back, EdgeArithmetic::Float),
                        ] {
                            let color = Vec3::new(0.9, 0.7, 0.5);
                            let effects = Effects {
                                shading,
                                material: Material { color, specular, shininess: 24.0 },
                                lighting,
                                texture: texture_mode.map(|(filter, wrap)| TextureBinding { texture, filter, wrap }),
                            };
                            let (filter, wrap) = texture_mode.unwrap_or((FilterMode::Bilinear, WrapMode::Repeat));
                            let material = SurfaceMaterial {
                                specular,
                                shininess: 24.0,
                                diffuse: texture_mode.map(|_| texture),
                                filter,
                                wrap,
                                ..SurfaceMaterial::plain(color)
                            };
                            let object = SurfaceDraw { mesh: *mesh, tangents: None, transforms, shading, material };
                            let state = DrawState { interpolation, depth_test, cull, edges, ..DrawState::default() };
                            let (before, before_depth, before_stats) = old(mesh, &transforms, &effects, &state);
                            let (after, after_depth, after_stats) = new(&object, &scene_lights, &state);
                            let variant = effects.resolve(mesh, &transforms, &state).unwrap();
                            assert_eq!(after_stats, before_stats, "{variant}");
                            let differing = after.iter().zip(&before).filter(|(a, b)| a != b).count();
                            assert_eq!(differing, 0, "{variant}: {differing} pixels differ");
                            assert_same_depths(&variant.to_string(), &before_depth, &after_depth, W as usize, 0);
                            combinations += 1;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(combinations, 2 * 6 * 5 * 2 * 2 * 5);
}
