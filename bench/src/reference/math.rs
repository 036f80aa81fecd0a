//! The little `f64` linear algebra the reference renderer needs: 3-vectors and column-major 4x4 matrices.

use std::ops::{Add, AddAssign, Mul, Neg, Sub};

/// A column-major 4x4 matrix acting on column vectors: `m[c][r]` is row `r` of column `c`.
pub type DMat4 = [[f64; 4]; 4];

/// The identity matrix.
pub const IDENTITY: DMat4 = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

/// An `f64` 3-vector (positions, directions, colours).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct V3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl V3 {
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0);

    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z }
    }

    pub fn from_array([x, y, z]: [f64; 3]) -> Self {
        Self { x, y, z }
    }

    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    pub fn dot(self, o: Self) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    pub fn cross(self, o: Self) -> Self {
        Self::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    pub fn length(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// The unit vector in the same direction, or zero for a zero (or non-finite-length) vector. Divides (rather
    /// than multiplying by the reciprocal) so that an axis-aligned vector normalises to exactly 1.
    pub fn normalize_or_zero(self) -> Self {
        let len = self.length();
        if len > 0.0 && len.is_finite() { Self::new(self.x / len, self.y / len, self.z / len) } else { Self::ZERO }
    }

    pub fn mul_elem(self, o: Self) -> Self {
        Self::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }

    pub fn clamp01(self) -> Self {
        // NaN becomes 0.
        let c = |v: f64| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        Self::new(c(self.x), c(self.y), c(self.z))
    }

    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl Add for V3 {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl AddAssign for V3 {
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl Sub for V3 {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Neg for V3 {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for V3 {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

/// `a * b`: applies `b` first.
pub fn mul(a: &DMat4, b: &DMat4) -> DMat4 {
    let mut m = [[0.0; 4]; 4];
    for (c, col) in m.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    m
}

/// Transforms a point (`w = 1`) by an affine matrix (the bottom row is ignored).
pub(crate) fn transform_point(m: &DMat4, p: V3) -> V3 {
    V3::new(
        m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z + m[3][0],
        m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z + m[3][1],
        m[0][2] * p.x + m[1][2] * p.y + m[2][2] * p.z + m[3][2],
    )
}

/// The columns of the upper-left 3x3 block.
fn columns3(m: &DMat4) -> [V3; 3] {
    [0, 1, 2].map(|c| V3::new(m[c][0], m[c][1], m[c][2]))
}

/// Determinant of the upper-left 3x3 block.
pub(crate) fn determinant3(m: &DMat4) -> f64 {
    let [a, b, c] = columns3(m);
    a.dot(b.cross(c))
}

/// The normal matrix of the upper-left 3x3 block `M`, as the core defines it: the cofactor matrix (which maps
/// cross products as `M` maps surfaces), negated when `M` mirrors. Returned as its three columns.
pub(crate) fn normal_matrix(m: &DMat4) -> [V3; 3] {
    let [a, b, c] = columns3(m);
    let cof = [b.cross(c), c.cross(a), a.cross(b)];
    if determinant3(m) < 0.0 { cof.map(|v| -v) } else { cof }
}

/// Applies a matrix given by its columns.
pub(crate) fn apply3(cols: &[V3; 3], v: V3) -> V3 {
    cols[0] * v.x + cols[1] * v.y + cols[2] * v.z
}

/// True when every element is finite.
pub(crate) fn is_finite(m: &DMat4) -> bool {
    m.iter().flatten().all(|v| v.is_finite())
}

/// The view matrix of a camera at `eye` looking at `target`: the core's [`rastty_core::camera::look_at`] in
/// `f64`, with the same fallback when `up` is (nearly) parallel to the view direction. `None` when `eye == target`.
pub(crate) fn look_at(eye: V3, target: V3, up: V3) -> Option<DMat4> {
    let forward = (target - eye).normalize_or_zero();
    if forward == V3::ZERO {
        return None;
    }
    let r = forward.cross(up).normalize_or_zero();
    let right = if r != V3::ZERO && forward.dot(up.normalize_or_zero()).abs() < 0.999_999 {
        r
    } else {
        let (ax, ay, az) = (forward.x.abs(), forward.y.abs(), forward.z.abs());
        let axis = if ax <= ay && ax <= az {
            V3::new(1.0, 0.0, 0.0)
        } else if ay <= az {
            V3::new(0.0, 1.0, 0.0)
        } else {
            V3::new(0.0, 0.0, 1.0)
        };
        forward.cross(axis).normalize_or_zero()
    };
    let true_up = right.cross(forward);
    // Rows are the camera axes; the translation moves the eye to the origin. Stored by columns.
    Some([
        [right.x, true_up.x, -forward.x, 0.0],
        [right.y, true_up.y, -forward.y, 0.0],
        [right.z, true_up.z, -forward.z, 0.0],
        [-right.dot(eye), -true_up.dot(eye), forward.dot(eye), 1.0],
    ])
}

/// The rotation matrix of the quaternion `(x, y, z, w)` after normalising it in `f64` (the core's
/// `Quat::to_mat3`, same formula).
pub fn quaternion_matrix([x, y, z, w]: [f64; 4]) -> DMat4 {
    let n = (x * x + y * y + z * z + w * w).sqrt();
    if !(n > 0.0 && n.is_finite()) {
        return IDENTITY;
    }
    let (x, y, z, w) = (x / n, y / n, z / n, w / n);
    let (x2, y2, z2) = (x + x, y + y, z + z);
    let (xx, yy, zz) = (x * x2, y * y2, z * z2);
    let (xy, xz, yz) = (x * y2, x * z2, y * z2);
    let (wx, wy, wz) = (w * x2, w * y2, w * z2);
    [
        [1.0 - (yy + zz), xy + wz, xz - wy, 0.0],
        [xy - wz, 1.0 - (xx + zz), yz + wx, 0.0],
        [xz + wy, yz - wx, 1.0 - (xx + yy), 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// A uniform scaling.
pub fn scale(s: f64) -> DMat4 {
    [[s, 0.0, 0.0, 0.0], [0.0, s, 0.0, 0.0], [0.0, 0.0, s, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

/// A translation.
pub fn translation([x, y, z]: [f64; 3]) -> DMat4 {
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [x, y, z, 1.0]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A core matrix widened, and the largest difference from `ours`.
    fn max_difference(core: &rastty_core::math::Mat4, ours: &DMat4) -> f64 {
        let widened = core.cols.map(|c| [c.x, c.y, c.z, c.w].map(f64::from));
        widened.iter().flatten().zip(ours.iter().flatten()).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
    }

    #[test]
    fn look_at_matches_the_core() {
        use rastty_core::math::Vec3;
        let cases = [
            ([0.0, 0.0, 5.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            ([1.0, 2.0, 3.0], [-1.0, 0.5, 0.0], [0.0, 1.0, 0.0]),
            ([0.0, 4.0, 0.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ];
        for (eye, target, up) in cases {
            let v3 = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
            let core = rastty_core::camera::look_at(v3(eye), v3(target), v3(up)).unwrap();
            let ours = look_at(V3::from_array(eye), V3::from_array(target), V3::from_array(up)).unwrap();
            assert!(max_difference(&core, &ours) < 1e-6, "{eye:?}");
        }
        assert!(look_at(V3::ZERO, V3::ZERO, V3::new(0.0, 1.0, 0.0)).is_none());
    }

    #[test]
    fn quaternion_matches_the_core() {
        use rastty_core::math::{Quat, Vec3};
        let q = Quat::from_axis_angle(Vec3::X, 0.3) * Quat::from_axis_angle(Vec3::Y, 0.7);
        let core = q.to_mat4();
        let ours = quaternion_matrix([q.x, q.y, q.z, q.w].map(f64::from));
        assert!(max_difference(&core, &ours) < 1e-6);
    }

    #[test]
    fn normal_matrix_keeps_normals_outward_under_mirroring() {
        let mirror = [[-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
        let n = apply3(&normal_matrix(&mirror), V3::new(1.0, 0.0, 0.0));
        assert_eq!(n, V3::new(-1.0, 0.0, 0.0));
        assert_eq!(mul(&IDENTITY, &mirror), mirror);
    }
}
