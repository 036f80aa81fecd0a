//! Helpers shared by the core's integration tests: screen-space triangles, a coverage-count target, ASCII art.
#![allow(dead_code)]

use rastty_core::environment::panorama::Panorama;
use rastty_core::environment::{Environment, Irradiance, PanoramaChain, Prefiltering, SplitSum, prepare};
use rastty_core::math::{Lanes, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{DrawState, DrawStats, Fragment, Shader, Slopes, draw};
use rastty_core::target::{
    ColorBuffer, ColorView, DEPTH_LANES, DepthBuffer, DepthView, NoDepth, Rgb565, Rgb888, Samples, Target, depth_to_u16,
};

/// Counts how many times each pixel is written.
pub struct Count<'a>(pub &'a mut [u32]);

impl ColorBuffer for Count<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn write(&mut self, index: usize, _: Vec3) {
        self.0[index] += 1;
    }
    fn fill(&mut self, _: Vec3) {
        self.0.fill(0);
    }
}

/// A shader whose mesh positions are screen pixels (x right, y down), depth z, on a `width x height` frame.
pub struct ScreenSpace {
    pub width: f32,
    pub height: f32,
}

impl Shader for ScreenSpace {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        let p = mesh.position(i);
        Vec4::new(2.0 * p.x / self.width - 1.0, 1.0 - 2.0 * p.y / self.height, p.z, 1.0)
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ONE
    }
}

/// Screen-space triangle corners `(x, y)`, depth 0.5.
pub type Tri = [(f32, f32); 3];

/// Renders screen-space triangles into a coverage count of a `width x height` frame (rows `rows`).
pub fn coverage_rows(
    width: u32,
    height: u32,
    rows: core::ops::Range<u32>,
    tris: &[Tri],
    state: &DrawState,
) -> (Vec<u32>, DrawStats) {
    sample_coverage(width, height, rows, Samples::One, tris, state)
}

/// [`coverage_rows`] with `samples` per pixel: a count per sample (each pixel's samples one after the other).
pub fn sample_coverage(
    width: u32,
    height: u32,
    rows: core::ops::Range<u32>,
    samples: Samples,
    tris: &[Tri],
    state: &DrawState,
) -> (Vec<u32>, DrawStats) {
    let positions: Vec<Vec3> = tris.iter().flatten().map(|&(x, y)| Vec3::new(x, y, 0.5)).collect();
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let mut counts = vec![0u32; width as usize * (rows.end - rows.start) as usize * samples.count()];
    let mut target = Target::multisampled(Count(&mut counts), NoDepth, width, height, rows, samples).unwrap();
    let shader = ScreenSpace { width: width as f32, height: height as f32 };
    let stats = draw(&mut target, &mesh, &shader, state).unwrap();
    (counts, stats)
}

/// [`coverage_rows`] for the whole frame.
pub fn coverage(width: u32, height: u32, tris: &[Tri], state: &DrawState) -> (Vec<u32>, DrawStats) {
    coverage_rows(width, height, 0..height, tris, state)
}

/// No culling: the tests choose windings freely.
pub fn both_sides() -> DrawState {
    DrawState { cull: rastty_core::pipeline::Cull::None, ..DrawState::default() }
}

/// Counts as ASCII art: `.` for 0, `#` for 1, digits for more.
pub fn ascii(counts: &[u32], width: u32) -> Vec<String> {
    counts
        .chunks(width as usize)
        .map(|row| {
            row.iter()
                .map(|&c| match c {
                    0 => '.',
                    1 => '#',
                    n => char::from_digit(n.min(9), 10).unwrap(),
                })
                .collect()
        })
        .collect()
}

/// Asserts that `counts` draws `expected`, printing both on failure.
#[track_caller]
pub fn assert_pattern(counts: &[u32], width: u32, expected: &[&str]) {
    let actual = ascii(counts, width);
    if actual != expected {
        panic!("pattern mismatch\nexpected:\n{}\nactual:\n{}\n", expected.join("\n"), actual.join("\n"));
    }
}

/// A shader drawing object-space positions through one matrix.
pub struct Transformed {
    pub clip_from_object: rastty_core::math::Mat4,
}

impl Shader for Transformed {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ONE
    }
}

/// A camera at the origin looking down -z with a symmetric perspective frustum.
#[derive(Clone, Copy)]
pub struct PinholeCamera {
    pub fovy: f64,
    pub near: f64,
    pub far: f64,
    pub width: u32,
    pub height: u32,
}

