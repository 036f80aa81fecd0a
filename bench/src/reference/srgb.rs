//! The sRGB transfer functions in `f64`, from the standard's formulas (IEC 61966-2-1): how the reference turns
//! stored colours into light and its averages of light back into stored values.

/// An encoded channel `c` in `[0, 1]` as linear light.
pub fn decode(c: f64) -> f64 {
    if c <= 0.040_45 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

/// Linear light `l` in `[0, 1]` as an encoded channel: `1.055 p - 0.055` with `p = l^(1/2.4)`, written
/// `p + 0.055 (p - 1)` so that 1 gives exactly 1.
pub fn encode(l: f64) -> f64 {
    if l <= 0.003_130_8 {
        return l * 12.92;
    }
    let p = l.powf(1.0 / 2.4);
    p + 0.055 * (p - 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The two curves invert each other, meet at the ends, and half the light of white is encoded 0.7354.
    #[test]
    fn decode_and_encode_invert_each_other() {
        for i in 0..=1000 {
            let c = f64::from(i) / 1000.0;
            assert!((encode(decode(c)) - c).abs() < 1e-12, "{c}");
        }
        assert_eq!((decode(0.0), decode(1.0), encode(0.0), encode(1.0)), (0.0, 1.0, 0.0, 1.0));
        assert!((encode(0.5) - 0.735_357).abs() < 1e-6);
    }
}
