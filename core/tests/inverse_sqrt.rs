//! `float::inv_sqrt`, which every normalisation uses: within one unit in the last place of `1 / sqrt(x)` for every
//! finite `x > 0`.
//!
//! Every input is covered, not sampled. Multiplying `x` by 4 multiplies its result by exactly 1/2 for normal
//! inputs: the estimate's exponent bits move by one, and every step of the iteration scales by a power of two
//! (its intermediate values stay near `sqrt(x)` and 1, so none overflows or underflows). So every mantissa of
//! [1, 4) (both exponent parities) stands for all normal inputs, which the test also checks bit for bit on every
//! exponent for a stride of mantissas; subnormal inputs are all checked directly.

use rastty_core::math::Vec3;
use rastty_core::math::float::inv_sqrt;

/// `1 / sqrt(x)` rounded to the nearest `f32` (computed in `f64`: its 53 bits round correctly to 24 except at a
/// tie, which the square root of a 24-bit number never is).
fn correctly_rounded(x: f32) -> f32 {
    (1.0 / f64::from(x).sqrt()) as f32
}

/// Distance in units in the last place between two positive finite `f32`s.
fn ulps(a: f32, b: f32) -> u32 {
    a.to_bits().abs_diff(b.to_bits())
}

/// The largest error over `inputs`, and the input where it occurs.
fn worst(inputs: impl Iterator<Item = f32>) -> (u32, f32) {
    inputs.map(|x| (ulps(inv_sqrt(x), correctly_rounded(x)), x)).fold((0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
}

#[test]
fn every_input_from_one_to_four_is_within_one_ulp() {
    let (one, four) = (1.0f32.to_bits(), 4.0f32.to_bits());
    let (error, at) = worst((one..four).map(f32::from_bits));
    assert!(error <= 1, "{error} ulp at {at:e}");
}

#[test]
fn every_subnormal_input_is_within_one_ulp() {
    let (error, at) = worst((1..f32::MIN_POSITIVE.to_bits()).map(f32::from_bits));
    assert!(error <= 1, "{error} ulp at {at:e}");
}

#[test]
fn scaling_by_four_halves_the_result_exactly_across_every_exponent() {
    // A stride through the mantissas of [1, 4), moved to every normal exponent pair.
    for bits in (1.0f32.to_bits()..4.0f32.to_bits()).step_by(997) {
        let x = f32::from_bits(bits);
        let y = inv_sqrt(x);
        for k in -63..=63 {
            let scale = 2f32.powi(2 * k);
            let scaled = x * scale;
            if !(scaled.is_normal() && scaled.is_finite()) {
                continue;
            }
            // Exact: both are powers of two times representable values well inside the normal range.
            let expected = y / 2f32.powi(k);
            assert_eq!(inv_sqrt(scaled).to_bits(), expected.to_bits(), "x = {scaled:e}");
        }
    }
    // The largest and the smallest normal inputs, and the largest finite one.
    for x in [f32::MAX, f32::MIN_POSITIVE, 1e38, 3e-38] {
        assert!(ulps(inv_sqrt(x), correctly_rounded(x)) <= 1, "{x:e}");
    }
}

#[test]
fn normalised_vectors_are_unit_length_to_rounding() {
    // Directions of every octant and magnitudes from subnormal squares to near overflow.
    let mut largest = 0.0f64;
    for i in 0..20_000u32 {
        let t = i as f32 * 0.618_034;
        let direction = Vec3::new(t.sin(), (t * 1.7).cos(), (t * 0.3).sin() - 0.2);
        let magnitude = 2f32.powi((i % 120) as i32 - 60);
        let v = direction * magnitude;
        let Some(n) = v.try_normalize() else { continue };
        let length = (f64::from(n.x).powi(2) + f64::from(n.y).powi(2) + f64::from(n.z).powi(2)).sqrt();
        largest = largest.max((length - 1.0).abs());
    }
    // One ulp in the inverse square root and one rounding per product: a few times 2^-24.
    assert!(largest < 4.0 * f64::from(f32::EPSILON), "{largest:e}");
}

#[test]
fn normalising_refuses_what_it_refused_before() {
    // Zero, NaN and infinite lengths give None; so do squares that underflow to zero or overflow to infinity,
    // exactly where the length (a correctly rounded square root of the same square) is zero or infinite.
    for v in [
        Vec3::ZERO,
        Vec3::new(f32::NAN, 0.0, 0.0),
        Vec3::new(f32::INFINITY, 1.0, 0.0),
        Vec3::new(1e-30, 0.0, 0.0),
        Vec3::new(2e19, 0.0, 0.0),
    ] {
        assert_eq!(v.try_normalize(), None, "{v:?}");
        assert_eq!(v.normalize_or_zero(), Vec3::ZERO, "{v:?}");
    }
    // Just inside: a square just below the largest finite value, and a subnormal one. A subnormal square holds
    // fewer bits (1e-40 about 17), so its length is off by up to 2^-17 however the root is taken.
    let n = Vec3::new(0.0, 1.8e19, 0.0).try_normalize().expect("a finite square");
    assert!((n - Vec3::Y).length() <= f32::EPSILON, "{n:?}");
    let n = Vec3::new(1e-20, 0.0, 0.0).try_normalize().expect("a non-zero square");
    let exact_from_square = f64::from(1e-20f32) / f64::from(1e-20f32 * 1e-20f32).sqrt();
    assert!((f64::from(n.x) - exact_from_square).abs() <= 2.0 * f64::from(f32::EPSILON), "{n:?}");
    assert!((n.x - 1.0).abs() < 1e-5 && n.y == 0.0 && n.z == 0.0, "{n:?}");
}
