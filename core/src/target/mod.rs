//! Render targets over memory the caller owns: a whole frame, or one horizontal band of it.
//!
//! A [`Target`] pairs a [`ColorBuffer`] with a [`DepthBuffer`] and says which rows of which frame they hold.
//! Rendering a frame as several bands, each into the same small buffers, gives exactly the pixels of rendering it
//! whole: every pixel is computed from frame coordinates only, never from where its band starts.
//!
//! For anti-aliasing, either store four samples per pixel ([`Target::multisampled`], [`Samples::Four`]: coverage
//! and depth per sample, one shading per pixel) and average them with [`resolve_rgb888`], or render `k` times
//! larger and average with [`downsample_rgb888`].
//!
//! ```
//! use rastty_core::target::{Rgb565, Target};
//! // A 320x240 display drawn 16 rows at a time: 10 KiB of colour and 10 KiB of depth, not 300 KiB.
//! let mut color = [0u16; 320 * 16];
//! let mut depth = [0u16; 320 * 16];
//! for y0 in (0..240).step_by(16) {
//!     let mut band = Target::band(Rgb565(&mut color), &mut depth[..], 320, 240, y0..y0 + 16).unwrap();
//!     band.clear(rastty_core::math::Vec3::ZERO);
//!     // ... draw the scene into `band`, then send its rows to the display.
//! }
//! ```

mod color_buffer;
mod depth_buffer;
mod samples;
mod supersample;
mod vertex_memory;

use core::ops::Range;

pub use color_buffer::{ColorBuffer, ColorView, NoColor, Rgb565, Rgb888};
pub use depth_buffer::{DEPTH_LANES, DepthBuffer, DepthView, NoDepth, clamp_depth, depth_to_u16};
pub(crate) use samples::{SAMPLE_COUNT, SAMPLE_REACH};
pub use samples::{SAMPLE_POSITIONS, Samples};
pub use supersample::{downsample_rgb888, resolve_rgb888};
pub use vertex_memory::{FrameGeometry, NoVertexMemory, SharedScreenVertices, VertexMemory, VertexSource};

use crate::math::Vec3;
use crate::pipeline::DepthTest;

/// Largest frame width or height, in pixels.
///
/// It keeps every frame well inside the rasterizer's guard band (see [`crate::pipeline`]).
pub const MAX_DIMENSION: u32 = 8192;

/// Why a target could not be built.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TargetError {
    /// The frame is zero pixels wide or high.
    Empty,
    /// The frame is wider or higher than [`MAX_DIMENSION`].
    TooLarge {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// The band's rows are empty or not within the frame.
    Rows {
        /// The band's rows.
        rows: Range<u32>,
        /// The frame's height.
        height: u32,
    },
    /// The colour buffer does not hold exactly one value per sample of the band.
    ColorLength {
        /// Samples in the band (its pixels times the samples per pixel).
        expected: usize,
        /// Values in the buffer.
        actual: usize,
    },
    /// The depth buffer does not hold exactly one value per sample of the band.
    DepthLength {
        /// Samples in the band (its pixels times the samples per pixel).
        expected: usize,
        /// Values in the buffer.
        actual: usize,
    },
}

impl core::fmt::Display for TargetError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Empty => f.write_str("the frame has no pixels"),
            Self::TooLarge { width, height } => {
                write!(f, "a {width}x{height} frame is larger than {MAX_DIMENSION}x{MAX_DIMENSION}")
            }
            Self::Rows { rows, height } => {
                write!(f, "rows {}..{} are not a non-empty band of a {height}-row frame", rows.start, rows.end)
            }
            Self::ColorLength { expected, actual } => {
                write!(f, "the colour buffer holds {actual} values, the band has {expected} samples")
            }
            Self::DepthLength { expected, actual } => {
                write!(f, "the depth buffer holds {actual} values, the band has {expected} samples")
            }
        }
    }
}

impl core::error::Error for TargetError {}

