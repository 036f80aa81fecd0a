//! Running a plan: the shadow passes into maps the renderer keeps, the forward pass into the caller's frame in
//! bands drawn side by side on threads (into samples the renderer keeps, resolved into the frame, when the plan
//! multisamples), then the ambient occlusion step, also in bands.

use std::ops::Range;
use std::thread;
use std::time::{Duration, Instant};

use rastty_core::math::Vec3;
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{DrawStats, LineStyle, draw_wireframe};
use rastty_core::shading::{Light, Lighting, Object, ShadingError, Variant, draw_mesh};
use rastty_core::shadow::{
    ShadowBias, ShadowError, ShadowMap, ShadowView, WindowRanges, clear_shadow_depth, draw_shadow_caster_band,
    window_ranges_band,
};
use rastty_core::target::{Rgb888, Samples, Target, resolve_rgb888};

use super::bins::TriangleBins;
use super::material::part_material;
use super::plan::{PlannedDraw, ShadowPass, tangents_for};
use super::workers::Workers;
use super::{PreparedScene, ScenePlan, SceneRenderError};
use crate::scene_file::SceneObject;

/// Wireframe lines (`--wireframe`, the viewer's `x` key): a pale cyan drawn just in front of the surface.
pub const WIREFRAME: LineStyle = LineStyle { color: Vec3::new(0.55, 0.9, 1.0), depth_bias: 2e-4 };

/// What one shadow pass did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowPassReport {
    /// The light's place in the file, from 1.
    pub light: usize,
    /// The map of an earlier frame was still right (same scene, light and view) and was used again: nothing was
    /// drawn.
    pub reused: bool,
    /// What drawing the casters did (zero when reused), summed over the map's bands.
    pub stats: DrawStats,
}

/// What one frame did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FrameReport {
    /// The shadow passes, in the plan's order.
    pub shadow_passes: Vec<ShadowPassReport>,
    /// The forward pass's counts, wireframe lines' fragments included, summed over the bands: a triangle counts
    /// once in each band whose rows it may reach (with a margin), as rasterized with no fragment in those it then
    /// misses (the bands share the frame's screen vertices, whose outcodes are the whole frame's).
    pub forward: DrawStats,
    /// How many bands of rows the frame was split into (see [`SceneRenderer`]).
    pub bands: usize,
    /// The variant each draw ran, in the plan's order (the plan's own, resolved again with the real maps).
    pub variants: Vec<Variant>,
    /// Time in the shadow passes.
    pub shadow_time: Duration,
    /// Time in the forward pass, clearing the target included.
    pub forward_time: Duration,
    /// Time in the ambient occlusion step.
    pub occlusion_time: Duration,
}

impl FrameReport {
    /// The whole frame's time.
    pub fn total_time(&self) -> Duration {
        self.shadow_time + self.forward_time + self.occlusion_time
    }
}

/// What a kept shadow map was drawn for.
#[derive(Clone, Copy, Debug, PartialEq)]
struct ShadowKey {
    scene: u64,
    light: usize,
    view: ShadowView,
}

/// A shadow map's depth buffer and its filter windows' depth ranges, kept from frame to frame.
///
/// The ranges are worked out in the map's second frame, not its first: they read every texel's window (a million
/// for a 1024x1024 map) to spare the lookups' reads, and one 800x800 frame looks up a quarter as many. A map used
/// once (`rastty render`, a moving light) never pays for them; a kept one (the viewer orbiting) does once.
#[derive(Debug, Default)]
struct ShadowSlot {
    key: Option<ShadowKey>,
    /// The ranges in `near` and `far` are those of the map in `depth`.
    ranges_ready: bool,
    depth: Vec<f32>,
    /// The nearest depth of each texel's filter window (empty for a map read without a filter).
    near: Vec<f32>,
    /// The farthest depth of each texel's filter window.
    far: Vec<f32>,
}

