//! The nearest and the farthest depth of every percentage-closer window of a shadow map, so that most lookups
//! are decided by one read instead of `(2r + 1)^2`.
//!
//! A lookup counts the window's texels at or beyond its depth `z`. All of them are, exactly when `z` is at or
//! before the window's nearest depth; none is, exactly when `z` is beyond its farthest and the window lies wholly
//! inside the map (a texel outside counts as lit). A lit surface's lookups, nearly all of them, fall in the first
//! case: the normal offset moves them before their own window ([`super::ShadowBias`]). Only lookups near a shadow's
//! edge still read the whole window.
//!
//! The ranges are computed once per map, after its depth pass, into two buffers the caller owns, band by band like
//! the depth pass; they hold for any lookup, so a map with them gives the same light as one without, bit for bit.
//! Each face of a cube map has its own windows, cut at its edges as a square map's are.

use core::ops::Range;

use super::ShadowError;
use crate::math::float;

/// The depth ranges of a map's windows: for texel `(x, y)` of a face, the nearest and the farthest of the depths
/// in the `(2r + 1)^2` texels around it that lie in the face. A window with a NaN depth has NaN for both (decides
/// nothing), except that a window reaching past the face's edge has `+inf` for its farthest (some of its texels are
/// lit, always).
#[derive(Clone, Copy, Debug)]
pub struct WindowRanges<'a> {
    near: &'a [f32],
    far: &'a [f32],
    size: u32,
    faces: u32,
    radius: u32,
}

impl<'a> WindowRanges<'a> {
    /// The ranges [`window_ranges_band`] wrote for every row of a map of `size x size` faces (one, or a cube's
    /// six: `near` and `far` hold `size * size` values per face) with windows of radius `radius`.
    ///
    /// # Errors
    /// [`ShadowError::Buffer`] when `near` and `far` do not hold the same whole number (at least one) of faces.
    pub fn new(near: &'a [f32], far: &'a [f32], size: u32, radius: u32) -> Result<Self, ShadowError> {
        let faces = whole_faces(near.len(), size)?;
        if far.len() != near.len() {
            return Err(ShadowError::Buffer { expected: near.len(), actual: far.len() });
        }
        Ok(Self { near, far, size, faces, radius })
    }

    /// Side of the map (of each of its faces) in texels.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// The number of faces: 1, or 6 for a cube map.
    pub fn faces(&self) -> u32 {
        self.faces
    }

    /// The `r` of the `(2r + 1)^2` windows.
    pub fn radius(&self) -> u32 {
        self.radius
    }

    /// How many of the window's `taps` texels around `(tx, ty)` of face `face` are at or beyond depth `z`, when
    /// the range alone tells: `taps` or 0. `None` when the texels must be read, and for a window centred outside
    /// the face.
    #[inline(always)]
    pub(crate) fn decided(&self, face: usize, tx: i32, ty: i32, z: f32, taps: u32) -> Option<u32> {
        let size = self.size as i32;
        if tx < 0 || ty < 0 || tx >= size || ty >= size {
            return None;
        }
        let side = self.size as usize;
        let i = (face * side + ty as usize) * side + tx as usize;
        // `z <= near` holds for every texel at once (and fails for a NaN `z` or `near`), `z > far` for none.
        if z <= *self.near.get(i)? {
            Some(taps)
        } else if z > *self.far.get(i)? {
            Some(0)
        } else {
            None
        }
    }
}

/// The number of `size x size` faces in `values` values: an error unless it is a whole number, at least one.
fn whole_faces(values: usize, size: u32) -> Result<u32, ShadowError> {
    let face = size as usize * size as usize;
    let faces = values.checked_div(face).unwrap_or(0);
    if faces == 0 || faces * face != values {
        return Err(ShadowError::Buffer { expected: face.max(1) * faces.max(1), actual: values });
    }
    u32::try_from(faces).map_err(|_| ShadowError::Buffer { expected: face, actual: values })
}

