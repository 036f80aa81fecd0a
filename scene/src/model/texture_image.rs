//! Decoded texture images (PNG, TGA, JPEG) as the core's `0xTTRRGGBB` texels (`TT`: transparency).

use std::io::Cursor;
use std::path::Path;
use std::sync::OnceLock;

use image::{ImageFormat, ImageReader, Limits};
use rastty_core::texture::{MipContent, Texture, TextureError, build_mip_levels, mip_chain_texels};

use super::error::{LoadError, LoadErrorKind};
use crate::input_file::read_input_file;

/// The largest width and height accepted for a texture.
pub const MAX_TEXTURE_SIDE: u32 = 16384;

/// An owned texture: `width * height` texels, `0xTTRRGGBB` with the transparency `255 - alpha` in the top byte
/// (so opaque texels are `0x00RRGGBB`), row-major with row 0 the top of the image (what
/// [`rastty_core::texture::Texture::new`] takes), and its levels of detail once a draw has asked for them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextureImage {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// The texels, top row first. Change them only before the image is first drawn: its levels of detail are
    /// built from them then ([`Self::mipmapped`]).
    pub texels: Vec<u32>,
    /// The levels of detail below the image, built once, on first use, as the content of that use says.
    levels: OnceLock<Vec<u32>>,
}

impl TextureImage {
    /// An image of `width x height` `texels` (top row first).
    pub fn new(width: u32, height: u32, texels: Vec<u32>) -> Self {
        Self { width, height, texels, levels: OnceLock::new() }
    }

    /// Reads and decodes the image file at `path`.
    ///
    /// # Errors
    /// [`LoadErrorKind::Io`] when the file cannot be read, [`LoadErrorKind::Image`] when it cannot be decoded.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, LoadError> {
        let path = path.as_ref();
        let bytes = read_input_file(path).map_err(|e| LoadError::new(path, LoadErrorKind::Io(e)))?;
        Self::decode(path, &bytes)
    }

    /// Decodes an image held in memory. The format is recognised from the signature of the contents (PNG, JPEG) or,
    /// failing that, from the extension of `name` (TGA has no signature). Every colour type is converted to RGBA: grey is
    /// replicated, palettes expanded, 16-bit channels reduced, and alpha (255 without one) kept as the texels'
    /// transparency, read only by alpha cut-outs. `name` is only used to
    /// guess the format and in the error.
    ///
    /// # Errors
    /// [`LoadErrorKind::Image`] when the format is unknown or unsupported, the data is corrupt or truncated, or the
    /// image is empty or wider or higher than [`MAX_TEXTURE_SIDE`].
    pub fn decode(name: &Path, bytes: &[u8]) -> Result<Self, LoadError> {
        let fail = |reason: String| LoadError::new(name, LoadErrorKind::Image(reason));
        // Only PNG's and JPEG's signatures are trusted: TGA has none, and a colour-mapped TGA starts with the bytes
        // of the ICO signature.
        let signature = image::guess_format(bytes).ok().filter(|f| matches!(f, ImageFormat::Png | ImageFormat::Jpeg));
        let format = signature.or_else(|| ImageFormat::from_path(name).ok());
        let Some(format) = format else {
            return Err(fail("unknown image format (expected PNG, JPEG or TGA)".into()));
        };
        let mut reader = ImageReader::with_format(Cursor::new(bytes), format);
        let mut limits = Limits::default();
        limits.max_image_width = Some(MAX_TEXTURE_SIDE);
        limits.max_image_height = Some(MAX_TEXTURE_SIDE);
        reader.limits(limits);
        let rgba = reader.decode().map_err(|e| fail(e.to_string()))?.into_rgba8();
        let (width, height) = rgba.dimensions();
        if width == 0 || height == 0 {
            return Err(fail(format!("the image is empty ({width}x{height})")));
        }
        // The core's texels: transparency (255 - alpha) in the top byte, so opaque texels are `0x00RRGGBB`.
        let texels = rgba
            .as_raw()
            .chunks_exact(4)
            .map(|p| (u32::from(255 - p[3]) << 24) | (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]))
            .collect();
        Ok(Self::new(width, height, texels))
    }

    /// The core's view of this texture alone, for sampling.
    ///
    /// # Errors
    /// [`TextureError`] when the fields are inconsistent (only possible if they were changed by hand).
    pub fn texture(&self) -> Result<Texture<'_>, TextureError> {
        Texture::new(&self.texels, self.width, self.height)
    }

    /// The core's view of this texture with its levels of detail, for mipmapped sampling: built on the first call
    /// (about 150 million instructions for a 1024x1024 colour map, docs/performance.md) from texels that mean
    /// `content`, and kept. An image used both as colour and as data (rare) keeps the levels of its first use.
    ///
    /// # Errors
    /// [`TextureError`] when the fields are inconsistent (only possible if they were changed by hand).
    pub fn mipmapped(&self, content: MipContent) -> Result<Texture<'_>, TextureError> {
        self.texture()?.with_mip_levels(self.mip_levels(content)?)
    }

    /// The levels of detail below this image ([`build_mip_levels`]), built on the first call from texels that mean
    /// `content`.
    ///
    /// # Errors
    /// [`TextureError`] when the fields are inconsistent (only possible if they were changed by hand).
    pub(crate) fn mip_levels(&self, content: MipContent) -> Result<&[u32], TextureError> {
        let texture = self.texture()?;
        let levels = self.levels.get_or_init(|| {
            let mut levels = vec![0; mip_chain_texels(self.width, self.height)];
            // Of the right length for a texture just made: it cannot fail.
            let _ = build_mip_levels(&texture, content, &mut levels);
            levels
        });
        Ok(levels)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_formats_are_errors_naming_the_file() {
        let e = TextureImage::decode(Path::new("t/x.dat"), b"not an image").unwrap_err();
        assert!(e.to_string().starts_with("t/x.dat: cannot decode the image: unknown image format"), "{e}");
        let e = TextureImage::decode(Path::new("t/x.bmp"), b"BM not compiled in").unwrap_err();
        assert!(e.to_string().starts_with("t/x.bmp: cannot decode the image: "), "{e}");
    }

    #[test]
    fn truncated_tga_is_an_error() {
        // A 2x2 24-bit header with only one pixel of data.
        let mut tga = vec![0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0x20];
        tga.extend_from_slice(&[1, 2, 3]);
        assert!(TextureImage::decode(Path::new("a.tga"), &tga).is_err());
    }

    #[test]
    fn oversized_dimensions_are_refused_before_decoding() {
        // 65535 x 65535, 24-bit, no data.
        let tga = [0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 24, 0x20];
        assert!(TextureImage::decode(Path::new("big.tga"), &tga).is_err());
    }

    #[test]
    fn texture_view_matches() {
        let t = TextureImage::new(2, 1, vec![0xFF0000, 0x00FF00]);
        assert_eq!(t.texture().unwrap().width(), 2);
        // One level below, the linear-light average of red and green, built once for the first content asked.
        assert_eq!(t.mip_levels(MipContent::Color).unwrap(), [0xBC_BC00]);
        assert_eq!(t.mip_levels(MipContent::Data).unwrap(), [0xBC_BC00]);
        assert_eq!(t.mipmapped(MipContent::Color).unwrap().mip_chain().level_count(), 2);
    }
}
