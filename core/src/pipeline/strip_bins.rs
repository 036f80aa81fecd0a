//! Geometry once per frame for a frame drawn strip by strip: which triangles can touch which strip, kept in memory
//! the caller lends.
//!
//! A frame drawn through one small band buffer, strip after strip (a microcontroller's way: `core/firmware`), would
//! otherwise take every triangle through the position stage, the outcodes and set-up once per strip. [`StripBins::bin`]
//! does that once for the frame: each triangle's vertices to the screen (through the draw's vertex cache), and the
//! draw's own tests on the whole frame: a triangle that is invalid, outside, culled, degenerate or covers no pixel
//! centre (or sample) is dropped there, as every strip's draw would drop it; any other is kept as a
//! [`BinnedTriangle`], its index and the strips that its bounding box's rows meet (every strip, for a triangle that
//! must be clipped). [`draw_strip`] then takes into one strip's target only the kept triangles that meet it, in
//! mesh order, through the loop of [`super::draw`]: the same pixels as [`super::draw`] on that target
//! (`core/tests/strip_bins.rs`). Bins are made and used only for a shader whose position stage is a matrix it
//! tells ([`Shader::clip_from_object`]), so that a draw can check they are its own; for any other shader, every
//! strip draws every triangle.
//!
//! # Memory and time
//! For a mesh of `N` vertices and `T` triangles drawn in `S` strips of `R` rows, `W` pixels wide:
//! - drawing each strip whole ([`super::draw`] on each band): no memory beyond the band (and the vertex cache on the
//!   stack); every strip pays the position stage of about `N` to `3 T` vertices and `T` rejections;
//! - binning: 4 bytes a kept triangle (at most `4 T`; for a closed model, about the triangles facing the camera),
//!   and 4 bytes for each [`BIN_BLOCK`] of them, the position stage of the frame once, then per strip a scan of the
//!   blocks and of the kept entries in the blocks that meet it (a few instructions each), and the draw of the
//!   triangles that meet it. Smaller strips take less band memory (`R W` colours and depths) and meet more triangles
//!   twice. Where there is no room left for the blocks, each strip scans every entry: the same pixels.
//!
//! When the entries run out (or at triangle 65,536, or in a frame of more than 256 strips), the triangles from
//! there on are drawn in every strip as [`super::draw`] draws them: slower, the same pixels.

use core::ops::Range;

use super::clip::CLIP_MASK;
use super::draw::{Path, check, draw_walk};
use super::raster::{EdgeSetup, FixedPoint, FloatingPoint, Rasterizer, Setup};
use super::screen_vertex::{NO_SCREEN, NOT_FINITE};
use super::vertex_cache::VertexCache;
use super::{ClipVolume, DrawError, DrawState, DrawStats, EdgeArithmetic, Shader};
use crate::math::Mat4;
use crate::mesh::{Indices, Mesh};
use crate::target::{ColorBuffer, DepthBuffer, Samples, Target, TargetError, VertexMemory, check_size};

/// Kept triangles per block: the strips of each run of this many entries are summed up in one more entry, which a
/// strip that it does not meet skips whole. Triangles kept in mesh order that lie near each other (a mesh ordered
/// for the vertex cache) fall in few strips, so a strip skips most blocks.
pub const BIN_BLOCK: usize = 32;

/// One kept triangle: its index in the mesh and the first and last strips it may cover; or a [`BIN_BLOCK`]'s summary,
/// the first and last strips of its triangles. Four bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BinnedTriangle {
    triangle: u16,
    first: u8,
    last: u8,
}

impl BinnedTriangle {
    /// A value to fill a caller's buffer with before binning (any value will do: binning overwrites what it keeps).
    pub const UNSET: Self = Self { triangle: 0, first: 0, last: 0 };

    /// Whether the triangle may cover pixels of strip `strip`.
    #[inline(always)]
    fn meets(self, strip: u8) -> bool {
        self.first <= strip && strip <= self.last
    }
}

