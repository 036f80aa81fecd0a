//! 3x3 matrix: linear maps of directions and the normal matrix.

use core::ops::Mul;

use super::Vec3;

/// A 3x3 `f32` matrix acting on column vectors (`m * v`), stored as three columns.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Mat3 {
    /// The columns: `cols[j]` is the image of the j-th unit axis.
    pub cols: [Vec3; 3],
}

impl Mat3 {
    /// The identity.
    pub const IDENTITY: Self = Self::from_cols(Vec3::X, Vec3::Y, Vec3::Z);

    /// Builds a matrix from its columns.
    #[inline(always)]
    pub const fn from_cols(c0: Vec3, c1: Vec3, c2: Vec3) -> Self {
        Self { cols: [c0, c1, c2] }
    }

    /// A diagonal (scaling) matrix.
    #[inline]
    pub const fn from_diagonal(d: Vec3) -> Self {
        Self::from_cols(Vec3::new(d.x, 0.0, 0.0), Vec3::new(0.0, d.y, 0.0), Vec3::new(0.0, 0.0, d.z))
    }

    /// Row `i` as a vector.
    #[inline(always)]
    pub fn row(&self, i: usize) -> Vec3 {
        let [a, b, c] = self.cols;
        match i {
            0 => Vec3::new(a.x, b.x, c.x),
            1 => Vec3::new(a.y, b.y, c.y),
            _ => Vec3::new(a.z, b.z, c.z),
        }
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Self::from_cols(self.row(0), self.row(1), self.row(2))
    }

    /// The determinant (the scalar triple product of the columns).
    #[must_use]
    pub fn determinant(&self) -> f32 {
        let [a, b, c] = self.cols;
        a.dot(b.cross(c))
    }

    /// The cofactor matrix, `det(M) * inverse(M)^T`, computed without dividing, so it exists for singular
    /// matrices too.
    ///
    /// For any `a`, `b`: `(M a) x (M b) == cofactor(M) (a x b)` — it maps cross products, and so surface normals,
    /// exactly as the matrix maps the surface.
    pub fn cofactor(&self) -> Self {
        let [a, b, c] = self.cols;
        Self::from_cols(b.cross(c), c.cross(a), a.cross(b))
    }

    /// The inverse, or `None` when the matrix is singular (determinant zero) or the result is not finite.
    #[must_use]
    pub fn inverse(&self) -> Option<Self> {
        let det = self.determinant();
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inv = self.cofactor().transpose() * (1.0 / det);
        inv.is_finite().then_some(inv)
    }

    /// The matrix for transforming surface normals: the cofactor matrix, negated when `M` mirrors (negative
    /// determinant) so that outward normals stay outward. Defined for singular matrices as well.
    ///
    /// Normals transformed this way are not unit length; normalise after transforming.
    pub fn normal_matrix(&self) -> Self {
        let cof = self.cofactor();
        if self.determinant() < 0.0 { cof * -1.0 } else { cof }
    }

    /// True when every element is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.cols.iter().all(|c| c.is_finite())
    }
}

impl Default for Mat3 {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Mul<Vec3> for Mat3 {
    type Output = Vec3;
    #[inline(always)]
    fn mul(self, v: Vec3) -> Vec3 {
        self.cols[0] * v.x + self.cols[1] * v.y + self.cols[2] * v.z
    }
}

impl Mul for Mat3 {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::from_cols(self * o.cols[0], self * o.cols[1], self * o.cols[2])
    }
}

impl Mul<f32> for Mat3 {
    type Output = Self;
    fn mul(self, s: f32) -> Self {
        Self::from_cols(self.cols[0] * s, self.cols[1] * s, self.cols[2] * s)
    }
}
