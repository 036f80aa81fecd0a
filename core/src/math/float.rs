//! The one place where `f32` maths beyond `+ - * /` happens.
//!
//! Every function here calls [`libm`] (or is exact integer/IEEE arithmetic), never the platform's own maths
//! library, so a desktop build and a `thumbv7em-none-eabihf` firmware compute bit-identical values and therefore
//! bit-identical pixels. Basic arithmetic needs no wrapper: IEEE 754 fixes its result, and Rust does not contract
//! `a * b + c` into a fused multiply-add on its own.

/// Square root (correctly rounded on every target).
#[inline(always)]
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// Sine of `x` radians.
#[inline(always)]
pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}

/// Cosine of `x` radians.
#[inline(always)]
pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}

/// Tangent of `x` radians.
#[inline(always)]
pub fn tan(x: f32) -> f32 {
    libm::tanf(x)
}

/// `x` raised to the power `y`.
#[inline(always)]
pub fn pow(x: f32, y: f32) -> f32 {
    libm::powf(x, y)
}

/// Largest integer value not greater than `x`.
#[inline(always)]
pub fn floor(x: f32) -> f32 {
    libm::floorf(x)
}

/// Absolute value.
#[inline(always)]
pub fn abs(x: f32) -> f32 {
    libm::fabsf(x)
}

/// Smaller of two values; a NaN argument loses to a number (IEEE 754 `minNum`).
#[inline(always)]
pub fn min(a: f32, b: f32) -> f32 {
    libm::fminf(a, b)
}

/// Larger of two values; a NaN argument loses to a number (IEEE 754 `maxNum`).
#[inline(always)]
pub fn max(a: f32, b: f32) -> f32 {
    libm::fmaxf(a, b)
}

/// `x` limited to `[lo, hi]`; NaN becomes `lo`.
#[inline(always)]
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    min(max(x, lo), hi)
}

/// `floor(x)` as an integer, exact for `|x| < 2^31`; saturates beyond, NaN gives 0.
///
/// Cheaper than [`floor`] followed by a cast: the cast truncates toward zero (saturating, as Rust defines it), and
/// one compare corrects negative non-integers.
#[inline(always)]
pub fn floor_to_i32(x: f32) -> i32 {
    let t = x as i32;
    t.saturating_sub(i32::from((t as f32) > x))
}
