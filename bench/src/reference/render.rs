//! Visibility and shading of samples: the prepared scene, binning, tiles, threads.

use std::f64::consts::PI;
use std::sync::atomic::{AtomicUsize, Ordering};

use rastty_core::camera::CameraError;
use rastty_core::color::ShadingSpace;
use rastty_core::pipeline::Cull;
use rastty_core::target::MAX_DIMENSION;

use super::math::{self, V3};
use super::metallic_roughness::{EnvironmentSampler, Surface, WhiteAlbedo, alpha_of, random_numbers};
use super::srgb;
use super::texture::sample_bilinear;
use super::{
    Camera, ENVIRONMENT_SAMPLES, ReferenceError, ReferenceImage, ReferenceProjection, ReferenceScene, Shading,
};

/// Samples per pixel along each axis: a regular 16x16 grid, 256 samples per pixel.
pub const SAMPLES_PER_AXIS: u32 = 16;
const N: usize = SAMPLES_PER_AXIS as usize;
const SAMPLES: usize = N * N;
/// Tiles are `TILE x TILE` pixels; each has the list of triangles that may cover it.
const TILE: u32 = 8;
/// Screen-space slack, in pixels, added around each triangle's bounding box against rounding.
const MARGIN: f64 = 1e-3;
/// No triangle.
const NONE: u32 = u32::MAX;

/// Maps screen coordinates to the ray parameter `s = (sx, sy)`: for a perspective camera the view-space ray
/// direction is `(sx, sy, -1)` from the eye, for an orthographic one the ray starts at `(sx, sy, 0)` and runs
/// along `(0, 0, -1)`. Either way the ray parameter of a hit is its view depth.
#[derive(Clone, Copy, Debug)]
enum Rays {
    Perspective { kx: f64, ky: f64 },
    Orthographic { left: f64, right: f64, bottom: f64, top: f64 },
}

/// A triangle set up for ray casting, in view space.
#[derive(Clone, Copy, Debug)]
struct Tri {
    /// Edge functions `E_i(s) = a sx + b sy + c` (`[a, b, c]`), `E_i` opposite vertex `i`, oriented so that a hit
    /// in front of the ray origin has all three `>= 0`; `E_i / sum E` is the hit's barycentric coordinate `i`.
    edges: [[f64; 3]; 3],
    /// The hit's view depth is `(num . [1, sx, sy]) / (den . [1, sx, sy])` (ray-plane intersection).
    num: [f64; 3],
    den: [f64; 3],
    /// Indices into [`Renderer::vertices`].
    vertices: [u32; 3],
    object: u32,
    /// The triangle's index in its object.
    index: u32,
    /// Unit world-space face normal (used when the object has no normals).
    face_normal: V3,
    /// Screen-space bounding box `[x0, x1, y0, y1]` of the part within the depth range, clipped to the image.
    bbox: [f64; 4],
}

/// `E(s)`, always evaluated in this order so that two triangles sharing an edge get exactly opposite values.
#[inline(always)]
fn edge(e: &[f64; 3], sx: f64, sy: f64) -> f64 {
    e[0] * sx + (e[1] * sy + e[2])
}

impl Tri {
    /// The view depth of the hit of ray `s`, if the ray hits the (closed) triangle within `[near, far]`.
    #[inline(always)]
    fn hit(&self, sx: f64, sy: f64, near: f64, far: f64) -> Option<f64> {
        let e0 = edge(&self.edges[0], sx, sy);
        let e1 = edge(&self.edges[1], sx, sy);
        let e2 = edge(&self.edges[2], sx, sy);
        if !(e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0 && e0 + e1 + e2 > 0.0) {
            return None;
        }
        let depth =
            (self.num[0] + self.num[1] * sx + self.num[2] * sy) / (self.den[0] + self.den[1] * sx + self.den[2] * sy);
        (depth >= near && depth <= far).then_some(depth)
    }

