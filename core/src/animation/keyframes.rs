//! Keyframed values: an animation sampler's key times and values, sampled at any time.

use crate::math::{Quat, float};

/// How a value between two keys is computed (glTF 2.0, section 3.11, "Animations"; appendix C,
/// "KeyInterpolation").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyInterpolation {
    /// The earlier key's value, until the next key.
    Step,
    /// Straight-line interpolation; spherical linear interpolation for rotations.
    Linear,
    /// A cubic Hermite spline through the keys, with an in-tangent and an out-tangent stored around each value.
    CubicSpline,
}

/// Why keys were refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyframeError {
    /// No keys, or values of zero components.
    Empty,
    /// A key time is not finite.
    TimeNotFinite {
        /// The key.
        key: usize,
    },
    /// A key time is not greater than the one before it.
    TimesNotIncreasing {
        /// The key.
        key: usize,
    },
    /// A value is not finite.
    ValueNotFinite {
        /// Its index in the values.
        index: usize,
    },
    /// The values do not number the keys times the components (times three for a cubic spline's tangents).
    ValueCount {
        /// The number needed.
        expected: usize,
        /// The number given.
        actual: usize,
    },
}

impl core::fmt::Display for KeyframeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Empty => f.write_str("there are no keys"),
            Self::TimeNotFinite { key } => write!(f, "key {key}'s time is not finite"),
            Self::TimesNotIncreasing { key } => write!(f, "key {key}'s time is not after the key before it"),
            Self::ValueNotFinite { index } => write!(f, "value {index} is not finite"),
            Self::ValueCount { expected, actual } => write!(f, "{actual} values where the keys need {expected}"),
        }
    }
}

impl core::error::Error for KeyframeError {}

/// Key times (seconds, increasing) and their values, `width` components each (3 for a translation or a scale, 4
/// for a rotation's quaternion `x, y, z, w`, the number of morph targets for weights). A cubic spline stores three
/// elements per key: in-tangent, value, out-tangent.
///
/// Before the first key a sample is the first key's value, after the last the last's (the specification's
/// clamping).
#[derive(Clone, Copy, Debug)]
pub struct Keyframes<'a> {
    times: &'a [f32],
    values: &'a [f32],
    width: usize,
    interpolation: KeyInterpolation,
}

impl<'a> Keyframes<'a> {
    /// Checks and wraps keys.
    ///
    /// # Errors
    /// [`KeyframeError`] when there are no keys, a time or value is not finite, times do not increase, or the
    /// values do not match the keys.
    pub fn new(
        times: &'a [f32],
        values: &'a [f32],
        width: usize,
        interpolation: KeyInterpolation,
    ) -> Result<Self, KeyframeError> {
        if times.is_empty() || width == 0 {
            return Err(KeyframeError::Empty);
        }
        if let Some(key) = times.iter().position(|t| !t.is_finite()) {
            return Err(KeyframeError::TimeNotFinite { key });
        }
        if let Some(key) = (1..times.len()).find(|&k| times[k] <= times[k - 1]) {
            return Err(KeyframeError::TimesNotIncreasing { key });
        }
        let per_key = if interpolation == KeyInterpolation::CubicSpline { 3 * width } else { width };
        let expected = times.len().saturating_mul(per_key);
        if values.len() != expected {
            return Err(KeyframeError::ValueCount { expected, actual: values.len() });
        }
        if let Some(index) = values.iter().position(|v| !v.is_finite()) {
            return Err(KeyframeError::ValueNotFinite { index });
        }
        Ok(Self { times, values, width, interpolation })
    }

    /// Components per value.
    #[must_use]
    pub fn width(&self) -> usize {
        self.width
    }

    /// The interpolation.
    #[must_use]
    pub fn interpolation(&self) -> KeyInterpolation {
        self.interpolation
    }

    /// The first key's time and the last's.
    #[must_use]
    pub fn span(&self) -> (f32, f32) {
        (self.times[0], self.times[self.times.len() - 1])
    }

