//! 4x4 matrix: affine and projective transforms of homogeneous points.

use core::ops::Mul;

use super::{Mat3, Quat, Vec3, Vec4, float};

/// A 4x4 `f32` matrix acting on column vectors (`m * v`), stored as four columns.
///
/// Conventions: column vectors, so `a * b` applies `b` first; right-handed coordinates. A translation lives in the
/// fourth column.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct Mat4 {
    /// The columns: `cols[j]` is the image of the j-th unit axis (`cols[3]` holds the translation).
    pub cols: [Vec4; 4],
}

impl Mat4 {
    /// The identity.
    pub const IDENTITY: Self = Self::from_cols(
        Vec4::new(1.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0, 0.0, 0.0),
        Vec4::new(0.0, 0.0, 1.0, 0.0),
        Vec4::new(0.0, 0.0, 0.0, 1.0),
    );

    /// Builds a matrix from its columns.
    #[inline(always)]
    pub const fn from_cols(c0: Vec4, c1: Vec4, c2: Vec4, c3: Vec4) -> Self {
        Self { cols: [c0, c1, c2, c3] }
    }

    /// Builds a matrix from its rows (convenient for writing matrices down as they appear on paper).
    pub const fn from_rows(r0: [f32; 4], r1: [f32; 4], r2: [f32; 4], r3: [f32; 4]) -> Self {
        Self::from_cols(
            Vec4::new(r0[0], r1[0], r2[0], r3[0]),
            Vec4::new(r0[1], r1[1], r2[1], r3[1]),
            Vec4::new(r0[2], r1[2], r2[2], r3[2]),
            Vec4::new(r0[3], r1[3], r2[3], r3[3]),
        )
    }

    /// A translation by `t`.
    pub const fn from_translation(t: Vec3) -> Self {
        let mut m = Self::IDENTITY;
        m.cols[3] = Vec4::new(t.x, t.y, t.z, 1.0);
        m
    }

    /// A scaling by `s` along the axes.
    pub const fn from_scale(s: Vec3) -> Self {
        Self::from_mat3(Mat3::from_diagonal(s))
    }

    /// A rotation by `angle` radians about `axis` (counter-clockwise looking down the axis toward the origin).
    /// A zero or non-finite axis gives the identity.
    pub fn from_axis_angle(axis: Vec3, angle: f32) -> Self {
        Quat::from_axis_angle(axis, angle).to_mat4()
    }

    /// Embeds a 3x3 linear map (no translation).
    pub const fn from_mat3(m: Mat3) -> Self {
        let [a, b, c] = m.cols;
        Self::from_cols(a.extend(0.0), b.extend(0.0), c.extend(0.0), Vec4::new(0.0, 0.0, 0.0, 1.0))
    }

    /// The upper-left 3x3 block (the linear part of an affine transform).
    pub const fn to_mat3(&self) -> Mat3 {
        Mat3::from_cols(self.cols[0].truncate(), self.cols[1].truncate(), self.cols[2].truncate())
    }

    /// Row `i` as a vector.
    #[inline(always)]
    pub fn row(&self, i: usize) -> Vec4 {
        let [a, b, c, d] = self.cols;
        match i {
            0 => Vec4::new(a.x, b.x, c.x, d.x),
            1 => Vec4::new(a.y, b.y, c.y, d.y),
            2 => Vec4::new(a.z, b.z, c.z, d.z),
            _ => Vec4::new(a.w, b.w, c.w, d.w),
        }
    }

    /// The bits of the sixteen elements, column by column: equal exactly when the matrices are the same bits
    /// (what a cache keyed on a matrix compares; `-0.0` and `0.0` differ, a NaN equals itself).
    #[must_use]
    pub fn to_bits(&self) -> [u32; 16] {
        let mut bits = [0; 16];
        for (b, v) in bits.iter_mut().zip(self.cols.iter().flat_map(|c| [c.x, c.y, c.z, c.w])) {
            *b = v.to_bits();
        }
        bits
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Self::from_cols(self.row(0), self.row(1), self.row(2), self.row(3))
    }

    /// The twelve 2x2 minors that the determinant and the inverse share: six from rows 0-1 and six from rows 2-3
    /// (Laplace expansion by complementary minors; Eberly, "The Laplace Expansion Theorem", 2008).
    fn minors(&self) -> ([f32; 6], [f32; 6]) {
        let [a, b, c, d] = self.cols;
        let s = [
            a.x * b.y - b.x * a.y,
            a.x * c.y - c.x * a.y,
            a.x * d.y - d.x * a.y,
            b.x * c.y - c.x * b.y,
            b.x * d.y - d.x * b.y,
            c.x * d.y - d.x * c.y,
        ];
        let t = [
            a.z * b.w - b.z * a.w,
            a.z * c.w - c.z * a.w,
            a.z * d.w - d.z * a.w,
            b.z * c.w - c.z * b.w,
            b.z * d.w - d.z * b.w,
            c.z * d.w - d.z * c.w,
        ];
        (s, t)
    }

