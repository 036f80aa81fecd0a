//! Shading: lights, materials, the shader family, and mesh draws that compile to exactly the effects a scene uses.
//!
//! | model | lit where | varyings (besides texture coordinates) |
//! |---|---|---|
//! | [`UnlitShader`] | nowhere | none |
//! | [`VertexColorShader`] | nowhere | colour |
//! | [`FlatShader`] | once per triangle ([`Shader::face`](crate::pipeline::Shader::face)) | none |
//! | [`GouraudShader`] | per vertex | diffuse light, specular light (with highlights) |
//! | [`PhongShader`] | per pixel | normal, world position (with highlights) |
//! | [`DepthShader`] | — | none (reads the fragment depth) |
//! | [`NormalShader`] | — | normal |
//!
//! Each is generic over a [`TextureStage`] ([`Untextured`] or [`Textured`] with a filter and wrap mode) and the
//! lit ones over [`Highlights`]. [`draw_mesh`] picks the combination a scene needs from its [`Effects`], once per
//! draw; [`draw_mesh_unspecialised`] runs the same draw through [`GeneralShader`], which branches instead, and
//! must give the same pixels.

mod debug_views;
mod draw_mesh;
mod effects;
mod flat;
mod general;
mod gouraud;
mod highlights;
mod light;
mod phong;
mod surface;
mod texture_stage;
mod transforms;
mod unlit;

pub use debug_views::{DepthShader, NormalShader};
pub use draw_mesh::{draw_mesh, draw_mesh_unspecialised};
pub use effects::{Effects, ShadingModel, TextureBinding, Variant};
pub use flat::FlatShader;
pub use general::{GeneralShader, GeneralVaryings};
pub use gouraud::GouraudShader;
pub use highlights::{Highlights, NoSpecular, Specular};
pub use light::{Light, LightTerms, Lighting, Material};
pub use phong::PhongShader;
pub use surface::Surface;
pub(crate) use surface::world_normal;
pub use texture_stage::{TextureStage, Textured, Untextured};
pub use transforms::Transforms;
pub use unlit::{UnlitShader, VertexColorShader};
