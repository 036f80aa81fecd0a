//! Shadow maps: a depth pass from a light into a buffer the caller owns, and the lookup that tells how much of a
//! point the light reaches.
//!
//! The lookup offsets the point along its surface normal before projecting it (normal-offset shadows: Holbein,
//! "Normal Offset Shadows", GDC 2011), by a number of shadow-map texels that grows as the light grazes the surface,
//! and then compares depths with a small constant bias. The offset removes shadow acne (a surface shadowing
//! itself because one texel spans a range of depths) without the large depth bias that detaches shadows from
//! their casters (peter-panning). `core/tests/shadows.rs` holds both limits.
//!
//! A directional light, and a point light outside the scene's bounds, see everything through one square map; a
//! point light among the objects sees every direction through the six faces of a cube (`cube.rs`), stored one
//! below the other as one map six sides high.

use core::ops::Range;

use crate::camera::{CameraError, look_at, orthographic, perspective};
use crate::light_kind::LightKind;
use crate::math::{BoundingSphere, Mat4, Vec3, float};
use crate::mesh::Mesh;
use crate::pipeline::columns::{self, Column, Column3};
use crate::pipeline::{BATCH_SIZE, ClipVolume, Cull, DrawState, DrawStats, PositionShader, draw, lanes};
use crate::target::{MAX_DIMENSION, NoColor, Target};

mod cube;
mod windows;

use cube::CubeFaces;
pub use cube::{CUBE_BORDER, CUBE_NEAR};
pub use windows::{WindowRanges, window_ranges_band};

/// Why a shadow map could not be set up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadowError {
    /// The bounds are empty (radius not positive) or not finite.
    Bounds,
    /// The light's camera could not be built.
    Camera(CameraError),
    /// The map's side is 0 or above [`crate::target::MAX_DIMENSION`], or for a cube map not above
    /// `2 * `[`CUBE_BORDER`].
    Size(u32),
    /// A band's rows are empty or leave the map.
    Rows {
        /// The band's first row.
        start: u32,
        /// The row after its last.
        end: u32,
        /// The map's rows: its side, or six sides for a cube map ([`ShadowView::rows`]).
        height: u32,
    },
    /// A cube map's filter windows of this radius would reach past the border of a face (at most
    /// `CUBE_BORDER - 1`).
    CubeFilter(u32),
    /// Window ranges ([`WindowRanges`]) made for another map size, number of faces or filter radius than the map's.
    Windows {
        /// The map's side.
        size: u32,
        /// The map's filter radius.
        radius: u32,
    },
    /// A buffer does not hold the map's `size * rows` values ([`ShadowView::rows`]; `size * rows.len()` for a band).
    Buffer {
        /// `size * rows`, or `size * rows.len()` for a band.
        expected: usize,
        /// Values given.
        actual: usize,
    },
}

impl core::fmt::Display for ShadowError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Bounds => f.write_str("the shadow bounds are empty or not finite"),
            Self::Camera(e) => write!(f, "the light's camera: {e}"),
            Self::Size(s) => write!(f, "a shadow map of {s}x{s} texels is not supported"),
            Self::Rows { start, end, height } => {
                write!(f, "rows {start}..{end} are not a band of a map {height} texels high")
            }
            Self::CubeFilter(radius) => write!(
                f,
                "a filter of radius {radius} reaches past the faces of a cube shadow map (at most {})",
                CUBE_BORDER - 1
            ),
            Self::Windows { size, radius } => {
                write!(f, "the window ranges are not those of a {size}x{size} map filtered with radius {radius}")
            }
            Self::Buffer { expected, actual } => {
                write!(f, "the shadow map needs {expected} depth values, {actual} given")
            }
        }
    }
}

impl core::error::Error for ShadowError {}

/// How far a shadow lookup moves the point off its surface, and the depth margin it allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowBias {
    /// Offset along the surface normal, in shadow-map texels, at normal incidence. Multiplied by `1 + r` for a
    /// percentage-closer filter of radius `r`.
    pub normal_offset: f32,
    /// Further offset per unit of `1 - n . l`, in texels: grazing light needs more.
    pub slope_offset: f32,
    /// Depth margin, in NDC depth units of the map.
    pub depth: f32,
}

impl ShadowBias {
    /// The defaults, chosen by `core/tests/shadows.rs`: no acne on a plane lit at 85 degrees from its normal, and
    /// a shadow already dark at the first pixel centre past where its caster touches the ground (2.7 map texels).
    pub const DEFAULT: Self = Self { normal_offset: 0.6, slope_offset: 1.5, depth: 2e-5 };
}

impl Default for ShadowBias {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// World size of one shadow-map texel.
#[derive(Clone, Copy, Debug, PartialEq)]
enum TexelSize {
    /// The same everywhere (orthographic).
    Constant(f32),
    /// Proportional to the distance from the light (perspective): `per_distance * |p - eye|`.
    Perspective { eye: Vec3, per_distance: f32 },
}

/// How a shadow map projects the world: through one square, or through the six faces of a cube.
// The cube's six matrices make it 400 bytes to the square's 64: without `alloc` there is nothing to box them in,
// and a view is built once per map and then borrowed by its lookups.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
enum Projection {
    /// World space to the light's clip space.
    Square(Mat4),
    /// Six views around a point light.
    Cube(CubeFaces),
}

/// A light's camera for its shadow map: what it projects, and how large a texel is in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowView {
    projection: Projection,
    texel: TexelSize,
    size: u32,
}

