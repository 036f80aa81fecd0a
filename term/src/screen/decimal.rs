//! ASCII decimal digits for the numbers inside escape sequences, written without allocation or `fmt`.

/// Appends the decimal digits of `n` to `out`.
#[inline]
pub(crate) fn write_decimal(out: &mut Vec<u8>, n: u32) {
    if n < 10 {
        out.push(b'0' + n as u8);
        return;
    }
    let mut digits = [0u8; 10];
    let mut i = digits.len();
    let mut rest = n;
    while rest > 0 {
        i -= 1;
        digits[i] = b'0' + (rest % 10) as u8;
        rest /= 10;
    }
    for &digit in &digits[i..] {
        out.push(digit);
    }
}

/// Appends the decimal digits of a byte value, one push per digit (no `memcpy` call for 1-3 bytes).
#[inline]
pub(crate) fn write_u8_decimal(out: &mut Vec<u8>, n: u8) {
    if n >= 100 {
        out.push(b'0' + n / 100);
    }
    if n >= 10 {
        out.push(b'0' + (n / 10) % 10);
    }
    out.push(b'0' + n % 10);
}

/// How many bytes [`write_decimal`] appends for `n`.
#[inline]
pub(crate) const fn decimal_len(n: u32) -> usize {
    match n {
        0..=9 => 1,
        10..=99 => 2,
        100..=999 => 3,
        1000..=9999 => 4,
        10_000..=99_999 => 5,
        _ => {
            let mut len = 6;
            let mut rest = n / 1_000_000;
            while rest > 0 {
                len += 1;
                rest /= 10;
            }
            len
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_match_std_formatting() {
        let samples = (0..2000).chain([9_999, 10_000, 99_999, 100_000, 999_999, 1_000_000, 12_345_678, u32::MAX]);
        for n in samples {
            let mut out = Vec::new();
            write_decimal(&mut out, n);
            assert_eq!(out, n.to_string().into_bytes(), "{n}");
            assert_eq!(decimal_len(n), out.len(), "{n}");
        }
        for n in 0..=255u8 {
            let mut out = Vec::new();
            write_u8_decimal(&mut out, n);
            assert_eq!(out, n.to_string().into_bytes(), "{n}");
        }
    }
}
