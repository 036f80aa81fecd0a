//! Mapped draws: the variant is resolved once, then the pipeline compiled for its varyings runs.

use super::varyings::Absent;
use super::{LightUse, SceneLights, SurfaceError, SurfaceMaterial, SurfaceShader, SurfaceVariant};
use crate::math::{Vec2, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::pipeline::{DrawState, DrawStats, draw, draw_unspecialised};
use crate::shading::Transforms;
use crate::target::{ColorBuffer, DepthBuffer, Target};

/// One object of a mapped draw: its mesh, tangents, place and material.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceDraw<'a> {
    /// The mesh (normals required; texture coordinates for maps).
    pub mesh: Mesh<'a>,
    /// One tangent per vertex ([`crate::mesh::compute_tangents`]), needed by a tangent-space normal map only.
    pub tangents: Option<&'a [Vec4]>,
    /// Its matrices.
    pub transforms: Transforms,
    /// How it looks.
    pub material: SurfaceMaterial<'a>,
}

/// Draws an object with its material under `lights`: resolves the [`SurfaceVariant`], then runs the pipeline
/// compiled for its varyings (world position, texture coordinates, tangent: each carried only when used) and
/// its fragment stages (only the maps and light kinds it has).
///
/// Shadow maps must be finished before (see [`super::draw_shadow_caster`]).
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
    let uses = lights.lights.iter().map(LightUse::from);
    let variant =
        SurfaceVariant::resolve(&object.mesh, object.tangents, &object.transforms, &object.material, uses, state)?;
    let tangents = object.tangents.unwrap_or(&[]);
    let (mesh, material, transforms) = (&object.mesh, object.material, object.transforms);
    let state = &variant.state;
    macro_rules! run {
        ($w:ty, $u:ty, $t:ty) => {{
            let shader = SurfaceShader::<$w, $u, $t>::new(variant, transforms, tangents, material, *lights);
            if general { draw_unspecialised(target, mesh, &shader, state) } else { draw(target, mesh, &shader, state) }
        }};
    }
    let result = if general {
        // Carrying every varying changes no pixel: each is interpolated independently of the others.
        if variant.tangents {
            run!(Vec3, Vec2, Vec4)
        } else if variant.uvs {
            run!(Vec3, Vec2, Absent)
        } else {
            run!(Vec3, Absent, Absent)
        }
    } else {
        match (variant.world, variant.uvs, variant.tangents) {
            (false, false, _) => run!(Absent, Absent, Absent),
            (true, false, _) => run!(Vec3, Absent, Absent),
            (false, true, false) => run!(Absent, Vec2, Absent),
            (true, true, false) => run!(Vec3, Vec2, Absent),
            (false, true, true) => run!(Absent, Vec2, Vec4),
            (true, true, true) => run!(Vec3, Vec2, Vec4),
        }
    };
    Ok((variant, result.map_err(SurfaceError::Draw)?))
}
