//! The debugging views over a batch: the depth buffer as grey levels, world normals as colours.

use crate::math::{Vec3, float};
use crate::pipeline::BATCH_SIZE;
use crate::pipeline::columns::{Column, Column3};

/// Grey levels from the fragments' NDC depths: `near` white, `far` black, clamped between.
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
pub(crate) fn depth(depths: &Column, len: usize, near: f32, far: f32, colors: &mut [Vec3; BATCH_SIZE]) {
    let scale = 1.0 / (far - near);
    let scale = if scale.is_finite() { scale } else { 0.0 };
    for i in 0..len {
        colors[i] = Vec3::splat(1.0 - float::clamp((depths[i] - near) * scale, 0.0, 1.0));
    }
}

/// The interpolated world normals `n`, normalised, as colours: `n * 0.5 + 0.5`.
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
pub(crate) fn normals(mut n: Column3, len: usize, colors: &mut [Vec3; BATCH_SIZE]) {
    n.normalize(len);
    for i in 0..len {
        colors[i] = n.get(i) * 0.5 + Vec3::splat(0.5);
    }
}
