//! The reference scene of a rastty scene, camera and plan options: the picture
//! [`rastty_scene::scene_render::SceneRenderer::render`] draws for a [`ScenePlan`] of them.

use rastty_core::pipeline::Cull;
use rastty_core::shading::ShadingModel;
use rastty_core::texture::FilterMode;

use super::math::{self, DMat4, V3};
use super::{
    Camera, ReferenceError, ReferenceLight, ReferenceLighting, ReferenceMaterial, ReferenceObject, ReferencePlace,
    ReferenceProjection, ReferenceScene, Shading,
};
use rastty_scene::model::Model;
use rastty_scene::scene_file::{
    LightFalloff, LightSpace, SceneCamera, SceneLight, SceneLightKind, SceneProjection as Lens,
};
use rastty_scene::scene_render::{PlanOptions, PreparedScene, ScenePlan, SceneRenderError, ShadingMode, part_material};

fn widen(v: rastty_core::math::Vec3) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

/// [`Model::fit`] in `f64`: centre the bounding box at the origin, scale its half-diagonal to 1.
fn fit(model: &Model) -> DMat4 {
    let Some(b) = model.bounds() else { return math::IDENTITY };
    let (min, max) = (widen(b.min), widen(b.max));
    let centre = [0, 1, 2].map(|i| min[i] * 0.5 + max[i] * 0.5);
    let radius = (0..3).map(|i| (max[i] - min[i]).powi(2)).sum::<f64>().sqrt() * 0.5;
    let scale = if radius > 0.0 && (1.0 / radius).is_finite() { 1.0 / radius } else { 1.0 };
    math::mul(&math::scale(scale), &math::translation(centre.map(|c| -c)))
}

/// An `f32` matrix widened, column by column.
fn widen_matrix(m: &rastty_core::math::Mat4) -> DMat4 {
    m.cols.map(|c| [c.x, c.y, c.z, c.w].map(f64::from))
}

/// The direction toward a directional light as rastty's `core_light` gives it, in `f64`: the file's direction of
/// travel reversed, and for a light in camera space turned into the world by the transpose of `view`'s rotation
/// and renormalised. `None` for a point or spot light ([`place`]).
fn to_light(light: &SceneLight, view: &DMat4) -> Option<[f64; 3]> {
    let SceneLightKind::Directional { direction } = light.kind else { return None };
    let toward = widen(-direction);
    Some(match light.space {
        LightSpace::World => toward,
        LightSpace::Camera => {
            math::apply3(&camera_to_world(view), V3::from_array(toward)).normalize_or_zero().to_array()
        }
    })
}

/// The rotation that takes camera coordinates to the world: row r of `view`'s rotation is the camera's axis r in
/// world coordinates, so these are the columns of its transpose.
fn camera_to_world(view: &DMat4) -> [V3; 3] {
    [0, 1, 2].map(|r| V3::new(view[0][r], view[1][r], view[2][r]))
}

/// Where a point or spot light is, in `f64`, as rastty's `core_light` places it: a light in camera space moved by
/// the eye and turned into the world by the transpose of `view`'s rotation. `None` for a directional light.
fn place(light: &SceneLight, view: &DMat4, camera: &Camera) -> Option<ReferencePlace> {
    let to_world = camera_to_world(view);
    let (position, axis, falloff, cone) = match light.kind {
        SceneLightKind::Directional { .. } => return None,
        SceneLightKind::Point { position, falloff } => (position, None, falloff, None),
        SceneLightKind::Spot { position, direction, inner, outer, falloff } => {
            (position, Some(direction), falloff, Some((f64::from(inner), f64::from(outer))))
        }
    };
    let (position, axis) = match light.space {
        LightSpace::World => (V3::from_array(widen(position)), axis.map(|a| V3::from_array(widen(a)))),
        LightSpace::Camera => (
            V3::from_array(camera.eye) + math::apply3(&to_world, V3::from_array(widen(position))),
            axis.map(|a| math::apply3(&to_world, V3::from_array(widen(a)))),
        ),
    };
    let inverse_square = match falloff {
        LightFalloff::None => None,
        LightFalloff::InverseSquare { range } => Some(range.map(f64::from)),
    };
    let cone = axis.zip(cone).map(|(a, (inner, outer))| (a.normalize_or_zero().to_array(), inner, outer));
    Some(ReferencePlace { position: position.to_array(), inverse_square, cone })
}

