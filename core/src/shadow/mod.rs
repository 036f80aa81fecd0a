//! Shadow maps: a depth pass from a light into a buffer the caller owns, and the lookup that tells how much of a
//! point the light reaches.
//!
//! The lookup offsets the point along its surface normal before projecting it (normal-offset shadows: Holbein,
//! "Normal Offset Shadows", GDC 2011), by a number of shadow-map texels that grows as the light grazes the surface,
//! and then compares depths with a small constant bias. The offset removes shadow acne (a surface shadowing
//! itself because one texel spans a range of depths) without the large depth bias that detaches shadows from
//! their casters (peter-panning). `core/tests/shadows.rs` holds both limits.

use core::ops::Range;

use crate::camera::{CameraError, look_at, orthographic, perspective};
use crate::math::{Mat4, Vec3, Vec4, float};
use crate::mesh::{Attributes, Mesh};
use crate::pipeline::{BATCH_SIZE, Cull, DrawState, DrawStats, Fragment, Shader, Slopes, draw, lanes};
use crate::shading::LightKind;
use crate::shading::columns::{self, Column, Column3};
use crate::target::{MAX_DIMENSION, NoColor, Target};

mod windows;

pub use windows::{WindowRanges, window_ranges_band};

/// Why a shadow map could not be set up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadowError {
    /// A point light inside (or on) the bounding sphere of what it lights: one map cannot see every direction
    /// (that needs a cube of six).
    LightInsideBounds,
    /// The bounds are empty (radius not positive) or not finite.
    Bounds,
    /// The light's camera could not be built.
    Camera(CameraError),
    /// The map's side is 0 or above [`crate::target::MAX_DIMENSION`].
    Size(u32),
    /// A band's rows are empty or leave the map.
    Rows {
        /// The band's first row.
        start: u32,
        /// The row after its last.
        end: u32,
        /// The map's side.
        size: u32,
    },
    /// Window ranges ([`WindowRanges`]) made for another map size or filter radius than the map's.
    Windows {
        /// The map's side.
        size: u32,
        /// The map's filter radius.
        radius: u32,
    },
    /// The depth buffer does not hold `size * size` values (`size * rows.len()` for a band).
    Buffer {
        /// `size * size`, or `size * rows.len()`.
        expected: usize,
        /// Values given.
        actual: usize,
    },
}

impl core::fmt::Display for ShadowError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::LightInsideBounds => {
                f.write_str("a point light inside the scene's bounds cannot cast shadows (that needs a cube map)")
            }
            Self::Bounds => f.write_str("the shadow bounds are empty or not finite"),
            Self::Camera(e) => write!(f, "the light's camera: {e}"),
            Self::Size(s) => write!(f, "a shadow map of {s}x{s} texels is not supported"),
            Self::Rows { start, end, size } => {
                write!(f, "rows {start}..{end} are not a band of a map {size} texels high")
            }
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

/// A sphere that holds everything a shadow map must see.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Its centre, in world space.
    pub centre: Vec3,
    /// Its radius (positive).
    pub radius: f32,
}

/// World size of one shadow-map texel.
#[derive(Clone, Copy, Debug, PartialEq)]
enum TexelSize {
    /// The same everywhere (orthographic).
    Constant(f32),
    /// Proportional to the distance from the light (perspective): `per_distance * |p - eye|`.
    Perspective { eye: Vec3, per_distance: f32 },
}

/// A light's camera for its shadow map: what it projects, and how large a texel is in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowView {
    /// World space to the light's clip space.
    pub clip_from_world: Mat4,
    texel: TexelSize,
    size: u32,
}