impl ShadowView {
    /// The view of a map fitted to `bounds` as seen from a light: for a directional light an orthographic box
    /// around the sphere, `size x size` texels; for a point or spot light outside the sphere the narrowest
    /// perspective cone that holds it, `size x size` texels; for one inside (or on) it a cube of six `size x size`
    /// faces around the light, each seeing as far as the sphere's farthest point. A spot light's map covers the
    /// bounds as a point light's does, whatever its cone.
    ///
    /// # Errors
    /// [`ShadowError::Bounds`] for empty or non-finite bounds, [`ShadowError::Size`] for a side of 0 or above
    /// [`MAX_DIMENSION`] (and for a cube not above `2 *` [`CUBE_BORDER`]), [`ShadowError::Camera`] if the light's
    /// direction or position is not usable.
    pub fn fit(kind: LightKind, bounds: BoundingSphere, size: u32) -> Result<Self, ShadowError> {
        let BoundingSphere { centre, radius: r } = bounds;
        if !(r > 0.0 && r.is_finite() && centre.is_finite()) {
            return Err(ShadowError::Bounds);
        }
        if size == 0 || size > MAX_DIMENSION {
            return Err(ShadowError::Size(size));
        }
        let size_f = size as f32;
        match kind {
            LightKind::Directional { to_light } => {
                let eye = centre + to_light * (2.0 * r);
                let view = look_at(eye, centre, Vec3::Y).map_err(ShadowError::Camera)?;
                let projection = orthographic(-r, r, -r, r, r, 3.0 * r).map_err(ShadowError::Camera)?;
                let texel = TexelSize::Constant(2.0 * r / size_f);
                Ok(Self { projection: Projection::Square(projection * view), texel, size })
            }
            LightKind::Point { position, .. } | LightKind::Spot { position, .. } => {
                let d = (centre - position).length();
                if !d.is_finite() {
                    return Err(ShadowError::Camera(CameraError::NotFinite));
                }
                let outside = d > r * 1.001;
                if !outside {
                    if size <= 2 * CUBE_BORDER {
                        return Err(ShadowError::Size(size));
                    }
                    let cube = CubeFaces::new(position, d + r, size).map_err(ShadowError::Camera)?;
                    let per_distance = 2.0 * cube.tan_half / size_f;
                    let texel = TexelSize::Perspective { eye: position, per_distance };
                    return Ok(Self { projection: Projection::Cube(cube), texel, size });
                }
                let half = float::asin(r / d);
                let view = look_at(position, centre, Vec3::Y).map_err(ShadowError::Camera)?;
                let near = float::max(d - r, d * 1e-3);
                let projection = perspective(2.0 * half, 1.0, near, d + r).map_err(ShadowError::Camera)?;
                let per_distance = 2.0 * float::tan(half) / size_f;
                let texel = TexelSize::Perspective { eye: position, per_distance };
                Ok(Self { projection: Projection::Square(projection * view), texel, size })
            }
        }
    }

    /// Side of the map (of each face of a cube map) in texels.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// The number of square faces: 1, or 6 for a cube map.
    pub fn faces(&self) -> u32 {
        match self.projection {
            Projection::Square(_) => 1,
            Projection::Cube(_) => 6,
        }
    }

    /// The map's rows: its faces stored one below the other, `size` rows each (face `f` in rows
    /// `f * size..(f + 1) * size`). Its depth buffer holds `size * rows` values.
    pub fn rows(&self) -> u32 {
        self.faces() * self.size
    }

    /// World space to the clip space of face `face`, or `None` past the last face.
    pub fn clip_from_world(&self, face: u32) -> Option<Mat4> {
        match &self.projection {
            Projection::Square(m) => (face == 0).then_some(*m),
            Projection::Cube(cube) => cube.clip_from_world.get(face as usize).copied(),
        }
    }

    /// The face whose texels a world point `p` is compared with: 0 for a square map; for a cube map that of the
    /// largest component of `p`'s direction from the light (+x, -x, +y, -y, +z, -z; ties to x, then y). A lookup
    /// picks it for the point after the normal offset.
    pub fn face_of(&self, p: Vec3) -> u32 {
        match &self.projection {
            Projection::Square(_) => 0,
            Projection::Cube(cube) => cube.face_of(p) as u32,
        }
    }

    /// World size of a map texel at `p`.
    #[inline(always)]
    fn texel_at(&self, p: Vec3) -> f32 {
        match self.texel {
            TexelSize::Constant(t) => t,
            TexelSize::Perspective { eye, per_distance } => per_distance * (p - eye).length(),
        }
    }
}

