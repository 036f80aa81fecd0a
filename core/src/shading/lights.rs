//! The lights of a draw: directional, point and spot lights, each with an optional shadow map.

use crate::color::ShadingSpace;
use crate::environment::Environment;
#[cfg(doc)]
use crate::light_kind::Falloff;
use crate::light_kind::LightKind;
use crate::math::Vec3;
use crate::shadow::ShadowMap;

/// One light of a scene.
#[derive(Clone, Copy, Debug)]
pub struct Light<'a> {
    /// Directional, point or spot, and how its light weakens.
    pub kind: LightKind,
    /// Colour times intensity.
    pub color: Vec3,
    /// Its shadow map, when it casts shadows.
    pub shadow: Option<ShadowMap<'a>>,
}

impl Light<'_> {
    /// A directional light shining from `to_light` (normalised here), without shadows.
    pub fn directional(to_light: Vec3, color: Vec3) -> Self {
        Self { kind: LightKind::Directional { to_light: to_light.normalize_or_zero() }, color, shadow: None }
    }

    /// A point light at `position` that does not weaken with distance ([`Falloff::None`]), without shadows.
    pub fn point(position: Vec3, color: Vec3) -> Self {
        Self { kind: LightKind::point(position), color, shadow: None }
    }
}

/// The light a scene sheds: an ambient term and any number of lights, borrowed, and the space surfaces are lit
/// in.
#[derive(Clone, Copy, Debug)]
pub struct Lighting<'a> {
    /// Light reaching every surface from every direction (linear light in [`ShadingSpace::Linear`], like the
    /// lights' colours).
    pub ambient: Vec3,
    /// The lights.
    pub lights: &'a [Light<'a>],
    /// Light from every direction, which the metallic-roughness model reflects (the other models read
    /// `ambient` alone).
    pub environment: Option<&'a Environment<'a>>,
    /// Linear light (sRGB-correct) or the stored codes as they are: how every draw under this lighting combines
    /// colours with light ([`ShadingSpace`]).
    pub space: ShadingSpace,
}

/// What choosing a draw's stages needs to know of a light: whether it is a point or spot light or an environment,
/// and the filter radius of its shadow map if it has one. [`super::Variant::resolve`] takes these, so a draw can be planned before
/// any shadow map exists.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightUse {
    /// A point or spot light (else directional): one whose direction is worked out per point.
    pub point: bool,
    /// An [`Environment`]: light from every direction (then neither `point` nor a shadow map).
    pub environment: bool,
    /// The percentage-closer filter radius of its shadow map, if it casts shadows.
    pub shadow_pcf: Option<u32>,
}

impl From<&Light<'_>> for LightUse {
    fn from(light: &Light<'_>) -> Self {
        Self {
            point: light.kind.position().is_some(),
            environment: false,
            shadow_pcf: light.shadow.as_ref().map(|s| s.pcf_radius()),
        }
    }
}

impl LightUse {
    /// An environment's use.
    pub const ENVIRONMENT: Self = Self { point: false, environment: true, shadow_pcf: None };
}

impl Lighting<'_> {
    /// What choosing a draw's stages needs to know of these lights: each light's [`LightUse`], then the
    /// environment's, if there is one.
    pub fn uses(&self) -> impl Iterator<Item = LightUse> + '_ {
        self.lights.iter().map(LightUse::from).chain(self.environment.map(|_| LightUse::ENVIRONMENT))
    }
}
