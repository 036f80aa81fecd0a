//! A frame, rendered strip by strip through one pair of band buffers, and its checksum.

use core::fmt;
use core::ops::Range;

use rastty_core::pipeline::DrawStats;
use rastty_core::target::{Rgb565, Target};

use crate::{BandBuffers, Fnv1a, Scene, SceneError};

/// Frame width in pixels.
pub const WIDTH: u32 = 320;
/// Frame height in pixels.
pub const HEIGHT: u32 = 240;
/// Rows per strip. The last strip is shorter when this does not divide [`HEIGHT`] (here it does).
pub const BAND_ROWS: u32 = 12;
/// Strips per frame.
pub const STRIPS: u32 = HEIGHT.div_ceil(BAND_ROWS);

/// One finished strip of the frame, as a display would receive it.
#[derive(Clone, Debug)]
pub struct Strip<'a> {
    /// The frame rows it holds.
    pub rows: Range<u32>,
    /// Its RGB565 pixels, row-major, `WIDTH * rows.len()` of them.
    pub pixels: &'a [u16],
}

/// Renders frame `frame` strip by strip through `buffers`, handing each finished strip to `show`, top to bottom.
/// Returns the number of strips and the draw counts summed over them.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// A [`SceneError`] if the mesh, the camera, a band or a draw fails (none does).
pub fn render_frame(
    frame: usize,
    buffers: &mut BandBuffers,
    mut show: impl FnMut(&Strip<'_>),
) -> Result<(u32, DrawStats), SceneError> {
    let scene = Scene::new(frame)?;
    let mut stats = DrawStats::default();
    let mut strips = 0;
    for y0 in (0..HEIGHT).step_by(BAND_ROWS as usize) {
        let y1 = (y0 + BAND_ROWS).min(HEIGHT);
        let len = (WIDTH * (y1 - y0)) as usize;
        let BandBuffers { color, depth } = buffers;
        let mut band = Target::band(Rgb565(&mut color[..len]), &mut depth[..len], WIDTH, HEIGHT, y0..y1)
            .map_err(SceneError::Target)?;
        stats += scene.draw(&mut band)?;
        show(&Strip { rows: y0..y1, pixels: &color[..len] });
        strips += 1;
    }
    Ok((strips, stats))
}

/// Renders frame `frame` and folds every strip, as it is finished, into the frame's [`Fnv1a`] checksum: the
/// checksum is the firmware's display.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// As [`render_frame`].
pub fn checksum_frame(frame: usize, buffers: &mut BandBuffers) -> Result<FrameReport, SceneError> {
    let mut checksum = Fnv1a::new();
    let (strips, stats) = render_frame(frame, buffers, |strip| checksum.write_rgb565(strip.pixels))?;
    Ok(FrameReport { frame, checksum: checksum.finish(), strips, stats })
}

/// What rendering a frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameReport {
    /// The frame's index.
    pub frame: usize,
    /// [`Fnv1a`] of the frame's pixels.
    pub checksum: u32,
    /// Strips rendered and checksummed.
    pub strips: u32,
    /// Triangle and fragment counts, summed over the strips (each strip draws the whole mesh).
    pub stats: DrawStats,
}

impl fmt::Display for FrameReport {
    /// The line that the firmware and the host both print, and `check.sh` compares:
    /// `frame 0: checksum 0x1234abcd, 20 strips, 24680 fragments`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "frame {}: checksum 0x{:08x}, {} strips, {} fragments",
            self.frame, self.checksum, self.strips, self.stats.fragments
        )
    }
}
