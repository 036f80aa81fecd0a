//! A post-transform vertex cache: the vertex stage runs once for a vertex that neighbouring triangles share.
//!
//! Indexed meshes reuse each vertex in about six triangles, mostly close together in the index buffer. A small
//! direct-mapped cache keeps the last results on the stack (no allocation). The slot is a multiplicative hash of
//! the vertex index, not the index modulo the size: a grid mesh whose rows are a multiple of 32 vertices (plus or
//! minus one) apart would otherwise put a triangle's vertices from two rows in the same slot and reuse nothing.
//! For a mesh in row order it cuts vertex-stage runs from three per triangle to about one
//! (`core/tests/vertex_cache.rs`). Positions (with their
//! outcodes and snapped screen coordinates) are computed when a triangle is met; varyings only when one of the
//! vertex's triangles is actually rasterized. The cache cannot change a pixel, because the vertex stage is a
//! function of the vertex index alone.

use super::clip::{CLIP_MASK, ClipVolume};
use super::raster::{Rasterizer, Snapped};
use super::{Shader, Varyings};
use crate::math::Vec4;
use crate::mesh::Mesh;

/// Number of entries: a power of two, small enough for a microcontroller's stack.
const ENTRIES: usize = 32;

/// The slot of vertex `index`: Fibonacci hashing (Knuth, TAOCP vol. 3, 6.4), the top bits of the index times
/// 2^32 / golden ratio, which spreads any stride over the slots.
#[inline(always)]
fn slot(index: usize) -> usize {
    ((index as u32).wrapping_mul(0x9E37_79B9) >> (32 - ENTRIES.trailing_zeros())) as usize
}

/// What is known of a vertex before its varyings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct VertexPosition {
    /// Clip-space position.
    pub pos: Vec4,
    /// The position is finite.
    pub finite: bool,
    /// Outcode against the draw's [`ClipVolume`].
    pub code: u16,
    /// Snapped screen position, when the vertex needs no clipping.
    pub screen: Option<Snapped>,
}

#[derive(Clone, Copy, Debug)]
struct Entry<V> {
    index: usize,
    position: VertexPosition,
    varyings: Option<V>,
}

/// The cache.
pub(crate) struct VertexCache<V> {
    slots: [Option<Entry<V>>; ENTRIES],
}

impl<V: Varyings> VertexCache<V> {
    pub fn new() -> Self {
        Self { slots: [None; ENTRIES] }
    }

    /// The position of vertex `index`, from the cache or computed (evicting whatever shared its slot).
    #[inline(always)]
    pub fn position<S: Shader<Varyings = V>>(
        &mut self,
        shader: &S,
        mesh: &Mesh<'_>,
        index: usize,
        volume: &ClipVolume,
        raster: &Rasterizer,
    ) -> VertexPosition {
        let slot = &mut self.slots[slot(index)];
        match slot {
            Some(entry) if entry.index == index => entry.position,
            _ => {
                let pos = shader.position(mesh, index);
                let finite = pos.is_finite();
                let code = if finite { volume.outcode(pos) } else { 0 };
                let screen = if finite && code & CLIP_MASK == 0 { raster.snap(pos) } else { None };
                let position = VertexPosition { pos, finite, code, screen };
                *slot = Some(Entry { index, position, varyings: None });
                position
            }
        }
    }

    /// The varyings of vertex `index`, from the cache or computed (and kept if the vertex still has its slot).
    #[inline(always)]
    pub fn varyings<S: Shader<Varyings = V>>(&mut self, shader: &S, mesh: &Mesh<'_>, index: usize) -> V {
        match &mut self.slots[slot(index)] {
            Some(entry) if entry.index == index => *entry.varyings.get_or_insert_with(|| shader.varyings(mesh, index)),
            _ => shader.varyings(mesh, index),
        }
    }
}