/// At most this many bands of frame rows per thread: threads take the next band as they finish one, so a frame
/// whose content sits in a few rows (a floor at the bottom, sky above) still keeps every thread busy, and a band's
/// colour and depth rows (8 bytes a pixel) stay in the core's cache from its clear to its last fragment.
pub const BANDS_PER_THREAD: usize = 8;
/// About this many pixels per band of a frame at least: each band repeats the set-up of every draw and the vertex
/// work of the triangles it shares with its neighbours, which a small frame would otherwise spend more time on than
/// on its pixels.
pub const BAND_PIXELS: usize = 65_536;

/// Draws [`ScenePlan`]s, keeping the shadow maps' buffers between frames.
///
/// A shadow map depends on the scene, the light and its view (the bounds and the map size), never on the camera,
/// so a map drawn for an earlier frame of the same prepared scene is used again as it is: orbiting in the viewer
/// redraws no shadow map. A switched-off effect is absent from the plan, so nothing of it runs; a kept map costs
/// only its memory until shadows are switched back on.
///
/// The shadow passes split their map into one band of rows per thread; the forward pass and the ambient
/// occlusion step split the frame into one band per [`BAND_PIXELS`] pixels, at least one and at most
/// [`BANDS_PER_THREAD`] per thread, which the threads take in turn (the forward pass's with the most triangles
/// first, so that the threads finish together). Each band runs the whole draw list into its own
/// rows, each draw with the triangles sorted into the band (conservatively, by their screen rows; the core clips
/// every triangle to the band), so maps and pixels are the same for any number of threads. The screen vertices of
/// each draw are computed once a frame, on the threads, and shared by the bands: only the varyings of vertices
/// of triangles that reach several bands are computed again.
///
/// A plan with several [`ScenePlan::samples`] per pixel draws its forward pass into colour and depth samples the
/// renderer keeps, band by band as above; each band then averages its samples into its pixels
/// ([`resolve_rgb888`], in the plan's shading space) and stores each pixel's nearest sample depth, which the
/// ambient occlusion step reads as it reads a single-sampled frame's depth.
///
/// The threads are started with the renderer and kept (`workers.rs`), and so are the screen vertices and the lists
/// the triangles are sorted into (`bins.rs`): a frame starts no thread and, once those have grown to the meshes,
/// allocates nothing in proportion to them.
#[derive(Debug)]
pub struct SceneRenderer {
    slots: Vec<ShadowSlot>,
    workers: Workers,
    /// The forward pass's triangles sorted into bands, one entry per draw of the last plan.
    bins: Vec<TriangleBins>,
    /// A multisampled forward pass's samples (empty until a plan asks for them).
    samples: SampleBuffers,
}

/// The colour and depth samples of a multisampled forward pass, [`Samples::count`] values a pixel, each pixel's
/// side by side, kept from frame to frame.
#[derive(Debug, Default)]
struct SampleBuffers {
    colors: Vec<u32>,
    depths: Vec<f32>,
}

/// One band's colour and depth samples, when the plan multisamples.
type BandSamples<'a> = Option<(&'a mut [u32], &'a mut [f32])>;

impl SampleBuffers {
    /// The buffers grown to `rows` of a frame `width` pixels wide and split as [`split_rows`] splits those rows
    /// into `band_count` bands, top first, then `None` for every further band; `None` for every band when
    /// `samples` is one.
    fn bands(
        &mut self,
        samples: Samples,
        width: u32,
        rows: Range<u32>,
        band_count: usize,
    ) -> impl Iterator<Item = BandSamples<'_>> {
        let none = std::iter::repeat_with(|| None);
        if samples == Samples::One {
            return Vec::new().into_iter().chain(none);
        }
        let row = width * samples.count() as u32;
        let values = row as usize * rows.len();
        if self.colors.len() != values {
            // Every value is cleared by its band before it is drawn, on the band's thread.
            (self.colors, self.depths) = (vec![0; values], vec![0.0; values]);
        }
        let colors = split_rows(&mut self.colors, row, rows.clone(), band_count);
        let depths = split_rows(&mut self.depths, row, rows, band_count);
        let bands: Vec<BandSamples<'_>> = colors.into_iter().zip(depths).map(|((_, c), (_, d))| Some((c, d))).collect();
        bands.into_iter().chain(none)
    }
}