/// The depth pass of a shadow map: draws `mesh` (placed by `model`) into `depth`, the map's `size * rows`
/// buffer ([`ShadowView::rows`]), as the light sees it, into every face. Both sides of a triangle cast shadows.
/// Clear the buffer to 1.0 first ([`clear_shadow_depth`]).
///
/// # Errors
/// [`ShadowError::Buffer`] when `depth` does not hold `size * rows` values.
pub fn draw_shadow_caster(
    view: &ShadowView,
    depth: &mut [f32],
    mesh: &Mesh<'_>,
    model: &Mat4,
) -> Result<DrawStats, ShadowError> {
    draw_shadow_caster_band(view, depth, 0..view.rows(), mesh, model)
}

/// [`draw_shadow_caster`] into rows `rows` of the map only: `depth` holds `size * rows.len()` values, row
/// `rows.start` first. Bands drawn separately (on separate threads, say) make exactly the map drawn whole. A band
/// may span several faces of a cube map.
///
/// A cube face draws the mesh only if its box (the corners of its positions' bounding box, placed by `model`)
/// may reach the face's view: a face that sees none of it counts its triangles as outside and transforms no
/// vertex. The statistics add up every face drawn in the band.
///
/// # Errors
/// [`ShadowError::Rows`] when `rows` is empty or leaves the map; [`ShadowError::Buffer`] when `depth` does not
/// hold `size * rows.len()` values.
pub fn draw_shadow_caster_band(
    view: &ShadowView,
    depth: &mut [f32],
    rows: Range<u32>,
    mesh: &Mesh<'_>,
    model: &Mat4,
) -> Result<DrawStats, ShadowError> {
    let (size, height) = (view.size, view.rows());
    if rows.is_empty() || rows.end > height {
        return Err(ShadowError::Rows { start: rows.start, end: rows.end, height });
    }
    let expected = size as usize * rows.len();
    if depth.len() != expected {
        return Err(ShadowError::Buffer { expected, actual: depth.len() });
    }
    let corners = match view.projection {
        Projection::Square(_) => None,
        Projection::Cube(_) => box_corners(mesh.positions()),
    };
    let volume = ClipVolume::new(size, size, 0, size);
    let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
    let mut stats = DrawStats::default();
    let mut rest = depth;
    let mut row = rows.start;
    while row < rows.end {
        let face = row / size;
        let face_rows = row - face * size..(rows.end - face * size).min(size);
        let length = size as usize * face_rows.len();
        let (band, after) = core::mem::take(&mut rest).split_at_mut(length);
        (rest, row) = (after, face * size + face_rows.end);
        let Some(clip_from_world) = view.clip_from_world(face) else { break };
        let clip_from_object = clip_from_world * *model;
        // The box is out of the face when its corners share a plane they are all beyond (their outcodes, as the
        // pipeline rejects a triangle), and so is every triangle in it.
        let out = |corners: [Vec3; 8]| {
            corners.iter().fold(!0, |all, &c| all & volume.outcode(clip_from_object.project_point(c)))
        };
        if corners.is_some_and(|corners| out(corners) != 0) {
            let triangles = mesh.triangle_count() as u64;
            stats += DrawStats { triangles_in: triangles, outside: triangles, ..DrawStats::default() };
            continue;
        }
        // The buffer's length was checked, so each face's band is valid.
        let Ok(mut target) = Target::band(NoColor, band, size, size, face_rows) else {
            return Err(ShadowError::Buffer { expected: length, actual: length });
        };
        // The caster reads positions only and the state is valid, so the pipeline has nothing to refuse.
        stats += draw(&mut target, mesh, &PositionShader { clip_from_object }, &state).unwrap_or_default();
    }
    Ok(stats)
}

/// The eight corners of the bounding box of `positions`, or `None` when there are none or one is not finite.
fn box_corners(positions: &[Vec3]) -> Option<[Vec3; 8]> {
    let first = *positions.first()?;
    let (mut lo, mut hi, mut finite) = (first, first, true);
    for &p in positions {
        lo = Vec3::new(float::min(lo.x, p.x), float::min(lo.y, p.y), float::min(lo.z, p.z));
        hi = Vec3::new(float::max(hi.x, p.x), float::max(hi.y, p.y), float::max(hi.z, p.z));
        finite &= p.is_finite();
    }
    if !finite {
        return None;
    }
    Some(core::array::from_fn(|i| {
        let pick = |bit: usize, lo: f32, hi: f32| if i & bit == 0 { lo } else { hi };
        Vec3::new(pick(1, lo.x, hi.x), pick(2, lo.y, hi.y), pick(4, lo.z, hi.z))
    }))
}

/// Sets every depth of a shadow map to the far plane (1.0): nothing casts a shadow yet.
pub fn clear_shadow_depth(depth: &mut [f32]) {
    depth.fill(1.0);
}

/// A finished shadow map: the light's view, its depths, and how lookups compare.
#[derive(Clone, Copy, Debug)]
pub struct ShadowMap<'a> {
    view: ShadowView,
    depth: &'a [f32],
    bias: ShadowBias,
    pcf_radius: u32,
    windows: Option<WindowRanges<'a>>,
}

