//! rastty's picture of a reference scene: the same description, converted to `f32` and drawn through the core with
//! one setting of the knobs.

use std::time::{Duration, Instant};

use rastty_core::camera::{CameraError, look_at, orthographic, perspective};
use rastty_core::color::{ShadingSpace, linear_to_srgb};
use rastty_core::environment::{
    Environment, Irradiance, Panorama, PanoramaChain, PanoramaError, Prefiltering, SplitSum, prepare,
};
use rastty_core::math::{Mat4, Vec2, Vec3, Vec4};
use rastty_core::mesh::{Indices, Mesh, MeshError};
use rastty_core::pipeline::DrawState;
use rastty_core::shading::{
    Cone, Falloff, Light, LightKind, Lighting, Material, Object, ShadingError, ShadingModel, Transforms, draw_mesh,
};
use rastty_core::target::{
    ColorBuffer, DepthBuffer, Rgb888, Samples, Target, TargetError, downsample_rgb888, resolve_rgb888,
};
use rastty_core::texture::{MipContent, MipFilter};

use super::settings::{self, DepthFormat, LitShading, Setting};
use crate::reference::{self, ReferenceLight, ReferenceProjection, ReferenceScene, Shading};

/// Why a scene could not be drawn.
#[derive(Debug)]
pub enum CoreRenderError {
    /// The camera is degenerate.
    Camera(CameraError),
    /// A mesh is malformed.
    Mesh(MeshError),
    /// The core refused a draw.
    Draw(ShadingError),
    /// The image size is not usable.
    Target(TargetError),
    /// The environment cannot be made ready.
    Environment(PanoramaError),
}

/// A reference light as the core takes it.
fn core_kind(light: &ReferenceLight) -> LightKind {
    let Some(place) = &light.place else { return LightKind::Directional { to_light: narrow(light.to_light) } };
    let position = narrow(place.position);
    let falloff = match place.inverse_square {
        None => Falloff::None,
        Some(range) => Falloff::inverse_square(range.map(|r| r as f32)),
    };
    match place.cone {
        None => LightKind::Point { position, falloff },
        Some((axis, inner, outer)) => {
            LightKind::Spot { position, falloff, cone: Cone::new(narrow(axis), inner as f32, outer as f32) }
        }
    }
}

impl std::fmt::Display for CoreRenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Camera(e) => write!(f, "camera: {e}"),
            Self::Mesh(e) => write!(f, "mesh: {e}"),
            Self::Draw(e) => write!(f, "draw: {e}"),
            Self::Target(e) => write!(f, "target: {e}"),
            Self::Environment(e) => write!(f, "environment: {e}"),
        }
    }
}

impl std::error::Error for CoreRenderError {}

/// One object in the core's terms.
struct CoreObject<'a> {
    positions: Vec<Vec3>,
    normals: Option<Vec<Vec3>>,
    uvs: Option<Vec<Vec2>>,
    source: &'a reference::ReferenceObject,
}

/// An environment made ready with one prefiltering: the buffers the core's [`Environment`] borrows, and how long
/// making them took.
pub struct PreparedEnvironment {
    /// The prefiltering.
    pub prefiltering: Prefiltering,
    /// Time to make the levels of detail, the specular chain and the irradiance, on one thread.
    pub time: Duration,
    height: u32,
    specular: Vec<Vec3>,
    irradiance: Irradiance,
}

impl PreparedEnvironment {
    /// `source` made ready as `prefiltering` says, on this thread, timed.
    fn new(source: &Panorama<'_>, prefiltering: Prefiltering) -> Result<Self, PanoramaError> {
        let start = Instant::now();
        let (lods, specular) = prefiltering.texel_counts(source.height())?;
        let (mut lods, mut specular) = (vec![Vec3::ZERO; lods], vec![Vec3::ZERO; specular]);
        let irradiance = prepare(source, &prefiltering, &mut lods, &mut specular)?;
        let height = prefiltering.height_for(source.height());
        Ok(Self { prefiltering, time: start.elapsed(), height, specular, irradiance })
    }

    fn environment<'t>(&'t self, split_sum: &'t SplitSum) -> Result<Environment<'t>, PanoramaError> {
        let chain = PanoramaChain::new(self.height, self.prefiltering.levels, &self.specular)?;
        Ok(Environment::new(self.irradiance, chain, split_sum))
    }
}

