//! A draw call: mesh → vertex stage → clip → raster → fragment → target.

use super::bins::Walk;
use super::clip::{CLIP_MASK, ClipVertex, ClipVolume, MAX_CLIPPED};
use super::fragment_stage::{FragmentStage, ShaderStage, Writes};
use super::fragments::Fragments;
use super::raster::{Coverage, EdgeSetup, FixedPoint, FloatingPoint, Pass, PixelLoops, Rasterizer, Setup, Shading};
use super::screen_vertex::{NO_SCREEN, NOT_FINITE, ScreenVertex, screen_vertices};
use super::stats::Outcome;
use super::vertex_cache::VertexCache;
use super::{DrawState, DrawStats, EdgeArithmetic, Interpolation, MAX_SUBPIXEL_BITS, Shader, Varyings};
use crate::mesh::{Attributes, Mesh};
use crate::target::{ColorBuffer, DepthBuffer, Samples, Target, TargetView, VertexMemory, VertexSource};

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
/// The state's interpolation and the target's samples select the pixel loop, once for the whole draw; the loops do
/// not depend on the shader or the buffers, and hand the shader batches of fragments
/// ([`Shader::shade_batch`]).
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
    state.check(mesh, S::ATTRIBUTES)?;
    Ok(draw_walk(target, mesh, shader, state, Path::Specialised))
}

/// Like [`draw`], but through the general pixel loops, which decide the edge arithmetic and the interpolation
/// per pixel.
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
    state.check(mesh, S::ATTRIBUTES)?;
    Ok(draw_walk(target, mesh, shader, state, Path::General))
}

/// Which pixel loops a draw runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Path {
    /// Those specialised for the draw ([`PixelLoops::specialised`]).
    Specialised,
    /// The general ones ([`PixelLoops::general`]).
    General,
}

/// [`draw`], once checked: the target as one type whatever its buffers ([`Target::views`]), so that what follows is
/// compiled once per shader, and the triangles it takes: those of the target's bins for its band when they were made
/// for this draw ([`Walk`]), otherwise all of them.
#[inline(always)]
fn draw_walk<S, C, D, M>(
    target: &mut Target<C, D, M>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    path: Path,
) -> DrawStats
where
    S: Shader,
    C: ColorBuffer,
    D: DepthBuffer,
    M: VertexMemory,
{
    let (view, vertices, bins) = target.views(state.depth_test);
    let walk = Walk::new(bins, mesh, shader, state, &view);
    match state.edges {
        EdgeArithmetic::FixedPoint => run::<S, FixedPoint>(view, vertices, mesh, shader, state, walk, path),
        EdgeArithmetic::Float => run::<S, FloatingPoint>(view, vertices, mesh, shader, state, walk, path),
    }
}

