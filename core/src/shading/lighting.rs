//! Light over a batch: ambient, Lambert diffuse and Blinn-Phong highlights from each light, or glTF's
//! metallic-roughness BRDF, times the share of it that its shadow map lets through.
//!
//! Each light is a few passes over the batch's columns, chosen per light and batch: the direction to the light
//! (constant, or one per fragment for a point light), the share of it that arrives (shadow lookups only for a light
//! with a shadow map), the diffuse term, and the highlight only when the material has one. The passes are
//! lane-wise loops ([`super::columns`]), except the shadow lookups, which read the map fragment by fragment.

use super::brdf::MetallicRoughness;
use super::capabilities::{self, has};
use super::scratch::Scratch;
use super::{Cone, Falloff, Light, LightKind, Lighting};
use crate::environment::Environment;
use crate::math::Vec3;
use crate::math::float::{self, Exponent};
use crate::pipeline::columns::{self, Column, Column3};
use crate::pipeline::lanes;

/// Fills `s.diffuse` (and `s.specular` when `specular`) with the light arriving at each fragment: the ambient
/// light (`s.ambient` when `occluded`, else the lights' own), then each light's.
///
/// Per light: `color * max(0, n . l) * shadow` to the diffuse light and, with `specular`,
/// `color * max(0, n . h)^shininess * shadow` to the specular light where `n . l > 0` (Blinn, "Models of light
/// reflection for computer synthesized pictures", SIGGRAPH 1977).
/// Point lights and shadow maps only where `CAPS` holds them ([`super::capabilities`]): a shader compiled without
/// them has had its variant checked to use none.
pub(crate) fn light<const CAPS: u32>(
    s: &mut Scratch,
    lights: &Lighting<'_>,
    eye: Vec3,
    shininess: Exponent,
    specular: bool,
    occluded: bool,
) {
    let len = s.len;
    s.diffuse = if occluded { s.ambient } else { Column3::splat(lights.ambient) };
    if specular {
        s.specular = Column3::ZERO;
        // The direction to the eye, once for every light.
        s.view = Column3::toward(eye, &s.world, len);
        s.view.normalize(len);
    }
    for light in lights.lights {
        let (to_light, n_dot_l, shares) = toward_light::<CAPS>(s, light);
        // max(0, n . l) times the share: the diffuse factor.
        let mut arriving = Column::ZERO;
        for i in 0..lanes(len) {
            arriving[i] = float::max(n_dot_l[i], 0.0);
        }
        if let Some(shares) = &shares {
            for i in 0..lanes(len) {
                arriving[i] *= shares[i];
            }
        }
        s.diffuse.add_scaled(light.color, &arriving, len);
        if specular {
            let shares = shares.as_ref();
            highlight(s.len, &s.shading, &s.view, &to_light, &n_dot_l, shares, light.color, shininess, &mut s.specular);
        }
    }
}

/// The light a metallic-roughness draw reflects besides its lights': the ambient light, scaled by the occlusion
/// map's share in `s.ambient` when `occluded`, and the environment's, if it reads one (scaled alike).
#[derive(Clone, Copy)]
pub(crate) struct Indirect<'a> {
    pub occluded: bool,
    pub environment: Option<&'a Environment<'a>>,
}

/// Fills `s.diffuse` with the light each fragment reflects under glTF's metallic-roughness model, its base colour
/// `s.albedo`, its metallic factor and roughness `surface`, fragment by fragment in scalar maths:
/// - the ambient light reflected by the diffuse lobe ([`MetallicRoughness::ambient`]) and the environment's
///   ([`Environment::reflected`]), each times the occlusion map's share when `indirect` says so;
/// - each light's ([`MetallicRoughness::lit_by`], times the share that arrives and that its shadow map lets
///   through).
pub(crate) fn light_metallic_roughness<const CAPS: u32>(
    s: &mut Scratch,
    lights: &Lighting<'_>,
    eye: Vec3,
    [metallic, roughness]: &[Column; 2],
    indirect: Indirect<'_>,
) {
    let len = s.len;
    let surface = |s: &Scratch, i: usize| MetallicRoughness {
        base_color: s.albedo.get(i),
        metallic: metallic[i],
        roughness: roughness[i],
    };
    let environment = indirect.environment.filter(|_| has(CAPS, capabilities::METALLIC_ROUGHNESS));
    if environment.is_some() || !lights.lights.is_empty() {
        s.view = Column3::toward(eye, &s.world, len);
        s.view.normalize(len);
    }
    for i in 0..lanes(len) {
        let surface = surface(s, i);
        let mut reflected = surface.ambient(lights.ambient);
        if let Some(environment) = environment {
            reflected += environment.reflected(&surface, s.shading.get(i), s.view.get(i));
        }
        if indirect.occluded {
            reflected = reflected.mul_elem(s.ambient.get(i));
        }
        s.diffuse.set(i, reflected);
    }
    for light in lights.lights {
        let (to_light, _, shares) = toward_light::<CAPS>(s, light);
        for i in 0..lanes(len) {
            let share = shares.as_ref().map_or(1.0, |shares| shares[i]);
            let lit = surface(s, i).lit_by(s.shading.get(i), s.view.get(i), to_light.get(i), light.color, share);
            s.diffuse.set(i, s.diffuse.get(i) + lit);
        }
    }
}

