//! A frame, rendered band by band through one pair of band buffers with its geometry binned once, and its
//! checksum.

use core::convert::Infallible;
use core::fmt;

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::pixelcolor::Rgb565;
use rastty_core::pipeline::{Bands, DrawStats};
use rastty_core::target::Samples;
use rastty_embedded_graphics::{BandMemory, FrameError, draw_frame};

use crate::{ChecksumDisplay, Fnv1a, FrameMemory, MemoryLayout, Scene, SceneError};

/// Frame width in pixels.
pub const WIDTH: u32 = 320;
/// Frame height in pixels.
pub const HEIGHT: u32 = 240;

/// Renders frame `frame` in the bands of `layout` through `memory` into `display`, band by band, top to bottom,
/// through [`draw_frame`] (one `fill_contiguous` a band): bins the triangles once, then draws each band from the
/// bins, and folds each band's depths into `depths`, when given, once it is drawn. Returns the number of bands and
/// the draw counts: binning's, with the bands' fragments.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// A [`SceneError`] if the mesh, the camera, a band or a draw fails (none does).
// Out of line: the firmware calls it twice (timed, then checked), and inlined in both places the whole draw
// would be compiled twice (12 KB of the core's code).
#[inline(never)]
pub fn render_frame(
    frame: usize,
    layout: MemoryLayout,
    memory: &mut FrameMemory,
    display: &mut impl DrawTarget<Color = Rgb565, Error = Infallible>,
    mut depths: Option<&mut Fnv1a>,
) -> Result<(u32, DrawStats), SceneError> {
    let scene = Scene::new(frame)?;
    let bands = Bands::new(WIDTH, HEIGHT, layout.band_rows, Samples::One).map_err(SceneError::Target)?;
    let FrameMemory { color, depth, bins } = memory;
    let bins = scene.bin(bins, bands)?;
    let mut stats = bins.stats();
    let band_memory = BandMemory::<Rgb565, u16> { color, depth };
    draw_frame(display, bands, band_memory, |band| {
        stats.fragments += scene.draw_band(band, &bins)?.fragments;
        if let Some(depths) = depths.as_deref_mut() {
            fold_depths(depths, band.depth());
        }
        Ok(())
    })
    .map_err(|e| match e {
        FrameError::Target(e) => SceneError::Target(e),
        FrameError::Draw(e) => e,
        FrameError::Samples(_) => SceneError::Multisampled,
        FrameError::Display(never) => match never {},
    })?;
    Ok((bands.count(), stats))
}

/// Folds a drawn band's depths into `depths`: out of line, so that the firmware's count of instructions by stage
/// (`firmware/stages.py`) can tell it from the display's checksum.
#[inline(never)]
fn fold_depths(depths: &mut Fnv1a, band: &[u16]) {
    depths.write_words(band);
}

/// Renders frame `frame` into a [`ChecksumDisplay`], which folds every band, as it is sent, into the frame's
/// [`crate::Fnv1a`] checksum: the checksum is the firmware's display; and the band's depths into a second one.
///
/// # Panics
/// If `frame >= FRAMES`.
///
/// # Errors
/// As [`render_frame`].
pub fn checksum_frame(
    frame: usize,
    layout: MemoryLayout,
    memory: &mut FrameMemory,
) -> Result<FrameChecksum, SceneError> {
    let (mut display, mut depths) = (ChecksumDisplay::new(), Fnv1a::new());
    let (bands, stats) = render_frame(frame, layout, memory, &mut display, Some(&mut depths))?;
    Ok(FrameChecksum { frame, layout, checksum: display.checksum(), depth: depths.finish(), bands, stats })
}

/// What rendering a frame did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameChecksum {
    /// The frame's index.
    pub frame: usize,
    /// The memory layout it was rendered in.
    pub layout: MemoryLayout,
    /// [`crate::Fnv1a`] of the frame's pixels.
    pub checksum: u32,
    /// [`crate::Fnv1a`] of the frame's depths, as the depth test left them.
    pub depth: u32,
    /// Bands rendered and checksummed.
    pub bands: u32,
    /// Triangle counts from binning, fragments summed over the bands.
    pub stats: DrawStats,
}

impl fmt::Display for FrameChecksum {
    /// The line that the firmware and the host both print, and `check.sh` compares:
    /// `frame 0 in 16 KiB: checksum 0x1234abcd, depth 0x5678ef01, 60 bands, 24680 fragments`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "frame {} in {} KiB: checksum 0x{:08x}, depth 0x{:08x}, {} bands, {} fragments",
            self.frame, self.layout.budget_kib, self.checksum, self.depth, self.bands, self.stats.fragments
        )
    }
}
