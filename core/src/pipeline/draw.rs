//! A draw call: mesh → vertex stage → clip → raster → fragment → target.

use super::batch::FragmentBatch;
use super::clip::{CLIP_MASK, ClipVertex, ClipVolume, MAX_CLIPPED};
use super::depth_stage::{DepthLess, DepthOff, DepthStage, DynamicDepth};
use super::edges::{DynamicEdgeSetup, EdgeSetup, FixedPoint, FloatingPoint};
use super::interpolator::{Affine, DynamicInterpolator, Interpolator, PerspectiveCorrect};
use super::raster::{Rasterizer, Setup, Stages, shade_batch};
use super::screen_vertex::{NO_SCREEN, NOT_FINITE, ScreenVertex, screen_vertices};
use super::strip_bins::Walk;
use super::vertex_cache::VertexCache;
use super::{DepthTest, DrawState, DrawStats, EdgeArithmetic, Interpolation, MAX_SUBPIXEL_BITS, Shader, Varyings};
use crate::mesh::{Attributes, Mesh};
use crate::target::{ColorBuffer, DepthBuffer, Target, VertexMemory};

/// Why a draw was refused (nothing was drawn).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawError {
    /// The shader reads a vertex attribute the mesh does not have.
    MissingAttributes {
        /// What the shader reads.
        needed: Attributes,
        /// What the mesh has.
        present: Attributes,
    },
    /// [`DrawState::subpixel_bits`] is above [`MAX_SUBPIXEL_BITS`].
    SubpixelBits(u8),
}

impl core::fmt::Display for DrawError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::MissingAttributes { needed, present } => {
                write!(f, "the shader needs mesh attributes {needed:?} but the mesh has {present:?}")
            }
            Self::SubpixelBits(b) => write!(f, "{b} sub-pixel bits requested, at most {MAX_SUBPIXEL_BITS} supported"),
        }
    }
}

impl core::error::Error for DrawError {}

/// Draws the triangles of `mesh` with `shader` into `target`.
///
/// The edge arithmetic, interpolation mode and depth test of `state` select one of eight compiled pixel loops,
/// once for the whole draw; together with the shader type that makes a loop that does exactly what this draw
/// needs.
///
/// # Errors
/// [`DrawError`] when the mesh lacks an attribute the shader reads or the state is out of range. Bad triangles
/// (indices out of range, NaN or infinite values) are skipped and counted instead.
///
/// # Examples
/// ```
/// use rastty_core::{math::{Vec3, Vec4}, mesh::{Attributes, Indices, Mesh}, pipeline::*, target::*};
///
/// /// Positions are already in clip space; every pixel is red.
/// struct Red;
/// impl Shader for Red {
///     type Varyings = ();
///     type Face = ();
///     const ATTRIBUTES: Attributes = Attributes::NONE;
///     fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
///         mesh.position(i).extend(1.0)
///     }
///     fn varyings(&self, _: &Mesh<'_>, _: usize) {}
///     fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
///     fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
///         Vec3::new(1.0, 0.0, 0.0)
///     }
/// }
///
/// let positions = [Vec3::new(-1.0, -1.0, 0.5), Vec3::new(1.0, -1.0, 0.5), Vec3::new(-1.0, 1.0, 0.5)];
/// let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
/// let (mut color, mut depth) = ([0u32; 16], [0f32; 16]);
/// let mut target = Target::new(Rgb888(&mut color), &mut depth[..], 4, 4).unwrap();
/// target.clear(Vec3::ZERO);
/// let stats = draw(&mut target, &mesh, &Red, &DrawState::default()).unwrap();
/// // The lower-left half of 4x4. The 4 centres on the diagonal lie on its right edge: the top-left rule leaves
/// // them to a neighbour, so 0 + 1 + 2 + 3 pixels remain.
/// assert_eq!(stats.fragments, 6);
/// assert_eq!(color[12], 0xFF0000);
/// ```
pub fn draw<S, C, D, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
) -> Result<DrawStats, DrawError>
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    check(mesh, S::ATTRIBUTES, state)?;
    Ok(draw_walk(target, mesh, shader, state, Walk::All(0..mesh.triangle_count())))
}

/// [`draw`] of the triangles `walk` takes, once checked: the first choice, the edge arithmetic.
#[inline(always)]
pub(super) fn draw_walk<S, C, D, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    walk: Walk<'_>,
) -> DrawStats
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    match state.edges {
        EdgeArithmetic::FixedPoint => with_interpolation_and_depth(target, mesh, shader, state, FixedPoint, walk),
        EdgeArithmetic::Float => with_interpolation_and_depth(target, mesh, shader, state, FloatingPoint, walk),
    }
}

