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

use super::clip::ClipVolume;
use super::raster::Rasterizer;
use super::screen_vertex::ScreenVertex;
use super::{Shader, Varyings};
use crate::mesh::Mesh;

/// Number of entries: a power of two, small enough for a microcontroller's stack.
const ENTRIES: usize = 32;

/// The slot of vertex `index`: Fibonacci hashing (Knuth, TAOCP vol. 3, 6.4), the top bits of the index times
/// 2^32 / golden ratio, which spreads any stride over the slots.
#[inline(always)]
fn slot(index: usize) -> usize {
    ((index as u32).wrapping_mul(0x9E37_79B9) >> (32 - ENTRIES.trailing_zeros())) as usize
}

#[derive(Clone, Copy, Debug)]
struct Entry<V> {
    index: usize,
    position: ScreenVertex,
    varyings: Option<V>,
}

/// The cache.
pub(crate) struct VertexCache<V> {
    slots: [Option<Entry<V>>; ENTRIES],
    /// Whether the draw reads positions from the caller's memory, not from here: varyings then take slots.
    varyings_only: bool,
}

impl<V: Varyings> VertexCache<V> {
    /// An empty cache for positions and varyings.
    pub fn new() -> Self {
        Self { slots: [None; ENTRIES], varyings_only: false }
    }

    /// An empty cache for varyings alone, for a draw whose positions are in the caller's memory
    /// ([`crate::target::VertexMemory`]). [`Self::position`] must not be called on it.
    pub fn for_varyings() -> Self {
        Self { slots: [None; ENTRIES], varyings_only: true }
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
    ) -> ScreenVertex {
        match &self.slots[slot(index)] {
            Some(entry) if entry.index == index => entry.position,
            _ => self.miss(shader, mesh, index, volume, raster),
        }
    }

    /// The screen vertices of the triangle `[a, b, c]`: from `screen`, the frame's or the draw's own computed
    /// beforehand, when there is one (the indices in range: `Mesh::triangle` checks them against the vertex count),
    /// otherwise through the cache. Three values, not an array: an array kept them on the stack (`perf` on sphere1m:
    /// 17 % of the samples).
    #[inline(always)]
    pub fn triangle<S: Shader<Varyings = V>>(
        &mut self,
        screen: Option<&[ScreenVertex]>,
        shader: &S,
        mesh: &Mesh<'_>,
        [a, b, c]: [usize; 3],
        volume: &ClipVolume,
        raster: &Rasterizer,
    ) -> (ScreenVertex, ScreenVertex, ScreenVertex) {
        match screen {
            Some(screen) => (screen[a], screen[b], screen[c]),
            None => (
                self.position(shader, mesh, a, volume, raster),
                self.position(shader, mesh, b, volume, raster),
                self.position(shader, mesh, c, volume, raster),
            ),
        }
    }

    /// [`Self::position`] when the vertex is not cached: computes it and takes its slot.
    ///
    /// Inlined into each of a triangle's three lookups on a processor with SIMD registers (a program drawing the
    /// peers comparison's sphere1m through `draw_mesh`, 3 rounds taking turns: medians 46.9, 46.6, 63.8 ms against
    /// 51.5, 54.5, 51.7; two rounds agree, the third was disturbed),
    /// one shared copy elsewhere: on the firmware 1.5 KB less code for 2.5 % more instructions
    /// (`firmware/measure.sh`, 2026-11-26).
    #[cfg_attr(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"), inline(always))]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    fn miss<S: Shader<Varyings = V>>(
        &mut self,
        shader: &S,
        mesh: &Mesh<'_>,
        index: usize,
        volume: &ClipVolume,
        raster: &Rasterizer,
    ) -> ScreenVertex {
        let position = ScreenVertex::new(shader.position(mesh, index), volume, raster);
        self.slots[slot(index)] = Some(Entry { index, position, varyings: None });
        position
    }

    /// The varyings of a triangle's three vertices, as [`Self::varyings`] gives them. Inlined where
    /// [`Self::miss`] is.
    #[cfg_attr(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"), inline(always))]
    #[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(never))]
    pub fn triangle_varyings<S: Shader<Varyings = V>>(
        &mut self,
        shader: &S,
        mesh: &Mesh<'_>,
        [a, b, c]: [usize; 3],
    ) -> [V; 3] {
        [self.varyings(shader, mesh, a), self.varyings(shader, mesh, b), self.varyings(shader, mesh, c)]
    }

    /// The varyings of vertex `index`, from the cache or computed ([`Self::varyings_miss`]).
    #[inline(always)]
    pub fn varyings<S: Shader<Varyings = V>>(&mut self, shader: &S, mesh: &Mesh<'_>, index: usize) -> V {
        match &self.slots[slot(index)] {
            Some(Entry { index: cached, varyings: Some(varyings), .. }) if *cached == index => *varyings,
            _ => self.varyings_miss(shader, mesh, index),
        }
    }

    /// [`Self::varyings`] when they are not cached: computes them ([`vertex_stage`]) and keeps them if the vertex
    /// still has its slot, or, in a cache for varyings only, in the slot it takes.
    #[inline(always)]
    fn varyings_miss<S: Shader<Varyings = V>>(&mut self, shader: &S, mesh: &Mesh<'_>, index: usize) -> V {
        let varyings = vertex_stage(shader, mesh, index);
        let varyings_only = self.varyings_only;
        let slot = &mut self.slots[slot(index)];
        match slot {
            Some(entry) if entry.index == index => entry.varyings = Some(varyings),
            _ if varyings_only => {
                *slot = Some(Entry { index, position: ScreenVertex::UNSET, varyings: Some(varyings) })
            }
            _ => {}
        }
        varyings
    }
}

/// The shader's varyings for vertex `index`.
///
/// Out of line on a processor with SIMD registers: inlined, the vertex stage (for Gouraud shading, every light)
/// was copied into each of the draw loop's six lookups, 50 to 75 KB of code a draw loop. Inlined elsewhere, where
/// [`VertexCache::triangle_varyings`] is the one copy.
#[cfg_attr(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128"), inline(never))]
#[cfg_attr(not(any(target_feature = "sse2", target_feature = "neon", target_feature = "simd128")), inline(always))]
fn vertex_stage<S: Shader>(shader: &S, mesh: &Mesh<'_>, index: usize) -> S::Varyings {
    shader.varyings(mesh, index)
}
