//! Where a light's rays come from and how they weaken on the way: what shading lights a surface with and what a
//! shadow map is fitted to.

use crate::math::{Vec3, float};

/// Where a light's rays come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// Parallel rays, like the sun's.
    Directional {
        /// Unit vector from the surface toward the light, in world space.
        to_light: Vec3,
    },
    /// Rays from one point in every direction, like a bulb's.
    Point {
        /// The light's position in world space.
        position: Vec3,
        /// How its light weakens with distance.
        falloff: Falloff,
    },
    /// Rays from one point within a cone, like a stage light's.
    Spot {
        /// The light's position in world space.
        position: Vec3,
        /// How its light weakens with distance.
        falloff: Falloff,
        /// Where it shines.
        cone: Cone,
    },
}

/// How the light of a point or spot light weakens with the distance `d` from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Falloff {
    /// Not at all: `color` is what a lit surface receives at any distance (OpenGL's default attenuation, OpenGL
    /// 1.5 specification 2.14.1: constant 1, linear and quadratic 0).
    None,
    /// As the inverse square of the distance, ended smoothly at a range: `color * window / d²`, the window
    /// `clamp(1 - (d / range)^4, 0, 1)` (the attenuation `KHR_lights_punctual` recommends). `color` is then what a
    /// surface facing the light receives at distance 1.
    InverseSquare {
        /// `1 / range²`: 0 for a light without a range (the window is then 1 everywhere).
        inverse_range_squared: f32,
    },
}

impl Falloff {
    /// The inverse square, ending at `range` (none when `None`, or when not positive and finite).
    #[must_use]
    pub fn inverse_square(range: Option<f32>) -> Self {
        let inverse_range_squared = match range {
            Some(r) if r > 0.0 && r.is_finite() => 1.0 / (r * r),
            _ => 0.0,
        };
        Self::InverseSquare { inverse_range_squared }
    }

    /// The share of the light's colour that arrives at `squared_distance` from it; 1 for [`Falloff::None`].
    ///
    /// At the light itself (distance 0) the share is the window over the smallest normal `f32`: large but finite,
    /// so that it times a zero `n . l` is zero, not NaN.
    #[inline(always)]
    #[must_use]
    pub fn at(self, squared_distance: f32) -> f32 {
        match self {
            Self::None => 1.0,
            Self::InverseSquare { inverse_range_squared } => {
                let ratio = squared_distance * inverse_range_squared;
                let window = float::clamp(1.0 - ratio * ratio, 0.0, 1.0);
                window / float::max(squared_distance, f32::MIN_POSITIVE)
            }
        }
    }
}

/// The cone of a spot light: full light within the inner angle from its axis, none beyond the outer angle, and
/// between them the squared linear ramp in the angles' cosines that `KHR_lights_punctual` gives as reference
/// code (steep near the inner angle, levelling off toward the outer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// Unit vector of the axis, the way the light shines.
    pub direction: Vec3,
    /// `1 / max(0.001, cos(inner) - cos(outer))`.
    pub scale: f32,
    /// `-cos(outer) * scale`.
    pub offset: f32,
}

impl Cone {
    /// The cone around `direction` (normalised here) with full light up to `inner` radians from the axis and none
    /// beyond `outer` radians. Angles are used as given: `0 <= inner < outer <= pi / 2` is what glTF allows; an
    /// inner angle at or beyond the outer makes the cone's edge hard (the ramp is 1000 times steeper than its
    /// cosines).
    #[must_use]
    pub fn new(direction: Vec3, inner: f32, outer: f32) -> Self {
        let (cos_inner, cos_outer) = (float::cos(inner), float::cos(outer));
        let scale = 1.0 / float::max(cos_inner - cos_outer, 0.001);
        Self { direction: direction.normalize_or_zero(), scale, offset: -cos_outer * scale }
    }

    /// The share of the light reaching a point whose unit direction toward the light is `to_light`
    /// (`clamp(cos * scale + offset, 0, 1)²`, with `cos` the cosine of the angle from the axis).
    #[inline(always)]
    #[must_use]
    pub fn at(self, to_light: Vec3) -> f32 {
        let d = self.direction;
        let cos = -(d.x * to_light.x + d.y * to_light.y + d.z * to_light.z);
        let t = float::clamp(cos * self.scale + self.offset, 0.0, 1.0);
        t * t
    }
}

impl LightKind {
    /// A point light at `position` that does not weaken with distance.
    #[must_use]
    pub const fn point(position: Vec3) -> Self {
        Self::Point { position, falloff: Falloff::None }
    }

    /// Where the light's rays start: `None` for a directional light.
    #[must_use]
    pub fn position(self) -> Option<Vec3> {
        match self {
            Self::Directional { .. } => None,
            Self::Point { position, .. } | Self::Spot { position, .. } => Some(position),
        }
    }

