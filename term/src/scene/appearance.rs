//! How a scene is drawn: shading mode, textures, wireframe, background.

use rastty_core::math::Vec3;

/// The shading modes offered to users.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ShadingMode {
    /// Colours and textures, no lighting.
    Unlit,
    /// Lit once per triangle.
    Flat,
    /// Lit per vertex.
    Gouraud,
    /// Lit per pixel.
    #[default]
    Phong,
    /// The depth buffer as grey levels.
    Depth,
    /// Surface normals as colours.
    Normals,
}

impl ShadingMode {
    /// All modes, in the viewer's cycling order.
    pub const ALL: [Self; 6] = [Self::Unlit, Self::Flat, Self::Gouraud, Self::Phong, Self::Depth, Self::Normals];

    /// The mode's name as given on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::Unlit => "unlit",
            Self::Flat => "flat",
            Self::Gouraud => "gouraud",
            Self::Phong => "phong",
            Self::Depth => "depth",
            Self::Normals => "normals",
        }
    }

    /// The next mode in cycling order (the viewer's `m` key).
    pub fn next(self) -> Self {
        let i = Self::ALL.iter().position(|&m| m == self).unwrap_or(0);
        Self::ALL[(i + 1) % Self::ALL.len()]
    }
}

impl std::str::FromStr for ShadingMode {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL.into_iter().find(|m| m.name() == s).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|m| m.name()).collect();
            format!("unknown shading mode {s:?} (expected one of: {})", names.join(", "))
        })
    }
}

/// Everything about a frame's look that is not the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Appearance {
    /// The shading mode.
    pub shading: ShadingMode,
    /// Use the model's textures (when it has texture coordinates and textures).
    pub textures: bool,
    /// Draw triangle edges over the shaded model.
    pub wireframe: bool,
    /// Background colour.
    pub background: Vec3,
}

impl Appearance {
    /// The default background, a dark blue-grey (`#16191f`).
    pub const DEFAULT_BACKGROUND: Vec3 = Vec3::new(22.0 / 255.0, 25.0 / 255.0, 31.0 / 255.0);
}

impl Default for Appearance {
    fn default() -> Self {
        Self { shading: ShadingMode::Phong, textures: true, wireframe: false, background: Self::DEFAULT_BACKGROUND }
    }
}

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
