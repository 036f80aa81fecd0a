//! Two-component vector: texture coordinates and screen positions.

use core::ops::{Add, Mul, Neg, Sub};

/// A 2-component `f32` vector.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[must_use]
pub struct Vec2 {
    /// First component (u, or screen x).
    pub x: f32,
    /// Second component (v, or screen y).
    pub y: f32,
}

impl Vec2 {
    /// `(0, 0)`.
    pub const ZERO: Self = Self::new(0.0, 0.0);

    /// Builds a vector from its components.
    #[inline(always)]
    pub const fn new(x: f32, y: f32) -> Self {
        Self { x, y }
    }

    /// Dot product.
    #[inline(always)]
    #[must_use]
    pub fn dot(self, o: Self) -> f32 {
        self.x * o.x + self.y * o.y
    }

    /// z component of the 3D cross product of `(self, 0)` and `(o, 0)`: twice the signed area of the triangle
    /// `(0, self, o)`.
    #[inline(always)]
    #[must_use]
    pub fn perp_dot(self, o: Self) -> f32 {
        self.x * o.y - self.y * o.x
    }

    /// True when both components are finite (neither NaN nor infinite).
    #[inline(always)]
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

impl Add for Vec2 {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y)
    }
}

impl Sub for Vec2 {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y)
    }
}

impl Mul<f32> for Vec2 {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: f32) -> Self {
        Self::new(self.x * s, self.y * s)
    }
}

impl Neg for Vec2 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y)
    }
}
