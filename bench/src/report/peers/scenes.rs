//! The six pictures of the comparison: meshes, sizes and the camera every renderer uses.
//!
//! Each mesh is moved and scaled once, here, so that its bounding box is centred on the origin with a largest
//! half-extent of 1; the renderers then need only the camera: eye at `(0, 0, 3)` looking at the origin, `y` up,
//! a vertical field of view of 45 degrees, near 0.1, far 100.

use std::path::{Path, PathBuf};

use rastty_core::camera::{look_at, perspective};
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_scene::model::{ModelOptions, TextureImage, load_model};

/// The albedo of the untextured scenes, `(235, 205, 170)`.
pub const ALBEDO: [u8; 3] = [235, 205, 170];
/// The ambient term of the shading `albedo * (AMBIENT + DIFFUSE * max(0, n.l))`.
pub const AMBIENT: f32 = 0.1;
/// The diffuse term's weight.
pub const DIFFUSE: f32 = 0.9;

/// The direction towards the light, normalised: `(0.4, 0.6, 1.0) / |(0.4, 0.6, 1.0)|`.
pub fn to_light() -> Vec3 {
    Vec3::new(0.4, 0.6, 1.0).normalize_or_zero()
}

/// One picture: a mesh, what colours it and the frame size.
pub struct PeerScene {
    /// Short name, the report's row.
    pub name: &'static str,
    /// What the picture is.
    pub description: String,
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// Positions, centred and scaled (see the module's description).
    pub positions: Vec<Vec3>,
    /// One unit normal per position.
    pub normals: Vec<Vec3>,
    /// Texture coordinates, one per position, when [`Self::texture`] is set.
    pub uvs: Option<Vec<Vec2>>,
    /// Three indices per triangle, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
    /// The albedo texture (nearest texel), or `None` for [`ALBEDO`].
    pub texture: Option<TextureImage>,
}

impl PeerScene {
    /// Triangles in the mesh.
    pub fn triangles(&self) -> usize {
        self.indices.len() / 3
    }

    /// The camera's view matrix (world to eye).
    pub fn view(&self) -> Mat4 {
        look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y).expect("a valid camera")
    }

    /// The camera's projection (eye to clip space, depth 0 at the near plane and 1 at the far one).
    pub fn projection(&self) -> Mat4 {
        let aspect = self.width as f32 / self.height as f32;
        perspective(45f32.to_radians(), aspect, 0.1, 100.0).expect("a valid projection")
    }

    /// The albedo at `uv` as the core samples it (nearest texel, repeating, `v` up), or [`ALBEDO`]; each channel
    /// in `[0, 1]`.
    pub fn albedo(&self, uv: Vec2) -> Vec3 {
        let [r, g, b] = match &self.texture {
            None => ALBEDO,
            Some(t) => {
                let (fu, fv) = (uv.x - uv.x.floor(), uv.y - uv.y.floor());
                let x = ((fu * t.width as f32).floor() as u32).min(t.width - 1);
                let y = (((1.0 - fv) * t.height as f32).floor() as u32).min(t.height - 1);
                let texel = t.texels[(y * t.width + x) as usize];
                [(texel >> 16) as u8, (texel >> 8) as u8, texel as u8]
            }
        };
        Vec3::new(r as f32, g as f32, b as f32) / 255.0
    }
}

/// Why a scene could not be made.
#[derive(Debug)]
pub struct PeerSceneError(pub String);

impl std::fmt::Display for PeerSceneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PeerSceneError {}

