//! Writing PNG files (and any other file) without ever leaving a partial file behind.

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
    PngEncoder::new(out)
        .write_image(&rgb8(pixels), width, height, image::ExtendedColorType::Rgb8)
        .map_err(io::Error::other)
}

/// `0x00RRGGBB` pixels as bytes `R, G, B, R, G, B, ...`.
pub fn rgb8(pixels: &[u32]) -> Vec<u8> {
    pixels.iter().flat_map(|p| [(p >> 16) as u8, (p >> 8) as u8, *p as u8]).collect()
}

/// Writes a file through `write` into a temporary file in the same directory, synced and then renamed over
/// `path`: `path` is either the whole new file or untouched. The temporary file is removed on failure.
///
/// # Errors
/// The first I/O error, or the first error of `write`.
pub fn write_atomically<E: From<io::Error>>(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<(), E>,
) -> Result<(), E> {
    PendingFile::write(path, write)?.commit().map_err(E::from)
}

/// A whole file written beside its path, not yet in its place: [`PendingFile::commit`] renames it over the path,
/// and dropping it uncommitted removes it. Files that must appear together (a numbered sequence of frames) are
/// written as pending files first and committed once all of them are complete.
#[derive(Debug)]
pub struct PendingFile {
    /// Where the file goes.
    path: PathBuf,
    /// Where it is meanwhile (`dir/.name.tmp-PID`).
    temporary: PathBuf,
    /// Renamed into place: nothing for `drop` to remove.
    committed: bool,
}

impl PendingFile {
    /// Writes a file through `write` into a temporary file in the directory of `path` and syncs it; nothing is
    /// at `path` yet. The temporary file is removed on failure.
    ///
    /// # Errors
    /// The first I/O error, or the first error of `write`.
    pub fn write<E: From<io::Error>>(
        path: &Path,
        write: impl FnOnce(&mut BufWriter<File>) -> Result<(), E>,
    ) -> Result<Self, E> {
        let temporary = temporary_path(path);
        let file = File::create(&temporary)?;
        // From here on, dropping `pending` removes the temporary file: a failure below leaves nothing behind.
        let pending = Self { path: path.to_path_buf(), temporary, committed: false };
        let mut out = BufWriter::new(file);
        write(&mut out)?;
        out.flush()?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()?;
        Ok(pending)
    }

    /// The path the file is renamed to.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Renames the file over its path.
    ///
    /// # Errors
    /// The rename's I/O error (the temporary file is then removed).
    pub fn commit(mut self) -> io::Result<()> {
        fs::rename(&self.temporary, &self.path)?;
        self.committed = true;
        Ok(())
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if !self.committed {
            let _ = fs::remove_file(&self.temporary);
        }
    }
}

/// `dir/.name.tmp-PID` beside `path`.
fn temporary_path(path: &Path) -> PathBuf {
    let name = path.file_name().map_or_else(|| "image".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> =
            fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    #[test]
    fn a_pending_file_appears_only_when_committed() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("frame.png");
        let pending = PendingFile::write(&path, |out| out.write_all(b"whole")).unwrap();
        assert_eq!(pending.path(), path);
        assert!(!path.exists());
        assert_eq!(names(dir.path()), [format!(".frame.png.tmp-{}", std::process::id())]);
        pending.commit().unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"whole");
        assert_eq!(names(dir.path()), ["frame.png"]);

        // Dropped uncommitted, or failed while writing: nothing is left, and the file in place is untouched.
        drop(PendingFile::write(&dir.path().join("other.png"), |out| out.write_all(b"x")).unwrap());
        let failed = write_atomically(&path, |out| {
            out.write_all(b"half")?;
            Err(io::Error::other("the renderer failed"))
        });
        assert_eq!(failed.unwrap_err().to_string(), "the renderer failed");
        assert_eq!(names(dir.path()), ["frame.png"]);
        assert_eq!(fs::read(&path).unwrap(), b"whole");
    }
}
