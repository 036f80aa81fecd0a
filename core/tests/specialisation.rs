//! "Only the effects a scene calls for": every combination of effects rendered through the specialised pipelines
//! and through the general one must give identical pixels, depths and statistics. The general path draws into a
//! caller's own depth buffer (`PlainDepth`), the specialised ones into the library's `&mut [f32]`.

use crate::common;

use common::{ExactColor, PlainDepth, Torus, assert_same_depths, checker_texels};
use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DepthTest, DrawState, DrawStats, EdgeArithmetic, Interpolation};
use rastty_core::shading::{
    Effects, Light, Lighting, Material, ShadingModel, TextureBinding, Transforms, draw_mesh, draw_mesh_unspecialised,
};
use rastty_core::target::Target;
use rastty_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 48;
const H: u32 = 40;

/// The exact colours, the depths and the statistics of one draw.
type Rendered = (Vec<[u32; 3]>, Vec<f32>, DrawStats);

fn render(
    mesh: &Mesh<'_>,
    transforms: &Transforms,
    effects: &Effects<'_>,
    state: &DrawState,
    specialised: bool,
) -> Rendered {
    // Exact f32 colours: a difference in the last bit counts.
    let mut color = vec![[0u32; 3]; (W * H) as usize];
    let mut depth = vec![0f32; (W * H) as usize];
    let background = Vec3::new(0.1, 0.2, 0.3);
    let stats = if specialised {
        let mut target = Target::new(ExactColor(&mut color), &mut depth[..], W, H).unwrap();
        target.clear(background);
        draw_mesh(&mut target, mesh, transforms, effects, state)
    } else {
        let mut target = Target::new(ExactColor(&mut color), PlainDepth(&mut depth), W, H).unwrap();
        target.clear(background);
        draw_mesh_unspecialised(&mut target, mesh, transforms, effects, state)
    }
    .unwrap();
    (color, depth, stats)
}

#[test]
fn specialised_pipelines_equal_the_general_one_for_every_combination() {
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
    let lights = [
        Light::directional(Vec3::new(0.5, 1.0, 0.8), Vec3::new(0.9, 0.85, 0.8)),
        Light::directional(Vec3::new(-1.0, -0.2, 0.3), Vec3::new(0.2, 0.25, 0.4)),
    ];
    let lighting = Lighting { ambient: Vec3::splat(0.08), lights: &lights };
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
    let mut clipped = 0;
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
                            let effects = Effects {
                                shading,
                                material: Material { color: Vec3::new(0.9, 0.7, 0.5), specular, shininess: 24.0 },
                                lighting,
                                texture: texture_mode.map(|(filter, wrap)| TextureBinding { texture, filter, wrap }),
                            };
                            let state = DrawState { interpolation, depth_test, cull, edges, ..DrawState::default() };
                            let (fast, fast_depth, fast_stats) = render(mesh, &transforms, &effects, &state, true);
                            let (general, general_depth, general_stats) =
                                render(mesh, &transforms, &effects, &state, false);
                            let variant = effects.resolve(mesh, &transforms, &state).unwrap();
                            assert_eq!(fast_stats, general_stats, "{variant}");
                            let differing = fast.iter().zip(&general).filter(|(a, b)| a != b).count();
                            assert_eq!(differing, 0, "{variant}: {differing} pixels differ");
                            assert_same_depths(&variant.to_string(), &general_depth, &fast_depth, W as usize, 0);
                            assert!(fast_stats.fragments > 100, "{variant}: the scene must cover pixels");
                            combinations += 1;
                            clipped += u64::from(fast_stats.clipped > 0);
                        }
                    }
                }
            }
        }
    }
    assert_eq!(combinations, 2 * 6 * 5 * 2 * 2 * 5);
    assert!(clipped > 0);
}

#[test]
fn resolve_keeps_only_what_the_scene_uses() {
    let torus = Torus::new(1.0, 0.4, 8, 6);
    let texels = checker_texels();
    let texture = Texture::new(&texels, 8, 8).unwrap();
    let lighting = Lighting { ambient: Vec3::ZERO, lights: &[] };
    let view = look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y).unwrap();
    let persp = Transforms::new(Mat4::IDENTITY, view, perspective(1.0, 1.0, 0.1, 10.0).unwrap());
    let ortho = Transforms::new(Mat4::IDENTITY, view, orthographic(-2.0, 2.0, -2.0, 2.0, 0.1, 10.0).unwrap());
    let mirrored =
        Transforms::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)), view, perspective(1.0, 1.0, 0.1, 10.0).unwrap());
    let binding = TextureBinding { texture, filter: FilterMode::Bilinear, wrap: WrapMode::Repeat };
    let effects = |shading, specular| Effects {
        shading,
        material: Material { specular, ..Material::default() },
        lighting,
        texture: Some(binding),
    };
    let state = DrawState::default();
    let explain = |e: Effects<'_>, mesh: &Mesh<'_>, t: &Transforms| e.resolve(mesh, t, &state).unwrap().to_string();

    let full = torus.mesh();
    let no_uv =
        Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap().with_normals(&torus.normals).unwrap();
    assert_eq!(
        explain(effects(ShadingModel::Phong, Vec3::ONE), &full, &persp),
        "phong, texture bilinear/repeat, specular, perspective-correct, depth less, cull back"
    );
    // No texture coordinates: untextured, whatever was asked.
    assert_eq!(
        explain(effects(ShadingModel::Phong, Vec3::ZERO), &no_uv, &persp),
        "phong, untextured, no specular, perspective-correct, depth less, cull back"
    );
    // Orthographic: affine interpolation, no per-pixel division.
    assert_eq!(
        explain(effects(ShadingModel::Gouraud, Vec3::ZERO), &full, &ortho),
        "gouraud, texture bilinear/repeat, no specular, affine, depth less, cull back"
    );
    // Unlit never lights; with vertex colours it uses them.
    assert_eq!(
        explain(effects(ShadingModel::Unlit, Vec3::ONE), &full, &persp),
        "unlit, vertex colours, texture bilinear/repeat, perspective-correct, depth less, cull back"
    );
    // Debug views never sample textures.
    assert_eq!(
        explain(effects(ShadingModel::Normals, Vec3::ONE), &full, &persp),
        "normals, perspective-correct, depth less, cull back"
    );
    // A mirroring model matrix flips the front face.
    let v = effects(ShadingModel::Flat, Vec3::ZERO).resolve(&full, &mirrored, &state).unwrap();
    assert_eq!(v.state.front_face, rastty_core::pipeline::Winding::Clockwise);
    // Normals are required where they are used.
    let positions_only = Mesh::new(&torus.positions, Indices::U16(&torus.indices)).unwrap();
    assert!(effects(ShadingModel::Gouraud, Vec3::ZERO).resolve(&positions_only, &persp, &state).is_err());
    assert!(effects(ShadingModel::Flat, Vec3::ZERO).resolve(&positions_only, &persp, &state).is_ok());
}
