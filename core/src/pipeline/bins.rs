//! A frame's triangles binned by band of rows, once, in memory the caller lends: so that each band's draw meets only
//! the triangles that can reach its rows.
//!
//! A frame drawn in bands, one after another through a small buffer (a microcontroller's way: `firmware/`) or side
//! by side on threads (the program's renderer), would otherwise take every triangle through the position stage, the
//! outcodes and set-up once per band. [`BandBins::bin`] does that once for the frame: each triangle's vertices to the
//! screen (from the frame's [`SharedScreenVertices`] when it is given them, otherwise through the draw's vertex
//! cache), and the draw's own tests on the whole frame: a triangle that is invalid, outside, culled, degenerate or
//! covers no pixel centre (or sample) is dropped there, as every band's draw would drop it; any other is kept as a
//! [`BinnedTriangle`], its index and the bands that its bounding box's rows meet (every band, for a triangle that must
//! be clipped). A band's target lent the bins ([`crate::target::FrameGeometry`]) then draws only the kept triangles
//! that meet it, in mesh order, through the usual draw loop: the same pixels as drawing every triangle into that
//! target (`core/tests/bins.rs`).
//!
//! A [`BandBins`] bins one run of the mesh's triangles, at most [`MAX_PART_TRIANGLES`] of them; a larger mesh is
//! binned in several parts (on several threads, if the caller likes), and a draw takes the parts in order.
//! Bins are made for a position stage that is a matrix, and used only by a shader that tells its matrix
//! ([`Shader::clip_from_object`]), so that a draw can check they are its own; a draw they were not made for (another
//! mesh, matrix, state or frame, a target that does not lie within one band, parts that do not cover the mesh in
//! order) draws every triangle.
//!
//! # Memory and time
//! For a mesh of `N` vertices and `T` triangles drawn in `B` bands of `R` rows, `W` pixels wide:
//! - drawing each band whole: no memory beyond the band (and the vertex cache on the stack); every band pays the
//!   position stage of about `N` to `3 T` vertices and `T` rejections;
//! - binning: 4 bytes a kept triangle (at most `4 T`; for a closed model, about the triangles facing the camera), and
//!   4 bytes for each [`BIN_BLOCK`] of them, the position stage and set-up of the frame once, then per band a scan of
//!   the blocks and of the kept entries in the blocks that meet it (a few instructions each), and the draw of the
//!   triangles that meet it. Smaller bands take less band memory (`R W` colours and depths) and meet more triangles
//!   twice. Where there is no room left for the blocks, each band scans every entry: the same pixels.
//!
//! When the entries run out (or past [`MAX_PART_TRIANGLES`], or in a frame of more than [`MAX_BINNED_BANDS`] bands), the part's
//! triangles from there on are drawn in every band as a draw without bins draws them: slower, the same pixels.

use core::ops::{Range, RangeInclusive};

use super::clip::{CLIP_MASK, ClipVertex, MAX_CLIPPED};
use super::raster::{EdgeSetup, FixedPoint, FloatingPoint, Rasterizer, Setup};
use super::screen_vertex::{NO_SCREEN, NOT_FINITE};
use super::stats::Outcome;
use super::vertex_cache::VertexCache;
use super::{ClipVolume, DrawError, DrawState, DrawStats, EdgeArithmetic, PositionShader, Shader};
use crate::math::Mat4;
use crate::mesh::{Attributes, Indices, Mesh};
use crate::target::{Samples, SharedScreenVertices, TargetError, TargetView, check_size};

/// Kept triangles per block: the bands of each run of this many entries are summed up in one more entry, which a band
/// that it does not meet skips whole. Triangles kept in mesh order that lie near each other (a mesh ordered for the
/// vertex cache) fall in few bands, so a band skips most blocks.
pub const BIN_BLOCK: usize = 32;

/// The most bands a frame's bins tell apart (an entry holds a band in 8 bits): in a frame of more, every triangle is
/// drawn in every band.
pub const MAX_BINNED_BANDS: u32 = 1 << 8;