    /// The unit direction from `point` toward the light, and the share of the light's colour that arrives there
    /// (`None`: all of it, nothing to multiply). The lanes of a batch compute the same, operation for operation
    /// ([`crate::shading`]'s per-pixel lighting).
    #[inline(always)]
    pub fn toward(self, point: Vec3) -> (Vec3, Option<f32>) {
        let (position, falloff, cone) = match self {
            Self::Directional { to_light } => return (to_light, None),
            Self::Point { position, falloff } => (position, falloff, None),
            Self::Spot { position, falloff, cone } => (position, falloff, Some(cone)),
        };
        let d = position - point;
        let to_light = d.normalize_or_zero();
        let share = match (falloff, cone) {
            (Falloff::None, None) => None,
            (Falloff::None, Some(cone)) => Some(cone.at(to_light)),
            (falloff, None) => Some(falloff.at(d.dot(d))),
            (falloff, Some(cone)) => Some(falloff.at(d.dot(d)) * cone.at(to_light)),
        };
        (to_light, share)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_square_without_range_is_one_over_distance_squared() {
        let f = Falloff::inverse_square(None);
        assert_eq!(f.at(4.0), 0.25);
        assert_eq!(f.at(1.0), 1.0);
        assert_eq!(f.at(0.0), 1.0 / f32::MIN_POSITIVE);
        assert_eq!(Falloff::None.at(100.0), 1.0);
    }

    #[test]
    fn the_range_window_ends_the_light_smoothly() {
        // Range 2: at distance 1 the window is 1 - (1/2)^4 = 15/16, at 2 and beyond 0.
        let f = Falloff::inverse_square(Some(2.0));
        assert_eq!(f.at(1.0), 15.0 / 16.0);
        assert_eq!(f.at(4.0), 0.0);
        assert_eq!(f.at(9.0), 0.0);
        // At distance sqrt(2): 1 - (2/4)^2 = 3/4, over 2.
        assert_eq!(f.at(2.0), 0.375);
        // A range that is not positive and finite is none.
        assert_eq!(Falloff::inverse_square(Some(-1.0)), Falloff::inverse_square(None));
        assert_eq!(Falloff::inverse_square(Some(f32::INFINITY)), Falloff::inverse_square(None));
    }

    #[test]
    fn a_cone_is_full_inside_dark_outside_and_a_squared_ramp_between() {
        // Inner 0, outer 60 degrees (cosine 1/2): scale 1 / (1 - 1/2) = 2, offset -1.
        let cone = Cone::new(-Vec3::Y, 0.0, core::f32::consts::FRAC_PI_3);
        assert!((cone.scale - 2.0).abs() < 1e-6 && (cone.offset + 1.0).abs() < 1e-6);
        // On the axis: a point below a light pointing down sees the light straight up.
        assert!((cone.at(Vec3::Y) - 1.0).abs() < 1e-6);
        // At 41.41 degrees (cosine 3/4): t = 3/4 * 2 - 1 = 1/2, the share 1/4.
        let cos = 0.75f32;
        let sin = (1.0 - cos * cos).sqrt();
        assert!((cone.at(Vec3::new(sin, cos, 0.0)) - 0.25).abs() < 1e-5);
        // Beyond the outer angle and behind the light: nothing.
        assert_eq!(cone.at(Vec3::new(1.0, 0.1, 0.0).normalize_or_zero()), 0.0);
        assert_eq!(cone.at(-Vec3::Y), 0.0);
    }

    #[test]
    fn toward_gives_the_direction_and_the_share() {
        let lamp = LightKind::Point { position: Vec3::new(0.0, 3.0, 0.0), falloff: Falloff::inverse_square(None) };
        let (l, share) = lamp.toward(Vec3::new(0.0, 1.0, 0.0));
        assert_eq!((l, share), (Vec3::Y, Some(0.25)));
        let plain = LightKind::point(Vec3::new(0.0, 2.0, 0.0));
        assert_eq!(plain.toward(Vec3::ZERO), (Vec3::Y, None));
        let sun = LightKind::Directional { to_light: Vec3::X };
        assert_eq!(sun.toward(Vec3::new(5.0, 5.0, 5.0)), (Vec3::X, None));
        let spot = LightKind::Spot {
            position: Vec3::new(0.0, 2.0, 0.0),
            falloff: Falloff::inverse_square(None),
            cone: Cone::new(-Vec3::Y, 0.2, 0.4),
        };
        assert_eq!(spot.toward(Vec3::ZERO), (Vec3::Y, Some(0.25)));
        assert_eq!(spot.toward(Vec3::new(5.0, 2.0, 0.0)).1, Some(0.0));
    }
}