impl<'a> ShadowMap<'a> {
    /// The shadow map of `view` with the depths its casters left in `depth`. `pcf_radius` 0 takes one sample
    /// (hard edges); `r` averages the `(2r + 1)^2` texels around the point (percentage-closer filtering: Reeves,
    /// Salesin and Cook, "Rendering Antialiased Shadows with Depth Maps", SIGGRAPH 1987).
    ///
    /// # Errors
    /// [`ShadowError::Buffer`] when `depth` does not hold `size * rows` values ([`ShadowView::rows`]);
    /// [`ShadowError::CubeFilter`] for a cube map whose filter would reach past a face's border.
    pub fn new(view: ShadowView, depth: &'a [f32], bias: ShadowBias, pcf_radius: u32) -> Result<Self, ShadowError> {
        let expected = view.size as usize * view.rows() as usize;
        if depth.len() != expected {
            return Err(ShadowError::Buffer { expected, actual: depth.len() });
        }
        if view.faces() > 1 && pcf_radius >= CUBE_BORDER {
            return Err(ShadowError::CubeFilter(pcf_radius));
        }
        Ok(Self { view, depth, bias, pcf_radius, windows: None })
    }

    /// The same map, with the depth ranges of its filter's windows ([`window_ranges_band`], computed from
    /// this map's depths): lookups that the range decides read one value instead of the window. The light reaching
    /// any point is the same, bit for bit.
    ///
    /// # Errors
    /// [`ShadowError::Windows`] when the ranges are for another map size, number of faces or filter radius.
    pub fn with_windows(self, windows: WindowRanges<'a>) -> Result<Self, ShadowError> {
        let faces = windows.faces() == self.view.faces();
        if windows.size() != self.view.size || windows.radius() != self.pcf_radius || !faces {
            return Err(ShadowError::Windows { size: self.view.size, radius: self.pcf_radius });
        }
        Ok(Self { windows: Some(windows), ..self })
    }

    /// The `r` of `(2r + 1)^2` percentage-closer samples.
    pub fn pcf_radius(&self) -> u32 {
        self.pcf_radius
    }

    /// Side of the map (of each face of a cube map) in texels.
    pub fn size(&self) -> u32 {
        self.view.size
    }

    /// The fraction of the light that reaches world point `p` on a surface with unit geometric normal `n`, where
    /// `n_dot_l` is `n . l` for this light: 1 lit, 0 in shadow. Points outside the map are lit.
    #[inline(always)]
    pub fn light_reaching(&self, p: Vec3, n: Vec3, n_dot_l: f32) -> f32 {
        let texel = self.view.texel_at(p);
        let (in_front, at) = self.lookup(p, n, n_dot_l, texel);
        if !in_front {
            return 1.0;
        }
        let lit = match self.pcf_radius {
            0 => self.lit_taps::<0>(at),
            1 => self.lit_taps::<1>(at),
            2 => self.lit_taps::<2>(at),
            r => self.lit_taps_any(r as i32, at),
        };
        self.share(lit)
    }

    /// [`Self::light_reaching`] for the first `len` lanes of a batch, into `share`: the same values, bit for bit.
    /// The projection into the map runs lane-wise ([`crate::pipeline::columns`]); only the taps read the map fragment by
    /// fragment.
    pub(crate) fn light_reaching_lanes(
        &self,
        p: &Column3,
        n: &Column3,
        n_dot_l: &Column,
        len: usize,
        share: &mut Column,
    ) {
        let texel = match self.view.texel {
            TexelSize::Constant(t) => Column::splat(t),
            TexelSize::Perspective { eye, per_distance } => {
                // `texel_at`, lane by lane: `|p - eye|`, which is `|eye - p|` bit for bit (squares lose the sign).
                let d = Column3::toward(eye, p, len);
                let mut length = Column::ZERO;
                d.dot(&d, &mut length, len);
                columns::sqrt_lanes(&mut length, len);
                length.map(|l| per_distance * l)
            }
        };
        let (mut tx, mut ty, mut z) = ([0i32; BATCH_SIZE], [0i32; BATCH_SIZE], Column::ZERO);
        let mut face = [0usize; BATCH_SIZE];
        let mut in_front = [false; BATCH_SIZE];
        // One decision per batch: an orthographic map (a directional light's) needs no division, a square one no
        // choice of face. The loops are written out: a helper returning the columns made the batch 7% slower
        // (copies of the columns).
        match &self.view.projection {
            Projection::Square(m) if m.is_affine() => {
                for i in 0..lanes(len) {
                    (in_front[i], _, tx[i], ty[i], z[i]) =
                        self.project::<true>(p.get(i), n.get(i), n_dot_l[i], texel[i], |_| (0, m));
                }
            }
            Projection::Square(m) => {
                for i in 0..lanes(len) {
                    (in_front[i], _, tx[i], ty[i], z[i]) =
                        self.project::<false>(p.get(i), n.get(i), n_dot_l[i], texel[i], |_| (0, m));
                }
            }
            Projection::Cube(cube) => {
                for i in 0..lanes(len) {
                    (in_front[i], face[i], tx[i], ty[i], z[i]) =
                        self.project::<false>(p.get(i), n.get(i), n_dot_l[i], texel[i], |q| cube.face(q));
                }
            }
        }
        // The radius is chosen once for the batch, not per lane, and so is whether faces differ: a square map's
        // lookups all read face 0, a constant its reads are then worked out with (1.4% more instructions in a
        // frame of `assets/scenes/spot_sun.toml` with the face read from its column).
        let cube = matches!(self.view.projection, Projection::Cube(_));
        macro_rules! count {
            ($lit:expr) => {
                if cube {
                    for i in 0..len {
                        let at = Tap { face: face[i], tx: tx[i], ty: ty[i], z: z[i] };
                        share[i] = if in_front[i] { self.share($lit(at)) } else { 1.0 };
                    }
                } else {
                    for i in 0..len {
                        let at = Tap { face: 0, tx: tx[i], ty: ty[i], z: z[i] };
                        share[i] = if in_front[i] { self.share($lit(at)) } else { 1.0 };
                    }
                }
            };
        }
        match self.pcf_radius {
            0 => count!(|at| self.lit_taps::<0>(at)),
            1 => count!(|at| self.lit_taps::<1>(at)),
            2 => count!(|at| self.lit_taps::<2>(at)),
            r => count!(|at| self.lit_taps_any(r as i32, at)),
        }
    }