/// The most triangles one [`BandBins`] bins (an entry holds a triangle's place in its part in 16 bits).
pub const MAX_PART_TRIANGLES: usize = 1 << 16;

/// One kept triangle: its place in its part of the mesh and the first and last bands it may cover; or a
/// [`BIN_BLOCK`]'s summary, the first and last bands of its triangles. Four bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BinnedTriangle {
    triangle: u16,
    first: u8,
    last: u8,
}

impl BinnedTriangle {
    /// A value to fill a caller's buffer with before binning (any value will do: binning overwrites what it keeps).
    pub const UNSET: Self = Self { triangle: 0, first: 0, last: 0 };

    /// The bands the triangle may cover pixels of.
    #[must_use]
    pub fn bands(self) -> RangeInclusive<u32> {
        u32::from(self.first)..=u32::from(self.last)
    }

    /// Whether the triangle may cover pixels of band `band`.
    #[inline(always)]
    fn meets(self, band: u8) -> bool {
        self.first <= band && band <= self.last
    }
}

/// How a frame is cut into bands: its size, the rows of each band (the last one may have fewer), and the samples per
/// pixel of the bands' targets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bands {
    width: u32,
    height: u32,
    rows: u32,
    samples: Samples,
}

impl Bands {
    /// A `width x height` frame in bands of `rows` rows, drawn with `samples` per pixel.
    ///
    /// # Errors
    /// [`TargetError::Empty`] or [`TargetError::TooLarge`] for the frame's size, as
    /// [`crate::target::Target::band`]; [`TargetError::Rows`] when `rows` is 0.
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

    /// Samples per pixel of the bands' targets.
    #[must_use]
    pub fn samples(&self) -> Samples {
        self.samples
    }

    /// The number of bands.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.height.div_ceil(self.rows)
    }

    /// The frame rows of band `band` (empty past the last band).
    #[must_use]
    pub fn rows(&self, band: u32) -> Range<u32> {
        let start = band.saturating_mul(self.rows).min(self.height);
        start..start.saturating_add(self.rows).min(self.height)
    }

    /// The band holding every row of `rows`, if one does.
    fn holding(&self, rows: &Range<u32>) -> Option<u32> {
        let band = rows.start / self.rows;
        (rows.end > rows.start && (rows.end - 1) / self.rows == band).then_some(band)
    }
}

/// What a set of bins was made for: a draw that differs in any of these draws every triangle instead.
#[derive(Clone, Copy, Debug)]
struct BinKey {
    /// The addresses and lengths of the mesh's positions and indices (the slices themselves, not merely equal
    /// values).
    mesh: [(usize, usize); 2],
    /// The bits of the shader's clip-from-object matrix ([`Shader::clip_from_object`]).
    matrix: [u32; 16],
    state: DrawState,
    bands: Bands,
}

impl BinKey {
    /// The key of a draw of `mesh` with a shader whose position stage is `matrix`.
    fn new(mesh: &Mesh<'_>, matrix: &Mat4, state: &DrawState, bands: Bands) -> Self {
        let positions = mesh.positions();
        let indices = match mesh.indices() {
            Indices::Sequential => (0, 0),
            Indices::U16(ix) => (ix.as_ptr() as usize, ix.len()),
            Indices::U32(ix) => (ix.as_ptr() as usize, ix.len()),
        };
        let mesh = [(positions.as_ptr() as usize, positions.len()), indices];
        Self { mesh, matrix: matrix.to_bits(), state: *state, bands }
    }

    /// Whether `other` is the same key. The matrix's words are folded, not compared one by one: a chain of
    /// comparisons becomes a call to `memcmp`, which compares byte by byte on a microcontroller (about 900
    /// instructions a draw on a Cortex-M4).
    fn matches(&self, other: &Self) -> bool {
        let differ = self.matrix.iter().zip(&other.matrix).fold(0, |differ, (a, b)| differ | (a ^ b));
        differ == 0 && self.mesh == other.mesh && self.state == other.state && self.bands == other.bands
    }
}

