//! The `raster` target: a small arbitrary scene through `rastty_core::shading::draw_mesh`, its general path
//! `rastty_core::testing::draw_mesh_general`, `pipeline::draw_wireframe`, shadow-map depth passes
//! (`shadow::draw_shadow_caster`) and depth-only `pipeline::draw` / `testing::draw_unspecialised` passes, with `f32`
//! and `u16` depth, one or four samples per pixel, whole and in bands, checking the core's documented invariants.
//!
//! [`Input`] decodes (with `arbitrary`) into a camera, a model matrix, a frame of 1..=64 x 1..=64 pixels with an
//! optional band of rows, a `DrawState` (sub-pixel bits mostly 0..=8, sometimes above; fixed-point or `f32` edge
//! arithmetic), a few vertices with normals, UVs and colours, `u16`/`u32` indices (some out of range), an optional
//! tiny texture, a shading model, a material, lights and a wireframe style, then ([`ExtrasIn`]) which lights are
//! point lights and which cast shadows, and which maps the tiny texture serves as (diffuse, normal, specular, glow)
//! with tangents computed, missing or given, and an optional environment (the studio, scaled and turned by any
//! values). Every float may be anything: small values, NaN, infinities, huge, tiny
//! or raw bit patterns. [`run`] draws it and panics when an invariant fails; docs/fuzzing.md lists them.

use arbitrary::{Arbitrary, Result, Unstructured};
use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::color::{ShadingSpace, pack_rgb888};
use rastty_core::environment::{
    Environment, Irradiance, Panorama, PanoramaChain, Prefiltering, SplitSum, prepare, studio,
};
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Lanes, Mat4, Vec2, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh, compute_tangents};
use rastty_core::pipeline::{
    Cull, DepthTest, DrawError, DrawState, DrawStats, EdgeArithmetic, Fragment, Interpolation, LineStyle,
    MAX_SUBPIXEL_BITS, Shader, Slopes, Winding, draw, draw_wireframe,
};
use rastty_core::shading::{
    Cone, Falloff, Light, LightKind, Lighting, Material, NormalMap, NormalSpace, Object, ShadingError, ShadingModel,
    Transforms, Variant, draw_mesh,
};
use rastty_core::shadow::{
    ShadowBias, ShadowMap, ShadowView, WindowRanges, clear_shadow_depth, draw_shadow_caster, window_ranges_band,
};
use rastty_core::target::{ColorBuffer, DEPTH_LANES, DepthBuffer, NoColor, Rgb888, Samples, Target};
use rastty_core::testing::{draw_mesh_general, draw_unspecialised};
use rastty_core::texture::{
    Anisotropy, FilterMode, MipContent, MipFilter, Texture, WrapMode, build_mip_levels, mip_chain_texels,
};

/// The filters between levels a textured input picks from.
const MIP_FILTERS: [MipFilter; 7] = [
    MipFilter::Off,
    MipFilter::Nearest,
    MipFilter::Linear,
    MipFilter::Anisotropic(Anisotropy::X2),
    MipFilter::Anisotropic(Anisotropy::X4),
    MipFilter::Anisotropic(Anisotropy::X8),
    MipFilter::Anisotropic(Anisotropy::X16),
];

const MAX_VERTICES: usize = 24;
const MAX_TRIANGLES: usize = 16;
const MAX_LIGHTS: usize = 3;
/// Largest side of a shadow map, in texels.
const MAX_SHADOW_SIZE: u32 = 16;
/// The colour targets are cleared to (its packed form is `0x4080BF`).
const CLEAR: Vec3 = Vec3::new(0.25, 0.5, 0.75);
/// Most pieces a clipped triangle is cut into: a polygon of at most 3 + 6 vertices, fanned (the core's
/// `MAX_CLIPPED - 2`, which is private).
const MAX_PIECES: u64 = 7;

// ---------------------------------------------------------------------------------------------------------------
// Decoding
// ---------------------------------------------------------------------------------------------------------------

/// An `f32` that is mostly a small, "reasonable" value, sometimes a special one, sometimes raw bits.
#[derive(Clone, Copy, Debug)]
struct F(f32);

const SPECIAL: [f32; 24] = [
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    -f32::MIN_POSITIVE,
    1e-45, // the smallest subnormal
    -0.0,
    0.0,
    1.0,
    -1.0,
    0.5,
    f32::EPSILON,
    1e-20,
    1e20,
    -1e20,
    1e38,
    16384.0, // the guard band
    -16384.0,
    16384.5,
    8_388_608.0, // 2^23
    core::f32::consts::PI,
    core::f32::consts::FRAC_PI_2,
];

impl<'a> Arbitrary<'a> for F {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let tag: u8 = u.arbitrary()?;
        Ok(F(match tag % 16 {
            // Small values in 1/256 steps, |x| < 128: most scenes stay visible.
            0..=8 => f32::from(u.arbitrary::<i16>()?) / 256.0,
            // Small integers.
            9..=11 => f32::from(u.arbitrary::<i8>()?),
            12..=13 => SPECIAL[usize::from(u.arbitrary::<u8>()?) % SPECIAL.len()],
            _ => f32::from_bits(u.arbitrary()?),
        }))
    }
}

#[derive(Arbitrary, Clone, Copy, Debug)]
struct V3(F, F, F);

impl V3 {
    fn get(self) -> Vec3 {
        Vec3::new(self.0.0, self.1.0, self.2.0)
    }
}

#[derive(Arbitrary, Clone, Copy, Debug)]
struct V2(F, F);

#[derive(Arbitrary, Debug)]
enum ProjectionIn {
    Perspective { fovy: F, aspect: Option<F>, near: F, far: F },
    Orthographic { left: F, right: F, bottom: F, top: F, near: F, far: F },
}

#[derive(Arbitrary, Debug)]
struct CameraIn {
    eye: V3,
    target: V3,
    up: V3,
    projection: ProjectionIn,
}

#[derive(Arbitrary, Debug)]
enum ModelIn {
    Identity,
    Scale(V3),
    Translate(V3),
    Matrix([[F; 4]; 4]),
}

#[derive(Arbitrary, Debug)]
enum CullIn {
    None,
    Back,
    Front,
}

#[derive(Arbitrary, Debug)]
struct StateIn {
    cull: CullIn,
    clockwise: bool,
    depth_off: bool,
    affine: bool,
    subpixel_bits: u8,
    float_edges: bool,
}

impl StateIn {
    fn get(&self) -> DrawState {
        DrawState {
            cull: match self.cull {
                CullIn::None => Cull::None,
                CullIn::Back => Cull::Back,
                CullIn::Front => Cull::Front,
            },
            front_face: if self.clockwise { Winding::Clockwise } else { Winding::CounterClockwise },
            depth_test: if self.depth_off { DepthTest::Off } else { DepthTest::Less },
            interpolation: if self.affine { Interpolation::Affine } else { Interpolation::PerspectiveCorrect },
            // Mostly valid (0..=8); 0xF0.. gives 9 and values up to 255, which must be refused.
            subpixel_bits: match self.subpixel_bits {
                b @ 0..=0xEF => b % (MAX_SUBPIXEL_BITS + 1),
                0xF0 => MAX_SUBPIXEL_BITS + 1,
                b => b,
            },
            edges: if self.float_edges { EdgeArithmetic::Float } else { EdgeArithmetic::FixedPoint },
        }
    }
}

