//! The one place where `f32` maths beyond `+ - * /` happens.
//!
//! Every function here either calls [`libm`], never the platform's own maths library, or is made of operations
//! whose result IEEE 754 fixes exactly (comparisons, conversions), so a desktop build and a
//! `thumbv7em-none-eabihf` firmware compute bit-identical values and therefore bit-identical pixels. Basic
//! arithmetic needs no wrapper: IEEE 754 fixes its result too, and Rust does not contract `a * b + c` into a fused
//! multiply-add on its own.
//!
//! [`pow_f64`] is a `const fn` made of basic arithmetic only, for tables the compiler computes once (the sRGB
//! tables of [`crate::color`]): the same bits on every target by construction.

/// Square root (correctly rounded on every target).
#[inline(always)]
#[must_use]
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// `1 / sqrt(x)` for a finite `x > 0`, subnormals included, within one unit in the last place of the exact value
/// (`core/tests/inverse_sqrt.rs` checks every input); zero, negative, infinite or NaN `x` gives a meaningless
/// value, so callers test `x` first.
///
/// What every normalisation in the core uses. Made of IEEE operations alone (no `libm` call, no square root
/// instruction), so a loop of it widens to SIMD, and every target computes the same bits: a bit-level estimate
/// (Lomont, "Fast inverse square root", 2003, constant 0x5F375A86; relative error below 3.5%), then three
/// Newton-Raphson steps for `y^-2 = x` (each squares the error: 2e-3, 5e-6, below rounding), each written as a
/// correction `y + y (1 - x y^2) / 2` so that its rounding stays below the correction's size. Subnormal inputs
/// are scaled by 2^24 first (exact), and their result by 2^12.
///
/// Where the target has SIMD registers the subnormal case is two selects, which a lane loop widens; elsewhere it
/// is a branch around them (on the Cortex-M4 a float comparison and a select cost several instructions each). The
/// same operations either way: a test compares the two forms bit for bit.
#[inline(always)]
#[must_use]
pub fn inv_sqrt(x: f32) -> f32 {
    if SIMD { inv_sqrt_selecting(x) } else { inv_sqrt_branching(x) }
}

/// True where the target has SIMD registers (x86-64, AArch64, WebAssembly with `simd128`): lane loops then run
/// over every lane, a constant count the compiler widens to SIMD instructions ([`crate::pipeline::columns`]), and
/// choices inside them are selects rather than branches.
pub(crate) const SIMD: bool = cfg!(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"));

/// 2^24: an even power, so its square root 2^12 is exact; a subnormal times it is normal.
const SUBNORMAL_SCALE: f32 = 16_777_216.0;

/// [`inv_sqrt`] of a normal `x` (or of a subnormal scaled by [`SUBNORMAL_SCALE`]): the estimate and three Newton
/// steps.
#[inline(always)]
fn inv_sqrt_normal(x: f32) -> f32 {
    let mut y = f32::from_bits(0x5F37_5A86_u32.wrapping_sub(x.to_bits() >> 1));
    for _ in 0..3 {
        let residual = 1.0 - x * y * y;
        y += y * (0.5 * residual);
    }
    y
}

/// [`inv_sqrt`] with the subnormal case chosen by selects.
#[inline(always)]
pub(crate) fn inv_sqrt_selecting(x: f32) -> f32 {
    let subnormal = x < f32::MIN_POSITIVE;
    let y = inv_sqrt_normal(if subnormal { x * SUBNORMAL_SCALE } else { x });
    if subnormal { y * 4096.0 } else { y }
}

/// [`inv_sqrt`] with the subnormal case behind a branch.
#[inline(always)]
pub(crate) fn inv_sqrt_branching(x: f32) -> f32 {
    if x < f32::MIN_POSITIVE { inv_sqrt_normal(x * SUBNORMAL_SCALE) * 4096.0 } else { inv_sqrt_normal(x) }
}

/// Whether `0 < x < inf` (false for NaN), as one comparison of the bits: a positive finite `f32`'s bits, less one,
/// are below those of the largest finite one, and no other value's are (zero's wrap round; the infinities', NaNs'
/// and negative values' are not below). A target without SIMD compares floats through its status flags, several
/// instructions a comparison.
#[inline(always)]
#[must_use]
pub fn positive_finite(x: f32) -> bool {
    x.to_bits().wrapping_sub(1) < f32::MAX.to_bits()
}

/// Sine of `x` radians.
#[inline(always)]
#[must_use]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}

/// Cosine of `x` radians.
#[inline(always)]
#[must_use]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}

/// Tangent of `x` radians.
#[inline(always)]
#[must_use]
pub fn tan(x: f32) -> f32 {
    libm::tanf(x)
}

/// Arc-sine in radians, in `[-pi/2, pi/2]`.
#[inline(always)]
#[must_use]
pub fn asin(x: f32) -> f32 {
    libm::asinf(x)
}

/// Arc-cosine in radians, in `[0, pi]`.
#[inline(always)]
#[must_use]
pub fn acos(x: f32) -> f32 {
    libm::acosf(x)
}

/// Arc-tangent in radians, in `[-pi/2, pi/2]`.
#[inline(always)]
#[must_use]
pub fn atan(x: f32) -> f32 {
    libm::atanf(x)
}

/// The angle of the point `(x, y)` from the positive `x` axis in radians, in `[-pi, pi]`.
#[inline(always)]
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}

