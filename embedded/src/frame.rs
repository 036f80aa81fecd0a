//! A frame, band by band, from the caller's draw to the display.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{Point, Size};
use embedded_graphics_core::primitives::Rectangle;
use rastty_core::pipeline::Bands;
use rastty_core::target::{DepthBuffer, Samples, Target, TargetError};

use crate::{DisplayColor, FrameError};

/// One band's memory, lent by the caller and reused for every band: stored pixels and depths, at least as many
/// of each as a band has pixels.
#[derive(Debug)]
pub struct BandMemory<'m, C: DisplayColor, Z> {
    /// The band's pixels, in the display's colour type as the core stores it.
    pub color: &'m mut [C::Stored],
    /// The band's depths (`u16` or `f32`).
    pub depth: &'m mut [Z],
}

/// Draws a frame cut as `bands` into `display`, band by band, top to bottom, through `memory`: `draw` draws into
/// each band's target (clearing it first, as it sees fit), then the band goes to the display in one
/// `fill_contiguous` call over its rows of the frame, from column 0.
///
/// # Errors
/// [`FrameError::Samples`] when `bands` has more than one sample a pixel, [`FrameError::Target`] when `memory` is
/// shorter than a band; otherwise the first error of `draw` or of the display, after which nothing more is drawn.
///
/// # Examples
/// ```
/// use embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, pixelcolor::Rgb565};
/// use rastty_core::{math::Vec3, pipeline::Bands, target::Samples};
/// use rastty_embedded_graphics::{BandMemory, draw_frame};
///
/// /// A display that counts the pixels it is sent.
/// struct Counting(usize);
/// impl OriginDimensions for Counting {
///     fn size(&self) -> Size {
///         Size::new(32, 24)
///     }
/// }
/// impl DrawTarget for Counting {
///     type Color = Rgb565;
///     type Error = core::convert::Infallible;
///     fn draw_iter<I: IntoIterator<Item = embedded_graphics_core::Pixel<Rgb565>>>(&mut self, p: I) -> Result<(), Self::Error> {
///         self.0 += p.into_iter().count();
///         Ok(())
///     }
/// }
///
/// let bands = Bands::new(32, 24, 8, Samples::One).unwrap();
/// let (mut color, mut depth) = ([0u16; 32 * 8], [0u16; 32 * 8]);
/// let memory = BandMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth };
/// let mut display = Counting(0);
/// draw_frame(&mut display, bands, memory, |target| {
///     target.clear(Vec3::new(0.1, 0.2, 0.3));
///     Ok::<(), core::convert::Infallible>(())
/// })
/// .unwrap();
/// assert_eq!(display.0, 32 * 24);
/// ```
pub fn draw_frame<D, C, Z, E>(
    display: &mut D,
    bands: Bands,
    memory: BandMemory<'_, C, Z>,
    mut draw: impl FnMut(&mut Target<C::Buffer<'_>, &mut [Z]>) -> Result<(), E>,
) -> Result<(), FrameError<D::Error, E>>
where
    D: DrawTarget<Color = C>,
    C: DisplayColor,
    for<'a> &'a mut [Z]: DepthBuffer,
{
    if bands.samples() != Samples::One {
        return Err(FrameError::Samples(bands.samples()));
    }
    let (width, height) = bands.size();
    let BandMemory { color, depth } = memory;
    for band in 0..bands.count() {
        let rows = bands.rows(band);
        let len = width as usize * rows.len();
        let (Some(color), Some(depth)) = (color.get_mut(..len), depth.get_mut(..len)) else {
            let short = if color.len() < len {
                TargetError::ColorLength { expected: len, actual: color.len() }
            } else {
                TargetError::DepthLength { expected: len, actual: depth.len() }
            };
            return Err(FrameError::Target(short));
        };
        let mut target =
            Target::band(C::buffer(color), &mut *depth, width, height, rows.clone()).map_err(FrameError::Target)?;
        draw(&mut target).map_err(FrameError::Draw)?;
        drop(target);
        // Frame sizes are at most `MAX_DIMENSION` (8,192): the casts are exact.
        let area = Rectangle::new(Point::new(0, rows.start as i32), Size::new(width, rows.len() as u32));
        display.fill_contiguous(&area, color.iter().map(|&p| C::from_stored(p))).map_err(FrameError::Display)?;
    }
    Ok(())
}
