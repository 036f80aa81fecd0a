//! Samples per pixel: where a multisampled target's coverage and depth are tested.

/// How many samples a [`super::Target`] stores per pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Samples {
    /// One, at the pixel centre.
    #[default]
    One,
    /// Four, at [`SAMPLE_POSITIONS`]: multisample anti-aliasing.
    Four,
}

impl Samples {
    /// The number of samples.
    #[must_use]
    pub const fn count(self) -> usize {
        match self {
            Self::One => 1,
            Self::Four => 4,
        }
    }
}

/// Where the four samples of a [`Samples::Four`] pixel lie, in eighths of a pixel from its centre, `(x right, y
/// down)`, in the order they are stored: a rotated grid, so that a near-horizontal or near-vertical edge crosses
/// four different rows and columns of samples (Direct3D's standard 4-sample pattern,
/// `D3D11_STANDARD_MULTISAMPLE_PATTERN`: (-2, -6), (6, -2), (-6, 2), (2, 6) sixteenths).
pub const SAMPLE_POSITIONS: [(i32, i32); 4] = [(-1, -3), (3, -1), (-3, 1), (1, 3)];

/// The samples of a [`Samples::Four`] pixel.
pub(crate) const SAMPLE_COUNT: usize = SAMPLE_POSITIONS.len();

/// The farthest any sample lies from its pixel centre along either axis, in eighths of a pixel.
pub(crate) const SAMPLE_REACH: i32 = 3;
const _: () = {
    let mut i = 0;
    while i < SAMPLE_POSITIONS.len() {
        let (x, y) = SAMPLE_POSITIONS[i];
        assert!(x.abs() <= SAMPLE_REACH && y.abs() <= SAMPLE_REACH);
        i += 1;
    }
};
