//! Specular highlights as a compile-time choice: a material without them compiles to a shader that neither
//! carries nor computes them.

use crate::math::Vec3;
use crate::pipeline::Varyings;

/// Whether a shader computes specular highlights, and what it carries per vertex to do so.
pub trait Highlights: Copy + Default {
    /// The per-vertex value the highlight needs (a specular term, or a world position), or `()`.
    type Value: Varyings;
    /// True when highlights are computed.
    const ENABLED: bool;
    /// Computes the per-vertex value (`f` runs only when highlights are on).
    fn capture(f: impl FnOnce() -> Vec3) -> Self::Value;
    /// Adds the highlight to the lit colour (`f` turns the value into the highlight; it runs only when on).
    fn apply(lit: Vec3, value: &Self::Value, f: impl FnOnce(Vec3) -> Vec3) -> Vec3;
}

/// Blinn-Phong highlights on.
#[derive(Clone, Copy, Debug, Default)]
pub struct Specular;

impl Highlights for Specular {
    type Value = Vec3;
    const ENABLED: bool = true;
    #[inline(always)]
    fn capture(f: impl FnOnce() -> Vec3) -> Vec3 {
        f()
    }
    #[inline(always)]
    fn apply(lit: Vec3, value: &Vec3, f: impl FnOnce(Vec3) -> Vec3) -> Vec3 {
        lit + f(*value)
    }
}

/// No highlights: nothing carried, nothing computed.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSpecular;

impl Highlights for NoSpecular {
    type Value = ();
    const ENABLED: bool = false;
    #[inline(always)]
    fn capture(_: impl FnOnce() -> Vec3) {}
    #[inline(always)]
    fn apply(lit: Vec3, _: &(), _: impl FnOnce(Vec3) -> Vec3) -> Vec3 {
        lit
    }
}
