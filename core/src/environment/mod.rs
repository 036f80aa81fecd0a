//! Light from every direction: an environment, and what glTF's metallic-roughness model reflects of it
//! (image-based lighting).
//!
//! An environment starts as a [`Panorama`] (an equirectangular image, or the built-in [`studio`]). It is made
//! ready once, into buffers the caller owns:
//! - its diffuse light, the [`Irradiance`] (nine numbers);
//! - its specular light, a [`PanoramaChain`] whose level `i` of `n` is the light averaged over the GGX lobe of
//!   roughness `i / (n - 1)` ([`prefilter_rows`], from a chain of the panorama's levels of detail, [`reduce`]);
//! - the [`SplitSum`] table.
//!
//! [`Environment::reflected`] then lights a surface with them as the Khronos glTF sample viewer does: the split-sum
//! approximation (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013) with the energy that single scattering
//! loses given back (Fdez-Agüera, "A Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting",
//! JCGT 2019), so that a white surface under a uniform white environment reflects exactly what it receives.

pub mod chain;
mod irradiance;
pub mod panorama;
mod prefilter;
pub mod sampling;
mod split_sum;
pub mod studio;

pub use chain::{PanoramaChain, reduce};
pub use irradiance::Irradiance;
pub use panorama::{Panorama, PanoramaError};
pub use prefilter::{Prefiltering, detail_levels, fill_levels_of_detail, prefilter, prefilter_rows, prepare};
pub use split_sum::SplitSum;

use crate::math::{Vec3, float};
use crate::shading::brdf::{MIN_N_DOT_V, MetallicRoughness};
use sampling::reflect;

/// An environment ready to light surfaces: its diffuse and specular light and the split-sum table, borrowed,
/// turned about the vertical axis.
#[derive(Clone, Copy, Debug)]
pub struct Environment<'a> {
    irradiance: Irradiance,
    specular: PanoramaChain<'a>,
    split_sum: &'a SplitSum,
    /// The turn's cosine and sine.
    turn: (f32, f32),
}

impl<'a> Environment<'a> {
    /// An environment of diffuse light `irradiance`, specular light `specular` (level `i` of `n` prefiltered for
    /// roughness `i / (n - 1)`) and the table `split_sum`, not turned.
    #[must_use]
    pub fn new(irradiance: Irradiance, specular: PanoramaChain<'a>, split_sum: &'a SplitSum) -> Self {
        Self { irradiance, specular, split_sum, turn: (1.0, 0.0) }
    }

    /// The same environment turned by `angle` radians about `+y`, counter-clockwise seen from above: what was
    /// seen along `-z` is then seen along `(-sin angle, 0, -cos angle)`.
    #[must_use]
    pub fn turned(self, angle: f32) -> Self {
        Self { turn: (float::cos(angle), float::sin(angle)), ..self }
    }

    /// The world direction `d` in the environment's own frame (the turn undone).
    #[inline(always)]
    fn own(&self, d: Vec3) -> Vec3 {
        let (c, s) = self.turn;
        Vec3::new(c * d.x - s * d.z, d.y, s * d.x + c * d.z)
    }

    /// The light arriving from the world direction `d`, as sharp as the specular light's first level holds it
    /// (what a background shows).
    pub fn radiance(&self, d: Vec3) -> Vec3 {
        self.specular.level(0).sample(self.own(d))
    }

    /// The light `surface` reflects toward the unit vector `v` (toward the eye) at a point of unit normal `n`:
    /// `FssEss L_r + (FmsEms + k_D) E`, with `L_r` the specular light in the mirror direction at the surface's
    /// roughness (blended between levels), `E` the irradiance over pi at `n`, `(A, B)` the split-sum table at `n .
    /// v` (raised to [`MIN_N_DOT_V`]) and roughness, and (Fdez-Agüera 2019, eqs. 11, 13-16, the roughness-dependent
    /// Fresnel of its listing 2):
    /// - `k_S = F0 + (max(1 - roughness, F0) - F0) (1 - n.v)^5`, `FssEss = k_S A + B`;
    /// - `Ems = 1 - (A + B)`, `F_avg = F0 + (1 - F0) / 21`, `FmsEms = Ems FssEss F_avg / (1 - F_avg Ems)`;
    /// - `k_D = c_diff (1 - FssEss - FmsEms)`.
    ///
    /// Roughness is clamped to `[0, 1]` here, not raised to [`crate::shading::brdf::MIN_ROUGHNESS`]: at 0 a metal
    /// is a mirror of the environment's first level.
    pub fn reflected(&self, surface: &MetallicRoughness, n: Vec3, v: Vec3) -> Vec3 {
        let roughness = float::clamp(surface.roughness, 0.0, 1.0);
        let n_dot_v = float::clamp(n.dot(v), MIN_N_DOT_V, 1.0);
        let (f0, diffuse) = (surface.f0(), surface.diffuse_color());
        let (a, b) = self.split_sum.at(n_dot_v, roughness);
        let c = 1.0 - n_dot_v;
        let fresnel = (Vec3::splat(1.0 - roughness).max(f0) - f0) * (c * c * c * c * c);
        let single = (f0 + fresnel) * a + Vec3::splat(b);
        let lost = 1.0 - (a + b);
        let average = f0 + (Vec3::ONE - f0) * (1.0 / 21.0);
        let multiple =
            (single * lost).mul_elem(average).mul_elem((Vec3::ONE - average * lost).map(|x| 1.0 / float::max(x, 1e-6)));
        let k_diffuse = diffuse.mul_elem(Vec3::ONE - single - multiple);
        let lod = roughness * (self.specular.levels() - 1) as f32;
        let specular = self.specular.sample(self.own(reflect(v, n)), lod);
        let irradiance = self.irradiance.at(self.own(n));
        single.mul_elem(specular) + (multiple + k_diffuse).mul_elem(irradiance)
    }
}
