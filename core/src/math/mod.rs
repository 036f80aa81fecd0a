//! Vectors, matrices and quaternions.
//!
//! Conventions used throughout rastty: column vectors (`m * v`), matrices stored by columns, right-handed
//! coordinates, angles in radians. All non-trivial float functions go through [`float`], which calls `libm`; code
//! outside the core that computes anything a pixel depends on should use it too.
//!
//! Every value type here is `#[must_use]`, and so is every function that returns a value (the lint below keeps it so):
//! a computed value left unused is a bug.

#![warn(clippy::must_use_candidate)]

mod bounding_sphere;
pub mod exact;
pub mod float;
mod lanes;
mod mat3;
mod mat4;
mod quat;
mod vec2;
mod vec3;
mod vec4;

pub use bounding_sphere::BoundingSphere;
pub use lanes::Lanes;
pub use mat3::Mat3;
pub use mat4::Mat4;
pub use quat::Quat;
pub use vec2::Vec2;
pub use vec3::Vec3;
pub use vec4::Vec4;