impl Default for SceneRenderer {
    fn default() -> Self {
        Self::new()
    }
}

/// The rows and buffers of one band of the frame.
struct Band<'a> {
    /// The band's place, top first.
    index: usize,
    rows: Range<u32>,
    pixels: &'a mut [u32],
    depth: &'a mut [f32],
    samples: BandSamples<'a>,
}

/// What the forward pass did in one band.
struct BandResult {
    stats: DrawStats,
    variants: Vec<Variant>,
}

impl SceneRenderer {
    /// A renderer with no shadow map yet, drawing on as many threads as this machine runs at once.
    pub fn new() -> Self {
        Self::with_threads(thread::available_parallelism().map_or(1, usize::from))
    }

    /// A renderer with no shadow map yet, drawing in `threads` bands at once (at least 1; a frame has at most one
    /// band per row). It starts its threads now and keeps them; if the system refuses to start them, it draws the
    /// same frames on the calling thread alone.
    pub fn with_threads(threads: usize) -> Self {
        let workers = Workers::new(threads);
        Self { slots: Vec::new(), workers, bins: Vec::new(), samples: SampleBuffers::default() }
    }

    /// The number of threads frames are drawn on.
    pub fn threads(&self) -> usize {
        self.workers.threads()
    }

    /// The number of bands of rows a frame is split into (fewer for a frame with fewer rows).
    fn bands(&self, pixels: usize) -> usize {
        let threads = self.threads();
        (pixels / BAND_PIXELS).clamp(threads, threads * BANDS_PER_THREAD)
    }

    /// Runs `plan` (made for `scene`) into `target`, a frame of the plan's size or a band of its rows: the shadow
    /// passes (each skipped when its kept map is still right), then, in bands on [`Self::threads`] threads, clears
    /// the target's rows to the background and draws every part, then the ambient occlusion step when planned.
    /// The frame drawn band by band has the pixels of the whole frame.
    ///
    /// # Errors
    /// [`SceneRenderError::Target`] when the target is not the plan's size, when it is a band and the plan has
    /// ambient occlusion (which reads the whole frame's depth), or when the plan names objects the scene does not
    /// have; the core's refusals as [`SceneRenderError::Shadow`], [`SceneRenderError::Texture`],
    /// [`SceneRenderError::Draw`] and [`SceneRenderError::Occlusion`].
    pub fn render(
        &mut self,
        scene: &PreparedScene,
        plan: &ScenePlan,
        target: &mut Target<Rgb888<'_>, &mut [f32]>,
    ) -> Result<FrameReport, SceneRenderError> {
        let (width, height, rows) = (target.width(), target.height(), target.rows());
        if (width, height) != plan.size {
            return Err(SceneRenderError::Target(format!(
                "the plan is for {}x{} pixels, the target is {width}x{height}",
                plan.size.0, plan.size.1
            )));
        }
        if plan.ambient_occlusion.is_some() && rows != (0..height) {
            return Err(SceneRenderError::Target(format!(
                "ambient occlusion reads the whole frame's depth: draw the plan into the whole frame, not rows {}..{}",
                rows.start, rows.end
            )));
        }
        let band_count = self.bands(width as usize * rows.len());
        let mut report = FrameReport { bands: band_count.clamp(1, rows.len()), ..FrameReport::default() };
        let start = Instant::now();
        self.shadow_passes(scene, plan, &mut report)?;
        report.shadow_time = start.elapsed();

        let start = Instant::now();
        let sources = Self::light_sources(&self.slots, plan)?;
        let lights = Lighting { ambient: plan.ambient, lights: &sources, space: plan.space };
        let (color, depth) = target.buffers_mut();
        let (pixels, depth) = (&mut *color.0, &mut **depth);
        let samples = self.samples.bands(plan.samples(), width, rows.clone(), band_count);
        let bands = split_rows(pixels, width, rows.clone(), band_count);
        let bands = bands.into_iter().zip(split_rows(depth, width, rows.clone(), band_count)).zip(samples).enumerate();
        let mut bands: Vec<_> = bands
            .map(|(index, (((rows, pixels), (_, depth)), samples))| Band { index, rows, pixels, depth, samples })
            .collect();
        let rows: Vec<_> = bands.iter().map(|band| band.rows.clone()).collect();
        if self.bins.len() < plan.draws.len() {
            self.bins.resize_with(plan.draws.len(), TriangleBins::default);
        }
        let bins = &mut self.bins[..plan.draws.len()];
        for (draw, bins) in plan.draws.iter().zip(bins.iter_mut()) {
            let (_, mesh) = planned_mesh(scene, draw)?;
            bins.sort(&mesh, &draw.transforms.clip_from_object, (width, height), &rows, &self.workers).map_err(
                |error| SceneRenderError::Draw { draw: draw.label.clone(), error: ShadingError::Draw(error) },
            )?;
        }
        let bins = &*bins;
        // Threads take the bands with the most triangles first, so that the last ones taken are short and the
        // threads finish together.
        bands.sort_by_key(|band| std::cmp::Reverse(bins.iter().map(|b| b.band_triangles(band.index)).sum::<usize>()));
        let results = self.workers.run(bands, |band| forward_band(scene, plan, bins, &lights, band, width, height));
        for result in results {
            let result = result?;
            report.forward += result.stats;
            // Every band resolves the same variants; keep the first band's.
            if report.variants.is_empty() {
                report.variants = result.variants;
            }
        }
        report.forward_time = start.elapsed();

        if let Some(occlusion) = &plan.ambient_occlusion {
            let start = Instant::now();
            let projection = plan.camera.projection;
            let whole_depth: &[f32] = depth;
            let margin = occlusion.margin_rows(&projection, width, height);
            let bands = split_rows(pixels, width, 0..height, band_count);
            let results = self.workers.run(bands, |(rows, pixels)| {
                // The band's rows of depth and `margin` more on each side: exactly the whole frame's result.
                let depth_rows = rows.start.saturating_sub(margin)..(rows.end + margin).min(height);
                let span = depth_rows.start as usize * width as usize..depth_rows.end as usize * width as usize;
                occlusion.apply(&projection, &whole_depth[span], depth_rows, pixels, rows, width, height)
            });
            for result in results {
                result.map_err(SceneRenderError::Occlusion)?;
            }
            report.occlusion_time = start.elapsed();
        }
        Ok(report)
    }