/// A reference scene converted once: meshes in `f32`, matrices from the core's own camera functions.
pub struct CoreScene<'a> {
    scene: &'a ReferenceScene,
    objects: Vec<CoreObject<'a>>,
    view: Mat4,
    projection: Mat4,
    /// The lights in linear light, as the scene gives them.
    lights: Vec<Light<'static>>,
    /// The lights with their colours encoded ([`in_space`]).
    encoded_lights: Vec<Light<'static>>,
    /// The scene's environment made ready with each prefiltering the settings name (none without one).
    pub environments: Vec<PreparedEnvironment>,
    split_sum: SplitSum,
}

/// A colour the scene gives in linear light as a draw lit in `space` takes it: as it is, or encoded to sRGB (what a
/// renderer that lights the stored values is given).
fn in_space(c: Vec3, space: ShadingSpace) -> Vec3 {
    match space {
        ShadingSpace::Linear => c,
        ShadingSpace::Encoded => c.map(linear_to_srgb),
    }
}

fn narrow(v: [f64; 3]) -> Vec3 {
    Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

fn matrix(m: &reference::math::DMat4) -> Mat4 {
    let col = |c: [f64; 4]| Vec4::new(c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32);
    Mat4::from_cols(col(m[0]), col(m[1]), col(m[2]), col(m[3]))
}

impl<'a> CoreScene<'a> {
    /// Converts `scene`.
    ///
    /// # Errors
    /// [`CoreRenderError::Camera`] for a camera the core refuses.
    pub fn new(scene: &'a ReferenceScene) -> Result<Self, CoreRenderError> {
        let c = &scene.camera;
        let view = look_at(narrow(c.eye), narrow(c.target), narrow(c.up)).map_err(CoreRenderError::Camera)?;
        let projection = match c.projection {
            ReferenceProjection::Perspective { fovy, aspect, near, far } => {
                perspective(fovy as f32, aspect as f32, near as f32, far as f32)
            }
            ReferenceProjection::Orthographic { left, right, bottom, top, near, far } => {
                orthographic(left as f32, right as f32, bottom as f32, top as f32, near as f32, far as f32)
            }
        }
        .map_err(CoreRenderError::Camera)?;
        let objects = scene
            .objects
            .iter()
            .map(|o| CoreObject {
                positions: o.positions.iter().map(|&p| narrow(p)).collect(),
                normals: o.normals.as_ref().map(|n| n.iter().map(|&v| narrow(v)).collect()),
                uvs: o.uvs.as_ref().map(|u| u.iter().map(|uv| Vec2::new(uv[0] as f32, uv[1] as f32)).collect()),
                source: o,
            })
            .collect();
        let lights: Vec<Light<'static>> = scene
            .lighting
            .lights
            .iter()
            // As given (the reference's lights are unit already): not normalised again in `f32`.
            .map(|l| Light { kind: core_kind(l), color: narrow(l.color), shadow: None })
            .collect();
        let encoded_lights =
            lights.iter().map(|l| Light { color: in_space(l.color, ShadingSpace::Encoded), ..*l }).collect();
        let mut environments: Vec<PreparedEnvironment> = Vec::new();
        if let Some(e) = &scene.environment {
            let texels: Vec<Vec3> = e.texels.iter().map(|&t| narrow(t)).collect();
            let source = Panorama::new(e.width, e.height, &texels).map_err(CoreRenderError::Environment)?;
            for setting in &settings::ALL {
                if !environments.iter().any(|p| p.prefiltering == setting.prefiltering) {
                    let prepared = PreparedEnvironment::new(&source, setting.prefiltering);
                    environments.push(prepared.map_err(CoreRenderError::Environment)?);
                }
            }
        }
        Ok(Self { scene, objects, view, projection, lights, encoded_lights, environments, split_sum: SplitSum::new() })
    }

    /// Clears `target` and draws the scene with `setting` (its supersampling is the caller's business).
    ///
    /// # Errors
    /// [`CoreRenderError`] when a mesh or a draw is refused.
    pub fn draw<C: ColorBuffer, D: DepthBuffer>(
        &self,
        target: &mut Target<C, D>,
        setting: &Setting,
    ) -> Result<(), CoreRenderError> {
        target.clear(narrow(self.scene.background));
        let space = setting.space;
        let ambient = in_space(narrow(self.scene.lighting.ambient), space);
        let lights = if space == ShadingSpace::Linear { &self.lights } else { &self.encoded_lights };
        let environment = match self.environments.iter().find(|p| p.prefiltering == setting.prefiltering) {
            Some(prepared) => Some(prepared.environment(&self.split_sum).map_err(CoreRenderError::Environment)?),
            None => None,
        };
        let lighting = Lighting { ambient, lights, environment: environment.as_ref(), space };
        for o in &self.objects {
            let src = o.source;
            let mut mesh = Mesh::new(&o.positions, Indices::U32(&src.indices)).map_err(CoreRenderError::Mesh)?;
            if let Some(n) = &o.normals {
                mesh = mesh.with_normals(n).map_err(CoreRenderError::Mesh)?;
            }
            if let Some(uv) = &o.uvs {
                mesh = mesh.with_uvs(uv).map_err(CoreRenderError::Mesh)?;
            }
            let shading = match (src.shading, setting.shading) {
                (Shading::Unlit, _) => ShadingModel::Unlit,
                (Shading::MetallicRoughness, _) => ShadingModel::MetallicRoughness,
                (Shading::Lit, LitShading::Flat) => ShadingModel::Flat,
                // Without normals the reference lights with the face normal, which is what flat shading does.
                (Shading::Lit, _) if o.normals.is_none() => ShadingModel::Flat,
                (Shading::Lit, LitShading::Gouraud) => ShadingModel::Gouraud,
                (Shading::Lit, LitShading::Phong) => ShadingModel::Phong,
            };
            let m = &src.material;
            let material = Material {
                color: in_space(narrow(m.color), space),
                specular: in_space(narrow(m.specular), space),
                shininess: m.shininess as f32,
                metallic: m.metallic as f32,
                roughness: m.roughness as f32,
                diffuse: src.texture.as_ref().and_then(|t| match setting.mip_filter {
                    MipFilter::Off => t.texture().ok(),
                    _ => t.mipmapped(MipContent::Color).ok(),
                }),
                filter: setting.filter,
                mip_filter: setting.mip_filter,
                wrap: src.wrap,
                ..Material::default()
            };
            let transforms = Transforms::new(matrix(&src.model), self.view, self.projection);
            let object = Object { mesh, tangents: None, transforms, shading, material };
            let state = DrawState { cull: src.cull, ..setting.draw_state() };
            draw_mesh(target, &object, &lighting, &state).map_err(CoreRenderError::Draw)?;
        }
        Ok(())
    }
}

/// A picture rendered with one setting, and what measuring it gave.
pub struct Rendered {
    /// `0x00RRGGBB` pixels.
    pub pixels: Vec<u32>,
    /// Fraction of each pixel's samples that some triangle covered.
    pub coverage: Vec<f64>,
    /// Median time of a frame (clear, draw, and the resolve of supersampling or multisampling).
    pub median: Duration,
}

/// Counts which samples are written.
struct Written<'b>(&'b mut [u8]);

