//! Lights, materials and the Blinn-Phong reflection model.

use crate::math::{Vec3, float};

/// A directional light, like the sun: parallel rays arriving from `to_light`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Unit vector from the surface toward the light, in world space.
    pub to_light: Vec3,
    /// Colour and intensity.
    pub color: Vec3,
}

impl Light {
    /// A light shining from `to_light` (normalised here; a zero vector gives a light that adds nothing).
    pub fn directional(to_light: Vec3, color: Vec3) -> Self {
        Self { to_light: to_light.normalize_or_zero(), color }
    }
}

/// The lights of a scene: an ambient term and any number of directional lights, borrowed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting<'a> {
    /// Light reaching every surface from every direction.
    pub ambient: Vec3,
    /// Directional lights.
    pub lights: &'a [Light],
}

impl Lighting<'_> {
    /// Ambient plus Lambertian diffuse light arriving at a surface with unit normal `n`:
    /// `ambient + sum(color * max(0, n . l))`.
    #[inline(always)]
    pub fn diffuse(&self, n: Vec3) -> Vec3 {
        let mut sum = self.ambient;
        for light in self.lights {
            sum += light.color * float::max(n.dot(light.to_light), 0.0);
        }
        sum
    }

    /// Blinn-Phong specular light at a surface with unit normal `n` seen along unit `to_eye`:
    /// `sum(color * max(0, n . h)^shininess)` over the lights in front of the surface, `h` the half vector
    /// (Blinn, "Models of light reflection for computer synthesized pictures", SIGGRAPH 1977).
    #[inline(always)]
    pub fn specular(&self, n: Vec3, to_eye: Vec3, shininess: f32) -> Vec3 {
        let mut sum = Vec3::ZERO;
        for light in self.lights {
            if n.dot(light.to_light) > 0.0 {
                let h = (light.to_light + to_eye).normalize_or_zero();
                sum += light.color * float::pow(float::max(n.dot(h), 0.0), shininess);
            }
        }
        sum
    }
}

/// How a surface reflects light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Diffuse (base) colour; multiplied by the texture when there is one.
    pub color: Vec3,
    /// Specular colour; zero turns highlights off, and the draw then compiles without them.
    pub specular: Vec3,
    /// Blinn-Phong exponent: larger is a smaller, sharper highlight.
    pub shininess: f32,
}

impl Material {
    /// True when the material has a specular highlight to compute.
    pub fn has_specular(&self) -> bool {
        self.specular != Vec3::ZERO
    }
}

impl Default for Material {
    fn default() -> Self {
        Self { color: Vec3::splat(0.8), specular: Vec3::ZERO, shininess: 32.0 }
    }
}

/// The light terms of one point, before the surface colour is applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightTerms {
    /// Ambient + diffuse, multiplied by the surface colour.
    pub diffuse: Vec3,
    /// Specular, multiplied by the specular colour.
    pub specular: Vec3,
}

impl LightTerms {
    /// The final colour: `albedo * diffuse + specular_color * specular`.
    #[inline(always)]
    pub fn shade(&self, albedo: Vec3, specular_color: Vec3) -> Vec3 {
        albedo.mul_elem(self.diffuse) + specular_color.mul_elem(self.specular)
    }
}