/// How a frame is cut into strips: its size, the rows of each strip (the last one may have fewer), and the samples
/// per pixel of the strips' targets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Strips {
    width: u32,
    height: u32,
    rows: u32,
    samples: Samples,
}

impl Strips {
    /// A `width x height` frame in strips of `rows` rows, drawn with `samples` per pixel.
    ///
    /// # Errors
    /// [`TargetError::Empty`] or [`TargetError::TooLarge`] for the frame's size, as [`Target::band`];
    /// [`TargetError::Rows`] when `rows` is 0.
    pub fn new(width: u32, height: u32, rows: u32, samples: Samples) -> Result<Self, TargetError> {
        check_size(width, height)?;
        if rows == 0 {
            return Err(TargetError::Rows { rows: 0..0, height });
        }
        Ok(Self { width, height, rows, samples })
    }

    /// The frame's width and height.
    #[must_use]
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Samples per pixel of the strips' targets.
    #[must_use]
    pub fn samples(&self) -> Samples {
        self.samples
    }

    /// The number of strips.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.height.div_ceil(self.rows)
    }

    /// The frame rows of strip `strip` (empty past the last strip).
    #[must_use]
    pub fn rows(&self, strip: u32) -> Range<u32> {
        let start = strip.saturating_mul(self.rows).min(self.height);
        start..start.saturating_add(self.rows).min(self.height)
    }

    /// The strip holding every row of `rows`, if one does.
    fn holding(&self, rows: &Range<u32>) -> Option<u32> {
        let strip = rows.start / self.rows;
        (rows.end > rows.start && (rows.end - 1) / self.rows == strip).then_some(strip)
    }
}

/// What a set of bins was made for: a draw that differs in any of these draws every triangle instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct BinKey {
    /// The addresses and lengths of the mesh's positions and indices (the slices themselves, not merely equal
    /// values).
    mesh: [(usize, usize); 2],
    /// The bits of the shader's clip-from-object matrix, when it tells it ([`Shader::clip_from_object`]): bins
    /// without one are never used.
    matrix: Option<[u32; 16]>,
    state: DrawState,
    strips: Strips,
}

impl BinKey {
    fn new<S: Shader>(mesh: &Mesh<'_>, shader: &S, state: &DrawState, strips: Strips) -> Self {
        let positions = mesh.positions();
        let matrix = shader.clip_from_object().map(Mat4::to_bits);
        let indices = match mesh.indices() {
            Indices::Sequential => (0, 0),
            Indices::U16(ix) => (ix.as_ptr() as usize, ix.len()),
            Indices::U32(ix) => (ix.as_ptr() as usize, ix.len()),
        };
        Self { mesh: [(positions.as_ptr() as usize, positions.len()), indices], matrix, state: *state, strips }
    }
}

/// The triangles of one draw of a mesh, binned by the strips of a frame, in memory the caller lends (see the
/// module docs). Made by [`StripBins::bin`]; read by [`draw_strip`] for each strip.
#[derive(Debug)]
pub struct StripBins<'m> {
    /// The kept triangles, in mesh order.
    kept: &'m [BinnedTriangle],
    /// The strips of each [`BIN_BLOCK`] of `kept`, or none where they did not fit the memory.
    blocks: &'m [BinnedTriangle],
    /// The first triangle not binned: it and all after it are drawn in every strip.
    rest: usize,
    key: BinKey,
    stats: DrawStats,
}