/// A run of the triangles of one draw of a mesh, binned by the bands of a frame, in memory the caller lends (see the
/// module docs). Made by [`BandBins::bin`]; lent to each band's target with the draw's other parts
/// ([`crate::target::FrameGeometry`]).
#[derive(Clone, Debug)]
pub struct BandBins<'m> {
    /// The kept triangles, in mesh order, by place in `triangles`.
    kept: &'m [BinnedTriangle],
    /// The bands of each [`BIN_BLOCK`] of `kept`, or none where they did not fit the memory.
    blocks: &'m [BinnedTriangle],
    /// The mesh's triangles this part holds.
    triangles: Range<usize>,
    /// The first of `triangles` not binned: it and all after it are drawn in every band.
    rest: usize,
    /// What the bins were made for.
    key: BinKey,
    stats: DrawStats,
}

impl<'m> BandBins<'m> {
    /// Bins triangles `triangles` of `mesh` (clamped to the mesh), placed by `clip_from_object` and drawn with
    /// `state`, by the bands of `bands`, into `memory`: with their screen vertices from `vertices` when those were
    /// computed for this draw, otherwise through a vertex cache. The bins serve the draws of a shader whose position
    /// stage is `clip_from_object` and that tells it ([`Shader::clip_from_object`]).
    ///
    /// # Errors
    /// [`DrawError::SubpixelBits`] for a state a draw refuses.
    pub fn bin(
        memory: &'m mut [BinnedTriangle],
        mesh: &Mesh<'_>,
        clip_from_object: &Mat4,
        state: &DrawState,
        bands: Bands,
        triangles: Range<usize>,
        vertices: Option<&SharedScreenVertices<'_>>,
    ) -> Result<Self, DrawError> {
        state.check(mesh, Attributes::NONE)?;
        let end = triangles.end.min(mesh.triangle_count());
        let triangles = triangles.start.min(end)..end;
        let key = BinKey::new(mesh, clip_from_object, state, bands);
        let frame = (bands.width, bands.height);
        let screen = vertices.and_then(|v| v.for_draw(mesh.positions(), clip_from_object, frame, state.subpixel_bits));
        let shader = PositionShader { clip_from_object: *clip_from_object };
        let run = BinRun { mesh, shader: &shader, state, bands, triangles: triangles.clone(), screen };
        let (kept, rest, stats) = match state.edges {
            EdgeArithmetic::FixedPoint => run.bin::<FixedPoint>(memory),
            EdgeArithmetic::Float => run.bin::<FloatingPoint>(memory),
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
        Ok(Self { kept, blocks, triangles, rest, key, stats })
    }

    /// The entries a part of `triangles` triangles needs for every triangle to be kept, with its blocks.
    #[must_use]
    pub const fn entries_for(triangles: usize) -> usize {
        triangles + triangles.div_ceil(BIN_BLOCK)
    }

    /// Whether each band's walk skips the [`BIN_BLOCK`]s of entries that do not meet it: false only where there are
    /// kept entries and the memory held no room for their summaries after them.
    #[must_use]
    pub fn blocks(&self) -> bool {
        !self.blocks.is_empty() || self.kept.is_empty()
    }

    /// The mesh's triangles this part holds.
    #[must_use]
    pub fn triangles(&self) -> Range<usize> {
        self.triangles.clone()
    }

    /// The triangles kept.
    #[must_use]
    pub fn kept(&self) -> usize {
        self.kept.len()
    }

    /// The first of [`Self::triangles`] that was not binned (their end when every one was): it and all after it are
    /// drawn in every band.
    #[must_use]
    pub fn rest(&self) -> usize {
        self.rest
    }

    /// Adds to `counts[b]` the triangles that band `b`'s draw will take from this part: the kept ones that meet it
    /// and those not binned (bands past the end of `counts` are left out).
    pub fn count_by_band(&self, counts: &mut [usize]) {
        for entry in self.kept {
            let bands = entry.bands();
            let (start, end) = (*bands.start() as usize, *bands.end() as usize + 1);
            counts.get_mut(start..end.min(counts.len())).into_iter().flatten().for_each(|c| *c += 1);
        }
        let rest = self.triangles.end - self.rest;
        counts.iter_mut().for_each(|c| *c += rest);
    }

    /// What binning counted for the triangles before [`Self::rest`], once for the frame: those it dropped by reason
    /// (a triangle that covers no pixel centre counts as rasterized, as in a draw), the ones it kept as rasterized,
    /// and those to be clipped as clipped and by what their pieces come to, as a draw of the frame counts them. No
    /// fragments: the bands' draws count those.
    #[must_use]
    pub fn stats(&self) -> DrawStats {
        self.stats
    }
}

/// What [`BandBins::bin`] bins, once checked.
struct BinRun<'a, 'm> {
    mesh: &'a Mesh<'m>,
    shader: &'a PositionShader,
    state: &'a DrawState,
    bands: Bands,
    triangles: Range<usize>,
    /// The frame's screen vertices, when they are this draw's.
    screen: Option<&'a [crate::pipeline::ScreenVertex]>,
}

impl BinRun<'_, '_> {
    /// Bins with the edge set-up `E` into `memory`: the entries kept, the first triangle not binned, and the counts.
    #[inline(always)]
    fn bin<E: EdgeSetup>(&self, memory: &mut [BinnedTriangle]) -> (usize, usize, DrawStats) {
        let Self { mesh, shader, state, bands, screen, .. } = *self;
        let (width, height) = (bands.width, bands.height);
        let volume = ClipVolume::new(width, height, 0, height);
        let raster = Rasterizer::for_frame(
            width,
            height,
            0..height,
            bands.samples,
            state.subpixel_bits,
            state.cull,
            state.front_face,
        );
        let mut cache = VertexCache::<()>::new();
        let mut stats = DrawStats::default();
        let first = self.triangles.start;
        if bands.count() > MAX_BINNED_BANDS {
            return (0, first, stats);
        }
        let last = (bands.count() - 1) as u8;
        let limit = self.triangles.end.min(first + MAX_PART_TRIANGLES);
        let mut kept = 0;
        for t in self.triangles.clone() {
            if t == limit || kept == memory.len() {
                return (kept, t, stats);
            }
            stats.triangles_in += 1;
            let Some(indices) = mesh.triangle(t) else {
                stats.invalid += 1;
                continue;
            };
            let (a, b, c) = cache.triangle(screen, shader, mesh, indices, &volume, &raster);
            let any = a.code | b.code | c.code;
            if any & NOT_FINITE != 0 {
                stats.invalid += 1;
                continue;
            }
            if a.code & b.code & c.code != 0 || (any & CLIP_MASK == 0 && any & NO_SCREEN != 0) {
                stats.outside += 1;
                continue;
            }
            let (first_band, last_band) = if any & CLIP_MASK != 0 {
                stats.clipped += 1;
                // What its pieces come to is counted here, once for the frame, as a draw of the frame counts it;
                // where they fall is found when the bands draw them.
                let tri = indices.map(|i| ClipVertex { pos: shader.position(mesh, i), var: () });
                let polygon = volume.clip(&tri, any & CLIP_MASK);
                let verts = polygon.vertices();
                let mut snapped = [None; MAX_CLIPPED];
                for (s, v) in snapped.iter_mut().zip(verts) {
                    *s = raster.snap(v.pos);
                }
                let mut outcome = Outcome::default();
                for i in 1..verts.len().saturating_sub(1) {
                    let (Some(p), Some(q), Some(r)) = (snapped[0], snapped[i], snapped[i + 1]) else { continue };
                    outcome.record(&E::setup(&raster, [p, q, r]));
                }
                let reaches_pixels = outcome.rasterized();
                outcome.count(&mut stats);
                if !reaches_pixels {
                    continue;
                }
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
                        let band = |y: i32| (y as u32 / bands.rows) as u8;
                        (band(y0), band(y1))
                    }
                }
            };
            // Below `limit`: the place fits 16 bits.
            memory[kept] = BinnedTriangle { triangle: (t - first) as u16, first: first_band, last: last_band };
            kept += 1;
        }
        (kept, self.triangles.end, stats)
    }
}

