//! Surface materials from MTL files: a diffuse colour and an optional texture.

use rastty_core::math::Vec3;

use super::texture_image::TextureImage;

/// The diffuse colour of a material whose MTL entry has no (usable) `Kd`, and of parts without a material.
pub const DEFAULT_DIFFUSE: Vec3 = Vec3::splat(0.8);

/// A material: what the renderer needs of an MTL `newmtl` entry.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// The name given by `newmtl`, raw (it may hold control characters: sanitise before printing).
    pub name: String,
    /// Diffuse colour (`Kd`), each component clamped to `[0, 1]`; [`DEFAULT_DIFFUSE`] when absent or not finite.
    pub diffuse: Vec3,
    /// The diffuse texture (`map_Kd`), when it names a file that could be read and decoded.
    pub texture: Option<TextureImage>,
}

impl Default for Material {
    /// An unnamed, untextured material of [`DEFAULT_DIFFUSE`].
    fn default() -> Self {
        Self { name: String::new(), diffuse: DEFAULT_DIFFUSE, texture: None }
    }
}

/// The diffuse colour for a `Kd` entry, or `None` when it is present but not finite (use the default and warn).
pub(crate) fn diffuse_from_kd(kd: Option<[f32; 3]>) -> Option<Vec3> {
    match kd {
        None => Some(DEFAULT_DIFFUSE),
        Some(c) if c.iter().all(|v| v.is_finite()) => {
            Some(Vec3::new(c[0].clamp(0.0, 1.0), c[1].clamp(0.0, 1.0), c[2].clamp(0.0, 1.0)))
        }
        Some(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kd_is_clamped_defaulted_or_refused() {
        assert_eq!(diffuse_from_kd(None), Some(DEFAULT_DIFFUSE));
        assert_eq!(diffuse_from_kd(Some([0.25, 2.0, -1.0])), Some(Vec3::new(0.25, 1.0, 0.0)));
        assert_eq!(diffuse_from_kd(Some([f32::NAN, 0.0, 0.0])), None);
    }
}
