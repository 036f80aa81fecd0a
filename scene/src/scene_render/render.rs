//! Running a plan: the shadow passes into maps the renderer keeps, the forward pass into the caller's frame in
//! bands drawn side by side on threads (into samples the renderer keeps, resolved into the frame, when the plan
//! multisamples), then the ambient occlusion step, also in bands.

use std::ops::Range;
use std::thread;
use std::time::{Duration, Instant};

use rastty_core::environment::Environment;
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::Mesh;
use rastty_core::pipeline::{Bands, DrawStats, LineStyle, MAX_BINNED_BANDS, draw_wireframe};
use rastty_core::shading::{Light, Lighting, Object, ShadingError, Variant, draw_mesh};
use rastty_core::shadow::{
    ShadowBias, ShadowError, ShadowMap, ShadowView, WindowRanges, clear_shadow_depth, draw_shadow_caster_band,
    window_ranges_band,
};
use rastty_core::target::{Rgb888, Samples, Target, resolve_rgb888};

use super::frame_geometry::{DrawGeometry, GeometryMemory};
use super::material::part_material;
use super::plan::{PlannedDraw, ShadowPass, tangents_for};
use super::workers::Workers;
use super::{PlannedCamera, PreparedScene, ScenePlan, SceneRenderError};
use crate::scene_file::SceneObject;

/// Wireframe lines (`--wireframe`, the viewer's `x` key): a pale cyan drawn just in front of the surface.
pub(crate) const WIREFRAME: LineStyle = LineStyle { color: Vec3::new(0.55, 0.9, 1.0), depth_bias: 2e-4 };

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
    /// The forward pass's counts: each triangle once, as binning the frame's triangles by band found it, and the
    /// fragments of every band, wireframe lines' included.
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
/// occlusion step cut the frame into the core's [`Bands`]: about one per [`BAND_PIXELS`] pixels, at least one and
/// at most [`BANDS_PER_THREAD`] per thread, which the threads take in turn (the forward pass's with the most
/// triangles first, so that the threads finish together). Each band runs the whole draw list into its own rows, so
/// maps and pixels are the same for any number of threads. Each draw's screen vertices are computed, and its
/// triangles binned by band, once a frame on the threads (`frame_geometry.rs`, the core's binning): a band's draw
/// runs no position stage and meets only the triangles that can reach its rows; only the varyings of vertices of
/// triangles that reach several bands are computed again.
///
/// A plan with several [`ScenePlan::samples`] per pixel draws its forward pass into colour and depth samples the
/// renderer keeps, band by band as above; each band then averages its samples into its pixels
/// ([`resolve_rgb888`], in the plan's shading space) and stores each pixel's nearest sample depth, which the
/// ambient occlusion step reads as it reads a single-sampled frame's depth.
///
/// The threads are started with the renderer and kept (`workers.rs`), and so is the memory of each draw's screen
/// vertices and bins (`frame_geometry.rs`): a frame starts no thread and, once those have grown to the meshes,
/// allocates nothing in proportion to them.
#[derive(Debug)]
pub struct SceneRenderer {
    slots: Vec<ShadowSlot>,
    workers: Workers,
    /// The memory of the forward pass's geometry, one entry per draw of the last plan.
    geometry: Vec<GeometryMemory>,
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
    /// into bands of `band_rows`, top first, then `None` for every further band; `None` for every band when
    /// `samples` is one.
    fn bands(
        &mut self,
        samples: Samples,
        width: u32,
        rows: Range<u32>,
        band_rows: u32,
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
        let colors = split_rows(&mut self.colors, row, rows.clone(), band_rows);
        let depths = split_rows(&mut self.depths, row, rows, band_rows);
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
    /// The band's place in the frame's [`Bands`], top first.
    index: usize,
    rows: Range<u32>,
    pixels: &'a mut [u32],
    depth: &'a mut [f32],
    samples: BandSamples<'a>,
}

/// What the forward pass did in one band.
struct BandResult {
    /// The fragments of its draws and lines.
    fragments: u64,
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
        Self { slots: Vec::new(), workers, geometry: Vec::new(), samples: SampleBuffers::default() }
    }

    /// The number of threads frames are drawn on.
    pub fn threads(&self) -> usize {
        self.workers.threads()
    }