#[derive(Arbitrary, Debug)]
struct VertexIn {
    position: V3,
    normal: V3,
    uv: V2,
    color: V3,
}

/// An index: mostly in range or one past the end, sometimes any `u16` (mostly out of range).
#[derive(Arbitrary, Clone, Copy, Debug)]
struct IndexIn(u16);

impl IndexIn {
    fn get(self, vertices: usize) -> u16 {
        if self.0 & 0x8000 == 0 { (usize::from(self.0) % (vertices + 1)) as u16 } else { self.0 }
    }
}

#[derive(Arbitrary, Debug)]
enum IndicesIn {
    Sequential,
    U16(Vec<IndexIn>),
    U32(Vec<IndexIn>),
}

#[derive(Arbitrary, Debug)]
struct TextureIn {
    width: u8,
    height: u8,
    texels: Vec<u32>,
    bilinear: bool,
    clamp: bool,
    /// Its levels of detail are built, and read as `mipmaps % 7` says: off, nearest level, blended, anisotropic
    /// up to 2, 4, 8 or 16 probes.
    mipmaps: u8,
}

#[derive(Arbitrary, Debug)]
enum ShadingIn {
    Unlit,
    Flat,
    Gouraud,
    Phong,
    MetallicRoughness,
    Depth { near: F, far: F },
    Normals,
}

#[derive(Arbitrary, Debug)]
enum LightIn {
    /// Through `Light::directional` (normalised), or `Light::point` at the vector for a point light.
    Directional(V3, V3),
    /// Built by hand: any vector, even NaN.
    Raw(V3, V3),
}

/// A shadow map of a light (see [`ExtrasIn::shadowed`]).
#[derive(Arbitrary, Debug)]
struct ShadowIn {
    /// Side `1 + size % 16` texels (of each face of a point light's cube map, when the light is inside the
    /// bounds; a cube of 8 or fewer is refused).
    size: u8,
    /// Percentage-closer radius `pcf % 4` (3 takes the general loop over taps).
    pcf: u8,
    /// The bounds the view is fitted to; `None`: the sphere around the mesh's world positions. Bounds that
    /// `ShadowView::fit` refuses leave the light without shadows (refusing is its contract).
    bounds: Option<(V3, F)>,
    /// Normal offset, slope offset and depth margin; `None`: `ShadowBias::DEFAULT`.
    bias: Option<(F, F, F)>,
    /// The specialised draws' maps carry window ranges (`ShadowMap::with_windows`); the general path's never do.
    windows: bool,
}

/// Tangents for a tangent-space normal map.
#[derive(Arbitrary, Debug)]
enum TangentsIn {
    /// `mesh::compute_tangents` (none when the mesh lacks normals or texture coordinates).
    Computed,
    /// None given.
    Missing,
    /// These, as many as decoded (up to one more than the vertices): any other count than the vertices' is refused.
    Given(Vec<(F, F, F, F)>),
}

/// The tiny texture as a normal map.
#[derive(Arbitrary, Debug)]
enum NormalMapIn {
    Object,
    Tangent(TangentsIn),
}

/// What the unified shading added to the scene: point lights, shadow maps, and the tiny texture as normal,
/// specular and glow map. Decoded after everything else, so that an input from before (whose bytes end earlier,
/// and `arbitrary` then gives zeros) decodes to the same scene with none of it.
#[derive(Arbitrary, Debug)]
struct ExtrasIn {
    /// Bit `i`: light `i` is a point light at its vector.
    point_lights: u8,
    /// Bit `i`: light `i` casts shadows.
    shadowed: u8,
    shadow: ShadowIn,
    /// The tiny texture is not the diffuse map.
    no_diffuse: bool,
    normal_map: Option<NormalMapIn>,
    specular_map: bool,
    glow_map: bool,
    /// An alpha cut-out: opacity and cut-off, in 255ths.
    cutout: Option<(u8, u8)>,
    /// The tiny texture is the occlusion map too.
    occlusion_map: bool,
    /// The metallic factor and roughness (any values: the metallic-roughness model clamps them).
    metallic_roughness: (F, F),
    /// The tiny texture is the metallic-roughness map too.
    metallic_roughness_map: bool,
    /// Light the stored sRGB codes instead of linear light.
    encoded_light: bool,
    /// Draw the frame again into four samples per pixel ([`run`]'s step 7).
    multisample: bool,
    /// An environment: the built-in studio at 16x8 texels times a factor (any value), turned by an angle (any).
    environment: Option<(F, F)>,
}

/// An environment's buffers: the studio at 16x8 texels times a factor, prefiltered small, and the split-sum table
/// (made once for every run).
struct EnvironmentBuffers {
    specular: Vec<Vec3>,
    irradiance: Irradiance,
}

/// Rows of the fuzzed environment's panorama and chain; levels of the chain; samples per texel.
const ENVIRONMENT: Prefiltering = Prefiltering { height: 8, levels: 3, samples: 4 };

impl EnvironmentBuffers {
    fn new(factor: f32) -> Self {
        let h = ENVIRONMENT.height;
        let mut texels = vec![Vec3::ZERO; (2 * h * h) as usize];
        studio::fill(h, &mut texels).expect("a panorama's size");
        texels.iter_mut().for_each(|t| *t = *t * factor);
        let panorama = Panorama::new(2 * h, h, &texels).expect("a panorama");
        let (lods, specular) = ENVIRONMENT.texel_counts(h).expect("the chains' sizes");
        let (mut lods, mut specular) = (vec![Vec3::ZERO; lods], vec![Vec3::ZERO; specular]);
        let irradiance = prepare(&panorama, &ENVIRONMENT, &mut lods, &mut specular).expect("its chains");
        Self { specular, irradiance }
    }

    fn environment(&self) -> Environment<'_> {
        static SPLIT_SUM: std::sync::OnceLock<SplitSum> = std::sync::OnceLock::new();
        let chain = PanoramaChain::new(ENVIRONMENT.height, ENVIRONMENT.levels, &self.specular).expect("a chain");
        Environment::new(self.irradiance, chain, SPLIT_SUM.get_or_init(SplitSum::new))
    }
}

/// One fuzz input: a scene to draw.
#[derive(Arbitrary, Debug)]
pub struct Input {
    camera: CameraIn,
    model: ModelIn,
    width: u8,
    height: u8,
    band: Option<(u8, u8)>,
    state: StateIn,
    vertices: Vec<VertexIn>,
    indices: IndicesIn,
    normals: bool,
    uvs: bool,
    colors: bool,
    texture: Option<TextureIn>,
    shading: ShadingIn,
    material_color: V3,
    material_specular: V3,
    shininess: F,
    ambient: V3,
    lights: Vec<LightIn>,
    wireframe: Option<(V3, F)>,
    extras: ExtrasIn,
}

