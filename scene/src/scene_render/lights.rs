//! A scene file's lights as the core's: colour times intensity, the direction of travel turned into the direction
//! toward the light, lights in camera space turned into the world, dark lights left out; and how lights are named
//! in messages.

use std::fmt;

use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::shading::{Cone, LightKind as CoreLightKind};

use super::lit_color;
use crate::scene_file::{LightSpace, SceneLight, SceneLightKind};

/// A light the frame uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedLight {
    /// Its place among the scene file's `[[lights]]`, from 1.
    pub number: usize,
    /// As the file gives it (for messages).
    pub source: SceneLight,
    /// Where its rays come from, as the core takes it.
    pub kind: CoreLightKind,
    /// Colour times intensity.
    pub color: Vec3,
    /// The index of its shadow pass in [`super::ScenePlan::shadow_passes`], when it casts shadows in this frame.
    pub shadow_pass: Option<usize>,
}

/// A light of the file that the frame leaves out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DroppedLight {
    /// Its place among the scene file's `[[lights]]`, from 1.
    pub number: usize,
    /// As the file gives it.
    pub source: SceneLight,
}

/// The light as the core takes it, in world space, for a frame whose camera has the view matrix `view` and the
/// eye `eye`, its colour as a draw lit in `space` takes it ([`lit_color`]) times its intensity; or `None` when it
/// sheds nothing (intensity 0 or a black colour): such a light would add zero to every pixel, so it is left out of
/// the frame rather than computed.
///
/// A light in camera space is turned into the world by the inverse of the view's rotation (its transpose: the
/// rows of a `look_at` matrix are orthonormal), and a point light's position moved by the eye.
pub fn core_light(light: &SceneLight, view: &Mat4, eye: Vec3, space: ShadingSpace) -> Option<(CoreLightKind, Vec3)> {
    let color = lit_color(light.color, space) * light.intensity;
    if color == Vec3::ZERO {
        return None;
    }
    let to_world = view.to_mat3().transpose();
    let place = |position: Vec3| match light.space {
        LightSpace::World => position,
        LightSpace::Camera => eye + to_world * position,
    };
    let turn = |direction: Vec3| match light.space {
        LightSpace::World => direction,
        LightSpace::Camera => (to_world * direction).normalize_or_zero(),
    };
    let kind = match light.kind {
        // The file gives the way the light travels; the core wants the way toward it.
        SceneLightKind::Directional { direction } => CoreLightKind::Directional { to_light: turn(-direction) },
        SceneLightKind::Point { position, falloff } => {
            CoreLightKind::Point { position: place(position), falloff: falloff.core() }
        }
        SceneLightKind::Spot { position, direction, inner, outer, falloff } => CoreLightKind::Spot {
            position: place(position),
            falloff: falloff.core(),
            cone: Cone::new(turn(direction), inner, outer),
        },
    };
    Some((kind, color))
}

/// Names a light by its place in the file and what it is: `light 2 (point at [1.2, 2.2, 1])`,
/// `light 1 (directional, travelling [-0.49, -0.81, -0.37])`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LightName<'a> {
    /// From 1.
    pub number: usize,
    /// The light.
    pub light: &'a SceneLight,
}

impl fmt::Display for LightName<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.light.kind {
            SceneLightKind::Directional { direction } => {
                write!(f, "light {} (directional, travelling {})", self.number, ShortTriple(direction))
            }
            SceneLightKind::Point { position, .. } => {
                write!(f, "light {} (point at {})", self.number, ShortTriple(position))
            }
            SceneLightKind::Spot { position, direction, .. } => write!(
                f,
                "light {} (spot at {}, pointing {})",
                self.number,
                ShortTriple(position),
                ShortTriple(direction)
            ),
        }
    }
}

/// A number in messages: at most three decimals, without trailing zeros (`1.2`, `0.737`, `-1`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShortNumber(pub f32);

impl fmt::Display for ShortNumber {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = format!("{:.3}", self.0);
        let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
        f.write_str(if text == "-0" { "0" } else { text })
    }
}

/// A vector in messages: `[x, y, z]`, each a [`ShortNumber`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShortTriple(pub Vec3);

impl fmt::Display for ShortTriple {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        write!(f, "[{}, {}, {}]", ShortNumber(v.x), ShortNumber(v.y), ShortNumber(v.z))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene_file::LightFalloff;
    use rastty_core::color::srgb_to_linear;

    fn light(kind: SceneLightKind, intensity: f32) -> SceneLight {
        SceneLight { kind, color: Vec3::new(1.0, 0.5, 0.25), intensity, shadows: false, space: LightSpace::World }
    }