    /// Barycentric coordinates of the hit of ray `s` (perspective-correct: those of the 3D point).
    fn barycentric(&self, sx: f64, sy: f64) -> [f64; 3] {
        let e = self.edges.map(|e| edge(&e, sx, sy));
        let sum = e[0] + e[1] + e[2];
        e.map(|v| v / sum)
    }
}

/// A vertex's shading inputs, in world space.
#[derive(Clone, Copy, Debug)]
struct Vertex {
    world: V3,
    /// Unit normal (zero for a zero normal, non-finite for a non-finite one).
    normal: V3,
    uv: [f64; 2],
}

/// What a ray through one point hits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Probe {
    /// Index of the object in [`ReferenceScene::objects`].
    pub object: usize,
    /// Index of the triangle in the object (indices `3 * triangle .. 3 * triangle + 3`).
    pub triangle: usize,
    /// View depth of the hit (distance from the eye along the view axis).
    pub depth: f64,
    /// Barycentric coordinates of the hit point on the triangle, in the order of its indices.
    pub barycentric: [f64; 3],
    /// The hit point in world space.
    pub world: [f64; 3],
    /// The interpolated texture coordinates, when the object has them.
    pub uv: Option<[f64; 2]>,
    /// The unit normal used for lighting ([`Shading::Lit`] only).
    pub normal: Option<[f64; 3]>,
    /// The shaded colour, clamped to `[0, 1]`, as stored (encoded from linear light in [`ShadingSpace::Linear`]).
    pub color: [f64; 3],
}

/// A scene prepared for rendering: vertices transformed, triangles set up and binned into tiles.
///
/// Make one to render and then [`Self::probe`] single points of the same scene; [`render`] does both steps.
#[derive(Debug)]
pub struct Renderer<'a> {
    scene: &'a ReferenceScene,
    rays: Rays,
    near: f64,
    far: f64,
    eye: V3,
    vertices: Vec<Vertex>,
    tris: Vec<Tri>,
    tiles_x: u32,
    tiles_y: u32,
    bins: Vec<Vec<u32>>,
    /// Per object: the white albedo of its roughness, for a [`Shading::MetallicRoughness`] object.
    albedos: Vec<Option<WhiteAlbedo>>,
    /// Directions drawn in proportion to the environment's light, when the scene has one.
    sampler: Option<EnvironmentSampler>,
}

/// Renders `scene`: 16x16 samples per pixel, averaged (see the [module documentation](super)).
///
/// # Errors
/// [`ReferenceError`] for an empty or oversized image, a degenerate camera or an inconsistent object.
pub fn render(scene: &ReferenceScene) -> Result<ReferenceImage, ReferenceError> {
    Ok(Renderer::new(scene)?.render())
}

/// Checks the camera; returns the view matrix, the rays and the depth range.
fn camera_setup(camera: &Camera) -> Result<(math::DMat4, Rays, f64, f64), CameraError> {
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    if !(finite(&camera.eye) && finite(&camera.target) && finite(&camera.up)) {
        return Err(CameraError::NotFinite);
    }
    let view = math::look_at(V3::from_array(camera.eye), V3::from_array(camera.target), V3::from_array(camera.up))
        .ok_or(CameraError::EyeAtTarget)?;
    match camera.projection {
        ReferenceProjection::Perspective { fovy, aspect, near, far } => {
            if !finite(&[fovy, aspect, near, far]) {
                return Err(CameraError::NotFinite);
            }
            if !(fovy > 0.0 && fovy < std::f64::consts::PI) {
                return Err(CameraError::FieldOfView);
            }
            if aspect <= 0.0 {
                return Err(CameraError::Aspect);
            }
            if !(near > 0.0 && far > near) {
                return Err(CameraError::DepthRange);
            }
            let ky = (fovy * 0.5).tan();
            Ok((view, Rays::Perspective { kx: ky * aspect, ky }, near, far))
        }
        ReferenceProjection::Orthographic { left, right, bottom, top, near, far } => {
            if !finite(&[left, right, bottom, top, near, far]) {
                return Err(CameraError::NotFinite);
            }
            if left == right || bottom == top {
                return Err(CameraError::EmptyBox);
            }
            if far <= near {
                return Err(CameraError::DepthRange);
            }
            Ok((view, Rays::Orthographic { left, right, bottom, top }, near, far))
        }
    }
}

