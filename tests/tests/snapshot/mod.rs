//! The golden-image harness: compares rendered frames with PNG files, writes what failed, and re-blesses.
//!
//! A snapshot named `NAME` is the golden `NAME.png` in a directory (the test files use [`golden_dir`],
//! `tests/snapshots/`, or a folder in it: `effects/` for `effect_snapshots.rs`). When a
//! frame does not match, the harness writes `NAME.actual.png` (the frame) and `NAME.diff.png` (the golden dimmed
//! to grey with the differing pixels in red) beside the golden and reports where they are. With
//! `UPDATE_SNAPSHOTS=1` in the environment ([`Mode::from_env`]), goldens are (re)written instead.

use std::fmt;
use std::fs;
use std::path::{Path, PathBuf};

use rastty_scene::png_file::write_png;

/// The environment variable that turns on blessing.
pub const UPDATE_VARIABLE: &str = "UPDATE_SNAPSHOTS";

/// Largest difference allowed in any channel of any pixel: none. Rendering is designed to be bit-exact on every
/// machine: the core does its non-trivial float maths through `libm`, never the platform's maths library, and Rust
/// never fuses or reorders float operations on its own, so the same scene gives the same pixels on every target
/// and at every optimisation level (debug and release builds give identical images). Any change of any pixel is
/// therefore a change of the renderer, to be looked at and blessed.
pub const TOLERANCE: u8 = 0;

/// Where the goldens live: `tests/snapshots/`.
pub fn golden_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"))
}

/// An RGB frame: `0x00RRGGBB` pixels, row-major, top row first (what `rastty_core::target::Rgb888` holds).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The pixels, `width * height` of them.
    pub pixels: Vec<u32>,
}

impl Image {
    /// Reads an 8-bit PNG file (an alpha channel, if any, is dropped).
    ///
    /// # Errors
    /// A message naming the file when it cannot be read or decoded.
    pub fn read_png(path: &Path) -> Result<Self, String> {
        let bytes = fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let decoded = image::load_from_memory_with_format(&bytes, image::ImageFormat::Png)
            .map_err(|e| format!("cannot decode {}: {e}", path.display()))?
            .into_rgb8();
        let (width, height) = decoded.dimensions();
        let pixels =
            decoded.pixels().map(|p| (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2])).collect();
        Ok(Self { width, height, pixels })
    }

    /// Writes the image as an 8-bit RGB PNG file, creating its directory if needed (a new folder of goldens is
    /// blessed like a new golden).
    ///
    /// # Errors
    /// A message naming the file when it cannot be written.
    pub fn write_png(&self, path: &Path) -> Result<(), String> {
        if let Some(dir) = path.parent() {
            fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        }
        write_png(path, self.width, self.height, &self.pixels).map_err(|e| e.to_string())
    }
}

/// What comparing two images of the same size found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// Pixels with some channel differing by more than the tolerance.
    pub differing: usize,
    /// The largest difference of any channel of any pixel (also within the tolerance).
    pub largest: u8,
}

/// The largest difference between the channels of two `0x00RRGGBB` pixels.
fn channel_difference(a: u32, b: u32) -> u8 {
    [16, 8, 0].into_iter().map(|shift| ((a >> shift) as u8).abs_diff((b >> shift) as u8)).max().unwrap_or(0)
}

/// Compares two images pixel by pixel: a pixel differs when one of its channels differs by more than `tolerance`.
/// `None` when the sizes differ.
pub fn compare(expected: &Image, actual: &Image, tolerance: u8) -> Option<Comparison> {
    if (expected.width, expected.height) != (actual.width, actual.height) {
        return None;
    }
    let mut comparison = Comparison { differing: 0, largest: 0 };
    for (&e, &a) in expected.pixels.iter().zip(&actual.pixels) {
        let d = channel_difference(e, a);
        comparison.largest = comparison.largest.max(d);
        if d > tolerance {
            comparison.differing += 1;
        }
    }
    Some(comparison)
}

/// A picture of where two images of the same size differ: the expected image as grey at a third of its
/// brightness, with each pixel differing by more than `tolerance` in pure red.
pub fn diff_image(expected: &Image, actual: &Image, tolerance: u8) -> Image {
    let pixels = expected
        .pixels
        .iter()
        .zip(&actual.pixels)
        .map(|(&e, &a)| {
            if channel_difference(e, a) > tolerance {
                0x00ff_0000
            } else {
                let (r, g, b) = ((e >> 16) & 0xff, (e >> 8) & 0xff, e & 0xff);
                let grey = (r * 299 + g * 587 + b * 114) / 3000;
                (grey << 16) | (grey << 8) | grey
            }
        })
        .collect();
    Image { width: expected.width, height: expected.height, pixels }
}

/// Whether a check compares with the golden or writes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Compare with the golden; a missing golden is a failure.
    Compare,
    /// Write the golden when it is missing or does not match.
    Bless,
}

impl Mode {
    /// [`Mode::Bless`] when `UPDATE_SNAPSHOTS` is set to anything but empty or `0`, else [`Mode::Compare`].
    pub fn from_env() -> Self {
        match std::env::var_os(UPDATE_VARIABLE) {
            Some(value) if !value.is_empty() && value != "0" => Self::Bless,
            _ => Self::Compare,
        }
    }
}

/// A passed check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Passed {
    /// The image matched the golden.
    Matched,
    /// The golden was written (it was missing or different); only in [`Mode::Bless`].
    Blessed,
}