impl<'m> StripBins<'m> {
    /// Bins the triangles of `mesh`, as `shader` places them and `state` draws them, by the strips of `strips`,
    /// into `memory`.
    ///
    /// # Errors
    /// As [`super::draw`]: [`DrawError`] when the mesh lacks an attribute the shader reads or the state is out of
    /// range.
    pub fn bin<S: Shader>(
        memory: &'m mut [BinnedTriangle],
        mesh: &Mesh<'_>,
        shader: &S,
        state: &DrawState,
        strips: Strips,
    ) -> Result<Self, DrawError> {
        check(mesh, S::ATTRIBUTES, state)?;
        let key = BinKey::new(mesh, shader, state, strips);
        if key.matrix.is_none() {
            return Ok(Self { kept: &[], blocks: &[], rest: 0, key, stats: DrawStats::default() });
        }
        let (kept, rest, stats) = match state.edges {
            EdgeArithmetic::FixedPoint => bin_triangles::<S, FixedPoint>(memory, mesh, shader, state, strips),
            EdgeArithmetic::Float => bin_triangles::<S, FloatingPoint>(memory, mesh, shader, state, strips),
        };
        let (kept, after) = memory.split_at_mut(kept);
        let blocks = match after.get_mut(..kept.len().div_ceil(BIN_BLOCK)) {
            Some(blocks) => {
                for (block, entries) in blocks.iter_mut().zip(kept.chunks(BIN_BLOCK)) {
                    let first = entries.iter().map(|e| e.first).min().unwrap_or(0);
                    let last = entries.iter().map(|e| e.last).max().unwrap_or(0);
                    *block = BinnedTriangle { triangle: 0, first, last };
                }
                &*blocks
            }
            None => &[],
        };
        Ok(Self { kept, blocks, rest, key, stats })
    }

    /// Whether each strip's walk skips the [`BIN_BLOCK`]s of entries that do not meet it: false only where there are
    /// kept entries and the memory held no room for their summaries after them.
    #[must_use]
    pub fn blocks(&self) -> bool {
        !self.blocks.is_empty() || self.kept.is_empty()
    }

    /// The triangles kept.
    #[must_use]
    pub fn kept(&self) -> usize {
        self.kept.len()
    }

    /// The first triangle that was not binned (the triangle count when every one was): it and all after it are
    /// drawn in every strip.
    #[must_use]
    pub fn rest(&self) -> usize {
        self.rest
    }

    /// What binning counted for the triangles before [`Self::rest`], once for the frame: those it dropped by
    /// reason (a triangle that covers no pixel centre counts as rasterized, as in a draw), and the ones it kept
    /// as rasterized, with those to be clipped also as clipped. No fragments: the strips' draws count those.
    #[must_use]
    pub fn stats(&self) -> DrawStats {
        self.stats
    }
}

/// [`StripBins::bin`] with the edge set-up of the state.
#[inline(always)]
fn bin_triangles<S: Shader, E: EdgeSetup>(
    memory: &mut [BinnedTriangle],
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    strips: Strips,
) -> (usize, usize, DrawStats) {
    let (width, height) = (strips.width, strips.height);
    let volume = ClipVolume::new(width, height, 0, height);
    let raster = Rasterizer::for_frame(
        width,
        height,
        0..height,
        strips.samples,
        state.subpixel_bits,
        state.cull,
        state.front_face,
    );
    let mut cache = VertexCache::<S::Varyings>::new();
    let mut stats = DrawStats::default();
    let last_strip = strips.count() - 1;
    // Strip numbers are kept in a byte; in a frame of more strips, every triangle is drawn in every strip.
    let Ok(last) = u8::try_from(last_strip) else { return (0, 0, stats) };
    let limit = mesh.triangle_count().min(usize::from(u16::MAX) + 1);
    let mut kept = 0;
    for t in 0..mesh.triangle_count() {
        if t == limit || kept == memory.len() {
            return (kept, t, stats);
        }
        stats.triangles_in += 1;
        let Some([ia, ib, ic]) = mesh.triangle(t) else {
            stats.invalid += 1;
            continue;
        };
        let a = cache.position(shader, mesh, ia, &volume, &raster);
        let b = cache.position(shader, mesh, ib, &volume, &raster);
        let c = cache.position(shader, mesh, ic, &volume, &raster);
        let any = a.code | b.code | c.code;
        if any & NOT_FINITE != 0 {
            stats.invalid += 1;
            continue;
        }
        if a.code & b.code & c.code != 0 || (any & CLIP_MASK == 0 && any & NO_SCREEN != 0) {
            stats.outside += 1;
            continue;
        }
        let (first, last) = if any & CLIP_MASK != 0 {
            // Where its clipped pieces fall is found when they are drawn.
            stats.clipped += 1;
            (0, last)
        } else {
            match E::setup(&raster, [a.screen, b.screen, c.screen]) {
                Setup::Degenerate => {
                    stats.degenerate += 1;
                    continue;
                }
                Setup::Culled => {
                    stats.culled += 1;
                    continue;
                }
                Setup::Empty => {
                    stats.rasterized += 1;
                    continue;
                }
                Setup::Ready(coverage) => {
                    stats.rasterized += 1;
                    if !coverage.covers_a_centre() {
                        continue;
                    }
                    let (y0, y1) = coverage.rows();
                    // Rows within the frame: the rasterizer clamps the box to it.
                    let strip = |y: i32| (y as u32 / strips.rows) as u8;
                    (strip(y0), strip(y1))
                }
            }
        };
        memory[kept] = BinnedTriangle { triangle: t as u16, first, last };
        kept += 1;
    }
    (kept, mesh.triangle_count(), stats)
}

