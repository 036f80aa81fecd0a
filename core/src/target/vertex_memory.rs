//! Memory a caller may lend a target for the geometry of a draw: the screen positions of its vertices, and, for a
//! frame drawn in bands, the draw's triangles binned by band.
//!
//! Without it, a draw finds a triangle's vertices through a small cache on the stack
//! ([`crate::pipeline`]'s vertex cache): each vertex's position is computed about once per triangle that
//! meets it after the cache has lost it, and every triangle pays three lookups. With a buffer of at least one
//! [`ScreenVertex`] per vertex of the mesh, a draw first runs the position stage once for every vertex, in order,
//! into the buffer, and the triangle loop reads its three vertices from it: on a dense mesh most triangles are
//! culled or cover no pixel, and their cost is then little more than those reads. The pixels are the same either
//! way (`core/tests/vertex_memory.rs`).
//!
//! A frame drawn in bands (one after another, or on several threads) would run that pass over the whole mesh in
//! every band, and take every triangle through set-up in every band. Instead, once for the frame, its screen vertices
//! can be computed, in parts on any threads ([`SharedScreenVertices::compute`]), and its triangles binned by band
//! ([`BandBins`], also in parts); both are lent read-only to every band's target as its [`FrameGeometry`].

use crate::math::{Mat4, Vec3};
use crate::pipeline::{BandBins, DrawError, MAX_SUBPIXEL_BITS, ScreenVertex};

/// What a target lends its draws for their geometry: [`NoVertexMemory`] (the default), a caller's
/// `&mut [ScreenVertex]`, or the frame's [`FrameGeometry`].
pub trait VertexMemory: Default {
    /// What a draw finds: memory to compute its screen vertices into, the frame's computed beforehand, or neither;
    /// and the frame's bins of the draw's triangles, if any.
    fn source(&mut self) -> (VertexSource<'_>, &[BandBins<'_>]);
}

/// What a draw finds of its screen vertices in its target ([`VertexMemory::source`]): one type whatever the
/// memory, so that the pipeline is compiled once for all of them.
#[derive(Debug, Default)]
pub enum VertexSource<'a> {
    /// Nothing: the triangles find their vertices through the vertex cache.
    #[default]
    Cache,
    /// Memory for the position stage of every vertex, run once, in order, before the triangles (used by a draw of
    /// a mesh of at most as many vertices; a larger one uses the cache).
    Memory(&'a mut [ScreenVertex]),
    /// The frame's screen vertices, computed beforehand (used by the draw they were computed for; any other uses
    /// the cache).
    Shared(SharedScreenVertices<'a>),
}

/// No memory for vertices: draws use the vertex cache.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoVertexMemory;

impl VertexMemory for NoVertexMemory {
    #[inline(always)]
    fn source(&mut self) -> (VertexSource<'_>, &[BandBins<'_>]) {
        (VertexSource::Cache, &[])
    }
}

/// A caller's buffer: used by a draw whose mesh has at most as many vertices as it holds (a draw of a larger
/// mesh uses the vertex cache). Its contents between draws mean nothing.
impl VertexMemory for &mut [ScreenVertex] {
    #[inline(always)]
    fn source(&mut self) -> (VertexSource<'_>, &[BandBins<'_>]) {
        (VertexSource::Memory(self), &[])
    }
}

/// Screen vertices of one mesh under one matrix for one frame, computed beforehand and lent read-only to the targets
/// of the frame's bands (in a [`FrameGeometry`]), on any threads: each band's draw reads its triangles'
/// vertices from them instead of running the position stage itself.
///
/// They record what they were computed for: the mesh's positions (the slice itself, not a copy), the matrix, the
/// frame's size and the sub-pixel bits. A draw uses them only when all four are its own and its shader's position
/// stage is that matrix applied to the positions ([`crate::pipeline::Shader::clip_from_object`]); any other draw
/// uses the vertex cache, with the same pixels. The outcodes are the whole frame's, so in a band a triangle outside
/// the band's rows reaches set-up instead of being rejected by its outcodes: the same pixels, counted as rasterized
/// rather than outside.
#[derive(Clone, Copy, Debug)]
pub struct SharedScreenVertices<'a> {
    vertices: &'a [ScreenVertex],
    key: FrameKey,
}