/// Whether a `width x height` frame can be drawn: [`TargetError::Empty`] when it has no pixels,
/// [`TargetError::TooLarge`] beyond [`MAX_DIMENSION`]. What [`Target::band`] and
/// [`crate::pipeline::Strips::new`] check first.
pub(crate) fn check_size(width: u32, height: u32) -> Result<(), TargetError> {
    if width == 0 || height == 0 {
        return Err(TargetError::Empty);
    }
    if width > MAX_DIMENSION || height > MAX_DIMENSION {
        return Err(TargetError::TooLarge { width, height });
    }
    Ok(())
}

/// A colour buffer and a depth buffer holding rows `[y0, y1)` of a `width x height` frame, one value per sample:
/// one sample per pixel, or four ([`Target::multisampled`]).
#[derive(Debug)]
pub struct Target<C: ColorBuffer, D: DepthBuffer, V: VertexMemory = NoVertexMemory> {
    pub(crate) color: C,
    pub(crate) depth: D,
    /// Memory for the screen positions of a draw's vertices ([`Target::with_vertex_memory`]).
    pub(crate) vertices: V,
    width: u32,
    height: u32,
    rows: Range<u32>,
    samples: Samples,
}

impl<C: ColorBuffer, D: DepthBuffer> Target<C, D> {
    /// A target for a whole `width x height` frame.
    ///
    /// # Errors
    /// As [`Target::band`].
    pub fn new(color: C, depth: D, width: u32, height: u32) -> Result<Self, TargetError> {
        Self::band(color, depth, width, height, 0..height)
    }

    /// A target for rows `rows` of a `width x height` frame: the buffers hold `width * rows.len()` pixels, row
    /// `rows.start` first.
    ///
    /// # Errors
    /// [`TargetError::Empty`] or [`TargetError::TooLarge`] for a frame of zero or more than [`MAX_DIMENSION`]
    /// pixels a side, [`TargetError::Rows`] for an empty band or one outside the frame, and
    /// [`TargetError::ColorLength`] / [`TargetError::DepthLength`] when a buffer has the wrong length.
    pub fn band(color: C, depth: D, width: u32, height: u32, rows: Range<u32>) -> Result<Self, TargetError> {
        Self::multisampled(color, depth, width, height, rows, Samples::One)
    }

    /// A target for rows `rows` of a `width x height` frame with `samples` per pixel: the buffers hold
    /// `width * rows.len() * samples.count()` values, each pixel's samples one after the other (pixel `i`'s sample
    /// `s` at `i * samples.count() + s`), in the order of [`SAMPLE_POSITIONS`]. Draws into it test coverage and
    /// depth per sample and shade once per pixel; [`resolve_rgb888`] averages the samples into pixels.
    ///
    /// # Errors
    /// As [`Target::band`], the lengths counted in samples.
    pub fn multisampled(
        color: C,
        depth: D,
        width: u32,
        height: u32,
        rows: Range<u32>,
        samples: Samples,
    ) -> Result<Self, TargetError> {
        check_size(width, height)?;
        if rows.start >= rows.end || rows.end > height {
            return Err(TargetError::Rows { rows, height });
        }
        let expected = width as usize * (rows.end - rows.start) as usize * samples.count();
        match color.pixel_count() {
            Some(actual) if actual != expected => {
                return Err(TargetError::ColorLength { expected, actual });
            }
            _ => {}
        }
        match depth.pixel_count() {
            Some(actual) if actual != expected => {
                return Err(TargetError::DepthLength { expected, actual });
            }
            _ => {}
        }
        Ok(Self { color, depth, vertices: NoVertexMemory, width, height, rows, samples })
    }

    /// The same target with `memory` for the screen positions of its draws' vertices: a draw of a mesh of at most
    /// `memory.len()` vertices then runs the position stage once per vertex instead of through the vertex cache
    /// (faster on dense meshes; the same pixels). See [`VertexMemory`].
    pub fn with_vertex_memory(
        self,
        memory: &mut [crate::pipeline::ScreenVertex],
    ) -> Target<C, D, &mut [crate::pipeline::ScreenVertex]> {
        let Self { color, depth, vertices: NoVertexMemory, width, height, rows, samples } = self;
        Target { color, depth, vertices: memory, width, height, rows, samples }
    }
}