/// The second and third choices of [`draw`]: the interpolator and the depth stage.
fn with_interpolation_and_depth<S, C, D, E, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    edges: E,
    walk: Walk<'_>,
) -> DrawStats
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
    E: EdgeSetup,
{
    use {DepthTest as T, Interpolation as I};
    let stages = (edges, walk);
    match (state.interpolation, state.depth_test) {
        (I::PerspectiveCorrect, T::Less) => run(target, mesh, shader, state, stages, PerspectiveCorrect, DepthLess),
        (I::PerspectiveCorrect, T::Off) => run(target, mesh, shader, state, stages, PerspectiveCorrect, DepthOff),
        (I::Affine, T::Less) => run(target, mesh, shader, state, stages, Affine, DepthLess),
        (I::Affine, T::Off) => run(target, mesh, shader, state, stages, Affine, DepthOff),
    }
}

/// Like [`draw`], but through one general pixel loop that decides interpolation and depth test per pixel.
///
/// Slower, and otherwise identical to the pixel: it exists so tests can prove that the specialised loops compute
/// exactly what the general one does, and benchmarks can show what specialising saves.
///
/// # Errors
/// As [`draw`].
pub fn draw_unspecialised<S, C, D, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
) -> Result<DrawStats, DrawError>
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    check(mesh, S::ATTRIBUTES, state)?;
    let (interpolator, depth) = (DynamicInterpolator(state.interpolation), DynamicDepth(state.depth_test));
    let walk = Walk::All(0..mesh.triangle_count());
    Ok(run(target, mesh, shader, state, (DynamicEdgeSetup(state.edges), walk), interpolator, depth))
}

pub(super) fn check(mesh: &Mesh<'_>, needed: Attributes, state: &DrawState) -> Result<(), DrawError> {
    let present = mesh.attributes();
    if !present.contains(needed) {
        return Err(DrawError::MissingAttributes { needed, present });
    }
    if state.subpixel_bits > MAX_SUBPIXEL_BITS {
        return Err(DrawError::SubpixelBits(state.subpixel_bits));
    }
    Ok(())
}

/// What happened to the pieces of one input triangle, to count it once in [`DrawStats`].
#[derive(Default)]
struct Outcome {
    rasterized: bool,
    culled: bool,
    degenerate: bool,
}

impl Outcome {
    fn record<E>(&mut self, setup: &Setup<E>) {
        match setup {
            Setup::Degenerate => self.degenerate = true,
            Setup::Culled => self.culled = true,
            Setup::Empty | Setup::Ready(_) => self.rasterized = true,
        }
    }

    fn count(self, stats: &mut DrawStats) {
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

/// The screen vertices in `memory` computed beforehand for this draw (its mesh's positions under the shader's
/// matrix, into a frame of `frame` pixels with the state's sub-pixel bits), if there are any.
#[inline(always)]
fn shared_vertices<'m, S: Shader, M: VertexMemory>(
    memory: &'m M,
    shader: &S,
    mesh: &Mesh<'_>,
    frame: (u32, u32),
    state: &DrawState,
) -> Option<&'m [ScreenVertex]> {
    let matrix = shader.clip_from_object()?;
    memory.shared()?.for_draw(mesh.positions(), matrix, frame, state.subpixel_bits)
}