/// What a set of shared screen vertices was computed for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct FrameKey {
    /// The address and length of the positions: the same slice, not merely equal values.
    positions: (usize, usize),
    /// The matrix's bits, column by column.
    matrix: [u32; 16],
    frame: (u32, u32),
    subpixel_bits: u8,
}

impl FrameKey {
    fn new(positions: &[Vec3], clip_from_object: &Mat4, frame: (u32, u32), subpixel_bits: u8) -> Self {
        let matrix = clip_from_object.to_bits();
        Self { positions: (positions.as_ptr() as usize, positions.len()), matrix, frame, subpixel_bits }
    }
}

impl<'a> SharedScreenVertices<'a> {
    /// The position stage of the vertices `first..first + out.len()` of `positions` under `clip_from_object`, for a
    /// `width x height` frame drawn with `subpixel_bits`, into `out`: one part of the vertices of a
    /// [`SharedScreenVertices`]. Entries past the end of `positions` are left alone.
    ///
    /// # Errors
    /// [`DrawError::SubpixelBits`] above [`MAX_SUBPIXEL_BITS`] (a draw refuses them too).
    pub fn compute(
        positions: &[Vec3],
        clip_from_object: &Mat4,
        (width, height): (u32, u32),
        subpixel_bits: u8,
        first: usize,
        out: &mut [ScreenVertex],
    ) -> Result<(), DrawError> {
        if subpixel_bits > MAX_SUBPIXEL_BITS {
            return Err(DrawError::SubpixelBits(subpixel_bits));
        }
        let count = positions.len().saturating_sub(first).min(out.len());
        crate::pipeline::frame_screen_vertices(
            |i| clip_from_object.project_point(positions[i]),
            (width, height),
            subpixel_bits,
            first,
            &mut out[..count],
        );
        Ok(())
    }

    /// `vertices`, computed by [`Self::compute`] for every one of `positions` (in one part or several) with the
    /// same matrix, frame size and sub-pixel bits. Wrong values here (vertices computed otherwise) give wrong
    /// pixels, never anything worse.
    pub fn new(
        vertices: &'a [ScreenVertex],
        positions: &[Vec3],
        clip_from_object: &Mat4,
        frame: (u32, u32),
        subpixel_bits: u8,
    ) -> Self {
        Self { vertices, key: FrameKey::new(positions, clip_from_object, frame, subpixel_bits) }
    }

    /// The vertices, when they were computed for a draw of `positions` under `clip_from_object` into a frame of
    /// `frame` pixels with `subpixel_bits`, and there is one for each position.
    #[inline]
    pub(crate) fn for_draw(
        &self,
        positions: &[Vec3],
        clip_from_object: &Mat4,
        frame: (u32, u32),
        subpixel_bits: u8,
    ) -> Option<&'a [ScreenVertex]> {
        let fits = self.key == FrameKey::new(positions, clip_from_object, frame, subpixel_bits);
        self.vertices.get(..positions.len()).filter(|_| fits)
    }
}

/// One draw's geometry computed once for a frame drawn in bands, lent read-only to each band's target
/// (`Target::for_draw`), on any threads: its screen vertices, its triangles binned by band, or both. A draw
/// uses each only when it was made for that draw (see [`SharedScreenVertices`] and [`BandBins`]); otherwise it
/// computes its own vertices, or takes every triangle: the same pixels.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameGeometry<'a> {
    /// The screen vertices of the draw's mesh.
    pub vertices: Option<SharedScreenVertices<'a>>,
    /// The draw's triangles binned by band, in parts that cover the mesh in order (empty: none).
    pub bins: &'a [BandBins<'a>],
}

impl VertexMemory for FrameGeometry<'_> {
    #[inline(always)]
    fn source(&mut self) -> (VertexSource<'_>, &[BandBins<'_>]) {
        (self.vertices.map_or(VertexSource::Cache, VertexSource::Shared), self.bins)
    }
}