/// The scenes named in `only` (all six when it is empty), in the report's order, the models read from `models`
/// (the shared models folder, never copied); with `quick`, the two dense spheres have a quarter of their
/// rings and segments, and the large one a quarter of its pixels.
///
/// # Errors
/// When a model or texture cannot be read.
pub fn scenes(models: &Path, quick: bool, only: &[String]) -> Result<Vec<PeerScene>, PeerSceneError> {
    let head_path = models.join("tinyrenderer/african_head/african_head.obj");
    let divide = if quick { 4 } else { 1 };
    let mut scenes = Vec::new();
    for name in super::SCENES.into_iter().filter(|n| only.is_empty() || only.iter().any(|o| o == n)) {
        scenes.push(match name {
            "head" => from_obj("head", &head_path, 800, 800, "file normals")?,
            "head-tex" => {
                let mut scene =
                    from_obj("head-tex", &head_path, 800, 800, "albedo the nearest texel of its diffuse map")?;
                let texture_path = models.join("tinyrenderer/african_head/african_head_diffuse.tga");
                scene.texture = Some(TextureImage::load(&texture_path).map_err(|e| PeerSceneError(e.to_string()))?);
                if scene.uvs.is_none() {
                    return Err(PeerSceneError(format!("{}: no texture coordinates", head_path.display())));
                }
                scene
            }
            "bunny" => from_obj("bunny", &models.join("common-3d/stanford-bunny.obj"), 640, 480, "smooth normals")?,
            "sphere100k" => sphere("sphere100k", 160 / divide, 320 / divide, 1920, 1080),
            "sphere1m" => sphere("sphere1m", 500 / divide, 1000 / divide, 640, 480),
            // Few large triangles at 4K: 600 of them drawn, about 4,400 pixels each (the core's `DrawStats`).
            _ => sphere("large", 24, 48, 3840 / divide.min(2), 2160 / divide.min(2)),
        });
    }
    Ok(scenes)
}

fn from_obj(name: &'static str, path: &Path, width: u32, height: u32, what: &str) -> Result<PeerScene, PeerSceneError> {
    let model = load_model(path, &ModelOptions::default()).map_err(|e| PeerSceneError(e.to_string()))?;
    let file = path.file_stem().map(PathBuf::from).unwrap_or_default();
    let triangles = model.triangle_count();
    let mut scene = PeerScene {
        name,
        description: format!("{}, {triangles} triangles, {what}, {width}x{height}", file.display()),
        width,
        height,
        positions: model.positions,
        normals: model.normals.iter().map(|n| n.normalize_or_zero()).collect(),
        uvs: model.uvs,
        indices: model.indices,
        texture: None,
    };
    centre(&mut scene.positions).ok_or_else(|| PeerSceneError(format!("{}: no finite positions", path.display())))?;
    Ok(scene)
}

/// Moves and scales `positions` so that their bounding box is centred on the origin with a largest half-extent
/// of 1. `None` when there is no finite box.
fn centre(positions: &mut [Vec3]) -> Option<()> {
    let (mut low, mut high) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for p in positions.iter() {
        (low, high) = (low.min(*p), high.max(*p));
    }
    let centre = (low + high) * 0.5;
    let half = (high - low) * 0.5;
    let extent = half.x.max(half.y).max(half.z);
    if !(extent.is_finite() && extent > 0.0) {
        return None;
    }
    for p in positions.iter_mut() {
        *p = (*p - centre) / extent;
    }
    Some(())
}

/// A UV sphere of radius 1: `rings` bands of latitude, `segments` of longitude; the bands at the poles are one
/// triangle per segment, the others two: `2 * segments * (rings - 1)` triangles.
pub fn sphere(name: &'static str, rings: u32, segments: u32, width: u32, height: u32) -> PeerScene {
    let mut positions = Vec::with_capacity(((rings + 1) * (segments + 1)) as usize);
    for i in 0..=rings {
        let theta = std::f32::consts::PI * i as f32 / rings as f32;
        for j in 0..=segments {
            let phi = std::f32::consts::TAU * j as f32 / segments as f32;
            positions.push(Vec3::new(theta.sin() * phi.cos(), theta.cos(), -theta.sin() * phi.sin()));
        }
    }
    let at = |i: u32, j: u32| i * (segments + 1) + j;
    let mut indices = Vec::with_capacity((2 * segments * (rings - 1) * 3) as usize);
    let mut outward = |t: [u32; 3]| {
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let facing = (b - a).cross(c - a).dot(a + b + c);
        indices.extend(if facing >= 0.0 { t } else { [t[0], t[2], t[1]] });
    };
    for i in 0..rings {
        for j in 0..segments {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if i != 0 {
                outward([a, b, d]);
            }
            if i != rings - 1 {
                outward([b, c, d]);
            }
        }
    }
    let normals = positions.iter().map(|p| p.normalize_or_zero()).collect();
    let triangles = indices.len() / 3;
    PeerScene {
        name,
        description: format!("UV sphere, {rings} rings x {segments} segments, {triangles} triangles, {width}x{height}"),
        width,
        height,
        positions,
        normals,
        uvs: None,
        indices,
        texture: None,
    }
}
