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
//! | vertex stage | [`pipeline::Shader::position`] | object space to clip space (once per shared vertex) |
//! | clip | [`pipeline`] (`clip.rs`) | near/far planes and a guard band, in homogeneous coordinates |
//! | raster | [`pipeline`] (`raster.rs`) | fixed-point snapping, exact edge functions, top-left rule |
//! | vertex stage | [`pipeline::Shader::varyings`] | per-vertex values, only for triangles that reach the pixel loop or need clipping |
//! | fragment | [`pipeline::Shader::fragment`], [`shading`], [`texture`] | depth test, interpolation, shading, texturing |
//! | target | [`target`] | RGB888 or RGB565 colour, `f32` or `u16` depth, whole frames or bands |
//!
//! [`pipeline::draw`] runs a [`pipeline::Shader`] of your own; [`shading::draw_mesh`] picks one of the built-in
//! shaders for the effects a scene calls for, and compiles exactly those. [`effects`] adds material maps and point
//! lights, computed only by the draws that use them; shadow maps ([`shadow`]) and ambient occlusion ([`occlusion`])
//! are passes of their own.
//!
//! # Example
//! ```
//! use rastty_core::camera::{look_at, perspective};
//! use rastty_core::math::{Mat4, Vec3};
//! use rastty_core::mesh::{Indices, Mesh};
//! use rastty_core::pipeline::DrawState;
//! use rastty_core::shading::{draw_mesh, Effects, Light, Lighting, Material, ShadingModel, Transforms};
//! use rastty_core::target::{Rgb888, Target};
//!
//! // One triangle facing the camera.
//! let positions = [Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
//! let normals = [Vec3::Z; 3];
//! let mesh = Mesh::new(&positions, Indices::Sequential).unwrap().with_normals(&normals).unwrap();
//!
//! let view = look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
//! let projection = perspective(1.0, 1.0, 0.1, 10.0).unwrap();
//! let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
//! let lights = [Light::directional(Vec3::Z, Vec3::ONE)];
//! let effects = Effects {
//!     shading: ShadingModel::Phong,
//!     material: Material::default(),
//!     lighting: Lighting { ambient: Vec3::splat(0.1), lights: &lights },
//!     texture: None,
//! };
//!
//! let (mut color, mut depth) = ([0u32; 32 * 32], [0f32; 32 * 32]);
//! let mut target = Target::new(Rgb888(&mut color), &mut depth[..], 32, 32).unwrap();
//! target.clear(Vec3::ZERO);
//! let stats = draw_mesh(&mut target, &mesh, &transforms, &effects, &DrawState::default()).unwrap();
//! assert_eq!(stats.rasterized, 1);
//! assert_eq!(color[16 * 32 + 16], 0x00E0E0E0); // (0.1 ambient + 1.0 diffuse) * 0.8 = 0.88 -> 224
//! ```

#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]
#![warn(clippy::std_instead_of_core)]

pub mod camera;
pub mod color;
pub mod effects;
pub mod math;
pub mod mesh;
pub mod occlusion;
pub mod pipeline;
pub mod shading;
pub mod shadow;
pub mod target;
pub mod texture;