    #[test]
    fn colour_times_intensity_and_the_direction_reversed() {
        let l = light(SceneLightKind::Directional { direction: -Vec3::Y }, 2.0);
        let (kind, color) = core_light(&l, &Mat4::IDENTITY, Vec3::ZERO, ShadingSpace::Encoded).unwrap();
        assert_eq!(kind, CoreLightKind::Directional { to_light: Vec3::Y });
        assert_eq!(color, Vec3::new(2.0, 1.0, 0.5));
        // In linear light the colour is decoded, the intensity not.
        let (_, color) = core_light(&l, &Mat4::IDENTITY, Vec3::ZERO, ShadingSpace::Linear).unwrap();
        assert_eq!(color, Vec3::new(2.0, 2.0 * srgb_to_linear(0.5), 2.0 * srgb_to_linear(0.25)));
        assert!((color.y - 0.428).abs() < 1e-3);
    }

    #[test]
    fn lights_in_camera_space_follow_the_camera() {
        // The eye at +x looking at the origin: the camera's z (toward the viewer) is the world's +x, its x (to the
        // right) the world's -z.
        let eye = Vec3::new(5.0, 0.0, 0.0);
        let view = rastty_core::camera::look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
        let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-6;
        let toward_viewer = SceneLight {
            space: LightSpace::Camera,
            ..light(SceneLightKind::Directional { direction: Vec3::new(0.0, 0.0, -1.0) }, 1.0)
        };
        let Some((CoreLightKind::Directional { to_light }, _)) =
            core_light(&toward_viewer, &view, eye, ShadingSpace::Encoded)
        else {
            panic!("a directional light")
        };
        assert!(close(to_light, Vec3::X), "{to_light:?}");
        let right = SceneLight {
            space: LightSpace::Camera,
            ..light(SceneLightKind::Point { position: Vec3::X, falloff: LightFalloff::None }, 1.0)
        };
        let Some((CoreLightKind::Point { position, .. }, _)) = core_light(&right, &view, eye, ShadingSpace::Encoded)
        else {
            panic!("a point light")
        };
        assert!(close(position, Vec3::new(5.0, 0.0, -1.0)), "{position:?}");
        // A spot to the right pointing away from the viewer: at world (5, 0, -1), along the world's -x, its cone
        // and fall-off kept.
        let spot = SceneLight {
            space: LightSpace::Camera,
            ..light(
                SceneLightKind::Spot {
                    position: Vec3::X,
                    direction: -Vec3::Z,
                    inner: 0.25,
                    outer: 0.5,
                    falloff: LightFalloff::InverseSquare { range: Some(3.0) },
                },
                1.0,
            )
        };
        let Some((CoreLightKind::Spot { position, falloff, cone }, _)) =
            core_light(&spot, &view, eye, ShadingSpace::Encoded)
        else {
            panic!("a spot light")
        };
        assert!(close(position, Vec3::new(5.0, 0.0, -1.0)), "{position:?}");
        assert!(close(cone.direction, -Vec3::X), "{:?}", cone.direction);
        assert_eq!(cone, Cone::new(cone.direction, 0.25, 0.5));
        assert_eq!(falloff, rastty_core::shading::Falloff::inverse_square(Some(3.0)));
    }

    #[test]
    fn dark_lights_are_left_out() {
        let (view, eye) = (Mat4::IDENTITY, Vec3::ZERO);
        assert!(
            core_light(
                &light(SceneLightKind::Point { position: Vec3::ONE, falloff: LightFalloff::None }, 0.0),
                &view,
                eye,
                ShadingSpace::Encoded
            )
            .is_none()
        );
        let black = SceneLight {
            color: Vec3::ZERO,
            ..light(SceneLightKind::Point { position: Vec3::ONE, falloff: LightFalloff::None }, 1.0)
        };
        assert!(core_light(&black, &view, eye, ShadingSpace::Encoded).is_none());
    }

    #[test]
    fn names_give_the_place_and_the_kind() {
        let l = light(SceneLightKind::Point { position: Vec3::new(1.2, 2.2, 1.0), falloff: LightFalloff::None }, 1.0);
        assert_eq!(LightName { number: 2, light: &l }.to_string(), "light 2 (point at [1.2, 2.2, 1])");
        let spot = SceneLightKind::Spot {
            position: Vec3::Y,
            direction: -Vec3::Y,
            inner: 0.0,
            outer: 0.5,
            falloff: LightFalloff::None,
        };
        assert_eq!(
            LightName { number: 1, light: &light(spot, 1.0) }.to_string(),
            "light 1 (spot at [0, 1, 0], pointing [0, -1, 0])"
        );
        assert_eq!(ShortNumber(-0.0001).to_string(), "0");
        assert_eq!(ShortNumber(0.73751).to_string(), "0.738");
        assert_eq!(ShortNumber(100.0).to_string(), "100");
    }
}
