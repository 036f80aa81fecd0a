//! The rendering pipeline: vertex stage, clipping, rasterization, depth test, fragment stage.
//!
//! Data flow of a [`draw`]:
//!
//! 1. **Vertex stage, positions** ([`Shader::position`]): each triangle's three vertices to clip space and, when
//!    they need no clipping, snapped to the screen ([`ScreenVertex`]): once per vertex into memory the target
//!    lends ([`crate::target::Target::with_vertex_memory`]), or about once per vertex shared by neighbouring
//!    triangles through a small cache, or read from the frame's screen vertices computed beforehand
//!    ([`crate::target::FrameGeometry`]), whose bins also limit the triangles a band's draw takes ([`BandBins`]).
//!    Triangles with an index out of range or a non-finite position are skipped.
//! 2. **Clip** ([`clip`](self#clipping)): rejected when all vertices are outside one plane of the view volume or
//!    the target's rows; cut when crossing the near or far plane or the guard band.
//! 3. **Raster** ([`raster`](self#rasterization)): divide by `w`, snap to fixed point, cull by winding, walk the
//!    covered pixel centres with exact integer edge functions and the top-left rule.
//! 4. **Vertex stage, varyings** ([`Shader::varyings`]): only for the vertices of triangles that reach the pixel
//!    loop (or must be clipped); a triangle with non-finite varyings is skipped.
//! 5. **Fragment**: depth test ([`DepthTest`]), then up to [`BATCH_SIZE`] fragments at a time, across triangles,
//!    into a [`FragmentBatch`]: interpolation ([`Interpolation`]) with the varyings' screen-space [`Slopes`] when
//!    the shader asks ([`Shader::slopes`]), [`Shader::shade_batch`] (by default [`Shader::fragment`] for each),
//!    write; or, for a depth-only shader (no [`Shader::FRAGMENT_STAGE`]), the depth test alone,
//!    [`DEPTH_LANES`](crate::target::DEPTH_LANES) pixels of a row at a time.
//!
//! # What is compiled
//! The pixel loops (coverage, depth test, the batch) do not depend on the shader or on the target's buffer types:
//! they draw into the target's views ([`crate::target::ColorView`], [`crate::target::DepthView`]) and hand each full
//! batch to the draw's fragment stage through one `dyn` call. They are compiled once per edge arithmetic,
//! interpolation, samples per pixel and fragment stage (none, shading, shading what it keeps), and a draw picks
//! its loop once. Per shader type there is the vertex stage, the triangle loop and the batch's interpolation and
//! shading; per buffer type, one conversion into the views.
//!
//! # Clipping
//! Near plane `z >= 0`, far plane `z <= w`, and a guard band of ±[`GUARD_BAND`] pixels in x and y; see the
//! `clip` module source for the details.
//!
//! # Rasterization
//! Vertices snap to `2^-subpixel_bits` of a pixel; coverage is exact in `i64`; pixel centres at
//! `(x + 0.5, y + 0.5)`; top-left fill rule (Direct3D 11.3 functional specification, 3.4.2.1). Depth is linear in
//! screen space; varyings are perspective-correct or affine. On a multisampled target
//! ([`crate::target::Target::multisampled`]) coverage and depth are tested at four samples per pixel, exactly and
//! under the same rule, and each pixel is shaded once.

mod batch;
mod bins;
mod clip;
pub(crate) mod columns;
pub(crate) mod draw;
mod edges;
mod fragment_stage;
mod fragments;
mod interpolator;
mod line;
mod raster;
mod screen_vertex;
mod shader;
mod slopes;
mod state;
mod stats;
mod varyings;
mod vertex_cache;

pub use batch::{FragmentBatch, OneFragment};
pub use bins::{BIN_BLOCK, BandBins, Bands, BinnedTriangle, MAX_BINNED_BANDS, MAX_PART_TRIANGLES};
pub(crate) use clip::ClipVolume;
pub use clip::GUARD_BAND;
pub use columns::{BATCH_SIZE, Column, lanes};
pub use draw::{DrawError, draw};
pub use line::{LineStyle, draw_wireframe};
pub use screen_vertex::ScreenVertex;
pub(crate) use screen_vertex::frame_screen_vertices;
pub(crate) use shader::PositionShader;
pub use shader::{Fragment, Shader};
pub use slopes::Slopes;
pub use state::{Cull, DepthTest, DrawState, EdgeArithmetic, FixedFunction, Interpolation, MAX_SUBPIXEL_BITS, Winding};
pub use stats::DrawStats;
pub use varyings::Varyings;
