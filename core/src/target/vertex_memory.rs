//! Memory a caller may lend a target for the screen positions of a draw's vertices.
//!
//! Without it, a draw finds a triangle's vertices through a small cache on the stack
//! ([`crate::pipeline`]'s vertex cache): each vertex's position is computed about once per triangle that
//! meets it after the cache has lost it, and every triangle pays three lookups. With a buffer of at least one
//! [`ScreenVertex`] per vertex of the mesh, a draw first runs the position stage once for every vertex, in order,
//! into the buffer, and the triangle loop reads its three vertices from it: on a dense mesh most triangles are
//! culled or cover no pixel, and their cost is then little more than those reads. The pixels are the same either
//! way (`core/tests/vertex_memory.rs`).

use crate::pipeline::ScreenVertex;

/// Where a target keeps vertex positions for its draws, if anywhere: [`NoVertexMemory`] (the default) or a
/// caller's `&mut [ScreenVertex]`.
pub trait VertexMemory: Default {
    /// The buffer, if there is one.
    fn screen_vertices(&mut self) -> Option<&mut [ScreenVertex]>;
}

/// No memory for vertices: draws use the vertex cache.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoVertexMemory;

impl VertexMemory for NoVertexMemory {
    #[inline(always)]
    fn screen_vertices(&mut self) -> Option<&mut [ScreenVertex]> {
        None
    }
}

/// A caller's buffer: used by a draw whose mesh has at most as many vertices as it holds (a draw of a larger
/// mesh uses the vertex cache). Its contents between draws mean nothing.
impl VertexMemory for &mut [ScreenVertex] {
    #[inline(always)]
    fn screen_vertices(&mut self) -> Option<&mut [ScreenVertex]> {
        Some(self)
    }
}
