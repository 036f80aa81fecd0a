//! Barycentric weights per pixel, perspective-correct or affine, chosen once per draw.
//!
//! The rasterizer hands over each covered pixel's three edge-function values `e_k` (proportional to the
//! screen-space barycentric coordinates) and an interpolator turns them into the weights `(w1, w2)` of vertices 1
//! and 2 for [`super::Varyings::interpolate`].

use super::Interpolation;
use super::slopes::FractionSteps;

/// Turns a pixel's edge-function values into varying weights.
pub(crate) trait Interpolator: Copy {
    /// Per-triangle constants.
    type Setup: Copy;
    /// The interpolator of a draw that interpolates in `mode` (which only the general path's reads).
    fn new(mode: Interpolation) -> Self;
    /// Prepares a triangle from its vertices' `1/w` and the reciprocal of its doubled screen area.
    fn setup(&self, inv_w: [f32; 3], inv_area: f32) -> Self::Setup;
    /// The weights of vertices 1 and 2 at a pixel with edge-function values `e`, as fractions `[n1, n2, d]`: the
    /// weights are `n1 * (1 / d)` and `n2 * (1 / d)`. Split so that a batch of pixels can do its divisions at once
    /// (see [`super::FragmentBatch`]).
    fn fractions(&self, setup: &Self::Setup, e: [f32; 3]) -> [f32; 3];
    /// How the fractions change when the edge-function values change by `step` (they are linear in them, the
    /// denominator of affine weights constant).
    fn fraction_step(&self, setup: &Self::Setup, step: [f32; 3]) -> [f32; 3];

    /// The fractions' steps one pixel right and one down, for edge-function steps `[x, y]` ([`super::edges::Edges::steps`]).
    #[inline(always)]
    fn fraction_steps(&self, setup: &Self::Setup, [x, y]: [[f32; 3]; 2]) -> FractionSteps {
        FractionSteps { dx: self.fraction_step(setup, x), dy: self.fraction_step(setup, y) }
    }
}

/// Perspective-correct: `w_k = (e_k / w_k) / sum_j (e_j / w_j)` (Heckbert and Moreton, "Interpolation for
/// Polygon Texture Mapping and Shading", 1991). One division per pixel.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PerspectiveCorrect;

impl Interpolator for PerspectiveCorrect {
    type Setup = [f32; 3];

    #[inline(always)]
    fn new(_: Interpolation) -> Self {
        Self
    }

    #[inline(always)]
    fn setup(&self, inv_w: [f32; 3], _: f32) -> [f32; 3] {
        // Only the ratios matter: scale so the largest is 1, which keeps the per-pixel sum away from underflow.
        let r = 1.0 / crate::math::float::max(inv_w[0], crate::math::float::max(inv_w[1], inv_w[2]));
        [inv_w[0] * r, inv_w[1] * r, inv_w[2] * r]
    }

    #[inline(always)]
    fn fractions(&self, q: &[f32; 3], e: [f32; 3]) -> [f32; 3] {
        let (l0, l1, l2) = (e[0] * q[0], e[1] * q[1], e[2] * q[2]);
        [l1, l2, l0 + l1 + l2]
    }

    #[inline(always)]
    fn fraction_step(&self, q: &[f32; 3], step: [f32; 3]) -> [f32; 3] {
        self.fractions(q, step)
    }
}

/// Affine (screen-space linear): `w_k = e_k / area`. No division per pixel.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Affine;

impl Interpolator for Affine {
    type Setup = f32;

    #[inline(always)]
    fn new(_: Interpolation) -> Self {
        Self
    }

    #[inline(always)]
    fn setup(&self, _: [f32; 3], inv_area: f32) -> f32 {
        inv_area
    }

    #[inline(always)]
    fn fractions(&self, inv_area: &f32, e: [f32; 3]) -> [f32; 3] {
        [e[1] * inv_area, e[2] * inv_area, 1.0]
    }

    #[inline(always)]
    fn fraction_step(&self, inv_area: &f32, step: [f32; 3]) -> [f32; 3] {
        [step[1] * inv_area, step[2] * inv_area, 0.0]
    }
}

/// Either of the above, decided per pixel: the general path that the specialised ones are tested against.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DynamicInterpolator(pub Interpolation);

impl Interpolator for DynamicInterpolator {
    type Setup = ([f32; 3], f32);

    #[inline(always)]
    fn new(mode: Interpolation) -> Self {
        Self(mode)
    }

    #[inline(always)]
    fn setup(&self, inv_w: [f32; 3], inv_area: f32) -> Self::Setup {
        (PerspectiveCorrect.setup(inv_w, inv_area), Affine.setup(inv_w, inv_area))
    }

    #[inline(always)]
    fn fractions(&self, setup: &Self::Setup, e: [f32; 3]) -> [f32; 3] {
        match self.0 {
            Interpolation::PerspectiveCorrect => PerspectiveCorrect.fractions(&setup.0, e),
            Interpolation::Affine => Affine.fractions(&setup.1, e),
        }
    }

    #[inline(always)]
    fn fraction_step(&self, setup: &Self::Setup, step: [f32; 3]) -> [f32; 3] {
        match self.0 {
            Interpolation::PerspectiveCorrect => PerspectiveCorrect.fraction_step(&setup.0, step),
            Interpolation::Affine => Affine.fraction_step(&setup.1, step),
        }
    }
}
