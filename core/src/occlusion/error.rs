//! Why ambient occlusion could not be applied.

use core::ops::Range;

use crate::target::MAX_DIMENSION;

/// Why ambient occlusion could not be applied (nothing was changed).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OcclusionError {
    /// `radius` or `strength` is negative, NaN or infinite.
    Settings,
    /// The frame is zero pixels wide or high, or larger than [`MAX_DIMENSION`].
    Frame {
        /// The frame's width.
        width: u32,
        /// The frame's height.
        height: u32,
    },
    /// The colour band's rows are empty or not within the frame.
    Rows {
        /// The colour band's rows.
        rows: Range<u32>,
        /// The frame's height.
        height: u32,
    },
    /// The depth rows do not contain the colour band's rows, or are not within the frame.
    DepthRows {
        /// The depth's rows.
        depth_rows: Range<u32>,
        /// The colour band's rows.
        rows: Range<u32>,
        /// The frame's height.
        height: u32,
    },
    /// The colour slice does not hold exactly one value per pixel of its rows.
    ColorLength {
        /// `rows.len() * width`.
        expected: usize,
        /// Values given.
        actual: usize,
    },
    /// The depth slice does not hold exactly one value per pixel of its rows.
    DepthLength {
        /// `depth_rows.len() * width`.
        expected: usize,
        /// Values given.
        actual: usize,
    },
    /// The projection matrix has no (finite) inverse, so depths cannot be brought back to view space.
    Projection,
}

impl core::fmt::Display for OcclusionError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Settings => f.write_str("the ambient occlusion radius and strength must be finite and not negative"),
            Self::Frame { width, height } => {
                write!(f, "a {width}x{height} frame is empty or larger than {MAX_DIMENSION}x{MAX_DIMENSION}")
            }
            Self::Rows { rows, height } => {
                write!(f, "rows {}..{} are not a non-empty band of a {height}-row frame", rows.start, rows.end)
            }
            Self::DepthRows { depth_rows, rows, height } => write!(
                f,
                "depth rows {}..{} do not contain rows {}..{} within a {height}-row frame",
                depth_rows.start, depth_rows.end, rows.start, rows.end
            ),
            Self::ColorLength { expected, actual } => {
                write!(f, "the colour slice holds {actual} pixels, its rows have {expected}")
            }
            Self::DepthLength { expected, actual } => {
                write!(f, "the depth slice holds {actual} values, its rows have {expected} pixels")
            }
            Self::Projection => f.write_str("the projection matrix has no inverse"),
        }
    }
}

impl core::error::Error for OcclusionError {}
