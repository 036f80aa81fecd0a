//! Depth storage the caller owns: the z-buffer.
//!
//! Depth is NDC depth in `[0, 1]`, 0 at the near plane (see [`crate::camera`]). The comparison is **less**: a
//! fragment is kept when its depth is strictly smaller than the stored one, so of two surfaces at exactly the same
//! depth, the one drawn first stays. Clearing sets every value to the far plane (1.0).
//!
//! Every depth a buffer is given has been through [`clamp_depth`], one rule for every draw: triangles, lines,
//! depth-only passes, bands and lane groups alike. A buffer only compares and stores; it never changes a depth, so
//! a caller's own buffer stores exactly what the library's buffers store.

use crate::math::{Lanes, float};

/// Consecutive pixels of a row that [`DepthBuffer::test_and_set_lanes`] tests at once: eight `f32`s, one AVX
/// register (two SSE ones).
pub const DEPTH_LANES: usize = 8;

/// A depth buffer: one value per pixel, row-major, `width` values per row.
pub trait DepthBuffer {
    /// Number of pixels stored, or `None` for a buffer that stores nothing.
    fn pixel_count(&self) -> Option<usize>;
    /// If `z` is nearer than the stored depth of pixel `index` (`z < stored`), stores it and returns true.
    ///
    /// `z` is always in `[0, 1]` and never NaN or `-0`: the pipeline passes every depth through [`clamp_depth`].
    fn test_and_set(&mut self, index: usize, z: f32) -> bool;
    /// Whether `z` is nearer than the stored depth of pixel `index`, without storing it: a draw that may discard
    /// fragments asks before shading and calls [`Self::test_and_set`] for those it keeps. A buffer may answer
    /// true when unsure (the default: every fragment is then shaded and tested afterwards), never false for a
    /// depth that [`Self::test_and_set`] would store.
    #[inline(always)]
    fn nearer(&self, index: usize, z: f32) -> bool {
        let _ = (index, z);
        true
    }
    /// [`Self::test_and_set`] for pixel `start + i` with depth `z[i]`, for each `i` where `covered[i]`; returns how
    /// many passed. The pixels need not be in one row (the depth-only pass lets a group reach past a row's end,
    /// uncovered).
    #[inline(always)]
    fn test_and_set_lanes(
        &mut self,
        start: usize,
        z: &Lanes<f32, DEPTH_LANES>,
        covered: &Lanes<bool, DEPTH_LANES>,
    ) -> u32 {
        one_by_one(self, start, z, covered)
    }
    /// Resets every value to the far plane.
    fn clear(&mut self);
    /// The buffer as the pipeline tests it: by default [`DepthView::Other`], tested through this trait's methods
    /// (a call per fragment). A type that holds one of the library's formats (an enum over buffers, say) may hand
    /// that over instead, to have it tested directly.
    #[inline(always)]
    fn view(&mut self) -> DepthView<'_>
    where
        Self: Sized,
    {
        DepthView::Other(self)
    }
}

/// A depth buffer as the pipeline tests it: one of the library's formats, tested directly, any other
/// [`DepthBuffer`] through its methods, or none at all for a draw without the depth test.
///
/// The pipeline draws into this one type whatever buffer the caller gave ([`DepthBuffer::view`]), so that its
/// loops are compiled once, not once for every depth buffer type a program draws into: the format is a branch
/// that takes the same way for every fragment of a draw.
pub enum DepthView<'a> {
    /// `f32` depth (`&mut [f32]`).
    F32(&'a mut [f32]),
    /// `u16` depth (`&mut [u16]`).
    U16(&'a mut [u16]),
    /// Any other depth buffer.
    Other(&'a mut dyn DepthBuffer),
    /// No test and no write: every fragment passes ([`crate::pipeline::DepthTest::Off`]).
    Off,
}

impl core::fmt::Debug for DepthView<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::F32(d) => write!(f, "F32({} pixels)", d.len()),
            Self::U16(d) => write!(f, "U16({} pixels)", d.len()),
            Self::Other(d) => write!(f, "Other({:?} pixels)", d.pixel_count()),
            Self::Off => f.write_str("Off"),
        }
    }
}

