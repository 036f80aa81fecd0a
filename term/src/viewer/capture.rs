//! `c` in the viewer: the current view saved as a PNG file in the current directory, under a name that overwrites
//! nothing.

use std::fs::{self, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// The most captures of one model in one folder (`NAME-0001.png` to `NAME-9999.png`).
pub const MAX_CAPTURES: u32 = 9999;
/// The longest side a capture has by default (the terminal's pixels doubled, cut to this).
pub const MAX_DEFAULT_SIDE: u32 = 4096;
/// The pixels of a cell whose size the terminal does not say: 8 wide (and the cell aspect times 8 high).
const ASSUMED_CELL_WIDTH: f32 = 8.0;

/// The start of a capture's file name for the model or scene `name` (a path, or `builtin:spot`): its file name
/// without the extension, each character other than an ASCII letter, digit, `-`, `_` or `.` made `_`, at most 64
/// of them; `rastty` when nothing is left.
pub fn capture_stem(name: &str) -> String {
    let file = name.rsplit(['/', ':']).next().unwrap_or(name);
    let stem = Path::new(file).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let kept: String = stem
        .chars()
        .take(64)
        .map(|c| if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') { c } else { '_' })
        .collect();
    let kept = kept.trim_start_matches('.');
    if kept.is_empty() { "rastty".to_owned() } else { kept.to_owned() }
}

/// The size of a capture: `given` (`--size`), else twice the terminal's text area in pixels (`pixels`, when the
/// terminal says; else its `cells` of 8 by 8 times `cell_aspect` pixels), scaled down to at most
/// [`MAX_DEFAULT_SIDE`] on the longer side.
pub fn capture_size(
    given: Option<(u32, u32)>,
    pixels: Option<(u16, u16)>,
    cells: (u16, u16),
    cell_aspect: f32,
) -> (u32, u32) {
    if let Some(size) = given {
        return size;
    }
    let (width, height) = match pixels {
        Some((w, h)) => (f32::from(w), f32::from(h)),
        None => {
            let (cols, rows) = (f32::from(cells.0), f32::from(cells.1));
            (cols * ASSUMED_CELL_WIDTH, rows * ASSUMED_CELL_WIDTH * cell_aspect)
        }
    };
    let (width, height) = (2.0 * width.max(1.0), 2.0 * height.max(1.0));
    let scale = (MAX_DEFAULT_SIDE as f32 / width.max(height)).min(1.0);
    ((width * scale).round().max(1.0) as u32, (height * scale).round().max(1.0) as u32)
}

/// Writes `bytes` to the first of `dir/STEM-0001.png` to `dir/STEM-9999.png` that does not exist, created
/// exclusively (a file that appears meanwhile is not overwritten either); returns its path. A file that could not
/// be written whole is removed.
///
/// # Errors
/// The first error other than an existing name, or [`io::ErrorKind::AlreadyExists`] when every name is taken.
pub fn save_new(dir: &Path, stem: &str, bytes: &[u8]) -> io::Result<PathBuf> {
    for n in 1..=MAX_CAPTURES {
        let path = dir.join(format!("{stem}-{n:04}.png"));
        let mut file = match OpenOptions::new().write(true).create_new(true).open(&path) {
            Ok(file) => file,
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        };
        if let Err(e) = file.write_all(bytes).and_then(|()| file.sync_all()) {
            drop(file);
            let _ = fs::remove_file(&path);
            return Err(e);
        }
        return Ok(path);
    }
    Err(io::Error::new(io::ErrorKind::AlreadyExists, format!("{stem}-0001.png to {stem}-{MAX_CAPTURES}.png all exist")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stems_keep_safe_characters_of_the_file_name() {
        assert_eq!(capture_stem("models/spot.obj"), "spot");
        assert_eq!(capture_stem("builtin:spot"), "spot");
        assert_eq!(capture_stem("a b/c\u{1b}[2Jd.glb"), "c__2Jd");
        assert_eq!(capture_stem("/"), "rastty");
        assert_eq!(capture_stem(".hidden.obj"), "hidden");
        assert_eq!(capture_stem(&"x".repeat(300)).len(), 64);
    }

    #[test]
    fn the_size_is_given_or_twice_the_terminals_pixels_within_the_cap() {
        assert_eq!(capture_size(Some((320, 200)), Some((1000, 500)), (100, 30), 2.0), (320, 200));
        assert_eq!(capture_size(None, Some((800, 480)), (100, 30), 2.0), (1600, 960));
        // 100 x 30 cells of 8 x 16 pixels.
        assert_eq!(capture_size(None, None, (100, 30), 2.0), (1600, 960));
        assert_eq!(capture_size(None, Some((4000, 1000)), (100, 30), 2.0), (4096, 1024));
    }

    #[test]
    fn saving_never_overwrites() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("m-0001.png"), b"kept").unwrap();
        let first = save_new(dir.path(), "m", b"one").unwrap();
        let second = save_new(dir.path(), "m", b"two").unwrap();
        assert_eq!(
            (first.file_name().unwrap(), second.file_name().unwrap()),
            ("m-0002.png".as_ref(), "m-0003.png".as_ref())
        );
        assert_eq!(fs::read(dir.path().join("m-0001.png")).unwrap(), b"kept");
        assert_eq!(fs::read(second).unwrap(), b"two");
        let missing = save_new(&dir.path().join("gone"), "m", b"x").unwrap_err();
        assert_eq!(missing.kind(), io::ErrorKind::NotFound);
    }
}
