//! Drawing a mesh: the variant is resolved once, then the pipeline compiled for its varyings runs.

use super::varyings::Absent;
use super::{Lighting, Material, ShadingError, ShadingModel, SurfaceShader, Transforms, Variant};
use crate::math::{Vec2, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::pipeline::{DrawState, DrawStats, draw};
use crate::target::{ColorBuffer, DepthBuffer, Target, VertexMemory};

/// One object of a draw: its mesh, tangents, place, shading model and material.
#[derive(Clone, Copy, Debug)]
pub struct Object<'a> {
    /// The mesh (normals for Gouraud and per-pixel lighting and the normals view; texture coordinates for maps;
    /// colours for the albedo).
    pub mesh: Mesh<'a>,
    /// One tangent per vertex ([`crate::mesh::compute_tangents`]), needed by a tangent-space normal map only.
    pub tangents: Option<&'a [Vec4]>,
    /// Its matrices.
    pub transforms: Transforms,
    /// How light shades it.
    pub shading: ShadingModel,
    /// How it looks.
    pub material: Material<'a>,
}

/// Draws an object with its material under `lights`: resolves the [`Variant`], then runs the pipeline compiled
/// for its varyings (each slot carried only when used) and its fragment stages (only the shading model, maps and
/// light kinds it has), batch by batch.
///
/// A draw cut out entirely ([`crate::shading::Cutout::Everything`]) runs the pipeline, counting its triangles,
/// and keeps no fragment.
///
/// Shadow maps must be finished before (see [`crate::shadow::draw_shadow_caster`]).
///
/// # Errors
/// As [`Variant::resolve`] and [`draw`].
pub fn draw_mesh<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
    target: &mut Target<C, D, M>,
    object: &Object<'_>,
    lights: &Lighting<'_>,
    state: &DrawState,
) -> Result<(Variant, DrawStats), ShadingError> {
    let variant = Variant::resolve(object, lights.uses(), lights.space, state)?;
    let tangents = object.tangents.unwrap_or(&[]);
    let (mesh, state) = (&object.mesh, &variant.state);
    macro_rules! run {
        ($a:ty, $b:ty, $u:ty, $t:ty, $c:ty) => {{
            let shader = SurfaceShader::<$a, $b, $u, $t, $c>::new(
                variant,
                object.transforms,
                tangents,
                object.material,
                *lights,
            )?;
            draw(target, mesh, &shader, state).map_err(ShadingError::Draw)?
        }};
    }
    let layout = variant.layout();
    let stats = match (layout.first, layout.second, layout.uvs, layout.tangents) {
        // Vertex colours are rare: their draws carry every slot (those not read hold zeros), so that they add one
        // compiled pipeline, not eight.
        _ if layout.colors => run!(Vec3, Vec3, Vec2, Vec4, Vec3),
        (false, _, false, _) => run!(Absent, Absent, Absent, Absent, Absent),
        (false, _, true, _) => run!(Absent, Absent, Vec2, Absent, Absent),
        (true, false, false, _) => run!(Vec3, Absent, Absent, Absent, Absent),
        (true, false, true, false) => run!(Vec3, Absent, Vec2, Absent, Absent),
        (true, false, true, true) => run!(Vec3, Absent, Vec2, Vec4, Absent),
        (true, true, false, _) => run!(Vec3, Vec3, Absent, Absent, Absent),
        (true, true, true, false) => run!(Vec3, Vec3, Vec2, Absent, Absent),
        (true, true, true, true) => run!(Vec3, Vec3, Vec2, Vec4, Absent),
    };
    Ok((variant, stats))
}