    /// The value at time `t` into `out[..width]` (components are interpolated each on its own; use
    /// [`Self::sample_rotation`] for rotations). Nothing is written when `out` is shorter than the width; a time that
    /// is not finite samples the first key.
    pub fn sample(&self, t: f32, out: &mut [f32]) {
        let Some(out) = out.get_mut(..self.width) else { return };
        match self.segment(t) {
            Segment::Key(k) => out.copy_from_slice(self.value(k)),
            Segment::Between { key, u, span } => {
                let (a, b) = (self.value(key), self.value(key + 1));
                match self.interpolation {
                    KeyInterpolation::Step => out.copy_from_slice(a),
                    KeyInterpolation::Linear => {
                        for (o, (a, b)) in out.iter_mut().zip(a.iter().zip(b)) {
                            *o = a * (1.0 - u) + b * u;
                        }
                    }
                    KeyInterpolation::CubicSpline => {
                        let h = Hermite::at(u, span);
                        let (out_tangent, in_tangent) = (self.element(key, 2), self.element(key + 1, 0));
                        for (i, o) in out.iter_mut().enumerate() {
                            *o = h.apply(a[i], out_tangent[i], b[i], in_tangent[i]);
                        }
                    }
                }
            }
        }
    }

    /// The rotation at time `t`, for keys of four components (`x, y, z, w`): spherical linear interpolation for
    /// `LINEAR`, the spline normalised for `CUBICSPLINE` (appendix C). The identity when the width is not 4 or the
    /// result has no direction.
    pub fn sample_rotation(&self, t: f32) -> Quat {
        if self.width != 4 {
            return Quat::IDENTITY;
        }
        let quat = |v: &[f32]| Quat { x: v[0], y: v[1], z: v[2], w: v[3] };
        match (self.segment(t), self.interpolation) {
            (Segment::Key(k), _) | (Segment::Between { key: k, .. }, KeyInterpolation::Step) => {
                quat(self.value(k)).normalize()
            }
            (Segment::Between { key, u, .. }, KeyInterpolation::Linear) => {
                slerp(quat(self.value(key)), quat(self.value(key + 1)), u)
            }
            (Segment::Between { .. }, KeyInterpolation::CubicSpline) => {
                let mut v = [0.0; 4];
                self.sample(t, &mut v);
                quat(&v).normalize()
            }
        }
    }

    /// Where `t` falls: on a key (before the first, after the last, or a single key), or between keys `key` and
    /// `key + 1`, a fraction `u` of the way, `span` seconds apart.
    fn segment(&self, t: f32) -> Segment {
        let last = self.times.len() - 1;
        if t.is_nan() || t <= self.times[0] {
            return Segment::Key(0);
        }
        if t >= self.times[last] {
            return Segment::Key(last);
        }
        // times[key] < t < times[key + 1] or t == times[key]: the keys up to t, less one.
        let key = self.times.partition_point(|&k| k <= t) - 1;
        let span = self.times[key + 1] - self.times[key];
        Segment::Between { key, u: (t - self.times[key]) / span, span }
    }

    /// Element `which` (0 in-tangent, 1 value, 2 out-tangent) of key `k` of a cubic spline.
    fn element(&self, k: usize, which: usize) -> &[f32] {
        let start = (3 * k + which) * self.width;
        &self.values[start..start + self.width]
    }

    /// Key `k`'s value.
    fn value(&self, k: usize) -> &[f32] {
        if self.interpolation == KeyInterpolation::CubicSpline {
            self.element(k, 1)
        } else {
            &self.values[k * self.width..(k + 1) * self.width]
        }
    }
}

/// See [`Keyframes::segment`].
enum Segment {
    Key(usize),
    Between { key: usize, u: f32, span: f32 },
}

/// The cubic Hermite basis at `u` of a segment `span` seconds long, tangents scaled by the span (appendix C:
/// `v(t) = (2t³ - 3t² + 1) v_k + t_d (t³ - 2t² + t) b_k + (-2t³ + 3t²) v_k+1 + t_d (t³ - t²) a_k+1`).
struct Hermite {
    value0: f32,
    tangent0: f32,
    value1: f32,
    tangent1: f32,
}

