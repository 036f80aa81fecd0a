//! Light at one point, in scalar maths: what flat shading computes once per triangle (at its centroid, with its
//! face normal) and Gouraud shading once per vertex, under the same lights as per-pixel lighting.

use super::{Lighting, SpecularSource, Transforms, Variant, world_normal};
#[cfg(doc)]
use crate::light_kind::LightKind;
use crate::math::{Vec3, float};
use crate::mesh::Mesh;

/// The light terms of one point, before the surface colour is applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightTerms {
    /// Ambient + diffuse, multiplied by the surface colour.
    pub diffuse: Vec3,
    /// Specular, multiplied by the specular colour.
    pub specular: Vec3,
}

/// The light arriving at `point` on a surface with unit normal `n`: ambient plus each light's
/// `color * max(0, n . l) * share`, and with `specular` each light's Blinn-Phong highlight
/// `color * max(0, n . h)^shininess * share` where `n . l > 0` (Blinn, SIGGRAPH 1977). `l` points toward the light
/// (the same for every point under a directional light), `h` is the unit half vector of `l` and the direction to
/// `eye`, and `share` what arrives of a light that weakens with distance or has a cone ([`LightKind::toward`]).
/// Shadow maps are not read: shadows are computed per pixel.
#[inline(always)]
pub(crate) fn light_at(
    lights: &Lighting<'_>,
    n: Vec3,
    point: Vec3,
    eye: Vec3,
    shininess: f32,
    specular: bool,
) -> LightTerms {
    let mut terms = LightTerms { diffuse: lights.ambient, specular: Vec3::ZERO };
    let to_eye = if specular { (eye - point).normalize_or_zero() } else { Vec3::ZERO };
    for light in lights.lights {
        let (to_light, share) = light.kind.toward(point);
        let n_dot_l = n.dot(to_light);
        let arriving = float::max(n_dot_l, 0.0);
        terms.diffuse += light.color * share.map_or(arriving, |s| arriving * s);
        if specular && n_dot_l > 0.0 {
            let h = (to_light + to_eye).normalize_or_zero();
            let k = float::pow(float::max(n.dot(h), 0.0), shininess);
            terms.specular += light.color * share.map_or(k, |s| k * s);
        }
    }
    terms
}

/// Gouraud shading's light at vertex `i` of `mesh` drawn with `variant`: [`light_at`] with the vertex's world
/// normal, at its world position where a point light or the highlight needs it. A non-finite normal takes the
/// diffuse light's place, so that the pipeline skips its triangle: the light alone would hide it (`max(NaN, 0)`
/// is 0) and draw the triangle unlit.
#[inline(always)]
pub(crate) fn vertex_light(
    t: &Transforms,
    lights: &Lighting<'_>,
    shininess: f32,
    variant: &Variant,
    mesh: &Mesh<'_>,
    i: usize,
) -> LightTerms {
    let n = world_normal(&t.normal, mesh.normal(i));
    let highlights = variant.specular != SpecularSource::None;
    let point =
        if highlights || variant.point_lights > 0 { t.model.transform_point(mesh.position(i)) } else { Vec3::ZERO };
    let light = light_at(lights, n, point, t.eye, shininess, highlights);
    LightTerms { diffuse: if n.is_finite() { light.diffuse } else { n }, specular: light.specular }
}

/// Flat shading's light for the triangle `[a, b, c]` of `mesh` drawn with `variant`: [`light_at`] with the face
/// normal (through the normal matrix), at the world centroid where a point light or the highlight needs it.
#[inline(always)]
pub(crate) fn face_light(
    t: &Transforms,
    lights: &Lighting<'_>,
    shininess: f32,
    variant: &Variant,
    mesh: &Mesh<'_>,
    [a, b, c]: [usize; 3],
) -> LightTerms {
    let (p0, p1, p2) = (mesh.position(a), mesh.position(b), mesh.position(c));
    let n = (t.normal * (p1 - p0).cross(p2 - p0)).normalize_or_zero();
    let highlights = variant.specular != SpecularSource::None;
    let centroid = if highlights || variant.point_lights > 0 {
        t.model.transform_point((p0 + p1 + p2) * (1.0 / 3.0))
    } else {
        Vec3::ZERO
    };
    light_at(lights, n, centroid, t.eye, shininess, highlights)
}