/// Checks that an object's arrays fit together.
fn check_object(o: &super::ReferenceObject) -> Result<(), String> {
    if o.indices.len() % 3 != 0 {
        return Err(format!("{} indices is not a whole number of triangles", o.indices.len()));
    }
    let n = o.positions.len();
    if let Some(&i) = o.indices.iter().find(|&&i| i as usize >= n) {
        return Err(format!("index {i} is out of range for {n} vertices"));
    }
    if o.normals.as_ref().is_some_and(|v| v.len() != n) {
        return Err(format!("the normals are not one per position ({n})"));
    }
    if o.uvs.as_ref().is_some_and(|v| v.len() != n) {
        return Err(format!("the texture coordinates are not one per position ({n})"));
    }
    if !math::is_finite(&o.model) {
        return Err("the model matrix is not finite".into());
    }
    Ok(())
}

/// Cuts a convex polygon to the side where `inside(v) >= 0` (Sutherland and Hodgman, "Reentrant polygon
/// clipping", CACM 1974).
fn clip_polygon(poly: &[V3], inside: impl Fn(V3) -> f64) -> Vec<V3> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (da, db) = (inside(a), inside(b));
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(a + (b - a) * (da / (da - db)));
        }
    }
    out
}

/// A stored colour (sRGB-encoded) as the light a sample in `space` carries.
fn light_of(c: V3, space: ShadingSpace) -> V3 {
    if space == ShadingSpace::Linear { V3::new(srgb::decode(c.x), srgb::decode(c.y), srgb::decode(c.z)) } else { c }
}

/// A sample's (or an average's) light as the value stored in `space`.
fn stored(c: V3, space: ShadingSpace) -> V3 {
    if space == ShadingSpace::Linear { V3::new(srgb::encode(c.x), srgb::encode(c.y), srgb::encode(c.z)) } else { c }
}

/// Pairwise sum (exact for a power-of-two count of equal values, and more accurate than a running sum).
fn pairwise(v: &[V3]) -> V3 {
    match v.len() {
        0 => V3::ZERO,
        1 => v[0],
        n => {
            let (a, b) = v.split_at(n / 2);
            pairwise(a) + pairwise(b)
        }
    }
}

/// `sum b_i f(v_i)`.
#[inline(always)]
fn interpolate(v: [&Vertex; 3], b: [f64; 3], f: impl Fn(&Vertex) -> V3) -> V3 {
    f(v[0]) * b[0] + f(v[1]) * b[1] + f(v[2]) * b[2]
}

/// One tile's results.
struct TileOut {
    rgb: Vec<[f64; 3]>,
    centre: Vec<bool>,
    coverage: Vec<f64>,
}

impl<'a> Renderer<'a> {
    /// Checks and prepares `scene`.
    ///
    /// # Errors
    /// As [`render`].
    pub fn new(scene: &'a ReferenceScene) -> Result<Self, ReferenceError> {
        let (width, height) = (scene.width, scene.height);
        if !(1..=MAX_DIMENSION).contains(&width) || !(1..=MAX_DIMENSION).contains(&height) {
            return Err(ReferenceError::Size { width, height });
        }
        let (view, rays, near, far) = camera_setup(&scene.camera).map_err(ReferenceError::Camera)?;
        for (object, o) in scene.objects.iter().enumerate() {
            check_object(o).map_err(|reason| ReferenceError::Object { object, reason })?;
        }
        let tiles_x = width.div_ceil(TILE);
        let tiles_y = height.div_ceil(TILE);
        let mut r = Self {
            scene,
            rays,
            near,
            far,
            eye: V3::from_array(scene.camera.eye),
            vertices: Vec::new(),
            tris: Vec::new(),
            tiles_x,
            tiles_y,
            bins: vec![Vec::new(); (tiles_x * tiles_y) as usize],
            albedos: scene
                .objects
                .iter()
                .map(|o| {
                    (o.shading == Shading::MetallicRoughness).then(|| WhiteAlbedo::new(alpha_of(o.material.roughness)))
                })
                .collect(),
            sampler: scene.environment.as_ref().map(EnvironmentSampler::new),
        };
        for (index, object) in scene.objects.iter().enumerate() {
            r.add_object(index, object, &view);
        }
        Ok(r)
    }

