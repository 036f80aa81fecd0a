//! Effects a scene may call for, computed only when it does: material maps (diffuse, tangent- or object-space
//! normal, specular, glow), directional and point lights, shadow maps, and screen-space ambient occlusion.
//!
//! A frame with effects is a sequence of passes, each run only if the scene needs it:
//!
//! 1. **Shadow passes** ([`crate::shadow`]), one per shadow-casting light: [`crate::shadow::ShadowView::fit`]
//!    frames the scene from the light, and [`crate::shadow::draw_shadow_caster`] draws every object's depth into a
//!    buffer the caller owns. For a filtered map, [`crate::shadow::window_ranges_band`] then records each filter
//!    window's nearest and farthest depth, so that most lookups read one value instead of the whole window.
//! 2. **Forward pass**: [`draw_surface`] per object. [`SurfaceVariant::resolve`] decides, once per draw, which
//!    varyings are interpolated (world position, texture coordinates, tangents) and which fragment stages run:
//!    normals (interpolated or from a map), albedo, lights (each with or without its shadow map and
//!    highlights), specular colour, glow. The pixel loop is compiled for the varyings; the fragment stages run as
//!    loops over batches of up to [`crate::pipeline::BATCH_SIZE`] fragments, one loop per choice, so the
//!    compiled code grows with the sum of the effects, not their product.
//! 3. **Ambient occlusion** ([`crate::occlusion`]): [`crate::occlusion::AmbientOcclusion::apply`] darkens the colour from the finished depth buffer.
//!
//! Turning an effect off by data (a white map, a black glow map, a zero-strength light, a shadow map nothing was
//! drawn into) gives the same pixels as leaving it out; `core/tests/effects.rs` proves it for each.

pub mod capabilities;
mod coarse;
pub(crate) mod columns;
mod draw;
mod light_terms;
mod lighting;
mod lights;
mod maps;
mod material;
mod normals;
mod scratch;
mod shader;
mod variant;
mod varyings;
mod views;

pub use draw::{SurfaceDraw, draw_surface, draw_surface_unspecialised};
pub use lights::{LightKind, LightSource, LightUse, SceneLights};
pub use material::{NormalMap, NormalSpace, SurfaceMaterial};
pub use shader::SurfaceShader;
pub use variant::{Layout, NormalSource, SpecularSource, SurfaceError, SurfaceVariant};
pub use varyings::{Absent, Slot, SurfaceVaryings};