/// The triangles a draw takes, in mesh order: all of them, or those its target's bins hold for its band.
#[derive(Clone, Debug)]
pub(crate) enum Walk<'b> {
    /// Every triangle of the range.
    All(Range<usize>),
    /// The bins' triangles that meet one band.
    Bins(BinWalk<'b>),
}

impl<'b> Walk<'b> {
    /// The walk of a draw of `mesh` with `shader` and `state` into `target`, lent `parts`: through the bins when they
    /// were made for this draw, cover the mesh in order, and `target` lies within one of their bands; otherwise
    /// every triangle.
    pub(crate) fn new<S: Shader>(
        parts: &'b [BandBins<'b>],
        mesh: &Mesh<'_>,
        shader: &S,
        state: &DrawState,
        target: &TargetView<'_>,
    ) -> Self {
        let all = Self::All(0..mesh.triangle_count());
        let (Some(first), Some(matrix)) = (parts.first(), shader.clip_from_object()) else { return all };
        let bands = first.key.bands;
        if (target.width(), target.height(), target.samples()) != (bands.width, bands.height, bands.samples) {
            return all;
        }
        let key = BinKey::new(mesh, matrix, state, bands);
        let mut end = 0;
        for part in parts {
            if !part.key.matches(&key) || part.triangles.start != end {
                return all;
            }
            end = part.triangles.end;
        }
        match bands.holding(&target.rows()) {
            Some(band) if end == mesh.triangle_count() => Self::Bins(BinWalk {
                parts,
                base: 0,
                kept: &[],
                blocks: &[],
                next: 0,
                block_end: 0,
                band: band as u8,
                rest: 0..0,
            }),
            _ => all,
        }
    }
}