impl Hermite {
    fn at(u: f32, span: f32) -> Self {
        let (u2, u3) = (u * u, u * u * u);
        Self {
            value0: 2.0 * u3 - 3.0 * u2 + 1.0,
            tangent0: span * (u3 - 2.0 * u2 + u),
            value1: -2.0 * u3 + 3.0 * u2,
            tangent1: span * (u3 - u2),
        }
    }

    fn apply(&self, v0: f32, out_tangent0: f32, v1: f32, in_tangent1: f32) -> f32 {
        self.value0 * v0 + self.tangent0 * out_tangent0 + self.value1 * v1 + self.tangent1 * in_tangent1
    }
}

/// Spherical linear interpolation of unit quaternions along the shorter arc (appendix C: `a = acos(|d|)`,
/// `v = sin(a(1-t))/sin(a) v_k + s sin(at)/sin(a) v_k+1`, `s` the sign of `d`), normalised; the normalised straight
/// line where the two are too close for the division.
fn slerp(a: Quat, b: Quat, u: f32) -> Quat {
    let dot = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
    let s = if dot < 0.0 { -1.0 } else { 1.0 };
    let angle = float::acos(float::min(float::abs(dot), 1.0));
    let sin = float::sin(angle);
    let (ka, kb) = if sin > 1e-4 {
        (float::sin(angle * (1.0 - u)) / sin, s * float::sin(angle * u) / sin)
    } else {
        (1.0 - u, s * u)
    };
    Quat { x: a.x * ka + b.x * kb, y: a.y * ka + b.y * kb, z: a.z * ka + b.z * kb, w: a.w * ka + b.w * kb }.normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    const TIMES: [f32; 3] = [1.0, 2.0, 4.0];
    const VALUES: [f32; 6] = [0.0, 10.0, 4.0, 20.0, 8.0, 0.0];

    fn sample(keys: &Keyframes<'_>, t: f32) -> [f32; 2] {
        let mut out = [f32::NAN; 2];
        keys.sample(t, &mut out);
        out
    }

    #[test]
    fn step_holds_each_key_until_the_next() {
        let keys = Keyframes::new(&TIMES, &VALUES, 2, KeyInterpolation::Step).unwrap();
        assert_eq!(sample(&keys, 0.0), [0.0, 10.0]);
        assert_eq!(sample(&keys, 1.0), [0.0, 10.0]);
        assert_eq!(sample(&keys, 1.999), [0.0, 10.0]);
        assert_eq!(sample(&keys, 2.0), [4.0, 20.0]);
        assert_eq!(sample(&keys, 3.5), [4.0, 20.0]);
        assert_eq!(sample(&keys, 4.0), [8.0, 0.0]);
        assert_eq!(sample(&keys, 100.0), [8.0, 0.0]);
        assert_eq!(sample(&keys, f32::NAN), [0.0, 10.0]);
    }

    #[test]
    fn linear_is_exact_on_keys_and_clamped_outside() {
        let keys = Keyframes::new(&TIMES, &VALUES, 2, KeyInterpolation::Linear).unwrap();
        assert_eq!(keys.span(), (1.0, 4.0));
        assert_eq!(sample(&keys, -5.0), [0.0, 10.0]);
        assert_eq!(sample(&keys, 1.5), [2.0, 15.0]);
        assert_eq!(sample(&keys, 2.0), [4.0, 20.0]);
        // A quarter of the way from 2 s to 4 s.
        assert_eq!(sample(&keys, 2.5), [5.0, 15.0]);
        assert_eq!(sample(&keys, 4.0), [8.0, 0.0]);
        assert_eq!(sample(&keys, f32::INFINITY), [8.0, 0.0]);
    }

    #[test]
    fn cubic_spline_follows_the_hermite_formula() {
        // One component; keys at 0 s and 2 s with values 1 and 3, out-tangent of the first 2, in-tangent of the
        // second -1 (per second). At u = 0.5 (t = 1 s): basis 0.5, 0.125 * 2 s, 0.5, -0.125 * 2 s:
        // 0.5 * 1 + 0.25 * 2 + 0.5 * 3 - 0.25 * -1 = 2.75.
        let times = [0.0, 2.0];
        let values = [9.0, 1.0, 2.0, -1.0, 3.0, 9.0];
        let keys = Keyframes::new(&times, &values, 1, KeyInterpolation::CubicSpline).unwrap();
        let at = |t: f32| {
            let mut out = [0.0];
            keys.sample(t, &mut out);
            out[0]
        };
        assert_eq!(at(1.0), 2.75);
        // On the keys, the values; outside, clamped (tangents 9 never reach the result).
        assert_eq!(at(0.0), 1.0);
        assert_eq!(at(2.0), 3.0);
        assert_eq!(at(-1.0), 1.0);
        assert_eq!(at(7.0), 3.0);
        // u = 0.25: basis 0.84375, 0.140625 * 2, 0.15625, -0.046875 * 2:
        // 0.84375 + 0.5625 + 0.46875 + 0.09375 = 1.96875.
        assert_eq!(at(0.5), 1.968_75);
    }

    #[test]
    fn rotations_take_the_shorter_arc_at_constant_speed() {
        use core::f32::consts::FRAC_PI_2;
        let (s, c) = (float::sin(FRAC_PI_2 / 2.0), float::cos(FRAC_PI_2 / 2.0));
        // The identity, then a quarter turn about z written with a negative w (the same rotation).
        let times = [0.0, 1.0];
        let values = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -s, -c];
        let keys = Keyframes::new(&times, &values, 4, KeyInterpolation::Linear).unwrap();
        // Half way: an eighth of a turn about z, the short way.
        let q = keys.sample_rotation(0.5);
        let (s8, c8) = (float::sin(FRAC_PI_2 / 4.0), float::cos(FRAC_PI_2 / 4.0));
        assert!((q.z - s8).abs() < 1e-6 && (q.w - c8).abs() < 1e-6 && q.x == 0.0 && q.y == 0.0, "{q:?}");
        // A third of the way: a third of the angle (constant angular speed).
        let q = keys.sample_rotation(1.0 / 3.0);
        let angle = 2.0 * float::atan(q.z / q.w);
        assert!((angle - FRAC_PI_2 / 3.0).abs() < 1e-6, "{angle}");
        let q = keys.sample_rotation(2.0);
        assert!((q.z + s).abs() < 1e-6 && (q.w + c).abs() < 1e-6);
        // Step holds the first; a wrong width gives the identity.
        let step = Keyframes::new(&times, &values, 4, KeyInterpolation::Step).unwrap();
        assert_eq!(step.sample_rotation(0.9), Quat::IDENTITY);
        let wide = Keyframes::new(&times, &values, 2, KeyInterpolation::Step).unwrap_err();
        assert_eq!(wide, KeyframeError::ValueCount { expected: 4, actual: 8 });
    }

    #[test]
    fn bad_keys_are_refused() {
        let linear = KeyInterpolation::Linear;
        assert_eq!(Keyframes::new(&[], &[], 1, linear).unwrap_err(), KeyframeError::Empty);
        assert_eq!(Keyframes::new(&[0.0], &[0.0], 0, linear).unwrap_err(), KeyframeError::Empty);
        assert_eq!(
            Keyframes::new(&[0.0, 0.0], &[0.0, 1.0], 1, linear).unwrap_err(),
            KeyframeError::TimesNotIncreasing { key: 1 }
        );
        assert_eq!(
            Keyframes::new(&[0.0, f32::NAN], &[0.0, 1.0], 1, linear).unwrap_err(),
            KeyframeError::TimeNotFinite { key: 1 }
        );
        assert_eq!(
            Keyframes::new(&[0.0, 1.0], &[0.0, f32::INFINITY], 1, linear).unwrap_err(),
            KeyframeError::ValueNotFinite { index: 1 }
        );
        assert_eq!(
            Keyframes::new(&[0.0, 1.0], &[0.0, 1.0], 1, KeyInterpolation::CubicSpline).unwrap_err(),
            KeyframeError::ValueCount { expected: 6, actual: 2 }
        );
        // A single key is a constant.
        let one = Keyframes::new(&[3.0], &[7.0], 1, linear).unwrap();
        let mut out = [0.0];
        one.sample(-1.0, &mut out);
        assert_eq!(out, [7.0]);
    }
}