impl PinholeCamera {
    pub fn projection(&self) -> rastty_core::math::Mat4 {
        let aspect = self.width as f32 / self.height as f32;
        rastty_core::camera::perspective(self.fovy as f32, aspect, self.near as f32, self.far as f32).unwrap()
    }

    /// Renders view-space triangles (camera at the origin) through the core.
    pub fn render(&self, tris: &[[[f32; 3]; 3]], state: &DrawState) -> (Vec<u32>, DrawStats) {
        let positions: Vec<Vec3> = tris.iter().flatten().map(|p| Vec3::new(p[0], p[1], p[2])).collect();
        let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
        let mut counts = vec![0u32; (self.width * self.height) as usize];
        let mut target = Target::new(Count(&mut counts), NoDepth, self.width, self.height).unwrap();
        let shader = Transformed { clip_from_object: self.projection() };
        let stats = draw(&mut target, &mesh, &shader, state).unwrap();
        (counts, stats)
    }

    /// Exact coverage in f64 by casting the ray through each pixel centre (offset by `(dx, dy)` pixels) and
    /// intersecting it with each triangle between the near and far planes.
    pub fn ray_cast(&self, tris: &[[[f32; 3]; 3]], dx: f64, dy: f64) -> Vec<u32> {
        let (w, h) = (self.width as f64, self.height as f64);
        let t = (self.fovy / 2.0).tan();
        let mut out = vec![0u32; (self.width * self.height) as usize];
        for j in 0..self.height {
            for i in 0..self.width {
                let x = (2.0 * (i as f64 + 0.5 + dx) / w - 1.0) * t * (w / h);
                let y = (1.0 - 2.0 * (j as f64 + 0.5 + dy) / h) * t;
                let dir = [x, y, -1.0];
                for tri in tris {
                    if let Some(dist) = ray_triangle(dir, tri) {
                        if dist >= self.near && dist <= self.far {
                            out[(j * self.width + i) as usize] += 1;
                        }
                    }
                }
            }
        }
        out
    }

    /// [`Self::ray_cast`] at the centres, and whether it agrees with itself ±0.01 px around every centre (so that
    /// sub-pixel snapping cannot change any pixel).
    pub fn robust_ray_cast(&self, tris: &[[[f32; 3]; 3]]) -> (Vec<u32>, usize) {
        let centre = self.ray_cast(tris, 0.0, 0.0);
        let mut fragile = vec![false; centre.len()];
        for (dx, dy) in [(-0.01, 0.0), (0.01, 0.0), (0.0, -0.01), (0.0, 0.01)] {
            for (f, (a, b)) in fragile.iter_mut().zip(centre.iter().zip(self.ray_cast(tris, dx, dy))) {
                *f |= *a != b;
            }
        }
        (centre, fragile.iter().filter(|&&f| f).count())
    }
}

/// Distance along `dir` (from the origin, in units of `dir`'s -z component) at which the ray meets the triangle,
/// by Moller-Trumbore.
fn ray_triangle(dir: [f64; 3], tri: &[[f32; 3]; 3]) -> Option<f64> {
    let p = tri.map(|v| v.map(f64::from));
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (e1, e2) = (sub(p[1], p[0]), sub(p[2], p[0]));
    let q = cross(dir, e2);
    let det = dot(e1, q);
    if det == 0.0 {
        return None;
    }
    let s = sub([0.0; 3], p[0]);
    let u = dot(s, q) / det;
    let r = cross(s, e1);
    let v = dot(dir, r) / det;
    let t = dot(e2, r) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some(t)
}

/// A torus with normals, texture coordinates and colours: self-occluding, so the depth test matters.
pub struct Torus {
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub uvs: Vec<rastty_core::math::Vec2>,
    pub colors: Vec<Vec3>,
    pub indices: Vec<u16>,
}