impl ColorBuffer for Written<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn write(&mut self, index: usize, _: Vec3) {
        if let Some(w) = self.0.get_mut(index) {
            *w = 1;
        }
    }
    fn fill(&mut self, _: Vec3) {
        self.0.fill(0);
    }
}

/// Frames of one setting: its buffers, reused from frame to frame, and the times measured so far.
///
/// The report times every setting of a scene in turns, one frame each per round, so that a burst of load on a
/// shared machine slows all settings alike instead of one.
pub struct Frames<'s> {
    setting: &'s Setting,
    /// Samples per pixel along each axis.
    k: u32,
    /// The size rendered: the frame's times `k`.
    size: (u32, u32),
    /// The supersampled or multisampled colour (empty with one sample per pixel: the draw then writes `pixels`
    /// directly).
    samples: Vec<u32>,
    pixels: Vec<u32>,
    depth: DepthBuffers,
    times: Vec<Duration>,
}

/// The depth buffer of a setting's format.
enum DepthBuffers {
    F32(Vec<f32>),
    U16(Vec<u16>),
}

impl<'s> Frames<'s> {
    /// Buffers for `setting` on `scene`'s frame (supersampled or multisampled when the setting says so).
    pub fn new(scene: &CoreScene<'_>, setting: &'s Setting) -> Self {
        let (w, h) = (scene.scene.width, scene.scene.height);
        let k = setting.supersample.max(1);
        let n = (w * k) as usize * (h * k) as usize * setting.multisample.count();
        let depth = match setting.depth {
            DepthFormat::F32 => DepthBuffers::F32(vec![0.0; n]),
            DepthFormat::U16 => DepthBuffers::U16(vec![0; n]),
        };
        Self {
            setting,
            k,
            size: (w * k, h * k),
            samples: if n > (w * h) as usize { vec![0; n] } else { Vec::new() },
            pixels: vec![0; (w * h) as usize],
            depth,
            times: Vec::new(),
        }
    }