    /// The determinant.
    #[must_use]
    pub fn determinant(&self) -> f32 {
        let (s, t) = self.minors();
        Self::determinant_from_minors(&s, &t)
    }

    fn determinant_from_minors(s: &[f32; 6], t: &[f32; 6]) -> f32 {
        s[0] * t[5] - s[1] * t[4] + s[2] * t[3] + s[3] * t[2] - s[4] * t[1] + s[5] * t[0]
    }

    /// The inverse, or `None` when the matrix is singular (determinant zero) or the result is not finite.
    #[must_use]
    pub fn inverse(&self) -> Option<Self> {
        // Adjugate from the same minors (Eberly 2008, section 2), divided by the determinant.
        let [a, b, c, d] = self.cols;
        let (s, t) = self.minors();
        let det = Self::determinant_from_minors(&s, &t);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let r = 1.0 / det;
        let inv = Self::from_rows(
            [
                (b.y * t[5] - c.y * t[4] + d.y * t[3]) * r,
                (-b.x * t[5] + c.x * t[4] - d.x * t[3]) * r,
                (b.w * s[5] - c.w * s[4] + d.w * s[3]) * r,
                (-b.z * s[5] + c.z * s[4] - d.z * s[3]) * r,
            ],
            [
                (-a.y * t[5] + c.y * t[2] - d.y * t[1]) * r,
                (a.x * t[5] - c.x * t[2] + d.x * t[1]) * r,
                (-a.w * s[5] + c.w * s[2] - d.w * s[1]) * r,
                (a.z * s[5] - c.z * s[2] + d.z * s[1]) * r,
            ],
            [
                (a.y * t[4] - b.y * t[2] + d.y * t[0]) * r,
                (-a.x * t[4] + b.x * t[2] - d.x * t[0]) * r,
                (a.w * s[4] - b.w * s[2] + d.w * s[0]) * r,
                (-a.z * s[4] + b.z * s[2] - d.z * s[0]) * r,
            ],
            [
                (-a.y * t[3] + b.y * t[1] - c.y * t[0]) * r,
                (a.x * t[3] - b.x * t[1] + c.x * t[0]) * r,
                (-a.w * s[3] + b.w * s[1] - c.w * s[0]) * r,
                (a.z * s[3] - b.z * s[1] + c.z * s[0]) * r,
            ],
        );
        inv.is_finite().then_some(inv)
    }

    /// The normal matrix of the linear part: see [`Mat3::normal_matrix`].
    pub fn normal_matrix(&self) -> Mat3 {
        self.to_mat3().normal_matrix()
    }

    /// Transforms a point (`w = 1`) and drops `w` without dividing: right for affine matrices.
    #[inline(always)]
    pub fn transform_point(&self, p: Vec3) -> Vec3 {
        (self.cols[0] * p.x + self.cols[1] * p.y + self.cols[2] * p.z + self.cols[3]).truncate()
    }

    /// Transforms a direction (`w = 0`): the translation does not apply.
    #[inline(always)]
    pub fn transform_vector(&self, v: Vec3) -> Vec3 {
        (self.cols[0] * v.x + self.cols[1] * v.y + self.cols[2] * v.z).truncate()
    }

    /// Transforms a point (`w = 1`) into homogeneous coordinates (for example into clip space).
    #[inline(always)]
    pub fn project_point(&self, p: Vec3) -> Vec4 {
        self.cols[0] * p.x + self.cols[1] * p.y + self.cols[2] * p.z + self.cols[3]
    }

    /// True when the matrix maps every point to `w = 1` (its last row is `0 0 0 1`): the transform is affine and
    /// needs no perspective division.
    #[must_use]
    pub fn is_affine(&self) -> bool {
        self.row(3) == Vec4::new(0.0, 0.0, 0.0, 1.0)
    }

    /// True when every element is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.cols.iter().all(|c| c.is_finite())
    }

    /// Largest absolute difference between corresponding elements.
    #[must_use]
    pub fn max_abs_diff(&self, o: &Self) -> f32 {
        let mut m = 0.0f32;
        for (a, b) in self.cols.iter().zip(&o.cols) {
            let d = *a - *b;
            m = float::max(
                m,
                float::max(float::max(float::abs(d.x), float::abs(d.y)), float::max(float::abs(d.z), float::abs(d.w))),
            );
        }
        m
    }
}

impl Default for Mat4 {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Mul<Vec4> for Mat4 {
    type Output = Vec4;
    #[inline(always)]
    fn mul(self, v: Vec4) -> Vec4 {
        self.cols[0] * v.x + self.cols[1] * v.y + self.cols[2] * v.z + self.cols[3] * v.w
    }
}

impl Mul for Mat4 {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::from_cols(self * o.cols[0], self * o.cols[1], self * o.cols[2], self * o.cols[3])
    }
}