    /// Where the lookup of `p` (unit geometric normal `n`, `n . l` = `n_dot_l`, a map texel `texel` world units
    /// wide there) reads the map: whether it is in front of the light, and the face, texel and depth to compare.
    #[inline(always)]
    fn lookup(&self, p: Vec3, n: Vec3, n_dot_l: f32, texel: f32) -> (bool, Tap) {
        let (in_front, face, tx, ty, z) = match &self.view.projection {
            Projection::Square(m) if m.is_affine() => self.project::<true>(p, n, n_dot_l, texel, |_| (0, m)),
            Projection::Square(m) => self.project::<false>(p, n, n_dot_l, texel, |_| (0, m)),
            Projection::Cube(cube) => self.project::<false>(p, n, n_dot_l, texel, |q| cube.face(q)),
        };
        (in_front, Tap { face, tx, ty, z })
    }

    /// [`Self::lookup`] with the face and its projection that `pick` gives for the moved point: whether it is in
    /// front of the light, the face, the texel `(tx, ty)` and the depth `z` to compare.
    ///
    /// `AFFINE` (only for an orthographic projection, a directional light's) skips the perspective division: `w`
    /// is then exactly 1 for a finite point (`0 * x + 0 * y + 0 * z + 1`), so dividing by it changes nothing, and a
    /// point with a non-finite coordinate has `w` NaN and is not in front either way.
    #[inline(always)]
    fn project<'m, const AFFINE: bool>(
        &self,
        p: Vec3,
        n: Vec3,
        n_dot_l: f32,
        texel: f32,
        pick: impl Fn(Vec3) -> (usize, &'m Mat4),
    ) -> (bool, usize, i32, i32, f32) {
        let b = &self.bias;
        // A PCF tap r texels away meets the receiver's own depth up to r texels' slope nearer the light: the
        // offset grows with the filter's reach.
        let reach = (1 + self.pcf_radius) as f32;
        let slope = 1.0 - float::clamp(n_dot_l, 0.0, 1.0);
        let offset = texel * (b.normal_offset + b.slope_offset * slope) * reach;
        let moved = p + n * offset;
        let (face, clip_from_world) = pick(moved);
        let clip = clip_from_world.project_point(moved);
        let in_front = clip.w > 0.0; // false for NaN too
        let inv_w = if AFFINE { 1.0 } else { 1.0 / clip.w };
        let half = self.view.size as f32 * 0.5;
        // NDC to texels as the pipeline's viewport maps them: x right, y down, pixel centres at +0.5.
        // Clamped far outside any map (so that `tx + r` cannot overflow), and widened to SIMD in a loop of lanes.
        let tx = float::floor_to_i32_clamped((clip.x * inv_w + 1.0) * half);
        let ty = float::floor_to_i32_clamped((1.0 - clip.y * inv_w) * half);
        // A point beyond the map's far plane compares as on it: lit wherever nothing was drawn.
        let z = float::min(clip.z * inv_w, 1.0) - b.depth;
        (in_front, face, tx, ty, z)
    }

    /// The share of the light that `lit` of the filter's taps let through.
    #[inline(always)]
    fn share(&self, lit: u32) -> f32 {
        let r = self.pcf_radius;
        let taps = (2 * r + 1) * (2 * r + 1);
        if lit == taps { 1.0 } else { lit as f32 / taps as f32 }
    }