impl Input {
    /// A small number naming the kind of scene (shading model, texture, depth test, band, wireframe, projection,
    /// index type, point lights or shadows, maps beyond the diffuse one), for picking varied seeds.
    pub fn kind(&self) -> u32 {
        let shading = match self.shading {
            ShadingIn::Unlit => 0,
            ShadingIn::Flat => 1,
            ShadingIn::Gouraud => 2,
            ShadingIn::Phong => 3,
            ShadingIn::Depth { .. } => 4,
            ShadingIn::Normals => 5,
            ShadingIn::MetallicRoughness => 6,
        };
        let indices = match self.indices {
            IndicesIn::Sequential => 0,
            IndicesIn::U16(_) => 1,
            IndicesIn::U32(_) => 2,
        };
        shading
            | u32::from(self.texture.is_some() && self.uvs) << 3
            | u32::from(self.state.depth_off) << 4
            | u32::from(self.band.is_some()) << 5
            | u32::from(self.wireframe.is_some()) << 6
            | u32::from(matches!(self.camera.projection, ProjectionIn::Orthographic { .. })) << 7
            | indices << 8
            | u32::from(self.point_or_shadowed_lights()) << 11
            | u32::from(self.texture.is_some() && self.uvs && self.extra_maps()) << 12
    }

    /// Some light is a point light or casts shadows.
    fn point_or_shadowed_lights(&self) -> bool {
        let lights = (1u8 << self.lights.len().min(MAX_LIGHTS)) - 1;
        (self.extras.point_lights | self.extras.shadowed) & lights != 0
    }

    /// The tiny texture is a normal, specular, glow or metallic-roughness map.
    fn extra_maps(&self) -> bool {
        let e = &self.extras;
        e.normal_map.is_some() || e.specular_map || e.glow_map || e.metallic_roughness_map
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Buffers that check the core's index contract
// ---------------------------------------------------------------------------------------------------------------

/// RGB888 written through the core's `Rgb888`, but a write at an index outside the buffer is a panic instead of
/// being ignored: the core promises to write only below the length the target was checked against.
struct CheckedColor<'a>(&'a mut [u32]);

impl ColorBuffer for CheckedColor<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn write(&mut self, index: usize, color: Vec3) {
        let len = self.0.len();
        assert!(index < len, "colour write at index {index} outside a buffer of {len} pixels");
        Rgb888(&mut *self.0).write(index, color);
    }
    fn fill(&mut self, color: Vec3) {
        Rgb888(&mut *self.0).fill(color);
    }
    fn write_samples(&mut self, first: usize, mask: u8, color: Vec3) {
        if mask != 0 {
            let (len, last) = (self.0.len(), first + 7 - mask.leading_zeros() as usize);
            assert!(last < len, "sample write at index {last} outside a buffer of {len} values");
        }
        Rgb888(&mut *self.0).write_samples(first, mask, color);
    }
}

/// A whole `width x height` frame of `samples` per pixel in the target's own buffers.
fn checked_frame<'a>(
    color: &'a mut [u32],
    depth: CheckedDepth<'a>,
    (width, height): (u32, u32),
    samples: Samples,
) -> Target<CheckedColor<'a>, CheckedDepth<'a>> {
    Target::multisampled(CheckedColor(color), depth, width, height, 0..height, samples).expect("a valid frame")
}

/// The values a [`CheckedDepth`] stores, in either of the core's depth formats.
enum Depths<'a> {
    F32(&'a mut [f32]),
    /// Quantized by the core's `&mut [u16]` (`depth_to_u16`).
    U16(&'a mut [u16]),
}

/// A depth buffer as a caller holds it, `f32` or `u16`, stored through the core's own slice buffers, that panics on
/// an index outside the buffer and on a depth outside the contract (in `[0, 1]`, never NaN or `-0`:
/// `rastty_core::target::clamp_depth`).
///
/// With `shortcuts`, the early test of cut-out draws (`nearer`) and the lane-wise test go through the core's slices
/// too; without, through the trait's defaults (shade every fragment, test pixel by pixel), so that a frame drawn
/// one way and its bands the other prove the shortcuts change nothing. The pipeline tests it through its view
/// (`DepthView::Other`), in the pixel loops every shader shares; the comparison with the library's own buffers
/// (`draw_mesh` into `&mut [f32]`) covers the loop compiled into each draw loop.
struct CheckedDepth<'a> {
    depths: Depths<'a>,
    shortcuts: bool,
}

impl<'a> CheckedDepth<'a> {
    fn f32(depths: &'a mut [f32], shortcuts: bool) -> Self {
        CheckedDepth { depths: Depths::F32(depths), shortcuts }
    }

    fn u16(depths: &'a mut [u16], shortcuts: bool) -> Self {
        CheckedDepth { depths: Depths::U16(depths), shortcuts }
    }

    fn len(&self) -> usize {
        match &self.depths {
            Depths::F32(d) => d.len(),
            Depths::U16(d) => d.len(),
        }
    }

    /// Panics unless `index` is inside the buffer and `z` inside the contract.
    fn check(&self, index: usize, z: f32) {
        let len = self.len();
        assert!(index < len, "depth test at index {index} outside a buffer of {len} pixels");
        assert!(z.to_bits() <= 1f32.to_bits(), "a depth buffer was given {z:e} ({:#010x}), not in [0, 1]", z.to_bits());
    }
}

impl DepthBuffer for CheckedDepth<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.len())
    }
    fn test_and_set(&mut self, index: usize, z: f32) -> bool {
        self.check(index, z);
        match &mut self.depths {
            Depths::F32(d) => d.test_and_set(index, z),
            Depths::U16(d) => d.test_and_set(index, z),
        }
    }
    fn nearer(&self, index: usize, z: f32) -> bool {
        if !self.shortcuts {
            return true;
        }
        self.check(index, z);
        match &self.depths {
            Depths::F32(d) => d.nearer(index, z),
            Depths::U16(d) => d.nearer(index, z),
        }
    }
    fn test_and_set_lanes(
        &mut self,
        start: usize,
        z: &Lanes<f32, DEPTH_LANES>,
        covered: &Lanes<bool, DEPTH_LANES>,
    ) -> u32 {
        for lane in (0..DEPTH_LANES).filter(|&lane| covered[lane]) {
            self.check(start + lane, z[lane]);
        }
        if let (Depths::F32(d), true) = (&mut self.depths, self.shortcuts) {
            return d.test_and_set_lanes(start, z, covered);
        }
        let passed = (0..DEPTH_LANES).filter(|&lane| covered[lane] && self.test_and_set(start + lane, z[lane]));
        passed.count() as u32
    }
    fn clear(&mut self) {
        match &mut self.depths {
            Depths::F32(d) => d.clear(),
            Depths::U16(d) => d.clear(),
        }
    }
}