    /// How a `width x height` frame drawn with `samples` a pixel is cut into bands of rows: about one per
    /// [`BAND_PIXELS`] pixels, at least one per thread and at most [`BANDS_PER_THREAD`] per thread (and
    /// [`MAX_BINNED_BANDS`]), of equal rows but the last.
    fn bands(&self, width: u32, height: u32, samples: Samples) -> Result<Bands, SceneRenderError> {
        let threads = self.threads();
        let count = (width as usize * height as usize / BAND_PIXELS).clamp(threads, threads * BANDS_PER_THREAD);
        let rows = height.div_ceil(count as u32).max(height.div_ceil(MAX_BINNED_BANDS));
        Bands::new(width, height, rows, samples).map_err(|e| SceneRenderError::Target(e.to_string()))
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
        let grid = self.bands(width, height, plan.samples())?;
        let band_rows = grid.rows(0).len() as u32;
        let mut report = FrameReport::default();
        let start = Instant::now();
        self.shadow_passes(scene, plan, &mut report)?;
        report.shadow_time = start.elapsed();

        let start = Instant::now();
        let sources = Self::light_sources(&self.slots, plan)?;
        let environment = scene_environment(scene, plan);
        let lights =
            Lighting { ambient: plan.ambient, lights: &sources, environment: environment.as_ref(), space: plan.space };
        let (color, depth) = target.buffers_mut();
        let (pixels, depth) = (&mut *color.0, &mut **depth);
        let samples = self.samples.bands(plan.samples(), width, rows.clone(), band_rows);
        let bands = split_rows(pixels, width, rows.clone(), band_rows);
        let bands = bands.into_iter().zip(split_rows(depth, width, rows.clone(), band_rows)).zip(samples);
        let mut bands: Vec<_> = bands
            .map(|(((rows, pixels), (_, depth)), samples)| {
                let index = (rows.start / band_rows) as usize;
                Band { index, rows, pixels, depth, samples }
            })
            .collect();
        report.bands = bands.len();
        if self.geometry.len() < plan.draws.len() {
            self.geometry.resize_with(plan.draws.len(), GeometryMemory::default);
        }
        let mut geometry = Vec::with_capacity(plan.draws.len());
        for (draw, memory) in plan.draws.iter().zip(&mut self.geometry) {
            let (_, mesh) = planned_mesh(scene, draw)?;
            let computed =
                memory.compute(&mesh, &draw.transforms.clip_from_object, &draw.variant.state, grid, &self.workers);
            let computed = computed.map_err(|error| SceneRenderError::Draw {
                draw: draw.label.clone(),
                error: ShadingError::Draw(error),
            })?;
            report.forward += computed.stats();
            geometry.push(computed);
        }
        // Threads take the bands with the most triangles first, so that the last ones taken are short and the
        // threads finish together.
        let mut counts = vec![0; grid.count() as usize];
        geometry.iter().for_each(|draw| draw.count_by_band(&mut counts));
        bands.sort_by_key(|band| std::cmp::Reverse(counts[band.index]));
        let geometry = &geometry;
        let results = self.workers.run(bands, |band| forward_band(scene, plan, geometry, &lights, band, width, height));
        for result in results {
            let result = result?;
            report.forward.fragments += result.fragments;
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
            let bands = split_rows(pixels, width, 0..height, band_rows);
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
            let band_rows = pass.view.rows().div_ceil(workers.threads() as u32);
            let bands = split_rows(&mut slot.depth, pass.view.size(), 0..pass.view.rows(), band_rows);
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
        let band_rows = pass.view.rows().div_ceil(workers.threads() as u32);
        let texels = self.depth.len();
        for buffer in [&mut self.near, &mut self.far] {
            if buffer.len() != texels {
                // Every value is written below, on the bands' threads.
                *buffer = vec![0.0; texels];
            }
        }
        let depth = &self.depth;
        let near = split_rows(&mut self.near, pass.view.size(), 0..pass.view.rows(), band_rows);
        let far = split_rows(&mut self.far, pass.view.size(), 0..pass.view.rows(), band_rows);
        let bands: Vec<_> = near.into_iter().zip(far).collect();
        let results = workers.run(bands, |((rows, near), (_, far))| {
            window_ranges_band(depth, pass.view.size(), pass.pcf_radius, rows, near, far)
        });
        results.into_iter().collect()
    }
}

/// Splits `buffer`, the values of the frame rows `rows`, `width` a row, into bands at every multiple of `band_rows`
/// (at least 1) of the frame's rows, top first, each with its rows.
fn split_rows<T>(mut buffer: &mut [T], width: u32, rows: Range<u32>, band_rows: u32) -> Vec<(Range<u32>, &mut [T])> {
    let band_rows = band_rows.max(1);
    let mut bands = Vec::with_capacity(rows.len().div_ceil(band_rows as usize) + 1);
    let mut start = rows.start;
    while start < rows.end {
        let end = ((start / band_rows + 1) * band_rows).min(rows.end);
        let (band, rest) = std::mem::take(&mut buffer).split_at_mut((end - start) as usize * width as usize);
        buffer = rest;
        bands.push((start..end, band));
        start = end;
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

/// The scene's environment as the plan turns it, when the plan has one.
fn scene_environment<'a>(scene: &'a PreparedScene, plan: &ScenePlan) -> Option<Environment<'a>> {
    let planned = plan.environment.as_ref()?;
    Some(scene.data().environment.as_ref()?.environment().turned(planned.turn))
}

/// The directions of the rays through a frame's pixel centres, from the camera's matrices.
struct CameraRays {
    /// Clip space to world space.
    world_from_clip: Mat4,
    size: (f32, f32),
}

impl CameraRays {
    fn new(camera: &PlannedCamera, width: u32, height: u32) -> Self {
        let clip_from_world = camera.projection * camera.view;
        Self {
            world_from_clip: clip_from_world.inverse().unwrap_or(Mat4::IDENTITY),
            size: (width as f32, height as f32),
        }
    }

