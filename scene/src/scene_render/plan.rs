//! The plan of one frame: which passes run, with which lights, and what each draw computes.

use rastty_core::color::ShadingSpace;
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Vec3, float};
use rastty_core::occlusion::AmbientOcclusion;
use rastty_core::pipeline::DrawState;
use rastty_core::shading::Transforms;
use rastty_core::shading::{LightUse, Material, Object, Variant};
use rastty_core::shadow::ShadowView;
use rastty_core::target::Samples;

use super::camera::PlannedCamera;
use super::lights::{DroppedLight, LightName, PlannedLight, core_light};
use super::material::{part_material, part_state};
use super::{PlanOptions, PreparedScene, SceneRenderError, lit_color};
use crate::scene_file::SceneCamera;

/// The smallest shadow map side: a frame this small still gets shadow edges finer than its pixels.
pub const MIN_SHADOW_MAP: u32 = 512;
/// The largest shadow map side (16 MiB of depth per light).
pub const MAX_SHADOW_MAP: u32 = 2048;
/// The largest face of a cube shadow map, a point light's among the objects: six faces of 1024x1024 texels hold
/// 24 MiB of depth, and their filter windows' depth ranges twice that again.
pub const MAX_CUBE_FACE: u32 = 1024;
/// The ambient occlusion of scenes that ask for it: the core's defaults, darkening in the scene's space.
pub const AMBIENT_OCCLUSION: AmbientOcclusion = AmbientOcclusion::DEFAULT;
/// Percentage-closer filtering radius of every shadow map: `r = 1` averages 3x3 texels.
pub const PCF_RADIUS: u32 = 1;

/// The side of the shadow maps for a frame of `width x height` pixels: the frame's longer side rounded up to a
/// power of two, within [`MIN_SHADOW_MAP`]`..=`[`MAX_SHADOW_MAP`] (1024 texels, 4 MiB, for 800x800).
///
/// The map spans the scene's bounding sphere and the frame shows about as much, so this gives at least one map
/// texel per pixel: shadow edges as sharp as the frame can show, and no more texels to draw, clear and look up
/// than that needs (at 800x800 a 2048 map made the shadow pass of `docs/scenes/african_head.toml` three times
/// slower, 8.2 against 2.6 ms, with no visible difference).
pub fn shadow_map_size(width: u32, height: u32) -> u32 {
    width.max(height).next_power_of_two().clamp(MIN_SHADOW_MAP, MAX_SHADOW_MAP)
}

/// A shadow pass: one light's depth map, drawn from every object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowPass {
    /// The light, an index into [`ScenePlan::lights`].
    pub light: usize,
    /// The light's view of the scene's bounds: one square, or a cube's six faces for a point light among the
    /// objects ([`ShadowView::faces`]), and the side of the map or of each face ([`ShadowView::size`]).
    pub view: ShadowView,
    /// Objects drawn into the map (every object of the scene casts).
    pub casters: usize,
    /// Percentage-closer filtering radius of the lookups.
    pub pcf_radius: u32,
}

impl ShadowPass {
    /// The map's texels as `rastty render --explain` and `--stats` print them: `1024x1024 texels`, or for a cube
    /// map `6 faces of 1024x1024 texels`.
    pub fn texels(&self) -> String {
        let side = self.view.size();
        match self.view.faces() {
            1 => format!("{side}x{side} texels"),
            faces => format!("{faces} faces of {side}x{side} texels"),
        }
    }
}

/// The environment light of a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedEnvironment {
    /// The environment as `--explain` names it ([`crate::environment::EnvironmentLight`]'s `Display`, escaped).
    pub description: String,
    /// Its turn about the vertical axis, in radians ([`PlanOptions::environment_turn`]).
    pub turn: f32,
    /// Shown behind the objects instead of the background colour.
    pub background: bool,
}

/// One draw of the forward pass: a part of an object's model.
#[derive(Clone, Debug, PartialEq)]
pub struct PlannedDraw {
    /// Index into the scene's objects.
    pub object: usize,
    /// Index into the object's model's parts.
    pub part: usize,
    /// `object N (FILE), part "NAME"`, raw (escape before printing).
    pub label: String,
    /// The draw's matrices.
    pub transforms: Transforms,
    /// The part's draw state (culling: [`part_state`]), as asked for; the variant holds it adapted to the
    /// transforms.
    pub state: DrawState,
    /// What the draw computes: its varyings and fragment stages.
    pub variant: Variant,
}

