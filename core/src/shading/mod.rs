//! Shading: how a mesh's surfaces are coloured, decided once per draw and computed only where used.
//!
//! [`draw_mesh`] draws an [`Object`] (mesh, tangents, [`Transforms`], [`ShadingModel`], [`Material`]) under
//! [`Lighting`] (ambient, directional, point and spot [`Light`]s, each with an optional shadow map). It resolves a
//! [`Variant`] once per draw, which covers every shading model: unlit (material or vertex colours), flat (light
//! once per triangle), Gouraud (once per vertex), per-pixel (Blinn-Phong, or glTF's metallic-roughness BRDF,
//! [`brdf`]), and the depth and normals views; which varyings are interpolated (the [`Layout`]); and which fragment stages run: normals (interpolated or from a tangent- or
//! object-space map), albedo (colour, vertex colours, diffuse map), each light with or without its shadow map and
//! highlights, specular colour (constant or map), glow. Its `Display` is the explanation `rastty render --explain`
//! prints.
//!
//! The pixel loop is compiled for the layout; the fragment stages run in the [`SurfaceShader`] as loops over
//! batches of fragments ([`crate::pipeline::FragmentBatch`]), one loop per choice, so the compiled code grows
//! with the sum of the choices, not their product. A firmware names the one shader its scene needs and the
//! [`capabilities`] it uses, and links nothing else.
//!
//! A frame is a sequence of passes, each run only if the scene needs it: shadow maps ([`crate::shadow`]) before,
//! [`draw_mesh`] per object, ambient occlusion ([`crate::occlusion`]) after.
//!
//! Proofs: every combination of a variant's choices gives, through [`draw_mesh`], the pixels of the general path
//! ([`crate::testing`]: one scalar shader deciding everything per fragment, through the general pixel loop) bit
//! for bit (`core/tests/specialisation.rs`); turning an effect off by data (a white map, a black glow map, a
//! zero-strength light, a shadow map nothing was drawn into) gives the pixels of leaving it out
//! (`core/tests/effects.rs`).

pub mod brdf;
pub mod capabilities;
mod coarse;
mod draw;
pub(crate) mod general;
mod light_terms;
mod lighting;
mod lights;
mod maps;
mod material;
mod normals;
mod one_fragment;
mod scratch;
mod shader;
mod shading_model;
mod surface;
mod transforms;
mod variant;
mod varyings;
mod views;

pub use crate::light_kind::{Cone, Falloff, LightKind};
pub use draw::{Object, draw_mesh};
pub use light_terms::LightTerms;
pub use lights::{Light, LightUse, Lighting};
pub use material::{Material, NormalMap, NormalSpace};
pub use shader::SurfaceShader;
pub use shading_model::ShadingModel;
pub use transforms::Transforms;
pub(crate) use transforms::{TangentFrame, world_normal};
pub use variant::{Cutout, Layout, NormalSource, ShadingError, SpecularSource, Variant};
pub use varyings::{Absent, Slot, SurfaceVaryings};