    /// The planned lights as the core takes them, with the kept shadow maps.
    fn light_sources<'a>(slots: &'a [ShadowSlot], plan: &ScenePlan) -> Result<Vec<Light<'a>>, SceneRenderError> {
        let mut sources = Vec::with_capacity(plan.lights.len());
        for light in &plan.lights {
            let shadow = match light.shadow_pass {
                Some(p) => {
                    let pass = &plan.shadow_passes[p];
                    let slot = &slots[p];
                    let map = ShadowMap::new(pass.view, &slot.depth, ShadowBias::DEFAULT, pass.pcf_radius);
                    let map = map.and_then(|map| {
                        if !slot.ranges_ready {
                            return Ok(map);
                        }
                        map.with_windows(WindowRanges::new(&slot.near, &slot.far, pass.view.size(), pass.pcf_radius)?)
                    });
                    Some(map.map_err(|error| SceneRenderError::Shadow { light: plan.light_name(light), error })?)
                }
                None => None,
            };
            sources.push(Light { kind: light.kind, color: light.color, shadow });
        }
        Ok(sources)
    }
    /// Draws the shadow maps the plan needs that are not kept already.
    fn shadow_passes(
        &mut self,
        scene: &PreparedScene,
        plan: &ScenePlan,
        report: &mut FrameReport,
    ) -> Result<(), SceneRenderError> {
        if self.slots.len() < plan.shadow_passes.len() {
            self.slots.resize_with(plan.shadow_passes.len(), ShadowSlot::default);
        }
        let workers = &self.workers;
        for (pass, slot) in plan.shadow_passes.iter().zip(&mut self.slots) {
            let light = &plan.lights[pass.light];
            let key = ShadowKey { scene: scene.id(), light: light.number, view: pass.view };
            let shadow_error = |error| SceneRenderError::Shadow { light: plan.light_name(light), error };
            if slot.key == Some(key) {
                if pass.pcf_radius > 0 && !slot.ranges_ready {
                    slot.window_ranges(pass, workers).map_err(shadow_error)?;
                    slot.ranges_ready = true;
                }
                report.shadow_passes.push(ShadowPassReport {
                    light: light.number,
                    reused: true,
                    stats: DrawStats::default(),
                });
                continue;
            }
            (slot.key, slot.ranges_ready) = (None, false);
            let texels = pass.view.size() as usize * pass.view.rows() as usize;
            if slot.depth.len() != texels {
                // Zeroed memory comes from the allocator untouched; the bands' clears below fill it (page faults
                // and all) on their own threads, once.
                slot.depth = vec![0.0; texels];
            }
            // One band per thread: casters are few fragments for their vertex work, which every band repeats. A
            // cube map's six faces are one tall map of rows to the bands.
            let bands = split_rows(&mut slot.depth, pass.view.size(), 0..pass.view.rows(), workers.threads());
            let results = workers.run(bands, |(rows, depth)| {
                clear_shadow_depth(depth);
                let mut stats = DrawStats::default();
                for object in &scene.data().objects {
                    let Some(mesh) = object.model.mesh() else { continue };
                    stats += draw_shadow_caster_band(&pass.view, depth, rows.clone(), &mesh, &object.transform)?;
                }
                Ok(stats)
            });
            let mut stats = DrawStats::default();
            for result in results {
                stats += result.map_err(shadow_error)?;
            }
            slot.key = Some(key);
            report.shadow_passes.push(ShadowPassReport { light: light.number, reused: false, stats });
        }
        Ok(())
    }
}

