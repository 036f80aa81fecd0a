//! A frame, strip by strip, from the caller's draw to the display.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{Point, Size};
use embedded_graphics_core::primitives::Rectangle;
use rastty_core::pipeline::Strips;
use rastty_core::target::{DepthBuffer, Samples, Target, TargetError};

use crate::{DisplayColor, FrameError};

/// One strip's memory, lent by the caller and reused for every strip: stored pixels and depths, at least as many
/// of each as a strip has pixels.
#[derive(Debug)]
pub struct StripMemory<'m, C: DisplayColor, Z> {
    /// The strip's pixels, in the display's colour type as the core stores it.
    pub color: &'m mut [C::Stored],
    /// The strip's depths (`u16` or `f32`).
    pub depth: &'m mut [Z],
}

/// Draws a frame cut as `strips` into `display`, strip by strip, top to bottom, through `memory`: `draw` draws into
/// each strip's target (clearing it first, as it sees fit), then the strip goes to the display in one
/// `fill_contiguous` call over its rows of the frame, from column 0.
///
/// # Errors
/// [`FrameError::Samples`] when `strips` has more than one sample a pixel, [`FrameError::Target`] when `memory` is
/// shorter than a strip; otherwise the first error of `draw` or of the display, after which nothing more is drawn.
///
/// # Examples
/// ```
/// use embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, pixelcolor::Rgb565};
/// use rastty_core::{math::Vec3, pipeline::Strips, target::Samples};
/// use rastty_embedded_graphics::{StripMemory, draw_frame};
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
/// let strips = Strips::new(32, 24, 8, Samples::One).unwrap();
/// let (mut color, mut depth) = ([0u16; 32 * 8], [0u16; 32 * 8]);
/// let memory = StripMemory::<Rgb565, u16> { color: &mut color, depth: &mut depth };
/// let mut display = Counting(0);
/// draw_frame(&mut display, strips, memory, |target| {
///     target.clear(Vec3::new(0.1, 0.2, 0.3));
///     Ok::<(), core::convert::Infallible>(())
/// })
/// .unwrap();
/// assert_eq!(display.0, 32 * 24);
/// ```
pub fn draw_frame<D, C, Z, E>(
    display: &mut D,
    strips: Strips,
    memory: StripMemory<'_, C, Z>,
    mut draw: impl FnMut(&mut Target<C::Buffer<'_>, &mut [Z]>) -> Result<(), E>,
) -> Result<(), FrameError<D::Error, E>>
where
    D: DrawTarget<Color = C>,
    C: DisplayColor,
    for<'a> &'a mut [Z]: DepthBuffer,
{
    if strips.samples() != Samples::One {
        return Err(FrameError::Samples(strips.samples()));
    }
    let (width, height) = strips.size();
    let StripMemory { color, depth } = memory;
    for strip in 0..strips.count() {
        let rows = strips.rows(strip);
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