impl ShadowView {
    /// The view of a `size x size` map fitted to `bounds` as seen from a light: an orthographic box around the
    /// sphere for a directional light, and for a point light the narrowest perspective cone that holds it.
    ///
    /// # Errors
    /// [`ShadowError::Bounds`] for empty or non-finite bounds, [`ShadowError::LightInsideBounds`] for a point light
    /// not outside the sphere, [`ShadowError::Camera`] if the light's direction or position is not usable.
    pub fn fit(kind: LightKind, bounds: Bounds, size: u32) -> Result<Self, ShadowError> {
        let Bounds { centre, radius: r } = bounds;
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
                Ok(Self { clip_from_world: projection * view, texel, size })
            }
            LightKind::Point { position } => {
                let d = (centre - position).length();
                let outside = d > r * 1.001; // false for NaN too
                if !outside {
                    return Err(ShadowError::LightInsideBounds);
                }
                let half = float::asin(r / d);
                let view = look_at(position, centre, Vec3::Y).map_err(ShadowError::Camera)?;
                let near = float::max(d - r, d * 1e-3);
                let projection = perspective(2.0 * half, 1.0, near, d + r).map_err(ShadowError::Camera)?;
                let per_distance = 2.0 * float::tan(half) / size_f;
                let texel = TexelSize::Perspective { eye: position, per_distance };
                Ok(Self { clip_from_world: projection * view, texel, size })
            }
        }
    }

    /// Side of the map in texels.
    pub fn size(&self) -> u32 {
        self.size
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

/// The depth-only shader of the shadow pass: positions into the light's clip space, nothing else.
#[derive(Clone, Copy, Debug)]
struct CasterShader {
    clip_from_object: Mat4,
}

impl Shader for CasterShader {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const FRAGMENT_STAGE: bool = false;

    #[inline(always)]
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }
    #[inline(always)]
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    #[inline(always)]
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    #[inline(always)]
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ZERO
    }
}

/// The depth pass of a shadow map: draws `mesh` (placed by `model`) into `depth`, the map's `size x size`
/// buffer, as the light sees it. Both faces cast shadows. Clear the buffer to 1.0 first
/// ([`clear_shadow_depth`]).
///
/// # Errors
/// [`ShadowError::Buffer`] when `depth` does not hold `size * size` values.
pub fn draw_shadow_caster(
    view: &ShadowView,
    depth: &mut [f32],
    mesh: &Mesh<'_>,
    model: &Mat4,
) -> Result<DrawStats, ShadowError> {
    draw_shadow_caster_band(view, depth, 0..view.size, mesh, model)
}