impl ShadowSlot {
    /// Works out the depth ranges of the filter windows of the map in `depth`, in one band of rows per thread
    /// (every band reads the whole map, so the depth pass must be done).
    fn window_ranges(&mut self, pass: &ShadowPass, workers: &Workers) -> Result<(), ShadowError> {
        let threads = workers.threads();
        let texels = self.depth.len();
        for buffer in [&mut self.near, &mut self.far] {
            if buffer.len() != texels {
                // Every value is written below, on the bands' threads.
                *buffer = vec![0.0; texels];
            }
        }
        let depth = &self.depth;
        let near = split_rows(&mut self.near, pass.view.size(), 0..pass.view.rows(), threads);
        let far = split_rows(&mut self.far, pass.view.size(), 0..pass.view.rows(), threads);
        let bands: Vec<_> = near.into_iter().zip(far).collect();
        let results = workers.run(bands, |((rows, near), (_, far))| {
            window_ranges_band(depth, pass.view.size(), pass.pcf_radius, rows, near, far)
        });
        results.into_iter().collect()
    }
}

/// Splits `buffer`, the values of the frame rows `rows`, `width` a row, into at most `count` bands of nearly equal
/// rows (at least one row each), top first, each with its rows.
fn split_rows<T>(mut buffer: &mut [T], width: u32, rows: Range<u32>, count: usize) -> Vec<(Range<u32>, &mut [T])> {
    let (first, height) = (rows.start, rows.end - rows.start);
    let count = count.clamp(1, height.max(1) as usize) as u32;
    let mut bands = Vec::with_capacity(count as usize);
    for i in 0..count {
        let rows = first + height * i / count..first + height * (i + 1) / count;
        let (band, rest) = std::mem::take(&mut buffer).split_at_mut(rows.len() * width as usize);
        buffer = rest;
        bands.push((rows, band));
    }
    bands
}

/// The mesh of a planned draw.
fn planned_mesh<'a>(
    scene: &'a PreparedScene,
    draw: &PlannedDraw,
) -> Result<(&'a SceneObject, Mesh<'a>), SceneRenderError> {
    let mismatch = || SceneRenderError::Target(format!("the plan's {} is not in the scene", draw.label));
    let object = scene.data().objects.get(draw.object).ok_or_else(mismatch)?;
    let mesh = object.model.part_mesh(draw.part).ok_or_else(mismatch)?;
    Ok((object, mesh))
}