impl<C: ColorBuffer, D: DepthBuffer, V: VertexMemory> Target<C, D, V> {
    /// Fills the colour buffer with `color` and resets the depth buffer to the far plane.
    pub fn clear(&mut self, color: Vec3) {
        self.color.fill(color);
        self.depth.clear();
    }

    /// As [`Self::clear`], each pixel (every sample of it) to `color(x, y)`, for column `x` and frame row `y`: a
    /// background that changes over the frame (the environment seen through the camera, say). Colours are stored
    /// as the colour buffer stores draws' colours (encoded, when they are in linear light, by the caller).
    pub fn clear_with(&mut self, color: impl Fn(u32, u32) -> Vec3) {
        self.depth.clear();
        let count = self.samples.count();
        let every = ((1u32 << count) - 1) as u8;
        let mut first = 0;
        for y in self.rows.clone() {
            for x in 0..self.width {
                self.color.write_samples(first, every, color(x, y));
                first += count;
            }
        }
    }

    /// This target's buffers lent to one draw with its geometry computed beforehand for the frame
    /// ([`FrameGeometry`]): the draw it was made for reads its vertices from its [`SharedScreenVertices`] (no
    /// position stage) and takes only the triangles its [`crate::pipeline::BandBins`] hold for the target's band; any
    /// other draw uses the vertex cache and takes every triangle. The same pixels either way.
    pub fn for_draw<'g>(
        &mut self,
        geometry: FrameGeometry<'g>,
    ) -> Target<ColorView<'_>, DepthView<'_>, FrameGeometry<'g>> {
        let Self { color, depth, width, height, rows, samples, .. } = self;
        Target {
            color: color.view(),
            depth: depth.view(),
            vertices: geometry,
            width: *width,
            height: *height,
            rows: rows.clone(),
            samples: *samples,
        }
    }

    /// Width of the frame (and of the band) in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height of the whole frame in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The frame rows this target holds.
    pub fn rows(&self) -> Range<u32> {
        self.rows.clone()
    }

    /// The samples stored per pixel.
    pub fn samples(&self) -> Samples {
        self.samples
    }

    /// The colour buffer.
    pub fn color(&self) -> &C {
        &self.color
    }

    /// The colour buffer, mutably.
    pub fn color_mut(&mut self) -> &mut C {
        &mut self.color
    }

    /// The depth buffer.
    pub fn depth(&self) -> &D {
        &self.depth
    }

    /// Both buffers, mutably: to split them into bands drawn side by side, or to post-process a finished frame.
    pub fn buffers_mut(&mut self) -> (&mut C, &mut D) {
        (&mut self.color, &mut self.depth)
    }

    /// Gives the buffers back.
    pub fn into_parts(self) -> (C, D) {
        (self.color, self.depth)
    }

    /// The target as a draw with `depth_test` draws into it, one type whatever its buffers ([`ColorBuffer::view`],
    /// [`DepthBuffer::view`]; [`DepthView::Off`] without the test), and what its draws find of screen vertices and
    /// bins.
    pub(crate) fn views(
        &mut self,
        depth_test: DepthTest,
    ) -> (TargetView<'_>, VertexSource<'_>, &[crate::pipeline::BandBins<'_>]) {
        let Self { color, depth, vertices, width, height, rows, samples } = self;
        let depth = match depth_test {
            DepthTest::Less => depth.view(),
            DepthTest::Off => DepthView::Off,
        };
        let view = Target {
            color: color.view(),
            depth,
            vertices: NoVertexMemory,
            width: *width,
            height: *height,
            rows: rows.clone(),
            samples: *samples,
        };
        let (source, bins) = vertices.source();
        (view, source, bins)
    }
}

/// A target as the pipeline draws into it: the caller's buffers behind one type ([`Target::views`]).
pub(crate) type TargetView<'a> = Target<ColorView<'a>, DepthView<'a>>;
