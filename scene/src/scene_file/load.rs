//! Loading a checked scene file: paths resolved against the scene file's directory, meshes loaded with
//! [`crate::model::load_model`], images with [`TextureImage::load`], each file once.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rastty_core::color::ShadingSpace;
use rastty_core::math::Vec3;
use rastty_core::texture::{Anisotropy, FilterMode, MipFilter, WrapMode};
use toml::Spanned;

use super::SceneFile;
use super::defaults;
use super::error::{SceneFileError, SceneFileErrorKind};
use super::hex_color::parse_hex_color;
use super::loaded::{
    CameraPlacement, FramedCamera, LightFalloff, ObjectAnimation, ObjectMaterial, ObjectNormalMap, SceneCamera,
    SceneData, SceneLight, SceneLightKind, SceneObject, SceneProjection,
};
use super::schema::{
    CameraSpec, FalloffSpec, FilterSpec, LightSpec, LightType, MaterialSpec, Mipmaps, NameOrIndex, ObjectSpec, Triple,
    WrapSpec,
};
use super::transform::object_transform;
use super::validate::{BUILTIN_PREFIX, Checker, unit};
use crate::builtin::builtin_model;
use crate::environment::{EnvironmentChoice, EnvironmentLight};
use crate::escaped::{Escaped, not_among, path_text};
use crate::model::{Model, ModelOptions, TextureImage, load_model};

