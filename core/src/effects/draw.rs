//! Mapped draws: the variant is resolved once, then the pipeline compiled for its varyings runs.

use super::varyings::Absent;
use super::{LightUse, SceneLights, SurfaceError, SurfaceMaterial, SurfaceShader, SurfaceVariant};
use crate::math::{Vec2, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::pipeline::{DrawState, DrawStats, draw, draw_unspecialised};
use crate::shading::{ShadingModel, Transforms};
use crate::target::{ColorBuffer, DepthBuffer, Target};

/// One object of a draw: its mesh, tangents, place, shading model and material.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceDraw<'a> {
    /// The mesh (normals for Gouraud and per-pixel lighting and the normals view; texture coordinates for maps;
    /// colours for unlit shading's albedo).
    pub mesh: Mesh<'a>,
    /// One tangent per vertex ([`crate::mesh::compute_tangents`]), needed by a tangent-space normal map only.
    pub tangents: Option<&'a [Vec4]>,
    /// Its matrices.
    pub transforms: Transforms,
    /// How light shades it.
    pub shading: ShadingModel,
    /// How it looks.
    pub material: SurfaceMaterial<'a>,
}

/// Draws an object with its material under `lights`: resolves the [`SurfaceVariant`], then runs the pipeline
/// compiled for its varyings (world position, texture coordinates, tangent: each carried only when used) and
/// its fragment stages (only the maps and light kinds it has).
///
/// Shadow maps must be finished before (see [`crate::shadow::draw_shadow_caster`]).
///
/// # Errors
/// As [`SurfaceVariant::resolve`] and [`draw`].
pub fn draw_surface<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    object: &SurfaceDraw<'_>,
    lights: &SceneLights<'_>,
    state: &DrawState,
) -> Result<(SurfaceVariant, DrawStats), SurfaceError> {
    dispatch(target, object, lights, state, false)
}

/// Like [`draw_surface`], but through the general pixel loop ([`draw_unspecialised`]) and with every varying
/// carried: the same pixels, for tests and benchmarks.
///
/// # Errors
/// As [`draw_surface`].
pub fn draw_surface_unspecialised<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    object: &SurfaceDraw<'_>,
    lights: &SceneLights<'_>,
    state: &DrawState,
) -> Result<(SurfaceVariant, DrawStats), SurfaceError> {
    dispatch(target, object, lights, state, true)
}

fn dispatch<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    object: &SurfaceDraw<'_>,
    lights: &SceneLights<'_>,
    state: &DrawState,
    general: bool,
) -> Result<(SurfaceVariant, DrawStats), SurfaceError> {
    let variant = SurfaceVariant::resolve(object, lights.lights.iter().map(LightUse::from), state)?;
    let stats = draw_resolved(target, object, lights, &variant, general)?;
    Ok((variant, stats))
}

/// Runs the pipeline compiled for `variant`'s layout: each slot carried only when used (or, for the general path,
/// every slot: carrying one more varying changes no pixel, each is interpolated independently of the others).
fn draw_resolved<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    object: &SurfaceDraw<'_>,
    lights: &SceneLights<'_>,
    variant: &SurfaceVariant,
    general: bool,
) -> Result<DrawStats, SurfaceError> {
    let tangents = object.tangents.unwrap_or(&[]);
    let (mesh, state) = (&object.mesh, &variant.state);
    macro_rules! run {
        ($a:ty, $b:ty, $u:ty, $t:ty) => {{
            let shader =
                SurfaceShader::<$a, $b, $u, $t>::new(*variant, object.transforms, tangents, object.material, *lights)?;
            let drawn = if general {
                draw_unspecialised(target, mesh, &shader, state)
            } else {
                draw(target, mesh, &shader, state)
            };
            drawn.map_err(SurfaceError::Draw)
        }};
    }
    let layout = variant.layout();
    if general {
        return if layout.tangents {
            run!(Vec3, Vec3, Vec2, Vec4)
        } else if layout.uvs {
            run!(Vec3, Vec3, Vec2, Absent)
        } else {
            run!(Vec3, Vec3, Absent, Absent)
        };
    }
    match (layout.first, layout.second, layout.uvs, layout.tangents) {
        (false, _, false, _) => run!(Absent, Absent, Absent, Absent),
        (false, _, true, _) => run!(Absent, Absent, Vec2, Absent),
        (true, false, false, _) => run!(Vec3, Absent, Absent, Absent),
        (true, false, true, false) => run!(Vec3, Absent, Vec2, Absent),
        (true, false, true, true) => run!(Vec3, Absent, Vec2, Vec4),
        (true, true, false, _) => run!(Vec3, Vec3, Absent, Absent),
        (true, true, true, false) => run!(Vec3, Vec3, Vec2, Absent),
        (true, true, true, true) => run!(Vec3, Vec3, Vec2, Vec4),
    }
}