/// The draw loop over the triangles `walk` takes, compiled per shader and edge arithmetic: the vertex stage,
/// clipping and set-up, then each triangle that covers a pixel through the draw's pixel loop.
///
/// The edge arithmetic is a type here, the set-up's, for the draw loop's sake: chosen per triangle instead, the
/// two set-ups' results met in one value, which was kept in memory, not registers (callgrind, sphere1m: 50
/// instructions a triangle more). The pixel loops do not depend on it.
fn run<S: Shader, E: EdgeSetup>(
    target: TargetView<'_>,
    vertices: VertexSource<'_>,
    mesh: &Mesh<'_>,
    shader: &S,
    state: &DrawState,
    walk: Walk<'_>,
    path: Path,
) -> DrawStats {
    let rows = target.rows();
    let volume = ClipVolume::new(target.width(), target.height(), rows.start, rows.end);
    let raster = Rasterizer::new(&target, state.subpixel_bits, state.cull, state.front_face);
    let frame = (target.width(), target.height());
    // The pixel loops, chosen once, and what they work with: the target, the batch and the fragment stage.
    let stage = ShaderStage::new(shader);
    let shading = match (S::FRAGMENT_STAGE, stage.cutout()) {
        (false, _) => Shading::DepthOnly,
        (true, false) => Shading::Shaded,
        (true, true) => Shading::CutOut,
    };
    let loops = match path {
        Path::Specialised => PixelLoops::specialised(state.interpolation, target.samples(), shading),
        Path::General => PixelLoops::general(target.samples(), shading),
    };
    // The one combination compiled into this loop: exact edges, one sample per pixel, perspective-correct (or no
    // fragment stage), nothing discarded; the general path never.
    let inline = path == Path::Specialised
        && target.samples() == Samples::One
        && match shading {
            Shading::DepthOnly => true,
            Shading::Shaded => state.interpolation == Interpolation::PerspectiveCorrect,
            Shading::CutOut => false,
        };
    let mut pass = Pass {
        fragments: S::FRAGMENT_STAGE.then(Fragments::new),
        interpolation: state.interpolation,
        cutout: shading == Shading::CutOut,
        // Asked once per draw.
        slopes: shader.slopes(),
        target,
        stage,
    };
    // Screen vertices computed beforehand for the frame are read as they are, when they are this draw's; memory
    // holding every vertex of the mesh gets the position stage once per vertex, in order, first; otherwise the
    // triangles go through the cache.
    let screen: Option<&[ScreenVertex]> = match vertices {
        VertexSource::Shared(shared) => shader
            .clip_from_object()
            .and_then(|matrix| shared.for_draw(mesh.positions(), matrix, frame, state.subpixel_bits)),
        VertexSource::Memory(memory) => memory.get_mut(..mesh.vertex_count()).map(|screen| {
            screen_vertices(|i| shader.position(mesh, i), 0, &volume, &raster, screen);
            &*screen
        }),
        VertexSource::Cache => None,
    };
    let mut cache = if screen.is_some() { VertexCache::for_varyings() } else { VertexCache::new() };
    let mut stats = DrawStats::default();

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
        let (a, b, c) = cache.triangle(screen, shader, mesh, indices, &volume, &raster);
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
            let setup = E::setup(&raster, [a.screen, b.screen, c.screen]);
            outcome.record(&setup);
            if let Setup::Ready(coverage) = &setup
                && coverage.covers_a_centre()
            {
                let vars = cache.triangle_varyings(shader, mesh, indices);
                if !vars.iter().all(Varyings::is_finite) {
                    stats.invalid += 1;
                    continue;
                }
                let face = shader.face(mesh, indices);
                stats.fragments += fill::<S, E>(&mut pass, &loops, coverage, vars.each_ref(), face, inline);
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
                ClipVertex { pos: shader.position(mesh, indices[0]), var: vars[0] },
                ClipVertex { pos: shader.position(mesh, indices[1]), var: vars[1] },
                ClipVertex { pos: shader.position(mesh, indices[2]), var: vars[2] },
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
                let setup = E::setup(&raster, [p, q, r]);
                outcome.record(&setup);
                if let Setup::Ready(coverage) = &setup {
                    let face = *face.get_or_insert_with(|| shader.face(mesh, indices));
                    let pieces = [&verts[0].var, &verts[i].var, &verts[i + 1].var];
                    // Rare: the shared loops, not a second copy of the draw's own.
                    stats.fragments += fill::<S, E>(&mut pass, &loops, coverage, pieces, face, false);
                }
            }
        }
        outcome.count(&mut stats);
    }
    // What is left in the batch.
    if let Some(fragments) = &mut pass.fragments
        && fragments.len() > 0
    {
        let target = &mut pass.target;
        let samples = target.samples();
        let mut depth = target.depth.view();
        let depth = (shading == Shading::CutOut).then_some(&mut depth);
        let writes = Writes { color: &mut target.color, depth, samples };
        stats.fragments += pass.stage.flush(fragments, writes);
    }
    stats
}

/// Runs the draw's pixel loop over one triangle (or clipped piece) that reaches it, with its varyings given in input
/// order and its face, first putting them into the batch's next slot: the fragments it counts.
///
/// With `inline`, the draw's usual pixel loop is compiled here, into the draw loop, with the
/// shader's fragment stage called directly; otherwise one of the loops every shader shares ([`PixelLoops`]), which
/// reads the coverage from memory: it is copied there for the triangles that reach it, so that the set-up of the
/// many that do not keeps it in registers (callgrind, sphere1m: 12 instructions a triangle).
#[inline(always)]
fn fill<S: Shader, E: EdgeSetup>(
    pass: &mut Pass<'_, ShaderStage<'_, S>>,
    loops: &PixelLoops,
    coverage: &Coverage<E::Edges>,
    varyings: [&S::Varyings; 3],
    face: S::Face,
    inline: bool,
) -> u64 {
    if let Some(fragments) = &pass.fragments {
        pass.stage.start_triangle(fragments, coverage.oriented(varyings), face);
    }
    if E::INLINE
        && inline
        && let Some(fragments) = E::fill_inline(coverage, pass, S::FRAGMENT_STAGE)
    {
        return fragments;
    }
    let stored = *coverage;
    E::fill(loops, &stored, pass)
}