/// [`draw_shadow_caster`] into rows `rows` of the map only: `depth` holds `size * rows.len()` values, row
/// `rows.start` first. Bands drawn separately (on separate threads, say) make exactly the map drawn whole.
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
    let size = view.size;
    if rows.is_empty() || rows.end > size {
        return Err(ShadowError::Rows { start: rows.start, end: rows.end, size });
    }
    let expected = size as usize * rows.len();
    let actual = depth.len();
    let Ok(mut target) = Target::band(NoColor, depth, size, size, rows) else {
        return Err(ShadowError::Buffer { expected, actual });
    };
    let shader = CasterShader { clip_from_object: view.clip_from_world * *model };
    let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
    // The caster reads positions only and the state is valid, so the pipeline has nothing to refuse.
    Ok(draw(&mut target, mesh, &shader, &state).unwrap_or_default())
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
    /// [`ShadowError::Buffer`] when `depth` does not hold `size * size` values.
    pub fn new(view: ShadowView, depth: &'a [f32], bias: ShadowBias, pcf_radius: u32) -> Result<Self, ShadowError> {
        let expected = view.size as usize * view.size as usize;
        if depth.len() != expected {
            return Err(ShadowError::Buffer { expected, actual: depth.len() });
        }
        Ok(Self { view, depth, bias, pcf_radius, windows: None })
    }

    /// The same map, with the depth ranges of its filter's windows ([`window_ranges_band`], computed from
    /// this map's depths): lookups that the range decides read one value instead of the window. The light reaching
    /// any point is the same, bit for bit.
    ///
    /// # Errors
    /// [`ShadowError::Windows`] when the ranges are for another map size or filter radius.
    pub fn with_windows(self, windows: WindowRanges<'a>) -> Result<Self, ShadowError> {
        if windows.size() != self.view.size || windows.radius() != self.pcf_radius {
            return Err(ShadowError::Windows { size: self.view.size, radius: self.pcf_radius });
        }
        Ok(Self { windows: Some(windows), ..self })
    }

    /// The `r` of `(2r + 1)^2` percentage-closer samples.
    pub fn pcf_radius(&self) -> u32 {
        self.pcf_radius
    }

    /// Side of the map in texels.
    pub fn size(&self) -> u32 {
        self.view.size
    }

    /// The fraction of the light that reaches world point `p` on a surface with unit geometric normal `n`, where
    /// `n_dot_l` is `n . l` for this light: 1 lit, 0 in shadow. Points outside the map are lit.
    #[inline(always)]
    pub fn light_reaching(&self, p: Vec3, n: Vec3, n_dot_l: f32) -> f32 {
        let texel = self.view.texel_at(p);
        let (in_front, tx, ty, z) = if self.affine() {
            self.lookup::<true>(p, n, n_dot_l, texel)
        } else {
            self.lookup::<false>(p, n, n_dot_l, texel)
        };
        if !in_front {
            return 1.0;
        }
        let lit = match self.pcf_radius {
            0 => self.lit_taps::<0>(tx, ty, z),
            1 => self.lit_taps::<1>(tx, ty, z),
            2 => self.lit_taps::<2>(tx, ty, z),
            r => self.lit_taps_any(r as i32, tx, ty, z),
        };
        self.share(lit)
    }

    /// [`Self::light_reaching`] for the first `len` lanes of a batch, into `share`: the same values, bit for bit.
    /// The projection into the map runs lane-wise ([`crate::shading::columns`]); only the taps read the map fragment by
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
            TexelSize::Constant(t) => [t; BATCH_SIZE],
            TexelSize::Perspective { eye, per_distance } => {
                // `texel_at`, lane by lane: `|p - eye|`, which is `|eye - p|` bit for bit (squares lose the sign).
                let d = Column3::toward(eye, p, len);
                let mut length = [0.0; BATCH_SIZE];
                d.dot(&d, &mut length, len);
                columns::sqrt_lanes(&mut length, len);
                length.map(|l| per_distance * l)
            }
        };
        let (mut tx, mut ty, mut z) = ([0i32; BATCH_SIZE], [0i32; BATCH_SIZE], [0.0; BATCH_SIZE]);
        let mut in_front = [false; BATCH_SIZE];
        // One decision per batch: an orthographic map (a directional light's) needs no division. The two loops
        // are written out: a helper returning the four columns made the batch 7% slower (copies of the columns).
        if self.affine() {
            for i in 0..lanes(len) {
                (in_front[i], tx[i], ty[i], z[i]) = self.lookup::<true>(p.get(i), n.get(i), n_dot_l[i], texel[i]);
            }
        } else {
            for i in 0..lanes(len) {
                (in_front[i], tx[i], ty[i], z[i]) = self.lookup::<false>(p.get(i), n.get(i), n_dot_l[i], texel[i]);
            }
        }
        // The radius is chosen once for the batch, not per lane.
        macro_rules! count {
            ($lit:expr) => {
                for i in 0..len {
                    share[i] = if in_front[i] { self.share($lit(tx[i], ty[i], z[i])) } else { 1.0 };
                }
            };
        }
        match self.pcf_radius {
            0 => count!(|x, y, z| self.lit_taps::<0>(x, y, z)),
            1 => count!(|x, y, z| self.lit_taps::<1>(x, y, z)),
            2 => count!(|x, y, z| self.lit_taps::<2>(x, y, z)),
            r => count!(|x, y, z| self.lit_taps_any(r as i32, x, y, z)),
        }
    }

    /// True when the light's projection is orthographic (a directional light's): every finite point has `w = 1`.
    #[inline(always)]
    fn affine(&self) -> bool {
        self.view.clip_from_world.is_affine()
    }

    /// Where the lookup of `p` (unit geometric normal `n`, `n . l` = `n_dot_l`, a map texel `texel` world units
    /// wide there) reads the map: whether it is in front of the light, the texel `(tx, ty)` and the depth `z` to
    /// compare.
    ///
    /// `AFFINE` (only for a map whose [`Self::affine`] holds) skips the perspective division: `w` is then exactly 1
    /// for a finite point (`0 * x + 0 * y + 0 * z + 1`), so dividing by it changes nothing, and a point with a
    /// non-finite coordinate has `w` NaN and is not in front either way.
    #[inline(always)]
    fn lookup<const AFFINE: bool>(&self, p: Vec3, n: Vec3, n_dot_l: f32, texel: f32) -> (bool, i32, i32, f32) {
        let b = &self.bias;
        // A PCF tap r texels away meets the receiver's own depth up to r texels' slope nearer the light: the
        // offset grows with the filter's reach.
        let reach = (1 + self.pcf_radius) as f32;
        let slope = 1.0 - float::clamp(n_dot_l, 0.0, 1.0);
        let offset = texel * (b.normal_offset + b.slope_offset * slope) * reach;
        let clip = self.view.clip_from_world.project_point(p + n * offset);
        let in_front = clip.w > 0.0; // false for NaN too
        let inv_w = if AFFINE { 1.0 } else { 1.0 / clip.w };
        let half = self.view.size as f32 * 0.5;
        // NDC to texels as the pipeline's viewport maps them: x right, y down, pixel centres at +0.5.
        // Clamped far outside any map (so that `tx + r` cannot overflow), and widened to SIMD in a loop of lanes.
        let tx = float::floor_to_i32_clamped((clip.x * inv_w + 1.0) * half);
        let ty = float::floor_to_i32_clamped((1.0 - clip.y * inv_w) * half);
        // A point beyond the map's far plane compares as on it: lit wherever nothing was drawn.
        let z = float::min(clip.z * inv_w, 1.0) - b.depth;
        (in_front, tx, ty, z)
    }

    /// The share of the light that `lit` of the filter's taps let through.
    #[inline(always)]
    fn share(&self, lit: u32) -> f32 {
        let r = self.pcf_radius;
        let taps = (2 * r + 1) * (2 * r + 1);
        if lit == taps { 1.0 } else { lit as f32 / taps as f32 }
    }

    /// How many of the `(2R + 1)^2` texels around `(tx, ty)` are at or beyond depth `z` (texels outside the map
    /// count as lit). A window wholly inside the map, nearly every lookup, reads its rows as slices with no test
    /// per texel; the loops have constant bounds and unroll.
    #[inline(always)]
    fn lit_taps<const R: i32>(&self, tx: i32, ty: i32, z: f32) -> u32 {
        if let Some(lit) = self.decided(tx, ty, z) {
            return lit;
        }
        let size = self.view.size as i32;
        let inside = tx >= R && ty >= R && tx < size - R && ty < size - R;
        if !inside {
            return self.count_taps(R, tx, ty, z);
        }
        let side = (2 * R + 1) as usize;
        let first = ((ty - R) * size + tx - R) as usize;
        let mut lit = 0u32;
        // Rows counted with a constant bound (not an inclusive range of rows), so the loop unrolls.
        for row in 0..side {
            let start = first + row * size as usize;
            // In the map (checked above); `get` keeps the lookup panic-free regardless.
            if let Some(row) = self.depth.get(start..start + side) {
                for &stored in row {
                    lit += u32::from(z <= stored);
                }
            }
        }
        lit
    }

    /// [`Self::lit_taps`] for any radius and any window, texel by texel.
    fn lit_taps_any(&self, r: i32, tx: i32, ty: i32, z: f32) -> u32 {
        if let Some(lit) = self.decided(tx, ty, z) {
            return lit;
        }
        self.count_taps(r, tx, ty, z)
    }

    /// What the window's depth range alone tells of [`Self::lit_taps`], if the map has ranges.
    #[inline(always)]
    fn decided(&self, tx: i32, ty: i32, z: f32) -> Option<u32> {
        let side = 2 * self.pcf_radius + 1;
        self.windows?.decided(tx, ty, z, side * side)
    }

    /// [`Self::lit_taps_any`] without the ranges: every texel of the window read.
    fn count_taps(&self, r: i32, tx: i32, ty: i32, z: f32) -> u32 {
        let size = self.view.size as i32;
        let mut lit = 0u32;
        for y in ty - r..=ty + r {
            for x in tx - r..=tx + r {
                let inside = x >= 0 && y >= 0 && x < size && y < size;
                let stored = if inside { self.depth[(y * size + x) as usize] } else { 1.0 };
                lit += u32::from(!inside || z <= stored);
            }
        }
        lit
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The view of a `size x size` map of the unit sphere from a light straight above it.
    fn overhead_view(size: u32) -> ShadowView {
        let bounds = Bounds { centre: Vec3::ZERO, radius: 1.0 };
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
                        let expected = map.lit_taps_any(radius as i32, tx, ty, z);
                        let unrolled = match radius {
                            0 => map.lit_taps::<0>(tx, ty, z),
                            1 => map.lit_taps::<1>(tx, ty, z),
                            2 => map.lit_taps::<2>(tx, ty, z),
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
                        let expected = plain.count_taps(radius as i32, tx, ty, z);
                        let counted = match radius {
                            0 => ranged.lit_taps::<0>(tx, ty, z),
                            1 => ranged.lit_taps::<1>(tx, ty, z),
                            2 => ranged.lit_taps::<2>(tx, ty, z),
                            r => ranged.lit_taps_any(r as i32, tx, ty, z),
                        };
                        assert_eq!(counted, expected, "radius {radius} at ({tx}, {ty}), z {z}");
                        match ranged.decided(tx, ty, z) {
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
        let bounds = Bounds { centre: Vec3::new(0.2, -0.1, 0.3), radius: 1.5 };
        let depth = [0.5; 64 * 64];
        let to_light = Vec3::new(-0.4, 0.8, 0.45).normalize_or_zero();
        let view = ShadowView::fit(LightKind::Directional { to_light }, bounds, 64).unwrap();
        let map = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, 1).unwrap();
        assert!(map.affine());
        let point = ShadowView::fit(LightKind::Point { position: Vec3::new(0.0, 5.0, 0.0) }, bounds, 64).unwrap();
        assert!(!ShadowMap::new(point, &depth, ShadowBias::DEFAULT, 1).unwrap().affine());
        let values = [0.0, -0.0, 0.37, -1.9, 2.5, 1e-30, -3e7, 1e30, f32::INFINITY, f32::NEG_INFINITY, f32::NAN];
        let bits = |(f, x, y, z): (bool, i32, i32, f32)| (f, x, y, z.to_bits());
        for (i, &a) in values.iter().enumerate() {
            for &b in &values {
                let p = Vec3::new(a, b, values[(i * 7 + 3) % values.len()]);
                let n = Vec3::new(0.0, 1.0, 0.0);
                for n_dot_l in [-1.0, 0.0, 0.3, 1.0] {
                    let texel = view.texel_at(p);
                    let divided = map.lookup::<false>(p, n, n_dot_l, texel);
                    let (in_front, ..) = divided;
                    if in_front {
                        assert_eq!(bits(map.lookup::<true>(p, n, n_dot_l, texel)), bits(divided), "{p:?}");
                    } else {
                        assert!(!map.lookup::<true>(p, n, n_dot_l, texel).0, "{p:?}");
                    }
                }
            }
        }
    }

    /// The lane-wise lookup gives bit for bit the scalar lookup's share, for directional and point lights, every
    /// filter radius, maps with and without window ranges, points in front of and behind the light, and lanes
    /// past the batch's length left alone.
    #[test]
    #[allow(clippy::needless_range_loop)] // lanes: one index into every column
    fn lanes_look_up_what_the_scalar_lookup_does() {
        const SIZE: u32 = 16;
        let bounds = Bounds { centre: Vec3::ZERO, radius: 1.0 };
        let depth: [f32; (SIZE * SIZE) as usize] = core::array::from_fn(|i| 0.3 + ((i * 37) % 97) as f32 / 200.0);
        let kinds = [
            LightKind::Directional { to_light: Vec3::new(0.3, 0.9, 0.2).normalize_or_zero() },
            LightKind::Point { position: Vec3::new(0.5, 4.0, 1.0) },
        ];
        let (mut p, mut n, mut n_dot_l) = (Column3::ZERO, Column3::ZERO, [0.0; BATCH_SIZE]);
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
        for kind in kinds {
            let view = ShadowView::fit(kind, bounds, SIZE).unwrap();
            for radius in 0..=3 {
                let plain = ShadowMap::new(view, &depth, ShadowBias::DEFAULT, radius).unwrap();
                let (mut near, mut far) = ([0.0; (SIZE * SIZE) as usize], [0.0; (SIZE * SIZE) as usize]);
                super::window_ranges_band(&depth, SIZE, radius, 0..SIZE, &mut near, &mut far).unwrap();
                let ranged = plain.with_windows(WindowRanges::new(&near, &far, SIZE, radius).unwrap()).unwrap();
                for (map, ranges) in [(plain, "without"), (ranged, "with")] {
                    let len = BATCH_SIZE - 3;
                    let mut share = [-1.0; BATCH_SIZE];
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
                    }
                    assert!(share[len..].iter().all(|&s| s == -1.0), "lanes past the length are left alone");
                }
            }
        }
        assert!(dark && lit && partly, "dark {dark}, lit {lit}, partly lit {partly}");
    }
}