/// The forward pass over one band: clears it to the background and draws every planned part into it, each with
/// the triangles that `bins` sorted into the band; into its samples when the plan multisamples, then averaged into
/// its pixels, each pixel's depth its nearest sample's.
fn forward_band(
    scene: &PreparedScene,
    plan: &ScenePlan,
    bins: &[TriangleBins],
    lights: &Lighting<'_>,
    band: Band<'_>,
    width: u32,
    height: u32,
) -> Result<BandResult, SceneRenderError> {
    let Band { index, rows, pixels, depth, samples } = band;
    let Some((sample_colors, sample_depths)) = samples else {
        return draw_band(scene, plan, bins, lights, (index, rows, Samples::One), (pixels, depth), (width, height));
    };
    let place = (index, rows, plan.samples());
    let result = draw_band(scene, plan, bins, lights, place, (sample_colors, sample_depths), (width, height))?;
    resolve_rgb888(sample_colors, plan.samples(), plan.space, pixels)?;
    for (pixel, samples) in depth.iter_mut().zip(sample_depths.chunks_exact(plan.samples().count())) {
        *pixel = samples.iter().fold(1.0, |nearest, &d| d.min(nearest));
    }
    Ok(result)
}

/// [`forward_band`]'s draws into band `index` (frame rows `rows`) with `samples` a pixel, into `colors` and
/// `depths`.
fn draw_band(
    scene: &PreparedScene,
    plan: &ScenePlan,
    bins: &[TriangleBins],
    lights: &Lighting<'_>,
    (index, rows, samples): (usize, Range<u32>, Samples),
    (colors, depths): (&mut [u32], &mut [f32]),
    (width, height): (u32, u32),
) -> Result<BandResult, SceneRenderError> {
    Target::multisampled(Rgb888(&mut *colors), &mut *depths, width, height, rows.clone(), samples)?
        .clear(plan.background);
    let mut result = BandResult { stats: DrawStats::default(), variants: Vec::with_capacity(plan.draws.len()) };
    for (draw, bins) in plan.draws.iter().zip(bins) {
        let (object, mesh) = planned_mesh(scene, draw)?;
        let maps = scene.part_maps(draw.object, draw.part);
        let material = part_material(object, maps, draw.part, plan.space, &plan.options)
            .map_err(|error| SceneRenderError::Texture { draw: draw.label.clone(), error })?;
        let tangents = tangents_for(scene, draw.object, &material);
        // The frame's screen vertices of the mesh, computed once for every band.
        let clip = &draw.transforms.clip_from_object;
        let shared = bins.shared(&mesh, clip, (width, height));
        let target = Target::multisampled(Rgb888(&mut *colors), &mut *depths, width, height, rows.clone(), samples)?;
        let mut target = target.with_shared_vertices(shared);
        let mut variant = draw.variant;
        // The band's triangles come in pieces of the mesh (at least one), in its order: drawn one after the other,
        // the pieces give the pixels of one draw of them all.
        for list in bins.band(index) {
            let triangles = mesh.with_indices(Indices::U32(list));
            let triangles = triangles.map_err(|error| SceneRenderError::Target(format!("{}: {error}", draw.label)))?;
            let surface = Object {
                mesh: triangles,
                tangents,
                transforms: draw.transforms,
                shading: draw.variant.shading,
                material,
            };
            let (drawn, stats) = draw_mesh(&mut target, &surface, lights, &draw.state)
                .map_err(|error| SceneRenderError::Draw { draw: draw.label.clone(), error })?;
            result.stats += stats;
            if plan.wireframe {
                // The lines' pixels count as fragments; their triangles are the ones counted above.
                let lines = draw_wireframe(&mut target, &triangles, clip, &WIREFRAME, &drawn.state);
                result.stats.fragments += lines.fragments;
            }
            variant = drawn;
        }
        result.variants.push(variant);
    }
    Ok(result)
}
