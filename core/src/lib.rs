//! rastty-core: a software rasterizer for any machine, from a desktop to a microcontroller.
//!
//! `#![no_std]`, no allocation, no `unsafe`, one dependency (`libm`). It renders into buffers the caller owns —
//! a whole frame or one band of rows at a time — and computes the same pixels on every target, because all
//! floating-point functions go through `libm` rather than the platform's maths library.
//!
//! # From mesh to pixel
//!
//! | stage | module | what happens |
//! |---|---|---|
//! | mesh | [`mesh`] | borrowed positions, normals, UVs, colours, `u16`/`u32` indices |
//! | camera | [`camera`] | look-at, perspective or orthographic projection, viewport |
//! | vertex stage | [`pipeline::Shader::position`] | object space to clip space and the screen (once per vertex into [`target::Target::with_vertex_memory`], once a frame for every band ([`target::FrameGeometry`]), else through a small cache) |
//! | clip | [`pipeline`] (`clip.rs`) | near/far planes and a guard band, in homogeneous coordinates |
//! | raster | [`pipeline`] (`raster.rs`) | fixed-point snapping, exact edge functions, top-left rule |
//! | vertex stage | [`pipeline::Shader::varyings`] | per-vertex values, only for triangles that reach the pixel loop or need clipping |
//! | fragment | [`pipeline::FragmentBatch`], [`shading`], [`texture`] | depth test, then the fragments in batches across triangles: interpolation, shading, texturing |
//! | target | [`target`] | RGB888 or RGB565 colour, `f32` or `u16` depth, whole frames or bands, one or four samples per pixel (multisample anti-aliasing); optional memory for screen positions |
//!
//! [`draw_mesh`] draws an [`Object`] under [`Lighting`]: it resolves the [`shading::Variant`] the object and the
//! lights call for, once per draw, and runs the pipeline compiled for exactly that (see [`shading`]). Shadow maps
//! ([`shadow`]) and ambient occlusion ([`occlusion`]) are passes of their own; an [`environment`] lights
//! metallic-roughness surfaces from every direction. [`pipeline::draw`] runs a
//! [`pipeline::Shader`] of your own: the low-level way in. A frame drawn band by band (through one small buffer, or
//! on threads) bins its triangles once ([`pipeline::BandBins`]) and lends the bins to each band's target
//! ([`target::FrameGeometry`]).
//!
//! A model that moves is posed first, into the caller's buffers ([`animation`]: keyframes, node transforms, morph
//! targets, skins), and then drawn as any mesh.
//!
//! The crate root re-exports what a typical draw needs, so one `use` line does.
//!
//! # Example
//! ```
//! use rastty_core::*;
//!
//! // One triangle facing the camera.
//! let positions = [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
//! let normals = [Vec3::Z; 3];
//! let mesh = Mesh::new(&positions, Indices::Sequential).unwrap().with_normals(&normals).unwrap();
//!
//! let view = look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
//! let projection = perspective(1.0, 1.0, 0.1, 10.0).unwrap();
//! let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
//! let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::Phong, material: Material::default() };
//! let sun = [Light::directional(Vec3::Z, Vec3::ONE)];
//! let lights = Lighting { ambient: Vec3::splat(0.1), lights: &sun, environment: None, space: ShadingSpace::Linear };
//!
//! let (mut color, mut depth) = ([0u32; 32 * 32], [0f32; 32 * 32]);
//! let mut target = Target::new(Rgb888(&mut color), &mut depth[..], 32, 32).unwrap();
//! target.clear(Vec3::ZERO);
//! let (_, stats) = draw_mesh(&mut target, &object, &lights, &DrawState::default()).unwrap();
//! assert_eq!(stats.rasterized, 1);
//! // (0.1 ambient + 1.0 diffuse) * 0.8 = 0.88 in linear light, sRGB code 241.
//! assert_eq!(color[16 * 32 + 16], 0x00F1F1F1);
//! ```

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]
#![warn(clippy::std_instead_of_core)]

pub mod animation;
pub mod camera;
pub mod color;
pub mod environment;
mod light_kind;
pub mod math;
pub mod mesh;
pub mod occlusion;
pub mod pipeline;
pub mod shading;
pub mod shadow;
pub mod target;
#[doc(hidden)]
pub mod testing;
pub mod texture;

pub use camera::{CameraError, look_at, orthographic, perspective};
pub use color::ShadingSpace;
pub use math::{Mat3, Mat4, Quat, Vec2, Vec3, Vec4};
pub use mesh::{Indices, Mesh, MeshError};
pub use pipeline::{DrawError, DrawState, DrawStats};
pub use shading::{
    Cone, Falloff, Light, LightKind, Lighting, Material, Object, ShadingError, ShadingModel, Transforms, draw_mesh,
};
pub use target::{Rgb565, Rgb888, Target, TargetError};
pub use texture::{FilterMode, Texture, WrapMode};