fn vec3(t: Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

fn vec3_or(value: &Option<Spanned<Triple>>, default: Vec3) -> Vec3 {
    value.as_ref().map_or(default, |v| vec3(*v.get_ref()))
}

/// Loads what `file` refers to. `file` has been validated by [`super::parse`].
pub(crate) fn load_scene_file(file: &SceneFile) -> Result<SceneData, SceneFileError> {
    let base = file.origin.parent().unwrap_or(Path::new(""));
    let mut loader = Loader {
        checker: Checker { file: &file.origin, text: &file.text },
        base,
        meshes: HashMap::new(),
        image_ids: HashMap::new(),
        images: Vec::new(),
        warnings: Vec::new(),
    };
    let spec = &file.spec;
    let mut objects = Vec::with_capacity(spec.objects.get_ref().len());
    for (i, object) in spec.objects.get_ref().iter().enumerate() {
        objects.push(loader.object(object.get_ref(), &format!("objects[{i}]"))?);
    }
    let background =
        spec.background.as_ref().and_then(|b| parse_hex_color(b.get_ref()).ok()).unwrap_or(defaults::BACKGROUND);
    let environment = loader.environment(spec.environment.as_ref())?;
    let Loader { images, warnings, .. } = loader;
    let mut lights: Vec<SceneLight> = spec.lights.iter().map(|l| light(l.get_ref())).collect();
    if spec.viewer_lights {
        lights.extend(defaults::VIEWER_LIGHTS);
    }
    let mut data = SceneData {
        camera: spec.camera.as_ref().map_or(CameraPlacement::Framed(FramedCamera::DEFAULT), |c| camera(c.get_ref())),
        lights,
        lights_of: None,
        objects,
        background,
        ambient: vec3_or(&spec.ambient, defaults::AMBIENT),
        ambient_occlusion: spec.ambient_occlusion,
        environment,
        space: if spec.linear_light { ShadingSpace::Linear } else { ShadingSpace::Encoded },
        images,
        warnings,
    };
    if spec.environment.is_none() && data.physically_based() {
        data.environment = Some(EnvironmentLight::studio());
    }
    Ok(data)
}

fn camera(c: &CameraSpec) -> CameraPlacement {
    let projection = match (&c.fov, &c.orthographic) {
        (_, Some(height)) if c.fov.is_none() => SceneProjection::Orthographic { height: *height.get_ref() },
        (Some(fov), _) => SceneProjection::Perspective { fov_degrees: *fov.get_ref() },
        _ => FramedCamera::DEFAULT.projection,
    };
    let (near, far) = (c.near.as_ref().map(|v| *v.get_ref()), c.far.as_ref().map(|v| *v.get_ref()));
    match (&c.position, &c.target) {
        (Some(position), Some(target)) => CameraPlacement::Placed(SceneCamera {
            position: vec3(*position.get_ref()),
            target: vec3(*target.get_ref()),
            up: c.up.as_ref().and_then(|u| unit(*u.get_ref())).unwrap_or(Vec3::Y),
            projection,
            near,
            far,
        }),
        // Validation admits a framed camera only without `position` and `target`.
        _ => {
            let d = FramedCamera::DEFAULT;
            CameraPlacement::Framed(FramedCamera {
                yaw_degrees: c.yaw.as_ref().map_or(d.yaw_degrees, |v| *v.get_ref()),
                pitch_degrees: c.pitch.as_ref().map_or(d.pitch_degrees, |v| *v.get_ref()),
                distance: c.distance.as_ref().map_or(d.distance, |v| *v.get_ref()),
                projection,
                near,
                far,
            })
        }
    }
}

fn light(l: &LightSpec) -> SceneLight {
    let kind = match l.kind.get_ref() {
        LightType::Directional => SceneLightKind::Directional { direction: direction(l) },
        LightType::Point => SceneLightKind::Point { position: vec3_or(&l.position, Vec3::ZERO), falloff: falloff(l) },
        LightType::Spot => SceneLightKind::Spot {
            position: vec3_or(&l.position, Vec3::ZERO),
            direction: direction(l),
            inner: l.inner_angle.as_ref().map_or(defaults::SPOT_INNER_DEGREES, |a| *a.get_ref()).to_radians(),
            outer: l.outer_angle.as_ref().map_or(defaults::SPOT_OUTER_DEGREES, |a| *a.get_ref()).to_radians(),
            falloff: falloff(l),
        },
    };
    SceneLight {
        kind,
        color: vec3_or(&l.color, Vec3::ONE),
        intensity: l.intensity.as_ref().map_or(1.0, |v| *v.get_ref()),
        shadows: l.shadows,
        space: l.space,
    }
}

/// A directional or spot light's unit direction of travel (checked: given and not zero).
fn direction(l: &LightSpec) -> Vec3 {
    l.direction.as_ref().and_then(|d| unit(*d.get_ref())).unwrap_or(-Vec3::Y)
}

/// A point or spot light's fall-off, as its keys give it (checked: a range only with the inverse square).
fn falloff(l: &LightSpec) -> LightFalloff {
    match l.falloff.as_ref().map(|f| *f.get_ref()) {
        None | Some(FalloffSpec::None) => LightFalloff::None,
        Some(FalloffSpec::InverseSquare) => {
            LightFalloff::InverseSquare { range: l.range.as_ref().map(|r| *r.get_ref()) }
        }
    }
}

/// The identity of a file for sharing: its canonical path when it has one, else the path as given.
fn identity(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

struct Loader<'a> {
    checker: Checker<'a>,
    /// The scene file's directory (empty for a file in the current directory).
    base: &'a Path,
    /// Meshes loaded so far, by identity (or the built-in name) and smoothing angle.
    meshes: HashMap<(PathBuf, Option<u32>), Arc<Model>>,
    /// Images loaded so far: identity to index in `images`.
    image_ids: HashMap<PathBuf, usize>,
    images: Vec<(PathBuf, Arc<TextureImage>)>,
    warnings: Vec<String>,
}

impl Loader<'_> {
    fn object(&mut self, o: &ObjectSpec, key: &str) -> Result<SceneObject, SceneFileError> {
        let options = ModelOptions { smooth_angle: o.smooth_angle.as_ref().map(|a| *a.get_ref()) };
        let (mesh_path, model) = self.mesh(&o.mesh, &format!("{key}.mesh"), &options)?;
        let scale = o.scale.as_ref().map_or(Vec3::ONE, |s| vec3(s.get_ref().triple()));
        let transform = object_transform(vec3_or(&o.translate, Vec3::ZERO), vec3_or(&o.rotate, Vec3::ZERO), scale);
        let material = self.material(&o.material, &format!("{key}.material"), model.uvs.is_some())?;
        let Some(spec) = &o.animation else {
            return Ok(SceneObject { mesh_path, model, transform, material, animation: None });
        };
        let animations = model.rig.as_ref().map_or(&[][..], |r| r.animations());
        let index = match spec.get_ref() {
            NameOrIndex::Name(name) => animations.iter().position(|a| a.name.as_deref() == Some(name)),
            NameOrIndex::Index(i) => usize::try_from(*i).ok().filter(|&i| i < animations.len()),
        };
        let Some(index) = index else {
            let asked = match spec.get_ref() {
                NameOrIndex::Name(name) => name.clone(),
                NameOrIndex::Index(i) => i.to_string(),
            };
            let labels = animations.iter().enumerate().map(|(k, a)| a.label(k));
            let message = not_among("animation", &asked, labels, &format!("{} does not move", path_text(&mesh_path)));
            return Err(self.checker.invalid(&spec.span(), format!("{key}.animation"), message));
        };
        let start = o.time.as_ref().map_or(0.0, |t| *t.get_ref());
        // Its own copy, standing where its animation starts: a still shows it there.
        let mut posed = Model::clone(&model);
        posed.pose(Some(index), start);
        let animation = Some(ObjectAnimation { index, start });
        Ok(SceneObject { mesh_path, model: Arc::new(posed), transform, material, animation })
    }

    fn mesh(
        &mut self,
        spec: &Spanned<String>,
        key: &str,
        options: &ModelOptions,
    ) -> Result<(PathBuf, Arc<Model>), SceneFileError> {
        let text = spec.get_ref();
        let (path, id) = if text.starts_with(BUILTIN_PREFIX) {
            // Validation admits only the built-in names there are.
            (PathBuf::from(text), PathBuf::from(text))
        } else {
            let path = self.base.join(text);
            let id = identity(&path);
            (path, id)
        };
        // The same file smoothed differently is another mesh.
        let id = (id, options.smooth_angle.map(f32::to_bits));
        if let Some(model) = self.meshes.get(&id) {
            return Ok((path, Arc::clone(model)));
        }
        let loaded = if text.starts_with(BUILTIN_PREFIX) { builtin_model() } else { load_model(&path, options) };
        let model = Arc::new(loaded.map_err(|error| {
            let kind = SceneFileErrorKind::Mesh { path: path.clone(), error: Box::new(error) };
            SceneFileError::new(self.checker.file, Some(self.checker.locate(&spec.span())), Some(key.into()), kind)
        })?);
        self.meshes.insert(id, Arc::clone(&model));
        Ok((path, model))
    }

    fn material(&mut self, m: &MaterialSpec, key: &str, has_uvs: bool) -> Result<ObjectMaterial, SceneFileError> {
        let mut image = |spec: &Option<Spanned<String>>, name: &str| -> Result<_, SceneFileError> {
            spec.as_ref().map(|s| self.image(s, &format!("{key}.{name}"), has_uvs)).transpose()
        };
        let diffuse = image(&m.diffuse, "diffuse")?;
        let normal_map = image(&m.normal_map, "normal_map")?;
        let specular_map = image(&m.specular_map, "specular_map")?;
        let glow_map = image(&m.glow_map, "glow_map")?;
        let space = m.normal_space.as_ref().map(|s| *s.get_ref()).unwrap_or_default();
        Ok(ObjectMaterial {
            color: m.color.as_ref().map(|c| vec3(*c.get_ref())),
            diffuse,
            normal_map: normal_map.map(|image| ObjectNormalMap { image, space }),
            specular: m.specular.as_ref().map(|s| vec3(s.get_ref().triple())),
            shininess: m.shininess.as_ref().map(|s| *s.get_ref()),
            metallic: m.metallic.as_ref().map(|s| *s.get_ref()),
            roughness: m.roughness.as_ref().map(|s| *s.get_ref()),
            specular_map,
            glow_map,
            filter: match m.filter {
                FilterSpec::Nearest => FilterMode::Nearest,
                FilterSpec::Bilinear => FilterMode::Bilinear,
            },
            wrap: match m.wrap {
                WrapSpec::Repeat => WrapMode::Repeat,
                WrapSpec::Clamp => WrapMode::Clamp,
            },
            mip_filter: match m.mipmaps {
                Mipmaps::Off => MipFilter::Off,
                Mipmaps::Nearest => MipFilter::Nearest,
                Mipmaps::Linear => MipFilter::Linear,
                Mipmaps::Anisotropic2 => MipFilter::Anisotropic(Anisotropy::X2),
                Mipmaps::Anisotropic4 => MipFilter::Anisotropic(Anisotropy::X4),
                Mipmaps::Anisotropic8 => MipFilter::Anisotropic(Anisotropy::X8),
                Mipmaps::Anisotropic16 => MipFilter::Anisotropic(Anisotropy::X16),
            },
        })
    }

    /// The environment the file names (`environment`), made ready; without the key, `None` here (the caller gives
    /// a physically based scene the studio).
    fn environment(&mut self, spec: Option<&Spanned<String>>) -> Result<Option<Arc<EnvironmentLight>>, SceneFileError> {
        let Some(spec) = spec else { return Ok(None) };
        let choice = EnvironmentChoice::parse(spec.get_ref(), self.base);
        let light = choice.light().map_err(|error| {
            let location = self.checker.locate(&spec.span());
            let path = match &choice {
                EnvironmentChoice::File(path) => path.clone(),
                _ => PathBuf::from(spec.get_ref()),
            };
            let kind = SceneFileErrorKind::Image { path, error: Box::new(error) };
            SceneFileError::new(self.checker.file, Some(location), Some("environment".into()), kind)
        })?;
        if let Some(warning) = light.as_ref().and_then(|l| l.warning()) {
            let location = self.checker.locate(&spec.span());
            self.warnings.push(format!("{}:{location}: environment: {warning}", path_text(self.checker.file)));
        }
        Ok(light)
    }

    fn image(&mut self, spec: &Spanned<String>, key: &str, has_uvs: bool) -> Result<Arc<TextureImage>, SceneFileError> {
        let location = self.checker.locate(&spec.span());
        if !has_uvs {
            self.warnings.push(format!(
                "{}:{location}: {}: the mesh has no texture coordinates, so this image does not show",
                path_text(self.checker.file),
                Escaped(key)
            ));
        }
        let path = self.base.join(spec.get_ref());
        let id = identity(&path);
        if let Some(&index) = self.image_ids.get(&id) {
            return Ok(Arc::clone(&self.images[index].1));
        }
        let image = Arc::new(TextureImage::load(&path).map_err(|error| {
            let kind = SceneFileErrorKind::Image { path: path.clone(), error: Box::new(error) };
            SceneFileError::new(self.checker.file, Some(location), Some(key.into()), kind)
        })?);
        self.image_ids.insert(id, self.images.len());
        self.images.push((path, Arc::clone(&image)));
        Ok(image)
    }
}
