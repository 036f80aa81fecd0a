//! Environment images: an equirectangular panorama read from a Radiance `.hdr` file (linear light, any
//! brightness) or a PNG or JPEG (sRGB, decoded to linear light), checked and clamped.

use std::io::Cursor;
use std::path::Path;

use image::{ImageFormat, ImageReader, Limits};
use rastty_core::color::srgb_to_linear;
use rastty_core::math::Vec3;

use crate::input_file::read_input_file;
use crate::model::{LoadError, LoadErrorKind};

/// The widest environment image accepted: 4096x2048 texels, 100 MB of linear light once decoded (held twice while
/// it is converted). The program averages it down to 256x128 texels (the default prefiltering), so a larger image
/// would add memory and time and nothing a picture shows.
pub const MAX_PANORAMA_WIDTH: u32 = 4096;

/// The brightest light an environment texel keeps (the largest finite half-precision float, what `.hdr` files
/// are usually made for): brighter values are lowered to it, so that sums over the panorama stay finite.
pub const MAX_RADIANCE: f32 = 65504.0;

/// A decoded environment image: `width x height` texels of linear light, row by row from the top, `width` twice
/// `height`.
#[derive(Clone, Debug, PartialEq)]
pub struct PanoramaImage {
    /// Texels across.
    pub width: u32,
    /// Texels down.
    pub height: u32,
    /// The texels, linear light, each component finite, from 0 to [`MAX_RADIANCE`].
    pub texels: Vec<Vec3>,
    /// Texels whose values were not finite, negative or above [`MAX_RADIANCE`], and were clamped.
    pub clamped: usize,
}

impl PanoramaImage {
    /// Reads and decodes the environment image at `path`.
    ///
    /// # Errors
    /// [`LoadErrorKind::Io`] when the file cannot be read, [`LoadErrorKind::Image`] as [`Self::decode`].
    pub fn load(path: &Path) -> Result<Self, LoadError> {
        let bytes = read_input_file(path).map_err(|e| LoadError::new(path, LoadErrorKind::Io(e)))?;
        Self::decode(path, &bytes)
    }

    /// Decodes an environment image held in memory: Radiance `.hdr` (recognised by its signature, `#?RADIANCE` or
    /// `#?RGBE`), PNG or JPEG (by theirs). `name` is used in errors only.
    ///
    /// # Errors
    /// [`LoadErrorKind::Image`] when the format is not one of these, the data is corrupt or truncated, the image is
    /// empty, wider than [`MAX_PANORAMA_WIDTH`], or not twice as wide as it is tall.
    pub fn decode(name: &Path, bytes: &[u8]) -> Result<Self, LoadError> {
        let fail = |reason: String| LoadError::new(name, LoadErrorKind::Image(reason));
        let format = match image::guess_format(bytes) {
            Ok(format @ (ImageFormat::Hdr | ImageFormat::Png | ImageFormat::Jpeg)) => format,
            _ => return Err(fail("unknown environment image format (expected Radiance .hdr, PNG or JPEG)".into())),
        };
        let mut reader = ImageReader::with_format(Cursor::new(bytes), format);
        let mut limits = Limits::default();
        limits.max_image_width = Some(MAX_PANORAMA_WIDTH);
        limits.max_image_height = Some(MAX_PANORAMA_WIDTH / 2);
        reader.limits(limits);
        let decoded = reader.decode().map_err(|e| fail(e.to_string()))?;
        let (width, height) = (decoded.width(), decoded.height());
        if width == 0 || height == 0 {
            return Err(fail(format!("the environment image is empty ({width}x{height})")));
        }
        if Some(width) != height.checked_mul(2) {
            return Err(fail(format!(
                "an environment image is an equirectangular panorama, twice as wide as it is tall, not {width}x{height}"
            )));
        }
        let mut clamped = 0;
        let texels: Vec<Vec3> = if format == ImageFormat::Hdr {
            let rgb = decoded.into_rgb32f();
            rgb.as_raw()
                .chunks_exact(3)
                .map(|p| {
                    let (texel, changed) = clamp_radiance(Vec3::new(p[0], p[1], p[2]));
                    clamped += usize::from(changed);
                    texel
                })
                .collect()
        } else {
            let rgb = decoded.into_rgb8();
            rgb.as_raw()
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0].into(), p[1].into(), p[2].into()).map(|c| srgb_to_linear(c / 255.0)))
                .collect()
        };
        Ok(Self { width, height, texels, clamped })
    }
}

/// `texel` with each component that is not finite made 0 and each one kept within `[0, MAX_RADIANCE]`, and
/// whether any changed.
fn clamp_radiance(texel: Vec3) -> (Vec3, bool) {
    let clamped = texel.map(|c| if c.is_finite() { c.clamp(0.0, MAX_RADIANCE) } else { 0.0 });
    let changed = clamped.x.to_bits() != texel.x.to_bits()
        || clamped.y.to_bits() != texel.y.to_bits()
        || clamped.z.to_bits() != texel.z.to_bits();
    (clamped, changed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_out_of_range_are_clamped() {
        assert_eq!(clamp_radiance(Vec3::new(0.5, 1.0, 2.0)), (Vec3::new(0.5, 1.0, 2.0), false));
        assert_eq!(clamp_radiance(Vec3::new(f32::NAN, -1.0, 1e30)), (Vec3::new(0.0, 0.0, MAX_RADIANCE), true));
        assert_eq!(clamp_radiance(Vec3::new(f32::INFINITY, 0.0, 0.0)), (Vec3::ZERO, true));
    }
}
