//! Light over a batch: ambient, Lambert diffuse and Blinn-Phong highlights from each light, times the share of
//! it that its shadow map lets through. One loop per kind of light, with or without shadows and highlights,
//! chosen per light and batch.

use super::scratch::Scratch;
use super::{LightKind, SceneLights, ShadowMap};
use crate::math::{Vec3, float};

/// How much of a light reaches a point.
trait Occlusion {
    fn light_reaching(&self, p: Vec3, n: Vec3, n_dot_l: f32) -> f32;
}

/// No shadow map: all of it (a multiplication by 1, which the compiler removes).
struct Unshadowed;

impl Occlusion for Unshadowed {
    #[inline(always)]
    fn light_reaching(&self, _: Vec3, _: Vec3, _: f32) -> f32 {
        1.0
    }
}

impl Occlusion for ShadowMap<'_> {
    #[inline(always)]
    fn light_reaching(&self, p: Vec3, n: Vec3, n_dot_l: f32) -> f32 {
        ShadowMap::light_reaching(self, p, n, n_dot_l)
    }
}

/// Fills `s.diffuse` (and `s.specular` when `specular`) with the light arriving at each fragment.
pub(crate) fn light(s: &mut Scratch, lights: &SceneLights<'_>, eye: Vec3, shininess: f32, specular: bool) {
    s.diffuse[..s.len].fill(lights.ambient);
    if specular {
        s.specular[..s.len].fill(Vec3::ZERO);
    }
    for light in lights.lights {
        let color = light.color;
        match (light.kind, &light.shadow, specular) {
            (LightKind::Directional { to_light }, None, false) => {
                add::<false>(s, color, |_| to_light, &Unshadowed, eye, shininess);
            }
            (LightKind::Directional { to_light }, None, true) => {
                add::<true>(s, color, |_| to_light, &Unshadowed, eye, shininess);
            }
            (LightKind::Directional { to_light }, Some(map), false) => {
                add::<false>(s, color, |_| to_light, map, eye, shininess);
            }
            (LightKind::Directional { to_light }, Some(map), true) => {
                add::<true>(s, color, |_| to_light, map, eye, shininess);
            }
            (LightKind::Point { position }, None, false) => {
                add::<false>(s, color, |p| (position - p).normalize_or_zero(), &Unshadowed, eye, shininess);
            }
            (LightKind::Point { position }, None, true) => {
                add::<true>(s, color, |p| (position - p).normalize_or_zero(), &Unshadowed, eye, shininess);
            }
            (LightKind::Point { position }, Some(map), false) => {
                add::<false>(s, color, |p| (position - p).normalize_or_zero(), map, eye, shininess);
            }
            (LightKind::Point { position }, Some(map), true) => {
                add::<true>(s, color, |p| (position - p).normalize_or_zero(), map, eye, shininess);
            }
        }
    }
}

/// One light's contribution: `color * max(0, n . l) * shadow` to the diffuse light and, with `SPECULAR`,
/// `color * max(0, n . h)^shininess * shadow` to the specular light where `n . l > 0` (Blinn, "Models of light
/// reflection for computer synthesized pictures", SIGGRAPH 1977).
#[inline(always)]
fn add<const SPECULAR: bool>(
    s: &mut Scratch,
    color: Vec3,
    to_light: impl Fn(Vec3) -> Vec3,
    occlusion: &impl Occlusion,
    eye: Vec3,
    shininess: f32,
) {
    for i in 0..s.len {
        let (n, p) = (s.shading[i], s.world[i]);
        let l = to_light(p);
        let n_dot_l = n.dot(l);
        let g = s.geometric[i];
        let share = occlusion.light_reaching(p, g, g.dot(l));
        s.diffuse[i] += color * (float::max(n_dot_l, 0.0) * share);
        if SPECULAR && n_dot_l > 0.0 {
            let h = (l + (eye - p).normalize_or_zero()).normalize_or_zero();
            s.specular[i] += color * (float::pow(float::max(n.dot(h), 0.0), shininess) * share);
        }
    }
}