impl ReferenceScene {
    /// The reference scene of what rastty's scene renderer draws for `scene` seen by `camera` with `options`, in a
    /// `width x height` image of physical aspect `aspect` (width over height, as passed to
    /// [`ScenePlan::with_aspect`]; `width / height` for a PNG, as [`ScenePlan::new`] takes it).
    ///
    /// rastty's plan of the frame decides what is drawn and with what: every draw of the plan (each part with
    /// triangles of each object, in order) becomes one [`ReferenceObject`] with back faces culled, its material as
    /// [`part_material`] resolves it (colour, specular colour, shininess, diffuse texture and its wrap mode), lit
    /// by the plan's lights and ambient light, over the plan's background, and clipped by the near and far planes
    /// the plan's camera chose (the file's, or derived around the scene's bounds). Everything rastty computes from
    /// those inputs in `f32` is redone in `f64`: the view and projection from the camera's eye, target, up and
    /// lens (the field of view or height across the frame's shorter side), each light's colour times intensity
    /// and, for a light in camera space, its direction turned into the world; an object whose transform is its
    /// model's fit into the unit sphere (a model shown without a scene file, [`Model::fit`]) gets that fit
    /// computed in `f64` from the model's bounds, any other object its transform (as loaded, in `f32`) widened.
    /// The camera's eye, target and up are taken as given (an orbited camera's are computed by rastty in `f32`).
    ///
    /// [`ShadingMode::Unlit`] is drawn unlit; the three lit modes ([`ShadingMode::Flat`],
    /// [`ShadingMode::Gouraud`], [`ShadingMode::Phong`]) all get the truth they approximate, per-pixel
    /// Blinn-Phong, as does [`ShadingMode::Material`] for a scene without physically based materials.
    ///
    /// # Errors
    /// [`ReferenceError::Unsupported`] for what the reference does not draw: the metallic-roughness model, the
    /// depth and normals views,
    /// wireframe lines, shadows, ambient occlusion, normal, specular and glow maps, and nearest
    /// texture filtering. [`ReferenceError::Camera`] when rastty would refuse the camera,
    /// [`ReferenceError::Plan`] when it would refuse the frame otherwise.
    pub fn from_scene(
        scene: &PreparedScene,
        camera: &SceneCamera,
        options: &PlanOptions,
        (width, height): (u32, u32),
        aspect: f64,
    ) -> Result<Self, ReferenceError> {
        let shading = match options.shading {
            ShadingMode::Unlit => Shading::Unlit,
            // Each part by its material: the plan below refuses physically based ones.
            ShadingMode::Material | ShadingMode::Flat | ShadingMode::Gouraud | ShadingMode::Phong => Shading::Lit,
            ShadingMode::MetallicRoughness => return Err(ReferenceError::Unsupported("the metallic-roughness model")),
            ShadingMode::Depth => return Err(ReferenceError::Unsupported("the depth view")),
            ShadingMode::Normals => return Err(ReferenceError::Unsupported("the normals view")),
        };
        if options.wireframe {
            return Err(ReferenceError::Unsupported("wireframe lines"));
        }
        // rastty's plan: its checks, its lights, its draws and its clipping planes.
        let plan =
            ScenePlan::with_aspect(scene, camera, (width, height), aspect as f32, options).map_err(|e| match e {
                SceneRenderError::Camera(e) => ReferenceError::Camera(e),
                e => ReferenceError::Plan(e),
            })?;
        if !plan.shadow_passes.is_empty() {
            return Err(ReferenceError::Unsupported("shadows"));
        }
        if plan.ambient_occlusion.is_some() {
            return Err(ReferenceError::Unsupported("ambient occlusion"));
        }
        if plan.draws.iter().any(|d| d.variant.shading == ShadingModel::MetallicRoughness) {
            return Err(ReferenceError::Unsupported("the metallic-roughness model"));
        }
        if plan.environment.as_ref().is_some_and(|e| e.background) {
            return Err(ReferenceError::Unsupported("the environment as the background"));
        }

        let view = Camera {
            eye: widen(camera.position),
            target: widen(camera.target),
            up: widen(camera.up),
            projection: projection(camera.projection, aspect, f64::from(plan.camera.near), f64::from(plan.camera.far)),
        };
        let view_matrix = math::look_at(V3::from_array(view.eye), V3::from_array(view.target), V3::from_array(view.up))
            .ok_or(ReferenceError::Camera(rastty_core::camera::CameraError::EyeAtTarget))?;

        let mut lights = Vec::with_capacity(plan.lights.len());
        for planned in &plan.lights {
            // The colour as rastty lights with it: decoded in linear light, times the intensity.
            let color = widen(planned.color);
            lights.push(match to_light(&planned.source, &view_matrix) {
                Some(to_light) => ReferenceLight { to_light, color, place: None },
                None => {
                    ReferenceLight { to_light: [0.0; 3], color, place: place(&planned.source, &view_matrix, &view) }
                }
            });
        }

        let objects_data = &scene.data().objects;
        let mut objects = Vec::with_capacity(plan.draws.len());
        // Old vertex index to the part's own, reset after each part.
        let mut remap = Vec::new();
        for draw in &plan.draws {
            let object = &objects_data[draw.object];
            let model = &*object.model;
            let maps = scene.part_maps(draw.object, draw.part);
            let material = part_material(object, maps, draw.part, plan.space, options)
                .map_err(|error| ReferenceError::Plan(SceneRenderError::Texture { draw: draw.label.clone(), error }))?;
            if material.normal_map.is_some() {
                return Err(ReferenceError::Unsupported("normal maps"));
            }
            if material.specular_map.is_some() {
                return Err(ReferenceError::Unsupported("specular maps"));
            }
            if material.glow_map.is_some() {
                return Err(ReferenceError::Unsupported("glow maps"));
            }
            // The image `part_material` samples (from its interleaved copy or from the image itself: the same
            // texels).
            let texture = match material.diffuse {
                Some(_) => object.material.diffuse_over(model.part_material(draw.part)).cloned(),
                None => None,
            };
            if texture.is_some() && material.filter == FilterMode::Nearest {
                return Err(ReferenceError::Unsupported("nearest texture filtering"));
            }
            let model_matrix =
                if object.transform == model.fit() { fit(model) } else { widen_matrix(&object.transform) };

            remap.clear();
            remap.resize(model.positions.len(), u32::MAX);
            let mut used = Vec::new();
            let indices: Vec<u32> = model.indices[model.parts[draw.part].indices.clone()]
                .iter()
                .map(|&i| {
                    let slot = &mut remap[i as usize];
                    if *slot == u32::MAX {
                        *slot = used.len() as u32;
                        used.push(i as usize);
                    }
                    *slot
                })
                .collect();
            objects.push(ReferenceObject {
                positions: used.iter().map(|&i| widen(model.positions[i])).collect(),
                normals: Some(used.iter().map(|&i| widen(model.normals[i])).collect()),
                uvs: model.uvs.as_ref().map(|uvs| used.iter().map(|&i| [uvs[i].x, uvs[i].y].map(f64::from)).collect()),
                indices,
                model: model_matrix,
                material: ReferenceMaterial {
                    color: widen(material.color),
                    specular: widen(material.specular),
                    shininess: f64::from(material.shininess),
                    metallic: f64::from(material.metallic),
                    roughness: f64::from(material.roughness),
                },
                texture,
                wrap: material.wrap,
                shading,
                cull: Cull::Back,
            });
        }
        Ok(Self {
            width,
            height,
            camera: view,
            lighting: ReferenceLighting { ambient: widen(plan.ambient), lights },
            background: widen(plan.background),
            objects,
            // The plan has no metallic-roughness draw (refused above): nothing would reflect an environment.
            environment: None,
            space: plan.space,
        })
    }
}

/// rastty's projection of `lens` (`PlannedCamera::new`) in `f64`: the field of view, or the orthographic height,
/// spans the frame's shorter side (vertically in a landscape frame, horizontally in a portrait one).
fn projection(lens: Lens, aspect: f64, near: f64, far: f64) -> ReferenceProjection {
    // The share of the shorter side the frame's height is: 1 in landscape, the aspect in portrait.
    let portrait = aspect.min(1.0);
    match lens {
        Lens::Perspective { fov_degrees } => {
            let fov = f64::from(fov_degrees).to_radians();
            let fovy = if aspect >= 1.0 { fov } else { 2.0 * ((fov * 0.5).tan() / portrait).atan() };
            ReferenceProjection::Perspective { fovy, aspect, near, far }
        }
        Lens::Orthographic { height } => {
            let half_height = f64::from(height) * 0.5 / portrait;
            let half_width = half_height * aspect;
            ReferenceProjection::Orthographic {
                left: -half_width,
                right: half_width,
                bottom: -half_height,
                top: half_height,
                near,
                far,
            }
        }
    }
}
