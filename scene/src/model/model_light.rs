//! A light a model file gives (glTF's `KHR_lights_punctual`, placed by its node), as a scene light.

use std::f32::consts::PI;

use rastty_core::color::linear_to_srgb;
use rastty_core::math::{Mat4, Vec3};

use crate::scene_file::{LightFalloff, LightSpace, SceneLight, SceneLightKind};

/// A light of a glTF file: what it is, and its node's world transform in the model's pose (moved by
/// [`super::Model::pose`] when an animation moves the node). Directional and spot lights shine down their node's
/// `-z` (`KHR_lights_punctual`).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelLight {
    /// Its name in the file, raw (escape before printing), or `None`.
    pub name: Option<String>,
    /// Its node's index in the file.
    pub node: usize,
    /// Its node's world transform, in the model's current pose.
    pub world: Mat4,
    /// Directional, point or spot.
    pub kind: ModelLightKind,
    /// Its linear colour (components not negative).
    pub color: Vec3,
    /// Lux for a directional light, candela for point and spot lights (not negative).
    pub intensity: f32,
    /// Where a point or spot light ends (positive), or `None`: nowhere.
    pub range: Option<f32>,
}

/// The kind of a glTF light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ModelLightKind {
    /// Parallel rays along the node's `-z`.
    Directional,
    /// Rays in every direction from the node's origin.
    Point,
    /// Rays within a cone around the node's `-z`.
    Spot {
        /// `innerConeAngle`, radians, from 0 and below `outer`.
        inner: f32,
        /// `outerConeAngle`, radians, at most pi / 2.
        outer: f32,
    },
}

impl ModelLight {
    /// Its name for messages: its own, or "light N" (N from 0, its place among the model's lights).
    pub fn label(&self, index: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("light {index}"))
    }

    /// What it is, for listings: `directional`, `point` or `spot`.
    pub fn kind_name(&self) -> &'static str {
        match self.kind {
            ModelLightKind::Directional => "directional",
            ModelLightKind::Point => "point",
            ModelLightKind::Spot { .. } => "spot",
        }
    }

    /// The light in the world of an object placed by `object_transform`, lighting as glTF viewers do.
    ///
    /// - The intensity is divided by pi: glTF's diffuse reflection is the Lambert BRDF `albedo / pi` times the
    ///   light arriving (glTF 2.0, appendix B; the Khronos sample viewer), where rastty's is `albedo` times it.
    /// - Point and spot lights weaken with the inverse square of the distance, ending at the range.
    /// - A uniform scale `s` of the object scales a range by `s` and an intensity by `s²`, so that the object
    ///   fitted to the view is lit as the file lights it at its own size (the scale of the light's own nodes does
    ///   not count, as the extension says).
    ///
    /// The colour, linear in the file, is encoded to sRGB as a scene light holds it (and decoded again when lit in
    /// linear light).
    ///
    /// `None` when the transforms leave the light no place, or a directional or spot light no direction.
    pub fn scene_light(&self, object_transform: &Mat4) -> Option<SceneLight> {
        let m = *object_transform * self.world;
        let position = m.transform_point(Vec3::ZERO);
        let direction = || m.transform_vector(-Vec3::Z).try_normalize();
        // The object's scale: the cube root of its volume scale, exact for the uniform scale of a fit.
        let scale = object_transform.to_mat3().determinant().abs().cbrt();
        if !(position.is_finite() && scale.is_finite() && scale > 0.0) {
            return None;
        }
        let falloff = LightFalloff::InverseSquare { range: self.range.map(|r| r * scale) };
        let squared = self.intensity * scale * scale;
        let (kind, intensity) = match self.kind {
            ModelLightKind::Directional => (SceneLightKind::Directional { direction: direction()? }, self.intensity),
            ModelLightKind::Point => (SceneLightKind::Point { position, falloff }, squared),
            ModelLightKind::Spot { inner, outer } => {
                (SceneLightKind::Spot { position, direction: direction()?, inner, outer, falloff }, squared)
            }
        };
        let color = self.color.map(linear_to_srgb);
        Some(SceneLight { kind, color, intensity: intensity / PI, shadows: false, space: LightSpace::World })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light(kind: ModelLightKind, world: Mat4) -> ModelLight {
        let color = Vec3::new(1.0, 0.5, 0.25);
        ModelLight { name: None, node: 0, world, kind, color, intensity: 3.0, range: Some(2.0) }
    }

    #[test]
    fn a_fitted_point_light_keeps_the_light_its_surfaces_receive() {
        // A light 4 units above the origin, the object halved and moved: the light is 2 units above the moved
        // origin, its range 1, its intensity a quarter, so that 3 / 4^2 in the file is 0.75 / 2^2 fitted.
        let up = Mat4::from_translation(Vec3::new(0.0, 4.0, 0.0));
        let fit = Mat4::from_translation(Vec3::X) * Mat4::from_scale(Vec3::splat(0.5));
        let l = light(ModelLightKind::Point, up).scene_light(&fit).unwrap();
        let SceneLightKind::Point { position, falloff } = l.kind else { panic!("a point light") };
        assert_eq!(position, Vec3::new(1.0, 2.0, 0.0));
        assert_eq!(falloff, LightFalloff::InverseSquare { range: Some(1.0) });
        assert_eq!(l.intensity, 0.75 / PI);
        let decoded = l.color.map(rastty_core::color::srgb_to_linear);
        assert!((decoded - Vec3::new(1.0, 0.5, 0.25)).length() < 1e-6, "{decoded:?}");
    }

    #[test]
    fn directional_and_spot_lights_shine_down_their_nodes_minus_z() {
        // Turned a quarter about -x, -z becomes -y: pointing down.
        let turned = Mat4::from_axis_angle(-Vec3::X, std::f32::consts::FRAC_PI_2);
        let sun = light(ModelLightKind::Directional, turned).scene_light(&Mat4::IDENTITY).unwrap();
        let SceneLightKind::Directional { direction } = sun.kind else { panic!("a directional light") };
        assert!((direction - -Vec3::Y).length() < 1e-6, "{direction:?}");
        assert_eq!(sun.intensity, 3.0 / PI);
        let spot = light(ModelLightKind::Spot { inner: 0.1, outer: 0.6 }, turned).scene_light(&Mat4::IDENTITY).unwrap();
        let SceneLightKind::Spot { direction, inner, outer, .. } = spot.kind else { panic!("a spot light") };
        assert!((direction - -Vec3::Y).length() < 1e-6, "{direction:?}");
        assert_eq!((inner, outer), (0.1, 0.6));
        // A node scaled to nothing leaves a spot no direction; a point light needs none.
        let flat = Mat4::from_scale(Vec3::ZERO);
        assert!(light(ModelLightKind::Spot { inner: 0.1, outer: 0.6 }, flat).scene_light(&Mat4::IDENTITY).is_none());
        assert!(light(ModelLightKind::Point, flat).scene_light(&Mat4::IDENTITY).is_some());
    }
}