    /// The ray parameter `sx` of screen column `x` (in pixels).
    fn ray_x(&self, x: f64) -> f64 {
        let w = f64::from(self.scene.width);
        match self.rays {
            Rays::Perspective { kx, .. } => (2.0 * x / w - 1.0) * kx,
            Rays::Orthographic { left, right, .. } => left + x / w * (right - left),
        }
    }

    /// The ray parameter `sy` of screen row `y` (in pixels, down).
    fn ray_y(&self, y: f64) -> f64 {
        let h = f64::from(self.scene.height);
        match self.rays {
            Rays::Perspective { ky, .. } => (1.0 - 2.0 * y / h) * ky,
            Rays::Orthographic { bottom, top, .. } => top - y / h * (top - bottom),
        }
    }

    /// Where a view-space point in front of the near plane appears on screen.
    fn to_screen(&self, v: V3) -> (f64, f64) {
        let (w, h) = (f64::from(self.scene.width), f64::from(self.scene.height));
        match self.rays {
            Rays::Perspective { kx, ky } => {
                let depth = -v.z;
                ((v.x / depth / kx + 1.0) * 0.5 * w, (1.0 - v.y / depth / ky) * 0.5 * h)
            }
            Rays::Orthographic { left, right, bottom, top } => {
                ((v.x - left) / (right - left) * w, (top - v.y) / (top - bottom) * h)
            }
        }
    }

    /// Transforms an object's vertices and sets up and bins its triangles.
    fn add_object(&mut self, object: usize, o: &super::ReferenceObject, view: &math::DMat4) {
        let base = self.vertices.len() as u32;
        let normal_matrix = math::normal_matrix(&o.model);
        let mirrors = math::determinant3(&o.model) < 0.0;
        let mut view_positions = Vec::with_capacity(o.positions.len());
        for (i, &p) in o.positions.iter().enumerate() {
            let world = math::transform_point(&o.model, V3::from_array(p));
            let normal = o.normals.as_ref().map_or(V3::ZERO, |n| {
                let n = math::apply3(&normal_matrix, V3::from_array(n[i]));
                if n.is_finite() { n.normalize_or_zero() } else { n }
            });
            let uv = o.uvs.as_ref().map_or([0.0; 2], |uv| uv[i]);
            self.vertices.push(Vertex { world, normal, uv });
            view_positions.push(math::transform_point(view, world));
        }
        let lit_normals = o.shading != Shading::Unlit && o.normals.is_some();
        for (index, t) in o.indices.chunks_exact(3).enumerate() {
            let idx = [t[0], t[1], t[2]];
            let v = idx.map(|i| view_positions[i as usize]);
            let w = idx.map(|i| self.vertices[(base + i) as usize]);
            // Like the core, a triangle with a non-finite vertex or (when lit) normal is skipped.
            if !v.iter().all(|p| p.is_finite()) || (lit_normals && !w.iter().all(|x| x.normal.is_finite())) {
                continue;
            }
            let face = (w[1].world - w[0].world).cross(w[2].world - w[0].world);
            let face_normal = if mirrors { -face } else { face }.normalize_or_zero();
            if let Some(tri) = self.setup(v, o.cull, mirrors) {
                let id = self.tris.len() as u32;
                self.tris.push(Tri {
                    vertices: idx.map(|i| base + i),
                    object: object as u32,
                    index: index as u32,
                    face_normal,
                    ..tri
                });
                self.bin(id);
            }
        }
    }