/// The direction toward `light` from each fragment, `n . l` with the shading normal, and the share of the light's
/// colour arriving (`None`: all of it): the share that reaches the point (a light that weakens with distance or has
/// a cone) times the share its shadow map lets through (a light with one). Point lights and shadow maps only where
/// `CAPS` holds them.
#[inline(always)]
fn toward_light<const CAPS: u32>(s: &Scratch, light: &Light<'_>) -> (Column3, Column, Option<Column>) {
    let len = s.len;
    // The direction toward the light and, for a light that weakens with distance or has a cone, the share of its
    // colour arriving: as `LightKind::toward` computes it, lane by lane.
    let (to_light, reaching) = match light.kind {
        LightKind::Directional { to_light } => (Column3::splat(to_light), None),
        LightKind::Point { position, falloff } if has(CAPS, capabilities::POINT_LIGHTS) => {
            toward(s, position, falloff, None)
        }
        LightKind::Spot { position, falloff, cone } if has(CAPS, capabilities::POINT_LIGHTS) => {
            toward(s, position, falloff, Some(cone))
        }
        LightKind::Point { .. } | LightKind::Spot { .. } => (Column3::ZERO, None),
    };
    let mut n_dot_l = Column::ZERO;
    s.shading.dot(&to_light, &mut n_dot_l, len);
    // The share of the light its shadow map lets through, if it has one.
    let shadowed = light.shadow.as_ref().filter(|_| has(CAPS, capabilities::SHADOWS)).map(|map| {
        let mut n_dot_geometric = Column::ZERO;
        s.geometric.dot(&to_light, &mut n_dot_geometric, len);
        let mut shares = Column::ZERO;
        map.light_reaching_lanes(&s.world, &s.geometric, &n_dot_geometric, len, &mut shares);
        shares
    });
    // What arrives of the light: the share reaching the point times the share its shadow lets through.
    let shares = match (reaching, shadowed) {
        (Some(mut reaching), Some(shadowed)) => {
            for i in 0..lanes(len) {
                reaching[i] *= shadowed[i];
            }
            Some(reaching)
        }
        (reaching, shadowed) => reaching.or(shadowed),
    };
    (to_light, n_dot_l, shares)
}

/// Adds `color * max(0, n . h)^shininess * share` to `specular` where `n . l > 0`, with `h` the unit half vector
/// of `l` and the view direction `v`, and `share` 1 without `shares`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn highlight(
    len: usize,
    n: &Column3,
    v: &Column3,
    l: &Column3,
    n_dot_l: &Column,
    shares: Option<&Column>,
    color: Vec3,
    shininess: Exponent,
    specular: &mut Column3,
) {
    let mut h = Column3::ZERO;
    for i in 0..lanes(len) {
        h.x[i] = l.x[i] + v.x[i];
        h.y[i] = l.y[i] + v.y[i];
        h.z[i] = l.z[i] + v.z[i];
    }
    h.normalize(len);
    let mut n_dot_h = Column::ZERO;
    n.dot(&h, &mut n_dot_h, len);
    // Into a new column, not in place: `x = max(x, 0)` in place compiled to masked stores (`vmaskmovps`), slow on
    // some x86 processors.
    let mut k = Column::ZERO;
    for i in 0..lanes(len) {
        k[i] = float::max(n_dot_h[i], 0.0);
    }
    columns::pow_lanes(&mut k, shininess, len);
    if let Some(shares) = shares {
        for i in 0..lanes(len) {
            k[i] *= shares[i];
        }
    }
    // Adding +0.0 where unlit leaves the sum as it was (it starts at +0.0 and never holds -0.0). The +0.0 comes
    // from clearing the bits under a mask, not from a select: LLVM turned "add this or 0.0" into two masked
    // stores (`vmaskmovps`, slow on x86 processors) for some channels; an `and` it keeps as one.
    for i in 0..lanes(len) {
        let mask = 0u32.wrapping_sub(u32::from(n_dot_l[i] > 0.0));
        let lit = |v: f32| f32::from_bits(v.to_bits() & mask);
        specular.x[i] += lit(color.x * k[i]);
        specular.y[i] += lit(color.y * k[i]);
        specular.z[i] += lit(color.z * k[i]);
    }
}

/// The unit directions from the batch's points toward a light at `position`, and the share of its colour arriving
/// at each (`None`: all of it): [`LightKind::toward`] lane by lane, the same operations in the same order.
#[inline(always)]
fn toward(s: &Scratch, position: Vec3, falloff: Falloff, cone: Option<Cone>) -> (Column3, Option<Column>) {
    let len = s.len;
    let mut l = Column3::toward(position, &s.world, len);
    let mut squared = Column::ZERO;
    if falloff != Falloff::None {
        l.dot(&l, &mut squared, len);
    }
    l.normalize(len);
    let mut share = Column::ZERO;
    match (falloff, cone) {
        (Falloff::None, None) => return (l, None),
        (Falloff::None, Some(cone)) => {
            for i in 0..lanes(len) {
                share[i] = cone.at(l.get(i));
            }
        }
        (falloff, None) => {
            for i in 0..lanes(len) {
                share[i] = falloff.at(squared[i]);
            }
        }
        (falloff, Some(cone)) => {
            for i in 0..lanes(len) {
                share[i] = falloff.at(squared[i]) * cone.at(l.get(i));
            }
        }
    }
    (l, Some(share))
}