impl Torus {
    pub fn new(major: f32, minor: f32, rings: u16, sides: u16) -> Self {
        let mut t = Torus { positions: vec![], normals: vec![], uvs: vec![], colors: vec![], indices: vec![] };
        let tau = core::f32::consts::TAU;
        for i in 0..=rings {
            for j in 0..=sides {
                let (u, v) = (i as f32 / rings as f32, j as f32 / sides as f32);
                let (a, b) = (u * tau, v * tau);
                let centre = Vec3::new(a.cos() * major, a.sin() * major, 0.0);
                let n = Vec3::new(a.cos() * b.cos(), a.sin() * b.cos(), b.sin());
                t.positions.push(centre + n * minor);
                t.normals.push(n);
                t.uvs.push(rastty_core::math::Vec2::new(u * 3.0, v));
                t.colors.push(Vec3::new(u, v, 1.0 - u));
            }
        }
        let row = sides + 1;
        for i in 0..rings {
            for j in 0..sides {
                let (a, b) = (i * row + j, (i + 1) * row + j);
                t.indices.extend_from_slice(&[a, b, b + 1, a, b + 1, a + 1]);
            }
        }
        t
    }

    pub fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, Indices::U16(&self.indices))
            .unwrap()
            .with_normals(&self.normals)
            .unwrap()
            .with_uvs(&self.uvs)
            .unwrap()
            .with_colors(&self.colors)
            .unwrap()
    }
}

/// The [`Torus`]`::new(1.0, 0.4, ..)` seen at an angle on a `width x height` frame, so close that the near plane
/// cuts it.
pub fn near_cut_torus_transforms(width: u32, height: u32) -> rastty_core::shading::Transforms {
    use rastty_core::camera::{look_at, perspective};
    use rastty_core::math::Mat4;
    let model = Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.0), 1.1);
    let view = look_at(Vec3::new(0.3, 0.5, 1.6), Vec3::ZERO, Vec3::Y).unwrap();
    let projection = perspective(1.2, width as f32 / height as f32, 0.5, 10.0).unwrap();
    rastty_core::shading::Transforms::new(model, view, projection)
}

/// An 8x8 checkerboard of two colours with a red texel in the top-left corner (so flips show).
pub fn checker_texels() -> Vec<u32> {
    (0..64)
        .map(|i| match (i % 8, i / 8) {
            (0, 0) => 0xFF0000,
            (x, y) if (x + y) % 2 == 0 => 0xF0E0C0,
            _ => 0x203060,
        })
        .collect()
}

/// Keeps the exact `f32` colour of each pixel, so comparisons see differences that 8-bit packing would hide.
pub struct ExactColor<'a>(pub &'a mut [[u32; 3]]);

impl ColorBuffer for ExactColor<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn write(&mut self, index: usize, c: Vec3) {
        self.0[index] = [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()];
    }
    fn fill(&mut self, c: Vec3) {
        self.0.fill([c.x.to_bits(), c.y.to_bits(), c.z.to_bits()]);
    }
}

/// A caller's own `f32` depth buffer, the simplest one can write: it stores the depth it is given when that is
/// nearer, through the trait's default lane method (pixel by pixel), and panics on an index outside it. Bands and
/// frames drawn into it must store exactly what the library's `&mut [f32]` stores: the depth rule is the
/// pipeline's, not the buffer's.
pub struct PlainDepth<'a>(pub &'a mut [f32]);

impl DepthBuffer for PlainDepth<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        let stored = &mut self.0[index];
        let nearer = z < *stored;
        if nearer {
            *stored = z;
        }
        nearer
    }
    fn clear(&mut self) {
        self.0.fill(1.0);
    }
}

/// [`PlainDepth`] in 16 bits: the depth it is given, quantized with `depth_to_u16`.
pub struct PlainDepth16<'a>(pub &'a mut [u16]);

impl DepthBuffer for PlainDepth16<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        let (q, stored) = (depth_to_u16(z), &mut self.0[index]);
        let nearer = q < *stored;
        if nearer {
            *stored = q;
        }
        nearer
    }
    fn clear(&mut self) {
        self.0.fill(u16::MAX);
    }
}

/// The bits of each value, so that comparisons tell `-0.0` from `0.0` and match NaN with NaN.
pub fn bits(depth: &[f32]) -> Vec<u32> {
    depth.iter().map(|d| d.to_bits()).collect()
}

/// A depth value of either format, compared by its bits.
pub trait DepthBits: Copy + core::fmt::Debug {
    fn bits(self) -> u32;
}

impl DepthBits for f32 {
    fn bits(self) -> u32 {
        self.to_bits()
    }
}

impl DepthBits for u16 {
    fn bits(self) -> u32 {
        self.into()
    }
}

