//! Why a frame could not be drawn.

use core::fmt;

use rastty_core::target::{Samples, TargetError};

/// Why [`crate::draw_frame`] stopped: the bands, the caller's draw or the display.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FrameError<D, E> {
    /// The memory does not make a band's target: shorter than a band.
    Target(TargetError),
    /// The bands have more than one sample a pixel: a display takes pixels, not samples.
    Samples(Samples),
    /// The caller's draw into a band failed.
    Draw(E),
    /// The display refused a band.
    Display(D),
}

impl<D: fmt::Debug, E: fmt::Display> fmt::Display for FrameError<D, E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Target(e) => write!(f, "band: {e}"),
            Self::Samples(s) => write!(f, "{} samples a pixel: a display takes one", s.count()),
            Self::Draw(e) => write!(f, "draw: {e}"),
            Self::Display(e) => write!(f, "display: {e:?}"),
        }
    }
}

impl<D: fmt::Debug, E: fmt::Debug + fmt::Display> core::error::Error for FrameError<D, E> {}
