//! Three-component vector: positions, directions, normals and RGB colours.

use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

use super::float;

/// A 3-component `f32` vector. Also used for RGB colours, with each channel nominally in `[0, 1]`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[must_use]
pub struct Vec3 {
    /// First component (x, or red).
    pub x: f32,
    /// Second component (y, or green).
    pub y: f32,
    /// Third component (z, or blue).
    pub z: f32,
}

impl Vec3 {
    /// `(0, 0, 0)`.
    pub const ZERO: Self = Self::splat(0.0);
    /// `(1, 1, 1)`; white as a colour.
    pub const ONE: Self = Self::splat(1.0);
    /// The unit x axis.
    pub const X: Self = Self::new(1.0, 0.0, 0.0);
    /// The unit y axis.
    pub const Y: Self = Self::new(0.0, 1.0, 0.0);
    /// The unit z axis.
    pub const Z: Self = Self::new(0.0, 0.0, 1.0);

    /// Builds a vector from its components.
    #[inline(always)]
    pub const fn new(x: f32, y: f32, z: f32) -> Self {
        Self { x, y, z }
    }

    /// All three components equal to `v`.
    #[inline(always)]
    pub const fn splat(v: f32) -> Self {
        Self::new(v, v, v)
    }

    /// Dot product.
    #[inline(always)]
    #[must_use]
    pub fn dot(self, o: Self) -> f32 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product (right-handed: `X.cross(Y) == Z`).
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        Self::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    /// Euclidean length.
    #[inline(always)]
    #[must_use]
    pub fn length(self) -> f32 {
        float::sqrt(self.dot(self))
    }

    /// Unit vector in the same direction, or `None` when the length is zero or not finite.
    ///
    /// `self` times [`float::inv_sqrt`] of its squared length: every normalisation in the core, scalar or lane by
    /// lane, computes exactly this. The squared length is zero or infinite exactly where the length is (a
    /// square root neither underflows nor overflows).
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        let squared = self.dot(self);
        float::positive_finite(squared).then(|| self * float::inv_sqrt(squared))
    }

    /// The coordinate axis with the smallest absolute dot product with `self` (X for the zero vector): crossed
    /// with `self`, it gives a well-conditioned perpendicular.
    pub(crate) fn least_aligned_axis(self) -> Self {
        let (ax, ay, az) = (float::abs(self.x), float::abs(self.y), float::abs(self.z));
        if ax <= ay && ax <= az {
            Self::X
        } else if ay <= az {
            Self::Y
        } else {
            Self::Z
        }
    }

    /// Unit vector in the same direction, or zero when that does not exist (zero or non-finite length).
    #[inline]
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().unwrap_or(Self::ZERO)
    }

    /// Component-wise product (used to modulate colours).
    #[inline(always)]
    pub fn mul_elem(self, o: Self) -> Self {
        Self::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }

    /// `f` of each component (a colour's channels through a transfer function).
    #[inline(always)]
    pub fn map(self, f: impl Fn(f32) -> f32) -> Self {
        Self::new(f(self.x), f(self.y), f(self.z))
    }

    /// Component-wise minimum.
    #[inline(always)]
    pub fn min(self, o: Self) -> Self {
        Self::new(float::min(self.x, o.x), float::min(self.y, o.y), float::min(self.z, o.z))
    }

    /// Component-wise maximum.
    #[inline(always)]
    pub fn max(self, o: Self) -> Self {
        Self::new(float::max(self.x, o.x), float::max(self.y, o.y), float::max(self.z, o.z))
    }

    /// Largest component.
    #[inline(always)]
    #[must_use]
    pub fn max_elem(self) -> f32 {
        float::max(self.x, float::max(self.y, self.z))
    }

    /// Linear interpolation: `self` at `t = 0`, `o` at `t = 1`.
    #[inline(always)]
    pub fn lerp(self, o: Self, t: f32) -> Self {
        self + (o - self) * t
    }

    /// True when every component is finite (neither NaN nor infinite).
    #[inline(always)]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Extends to a [`super::Vec4`] with the given `w`.
    #[inline(always)]
    pub const fn extend(self, w: f32) -> super::Vec4 {
        super::Vec4::new(self.x, self.y, self.z, w)
    }
}

impl Add for Vec3 {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl AddAssign for Vec3 {
    #[inline(always)]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl Sub for Vec3 {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f32> for Vec3 {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: f32) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

impl Div<f32> for Vec3 {
    type Output = Self;
    #[inline(always)]
    fn div(self, s: f32) -> Self {
        Self::new(self.x / s, self.y / s, self.z / s)
    }
}

impl Neg for Vec3 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}
