//! The reference scene of a rastty model, camera and appearance: the picture [`rastty::scene::Scene::draw`] draws.

use rastty_core::pipeline::Cull;
use rastty_core::texture::WrapMode;

use super::math::{self, Mat4};
use super::{Camera, Light, Lighting, Material, Object, Projection, ReferenceError, Scene, Shading};
use rastty::model::{DEFAULT_DIFFUSE, Model};
use rastty::scene::{self, Appearance, Lens, OrbitCamera, ShadingMode};

fn widen(v: rastty_core::math::Vec3) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

/// [`Model::fit`] in `f64`: centre the bounding box at the origin, scale its half-diagonal to 1.
fn fit(model: &Model) -> Mat4 {
    let Some(b) = model.bounds() else { return math::IDENTITY };
    let (min, max) = (widen(b.min), widen(b.max));
    let centre = [0, 1, 2].map(|i| min[i] * 0.5 + max[i] * 0.5);
    let radius = (0..3).map(|i| (max[i] - min[i]).powi(2)).sum::<f64>().sqrt() * 0.5;
    let scale = if radius > 0.0 && (1.0 / radius).is_finite() { 1.0 / radius } else { 1.0 };
    math::mul(&math::scale(scale), &math::translation(centre.map(|c| -c)))
}

impl Scene {
    /// The reference scene of what [`rastty::scene::Scene::draw`] draws for `model` seen by `camera` with
    /// `appearance`, in a `width x height` image of physical aspect `aspect` (width over height, as passed to
    /// `draw`; `width / height` for a PNG).
    ///
    /// Everything rastty computes in `f32` is redone in `f64` from the same inputs: the fit transform, the
    /// orientation (the camera's quaternion, renormalised), the view and projection (near and far planes as
    /// [`OrbitCamera::planes`] gives them), lights, material and texture. Each part becomes one [`Object`] in
    /// drawing order, with back faces culled. [`ShadingMode::Unlit`] is drawn unlit; the three lit modes
    /// ([`ShadingMode::Flat`], [`ShadingMode::Gouraud`], [`ShadingMode::Phong`]) all get the truth they
    /// approximate, per-pixel Blinn-Phong.
    ///
    /// # Errors
    /// [`ReferenceError::Unsupported`] for the depth and normals views and for wireframe lines;
    /// [`ReferenceError::Camera`] when rastty would refuse the camera.
    pub fn from_model(
        model: &Model,
        camera: &OrbitCamera,
        appearance: &Appearance,
        (width, height): (u32, u32),
        aspect: f64,
    ) -> Result<Self, ReferenceError> {
        let shading = match appearance.shading {
            ShadingMode::Unlit => Shading::Unlit,
            ShadingMode::Flat | ShadingMode::Gouraud | ShadingMode::Phong => Shading::Lit,
            ShadingMode::Depth => return Err(ReferenceError::Unsupported("the depth view")),
            ShadingMode::Normals => return Err(ReferenceError::Unsupported("the normals view")),
        };
        if appearance.wireframe {
            return Err(ReferenceError::Unsupported("wireframe lines"));
        }
        // The same checks as rastty's.
        let matrices = camera.matrices(aspect as f32).map_err(ReferenceError::Camera)?;
        let (near, far) = (f64::from(matrices.near), f64::from(matrices.far));
        let distance = f64::from(camera.distance);
        // As `OrbitCamera::matrices`: the field of view spans the shorter side.
        let fov = f64::from(camera.lens.fov_degrees()).to_radians();
        let half_tan = (fov * 0.5).tan() / aspect.min(1.0);
        let projection = match camera.lens {
            Lens::Perspective { .. } => {
                let fovy = if aspect >= 1.0 { fov } else { 2.0 * half_tan.atan() };
                Projection::Perspective { fovy, aspect, near, far }
            }
            Lens::Orthographic { .. } => {
                let (half_height, half_width) = (distance * half_tan, distance * half_tan * aspect);
                Projection::Orthographic {
                    left: -half_width,
                    right: half_width,
                    bottom: -half_height,
                    top: half_height,
                    near,
                    far,
                }
            }
        };
        let view = Camera { eye: [0.0, 0.0, distance], target: [0.0; 3], up: [0.0, 1.0, 0.0], projection };
        let q = camera.orientation;
        let model_matrix = math::mul(&math::quaternion_matrix([q.x, q.y, q.z, q.w].map(f64::from)), &fit(model));

        let mut objects = Vec::new();
        // Old vertex index to the part's own, reset after each part.
        let mut remap = vec![u32::MAX; model.positions.len()];
        for (p, part) in model.parts.iter().enumerate() {
            // rastty skips a part whose arrays are inconsistent.
            if model.part_mesh(p).is_none() {
                continue;
            }
            let mut used = Vec::new();
            let indices: Vec<u32> = model.indices[part.indices.clone()]
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
            for &i in &used {
                remap[i] = u32::MAX;
            }
            let material = model.part_material(p);
            let texture = material
                .filter(|_| appearance.textures)
                .and_then(|m| m.texture.as_ref())
                .filter(|t| t.texture().is_ok())
                .cloned();
            objects.push(Object {
                positions: used.iter().map(|&i| widen(model.positions[i])).collect(),
                normals: Some(used.iter().map(|&i| widen(model.normals[i])).collect()),
                uvs: model.uvs.as_ref().map(|uvs| used.iter().map(|&i| [uvs[i].x, uvs[i].y].map(f64::from)).collect()),
                indices,
                model: model_matrix,
                material: Material {
                    color: widen(material.map_or(DEFAULT_DIFFUSE, |m| m.diffuse)),
                    specular: widen(scene::SPECULAR),
                    shininess: f64::from(scene::SHININESS),
                },
                texture,
                wrap: WrapMode::Repeat,
                shading,
                cull: Cull::Back,
            });
        }
        Ok(Self {
            width,
            height,
            camera: view,
            lighting: Lighting {
                ambient: widen(scene::AMBIENT),
                lights: scene::LIGHTS
                    .iter()
                    .map(|l| Light { to_light: widen(l.to_light), color: widen(l.color) })
                    .collect(),
            },
            background: widen(appearance.background),
            objects,
        })
    }
}
