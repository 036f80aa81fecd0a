//! Writing PNG files without ever leaving a partial file behind.

use std::fmt;
use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use image::ImageEncoder;
use image::codecs::png::PngEncoder;

/// Why a PNG file could not be written.
#[derive(Debug)]
pub struct PngError {
    /// The file that was to be written.
    pub path: PathBuf,
    /// What went wrong.
    pub reason: String,
}

impl fmt::Display for PngError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write {}: {}", crate::escaped::path_text(&self.path), self.reason)
    }
}

impl std::error::Error for PngError {}

/// Writes `0x00RRGGBB` pixels (row-major, top row first) as an 8-bit RGB PNG.
///
/// The image goes to a temporary file in the same directory, which is renamed over `path` only once it is
/// complete, so `path` is either the whole new image or untouched.
///
/// # Errors
/// [`PngError`] naming the path: the directory does not exist or is not writable, the disk is full, or the pixel
/// count does not match the size.
pub fn write_png(path: &Path, width: u32, height: u32, pixels: &[u32]) -> Result<(), PngError> {
    let fail = |reason: String| PngError { path: path.to_path_buf(), reason };
    if pixels.len() != width as usize * height as usize {
        return Err(fail(format!("{} pixels given for a {width}x{height} image", pixels.len())));
    }
    if path.is_dir() || path.as_os_str().to_string_lossy().ends_with(std::path::MAIN_SEPARATOR) {
        return Err(fail("it is a directory, not a file name".into()));
    }
    write_atomically(path, |out| encode_png(out, width, height, pixels)).map_err(|e| fail(e.to_string()))
}

/// Encodes `0x00RRGGBB` pixels (row-major, top row first) as an 8-bit RGB PNG into `out`.
///
/// # Errors
/// The first I/O error, or an encoder error (the pixel count does not match the size) as [`io::ErrorKind::Other`].
pub fn encode_png(out: &mut impl Write, width: u32, height: u32, pixels: &[u32]) -> io::Result<()> {
    let rgb: Vec<u8> = pixels.iter().flat_map(|p| [(p >> 16) as u8, (p >> 8) as u8, *p as u8]).collect();
    PngEncoder::new(out).write_image(&rgb, width, height, image::ExtendedColorType::Rgb8).map_err(io::Error::other)
}

/// Writes a file through `write` into a temporary file in the same directory, synced and then renamed over
/// `path`: `path` is either the whole new file or untouched. The temporary file is removed on failure.
///
/// # Errors
/// The first I/O error.
pub fn write_atomically(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> io::Result<()> {
    let temporary = temporary_path(path);
    let result = (|| -> io::Result<()> {
        let mut out = BufWriter::new(File::create(&temporary)?);
        write(&mut out)?;
        out.flush()?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()?;
        fs::rename(&temporary, path)
    })();
    if result.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// `dir/.name.tmp-PID` beside `path`.
fn temporary_path(path: &Path) -> PathBuf {
    let name = path.file_name().map_or_else(|| "image".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}
