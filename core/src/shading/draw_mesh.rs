//! Mesh draws with effects: the variant is chosen once, then one monomorphised pipeline runs.

use super::texture_stage::Textured;
use super::{
    DepthShader, Effects, FlatShader, GeneralShader, GouraudShader, NoSpecular, NormalShader, PhongShader,
    ShadingModel, Specular, Surface, Transforms, UnlitShader, Untextured, Variant, VertexColorShader,
};
use crate::mesh::Mesh;
use crate::pipeline::{DrawError, DrawState, DrawStats, draw, draw_unspecialised};
use crate::target::{ColorBuffer, DepthBuffer, Target};
use crate::texture::{Bilinear, Clamp, FilterMode, Nearest, Repeat, WrapMode};

/// Binds `$t` to the texture stage of `$binding` (a type per filter and wrap mode) and evaluates `$body`.
macro_rules! with_texture_stage {
    ($binding:expr, $t:ident => $body:expr) => {
        match $binding {
            None => {
                let $t = Untextured;
                $body
            }
            Some(b) => match (b.filter, b.wrap) {
                (FilterMode::Nearest, WrapMode::Repeat) => {
                    let $t = Textured::<Nearest, Repeat>::new(b.texture);
                    $body
                }
                (FilterMode::Nearest, WrapMode::Clamp) => {
                    let $t = Textured::<Nearest, Clamp>::new(b.texture);
                    $body
                }
                (FilterMode::Bilinear, WrapMode::Repeat) => {
                    let $t = Textured::<Bilinear, Repeat>::new(b.texture);
                    $body
                }
                (FilterMode::Bilinear, WrapMode::Clamp) => {
                    let $t = Textured::<Bilinear, Clamp>::new(b.texture);
                    $body
                }
            },
        }
    };
}

/// Names `$h` the highlights type for `$on` and evaluates `$body`.
macro_rules! with_highlights {
    ($on:expr, $h:ident => $body:expr) => {
        if $on {
            type $h = Specular;
            $body
        } else {
            type $h = NoSpecular;
            $body
        }
    };
}

/// Draws `mesh` with `effects`: resolves the [`Variant`] the scene calls for, then runs the pipeline compiled for
/// exactly that variant (shading model × texture filter and wrap × highlights × interpolation × depth test).
///
/// # Errors
/// As [`Effects::resolve`] and [`draw`].
pub fn draw_mesh<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    mesh: &Mesh<'_>,
    transforms: &Transforms,
    effects: &Effects<'_>,
    state: &DrawState,
) -> Result<DrawStats, DrawError> {
    let variant = effects.resolve(mesh, transforms, state)?;
    let surface = Surface { transforms: *transforms, material: effects.material, lighting: effects.lighting };
    draw_variant(target, mesh, &variant, surface)
}

/// Like [`draw_mesh`], but through [`GeneralShader`] and the general pixel loop, which branch on the variant at
/// run time. The pixels are identical; only the speed differs.
///
/// # Errors
/// As [`draw_mesh`].
pub fn draw_mesh_unspecialised<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    mesh: &Mesh<'_>,
    transforms: &Transforms,
    effects: &Effects<'_>,
    state: &DrawState,
) -> Result<DrawStats, DrawError> {
    let variant = effects.resolve(mesh, transforms, state)?;
    let surface = Surface { transforms: *transforms, material: effects.material, lighting: effects.lighting };
    draw_unspecialised(target, mesh, &GeneralShader::new(variant, surface), &variant.state)
}

fn draw_variant<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    mesh: &Mesh<'_>,
    variant: &Variant<'_>,
    surface: Surface<'_>,
) -> Result<DrawStats, DrawError> {
    let state = &variant.state;
    let clip = surface.transforms.clip_from_object;
    match variant.shading {
        ShadingModel::Unlit if variant.vertex_colors => {
            with_texture_stage!(variant.texture, t => draw(target, mesh, &VertexColorShader::new(clip, t), state))
        }
        ShadingModel::Unlit => with_texture_stage!(variant.texture, t => {
            draw(target, mesh, &UnlitShader::new(clip, surface.material.color, t), state)
        }),
        ShadingModel::Flat => {
            with_texture_stage!(variant.texture, t => draw(target, mesh, &FlatShader::new(surface, t), state))
        }
        ShadingModel::Gouraud => {
            with_texture_stage!(variant.texture, t => with_highlights!(variant.specular, H => {
                draw(target, mesh, &GouraudShader::<_, H>::new(surface, t), state)
            }))
        }
        ShadingModel::Phong => {
            with_texture_stage!(variant.texture, t => with_highlights!(variant.specular, H => {
                draw(target, mesh, &PhongShader::<_, H>::new(surface, t), state)
            }))
        }
        ShadingModel::Depth { near, far } => draw(target, mesh, &DepthShader::new(clip, near, far), state),
        ShadingModel::Normals => draw(target, mesh, &NormalShader::new(clip, surface.transforms.normal), state),
    }
}