/// A walk through the kept triangles of each part that meet one band, then the part's triangles not binned.
#[derive(Clone, Debug)]
pub(crate) struct BinWalk<'b> {
    /// The parts not yet started.
    parts: &'b [BandBins<'b>],
    /// The first triangle of the part being walked.
    base: usize,
    /// Its kept triangles.
    kept: &'b [BinnedTriangle],
    /// Their blocks' bands (empty: none to skip by).
    blocks: &'b [BinnedTriangle],
    /// The next entry of `kept` to look at.
    next: usize,
    /// The end of the block being scanned; at most `next` between blocks.
    block_end: usize,
    /// The band drawn.
    band: u8,
    /// The part's triangles that were not binned.
    rest: Range<usize>,
}

impl Iterator for Walk<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        match self {
            Self::All(all) => all.next(),
            Self::Bins(walk) => walk.next(),
        }
    }
}

impl Iterator for BinWalk<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        loop {
            if self.next < self.block_end {
                let entry = self.kept[self.next];
                self.next += 1;
                if entry.meets(self.band) {
                    return Some(self.base + usize::from(entry.triangle));
                }
            } else if self.next < self.kept.len() {
                // The next block: skipped whole if it does not meet the band.
                let end = (self.next + BIN_BLOCK).min(self.kept.len());
                match self.blocks.get(self.next / BIN_BLOCK) {
                    Some(block) if !block.meets(self.band) => self.next = end,
                    _ => self.block_end = end,
                }
            } else if let Some(t) = self.rest.next() {
                return Some(t);
            } else {
                let (part, parts) = self.parts.split_first()?;
                *self = Self {
                    parts,
                    base: part.triangles.start,
                    kept: part.kept,
                    blocks: part.blocks,
                    next: 0,
                    block_end: 0,
                    band: self.band,
                    rest: part.rest..part.triangles.end,
                };
            }
        }
    }
}