    /// Renders one frame (clear, draw, and the resolve of supersampling or multisampling) and records its time.
    ///
    /// # Errors
    /// As [`CoreScene::draw`].
    pub fn time_one(&mut self, scene: &CoreScene<'_>) -> Result<(), CoreRenderError> {
        let ((sw, sh), samples) = (self.size, self.setting.multisample);
        let color = Rgb888(if self.samples.is_empty() { &mut self.pixels } else { &mut self.samples });
        let draw_time = match &mut self.depth {
            DepthBuffers::F32(d) => {
                timed_draw(scene, self.setting, Target::multisampled(color, &mut d[..], sw, sh, 0..sh, samples))?
            }
            DepthBuffers::U16(d) => {
                timed_draw(scene, self.setting, Target::multisampled(color, &mut d[..], sw, sh, 0..sh, samples))?
            }
        };
        let start = Instant::now();
        let space = self.setting.space;
        let resolved = if self.k > 1 {
            downsample_rgb888(&self.samples, sw, self.k, space, &mut self.pixels)
        } else if samples != Samples::One {
            resolve_rgb888(&self.samples, samples, space, &mut self.pixels)
        } else {
            Ok(())
        };
        resolved.map_err(CoreRenderError::Target)?;
        self.times.push(draw_time + start.elapsed());
        Ok(())
    }

    /// The last frame's pixels, the median time (of one frame rendered now, if none was timed), and the coverage
    /// of one more draw.
    ///
    /// # Errors
    /// As [`CoreScene::draw`].
    pub fn finish(mut self, scene: &CoreScene<'_>) -> Result<Rendered, CoreRenderError> {
        if self.times.is_empty() {
            self.time_one(scene)?;
        }
        let median = super::super::median(&self.times);
        let (w, h) = (scene.scene.width, scene.scene.height);
        let (k, (sw, sh), samples) = (self.k, self.size, self.setting.multisample);
        // A pixel's samples: its k x k block, each block holding `samples` side by side.
        let (m, per_row) = (samples.count(), sw as usize * samples.count());
        let mut written = vec![0u8; per_row * sh as usize];
        let color = Written(&mut written);
        match &mut self.depth {
            DepthBuffers::F32(d) => {
                timed_draw(scene, self.setting, Target::multisampled(color, &mut d[..], sw, sh, 0..sh, samples))?
            }
            DepthBuffers::U16(d) => {
                timed_draw(scene, self.setting, Target::multisampled(color, &mut d[..], sw, sh, 0..sh, samples))?
            }
        };
        let pixels = self.pixels;
        let all = (k * k) as f64 * m as f64;
        let coverage = (0..(w * h) as usize)
            .map(|i| {
                let (x, y) = (i % w as usize, i / w as usize);
                let mut hits = 0u32;
                for sy in 0..k as usize {
                    let row = (y * k as usize + sy) * per_row + x * k as usize * m;
                    hits += written[row..row + k as usize * m].iter().map(|&b| u32::from(b)).sum::<u32>();
                }
                f64::from(hits) / all
            })
            .collect();
        Ok(Rendered { pixels, coverage, median })
    }
}

/// Draws `scene` into `target` (refused if its buffers do not fit), timing the draw alone.
fn timed_draw<C: ColorBuffer, D: DepthBuffer>(
    scene: &CoreScene<'_>,
    setting: &Setting,
    target: Result<Target<C, D>, TargetError>,
) -> Result<Duration, CoreRenderError> {
    let mut target = target.map_err(CoreRenderError::Target)?;
    let start = Instant::now();
    scene.draw(&mut target, setting)?;
    Ok(start.elapsed())
}