/// Base-2 logarithm.
#[inline(always)]
#[must_use]
pub fn log2(x: f32) -> f32 {
    libm::log2f(x)
}

/// `x` raised to the power `y`.
///
/// Whole exponents up to 256 (Blinn-Phong shininess nearly always is one) are computed by repeated squaring: a
/// handful of multiplications instead of a `powf` call, equally deterministic on every target.
#[inline(always)]
#[must_use]
pub fn pow(x: f32, y: f32) -> f32 {
    Exponent::new(y).raise(x)
}

/// An exponent of [`pow`], sorted once where many values are raised to it: whole (computed by [`powi`]) or not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Exponent {
    /// A whole number from 0 to 256 ([`whole_exponent`]).
    Whole(u32),
    /// Any other value, for `powf`.
    Other(f32),
}

impl Exponent {
    /// `y`, sorted.
    #[inline(always)]
    #[must_use]
    pub fn new(y: f32) -> Self {
        whole_exponent(y).map_or(Self::Other(y), Self::Whole)
    }

    /// `x` raised to this exponent: [`pow`]`(x, y)`.
    #[inline(always)]
    #[must_use]
    pub fn raise(self, x: f32) -> f32 {
        match self {
            Self::Whole(n) => powi(x, n),
            Self::Other(y) => libm::powf(x, y),
        }
    }
}

/// `y` as a whole number when it is one from 0 to 256: the exponents [`pow`] computes by [`powi`].
#[inline(always)]
#[must_use]
pub fn whole_exponent(y: f32) -> Option<u32> {
    ((0.0..=256.0).contains(&y) && y == (y as u32) as f32).then_some(y as u32)
}

/// `x` raised to the whole power `n`, by binary exponentiation (square-and-multiply, Knuth TAOCP vol. 2,
/// 4.6.3), in a fixed order of operations.
#[inline(always)]
#[must_use]
pub fn powi(mut x: f32, mut n: u32) -> f32 {
    let mut result = 1.0;
    while n > 0 {
        if n & 1 == 1 {
            result *= x;
        }
        x *= x;
        n >>= 1;
    }
    result
}

/// 2^23: from here up every `f32` is an integer, and adding it to a smaller non-negative value rounds that value
/// to an integer (ties to even) in one exact IEEE operation.
const TWO_POW_23: f32 = 8_388_608.0;

/// Largest integer value not greater than `x`; NaN and infinities are returned unchanged. (The sign of a zero
/// result is not specified.)
///
/// Exact: `x` rounded to an integer by adding and subtracting 2^23 (with `x`'s sign), then corrected by one where
/// that rounded up. Branch-light and much cheaper than a software `floorf` on targets without a rounding
/// instruction.
#[inline(always)]
#[must_use]
pub fn floor(x: f32) -> f32 {
    if abs(x) < TWO_POW_23 {
        let c = f32::from_bits(TWO_POW_23.to_bits() | (x.to_bits() & 0x8000_0000));
        let r = (x + c) - c;
        // Subtract 1 where rounding went up; written without a branch (the comparison is data-dependent).
        r - f32::from(u8::from(r > x))
    } else {
        x
    }
}

/// `x` rounded to the nearest `f32` (ties to even), as `x as f32` does. On a 32-bit target a value that fits `i32`
/// (every edge value of a small triangle) goes through the single-precision unit's `i32` conversion instead of a
/// software `i64` one (about 40 instructions on a Cortex-M4): the same rounding of the same integer, so the same
/// bits.
#[inline(always)]
#[must_use]
pub fn from_i64(x: i64) -> f32 {
    #[cfg(target_pointer_width = "32")]
    {
        // Out of line, so that the compiler keeps the branch instead of computing both conversions and choosing.
        #[cold]
        #[inline(never)]
        fn wide(x: i64) -> f32 {
            x as f32
        }
        match i32::try_from(x) {
            Ok(x) => x as f32,
            Err(_) => wide(x),
        }
    }
    #[cfg(not(target_pointer_width = "32"))]
    {
        x as f32
    }
}