/// Writes the depth ranges of the windows of radius `radius` centred in rows `rows` of the finished map `depth`,
/// of `size x size` faces stored one below the other (one, or a cube's six; [`super::ShadowView::rows`]), into
/// `near` and `far`, which hold `size * rows.len()` values each, row `rows.start` first. Bands written separately
/// (on separate threads, say) make exactly the ranges written whole; every band reads the whole of its faces, so
/// all of the depth pass must be done. A band may span several faces.
///
/// # Errors
/// [`ShadowError::Rows`] when `rows` is empty or leaves the map; [`ShadowError::Buffer`] when `depth` does not hold
/// a whole number of faces or `near` or `far` not `size * rows.len()` values.
pub fn window_ranges_band(
    depth: &[f32],
    size: u32,
    radius: u32,
    rows: Range<u32>,
    near: &mut [f32],
    far: &mut [f32],
) -> Result<(), ShadowError> {
    let faces = whole_faces(depth.len(), size)?;
    let height = faces * size;
    if rows.is_empty() || rows.end > height {
        return Err(ShadowError::Rows { start: rows.start, end: rows.end, height });
    }
    let side = size as usize;
    let band = side * rows.len();
    for buffer in [&*near, &*far] {
        if buffer.len() != band {
            return Err(ShadowError::Buffer { expected: band, actual: buffer.len() });
        }
    }
    let (mut near, mut far) = (near, far);
    let mut row = rows.start;
    while row < rows.end {
        let face = row / size;
        let face_rows = row - face * size..(rows.end - face * size).min(size);
        let length = side * face_rows.len();
        let (face_near, rest_near) = core::mem::take(&mut near).split_at_mut(length);
        let (face_far, rest_far) = core::mem::take(&mut far).split_at_mut(length);
        (near, far, row) = (rest_near, rest_far, face * size + face_rows.end);
        let texels = side * side;
        let face_depth = &depth[face as usize * texels..(face as usize + 1) * texels];
        face_ranges(face_depth, side, radius, face_rows, face_near, face_far);
    }
    Ok(())
}

/// [`window_ranges_band`] for rows `rows` of one face, whose depths are `depth` (`side * side` values; `near` and
/// `far` hold `side * rows.len()`, as checked by the caller).
fn face_ranges(depth: &[f32], side: usize, radius: u32, rows: Range<u32>, near: &mut [f32], far: &mut [f32]) {
    // A radius beyond the map reaches every texel; clamping it keeps the index arithmetic in range.
    let r = (radius as usize).min(side);
    // A depth pass never leaves a NaN (its depth test fails for one), so the rows this band reads are checked once
    // and, without a NaN, widened with minNum and maxNum, which make plain SIMD stores; with one, with
    // comparisons that keep it.
    let read = (rows.start as usize).saturating_sub(r)..(rows.end as usize + r).min(side);
    // A fold, not `any`: no branch per value, so the check widens to SIMD.
    let nan = depth[read.start * side..read.end * side].iter().fold(false, |nan, d| nan | d.is_nan());
    let rows_near = near.chunks_exact_mut(side);
    let rows_far = far.chunks_exact_mut(side);
    for ((y, near), far) in (rows.start as usize..rows.end as usize).zip(rows_near).zip(rows_far) {
        near.fill(f32::INFINITY);
        far.fill(f32::NEG_INFINITY);
        for source in y.saturating_sub(r)..(y + r + 1).min(side) {
            let row = &depth[source * side..(source + 1) * side];
            if nan {
                widen_by_row(row, r, near, far, nearer, farther);
            } else {
                widen_by_row(row, r, near, far, float::min_num, float::max_num);
            }
        }
        // Texels outside the map count as lit: a window reaching past an edge is never wholly in shadow.
        let past_edge = y < r || y + r >= side;
        if past_edge {
            far.fill(f32::INFINITY);
        } else {
            // Here `r < side`: the row has a window's reach of texels on each side of its centre.
            far[..r].fill(f32::INFINITY);
            far[side - r..].fill(f32::INFINITY);
        }
    }
}

/// Widens each texel's range in `near` and `far` by the texels of `row` within `r` columns of it, with `lower` and
/// `higher` as the minimum and maximum.
#[inline(always)]
fn widen_by_row(
    row: &[f32],
    r: usize,
    near: &mut [f32],
    far: &mut [f32],
    lower: impl Fn(f32, f32) -> f32,
    higher: impl Fn(f32, f32) -> f32,
) {
    // `r <= side` (the caller clamps it).
    let side = row.len();
    // The columns whose window lies inside the row: one pass per offset, over contiguous slices (SIMD).
    if side > 2 * r {
        let inner = side - 2 * r;
        for offset in 0..=2 * r {
            let source = &row[offset..offset + inner];
            let (near, far) = (&mut near[r..r + inner], &mut far[r..r + inner]);
            for ((n, f), &d) in near.iter_mut().zip(far.iter_mut()).zip(source) {
                (*n, *f) = (lower(*n, d), higher(*f, d));
            }
        }
    }
    // The columns near the row's ends, texel by texel (their windows are cut by the edge).
    for x in (0..r).chain(side.saturating_sub(r).max(r)..side) {
        for &d in &row[x.saturating_sub(r)..(x + r + 1).min(side)] {
            (near[x], far[x]) = (lower(near[x], d), higher(far[x], d));
        }
    }
}

