//! Exact sums and products of floats, as floating-point expansions.
//!
//! An expansion represents a real number exactly as the unevaluated sum of `f64` components that do not overlap
//! (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", Discrete &
//! Computational Geometry 18, 1997). Sums and products of `f32` inputs computed this way have no rounding error at
//! all; only the final [`Expansion::value`] rounds, relative to the result itself. Clipping uses it so that an
//! intersection far smaller than the vertices it comes from (a triangle 10^30 units wide crossing the view) is
//! still found to full precision. Every operation is plain IEEE `f64` arithmetic: identical on every target.
//!
//! On a target without SIMD registers (a microcontroller), where each `f64` operation is a call into software
//! arithmetic, the operations are kept out of line: clipping is rare, and inlined they made this file the core's
//! largest code on the firmware (8.2 KB of 33.2). Out of line, with the clipper's distances and meeting points,
//! the core's code there is 5.9 KB smaller (27.3 KB, `firmware/measure.sh`).

/// Components an expansion can hold: enough for `a * b - c * d` with `a`, `c` sums of four exact products.
const CAPACITY: usize = 32;

/// `a + b` as `(rounded sum, exact error)` (Knuth's TwoSum).
#[cfg_attr(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"), inline)]
#[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Splits `a` into two halves of 26 bits each (Dekker).
#[inline]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a * b` as `(rounded product, exact error)` (Dekker's TwoProduct, without a fused multiply-add so that every
/// target computes the same bits). Exact unless the product overflows or underflows.
#[cfg_attr(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"), inline)]
#[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = al * bl - (((p - ah * bh) - al * bh) - ah * bl);
    (p, e)
}

/// A real number held exactly as a sum of non-overlapping `f64` components in increasing magnitude.
#[derive(Clone, Copy, Debug)]
pub struct Expansion {
    terms: [f64; CAPACITY],
    len: usize,
}

impl Expansion {
    /// Zero.
    pub const ZERO: Self = Self { terms: [0.0; CAPACITY], len: 0 };

    /// An expansion equal to `a`.
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn from_f64(a: f64) -> Self {
        let mut e = Self::ZERO;
        if a != 0.0 {
            e.terms[0] = a;
            e.len = 1;
        }
        e
    }

    /// The exact product of two `f32`s (exact in one `f64`: 24 + 24 bits of mantissa).
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn product(a: f32, b: f32) -> Self {
        Self::from_f64(f64::from(a) * f64::from(b))
    }

    fn push(&mut self, t: f64) {
        // Zero components are dropped; the capacity is sized so that the uses in this crate never fill it.
        if t != 0.0 && self.len < CAPACITY {
            self.terms[self.len] = t;
            self.len += 1;
        }
    }

    /// `self + b` exactly (Shewchuk's Grow-Expansion with zero elimination).
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn add_f64(&self, b: f64) -> Self {
        let mut out = Self::ZERO;
        let mut q = b;
        for &t in &self.terms[..self.len] {
            let (s, e) = two_sum(q, t);
            out.push(e);
            q = s;
        }
        out.push(q);
        out
    }

    /// `self + other` exactly.
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn add(&self, other: &Self) -> Self {
        let mut out = *self;
        for &t in &other.terms[..other.len] {
            out = out.add_f64(t);
        }
        out
    }

    /// `-self`.
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn neg(&self) -> Self {
        let mut out = *self;
        for t in &mut out.terms[..out.len] {
            *t = -*t;
        }
        out
    }

    /// `self - other` exactly.
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn sub(&self, other: &Self) -> Self {
        self.add(&other.neg())
    }

    /// `self * b` exactly (Shewchuk's Scale-Expansion).
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn scale(&self, b: f64) -> Self {
        let mut out = Self::ZERO;
        let Some((&first, rest)) = self.terms[..self.len].split_first() else { return out };
        let (mut q, e) = two_product(first, b);
        out.push(e);
        for &t in rest {
            let (p, pe) = two_product(t, b);
            let (s, e1) = two_sum(q, pe);
            out.push(e1);
            let (s2, e2) = two_sum(p, s);
            out.push(e2);
            q = s2;
        }
        out.push(q);
        out
    }

    /// The value rounded to an `f64`, accurate to about one unit in the last place of the value itself.
    ///
    /// Components are summed from the smallest: for a non-overlapping expansion the rounding errors stay below
    /// the last place of the result.
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn value(&self) -> f64 {
        self.terms[..self.len].iter().fold(0.0, |sum, &t| sum + t)
    }

    /// The sign: -1, 0 or 1 (exact: the largest component has the sign of the sum).
    #[must_use]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn signum(&self) -> i32 {
        match self.terms[..self.len].last() {
            Some(&t) if t > 0.0 => 1,
            Some(&t) if t < 0.0 => -1,
            _ => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_keep_what_f64_loses() {
        let big = Expansion::from_f64(1e20);
        let sum = big.add_f64(13643.0).add_f64(-1e20);
        assert_eq!(sum.value(), 13643.0);
        assert_eq!(sum.signum(), 1);
    }

    #[test]
    fn products_are_exact() {
        // (2^30 + 1)^2 = 2^60 + 2^31 + 1 needs 61 bits.
        let a = 1_073_741_825.0;
        let p = Expansion::from_f64(a).scale(a);
        let minus = p.add_f64(-1_152_921_504_606_846_976.0).add_f64(-2_147_483_648.0);
        assert_eq!(minus.value(), 1.0);
    }

    #[test]
    fn cancellation_in_a_difference_of_products_is_exact() {
        // x1 y2 - x2 y1 for (x, y) and (-x, -y), two points on a line through the origin 1e20 away: exactly 0.
        let (x, y) = (9.95e19f32, 9.98e18f32);
        let d = Expansion::product(x, -y).sub(&Expansion::product(y, -x));
        assert_eq!((d.signum(), d.value()), (0, 0.0));
        // And a tiny non-zero result survives next to 1e40-sized terms.
        let d = Expansion::product(x, y).sub(&Expansion::product(x, y)).add_f64(0.25);
        assert_eq!(d.value(), 0.25);
    }
}