/// Absolute value (clears the sign bit).
#[inline(always)]
#[must_use]
pub fn abs(x: f32) -> f32 {
    f32::from_bits(x.to_bits() & 0x7FFF_FFFF)
}

/// Smaller of two values; if `a` is NaN, `b`. A comparison, not a `libm` call: exact, and compiled inline.
#[inline(always)]
#[must_use]
pub fn min(a: f32, b: f32) -> f32 {
    if a < b { a } else { b }
}

/// Larger of two values; if `a` is NaN, `b`. A comparison, not a `libm` call: exact, and compiled inline.
#[inline(always)]
#[must_use]
pub fn max(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

/// Smaller of two values, ignoring a NaN (IEEE 754 minNum: NaN only if both are; of `-0.0` and `0.0`, either).
/// Exact. Unlike [`min`], a loop that keeps a running minimum in memory with it compiles to plain SIMD stores,
/// not masked ones (which are slow on some x86 processors).
#[inline(always)]
#[must_use]
pub fn min_num(a: f32, b: f32) -> f32 {
    a.min(b)
}

/// Larger of two values, ignoring a NaN (IEEE 754 maxNum); see [`min_num`].
#[inline(always)]
#[must_use]
pub fn max_num(a: f32, b: f32) -> f32 {
    a.max(b)
}

/// `x` limited to `[lo, hi]`; NaN becomes `lo`.
#[inline(always)]
#[must_use]
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    min(max(x, lo), hi)
}

/// `floor(x)` as an integer, exact for `|x| < 2^31`; saturates beyond, NaN gives 0.
///
/// Cheaper than [`floor`] followed by a cast: the cast truncates toward zero (saturating, as Rust defines it), and
/// one compare corrects negative non-integers.
#[inline(always)]
#[must_use]
pub fn floor_to_i32(x: f32) -> i32 {
    let t = x as i32;
    t.saturating_sub(i32::from((t as f32) > x))
}

/// `floor(x)` as an integer for `x` within `±(2^22 - 1)`; beyond, the floor of `x` clamped to that range, and NaN
/// gives 0 (as [`floor_to_i32`] does).
///
/// Unlike [`floor_to_i32`], it has no saturating conversion (which compiles to a branch per value), so a loop of
/// it widens to SIMD: the clamped floor plus `2^22` is a whole number in `(0, 2^23)`, read from the mantissa bits
/// by [`round_small_to_u32`].
#[inline(always)]
#[must_use]
pub fn floor_to_i32_clamped(x: f32) -> i32 {
    const OFFSET: i32 = 1 << 22;
    const LIMIT: f32 = (OFFSET - 1) as f32;
    let x = if x.is_nan() { 0.0 } else { clamp(x, -LIMIT, LIMIT) };
    round_small_to_u32(floor(x) + OFFSET as f32) as i32 - OFFSET
}

/// `x` in `[0, 2^23)` rounded to the nearest integer (ties to even). Outside that range the result is
/// meaningless but defined (never a panic), so callers bound `x` first.
///
/// Adding 2^23 leaves the rounded value in the low mantissa bits: an exact IEEE operation, and cheaper than a
/// saturating float-to-integer cast.
#[inline(always)]
#[must_use]
pub fn round_small_to_u32(x: f32) -> u32 {
    (x + TWO_POW_23).to_bits() & 0x7F_FFFF
}

/// Maps `x` in `[0, 1]` to an integer in `0..=max` (`max < 2^23`), rounding to nearest with ties to even; values
/// outside saturate and NaN gives 0.
#[inline(always)]
#[must_use]
pub fn quantize_unit(x: f32, max: f32) -> u32 {
    round_small_to_u32(clamp(x, 0.0, 1.0) * max)
}

/// `x^y` for finite `x > 0`, in `f64`, as `exp(y ln x)` from series (relative error a few units in the last place
/// per unit of `|y ln x|`, below `10^-14` for the sRGB curve): a `const fn` for tables computed at compile time. Overflow gives infinity and underflow zero.
#[must_use]
pub const fn pow_f64(x: f64, y: f64) -> f64 {
    exp_f64(y * ln_f64(x))
}

/// `ln x` for finite `x > 0`: `x = m 2^e` with `m` in `[1/sqrt 2, sqrt 2)`, and `ln m = 2 atanh((m - 1) / (m + 1))`
/// by its series (Abramowitz and Stegun 4.1.28), whose argument is at most 0.172, so 20 terms reach `10^-32`.
const fn ln_f64(x: f64) -> f64 {
    let bits = x.to_bits();
    let mut exponent = ((bits >> 52) & 0x7FF) as i64 - 1023;
    let mut m = f64::from_bits((bits & ((1 << 52) - 1)) | (1023 << 52));
    if m > core::f64::consts::SQRT_2 {
        m /= 2.0;
        exponent += 1;
    }
    let s = (m - 1.0) / (m + 1.0);
    let (s2, mut power, mut sum, mut k) = (s * s, s, 0.0, 1.0);
    while k < 40.0 {
        sum += power / k;
        power *= s2;
        k += 2.0;
    }
    exponent as f64 * core::f64::consts::LN_2 + 2.0 * sum
}

