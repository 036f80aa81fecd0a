//! A scene file's lights as the core's: colour times intensity, the direction of travel turned into the direction
//! toward the light, dark lights left out; and how lights are named in messages.

use std::fmt;

use rastty_core::effects::LightKind as CoreLightKind;
use rastty_core::math::Vec3;

use crate::scene_file::{LightKind, SceneLight};

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

/// The light as the core takes it, or `None` when it sheds nothing (intensity 0 or a black colour): such a light
/// would add zero to every pixel, so it is left out of the frame rather than computed.
pub fn core_light(light: &SceneLight) -> Option<(CoreLightKind, Vec3)> {
    let color = light.color * light.intensity;
    if color == Vec3::ZERO {
        return None;
    }
    let kind = match light.kind {
        // The file gives the way the light travels; the core wants the way toward it.
        LightKind::Directional { direction } => CoreLightKind::Directional { to_light: -direction },
        LightKind::Point { position } => CoreLightKind::Point { position },
    };
    Some((kind, color))
}

/// Names a light by its place in the file and what it is: `light 2 (point at [1.2, 2.2, 1])`,
/// `light 1 (directional, travelling [-0.49, -0.81, -0.37])`.
#[derive(Clone, Copy, Debug)]
pub struct LightName<'a> {
    /// From 1.
    pub number: usize,
    /// The light.
    pub light: &'a SceneLight,
}

impl fmt::Display for LightName<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.light.kind {
            LightKind::Directional { direction } => {
                write!(f, "light {} (directional, travelling {})", self.number, Triple(direction))
            }
            LightKind::Point { position } => write!(f, "light {} (point at {})", self.number, Triple(position)),
        }
    }
}

/// A number in messages: at most three decimals, without trailing zeros (`1.2`, `0.737`, `-1`).
#[derive(Clone, Copy, Debug)]
pub struct Number(pub f32);

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = format!("{:.3}", self.0);
        let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
        f.write_str(if text == "-0" { "0" } else { text })
    }
}

/// A vector in messages: `[x, y, z]`, each a [`Number`].
#[derive(Clone, Copy, Debug)]
pub struct Triple(pub Vec3);

impl fmt::Display for Triple {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        write!(f, "[{}, {}, {}]", Number(v.x), Number(v.y), Number(v.z))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light(kind: LightKind, intensity: f32) -> SceneLight {
        SceneLight { kind, color: Vec3::new(1.0, 0.5, 0.25), intensity, shadows: false }
    }

    #[test]
    fn colour_times_intensity_and_the_direction_reversed() {
        let l = light(LightKind::Directional { direction: -Vec3::Y }, 2.0);
        let (kind, color) = core_light(&l).unwrap();
        assert_eq!(kind, CoreLightKind::Directional { to_light: Vec3::Y });
        assert_eq!(color, Vec3::new(2.0, 1.0, 0.5));
    }

    #[test]
    fn dark_lights_are_left_out() {
        assert!(core_light(&light(LightKind::Point { position: Vec3::ONE }, 0.0)).is_none());
        let black = SceneLight { color: Vec3::ZERO, ..light(LightKind::Point { position: Vec3::ONE }, 1.0) };
        assert!(core_light(&black).is_none());
    }

    #[test]
    fn names_give_the_place_and_the_kind() {
        let l = light(LightKind::Point { position: Vec3::new(1.2, 2.2, 1.0) }, 1.0);
        assert_eq!(LightName { number: 2, light: &l }.to_string(), "light 2 (point at [1.2, 2.2, 1])");
        assert_eq!(Number(-0.0001).to_string(), "0");
        assert_eq!(Number(0.73751).to_string(), "0.738");
        assert_eq!(Number(100.0).to_string(), "100");
    }
}