/// Panics at the first pixel where `actual` and `expected` (rows of a frame `width` pixels wide, the first being
/// row `first_row`) differ in their bits, naming it.
pub fn assert_same_depths<T: DepthBits>(what: &str, actual: &[T], expected: &[T], width: usize, first_row: usize) {
    assert_eq!(actual.len(), expected.len(), "{what}: lengths");
    if let Some(i) = (0..actual.len()).find(|&i| actual[i].bits() != expected[i].bits()) {
        let (x, y) = (i % width, first_row + i / width);
        panic!("{what}: depth at ({x}, {y}) is {:?}, expected {:?}", actual[i], expected[i]);
    }
}

/// The colour buffer of a frame or band: exact colours or one of the library's packed formats, so that a test can
/// run against any of them. Its view hands the library's formats to the pipeline as they are: draws into it take the
/// paths draws into those formats take.
pub enum AnyColor<'a> {
    Exact(ExactColor<'a>),
    Rgb888(Rgb888<'a>),
    Rgb565(Rgb565<'a>),
}

impl ColorBuffer for AnyColor<'_> {
    fn pixel_count(&self) -> Option<usize> {
        match self {
            Self::Exact(c) => c.pixel_count(),
            Self::Rgb888(c) => c.pixel_count(),
            Self::Rgb565(c) => c.pixel_count(),
        }
    }
    fn write(&mut self, index: usize, color: Vec3) {
        match self {
            Self::Exact(c) => c.write(index, color),
            Self::Rgb888(c) => c.write(index, color),
            Self::Rgb565(c) => c.write(index, color),
        }
    }
    fn fill(&mut self, color: Vec3) {
        match self {
            Self::Exact(c) => c.fill(color),
            Self::Rgb888(c) => c.fill(color),
            Self::Rgb565(c) => c.fill(color),
        }
    }
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        match self {
            Self::Exact(c) => c.write_samples(first, mask, color),
            Self::Rgb888(c) => c.write_samples(first, mask, color),
            Self::Rgb565(c) => c.write_samples(first, mask, color),
        }
    }
    fn view(&mut self) -> ColorView<'_> {
        match self {
            Self::Exact(c) => c.view(),
            Self::Rgb888(c) => c.view(),
            Self::Rgb565(c) => c.view(),
        }
    }
}

/// The depth buffer of a frame or band: the library's (lane-wise where it can be) or a caller's own (pixel by
/// pixel). One type, like [`AnyColor`], whose view hands the library's formats over as they are.
pub enum AnyDepth<'a> {
    F32(&'a mut [f32]),
    U16(&'a mut [u16]),
    Plain(PlainDepth<'a>),
    Plain16(PlainDepth16<'a>),
}

impl DepthBuffer for AnyDepth<'_> {
    fn pixel_count(&self) -> Option<usize> {
        match self {
            Self::F32(d) => d.pixel_count(),
            Self::U16(d) => d.pixel_count(),
            Self::Plain(d) => d.pixel_count(),
            Self::Plain16(d) => d.pixel_count(),
        }
    }
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        match self {
            Self::F32(d) => d.test_and_set(index, z),
            Self::U16(d) => d.test_and_set(index, z),
            Self::Plain(d) => d.test_and_set(index, z),
            Self::Plain16(d) => d.test_and_set(index, z),
        }
    }
    fn test_and_set_lanes(
        &mut self,
        start: usize,
        z: &Lanes<f32, DEPTH_LANES>,
        covered: &Lanes<bool, DEPTH_LANES>,
    ) -> u32 {
        match self {
            Self::F32(d) => d.test_and_set_lanes(start, z, covered),
            Self::U16(d) => d.test_and_set_lanes(start, z, covered),
            Self::Plain(d) => d.test_and_set_lanes(start, z, covered),
            Self::Plain16(d) => d.test_and_set_lanes(start, z, covered),
        }
    }
    fn clear(&mut self) {
        match self {
            Self::F32(d) => d.clear(),
            Self::U16(d) => d.clear(),
            Self::Plain(d) => d.clear(),
            Self::Plain16(d) => d.clear(),
        }
    }
    fn view(&mut self) -> DepthView<'_> {
        match self {
            Self::F32(d) => d.view(),
            Self::U16(d) => d.view(),
            Self::Plain(d) => d.view(),
            Self::Plain16(d) => d.view(),
        }
    }
}

/// What a shaded scene is drawn into: any colour and any depth buffer.
pub type Frame<'c, 'd> = Target<AnyColor<'c>, AnyDepth<'d>>;

