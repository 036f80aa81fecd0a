//! Colours written `RRGGBB`: a scene file's `background` and the `--background` option.

use rastty_core::math::Vec3;

/// Parses a colour written `RRGGBB` (an optional leading `#` is accepted).
///
/// # Errors
/// A message naming the text when it is not six hexadecimal digits.
pub fn parse_hex_color(text: &str) -> Result<Vec3, String> {
    let hex = text.strip_prefix('#').unwrap_or(text);
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(format!("{text:?} is not a colour written RRGGBB"));
    }
    let value = u32::from_str_radix(hex, 16).map_err(|e| e.to_string())?;
    Ok(rastty_core::color::unpack_rgb888(value))
}