/// The draw loop over the triangles `walk` takes, monomorphised on the shader, the edge arithmetic, the
/// interpolator and the depth stage.
fn run<S, C, D, E, I, Z, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    (edges, walk): (E, Walk<'_>),
    interpolator: I,
    depth: Z,
) -> DrawStats
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
    E: EdgeSetup,
    I: Interpolator,
    Z: DepthStage,
{
    let rows = target.rows();
    let volume = ClipVolume::new(target.width(), target.height(), rows.start, rows.end);
    let raster = Rasterizer::new(target, state.subpixel_bits, state.cull, state.front_face);
    // Asked once per draw; a constant false for shaders that never discard.
    let stages = Stages { shader, interpolator, depth, cutout: S::CUTOUT && shader.cutout(), slopes: shader.slopes() };
    // The caller's memory for screen positions, taken out of the target for the draw (the pixel loop borrows the
    // target) and put back at the end. Screen vertices computed beforehand for the frame are read as they are,
    // when they are this draw's; a buffer holding every vertex of the mesh gets the position stage once per
    // vertex, in order, first; otherwise the triangles go through the cache. (`shared_vertices` is asked twice:
    // a `match` on it would keep `memory` borrowed into the arm that borrows it mutably.)
    let mut memory = core::mem::take(&mut target.vertices);
    let frame = (target.width(), target.height());
    let screen: Option<&[ScreenVertex]> = if shared_vertices(&memory, shader, mesh, frame, state).is_some() {
        shared_vertices(&memory, shader, mesh, frame, state)
    } else {
        memory.screen_vertices().and_then(|m| m.get_mut(..mesh.vertex_count())).map(|screen| {
            screen_vertices(|i| shader.position(mesh, i), 0, &volume, &raster, screen);
            &*screen
        })
    };
    let mut cache = if screen.is_some() { VertexCache::for_varyings() } else { VertexCache::new() };
    let mut stats = DrawStats::default();
    // Fragments of a batched shader, across triangles; made with the first rasterized triangle's values.
    let mut batch: Option<FragmentBatch<S::Varyings, S::Face>> = None;

    // A loop, not `Mesh::for_each_triangle`: its closure, called from one place per index type, stayed out of line,
    // and each triangle paid a call and reloaded every captured value (callgrind, sphere1m with vertex memory, two
    // frames: 776.1 against 725.9 million instructions).
    for t in walk {
        let indices = mesh.triangle(t);
        stats.triangles_in += 1;
        let Some(indices) = indices else {
            stats.invalid += 1;
            continue;
        };
        // Three lookups, not `indices.map`: the array map kept its results on the stack (`perf` on sphere1m: 17 % of
        // the samples).
        let [ia, ib, ic] = indices;
        let (a, b, c) = match screen {
            // In range: `Mesh::triangle` checks each index against the vertex count.
            Some(screen) => (screen[ia], screen[ib], screen[ic]),
            None => (
                cache.position(shader, mesh, ia, &volume, &raster),
                cache.position(shader, mesh, ib, &volume, &raster),
                cache.position(shader, mesh, ic, &volume, &raster),
            ),
        };
        let any = a.code | b.code | c.code;
        if any & NOT_FINITE != 0 {
            stats.invalid += 1;
            continue;
        }
        if a.code & b.code & c.code != 0 {
            stats.outside += 1;
            continue;
        }
        let mut outcome = Outcome::default();
        let clip_mask = any & CLIP_MASK;
        if clip_mask == 0 {
            // The common case: varyings only once coverage is known.
            if any & NO_SCREEN != 0 {
                stats.outside += 1;
                continue;
            }
            let (sa, sb, sc) = (a.screen, b.screen, c.screen);
            let setup = edges.setup(&raster, [sa, sb, sc]);
            outcome.record(&setup);
            if let Setup::Ready(coverage) = setup
                && coverage.covers_a_centre()
            {
                let vars = cache.triangle_varyings(shader, mesh, indices);
                if !vars.iter().all(Varyings::is_finite) {
                    stats.invalid += 1;
                    continue;
                }
                let face = shader.face(mesh, indices);
                let batch = batch.get_or_insert_with(|| FragmentBatch::new(vars[0], face));
                stats.fragments += coverage.fill(&stages, &face, vars.each_ref(), batch, target);
            }
        } else {
            // Clipping cuts varyings too, so they are needed first.
            stats.clipped += 1;
            let vars = cache.triangle_varyings(shader, mesh, indices);
            if !vars.iter().all(Varyings::is_finite) {
                stats.invalid += 1;
                continue;
            }
            let tri = [
                ClipVertex { pos: shader.position(mesh, ia), var: vars[0] },
                ClipVertex { pos: shader.position(mesh, ib), var: vars[1] },
                ClipVertex { pos: shader.position(mesh, ic), var: vars[2] },
            ];
            let polygon = volume.clip(&tri, clip_mask);
            let verts = polygon.vertices();
            let mut snapped = [None; MAX_CLIPPED];
            for (s, v) in snapped.iter_mut().zip(verts) {
                *s = raster.snap(v.pos);
            }
            let mut face = None;
            // A convex polygon is a fan around its first vertex.
            for i in 1..verts.len().saturating_sub(1) {
                let (Some(p), Some(q), Some(r)) = (snapped[0], snapped[i], snapped[i + 1]) else { continue };
                let setup = edges.setup(&raster, [p, q, r]);
                outcome.record(&setup);
                if let Setup::Ready(coverage) = setup {
                    let face = face.get_or_insert_with(|| shader.face(mesh, indices));
                    let batch = batch.get_or_insert_with(|| FragmentBatch::new(verts[0].var, *face));
                    let pieces = [&verts[0].var, &verts[i].var, &verts[i + 1].var];
                    stats.fragments += coverage.fill(&stages, face, pieces, batch, target);
                }
            }
        }
        outcome.count(&mut stats);
    }
    if let Some(batch) = batch.as_mut().filter(|b| !b.is_empty()) {
        stats.fragments += shade_batch(&stages, batch, target);
    }
    target.vertices = memory;
    stats
}