/// `e^x`: `x = k ln 2 + r` with `|r| <= ln 2 / 2`, `e^r` by its Taylor series to 24 terms, times `2^k` built
/// from its bits.
const fn exp_f64(x: f64) -> f64 {
    let k = (x / core::f64::consts::LN_2 + if x < 0.0 { -0.5 } else { 0.5 }) as i64;
    if k > 1023 {
        return f64::INFINITY;
    }
    if k < -1022 {
        return 0.0;
    }
    let r = x - k as f64 * core::f64::consts::LN_2;
    let (mut term, mut sum, mut n) = (1.0, 1.0, 1.0);
    while n < 25.0 {
        term *= r / n;
        sum += term;
        n += 1.0;
    }
    sum * f64::from_bits(((k + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The two forms of [`inv_sqrt`] give the same bits, for every subnormal, across the exponents and for the
    /// values its callers refuse (zero, negative, infinite, NaN).
    #[test]
    fn inverse_square_roots_by_selects_and_by_branches_agree() {
        let spread = (0..=u32::MAX).step_by(4_099);
        let subnormals = (1..0x0080_0000).step_by(7);
        let edges = [0, 0x8000_0000, 0x7F80_0000, 0xFF80_0000, 0x7FC0_0000, 0x0080_0000, 0x007F_FFFF, 0x3F80_0000];
        for bits in spread.chain(subnormals).chain(edges) {
            let x = f32::from_bits(bits);
            assert_eq!(inv_sqrt_selecting(x).to_bits(), inv_sqrt_branching(x).to_bits(), "{bits:#010x}");
        }
    }

    /// [`positive_finite`] is `0 < x < inf` for every `f32` bit pattern at the edges of each class, and a spread of
    /// all of them.
    #[test]
    fn positive_finite_is_the_two_comparisons() {
        let edges = [0, 1, 0x007F_FFFF, 0x0080_0000, 0x3F80_0000, 0x7F7F_FFFF, 0x7F80_0000, 0x7F80_0001, 0x7FFF_FFFF];
        let spread = (0..=u32::MAX).step_by(65_521);
        for bits in edges.into_iter().flat_map(|b| [b, b | 0x8000_0000]).chain(spread) {
            let x = f32::from_bits(bits);
            assert_eq!(positive_finite(x), x > 0.0 && x < f32::INFINITY, "{bits:#010x}");
        }
    }

    /// The series agree with the platform's `powf` to a few units in the last place of an `f64` per unit of
    /// `|y ln x|` (the error of `y ln x` grows through the exponential), over the range the sRGB tables use and
    /// far beyond it.
    #[test]
    fn pow_f64_matches_the_platform() {
        for i in 1..=2000 {
            let x = f64::from(i) / 1000.0;
            for y in [2.4, 1.0 / 2.4, 0.5, 3.0, -1.7] {
                let (ours, theirs) = (pow_f64(x, y), x.powf(y));
                let ulps = 4.0 * (1.0 + (y * x.ln()).abs());
                assert!((ours - theirs).abs() <= ulps * f64::EPSILON * theirs, "{x}^{y}: {ours} against {theirs}");
            }
        }
        assert_eq!(pow_f64(1.0, 2.4), 1.0);
        assert_eq!(pow_f64(1e300, 2.4), f64::INFINITY);
        assert_eq!(pow_f64(1e-300, 2.4), 0.0);
    }

    /// Within `±(2^22 - 1)` the clamped floor is [`floor_to_i32`]'s, bit for bit; beyond it clamps, and NaN
    /// gives 0 as in [`floor_to_i32`].
    #[test]
    fn clamped_floor_matches_the_saturating_floor_in_range() {
        let limit = 4_194_303.0;
        let samples = [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 0.999_999_9, -1e-30, 2.5, -2.5, limit, -limit, 4_194_302.5];
        for x in samples.into_iter().chain((0..2000).map(|i| (i as f32 - 1000.0) * 1234.567)) {
            assert_eq!(floor_to_i32_clamped(x), floor_to_i32(x), "{x}");
        }
        for (x, expected) in [
            (4_194_303.5, 4_194_303),
            (1e30, 4_194_303),
            (f32::INFINITY, 4_194_303),
            (-4_194_303.5, -4_194_303),
            (f32::NEG_INFINITY, -4_194_303),
            (f32::NAN, 0),
        ] {
            assert_eq!(floor_to_i32_clamped(x), expected, "{x}");
        }
    }
}
