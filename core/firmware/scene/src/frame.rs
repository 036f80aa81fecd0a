//! A frame, rendered strip by strip through one pair of band buffers with its geometry binned once, and its
//! checksum.

use core::fmt;
use core::ops::Range;

use rastty_core::pipeline::{DrawStats, Strips};
use rastty_core::target::{Rgb565, Samples, Target};

use crate::{Fnv1a, FrameMemory, Layout, Scene, SceneError};

/// Frame width in pixels.
pub const WIDTH: u32 = 320;
/// Frame height in pixels.
pub const HEIGHT: u32 = 240;

/// One finished strip of the frame, as a display would receive it.
#[derive(Clone, Debug)]
pub struct Strip<'a> {
    /// The frame rows it holds.
    pub rows: Range<u32>,
    /// Its RGB565 pixels, row-major, `WIDTH * rows.len()` of them.
    pub pixels: &'a [u16],
}

/// Renders frame `frame` in the strips of `layout` through `memory`, handing each finished strip to `show`, top to
/// bottom: bins the triangles once, then draws each strip from the bins. Returns the number of strips and the
/// draw counts: binning's, with the strips' fragments.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// A [`SceneError`] if the mesh, the camera, a band or a draw fails (none does).
pub fn render_frame(
    frame: usize,
    layout: Layout,
    memory: &mut FrameMemory,
    mut show: impl FnMut(&Strip<'_>),
) -> Result<(u32, DrawStats), SceneError> {
    let scene = Scene::new(frame)?;
    let strips = Strips::new(WIDTH, HEIGHT, layout.band_rows, Samples::One).map_err(SceneError::Target)?;
    let FrameMemory { color, depth, bins } = memory;
    let bins = scene.bin(bins, strips)?;
    let mut stats = bins.stats();
    for strip in 0..strips.count() {
        let rows = strips.rows(strip);
        let len = (WIDTH * rows.len() as u32) as usize;
        let mut band = Target::band(Rgb565(&mut color[..len]), &mut depth[..len], WIDTH, HEIGHT, rows.clone())
            .map_err(SceneError::Target)?;
        stats.fragments += scene.draw_strip(&mut band, &bins)?.fragments;
        show(&Strip { rows, pixels: &color[..len] });
    }
    Ok((strips.count(), stats))
}

/// Renders frame `frame` and folds every strip, as it is finished, into the frame's [`Fnv1a`] checksum: the
/// checksum is the firmware's display.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// As [`render_frame`].
pub fn checksum_frame(frame: usize, layout: Layout, memory: &mut FrameMemory) -> Result<FrameReport, SceneError> {
    let mut checksum = Fnv1a::new();
    let (strips, stats) = render_frame(frame, layout, memory, |strip| checksum.write_rgb565(strip.pixels))?;
    Ok(FrameReport { frame, layout, checksum: checksum.finish(), strips, stats })
}

/// What rendering a frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameReport {
    /// The frame's index.
    pub frame: usize,
    /// The memory layout it was rendered in.
    pub layout: Layout,
    /// [`Fnv1a`] of the frame's pixels.
    pub checksum: u32,
    /// Strips rendered and checksummed.
    pub strips: u32,
    /// Triangle counts from binning, fragments summed over the strips.
    pub stats: DrawStats,
}

impl fmt::Display for FrameReport {
    /// The line that the firmware and the host both print, and `check.sh` compares:
    /// `frame 0 in 16 KiB: checksum 0x1234abcd, 60 strips, 24680 fragments`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "frame {} in {} KiB: checksum 0x{:08x}, {} strips, {} fragments",
            self.frame, self.layout.budget_kib, self.checksum, self.strips, self.stats.fragments
        )
    }
}