/// The mesh's positions through `clip_from_object`, nothing else: with `FRAGMENT` false a depth-only shader (the
/// pipeline's lane-wise depth pass), with it true a shader that writes one colour (the ordinary pixel loop).
struct Positions<const FRAGMENT: bool>(Mat4);

impl<const FRAGMENT: bool> Shader for Positions<FRAGMENT> {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const FRAGMENT_STAGE: bool = FRAGMENT;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.0.project_point(mesh.position(i))
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        assert!(FRAGMENT, "a depth-only shader's fragment stage ran");
        Vec3::ONE
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Invariants
// ---------------------------------------------------------------------------------------------------------------

/// Every input triangle ends in exactly one bucket.
fn check_stats(what: &str, s: &DrawStats, triangles: u64) {
    assert_eq!(s.triangles_in, triangles, "{what}: triangles_in, {s:?}");
    assert_eq!(
        s.invalid + s.outside + s.culled + s.degenerate + s.rasterized,
        s.triangles_in,
        "{what}: buckets do not add up, {s:?}"
    );
    assert!(s.clipped <= s.triangles_in, "{what}: more clipped than submitted, {s:?}");
}

/// Triangles: each covers a pixel centre at most once, a clipped one is cut into at most `MAX_PIECES` pieces.
fn check_fill_fragments(what: &str, s: &DrawStats, pixels: u64) {
    let pieces = s.rasterized + (MAX_PIECES - 1) * s.clipped.min(s.rasterized);
    assert!(s.fragments <= pixels * pieces, "{what}: {} fragments for {pixels} pixels, {s:?}", s.fragments);
}

/// Lines: at most one pixel per column or per row of the band, for each of three edges.
fn check_line_fragments(what: &str, s: &DrawStats, width: u64, rows: u64) {
    let per_line = width.max(rows);
    assert!(s.fragments <= 3 * s.rasterized * per_line, "{what}: {} line fragments, {s:?}", s.fragments);
}

fn check_depth_range(what: &str, depth: &[f32], depth_test: DepthTest) {
    for (i, &d) in depth.iter().enumerate() {
        match depth_test {
            DepthTest::Less => {
                assert!((0.0..=1.0).contains(&d), "{what}: depth[{i}] = {d:e} ({:#010x}) not in [0, 1]", d.to_bits())
            }
            DepthTest::Off => assert!(d.to_bits() == 1f32.to_bits(), "{what}: depth test off but depth[{i}] = {d:e}"),
        }
    }
}

/// Two draws of one scene resolve the same variant (compared by its `Debug` form, which shows a NaN depth-view
/// bound as equal to itself).
fn assert_same_variant(what: &str, variant: &Variant, expected: &Variant) {
    assert_eq!(format!("{variant:?}"), format!("{expected:?}"), "{what}: another variant than draw_mesh's whole frame");
}

fn bits(depth: &[f32]) -> Vec<u32> {
    depth.iter().map(|d| d.to_bits()).collect()
}

// ---------------------------------------------------------------------------------------------------------------
// The target
// ---------------------------------------------------------------------------------------------------------------

/// The frame drawn by `testing::draw_mesh_general` (into checked buffers with `samples` per pixel, under `lights`:
/// the shadow maps without window ranges) must equal `draw_mesh`'s: variant, samples, depth bits and statistics.
fn compare_general(
    object: &Object<'_>,
    lights: &Lighting<'_>,
    state: &DrawState,
    (width, height, samples): (u32, u32, Samples),
    (color, depth): (&[u32], &[f32]),
    (full_variant, full_stats): (&Variant, &DrawStats),
) {
    // Each pixel's samples side by side: `w` counts samples.
    let (w, h) = (width as usize * samples.count(), height as usize);
    let mut color_g = vec![0u32; w * h];
    let mut depth_g = vec![0f32; w * h];
    {
        let depth = CheckedDepth::f32(&mut depth_g, false);
        let mut target = checked_frame(&mut color_g, depth, (width, height), samples);
        target.clear(CLEAR);
        let (variant, stats) = draw_mesh_general(&mut target, object, lights, state)
            .expect("draw_mesh accepted the draw, draw_mesh_general must too");
        assert_same_variant("draw_mesh_general", &variant, full_variant);
        assert_eq!(&stats, full_stats, "draw_mesh_general stats differ from draw_mesh ({full_variant}, {samples:?})");
    }
    if let Some(i) = (0..w * h).find(|&i| color[i] != color_g[i]) {
        panic!(
            "draw_mesh_general sample ({}, {}) = {:#08x}, draw_mesh gave {:#08x} ({full_variant}, {samples:?})",
            i % w,
            i / w,
            color_g[i],
            color[i]
        );
    }
    assert_eq!(
        bits(depth),
        bits(&depth_g),
        "draw_mesh_general depth differs from draw_mesh ({full_variant}, {samples:?})"
    );
}

/// What a draw of the scene must answer when it is refused, in the order the core checks.
#[derive(Clone, Copy, Debug)]
enum Refusal {
    /// The shading model reads normals (Gouraud, Phong, normals) and the mesh has none.
    MissingNormals,
    /// A tangent-space normal map in use with a tangent count other than the vertex count.
    Tangents { expected: usize, actual: usize },
    /// Sub-pixel bits above `MAX_SUBPIXEL_BITS`.
    SubpixelBits(u8),
}

/// One shadow map's depth pass and window ranges, owned here so that the lights can borrow them.
struct ShadowBuffers {
    view: ShadowView,
    depth: Vec<f32>,
    bias: ShadowBias,
    pcf: u32,
    /// Nearest and farthest depths of each filter window, when the specialised draws use them.
    windows: Option<(Vec<f32>, Vec<f32>)>,
}

/// The shadow map of `light` as `input` asks for it, its depth pass drawn (its statistics checked), or `None` when
/// the view cannot be fitted.
fn shadow_buffers(
    input: &ShadowIn,
    light: &Light<'_>,
    (mesh, triangles): (&Mesh<'_>, u64),
    model: &Mat4,
) -> Option<ShadowBuffers> {
    let size = 1 + u32::from(input.size) % MAX_SHADOW_SIZE;
    let pcf = u32::from(input.pcf % 4);
    let bounds = match input.bounds {
        Some((centre, radius)) => BoundingSphere { centre: centre.get(), radius: radius.0 },
        None => {
            let world: Vec<Vec3> = mesh.positions().iter().map(|&p| model.transform_point(p)).collect();
            let centre = world.iter().fold(Vec3::ZERO, |sum, &p| sum + p) / world.len() as f32;
            let radius = world.iter().fold(0f32, |r, &p| r.max((p - centre).length()));
            BoundingSphere { centre, radius: radius * 1.01 }
        }
    };
    let view = ShadowView::fit(light.kind, bounds, size).ok()?;
    let rows = view.rows();
    let mut depth = vec![0f32; (size * rows) as usize];
    clear_shadow_depth(&mut depth);
    let stats = draw_shadow_caster(&view, &mut depth, mesh, model).expect("a buffer of the map's size");
    check_stats("shadow caster", &stats, triangles * u64::from(view.faces()));
    check_fill_fragments("shadow caster", &stats, u64::from(size * size));
    assert!(depth.iter().all(|d| (0.0..=1.0).contains(d)), "shadow caster: a depth outside [0, 1]");
    let bias = input.bias.map_or(ShadowBias::DEFAULT, |(n, s, d)| ShadowBias {
        normal_offset: n.0,
        slope_offset: s.0,
        depth: d.0,
    });
    let windows = input.windows.then(|| {
        let n = depth.len();
        let (mut near, mut far) = (vec![0f32; n], vec![0f32; n]);
        window_ranges_band(&depth, size, pcf, 0..rows, &mut near, &mut far).expect("buffers of the map's size");
        (near, far)
    });
    Some(ShadowBuffers { view, depth, bias, pcf, windows })
}

/// `light` with the shadow map of `buffers` (with its window ranges when `windows` and the buffers have them).
fn with_shadow<'a>(light: &Light<'a>, buffers: Option<&'a ShadowBuffers>, windows: bool) -> Light<'a> {
    let shadow = buffers.map(|b| {
        let map = ShadowMap::new(b.view, &b.depth, b.bias, b.pcf).expect("a buffer of the map's size");
        match (&b.windows, windows) {
            (Some((near, far)), true) => {
                let size = b.view.size();
                let ranges = WindowRanges::new(near, far, size, b.pcf).expect("buffers of the map's size");
                map.with_windows(ranges).expect("ranges of this map")
            }
            _ => map,
        }
    });
    Light { kind: light.kind, color: light.color, shadow }
}

/// Draws `input` every way the target compares and checks the invariants (a failure is a panic).
///
/// Returns the whole frame's `draw_mesh` statistics, or `None` when the camera was refused or the draw was
/// (rightly) refused.
pub fn run(input: Input) -> Option<DrawStats> {
    let width = 1 + u32::from(input.width) % 64;
    let height = 1 + u32::from(input.height) % 64;
    let (w, h) = (width as usize, height as usize);

    // Camera: a refusal is the constructors' contract, not a finding.
    let c = &input.camera;
    let Ok(view) = look_at(c.eye.get(), c.target.get(), c.up.get()) else { return None };
    let projection = match c.projection {
        ProjectionIn::Perspective { fovy, aspect, near, far } => {
            let aspect = aspect.map_or(width as f32 / height as f32, |a| a.0);
            perspective(fovy.0, aspect, near.0, far.0)
        }
        ProjectionIn::Orthographic { left, right, bottom, top, near, far } => {
            orthographic(left.0, right.0, bottom.0, top.0, near.0, far.0)
        }
    };
    let Ok(projection) = projection else { return None };
    let model = match &input.model {
        ModelIn::Identity => Mat4::IDENTITY,
        ModelIn::Scale(s) => Mat4::from_scale(s.get()),
        ModelIn::Translate(t) => Mat4::from_translation(t.get()),
        ModelIn::Matrix(r) => {
            Mat4::from_rows(r[0].map(|f| f.0), r[1].map(|f| f.0), r[2].map(|f| f.0), r[3].map(|f| f.0))
        }
    };
    let transforms = Transforms::new(model, view, projection);

    // Mesh.
    let vertices = &input.vertices[..input.vertices.len().min(MAX_VERTICES)];
    let positions: Vec<Vec3> = vertices.iter().map(|v| v.position.get()).collect();
    let normals: Vec<Vec3> = vertices.iter().map(|v| v.normal.get()).collect();
    let uvs: Vec<Vec2> = vertices.iter().map(|v| Vec2::new(v.uv.0.0, v.uv.1.0)).collect();
    let colors: Vec<Vec3> = vertices.iter().map(|v| v.color.get()).collect();
    let n = positions.len();
    let whole = |len: usize| len.min(3 * MAX_TRIANGLES) / 3 * 3;
    let (u16s, u32s): (Vec<u16>, Vec<u32>) = match &input.indices {
        IndicesIn::Sequential => (Vec::new(), Vec::new()),
        IndicesIn::U16(ix) => (ix[..whole(ix.len())].iter().map(|i| i.get(n)).collect(), Vec::new()),
        IndicesIn::U32(ix) => (Vec::new(), ix[..whole(ix.len())].iter().map(|i| u32::from(i.get(n))).collect()),
    };
    let (indices, positions) = match &input.indices {
        IndicesIn::Sequential => (Indices::Sequential, &positions[..n / 3 * 3]),
        IndicesIn::U16(_) => (Indices::U16(&u16s), &positions[..]),
        IndicesIn::U32(_) => (Indices::U32(&u32s), &positions[..]),
    };
    let m = positions.len();
    let mut mesh = Mesh::new(positions, indices).expect("whole triangles");
    if input.normals {
        mesh = mesh.with_normals(&normals[..m]).expect("one normal per position");
    }
    if input.uvs {
        mesh = mesh.with_uvs(&uvs[..m]).expect("one uv per position");
    }
    if input.colors {
        mesh = mesh.with_colors(&colors[..m]).expect("one colour per position");
    }
    let triangles = mesh.triangle_count() as u64;

    // Tangents, even when no normal map uses them.
    let extras = &input.extras;
    let mut tangents = Vec::new();
    let tangents = match &extras.normal_map {
        Some(NormalMapIn::Tangent(TangentsIn::Computed)) => {
            tangents.resize(m, Vec4::ZERO);
            compute_tangents(&mesh, &mut tangents).ok().map(|()| &tangents[..])
        }
        Some(NormalMapIn::Tangent(TangentsIn::Given(given))) => {
            tangents.extend(given.iter().take(MAX_VERTICES + 1).map(|t| Vec4::new(t.0.0, t.1.0, t.2.0, t.3.0)));
            Some(&tangents[..])
        }
        _ => None,
    };

    // Material.
    let (texels, mut levels): (Vec<u32>, Vec<u32>);
    let (texture, filter, wrap, mip_filter) = match &input.texture {
        None => (None, FilterMode::Bilinear, WrapMode::Repeat, MipFilter::Off),
        Some(t) => {
            let (tw, th) = (1 + u32::from(t.width) % 4, 1 + u32::from(t.height) % 4);
            let count = (tw * th) as usize;
            texels = (0..count).map(|i| if t.texels.is_empty() { 0 } else { t.texels[i % t.texels.len()] }).collect();
            let texture = Texture::new(&texels, tw, th).expect("a valid tiny texture");
            levels = vec![0; mip_chain_texels(tw, th)];
            build_mip_levels(&texture, MipContent::Color, &mut levels).expect("levels sized by mip_chain_texels");
            (
                Some(texture.with_mip_levels(&levels).expect("the levels built for it")),
                if t.bilinear { FilterMode::Bilinear } else { FilterMode::Nearest },
                if t.clamp { WrapMode::Clamp } else { WrapMode::Repeat },
                MIP_FILTERS[usize::from(t.mipmaps) % MIP_FILTERS.len()],
            )
        }
    };
    let material = Material {
        color: input.material_color.get(),
        specular: input.material_specular.get(),
        shininess: input.shininess.0,
        diffuse: texture.filter(|_| !extras.no_diffuse),
        normal_map: extras.normal_map.as_ref().and(texture).map(|texture| NormalMap {
            texture,
            space: match extras.normal_map {
                Some(NormalMapIn::Object) => NormalSpace::Object,
                _ => NormalSpace::Tangent,
            },
        }),
        specular_map: texture.filter(|_| extras.specular_map),
        glow_map: texture.filter(|_| extras.glow_map),
        occlusion_map: texture.filter(|_| extras.occlusion_map),
        metallic: extras.metallic_roughness.0.0,
        roughness: extras.metallic_roughness.1.0,
        metallic_roughness_map: texture.filter(|_| extras.metallic_roughness_map),
        filter,
        wrap,
        mip_filter,
        opacity: extras.cutout.map_or(1.0, |(opacity, _)| f32::from(opacity) / 255.0),
        alpha_cutoff: extras.cutout.map(|(_, cutoff)| f32::from(cutoff) / 255.0),
    };

    // Lights: directional, point, or (from raw values) a spot aimed at the origin that falls off by the inverse
    // square within a range, each with its shadow map if it casts one.
    let lights: Vec<Light> = input
        .lights
        .iter()
        .take(MAX_LIGHTS)
        .enumerate()
        .map(|(i, l)| match (l, extras.point_lights >> i & 1 == 1) {
            (LightIn::Directional(d, c), false) => Light::directional(d.get(), c.get()),
            (LightIn::Directional(p, c), true) => Light::point(p.get(), c.get()),
            (LightIn::Raw(d, c), false) => {
                Light { kind: LightKind::Directional { to_light: d.get() }, color: c.get(), shadow: None }
            }
            (LightIn::Raw(p, c), true) => {
                let (position, color) = (p.get(), c.get());
                let range = Some(color.x.abs() * 4.0);
                let cone = Cone::new(-position, color.y.abs(), color.z.abs());
                let kind = LightKind::Spot { position, falloff: Falloff::inverse_square(range), cone };
                Light { kind, color, shadow: None }
            }
        })
        .collect();
    let shadows: Vec<Option<ShadowBuffers>> = (lights.iter().enumerate())
        .map(|(i, light)| {
            let shadowed = extras.shadowed >> i & 1 == 1;
            shadowed.then(|| shadow_buffers(&extras.shadow, light, (&mesh, triangles), &model)).flatten()
        })
        .collect();
    // The specialised draws' lights (with window ranges where asked for) and the general path's (never).
    let general_lights: Vec<Light> =
        lights.iter().zip(&shadows).map(|(l, s)| with_shadow(l, s.as_ref(), false)).collect();
    let lights: Vec<Light> = lights.iter().zip(&shadows).map(|(l, s)| with_shadow(l, s.as_ref(), true)).collect();
    let shading = match input.shading {
        ShadingIn::Unlit => ShadingModel::Unlit,
        ShadingIn::Flat => ShadingModel::Flat,
        ShadingIn::Gouraud => ShadingModel::Gouraud,
        ShadingIn::Phong => ShadingModel::Phong,
        ShadingIn::MetallicRoughness => ShadingModel::MetallicRoughness,
        ShadingIn::Depth { near, far } => ShadingModel::Depth { near: near.0, far: far.0 },
        ShadingIn::Normals => ShadingModel::Normals,
    };
    let object = Object { mesh, tangents, transforms, shading, material };
    let ambient = input.ambient.get();
    let space = if input.extras.encoded_light { ShadingSpace::Encoded } else { ShadingSpace::Linear };
    let environment_buffers = extras.environment.map(|(factor, _)| EnvironmentBuffers::new(factor.0));
    let environment = environment_buffers
        .as_ref()
        .zip(extras.environment)
        .map(|(buffers, (_, turn))| buffers.environment().turned(turn.0));
    let lighting = Lighting { ambient, lights: &lights, environment: environment.as_ref(), space };
    let general_lighting = Lighting { ambient, lights: &general_lights, environment: environment.as_ref(), space };
    let state = input.state.get();
    let style = input.wireframe.map(|(c, bias)| LineStyle { color: c.get(), depth_bias: bias.0 });

    // What the draw must answer.
    let needs_normals = shading.per_pixel() || matches!(shading, ShadingModel::Gouraud | ShadingModel::Normals);
    let tangent_map = shading.per_pixel()
        && input.uvs
        && matches!(object.material.normal_map, Some(NormalMap { space: NormalSpace::Tangent, .. }));
    let given_tangents = tangents.map_or(0, <[Vec4]>::len);
    let expected_error = if needs_normals && !input.normals {
        Some(Refusal::MissingNormals)
    } else if tangent_map && given_tangents != m {
        Some(Refusal::Tangents { expected: m, actual: given_tangents })
    } else if state.subpixel_bits > MAX_SUBPIXEL_BITS {
        Some(Refusal::SubpixelBits(state.subpixel_bits))
    } else {
        None
    };
    let check_error = |what: &str, e: ShadingError| match (expected_error, e) {
        (Some(Refusal::MissingNormals), ShadingError::Draw(DrawError::MissingAttributes { needed, present })) => {
            assert!(needed.normals && !present.normals, "{what}: {e:?}")
        }
        (Some(Refusal::Tangents { expected, actual }), ShadingError::Tangents { expected: e1, actual: a1 }) => {
            assert_eq!((e1, a1), (expected, actual), "{what}: tangent counts")
        }
        (Some(Refusal::SubpixelBits(bits)), ShadingError::Draw(DrawError::SubpixelBits(b))) => {
            assert_eq!(b, bits, "{what}")
        }
        _ => panic!("{what}: unexpected {e:?}, expected {expected_error:?} (state {state:?})"),
    };
    let clear_color = pack_rgb888(CLEAR);

    // 1. The whole frame through the specialised pipeline, into RGB888 + f32 (the core's shortcuts on).
    let mut color = vec![0u32; w * h];
    let mut depth = vec![0f32; w * h];
    let (full_variant, full_stats);
    {
        let mut target = checked_frame(&mut color, CheckedDepth::f32(&mut depth, true), (width, height), Samples::One);
        target.clear(CLEAR);
        match draw_mesh(&mut target, &object, &lighting, &state) {
            Ok((variant, stats)) => {
                assert!(
                    expected_error.is_none(),
                    "draw_mesh accepted {state:?} / {shading:?} ({variant}), expected {expected_error:?}"
                );
                // The explanation `rastty render --explain` prints: it must format.
                let _ = variant.to_string();
                (full_variant, full_stats) = (variant, stats);
            }
            Err(e) => {
                check_error("draw_mesh", e);
                assert!(color.iter().all(|&p| p == clear_color), "a refused draw wrote pixels");
                assert!(depth.iter().all(|&d| d == 1.0), "a refused draw wrote depth");
                // Same refusal through the general path; nothing else to check.
                let (mut c2, mut d2) = (vec![0u32; w * h], vec![0f32; w * h]);
                let mut t2 = checked_frame(&mut c2, CheckedDepth::f32(&mut d2, true), (width, height), Samples::One);
                t2.clear(CLEAR);
                match draw_mesh_general(&mut t2, &object, &general_lighting, &state) {
                    Ok(s) => panic!("draw_mesh refused with {e:?} but draw_mesh_general drew {s:?}"),
                    Err(e2) => assert_eq!(e, e2, "the two paths refuse differently"),
                }
                return None;
            }
        }
    }
    let pixels = (w * h) as u64;
    check_stats("draw_mesh", &full_stats, triangles);
    check_fill_fragments("draw_mesh", &full_stats, pixels);
    check_depth_range("draw_mesh", &depth, state.depth_test);

    // 2. The same frame through the general path (GeneralShader through the general pixel loop, shadow maps without
    //    window ranges): the same variant, identical pixels, depth and stats.
    let full = (&full_variant, &full_stats);
    compare_general(&object, &general_lighting, &state, (width, height, Samples::One), (&color, &depth), full);

    // 3. The wireframe over it.
    let mut line_stats = DrawStats::default();
    if let Some(style) = &style {
        let mut target = checked_frame(&mut color, CheckedDepth::f32(&mut depth, true), (width, height), Samples::One);
        let stats = draw_wireframe(&mut target, &object.mesh, &transforms.clip_from_object, style, &state);
        check_stats("draw_wireframe", &stats, triangles);
        check_line_fragments("draw_wireframe", &stats, width.into(), height.into());
        line_stats = stats;
        check_depth_range("draw_wireframe", &depth, state.depth_test);
    }

    // 4. The same frame with 16-bit depth, for its bands to equal.
    //    (Its depth tests differ from the f32 frame's where two depths quantize alike: nothing to compare there.)
    let (mut color16, mut depth16) = (vec![0u32; w * h], vec![0u16; w * h]);
    let frame16 = {
        let depth = CheckedDepth::u16(&mut depth16, true);
        let mut target = checked_frame(&mut color16, depth, (width, height), Samples::One);
        let draws = (&object, &lighting, &state);
        draw_band(&mut target, (&full_variant, triangles), draws, style.as_ref(), "the frame, u16 depth")
    };

    // 5. Bands: the chosen band and the rows above and below it partition the frame. Each band, drawn into
    //    buffers of the caller's own (which check every index and every depth given), equals the frame's rows bit
    //    for bit, pixels and depths, in either depth format; and the fragments add up to the frame's.
    let (start, end) = match input.band {
        None => (0, height),
        Some((s, l)) => {
            let s = u32::from(s) % height;
            (s, s + 1 + u32::from(l) % (height - s))
        }
    };
    let bands = [(0, start), (start, end), (end, height)];
    let (mut fragments, mut fragments16) = ((0, 0), (0, 0));
    for (y0, y1) in bands {
        if y0 >= y1 {
            continue;
        }
        let rows = (y1 - y0) as usize;
        let frame_rows = y0 as usize * w..y1 as usize * w;
        let draws = (&object, &lighting, &state);
        let (mut band_color, mut band_depth) = (vec![0u32; w * rows], vec![0f32; w * rows]);
        let mut target = Target::band(
            CheckedColor(&mut band_color),
            CheckedDepth::f32(&mut band_depth, false),
            width,
            height,
            y0..y1,
        )
        .expect("a valid band");
        let what = format!("band {y0}..{y1}");
        let (f, l) = draw_band(&mut target, (&full_variant, triangles), draws, style.as_ref(), &what);
        fragments = (fragments.0 + f, fragments.1 + l);
        compare_pixels(&what, &band_color, &color[frame_rows.clone()], w, y0);
        compare_depths(&what, &bits(&band_depth), &bits(&depth[frame_rows.clone()]), w, y0);

        let (mut band_color, mut band_depth) = (vec![0u32; w * rows], vec![0u16; w * rows]);
        let mut target = Target::band(
            CheckedColor(&mut band_color),
            CheckedDepth::u16(&mut band_depth, false),
            width,
            height,
            y0..y1,
        )
        .expect("a valid band");
        let what = format!("band {y0}..{y1}, u16 depth");
        let (f, l) = draw_band(&mut target, (&full_variant, triangles), draws, style.as_ref(), &what);
        fragments16 = (fragments16.0 + f, fragments16.1 + l);
        compare_pixels(&what, &band_color, &color16[frame_rows.clone()], w, y0);
        let widen = |d: &[u16]| d.iter().map(|&q| u32::from(q)).collect::<Vec<_>>();
        compare_depths(&what, &widen(&band_depth), &widen(&depth16[frame_rows]), w, y0);
    }
    assert_eq!(fragments, (full_stats.fragments, line_stats.fragments), "the bands' fragments add up to the frame's");
    assert_eq!(fragments16, frame16, "u16 bands: fragments add up to the frame's");

    // 6. Depth-only passes of the same positions and state: the lane-wise pass, the general pixel loop's and every
    //    band's store the depths of a shaded pass bit for bit, and count its fragments.
    check_depth_only(&object.mesh, &transforms.clip_from_object, &state, (width, height), &bands);

    // 7. Four samples per pixel (when the input asks): the frame, the general path's equal to it, and its bands
    //    equal to its rows.
    if input.extras.multisample {
        let draws = (&object, &lighting, &general_lighting);
        check_multisampled(draws, &state, (width, height), &bands, (&full_variant, triangles), style.as_ref());
    }
    Some(full_stats)
}

/// Step 7 of [`run`]: the frame drawn into four samples per pixel by `draw_mesh` (statistics and depths checked),
/// by the general path under `general_lights` (equal samples, depths and statistics), the wireframe over it, and
/// each band into checked buffers: the frame's samples and depths bit for bit, the fragments adding up.
fn check_multisampled(
    (object, lights, general_lights): (&Object<'_>, &Lighting<'_>, &Lighting<'_>),
    state: &DrawState,
    (width, height): (u32, u32),
    bands: &[(u32, u32)],
    (frame_variant, triangles): (&Variant, u64),
    style: Option<&LineStyle>,
) {
    let n = Samples::Four.count();
    let row = width as usize * n;
    let (mut color, mut depth) = (vec![0u32; row * height as usize], vec![0f32; row * height as usize]);
    let stats = {
        let mut target = checked_frame(&mut color, CheckedDepth::f32(&mut depth, true), (width, height), Samples::Four);
        target.clear(CLEAR);
        let (variant, stats) = draw_mesh(&mut target, object, lights, state).expect("the frame's draw was accepted");
        assert_same_variant("four samples", &variant, frame_variant);
        stats
    };
    check_stats("four samples", &stats, triangles);
    check_fill_fragments("four samples", &stats, u64::from(width * height));
    check_depth_range("four samples", &depth, state.depth_test);
    let full = (frame_variant, &stats);
    compare_general(object, general_lights, state, (width, height, Samples::Four), (&color, &depth), full);
    let lines = style.map_or(0, |style| {
        let mut target = checked_frame(&mut color, CheckedDepth::f32(&mut depth, true), (width, height), Samples::Four);
        let lines = draw_wireframe(&mut target, &object.mesh, &object.transforms.clip_from_object, style, state);
        check_stats("four samples, wireframe", &lines, triangles);
        check_line_fragments("four samples, wireframe", &lines, width.into(), height.into());
        lines.fragments
    });
    let mut fragments = (0, 0);
    for &(y0, y1) in bands.iter().filter(|(y0, y1)| y0 < y1) {
        let samples = y0 as usize * row..y1 as usize * row;
        let (mut band_color, mut band_depth) = (vec![0u32; samples.len()], vec![0f32; samples.len()]);
        let (c, d) = (CheckedColor(&mut band_color), CheckedDepth::f32(&mut band_depth, false));
        let mut target = Target::multisampled(c, d, width, height, y0..y1, Samples::Four).expect("a valid band");
        let what = format!("four samples, band {y0}..{y1} (x counts samples)");
        let (f, l) = draw_band(&mut target, (frame_variant, triangles), (object, lights, state), style, &what);
        fragments = (fragments.0 + f, fragments.1 + l);
        compare_pixels(&what, &band_color, &color[samples.clone()], row, y0);
        compare_depths(&what, &bits(&band_depth), &bits(&depth[samples]), row, y0);
    }
    assert_eq!(fragments, (stats.fragments, lines), "four samples: the bands' fragments add up to the frame's");
}

/// `draw_mesh` then, if there is a `style`, `draw_wireframe` into `target` (cleared first), with their statistics
/// checked and the frame's variant; returns their fragments.
fn draw_band<C: ColorBuffer, D: DepthBuffer>(
    target: &mut Target<C, D>,
    (frame_variant, triangles): (&Variant, u64),
    (object, lights, state): (&Object<'_>, &Lighting<'_>, &DrawState),
    style: Option<&LineStyle>,
    what: &str,
) -> (u64, u64) {
    target.clear(CLEAR);
    let (width, rows) = (u64::from(target.width()), target.rows().len() as u64);
    let (variant, stats) = draw_mesh(target, object, lights, state).expect("the frame's draw was accepted");
    assert_same_variant(what, &variant, frame_variant);
    check_stats(what, &stats, triangles);
    check_fill_fragments(what, &stats, width * rows);
    let Some(style) = style else { return (stats.fragments, 0) };
    let lines = draw_wireframe(target, &object.mesh, &object.transforms.clip_from_object, style, state);
    check_stats(what, &lines, triangles);
    check_line_fragments(what, &lines, width, rows);
    (stats.fragments, lines.fragments)
}

/// Panics at the first pixel where a band (whose first row is `y0`) differs from the frame's rows.
fn compare_pixels(what: &str, band: &[u32], frame: &[u32], width: usize, y0: u32) {
    if let Some(i) = (0..band.len()).find(|&i| band[i] != frame[i]) {
        let (x, y) = (i % width, y0 as usize + i / width);
        panic!("{what}: pixel ({x}, {y}) = {:#08x}, the whole frame has {:#08x}", band[i], frame[i]);
    }
}

/// Panics at the first pixel where a band's depth bits differ from the frame's rows'.
fn compare_depths(what: &str, band: &[u32], frame: &[u32], width: usize, y0: u32) {
    if let Some(i) = (0..band.len()).find(|&i| band[i] != frame[i]) {
        let (x, y) = (i % width, y0 as usize + i / width);
        panic!("{what}: depth ({x}, {y}) has bits {:#010x}, the whole frame has {:#010x}", band[i], frame[i]);
    }
}

/// Step 6 of [`run`].
fn check_depth_only(
    mesh: &Mesh<'_>,
    clip_from_object: &Mat4,
    state: &DrawState,
    size: (u32, u32),
    bands: &[(u32, u32)],
) {
    let (width, height) = size;
    let n = (width * height) as usize;
    let depth_only = Positions::<false>(*clip_from_object);
    let (mut colors, mut shaded) = (vec![0u32; n], vec![0f32; n]);
    let mut target = checked_frame(&mut colors, CheckedDepth::f32(&mut shaded, true), (width, height), Samples::One);
    target.clear(CLEAR);
    let expected = match draw(&mut target, mesh, &Positions::<true>(*clip_from_object), state) {
        Ok(stats) => stats,
        Err(e) => {
            assert!(matches!(e, DrawError::SubpixelBits(_)), "a shader that reads no attribute was refused: {e:?}");
            let mut depth = vec![1f32; n];
            let mut target =
                Target::new(NoColor, CheckedDepth::f32(&mut depth, true), width, height).expect("a valid frame");
            assert_eq!(draw(&mut target, mesh, &depth_only, state), Err(e), "the depth-only pass refuses alike");
            return;
        }
    };
    let mut depth = vec![0f32; n];
    let mut target = Target::new(NoColor, CheckedDepth::f32(&mut depth, true), width, height).expect("a valid frame");
    target.clear(CLEAR);
    let stats = draw(&mut target, mesh, &depth_only, state).expect("the shaded pass was accepted");
    assert_eq!(stats, expected, "depth-only pass: statistics");
    compare_depths("depth-only pass", &bits(&depth), &bits(&shaded), width as usize, 0);

    let mut target = Target::new(NoColor, CheckedDepth::f32(&mut depth, false), width, height).expect("a valid frame");
    target.clear(CLEAR);
    let stats = draw_unspecialised(&mut target, mesh, &depth_only, state).expect("the shaded pass was accepted");
    assert_eq!(stats, expected, "depth-only pass, general pixel loop: statistics");
    compare_depths("depth-only pass, general pixel loop", &bits(&depth), &bits(&shaded), width as usize, 0);

    let mut fragments = 0;
    for &(y0, y1) in bands.iter().filter(|(y0, y1)| y0 < y1) {
        let rows = y0 as usize * width as usize..y1 as usize * width as usize;
        let mut band = vec![0f32; rows.len()];
        let mut target =
            Target::band(NoColor, CheckedDepth::f32(&mut band, false), width, height, y0..y1).expect("a valid band");
        target.clear(CLEAR);
        fragments += draw(&mut target, mesh, &depth_only, state).expect("the shaded pass was accepted").fragments;
        let what = format!("depth-only pass, band {y0}..{y1}");
        compare_depths(&what, &bits(&band), &bits(&shaded[rows]), width as usize, y0);
    }
    assert_eq!(fragments, expected.fragments, "depth-only bands: fragments add up to the frame's");
}
