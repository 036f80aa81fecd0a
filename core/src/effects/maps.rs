//! Colour maps over a batch: albedo, specular colour and glow, each one loop per filter and wrap mode.

use super::scratch::Scratch;
use crate::math::Vec3;
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
    for (a, uv) in s.albedo[..s.len].iter_mut().zip(&s.uv) {
        *a = color.mul_elem(map.sample::<F, W>(*uv));
    }
}

/// Specular colour: `specular` times the specular map.
pub(crate) fn specular_color<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>, specular: Vec3) {
    for (c, uv) in s.specular_color[..s.len].iter_mut().zip(&s.uv) {
        *c = specular.mul_elem(map.sample::<F, W>(*uv));
    }
}

/// Emission: the glow map.
pub(crate) fn glow<F: Filter, W: Wrap>(s: &mut Scratch, map: &Texture<'_>) {
    for (e, uv) in s.emission[..s.len].iter_mut().zip(&s.uv) {
        *e = map.sample::<F, W>(*uv);
    }
}