    /// How many of the `(2R + 1)^2` texels around the tap's are at or beyond its depth (texels outside its face
    /// count as lit). A window wholly inside the face, nearly every lookup, reads its rows as slices with no test
    /// per texel; the loops have constant bounds and unroll.
    #[inline(always)]
    fn lit_taps<const R: i32>(&self, at: Tap) -> u32 {
        if let Some(lit) = self.decided(at) {
            return lit;
        }
        let Tap { tx, ty, z, .. } = at;
        let size = self.view.size as i32;
        let inside = tx >= R && ty >= R && tx < size - R && ty < size - R;
        if !inside {
            return self.count_taps(R, at);
        }
        let depth = self.face_depth(at.face);
        let side = (2 * R + 1) as usize;
        let first = ((ty - R) * size + tx - R) as usize;
        let mut lit = 0u32;
        // Rows counted with a constant bound (not an inclusive range of rows), so the loop unrolls.
        for row in 0..side {
            let start = first + row * size as usize;
            // In the face (checked above); `get` keeps the lookup panic-free regardless.
            if let Some(row) = depth.get(start..start + side) {
                for &stored in row {
                    lit += u32::from(z <= stored);
                }
            }
        }
        lit
    }

    /// [`Self::lit_taps`] for any radius and any window, texel by texel.
    fn lit_taps_any(&self, r: i32, at: Tap) -> u32 {
        if let Some(lit) = self.decided(at) {
            return lit;
        }
        self.count_taps(r, at)
    }

    /// What the window's depth range alone tells of [`Self::lit_taps`], if the map has ranges.
    #[inline(always)]
    fn decided(&self, at: Tap) -> Option<u32> {
        let side = 2 * self.pcf_radius + 1;
        self.windows?.decided(at.face, at.tx, at.ty, at.z, side * side)
    }

    /// [`Self::lit_taps_any`] without the ranges: every texel of the window read.
    fn count_taps(&self, r: i32, at: Tap) -> u32 {
        let Tap { tx, ty, z, .. } = at;
        let depth = self.face_depth(at.face);
        let size = self.view.size as i32;
        let mut lit = 0u32;
        for y in ty - r..=ty + r {
            for x in tx - r..=tx + r {
                let inside = x >= 0 && y >= 0 && x < size && y < size;
                let stored = if inside { depth.get((y * size + x) as usize).copied().unwrap_or(1.0) } else { 1.0 };
                lit += u32::from(!inside || z <= stored);
            }
        }
        lit
    }

    /// The depths of face `face` (all of a square map's).
    #[inline(always)]
    fn face_depth(&self, face: usize) -> &'a [f32] {
        let texels = self.view.size as usize * self.view.size as usize;
        self.depth.get(face * texels..(face + 1) * texels).unwrap_or(&[])
    }
}

