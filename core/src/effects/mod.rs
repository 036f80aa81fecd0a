//! Effects a scene may call for, computed only when it does: material maps (diffuse, tangent- or object-space
//! normal, specular, glow), directional and point lights, shadow maps, and screen-space ambient occlusion.
//!
//! A frame with effects is a sequence of passes, each run only if the scene needs it:
//!
//! 1. **Shadow passes**, one per shadow-casting light: [`ShadowView::fit`] frames the scene from the light, and
//!    [`draw_shadow_caster`] draws every object's depth into a buffer the caller owns. For a filtered map,
//!    [`window_ranges_band`] then records each filter window's nearest and farthest depth ([`WindowRanges`]), so
//!    that most lookups read one value instead of the whole window.
//! 2. **Forward pass**: [`draw_surface`] per object. [`SurfaceVariant::resolve`] decides, once per draw, which
//!    varyings are interpolated (world position, texture coordinates, tangents) and which fragment stages run:
//!    normals (interpolated or from a map), albedo, lights (each with or without its shadow map and
//!    highlights), specular colour, glow. The pixel loop is compiled for the varyings; the fragment stages run as
//!    loops over batches of up to [`crate::pipeline::BATCH_SIZE`] fragments, one loop per choice, so the
//!    compiled code grows with the sum of the effects, not their product.
//! 3. **Ambient occlusion**: [`AmbientOcclusion::apply`] darkens the colour from the finished depth buffer.
//!
//! Turning an effect off by data (a white map, a black glow map, a zero-strength light, a shadow map nothing was
//! drawn into) gives the same pixels as leaving it out; `core/tests/effects.rs` proves it for each.

mod columns;
mod draw;
mod lighting;
mod lights;
mod maps;
mod material;
mod normals;
mod occlusion;
mod scratch;
mod shader;
mod shadow;
mod shadow_windows;
mod variant;
mod varyings;

pub use draw::{SurfaceDraw, draw_surface, draw_surface_unspecialised};
pub use lights::{LightKind, LightSource, LightUse, SceneLights};
pub use material::{NormalMap, NormalSpace, SurfaceMaterial};
pub use occlusion::{AmbientOcclusion, OcclusionError};
pub use shader::SurfaceShader;
pub use shadow::{
    Bounds, ShadowBias, ShadowError, ShadowMap, ShadowView, clear_shadow_depth, draw_shadow_caster,
    draw_shadow_caster_band,
};
pub use shadow_windows::{WindowRanges, window_ranges_band};
pub use variant::{NormalSource, SpecularSource, SurfaceError, SurfaceVariant};
pub use varyings::{Absent, Slot, SurfaceVaryings};