    /// Edge functions, depth plane, facing and bounding box of a view-space triangle; `None` when it is culled,
    /// edge-on, degenerate, or outside the depth range or the image.
    fn setup(&self, v: [V3; 3], cull: Cull, mirrors: bool) -> Option<Tri> {
        let n = (v[1] - v[0]).cross(v[2] - v[0]);
        let plane = n.dot(v[0]);
        let perspective = matches!(self.rays, Rays::Perspective { .. });
        // Edge i is opposite vertex i: from v[j] to v[k].
        let edges = [(1, 2), (2, 0), (0, 1)].map(|(j, k)| {
            let c = v[j].cross(v[k]);
            if perspective {
                // d . (v_j x v_k) with d = (sx, sy, -1).
                [c.x, c.y, -c.z]
            } else {
                // (0, 0, -1) . ((v_j - o) x (v_k - o)) with o = (sx, sy, 0), expanded.
                let e = v[k] - v[j];
                [e.y, -e.x, -c.z]
            }
        });
        // The sign of `sum E = d . n` for hits in front of the ray origin; negative when the normal faces the ray,
        // which is counter-clockwise on screen.
        let sign = if perspective { plane } else { -n.z };
        if sign == 0.0 || !sign.is_finite() {
            return None;
        }
        let front = (sign < 0.0) != mirrors;
        match cull {
            Cull::Back if !front => return None,
            Cull::Front if front => return None,
            _ => {}
        }
        let s = sign.signum();
        let edges = edges.map(|e| e.map(|x| x * s));
        let (num, den) =
            if perspective { ([plane, 0.0, 0.0], [-n.z, n.x, n.y]) } else { ([plane, -n.x, -n.y], [-n.z, 0.0, 0.0]) };
        // The part within the depth range, on screen.
        let (near, far) = (self.near, self.far);
        let part = clip_polygon(&v, |p| -p.z - near);
        let part = clip_polygon(&part, |p| far + p.z);
        if part.is_empty() {
            return None;
        }
        let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for p in part {
            let (x, y) = self.to_screen(p);
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
        let (w, h) = (f64::from(self.scene.width), f64::from(self.scene.height));
        let bbox = [(x0 - MARGIN).max(0.0), (x1 + MARGIN).min(w), (y0 - MARGIN).max(0.0), (y1 + MARGIN).min(h)];
        // `!(a <= b)` also rejects NaN.
        if !(bbox[0] <= bbox[1] && bbox[2] <= bbox[3]) {
            return None;
        }
        Some(Tri { edges, num, den, vertices: [0; 3], object: 0, index: 0, face_normal: V3::ZERO, bbox })
    }

    /// Adds triangle `id` to the bins of the tiles its bounding box touches.
    fn bin(&mut self, id: u32) {
        let [x0, x1, y0, y1] = self.tris[id as usize].bbox;
        let t = f64::from(TILE);
        let tx0 = (x0 / t).floor() as u32;
        let tx1 = ((x1 / t).floor() as u32).min(self.tiles_x - 1);
        let ty0 = (y0 / t).floor() as u32;
        let ty1 = ((y1 / t).floor() as u32).min(self.tiles_y - 1);
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                self.bins[(ty * self.tiles_x + tx) as usize].push(id);
            }
        }
    }

    /// Renders the scene, on as many threads as the machine has cores.
    pub fn render(&self) -> ReferenceImage {
        let (width, height) = (self.scene.width, self.scene.height);
        let tiles = self.bins.len();
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).clamp(1, tiles);
        let next = AtomicUsize::new(0);
        let done: Vec<Vec<(usize, TileOut)>> = std::thread::scope(|s| {
            let workers: Vec<_> = (0..threads)
                .map(|_| {
                    s.spawn(|| {
                        let mut out = Vec::new();
                        loop {
                            let tile = next.fetch_add(1, Ordering::Relaxed);
                            if tile >= tiles {
                                break out;
                            }
                            out.push((tile, self.render_tile(tile)));
                        }
                    })
                })
                .collect();
            workers.into_iter().map(|w| w.join().unwrap_or_else(|e| std::panic::resume_unwind(e))).collect()
        });
        let n = width as usize * height as usize;
        let mut image = ReferenceImage {
            width,
            height,
            rgb: vec![[0.0; 3]; n],
            centre_covered: vec![false; n],
            coverage: vec![0.0; n],
        };
        for (tile, out) in done.into_iter().flatten() {
            let (px0, py0, tw, _) = self.tile_rect(tile);
            for (i, ((rgb, centre), coverage)) in out.rgb.into_iter().zip(out.centre).zip(out.coverage).enumerate() {
                let (x, y) = (px0 + i as u32 % tw, py0 + i as u32 / tw);
                let p = image.index(x, y);
                (image.rgb[p], image.centre_covered[p], image.coverage[p]) = (rgb, centre, coverage);
            }
        }
        image
    }

    /// Left, top, width and height of a tile, in pixels.
    fn tile_rect(&self, tile: usize) -> (u32, u32, u32, u32) {
        let (tx, ty) = (tile as u32 % self.tiles_x, tile as u32 / self.tiles_x);
        let (px0, py0) = (tx * TILE, ty * TILE);
        (px0, py0, TILE.min(self.scene.width - px0), TILE.min(self.scene.height - py0))
    }

    /// Decides every sample and pixel centre of a tile, then shades and averages.
    fn render_tile(&self, tile: usize) -> TileOut {
        let (px0, py0, tw, th) = self.tile_rect(tile);
        let (tw, th) = (tw as usize, th as usize);
        let (sw, sh) = (tw * N, th * N);
        // Global sample columns and rows of the tile, and their ray parameters.
        let (col0, row0) = (px0 as i64 * N as i64, py0 as i64 * N as i64);
        let sub = |i: i64| (i as f64 + 0.5) / N as f64;
        let sx: Vec<f64> = (0..sw as i64).map(|k| self.ray_x(sub(col0 + k))).collect();
        let sy: Vec<f64> = (0..sh as i64).map(|k| self.ray_y(sub(row0 + k))).collect();
        let cx: Vec<f64> = (0..tw).map(|i| self.ray_x(f64::from(px0) + i as f64 + 0.5)).collect();
        let cy: Vec<f64> = (0..th).map(|j| self.ray_y(f64::from(py0) + j as f64 + 0.5)).collect();
        let mut depth = vec![f64::INFINITY; sw * sh];
        let mut id = vec![NONE; sw * sh];
        let mut centre_depth = vec![f64::INFINITY; tw * th];
        let mut centre_id = vec![NONE; tw * th];
        // Index range `lo..=hi` of grid points `(i + 0.5) / scale` within `[a, b]`, relative to `first`, clipped to
        // `0..count`.
        let range = |a: f64, b: f64, scale: f64, first: i64, count: usize| {
            let lo = ((a * scale - 0.5).ceil() as i64 - first).max(0);
            let hi = ((b * scale - 0.5).floor() as i64 - first).min(count as i64 - 1);
            lo as usize..(hi + 1).max(lo) as usize
        };
        for &t in &self.bins[tile] {
            let tri = &self.tris[t as usize];
            let [x0, x1, y0, y1] = tri.bbox;
            let cols = range(x0, x1, N as f64, col0, sw);
            for r in range(y0, y1, N as f64, row0, sh) {
                for k in cols.clone() {
                    if let Some(d) = tri.hit(sx[k], sy[r], self.near, self.far) {
                        let i = r * sw + k;
                        if d < depth[i] {
                            (depth[i], id[i]) = (d, t);
                        }
                    }
                }
            }
            let cols = range(x0, x1, 1.0, i64::from(px0), tw);
            for r in range(y0, y1, 1.0, i64::from(py0), th) {
                for k in cols.clone() {
                    if let Some(d) = tri.hit(cx[k], cy[r], self.near, self.far) {
                        let i = r * tw + k;
                        if d < centre_depth[i] {
                            (centre_depth[i], centre_id[i]) = (d, t);
                        }
                    }
                }
            }
        }
        let space = self.scene.space;
        let background = light_of(V3::from_array(self.scene.background).clamp01(), space);
        let mut out = TileOut { rgb: Vec::with_capacity(tw * th), centre: Vec::new(), coverage: Vec::new() };
        let mut samples = [V3::ZERO; SAMPLES];
        for j in 0..th {
            for i in 0..tw {
                let mut hits = 0usize;
                for l in 0..N {
                    for k in 0..N {
                        let (r, c) = (j * N + l, i * N + k);
                        let t = id[r * sw + c];
                        samples[l * N + k] = if t == NONE {
                            background
                        } else {
                            hits += 1;
                            let tri = &self.tris[t as usize];
                            // Each sample's own random numbers, from its place in the image.
                            let seed = ((row0 + r as i64) as u64) << 32 | (col0 + c as i64) as u64;
                            self.shade(tri, tri.barycentric(sx[c], sy[r]), seed).0
                        };
                    }
                }
                out.rgb.push(stored(pairwise(&samples) * (1.0 / SAMPLES as f64), space).to_array());
                out.coverage.push(hits as f64 / SAMPLES as f64);
                out.centre.push(centre_id[j * tw + i] != NONE);
            }
        }
        out
    }

    /// The colour (clamped), shading normal and texture coordinates at barycentric `b` of `tri`; `seed` chooses the
    /// directions a metallic-roughness surface integrates its environment over.
    fn shade(&self, tri: &Tri, b: [f64; 3], seed: u64) -> (V3, Option<V3>, Option<[f64; 2]>) {
        let o = &self.scene.objects[tri.object as usize];
        let v = tri.vertices.map(|i| &self.vertices[i as usize]);
        let uv = o.uvs.as_ref().map(|_| {
            let uv = interpolate(v, b, |x| V3::new(x.uv[0], x.uv[1], 0.0));
            [uv.x, uv.y]
        });
        let mut albedo = V3::from_array(o.material.color);
        if let (Some(texture), Some(uv)) = (&o.texture, uv) {
            albedo = albedo.mul_elem(V3::from_array(sample_bilinear(texture, o.wrap, self.scene.space, uv)));
        }
        if o.shading == Shading::Unlit {
            return (albedo.clamp01(), None, uv);
        }
        // Lit: the interpolated normal (the face's without normals) and the point.
        let n = if o.normals.is_some() { interpolate(v, b, |x| x.normal).normalize_or_zero() } else { tri.face_normal };
        let world = interpolate(v, b, |x| x.world);
        match o.shading {
            Shading::Unlit | Shading::Lit => (self.light(albedo, n, world, &o.material).clamp01(), Some(n), uv),
            Shading::MetallicRoughness => {
                let albedo_table = self.albedos[tri.object as usize].as_ref();
                let color = albedo_table.map_or(V3::ZERO, |table| {
                    let surface = Surface {
                        base: albedo,
                        metallic: o.material.metallic,
                        alpha: alpha_of(o.material.roughness),
                        albedo: table,
                    };
                    self.metallic_roughness(&surface, n, world, seed)
                });
                (color.clamp01(), Some(n), uv)
            }
        }
    }

    /// The light `surface` reflects at `world` of unit normal `n`: the ambient light times its diffuse colour, each
    /// light's (the BRDF times pi), and the environment's.
    fn metallic_roughness(&self, surface: &Surface<'_>, n: V3, world: V3, seed: u64) -> V3 {
        let lighting = &self.scene.lighting;
        let v = (self.eye - world).normalize_or_zero();
        let diffuse = surface.base * (1.0 - surface.metallic.clamp(0.0, 1.0));
        let mut light = V3::from_array(lighting.ambient).mul_elem(diffuse);
        for source in &lighting.lights {
            let (l, share) = source.toward(world.to_array());
            light += surface.reflected(n, v, V3::from_array(l)).mul_elem(V3::from_array(source.color)) * (PI * share);
        }
        if let (Some(environment), Some(sampler)) = (&self.scene.environment, &self.sampler) {
            let mut random = random_numbers(seed);
            light += surface.environment_light(environment, sampler, n, v, ENVIRONMENT_SAMPLES, &mut random);
        }
        light
    }

    /// Blinn-Phong at a point with unit normal `n` (the core's `ReferenceLighting::diffuse` and `ReferenceLighting::specular`).
    fn light(&self, albedo: V3, n: V3, world: V3, material: &super::ReferenceMaterial) -> V3 {
        let lighting = &self.scene.lighting;
        let mut diffuse = V3::from_array(lighting.ambient);
        let toward = |light: &super::ReferenceLight| {
            let (l, share) = light.toward(world.to_array());
            (V3::from_array(l), share)
        };
        for light in &lighting.lights {
            let (l, share) = toward(light);
            diffuse += V3::from_array(light.color) * (n.dot(l).max(0.0) * share);
        }
        let lit = albedo.mul_elem(diffuse);
        let specular_color = V3::from_array(material.specular);
        if specular_color == V3::ZERO {
            return lit;
        }
        let to_eye = (self.eye - world).normalize_or_zero();
        let mut specular = V3::ZERO;
        for light in &lighting.lights {
            let (l, share) = toward(light);
            if n.dot(l) > 0.0 {
                let h = (l + to_eye).normalize_or_zero();
                specular += V3::from_array(light.color) * (n.dot(h).max(0.0).powf(material.shininess) * share);
            }
        }
        lit + specular_color.mul_elem(specular)
    }

    /// What the ray through screen point `(x, y)` (pixels, `y` down) hits, if anything: the same decision and
    /// shading as a sample there.
    pub fn probe(&self, x: f64, y: f64) -> Option<Probe> {
        let (sx, sy) = (self.ray_x(x), self.ray_y(y));
        let (w, h) = (f64::from(self.scene.width), f64::from(self.scene.height));
        let all: Vec<u32>;
        let candidates = if (0.0..w).contains(&x) && (0.0..h).contains(&y) {
            let (tx, ty) = ((x / f64::from(TILE)) as u32, (y / f64::from(TILE)) as u32);
            &self.bins[(ty * self.tiles_x + tx) as usize]
        } else {
            all = (0..self.tris.len() as u32).collect();
            &all
        };
        let mut best: Option<(f64, u32)> = None;
        for &t in candidates {
            match (self.tris[t as usize].hit(sx, sy, self.near, self.far), best) {
                (Some(d), Some((b, _))) if d >= b => {}
                (Some(d), _) => best = Some((d, t)),
                (None, _) => {}
            }
        }
        let (depth, t) = best?;
        let tri = &self.tris[t as usize];
        let barycentric = tri.barycentric(sx, sy);
        let seed = (y * f64::from(N as u32)) as u64 ^ ((x * f64::from(N as u32)) as u64) << 32;
        let (color, normal, uv) = self.shade(tri, barycentric, seed);
        let v = tri.vertices.map(|i| self.vertices[i as usize].world);
        let world = v[0] * barycentric[0] + v[1] * barycentric[1] + v[2] * barycentric[2];
        Some(Probe {
            object: tri.object as usize,
            triangle: tri.index as usize,
            depth,
            barycentric,
            world: world.to_array(),
            uv,
            normal: normal.map(V3::to_array),
            color: stored(color, self.scene.space).to_array(),
        })
    }
}