/// Where one lookup reads a shadow map.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Tap {
    /// The face (0 for a square map).
    face: usize,
    /// The texel's column in its face.
    tx: i32,
    /// The texel's row in its face.
    ty: i32,
    /// The depth the texels are compared with.
    z: f32,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The view of a `size x size` map of the unit sphere from a light straight above it.
    fn overhead_view(size: u32) -> ShadowView {
        let bounds = BoundingSphere { centre: Vec3::ZERO, radius: 1.0 };
        ShadowView::fit(LightKind::Directional { to_light: Vec3::Y }, bounds, size).unwrap()
    }

    /// The unrolled windows count exactly what the texel-by-texel loop counts, inside the map and across its
    /// edges and corners.
    #[test]
    fn unrolled_pcf_windows_count_as_the_general_loop() {
        const SIZE: u32 = 9;
        let view = overhead_view(SIZE);
        // Depths in a scrambled order so that every window sees a different mix.
        let depth: [f32; (SIZE * SIZE) as usize] = core::array::from_fn(|i| ((i * 37) % 81) as f32 / 81.0);
        for radius in 0..=3 {
            let map = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, radius).unwrap();
            for ty in -3..SIZE as i32 + 3 {
                for tx in -3..SIZE as i32 + 3 {
                    for z in [0.0, 0.3, 0.5, 0.99] {
                        let at = Tap { face: 0, tx, ty, z };
                        let expected = map.lit_taps_any(radius as i32, at);
                        let unrolled = match radius {
                            0 => map.lit_taps::<0>(at),
                            1 => map.lit_taps::<1>(at),
                            2 => map.lit_taps::<2>(at),
                            _ => expected,
                        };
                        assert_eq!(unrolled, expected, "radius {radius} at ({tx}, {ty}), z {z}");
                    }
                }
            }
        }
    }

    /// With window ranges, every window (inside the map, across its edges, centred outside it) counts what reading
    /// its texels counts, for depths NaN, signed zero and infinite too, and the ranges decide most lookups.
    #[test]
    fn window_ranges_count_what_the_texels_count() {
        const SIZE: u32 = 9;
        let view = overhead_view(SIZE);
        // A smooth slope (lit surfaces), a step (a shadow's edge), a NaN and a -0.0.
        let depth: [f32; (SIZE * SIZE) as usize] = core::array::from_fn(|i| match i {
            70 => f32::NAN,
            13 => -0.0,
            _ if i % 9 < 5 => 0.3 + i as f32 / 400.0,
            _ => 0.8,
        });
        let zs = [f32::NEG_INFINITY, -0.0, 0.0, 0.2, 0.3 + 20.0 / 400.0, 0.5, 0.8, 0.9, 1.0, f32::INFINITY, f32::NAN];
        for radius in 0..=3u32 {
            let (mut near, mut far) = ([0.0; (SIZE * SIZE) as usize], [0.0; (SIZE * SIZE) as usize]);
            super::window_ranges_band(&depth, SIZE, radius, 0..SIZE, &mut near, &mut far).unwrap();
            let plain = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, radius).unwrap();
            let windows = WindowRanges::new(&near, &far, SIZE, radius).unwrap();
            let ranged = plain.with_windows(windows).unwrap();
            let (mut all, mut none) = (0, 0);
            for ty in -4..SIZE as i32 + 4 {
                for tx in -4..SIZE as i32 + 4 {
                    for z in zs {
                        let at = Tap { face: 0, tx, ty, z };
                        let expected = plain.count_taps(radius as i32, at);
                        let counted = match radius {
                            0 => ranged.lit_taps::<0>(at),
                            1 => ranged.lit_taps::<1>(at),
                            2 => ranged.lit_taps::<2>(at),
                            r => ranged.lit_taps_any(r as i32, at),
                        };
                        assert_eq!(counted, expected, "radius {radius} at ({tx}, {ty}), z {z}");
                        match ranged.decided(at) {
                            Some(0) => none += 1,
                            Some(_) => all += 1,
                            None => {}
                        }
                    }
                }
            }
            assert!(all > 0 && none > 0, "radius {radius}: {all} decided lit, {none} decided dark");
        }
        let (near, far) = ([0.0; (SIZE * SIZE) as usize], [0.0; (SIZE * SIZE) as usize]);
        let plain = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, 1).unwrap();
        let other_radius = WindowRanges::new(&near, &far, SIZE, 2).unwrap();
        assert_eq!(plain.with_windows(other_radius).err(), Some(ShadowError::Windows { size: SIZE, radius: 1 }));
    }

    /// An orthographic map's lookup without the perspective division finds the same texel, depth and facing as
    /// with it, at points across and beyond the map, huge, tiny, infinite and NaN; a perspective map is not
    /// affine.
    #[test]
    fn orthographic_lookups_need_no_division() {
        let bounds = BoundingSphere { centre: Vec3::new(0.2, -0.1, 0.3), radius: 1.5 };
        let depth = [0.5; 64 * 64];
        let to_light = Vec3::new(-0.4, 0.8, 0.45).normalize_or_zero();
        let view = ShadowView::fit(LightKind::Directional { to_light }, bounds, 64).unwrap();
        let map = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, 1).unwrap();
        let Projection::Square(m) = &view.projection else { panic!("a directional light's map is square") };
        assert!(m.is_affine());
        let point = ShadowView::fit(LightKind::point(Vec3::new(0.0, 5.0, 0.0)), bounds, 64).unwrap();
        assert!(matches!(point.projection, Projection::Square(m) if !m.is_affine()));
        let values = [0.0, -0.0, 0.37, -1.9, 2.5, 1e-30, -3e7, 1e30, f32::INFINITY, f32::NEG_INFINITY, f32::NAN];
        let bits = |(f, face, x, y, z): (bool, usize, i32, i32, f32)| (f, face, x, y, z.to_bits());
        for (i, &a) in values.iter().enumerate() {
            for &b in &values {
                let p = Vec3::new(a, b, values[(i * 7 + 3) % values.len()]);
                let n = Vec3::new(0.0, 1.0, 0.0);
                for n_dot_l in [-1.0, 0.0, 0.3, 1.0] {
                    let texel = view.texel_at(p);
                    let divided = map.project::<false>(p, n, n_dot_l, texel, |_| (0, m));
                    let (in_front, ..) = divided;
                    if in_front {
                        assert_eq!(bits(map.project::<true>(p, n, n_dot_l, texel, |_| (0, m))), bits(divided), "{p:?}");
                    } else {
                        assert!(!map.project::<true>(p, n, n_dot_l, texel, |_| (0, m)).0, "{p:?}");
                    }
                }
            }
        }
    }

    /// The lane-wise lookup gives bit for bit the scalar lookup's share, for directional and point lights (outside
    /// the bounds, and inside them with a cube map), every filter radius, maps with and without window ranges,
    /// points in front of and behind the light, and lanes past the batch's length left alone.
    #[test]
    #[allow(clippy::needless_range_loop)] // lanes: one index into every column
    fn lanes_look_up_what_the_scalar_lookup_does() {
        const SIZE: u32 = 16;
        const CUBE: usize = (6 * SIZE * SIZE) as usize;
        let bounds = BoundingSphere { centre: Vec3::ZERO, radius: 1.0 };
        let all: [f32; CUBE] = core::array::from_fn(|i| 0.3 + ((i * 37) % 97) as f32 / 200.0);
        let kinds = [
            LightKind::Directional { to_light: Vec3::new(0.3, 0.9, 0.2).normalize_or_zero() },
            LightKind::point(Vec3::new(0.5, 4.0, 1.0)),
            LightKind::point(Vec3::new(0.1, -0.2, 0.15)),
        ];
        let (mut p, mut n, mut n_dot_l) = (Column3::ZERO, Column3::ZERO, Column::ZERO);
        for i in 0..BATCH_SIZE {
            let t = i as f32 / BATCH_SIZE as f32;
            // Across the map, and a few points behind the point light.
            let y = if i % 7 == 6 { 6.0 } else { t - 0.5 };
            p.set(i, Vec3::new(1.6 * t - 0.8, y, 0.7 - 1.3 * t));
            n.set(i, Vec3::new(t - 0.5, 1.0, 0.25).normalize_or_zero());
            n_dot_l[i] = 1.2 * t - 0.1;
        }
        // Shadowed, lit and partly lit lanes all occur.
        let (mut dark, mut lit, mut partly) = (false, false, false);
        let mut faces = [false; 6];
        for kind in kinds {
            let view = ShadowView::fit(kind, bounds, SIZE).unwrap();
            let texels = (view.rows() * SIZE) as usize;
            let depth = &all[..texels];
            for radius in 0..=3 {
                let plain = ShadowMap::new(view, depth, ShadowBias::DEFAULT, radius).unwrap();
                let (mut near, mut far) = ([0.0; CUBE], [0.0; CUBE]);
                let (near, far) = (&mut near[..texels], &mut far[..texels]);
                super::window_ranges_band(depth, SIZE, radius, 0..view.rows(), near, far).unwrap();
                let ranged = plain.with_windows(WindowRanges::new(near, far, SIZE, radius).unwrap()).unwrap();
                for (map, ranges) in [(plain, "without"), (ranged, "with")] {
                    let len = BATCH_SIZE - 3;
                    let mut share = Column::splat(-1.0);
                    map.light_reaching_lanes(&p, &n, &n_dot_l, len, &mut share);
                    for i in 0..len {
                        let expected = plain.light_reaching(p.get(i), n.get(i), n_dot_l[i]);
                        let scalar = map.light_reaching(p.get(i), n.get(i), n_dot_l[i]);
                        assert_eq!(
                            scalar.to_bits(),
                            expected.to_bits(),
                            "{kind:?}, radius {radius}, lane {i}, {ranges} ranges"
                        );
                        assert_eq!(
                            share[i].to_bits(),
                            expected.to_bits(),
                            "{kind:?}, radius {radius}, lane {i}, {ranges} ranges"
                        );
                        dark |= share[i] == 0.0;
                        lit |= share[i] == 1.0;
                        partly |= share[i] > 0.0 && share[i] < 1.0;
                        faces[view.face_of(p.get(i)) as usize] |= view.faces() == 6;
                    }
                    assert!(share[len..].iter().all(|&s| s == -1.0), "lanes past the length are left alone");
                }
            }
        }
        assert!(dark && lit && partly, "dark {dark}, lit {lit}, partly lit {partly}");
        assert!(faces.iter().filter(|&&f| f).count() >= 3, "the cube's lookups reach faces {faces:?}");
    }

    /// A cube map's view: six faces, `6 * size` rows, each face's projection a perspective one; too small a face
    /// and too wide a filter are refused.
    #[test]
    fn point_lights_inside_the_bounds_get_a_cube() {
        let bounds = BoundingSphere { centre: Vec3::ZERO, radius: 2.0 };
        let inside = LightKind::point(Vec3::new(0.5, 1.0, -0.5));
        let view = ShadowView::fit(inside, bounds, 32).unwrap();
        assert_eq!((view.faces(), view.rows(), view.size()), (6, 192, 32));
        assert!((0..6).all(|f| view.clip_from_world(f).is_some_and(|m| !m.is_affine())));
        assert_eq!(view.clip_from_world(6), None);
        let outside = ShadowView::fit(LightKind::point(Vec3::new(0.0, 5.0, 0.0)), bounds, 32).unwrap();
        assert_eq!((outside.faces(), outside.rows()), (1, 32));
        assert_eq!(ShadowView::fit(inside, bounds, 2 * CUBE_BORDER), Err(ShadowError::Size(2 * CUBE_BORDER)));
        assert!(ShadowView::fit(inside, bounds, 2 * CUBE_BORDER + 1).is_ok());
        let depth = [1.0; 6 * 32 * 32];
        assert!(ShadowMap::new(view, &depth, ShadowBias::DEFAULT, CUBE_BORDER - 1).is_ok());
        let wide = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, CUBE_BORDER).err();
        assert_eq!(wide, Some(ShadowError::CubeFilter(CUBE_BORDER)));
        let short = ShadowMap::new(view, &depth[..32 * 32], ShadowBias::DEFAULT, 1).err();
        assert_eq!(short, Some(ShadowError::Buffer { expected: 6 * 32 * 32, actual: 32 * 32 }));
        let nan = LightKind::point(Vec3::new(f32::NAN, 0.0, 0.0));
        assert_eq!(ShadowView::fit(nan, bounds, 32), Err(ShadowError::Camera(CameraError::NotFinite)));
    }
}
