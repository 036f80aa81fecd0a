//! Running a plan: the shadow passes into maps the renderer keeps, the forward pass into the caller's target, then
//! the ambient occlusion step.

use std::time::{Duration, Instant};

use rasterm_core::effects::{
    LightSource, SceneLights, ShadowBias, ShadowMap, ShadowView, SurfaceDraw, SurfaceVariant, clear_shadow_depth,
    draw_shadow_caster, draw_surface,
};
use rasterm_core::pipeline::{DrawState, DrawStats, draw_wireframe};
use rasterm_core::target::{ColorBuffer, DepthBuffer, Target};

use super::camera::FrameCamera;
use super::material::part_material;
use super::plan::tangents_for;
use super::{PreparedScene, ScenePlan, SceneRenderError};
use crate::scene::WIREFRAME;

/// What one shadow pass did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowPassReport {
    /// The light's place in the file, from 1.
    pub light: usize,
    /// The map of an earlier frame was still right (same scene, light and view) and was used again: nothing was
    /// drawn.
    pub reused: bool,
    /// What drawing the casters did (zero when reused).
    pub stats: DrawStats,
}

/// What one frame did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FrameReport {
    /// The shadow passes, in the plan's order.
    pub shadow_passes: Vec<ShadowPassReport>,
    /// The forward pass's counts, wireframe lines' fragments included.
    pub forward: DrawStats,
    /// The variant each draw ran, in the plan's order (the plan's own, resolved again with the real maps).
    pub variants: Vec<SurfaceVariant>,
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

/// A shadow map's depth buffer, kept from frame to frame.
#[derive(Debug, Default)]
struct ShadowSlot {
    key: Option<ShadowKey>,
    depth: Vec<f32>,
}

/// Draws [`ScenePlan`]s, keeping the shadow maps' buffers between frames.
///
/// A shadow map depends on the scene, the light and its view (the bounds and the map size), never on the camera,
/// so a map drawn for an earlier frame of the same prepared scene is used again as it is: orbiting in the viewer
/// redraws no shadow map. A switched-off effect is absent from the plan, so nothing of it runs; a kept map costs
/// only its memory until shadows are switched back on.
#[derive(Debug, Default)]
pub struct SceneRenderer {
    slots: Vec<ShadowSlot>,
}

impl SceneRenderer {
    /// A renderer with no shadow map yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Runs `plan` (made for `scene`) into `target`, which must be the plan's size: the shadow passes (each skipped
    /// when its kept map is still right), then clears the target to the background and draws every part, then the
    /// ambient occlusion step when planned.
    ///
    /// # Errors
    /// [`SceneRenderError::Target`] when the target is not the plan's size or the plan names objects the scene does
    /// not have; the core's refusals as [`SceneRenderError::Shadow`], [`SceneRenderError::Texture`] and
    /// [`SceneRenderError::Draw`].
    pub fn render<C: ColorBuffer, D: DepthBuffer>(
        &mut self,
        scene: &PreparedScene,
        plan: &ScenePlan,
        target: &mut Target<C, D>,
    ) -> Result<FrameReport, SceneRenderError> {
        if (target.width(), target.height()) != plan.size {
            return Err(SceneRenderError::Target(format!(
                "the plan is for {}x{} pixels, the target is {}x{}",
                plan.size.0,
                plan.size.1,
                target.width(),
                target.height()
            )));
        }
        let mut report = FrameReport::default();
        let start = Instant::now();
        self.shadow_passes(scene, plan, &mut report)?;
        report.shadow_time = start.elapsed();

        let start = Instant::now();
        let mut sources = Vec::with_capacity(plan.lights.len());
        for light in &plan.lights {
            let shadow = match light.shadow_pass {
                Some(p) => {
                    let pass = &plan.shadow_passes[p];
                    let map = ShadowMap::new(pass.view, &self.slots[p].depth, ShadowBias::DEFAULT, pass.pcf_radius);
                    Some(map.map_err(|error| SceneRenderError::Shadow {
                        light: plan.light_name(light),
                        bounds: plan.bounds,
                        error,
                    })?)
                }
                None => None,
            };
            sources.push(LightSource { kind: light.kind, color: light.color, shadow });
        }
        let lights = SceneLights { ambient: plan.ambient, lights: &sources };
        target.clear(plan.background);
        let objects = &scene.data().objects;
        for draw in &plan.draws {
            let mismatch = || SceneRenderError::Target(format!("the plan's {} is not in the scene", draw.label));
            let object = objects.get(draw.object).ok_or_else(mismatch)?;
            let mesh = object.model.part_mesh(draw.part).ok_or_else(mismatch)?;
            let material = part_material(object, draw.part, &plan.options)
                .map_err(|error| SceneRenderError::Texture { draw: draw.label.clone(), error })?;
            let tangents = tangents_for(scene, draw.object, &material);
            let surface = SurfaceDraw { mesh, tangents, transforms: draw.transforms, material };
            let (variant, stats) = draw_surface(target, &surface, &lights, &DrawState::DEFAULT)
                .map_err(|error| SceneRenderError::Draw { draw: draw.label.clone(), error })?;
            report.forward += stats;
            if plan.wireframe {
                // The lines' pixels count as fragments; their triangles are the ones counted above.
                let clip = &draw.transforms.clip_from_object;
                report.forward.fragments += draw_wireframe(target, &mesh, clip, &WIREFRAME, &variant.state).fragments;
            }
            report.variants.push(variant);
        }
        report.forward_time = start.elapsed();

        if plan.ambient_occlusion {
            let start = Instant::now();
            apply_ambient_occlusion(target, &plan.camera);
            report.occlusion_time = start.elapsed();
        }
        Ok(report)
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
        for (pass, slot) in plan.shadow_passes.iter().zip(&mut self.slots) {
            let light = &plan.lights[pass.light];
            let key = ShadowKey { scene: scene.id(), light: light.number, view: pass.view };
            if slot.key == Some(key) {
                report.shadow_passes.push(ShadowPassReport {
                    light: light.number,
                    reused: true,
                    stats: DrawStats::default(),
                });
                continue;
            }
            slot.key = None;
            let side = pass.map_size as usize;
            slot.depth.resize(side * side, 1.0);
            clear_shadow_depth(&mut slot.depth);
            let mut stats = DrawStats::default();
            for object in &scene.data().objects {
                let Some(mesh) = object.model.mesh() else { continue };
                stats +=
                    draw_shadow_caster(&pass.view, &mut slot.depth, &mesh, &object.transform).map_err(|error| {
                        SceneRenderError::Shadow { light: plan.light_name(light), bounds: plan.bounds, error }
                    })?;
            }
            slot.key = Some(key);
            report.shadow_passes.push(ShadowPassReport { light: light.number, reused: false, stats });
        }
        Ok(())
    }
}

/// The ambient occlusion step: darkens creases and contact areas from the finished depth buffer of `target`, seen
/// through `camera`.
///
/// Not applied yet: the core's screen-space ambient occlusion is being written elsewhere, and until it lands this
/// step returns without changing a pixel. Plans list it (and `--explain` says it changes nothing yet) whenever a
/// scene asks for ambient occlusion and the effect is on; this function is the one place to wire it.
pub fn apply_ambient_occlusion<C: ColorBuffer, D: DepthBuffer>(target: &mut Target<C, D>, camera: &FrameCamera) {
    // AO: wired when core::effects::AmbientOcclusion lands
    let _ = (target, camera);
}
