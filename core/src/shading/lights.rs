//! The lights of a draw: directional and point lights, each with an optional shadow map.

use crate::color::ShadingSpace;
use crate::light_kind::LightKind;
use crate::math::Vec3;
use crate::shadow::ShadowMap;

/// One light of a scene.
#[derive(Clone, Copy, Debug)]
pub struct Light<'a> {
    /// Directional or point.
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

    /// A point light at `position`, without shadows.
    pub fn point(position: Vec3, color: Vec3) -> Self {
        Self { kind: LightKind::Point { position }, color, shadow: None }
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
    /// Linear light (sRGB-correct) or the stored codes as they are: how every draw under this lighting combines
    /// colours with light ([`ShadingSpace`]).
    pub space: ShadingSpace,
}

/// What choosing a draw's stages needs to know of a light: whether it is a point light, and the filter radius of
/// its shadow map if it has one. [`super::Variant::resolve`] takes these, so a draw can be planned before
/// any shadow map exists.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightUse {
    /// A point light (else directional).
    pub point: bool,
    /// The percentage-closer filter radius of its shadow map, if it casts shadows.
    pub shadow_pcf: Option<u32>,
}

impl From<&Light<'_>> for LightUse {
    fn from(light: &Light<'_>) -> Self {
        Self {
            point: matches!(light.kind, LightKind::Point { .. }),
            shadow_pcf: light.shadow.as_ref().map(|s| s.pcf_radius()),
        }
    }
}