impl<'a> From<&'a mut [f32]> for DepthView<'a> {
    fn from(depth: &'a mut [f32]) -> Self {
        Self::F32(depth)
    }
}

impl<'a> From<&'a mut [u16]> for DepthView<'a> {
    fn from(depth: &'a mut [u16]) -> Self {
        Self::U16(depth)
    }
}

/// The `f32` buffer a view holds, or the view back when it holds another.
impl<'a> TryFrom<DepthView<'a>> for &'a mut [f32] {
    type Error = DepthView<'a>;
    fn try_from(view: DepthView<'a>) -> Result<Self, DepthView<'a>> {
        match view {
            DepthView::F32(depth) => Ok(depth),
            other => Err(other),
        }
    }
}

/// The `u16` buffer a view holds, or the view back when it holds another.
impl<'a> TryFrom<DepthView<'a>> for &'a mut [u16] {
    type Error = DepthView<'a>;
    fn try_from(view: DepthView<'a>) -> Result<Self, DepthView<'a>> {
        match view {
            DepthView::U16(depth) => Ok(depth),
            other => Err(other),
        }
    }
}

impl DepthBuffer for DepthView<'_> {
    fn pixel_count(&self) -> Option<usize> {
        match self {
            Self::F32(d) => Some(d.len()),
            Self::U16(d) => Some(d.len()),
            Self::Other(d) => d.pixel_count(),
            Self::Off => None,
        }
    }
    #[inline(always)]
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        match self {
            Self::F32(d) => d.test_and_set(index, z),
            Self::U16(d) => d.test_and_set(index, z),
            Self::Other(d) => d.test_and_set(index, z),
            Self::Off => true,
        }
    }
    #[inline(always)]
    fn nearer(&self, index: usize, z: f32) -> bool {
        match self {
            Self::F32(d) => d.nearer(index, z),
            Self::U16(d) => d.nearer(index, z),
            Self::Other(d) => d.nearer(index, z),
            Self::Off => true,
        }
    }
    #[inline(always)]
    fn test_and_set_lanes(
        &mut self,
        start: usize,
        z: &Lanes<f32, DEPTH_LANES>,
        covered: &Lanes<bool, DEPTH_LANES>,
    ) -> u32 {
        match self {
            Self::F32(d) => d.test_and_set_lanes(start, z, covered),
            Self::U16(d) => d.test_and_set_lanes(start, z, covered),
            Self::Other(d) => d.test_and_set_lanes(start, z, covered),
            Self::Off => covered.iter().map(|&c| u32::from(c)).sum(),
        }
    }
    fn clear(&mut self) {
        match self {
            Self::F32(d) => d.clear(),
            Self::U16(d) => d.clear(),
            Self::Other(d) => d.clear(),
            Self::Off => {}
        }
    }
    #[inline(always)]
    fn view(&mut self) -> DepthView<'_> {
        match self {
            Self::F32(d) => DepthView::F32(d),
            Self::U16(d) => DepthView::U16(d),
            Self::Other(d) => DepthView::Other(&mut **d),
            Self::Off => DepthView::Off,
        }
    }
}

/// `f32` depth: the depth as given, in `[0, 1]` (see [`clamp_depth`]).
impl DepthBuffer for &mut [f32] {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.len())
    }
    #[inline(always)]
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        match self.get_mut(index) {
            Some(d) if z < *d => {
                *d = z;
                true
            }
            _ => false,
        }
    }
    #[inline(always)]
    fn nearer(&self, index: usize, z: f32) -> bool {
        self.get(index).is_some_and(|&d| z < d)
    }
    /// Branch-free over a group whose stored depths are all non-negative numbers (sign bit clear, not NaN), as
    /// every depth this library stores is, so that it widens to SIMD; any other group (a caller may fill the buffer
    /// with anything) goes pixel by pixel.
    ///
    /// The new depths are the minimum of the stored ones and, per lane, the passing depth or `+inf`: over such
    /// depths that is exactly the test's result, and it compiles to plain stores. (Choosing between the new and the
    /// stored value compiled to masked stores, slow on some x86 processors.)
    #[inline(always)]
    fn test_and_set_lanes(
        &mut self,
        start: usize,
        z: &Lanes<f32, DEPTH_LANES>,
        covered: &Lanes<bool, DEPTH_LANES>,
    ) -> u32 {
        let group = self.get_mut(start..start + DEPTH_LANES).and_then(|s| <&mut [f32; DEPTH_LANES]>::try_from(s).ok());
        let ordinary =
            |g: &[f32; DEPTH_LANES]| g.iter().fold(true, |a, d| a & (d.to_bits() <= f32::INFINITY.to_bits()));
        let Some(stored) = group.filter(|g| ordinary(g)) else {
            return one_by_one(self, start, z, covered);
        };
        let mut candidate = Lanes::<f32, DEPTH_LANES>::ZERO;
        let mut passed = 0;
        for i in 0..DEPTH_LANES {
            let pass = covered[i] & (z[i] < stored[i]);
            candidate[i] = if pass { z[i] } else { f32::INFINITY };
            passed += u32::from(pass);
        }
        for i in 0..DEPTH_LANES {
            stored[i] = float::min_num(stored[i], candidate[i]);
        }
        passed
    }
    fn clear(&mut self) {
        self.fill(1.0);
    }
    #[inline(always)]
    fn view(&mut self) -> DepthView<'_> {
        DepthView::F32(self)
    }
}

