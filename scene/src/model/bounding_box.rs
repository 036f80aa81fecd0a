//! Axis-aligned bounding boxes, and the transform that fits one into the unit sphere.

use rastty_core::math::{Mat4, Vec3};

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingBox {
    /// The smallest coordinates.
    pub min: Vec3,
    /// The largest coordinates.
    pub max: Vec3,
}

impl BoundingBox {
    /// The box around `points`, or `None` when there are none or any is not finite.
    pub(crate) fn from_points(points: &[Vec3]) -> Option<Self> {
        let (&first, rest) = points.split_first()?;
        let mut b = Self { min: first, max: first };
        for &p in rest {
            b.min = b.min.min(p);
            b.max = b.max.max(p);
        }
        (points.iter().all(|p| p.is_finite())).then_some(b)
    }

    /// The box around both.
    #[must_use]
    pub fn union(&self, other: &Self) -> Self {
        Self { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    /// The centre of the box.
    pub fn center(&self) -> Vec3 {
        self.min * 0.5 + self.max * 0.5
    }

    /// The extent along each axis.
    pub fn size(&self) -> Vec3 {
        self.max - self.min
    }

    /// Half the diagonal: the radius of the sphere around the box, centred at [`Self::center`]. Computed in `f64`.
    pub fn radius(&self) -> f32 {
        let s = self.size();
        let (x, y, z) = (f64::from(s.x), f64::from(s.y), f64::from(s.z));
        ((x * x + y * y + z * z).sqrt() * 0.5) as f32
    }

    /// The transform that moves the centre of the box to the origin and scales uniformly so that the box's
    /// bounding sphere ([`Self::radius`]) has radius 1. A box of zero size (a single point), or one so small for its
    /// distance from the origin that the scaled transform would overflow `f32`, is only moved.
    pub fn fit(&self) -> Mat4 {
        let radius = self.radius();
        let moved = Mat4::from_translation(-self.center());
        let scaled = Mat4::from_scale(Vec3::splat(1.0 / radius)) * moved;
        if radius > 0.0 && scaled.is_finite() { scaled } else { moved }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn box_of_points() {
        let b = BoundingBox::from_points(&[Vec3::new(1.0, -2.0, 3.0), Vec3::new(-1.0, 4.0, 0.0)]).unwrap();
        assert_eq!(b.min, Vec3::new(-1.0, -2.0, 0.0));
        assert_eq!(b.max, Vec3::new(1.0, 4.0, 3.0));
        assert_eq!(b.center(), Vec3::new(0.0, 1.0, 1.5));
        assert!(BoundingBox::from_points(&[]).is_none());
        assert!(BoundingBox::from_points(&[Vec3::ZERO, Vec3::splat(f32::NAN)]).is_none());
    }

    #[test]
    fn fit_maps_the_box_corners_onto_the_unit_sphere() {
        let b = BoundingBox { min: Vec3::new(-250.0, 0.0, 100.0), max: Vec3::new(250.0, 500.0, 300.0) };
        let m = b.fit();
        let lo = m.transform_point(b.min);
        let hi = m.transform_point(b.max);
        assert!(close(lo, -hi), "{lo:?} {hi:?}");
        assert!((hi.length() - 1.0).abs() < 1e-6);
        assert!(close(m.transform_point(b.center()), Vec3::ZERO));
    }

    #[test]
    fn a_point_is_only_centred() {
        let b = BoundingBox { min: Vec3::ONE, max: Vec3::ONE };
        assert_eq!(b.fit().transform_point(Vec3::ONE), Vec3::ZERO);
        assert_eq!(b.fit().transform_vector(Vec3::X), Vec3::X);
    }

    #[test]
    fn extreme_boxes_stay_finite() {
        let b = BoundingBox { min: Vec3::splat(-1e15), max: Vec3::splat(1e15) };
        assert!(b.fit().is_finite());
        // A box of 1e-38 at 1,574 from the origin: scaling it to radius 1 would put the origin at infinity.
        let far_speck = BoundingBox { min: Vec3::new(0.0, 1574.0, 0.0), max: Vec3::new(9e-39, 1574.0, 0.0) };
        assert_eq!(far_speck.fit(), Mat4::from_translation(-far_speck.center()));
        assert!((b.fit().transform_point(b.max).length() - 1.0).abs() < 1e-5);
    }
}