/// The smaller of `a` and `b`; NaN if either is, so a NaN anywhere in a window is kept.
#[inline(always)]
fn nearer(a: f32, b: f32) -> f32 {
    if (b < a) | b.is_nan() { b } else { a }
}

/// The larger of `a` and `b`; NaN if either is.
#[inline(always)]
fn farther(a: f32, b: f32) -> f32 {
    if (b > a) | b.is_nan() { b } else { a }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ranges of a map computed directly: texel by texel over every window.
    fn direct(depth: &[f32], size: usize, r: usize) -> (Vec<f32>, Vec<f32>) {
        let mut near = vec![0.0; size * size];
        let mut far = vec![0.0; size * size];
        for y in 0..size {
            for x in 0..size {
                let (mut n, mut f, mut nan, mut cut) = (f32::INFINITY, f32::NEG_INFINITY, false, false);
                for wy in y as i64 - r as i64..=(y + r) as i64 {
                    for wx in x as i64 - r as i64..=(x + r) as i64 {
                        if wx < 0 || wy < 0 || wx >= size as i64 || wy >= size as i64 {
                            cut = true;
                            continue;
                        }
                        let d = depth[wy as usize * size + wx as usize];
                        nan |= d.is_nan();
                        n = n.min(d);
                        f = f.max(d);
                    }
                }
                near[y * size + x] = if nan { f32::NAN } else { n };
                far[y * size + x] = if cut {
                    f32::INFINITY
                } else if nan {
                    f32::NAN
                } else {
                    f
                };
            }
        }
        (near, far)
    }

    extern crate std;
    use std::vec;
    use std::vec::Vec;

    /// Bands of any height give, bit for bit, the ranges worked out window by window, for radii from 0 to past
    /// the map, in maps with NaN depths and without (negative ones included).
    #[test]
    fn bands_give_the_ranges_of_every_window() {
        for (size, nans) in [1usize, 2, 5, 9].into_iter().flat_map(|size| [(size, true), (size, false)]) {
            let depth: Vec<f32> = (0..size * size)
                .map(|i| if nans && i % 17 == 11 { f32::NAN } else { ((i * 37) % 29) as f32 / 29.0 - 0.5 })
                .collect();
            for radius in 0..=size + 1 {
                let (near, far) = direct(&depth, size, radius);
                for band in 1..=size {
                    let (mut n, mut f) = (vec![-7.0; size * size], vec![-7.0; size * size]);
                    let mut start = 0;
                    for (nb, fb) in n.chunks_mut(band * size).zip(f.chunks_mut(band * size)) {
                        let rows = start as u32..(start + nb.len() / size) as u32;
                        start = rows.end as usize;
                        window_ranges_band(&depth, size as u32, radius as u32, rows, nb, fb).unwrap();
                    }
                    let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&n), bits(&near), "near, size {size}, radius {radius}, bands of {band}");
                    assert_eq!(bits(&f), bits(&far), "far, size {size}, radius {radius}, bands of {band}");
                }
            }
        }
    }

    /// Wrong rows and buffer sizes are refused, naming what was expected.
    #[test]
    fn wrong_rows_and_buffers_are_refused() {
        let depth = [1.0; 16];
        let (mut n, mut f) = ([0.0; 8], [0.0; 8]);
        assert_eq!(
            window_ranges_band(&depth, 4, 1, 3..5, &mut n, &mut f),
            Err(ShadowError::Rows { start: 3, end: 5, height: 4 })
        );
        assert_eq!(
            window_ranges_band(&depth[..15], 4, 1, 0..2, &mut n, &mut f),
            Err(ShadowError::Buffer { expected: 16, actual: 15 })
        );
        assert_eq!(
            window_ranges_band(&depth, 4, 1, 0..1, &mut n, &mut f),
            Err(ShadowError::Buffer { expected: 4, actual: 8 })
        );
        assert_eq!(WindowRanges::new(&n, &f, 4, 1).err(), Some(ShadowError::Buffer { expected: 16, actual: 8 }));
        assert_eq!(WindowRanges::new(&depth, &n, 4, 1).err(), Some(ShadowError::Buffer { expected: 16, actual: 8 }));
    }
}
