//! Directions for integrating over the sphere: the Hammersley point set and GGX importance sampling, the same
//! points on every machine.

use core::f32::consts::TAU;

use crate::math::{Vec3, float};

/// Point `i` of the `count` points of the Hammersley set in the unit square: `(i / count, radical inverse of i)`
/// (Hammersley and Handscomb, "Monte Carlo Methods", 1964; the bit-reversed form, as Karis's "Real Shading in
/// Unreal Engine 4", 2013, uses it).
#[inline(always)]
#[must_use]
pub fn hammersley(i: u32, count: u32) -> (f32, f32) {
    (i as f32 / count as f32, i.reverse_bits() as f32 * (1.0 / 4_294_967_296.0))
}

/// The microfacet normal for the point `(a, b)` of the unit square, drawn in proportion to the GGX distribution
/// of `alpha` (roughness squared) projected on the normal `n`: azimuth `2 pi a` and polar angle
/// `cos theta = sqrt((1 - b) / (1 + (alpha^2 - 1) b))` around `n` (Walter et al., "Microfacet Models for
/// Refraction through Rough Surfaces", 2007, eqs. 35-36).
#[inline(always)]
pub fn ggx_half_vector(a: f32, b: f32, alpha: f32, n: Vec3) -> Vec3 {
    let a2 = alpha * alpha;
    let cos_theta = float::sqrt((1.0 - b) / (1.0 + (a2 - 1.0) * b));
    let sin_theta = float::sqrt(float::max(1.0 - cos_theta * cos_theta, 0.0));
    let phi = TAU * a;
    let (tangent, bitangent) = basis(n);
    tangent * (sin_theta * float::cos(phi)) + bitangent * (sin_theta * float::sin(phi)) + n * cos_theta
}

/// Two unit vectors that make a right-handed orthonormal basis with the unit vector `n` (Duff et al., "Building
/// an Orthonormal Basis, Revisited", JCGT 2017, listing 3).
#[inline(always)]
pub fn basis(n: Vec3) -> (Vec3, Vec3) {
    let sign = if n.z >= 0.0 { 1.0 } else { -1.0 };
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3::new(b, sign + n.y * n.y * a, -n.y))
}

/// The mirror direction of `v` about the unit normal `h`: `2 (v . h) h - v`.
#[inline(always)]
pub fn reflect(v: Vec3, h: Vec3) -> Vec3 {
    h * (2.0 * v.dot(h)) - v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_basis_is_orthonormal() {
        for n in [Vec3::Z, -Vec3::Z, Vec3::X, Vec3::new(0.3, -0.5, 0.2).normalize_or_zero()] {
            let (t, b) = basis(n);
            for (p, q) in [(t, b), (t, n), (b, n)] {
                assert!(p.dot(q).abs() < 1e-6, "{n:?}");
            }
            assert!((t.length() - 1.0).abs() < 1e-6 && (b.length() - 1.0).abs() < 1e-6);
            assert!((t.cross(b) - n).length() < 1e-6, "{n:?}");
        }
    }

    #[test]
    fn the_points_are_the_hammersley_set() {
        assert_eq!(hammersley(0, 4), (0.0, 0.0));
        assert_eq!(hammersley(1, 4), (0.25, 0.5));
        assert_eq!(hammersley(2, 4), (0.5, 0.25));
        assert_eq!(hammersley(3, 4), (0.75, 0.75));
        // The smoothest surface samples its normal alone.
        let h = ggx_half_vector(0.3, 0.9, 0.0, Vec3::Y);
        assert!((h - Vec3::Y).length() < 1e-6, "{h:?}");
    }
}