/// Everything one frame of a scene runs, in order: the shadow passes, the forward pass (one draw per part of each
/// object, with wireframe lines when asked), and ambient occlusion when the scene asks for it. Nothing else runs,
/// and switched-off effects ([`PlanOptions::effects`]) are absent from it. Its [`Display`](std::fmt::Display) is
/// the text of `rastty render --explain`.
#[derive(Clone, Debug, PartialEq)]
pub struct ScenePlan {
    /// The frame's size in pixels.
    pub size: (u32, u32),
    /// The camera's matrices for this frame.
    pub camera: PlannedCamera,
    /// The colour the frame is cleared to.
    pub background: Vec3,
    /// How surfaces are lit (the scene's [`crate::scene_file::SceneData::space`]).
    pub space: ShadingSpace,
    /// The ambient light, as lit in `space` ([`super::lit_color`]).
    pub ambient: Vec3,
    /// The lights used, in file order.
    pub lights: Vec<PlannedLight>,
    /// The lights left out because they shed nothing.
    pub dropped_lights: Vec<DroppedLight>,
    /// The scene's bounds, which shadow maps are fitted to.
    pub bounds: BoundingSphere,
    /// The shadow passes, one per light casting shadows, in the lights' order.
    pub shadow_passes: Vec<ShadowPass>,
    /// The forward pass's draws, in file order of objects and then parts.
    pub draws: Vec<PlannedDraw>,
    /// Triangle edges drawn over each part.
    pub wireframe: bool,
    /// The ambient occlusion step after the forward pass, when the scene asks for it and the effect is on.
    pub ambient_occlusion: Option<AmbientOcclusion>,
    /// The environment light, when the scene has one and the effect is on.
    pub environment: Option<PlannedEnvironment>,
    /// The diffuse textures are used.
    pub textures: bool,
    /// The effects allowed when the plan was made.
    pub options: PlanOptions,
}

impl ScenePlan {
    /// Samples per pixel of the forward pass ([`PlanOptions::multisample`]): with more than one it draws into
    /// buffers of samples that the renderer keeps and resolves them into the frame's pixels.
    pub fn samples(&self) -> Samples {
        if self.options.multisample { Samples::Four } else { Samples::One }
    }

    /// Plans a frame of `width x height` pixels of `scene` seen by `camera` (the file's, or the viewer's after
    /// orbiting), with the effects `options` allows.
    ///
    /// - Lights shedding nothing (intensity 0, black) are dropped (listed in [`Self::dropped_lights`]).
    /// - A light with `shadows = true` gets a shadow pass when shadows are on: a [`shadow_map_size`] map fitted to
    ///   the scene's bounds, [`PCF_RADIUS`] filtering; for a point light inside the bounds a cube of six faces of
    ///   that size, at most [`MAX_CUBE_FACE`].
    /// - Each part with triangles of each object is one draw, whose [`Variant`] is resolved here. The
    ///   variant depends only on each light's kind and shadow filtering ([`LightUse`]), not on what a map holds,
    ///   so planning allocates no shadow map and draws nothing. [`super::SceneRenderer::render`] resolves the same variants when it draws.
    /// - Ambient occlusion when the scene asks for it and it is on.
    ///
    /// # Errors
    /// [`SceneRenderError::Camera`] for a camera the core refuses; [`SceneRenderError::Shadow`] for a shadow light
    /// whose map cannot be fitted (a light at a position or in a direction the core refuses);
    /// [`SceneRenderError::Texture`] and
    /// [`SceneRenderError::Draw`] for a draw the core refuses.
    pub fn new(
        scene: &PreparedScene,
        camera: &SceneCamera,
        (width, height): (u32, u32),
        options: &PlanOptions,
    ) -> Result<Self, SceneRenderError> {
        let aspect = width as f32 / height.max(1) as f32;
        Self::with_aspect(scene, camera, (width, height), aspect, options)
    }

