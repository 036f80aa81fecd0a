//! The colour of one side (foreground or background) of a terminal cell.

/// A cell colour as the terminal is told it: a 24-bit colour, a palette index, or the terminal's default.
///
/// `Indexed(0..=15)` are the 16 ANSI colours (sent as `30-37`/`90-97` and `40-47`/`100-107`);
/// `Indexed(16..=255)` are the xterm 256-colour cube and grey ramp (sent as `38;5;n`/`48;5;n`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Color {
    /// 24-bit colour, sent as `38;2;r;g;b` / `48;2;r;g;b`.
    Rgb(u8, u8, u8),
    /// A palette index.
    Indexed(u8),
    /// The terminal's default foreground or background (`39` / `49`).
    #[default]
    Default,
}

impl Color {
    /// The colour of a renderer pixel `0x00RRGGBB` (the top byte is ignored).
    #[inline]
    pub const fn from_pixel(pixel: u32) -> Self {
        let [_, r, g, b] = pixel.to_be_bytes();
        Color::Rgb(r, g, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_channels_are_unpacked_in_rgb_order() {
        assert_eq!(Color::from_pixel(0x00_12_34_56), Color::Rgb(0x12, 0x34, 0x56));
        assert_eq!(Color::from_pixel(0xFF_00_00_01), Color::Rgb(0, 0, 1));
    }
}