/// Draws into `target`, one strip of the frame `bins` was made for (or part of one), the triangles of `mesh` that
/// meet it, with `shader`: the pixels of [`super::draw`] on the same target. A draw that `bins` was not made for
/// (another mesh, matrix, state or frame, a target that does not lie within one strip) draws every triangle, as
/// [`super::draw`] does; so does a shader that does not tell its matrix ([`Shader::clip_from_object`]).
///
/// The counts returned are those of this strip's draw of the triangles it took (see [`StripBins::stats`]).
///
/// # Errors
/// As [`super::draw`].
pub fn draw_strip<S, C, D, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    bins: &StripBins<'_>,
) -> Result<DrawStats, DrawError>
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    check(mesh, S::ATTRIBUTES, state)?;
    let all = Walk::All(0..mesh.triangle_count());
    let strips = bins.key.strips;
    let fits = (target.width(), target.height(), target.samples()) == (strips.width, strips.height, strips.samples)
        && bins.key.matrix.is_some()
        && bins.key == BinKey::new(mesh, shader, state, strips);
    let walk = match strips.holding(&target.rows()) {
        Some(strip) if fits => Walk::Strip {
            kept: bins.kept,
            blocks: bins.blocks,
            next: 0,
            block_end: 0,
            strip: strip as u8,
            rest: bins.rest..mesh.triangle_count(),
        },
        _ => all,
    };
    Ok(draw_walk(target, mesh, shader, state, walk, Path::Specialised))
}

impl Iterator for Walk<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        match self {
            Self::All(all) => all.next(),
            Self::Strip { kept, blocks, next, block_end, strip, rest } => loop {
                if *next < *block_end {
                    let entry = kept[*next];
                    *next += 1;
                    if entry.meets(*strip) {
                        return Some(usize::from(entry.triangle));
                    }
                } else if *next < kept.len() {
                    // The next block: skipped whole if it does not meet the strip.
                    let end = (*next + BIN_BLOCK).min(kept.len());
                    match blocks.get(*next / BIN_BLOCK) {
                        Some(block) if !block.meets(*strip) => *next = end,
                        _ => *block_end = end,
                    }
                } else {
                    return rest.next();
                }
            },
        }
    }
}

/// The triangles a draw takes, in mesh order: all of them, or those of a strip's bins.
#[derive(Clone, Debug)]
pub(crate) enum Walk<'b> {
    /// Every triangle of the range.
    All(Range<usize>),
    /// The kept triangles that meet strip `strip`, then every triangle of `rest`.
    Strip {
        /// The kept triangles.
        kept: &'b [BinnedTriangle],
        /// Their blocks' strips (empty: none to skip by).
        blocks: &'b [BinnedTriangle],
        /// The next entry of `kept` to look at.
        next: usize,
        /// The end of the block being scanned; at most `next` between blocks.
        block_end: usize,
        /// The strip drawn.
        strip: u8,
        /// The triangles that were not binned.
        rest: Range<usize>,
    },
}