    /// As [`Self::new`], for a frame whose pixels are not square: `aspect` is the frame's physical width over its
    /// height (a terminal's cells are taller than wide).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_aspect(
        scene: &PreparedScene,
        camera: &SceneCamera,
        (width, height): (u32, u32),
        aspect: f32,
        options: &PlanOptions,
    ) -> Result<Self, SceneRenderError> {
        let data = scene.data();
        let bounds = scene.bounds();
        let frame_camera = PlannedCamera::new(camera, &bounds, aspect)?;
        let map_size = shadow_map_size(width, height);
        let mut lights = Vec::new();
        let mut dropped_lights = Vec::new();
        let mut shadow_passes = Vec::new();
        for (i, light) in data.lights.iter().enumerate() {
            let number = i + 1;
            let Some((kind, color)) = core_light(light, &frame_camera.view, camera.position, data.space) else {
                dropped_lights.push(DroppedLight { number, source: *light });
                continue;
            };
            let shadow_pass = if light.shadows && options.effects.shadows {
                let fit = |size| {
                    ShadowView::fit(kind, bounds, size).map_err(|error| SceneRenderError::Shadow {
                        light: LightName { number, light }.to_string(),
                        error,
                    })
                };
                let mut view = fit(map_size)?;
                if view.faces() > 1 && map_size > MAX_CUBE_FACE {
                    view = fit(MAX_CUBE_FACE)?;
                }
                let casters = data.objects.len();
                shadow_passes.push(ShadowPass { light: lights.len(), view, casters, pcf_radius: PCF_RADIUS });
                Some(shadow_passes.len() - 1)
            } else {
                None
            };
            lights.push(PlannedLight { number, source: *light, kind, color, shadow_pass });
        }
        let mut plan = Self {
            size: (width, height),
            camera: frame_camera,
            background: options.background.unwrap_or(data.background),
            space: data.space,
            ambient: lit_color(data.ambient, data.space),
            lights,
            dropped_lights,
            bounds,
            shadow_passes,
            draws: Vec::new(),
            wireframe: options.wireframe,
            ambient_occlusion: (data.ambient_occlusion && options.effects.ambient_occlusion)
                .then_some(AmbientOcclusion { space: data.space, ..AMBIENT_OCCLUSION }),
            environment: data.environment.as_ref().filter(|_| options.effects.environment).map(|light| {
                PlannedEnvironment {
                    description: light.to_string(),
                    turn: options.environment_turn,
                    background: options.environment_background,
                }
            }),
            textures: options.textures,
            options: *options,
        };
        plan.draws = plan.plan_draws(scene, camera)?;
        Ok(plan)
    }

    /// The NDC depths of the near and far side of the scene's bounding sphere along the view, within the clipping
    /// planes: what the depth view maps to white and black.
    fn depth_range(&self, camera: &SceneCamera) -> (f32, f32) {
        let c = &self.camera;
        let forward = (camera.target - camera.position).normalize_or_zero();
        let centre = (self.bounds.centre - camera.position).dot(forward);
        let ndc = |distance: f32| {
            let p = c.projection.project_point(Vec3::new(0.0, 0.0, -distance));
            p.z / p.w
        };
        let r = self.bounds.radius;
        (ndc(float::max(centre - r, c.near)), ndc(float::min(centre + r, c.far)))
    }

    /// The forward pass's draws, with their variants resolved for the planned lights.
    fn plan_draws(&self, scene: &PreparedScene, camera: &SceneCamera) -> Result<Vec<PlannedDraw>, SceneRenderError> {
        let depth_range = self.depth_range(camera);
        let lights: Vec<LightUse> = self
            .lights
            .iter()
            .map(|l| LightUse {
                point: l.kind.position().is_some(),
                environment: false,
                shadow_pcf: l.shadow_pass.map(|p| self.shadow_passes[p].pcf_radius),
            })
            .chain(self.environment.as_ref().map(|_| LightUse::ENVIRONMENT))
            .collect();
        let mut draws = Vec::new();
        for (index, object) in scene.data().objects.iter().enumerate() {
            let transforms = Transforms::new(object.transform, self.camera.view, self.camera.projection);
            for (part_index, part) in object.model.parts.iter().enumerate() {
                if part.indices.is_empty() {
                    continue;
                }
                let label = format!("{}, part \"{}\"", scene.object_label(index), part.name);
                let Some(mesh) = object.model.part_mesh(part_index) else { continue };
                let maps = scene.part_maps(index, part_index);
                let material = part_material(object, maps, part_index, self.space, &self.options)
                    .map_err(|error| SceneRenderError::Texture { draw: label.clone(), error })?;
                let tangents = tangents_for(scene, index, &material);
                let shading = self.options.shading.model(depth_range, object.physically_based(part_index));
                let object = Object { mesh, tangents, transforms, shading, material };
                let state = part_state(&scene.data().objects[index], part_index);
                let variant = Variant::resolve(&object, lights.iter().copied(), self.space, &state)
                    .map_err(|error| SceneRenderError::Draw { draw: label.clone(), error })?;
                draws.push(PlannedDraw { object: index, part: part_index, label, transforms, state, variant });
            }
        }
        Ok(draws)
    }

    /// The name of a planned light in messages.
    pub(crate) fn light_name(&self, light: &PlannedLight) -> String {
        LightName { number: light.number, light: &light.source }.to_string()
    }
}

/// The tangents a draw of `object` with `material` needs: the object's, when the material has a normal map (which
/// it has only when the normal-map effect is on).
pub(crate) fn tangents_for<'a>(
    scene: &'a PreparedScene,
    object: usize,
    material: &Material<'_>,
) -> Option<&'a [rastty_core::math::Vec4]> {
    material.normal_map.and_then(|_| scene.tangents(object))
}
