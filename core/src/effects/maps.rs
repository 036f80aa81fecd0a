//! Colour maps over a batch: albedo, specular colour and glow, each one loop per filter and wrap mode.

use super::columns::{Column2, Column3};
use super::scratch::Scratch;
use crate::color::unpack_rgb888;
use crate::math::Vec3;
use crate::pipeline::BATCH_SIZE;
use crate::texture::{Filter, Texture, Wrap};

/// Calls `$f::<F, W>($args)` with the filter and wrap types of run-time modes `$filter` and `$wrap`: one
/// decision per batch, then a loop compiled for that sampler.
macro_rules! with_sampler {
    ($filter:expr, $wrap:expr, $f:ident($($arg:expr),* $(,)?)) => {{
        use $crate::texture::{Bilinear, Clamp, FilterMode, Nearest, Repeat, WrapMode};
        match ($filter, $wrap) {
            (FilterMode::Nearest, WrapMode::Repeat) => $f::<Nearest, Repeat>($($arg),*),
            (FilterMode::Nearest, WrapMode::Clamp) => $f::<Nearest, Clamp>($($arg),*),
            (FilterMode::Bilinear, WrapMode::Repeat) => $f::<Bilinear, Repeat>($($arg),*),
            (FilterMode::Bilinear, WrapMode::Clamp) => $f::<Bilinear, Clamp>($($arg),*),
        }
    }};
}
pub(crate) use with_sampler;

/// Albedo: `color` times the diffuse map.
pub(crate) fn albedo<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>, color: Vec3) {
    modulated::<F, W>(&mut s.albedo, &s.uv, map, Some(color));
}

/// Specular colour: `specular` times the specular map.
pub(crate) fn specular_color<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>, specular: Vec3) {
    modulated::<F, W>(&mut s.specular_color, &s.uv, map, Some(specular));
}

/// Emission: the glow map.
pub(crate) fn glow<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>) {
    modulated::<F, W>(&mut s.emission, &s.uv, map, None);
}

/// The map at every lane's texture coordinates, times `color` if given, into `out`.
#[allow(clippy::needless_range_loop)] // lanes: one index into every column
#[inline(always)]
fn modulated<F: Filter, W: Wrap>(out: &mut Column3, uv: &Column2, map: &Texture<'_>, color: Option<Vec3>) {
    let mut texels = [0; BATCH_SIZE];
    F::sample_packed_lanes::<W, BATCH_SIZE>(map, &uv.x, &uv.y, &mut texels);
    match color {
        // `color.mul_elem(texel)`, lane by lane.
        Some(color) => {
            for i in 0..BATCH_SIZE {
                let c = unpack_rgb888(texels[i]);
                out.x[i] = color.x * c.x;
                out.y[i] = color.y * c.y;
                out.z[i] = color.z * c.z;
            }
        }
        None => {
            for i in 0..BATCH_SIZE {
                out.set(i, unpack_rgb888(texels[i]));
            }
        }
    }
}