/// A whole frame of `color` and `depth` (an [`ExactColor`], `Rgb888`, `Rgb565`; a `&mut [f32]`, `&mut [u16]`,
/// [`PlainDepth`], [`PlainDepth16`]).
pub fn frame<'c, 'd>(
    color: impl Into<AnyColor<'c>>,
    depth: impl Into<AnyDepth<'d>>,
    width: u32,
    height: u32,
) -> Frame<'c, 'd> {
    Target::new(color.into(), depth.into(), width, height).unwrap()
}

/// The band `rows` of a `width x height` frame with `samples` per pixel, drawn into `color` and `depth` (as
/// [`frame`]).
pub fn multisampled<'c, 'd>(
    color: impl Into<AnyColor<'c>>,
    depth: impl Into<AnyDepth<'d>>,
    width: u32,
    height: u32,
    rows: core::ops::Range<u32>,
    samples: Samples,
) -> Frame<'c, 'd> {
    Target::multisampled(color.into(), depth.into(), width, height, rows, samples).unwrap()
}

/// The band `rows` of a `width x height` frame, drawn into `color` and `depth` (as [`frame`]).
pub fn band<'c, 'd>(
    color: impl Into<AnyColor<'c>>,
    depth: impl Into<AnyDepth<'d>>,
    width: u32,
    height: u32,
    rows: core::ops::Range<u32>,
) -> Frame<'c, 'd> {
    multisampled(color, depth, width, height, rows, Samples::One)
}

impl<'a> From<ExactColor<'a>> for AnyColor<'a> {
    fn from(c: ExactColor<'a>) -> Self {
        Self::Exact(c)
    }
}

impl<'a> From<Rgb888<'a>> for AnyColor<'a> {
    fn from(c: Rgb888<'a>) -> Self {
        Self::Rgb888(c)
    }
}

impl<'a> From<Rgb565<'a>> for AnyColor<'a> {
    fn from(c: Rgb565<'a>) -> Self {
        Self::Rgb565(c)
    }
}

impl<'a> From<&'a mut [f32]> for AnyDepth<'a> {
    fn from(d: &'a mut [f32]) -> Self {
        Self::F32(d)
    }
}

impl<'a> From<&'a mut [u16]> for AnyDepth<'a> {
    fn from(d: &'a mut [u16]) -> Self {
        Self::U16(d)
    }
}

impl<'a> From<PlainDepth<'a>> for AnyDepth<'a> {
    fn from(d: PlainDepth<'a>) -> Self {
        Self::Plain(d)
    }
}

impl<'a> From<PlainDepth16<'a>> for AnyDepth<'a> {
    fn from(d: PlainDepth16<'a>) -> Self {
        Self::Plain16(d)
    }
}

/// The buffers of an environment made ready from a panorama: its levels of detail and specular chain, its
/// irradiance, and the split-sum table.
pub struct Prepared {
    pub specular: Vec<Vec3>,
    pub irradiance: Irradiance,
    pub height: u32,
    pub levels: u32,
    pub split_sum: SplitSum,
}

impl Prepared {
    pub fn new(panorama: &Panorama<'_>, prefiltering: Prefiltering) -> Self {
        let height = prefiltering.height_for(panorama.height());
        let (lods, specular) = prefiltering.texel_counts(panorama.height()).unwrap();
        let (mut lods, mut specular) = (vec![Vec3::ZERO; lods], vec![Vec3::ZERO; specular]);
        let irradiance = prepare(panorama, &prefiltering, &mut lods, &mut specular).unwrap();
        Self { specular, irradiance, height, levels: prefiltering.levels, split_sum: SplitSum::new() }
    }

    pub fn environment(&self) -> Environment<'_> {
        let chain = PanoramaChain::new(self.height, self.levels, &self.specular).unwrap();
        Environment::new(self.irradiance, chain, &self.split_sum)
    }
}

/// A 64x32 panorama of 8x8 blocks, each its own colour.
pub fn blocks() -> Vec<Vec3> {
    (0..64 * 32)
        .map(|i| {
            let (bx, by) = ((i % 64) / 8, (i / 64) / 8);
            Vec3::new(bx as f32 / 8.0, by as f32 / 4.0, ((bx * 7 + by * 3) % 11) as f32 / 11.0)
        })
        .collect()
}

/// An environment of [`blocks`], its first level the panorama itself.
pub fn block_environment() -> Prepared {
    let texels = blocks();
    let panorama = Panorama::new(64, 32, &texels).unwrap();
    Prepared::new(&panorama, Prefiltering { height: 32, ..Prefiltering::DEFAULT })
}
