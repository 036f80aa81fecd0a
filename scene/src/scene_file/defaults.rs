//! What a scene has when its file (or a model shown without one) leaves it out: the viewer's look.

use rastty_core::math::Vec3;

use super::loaded::{SceneLight, SceneLightKind};
use super::schema::LightSpace;

/// The background, a dark blue-grey (`#16191f`).
pub const BACKGROUND: Vec3 = Vec3::new(22.0 / 255.0, 25.0 / 255.0, 31.0 / 255.0);
/// The ambient light.
pub const AMBIENT: Vec3 = Vec3::new(0.14, 0.14, 0.16);
/// The specular colour of a material that gives none.
pub const SPECULAR: Vec3 = Vec3::new(0.22, 0.22, 0.22);
/// A spot light's inner cone angle when its table gives none, in degrees (`KHR_lights_punctual`'s default).
pub const SPOT_INNER_DEGREES: f32 = 0.0;
/// A spot light's outer cone angle when its table gives none, in degrees (`KHR_lights_punctual`'s pi / 4).
pub const SPOT_OUTER_DEGREES: f32 = 45.0;
/// The Blinn-Phong exponent of a material that gives none.
pub const SHININESS: f32 = 28.0;

/// The metallic factor of a part whose file and scene give none: a dielectric.
pub const METALLIC: f32 = 0.0;

/// The roughness of a part whose file and scene give none: the roughest.
pub const ROUGHNESS: f32 = 1.0;

/// The viewer's lights (`viewer_lights = true`, and every model shown without a scene file), in camera space so
/// that they follow the camera: a warm key light from the upper left and a cool fill light from the right,
/// without shadows.
pub const VIEWER_LIGHTS: [SceneLight; 2] = [
    SceneLight {
        // Travelling from the upper left, in front of the model, toward it: toward the light is
        // (-0.445435, 0.668153, 0.596559), a unit vector.
        kind: SceneLightKind::Directional { direction: Vec3::new(0.445_435, -0.668_153, -0.596_559) },
        color: Vec3::new(0.9, 0.87, 0.8),
        intensity: 1.0,
        shadows: false,
        space: LightSpace::Camera,
    },
    SceneLight {
        // From the right, in front: toward the light is (0.882353, 0, 0.470588), a unit vector.
        kind: SceneLightKind::Directional { direction: Vec3::new(-0.882_353, 0.0, -0.470_588) },
        color: Vec3::new(0.18, 0.2, 0.26),
        intensity: 1.0,
        shadows: false,
        space: LightSpace::Camera,
    },
];