    /// The unit direction through the centre of pixel `(x, y)` (row 0 at the top): from the near plane's point to
    /// the far plane's.
    fn through(&self, x: u32, y: u32) -> Vec3 {
        let ndc_x = (x as f32 + 0.5) / self.size.0 * 2.0 - 1.0;
        let ndc_y = 1.0 - (y as f32 + 0.5) / self.size.1 * 2.0;
        let point = |z: f32| {
            let p = self.world_from_clip * Vec4::new(ndc_x, ndc_y, z, 1.0);
            p.truncate() * (1.0 / p.w)
        };
        (point(1.0) - point(-1.0)).normalize_or_zero()
    }
}

/// The forward pass over one band: clears it to the background and draws every planned part into it, each lent its
/// geometry for the frame (so with the triangles binned into the band); into its samples when the plan multisamples,
/// then averaged into its pixels, each pixel's depth its nearest sample's.
fn forward_band(
    scene: &PreparedScene,
    plan: &ScenePlan,
    geometry: &[DrawGeometry<'_>],
    lights: &Lighting<'_>,
    band: Band<'_>,
    width: u32,
    height: u32,
) -> Result<BandResult, SceneRenderError> {
    let Band { rows, pixels, depth, samples, .. } = band;
    let Some((sample_colors, sample_depths)) = samples else {
        return draw_band(scene, plan, geometry, lights, (rows, Samples::One), (pixels, depth), (width, height));
    };
    let place = (rows, plan.samples());
    let result = draw_band(scene, plan, geometry, lights, place, (sample_colors, sample_depths), (width, height))?;
    resolve_rgb888(sample_colors, plan.samples(), plan.space, pixels)?;
    for (pixel, samples) in depth.iter_mut().zip(sample_depths.chunks_exact(plan.samples().count())) {
        *pixel = samples.iter().fold(1.0, |nearest, &d| d.min(nearest));
    }
    Ok(result)
}

/// [`forward_band`]'s draws into frame rows `rows` with `samples` a pixel, into `colors` and `depths`.
fn draw_band(
    scene: &PreparedScene,
    plan: &ScenePlan,
    geometry: &[DrawGeometry<'_>],
    lights: &Lighting<'_>,
    (rows, samples): (Range<u32>, Samples),
    (colors, depths): (&mut [u32], &mut [f32]),
    (width, height): (u32, u32),
) -> Result<BandResult, SceneRenderError> {
    let mut band = Target::multisampled(Rgb888(colors), depths, width, height, rows, samples)?;
    match lights.environment.filter(|_| plan.environment.as_ref().is_some_and(|e| e.background)) {
        Some(environment) => {
            let rays = CameraRays::new(&plan.camera, width, height);
            band.clear_with(|x, y| plan.space.stored(environment.radiance(rays.through(x, y))));
        }
        None => band.clear(plan.background),
    }
    let mut result = BandResult { fragments: 0, variants: Vec::with_capacity(plan.draws.len()) };
    for (draw, geometry) in plan.draws.iter().zip(geometry) {
        let (object, mesh) = planned_mesh(scene, draw)?;
        let maps = scene.part_maps(draw.object, draw.part);
        let material = part_material(object, maps, draw.part, plan.space, &plan.options)
            .map_err(|error| SceneRenderError::Texture { draw: draw.label.clone(), error })?;
        let tangents = tangents_for(scene, draw.object, &material);
        let surface = Object { mesh, tangents, transforms: draw.transforms, shading: draw.variant.shading, material };
        let mut target = band.for_draw(geometry.lend());
        let (drawn, stats) = draw_mesh(&mut target, &surface, lights, &draw.state)
            .map_err(|error| SceneRenderError::Draw { draw: draw.label.clone(), error })?;
        result.fragments += stats.fragments;
        if plan.wireframe {
            // Every triangle's lines, clipped to the band.
            let clip = &draw.transforms.clip_from_object;
            result.fragments += draw_wireframe(&mut target, &mesh, clip, &WIREFRAME, &drawn.state).fragments;
        }
        result.variants.push(drawn);
    }
    Ok(result)
}