/// The depth a fragment is tested and stored with: its interpolated NDC depth `z` clamped to `[0, 1]`, NaN as 1
/// and `-0` as `+0`.
///
/// Interpolation in `f32` can round a hair past the vertices' range (-9.4e-38 between vertices at 0 and 1e-30),
/// and a line's depth bias can take it below the near plane. Like Direct3D, which clamps a fragment's depth to the
/// viewport's depth range before the depth test, the pipeline clamps every depth here, once, before the test and
/// whatever the buffer: so every depth format, band, lane group and depth-only pass stores the same depth, and a
/// fragment's [`Fragment::depth`](crate::pipeline::Fragment::depth) is the depth it was tested with. NaN becomes
/// the far plane, which never passes the less test against a cleared buffer; `-0` becomes `+0`, so stored depths
/// keep their sign bit clear. (The minimum first: NaN is not below 1, so it becomes 1; then `-0` is not above 0.)
#[must_use]
#[inline(always)]
pub fn clamp_depth(z: f32) -> f32 {
    float::max(float::min(z, 1.0), 0.0)
}

/// [`DepthBuffer::test_and_set_lanes`] as a loop of [`DepthBuffer::test_and_set`].
#[inline(always)]
fn one_by_one<D: DepthBuffer + ?Sized>(
    depth: &mut D,
    start: usize,
    z: &Lanes<f32, DEPTH_LANES>,
    covered: &Lanes<bool, DEPTH_LANES>,
) -> u32 {
    let mut passed = 0;
    for i in 0..DEPTH_LANES {
        if covered[i] && depth.test_and_set(start + i, z[i]) {
            passed += 1;
        }
    }
    passed
}

/// Quantizes NDC depth in `[0, 1]` to 16 bits, rounding to nearest (values outside saturate, NaN gives 0).
#[inline(always)]
pub fn depth_to_u16(z: f32) -> u16 {
    crate::math::float::quantize_unit(z, 65535.0) as u16
}

/// `u16` depth: NDC depth quantized to 65536 levels (see [`depth_to_u16`]); half the memory of `f32`.
impl DepthBuffer for &mut [u16] {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.len())
    }
    #[inline(always)]
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        let q = depth_to_u16(z);
        match self.get_mut(index) {
            Some(d) if q < *d => {
                *d = q;
                true
            }
            _ => false,
        }
    }
    #[inline(always)]
    fn nearer(&self, index: usize, z: f32) -> bool {
        self.get(index).is_some_and(|&d| depth_to_u16(z) < d)
    }
    fn clear(&mut self) {
        self.fill(u16::MAX);
    }
    #[inline(always)]
    fn view(&mut self) -> DepthView<'_> {
        DepthView::U16(self)
    }
}

/// No depth buffer: every fragment passes.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoDepth;

impl DepthBuffer for NoDepth {
    fn pixel_count(&self) -> Option<usize> {
        None
    }
    #[inline(always)]
    fn test_and_set(&mut self, _: usize, _: f32) -> bool {
        true
    }
    fn clear(&mut self) {}
}
