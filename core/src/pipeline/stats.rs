//! What a draw did.

use core::ops::AddAssign;

use super::raster::Setup;

/// Counts from one draw (or several, added up).
///
/// Every input triangle ends in exactly one of `invalid`, `outside`, `culled`, `degenerate` and `rasterized`;
/// `clipped` counts, in addition, the triangles that had to be clipped on their way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawStats {
    /// Triangles submitted.
    pub triangles_in: u64,
    /// Skipped: an index out of range, or a NaN or infinite position or varying.
    pub invalid: u64,
    /// Entirely outside the view volume or the target's rows.
    pub outside: u64,
    /// Discarded by face culling.
    pub culled: u64,
    /// Zero area once snapped to the sub-pixel grid.
    pub degenerate: u64,
    /// Crossed the near or far plane or the guard band and were clipped.
    pub clipped: u64,
    /// Reached the pixel loop (they may still cover no pixel centre).
    pub rasterized: u64,
    /// Fragments that passed the depth test and were shaded. In a draw that discards fragments
    /// ([`super::Shader::cutout`]): the fragments kept that passed it, as written. On a multisampled target a
    /// fragment is a pixel of a triangle with a sample that passed (shaded once whatever the number).
    pub fragments: u64,
}

impl AddAssign for DrawStats {
    fn add_assign(&mut self, o: Self) {
        self.triangles_in += o.triangles_in;
        self.invalid += o.invalid;
        self.outside += o.outside;
        self.culled += o.culled;
        self.degenerate += o.degenerate;
        self.clipped += o.clipped;
        self.rasterized += o.rasterized;
        self.fragments += o.fragments;
    }
}

/// What happened to the pieces of one input triangle, to count it once in [`DrawStats`].
#[derive(Default)]
pub(crate) struct Outcome {
    rasterized: bool,
    culled: bool,
    degenerate: bool,
}

impl Outcome {
    /// Notes what set-up made of one piece.
    pub fn record<E>(&mut self, setup: &Setup<E>) {
        match setup {
            Setup::Degenerate => self.degenerate = true,
            Setup::Culled => self.culled = true,
            Setup::Empty | Setup::Ready(_) => self.rasterized = true,
        }
    }

    /// Whether a piece reached the pixel loop.
    pub fn rasterized(&self) -> bool {
        self.rasterized
    }

    /// Counts the triangle once: rasterized if any piece was, else culled, else degenerate, else outside.
    pub fn count(self, stats: &mut DrawStats) {
        if self.rasterized {
            stats.rasterized += 1;
        } else if self.culled {
            stats.culled += 1;
        } else if self.degenerate {
            stats.degenerate += 1;
        } else {
            stats.outside += 1;
        }
    }
}
