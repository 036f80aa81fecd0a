//! Test oracles: the general paths that the specialised ones are proven equal to, for tests, fuzz targets and
//! benchmarks. Hidden from the documentation and not part of the API a renderer calls: slower by design.

use crate::pipeline::DrawStats;
use crate::shading::{Lighting, Object, ShadingError, Variant};
use crate::target::{ColorBuffer, DepthBuffer, Target};

pub use crate::pipeline::draw::draw_unspecialised;
pub use crate::shading::general::{GeneralShader, GeneralVaryings};

/// [`crate::shading::draw_mesh`] through the general path: the same variant, drawn by [`GeneralShader`] (every
/// choice made per vertex and per fragment in scalar maths) through [`draw_unspecialised`] (interpolation and
/// depth test decided per pixel, every varying carried). It must give the same pixels, depths and counts.
///
/// # Errors
/// As [`crate::shading::draw_mesh`].
pub fn draw_mesh_general<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    object: &Object<'_>,
    lights: &Lighting<'_>,
    state: &crate::pipeline::DrawState,
) -> Result<(Variant, DrawStats), ShadingError> {
    let variant = Variant::resolve(object, lights.uses(), lights.space, state)?;
    let tangents = object.tangents.unwrap_or(&[]);
    let shader = GeneralShader::new(variant, object.transforms, tangents, object.material, *lights);
    let stats = draw_unspecialised(target, &object.mesh, &shader, &variant.state).map_err(ShadingError::Draw)?;
    Ok((variant, stats))
}