/// A failed check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// There is no golden (or it cannot be read) and the mode is [`Mode::Compare`].
    Missing {
        /// The golden's path.
        golden: PathBuf,
        /// Why it could not be read.
        reason: String,
        /// Where the image was written, to look at before blessing.
        actual_path: PathBuf,
    },
    /// The image and the golden differ in size.
    Size {
        /// The golden's path.
        golden: PathBuf,
        /// The golden's width and height.
        expected: (u32, u32),
        /// The image's width and height.
        actual: (u32, u32),
        /// Where the image was written.
        actual_path: PathBuf,
    },
    /// Some pixels differ by more than the tolerance.
    Pixels {
        /// The golden's path.
        golden: PathBuf,
        /// What the comparison found.
        comparison: Comparison,
        /// The tolerance used.
        tolerance: u8,
        /// Where the image was written.
        actual_path: PathBuf,
        /// Where the picture of the differences was written.
        diff_path: PathBuf,
    },
    /// A file could not be written.
    Write(String),
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Missing { golden, reason, actual_path } => write!(
                f,
                "no usable golden image {} ({reason}); the image is in {}. If the scene is new or meant to \
                 change, bless it with `{UPDATE_VARIABLE}=1 cargo test -p rastty-tests` and look at the golden \
                 before committing it",
                golden.display(),
                actual_path.display()
            ),
            Self::Size { golden, expected, actual, actual_path } => write!(
                f,
                "the image is {}x{} but the golden {} is {}x{}; the image is in {}",
                actual.0,
                actual.1,
                golden.display(),
                expected.0,
                expected.1,
                actual_path.display()
            ),
            Self::Pixels { golden, comparison, tolerance, actual_path, diff_path } => write!(
                f,
                "{} pixel(s) differ from the golden {} by more than {tolerance} in some channel (largest channel \
                 difference {}); the image is in {} and the differences (in red) in {}",
                comparison.differing,
                golden.display(),
                comparison.largest,
                actual_path.display(),
                diff_path.display()
            ),
            Self::Write(reason) => f.write_str(reason),
        }
    }
}

/// The files of one check: `dir/NAME.png` is the golden, and `dir/NAME{variant}.actual.png` and
/// `dir/NAME{variant}.diff.png` hold what failed (a variant such as `.bands` tells apart several renderings
/// checked against the same golden).
#[derive(Clone, Debug)]
pub struct Snapshot<'a> {
    /// The directory of the golden.
    pub dir: &'a Path,
    /// The snapshot's name.
    pub name: &'a str,
    /// Appended to the name of the failure files; empty for none.
    pub variant: &'a str,
}

impl Snapshot<'_> {
    /// The golden's path.
    pub fn golden(&self) -> PathBuf {
        self.dir.join(format!("{}.png", self.name))
    }

    /// Where a failing image is written.
    pub fn actual(&self) -> PathBuf {
        self.dir.join(format!("{}{}.actual.png", self.name, self.variant))
    }

    /// Where the picture of the differences is written.
    pub fn diff(&self) -> PathBuf {
        self.dir.join(format!("{}{}.diff.png", self.name, self.variant))
    }

    /// Removes the failure files of an earlier run, if any.
    pub fn remove_failure_files(&self) {
        let _ = fs::remove_file(self.actual());
        let _ = fs::remove_file(self.diff());
    }

    /// Checks `image` against the golden with a per-channel `tolerance`.
    ///
    /// In [`Mode::Compare`], a missing golden is a failure (and is not created: only the image is written as the
    /// actual file); a mismatch writes the failure files. In [`Mode::Bless`], a missing or mismatching golden is (re)written; one that matches is left as it
    /// is. A passing check removes failure files left by an earlier run.
    ///
    /// # Errors
    /// [`Failure`] saying what differs and where the failure files are.
    pub fn check(&self, image: &Image, tolerance: u8, mode: Mode) -> Result<Passed, Failure> {
        let golden_path = self.golden();
        let golden = match Image::read_png(&golden_path) {
            Ok(golden) => golden,
            Err(_) if mode == Mode::Bless => return self.bless(image),
            Err(reason) => {
                let actual_path = self.actual();
                image.write_png(&actual_path).map_err(Failure::Write)?;
                let _ = fs::remove_file(self.diff());
                return Err(Failure::Missing { golden: golden_path, reason, actual_path });
            }
        };
        match compare(&golden, image, tolerance) {
            Some(comparison) if comparison.differing == 0 => {
                self.remove_failure_files();
                Ok(Passed::Matched)
            }
            _ if mode == Mode::Bless => self.bless(image),
            None => {
                let actual_path = self.actual();
                image.write_png(&actual_path).map_err(Failure::Write)?;
                let _ = fs::remove_file(self.diff());
                Err(Failure::Size {
                    golden: golden_path,
                    expected: (golden.width, golden.height),
                    actual: (image.width, image.height),
                    actual_path,
                })
            }
            Some(comparison) => {
                let (actual_path, diff_path) = (self.actual(), self.diff());
                image.write_png(&actual_path).map_err(Failure::Write)?;
                diff_image(&golden, image, tolerance).write_png(&diff_path).map_err(Failure::Write)?;
                Err(Failure::Pixels { golden: golden_path, comparison, tolerance, actual_path, diff_path })
            }
        }
    }

    /// Writes `image` as the golden.
    fn bless(&self, image: &Image) -> Result<Passed, Failure> {
        image.write_png(&self.golden()).map_err(Failure::Write)?;
        self.remove_failure_files();
        Ok(Passed::Blessed)
    }
}
