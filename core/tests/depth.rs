//! The z-buffer: comparison, formats, clearing, and the depth test switched off.

use crate::common;

use common::ScreenSpace;
use rastty_core::math::{Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{DepthTest, DrawState, DrawStats, EdgeArithmetic, Fragment, Shader, Slopes, draw};
use rastty_core::target::{DepthBuffer, Rgb888, Target, depth_to_u16};
use rastty_core::testing::draw_unspecialised;

/// Colours each triangle by its first vertex's index, so the winner of each pixel is visible.
struct ByTriangle(ScreenSpace);

impl Shader for ByTriangle {
    type Varyings = ();
    type Face = Vec3;
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.0.position(mesh, i)
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, t: [usize; 3]) -> Vec3 {
        Vec3::new(t[0] as f32 / 255.0, 0.0, 0.0)
    }
    fn fragment(&self, _: &Fragment, face: &Vec3, _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        *face
    }
}

/// Two full-frame quads at depths `z0` (vertices 0..6) and `z1` (6..12) on a 4x4 frame; returns which quad each
/// pixel shows (0 or 6) and the final depth buffer.
fn two_quads<D: DepthBuffer>(z0: f32, z1: f32, depth: D, test: DepthTest) -> (Vec<u32>, D) {
    let quad = |z: f32| {
        [(0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (0.0, 0.0), (4.0, 4.0), (4.0, 0.0)].map(|(x, y)| Vec3::new(x, y, z))
    };
    let positions: Vec<Vec3> = quad(z0).into_iter().chain(quad(z1)).collect();
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let mut color = vec![0u32; 16];
    let mut target = Target::new(Rgb888(&mut color), depth, 4, 4).unwrap();
    target.clear(Vec3::ONE);
    let state = DrawState { depth_test: test, ..DrawState::default() };
    draw(&mut target, &mesh, &ByTriangle(ScreenSpace { width: 4.0, height: 4.0 }), &state).unwrap();
    let (_, depth) = target.into_parts();
    (color.iter().map(|&c| (c >> 16) & 0xFF).collect(), depth)
}

#[test]
fn the_nearer_surface_wins_in_either_order() {
    let mut d = [0f32; 16];
    assert!(two_quads(0.3, 0.6, &mut d[..], DepthTest::Less).0.iter().all(|&w| w <= 3), "first (nearer) wins");
    assert!(d.iter().all(|&z| z == 0.3));
    assert!(two_quads(0.6, 0.3, &mut d[..], DepthTest::Less).0.iter().all(|&w| w >= 6), "second (nearer) wins");
    let mut d16 = [0u16; 16];
    assert!(two_quads(0.3, 0.6, &mut d16[..], DepthTest::Less).0.iter().all(|&w| w <= 3));
    assert!(two_quads(0.6, 0.3, &mut d16[..], DepthTest::Less).0.iter().all(|&w| w >= 6));
    assert!(d16.iter().all(|&z| z == depth_to_u16(0.3)));
}

#[test]
fn coplanar_surfaces_keep_the_first_drawn_every_frame() {
    // The comparison is strictly less: at equal depth the surface already there stays, frame after frame.
    for _ in 0..3 {
        let mut d = [0f32; 16];
        assert!(two_quads(0.5, 0.5, &mut d[..], DepthTest::Less).0.iter().all(|&w| w <= 3));
        let mut d16 = [0u16; 16];
        // 0.5 and 0.500001 differ as f32 but quantise to the same u16 level: still the first wins.
        assert!(two_quads(0.5, 0.500_001, &mut d16[..], DepthTest::Less).0.iter().all(|&w| w <= 3));
    }
}

#[test]
fn depth_test_off_draws_in_order_and_leaves_the_buffer_alone() {
    let mut d = [0f32; 16];
    let (winners, _) = two_quads(0.3, 0.6, &mut d[..], DepthTest::Off);
    assert!(winners.iter().all(|&w| w >= 6), "the last drawn wins");
    assert!(d.iter().all(|&z| z == 1.0), "cleared to far and never written");
}

#[test]
fn u16_depth_quantisation() {
    assert_eq!(depth_to_u16(0.0), 0);
    assert_eq!(depth_to_u16(1.0), u16::MAX);
    assert_eq!(depth_to_u16(0.5), 32768);
    assert_eq!(depth_to_u16(-0.1), 0);
    assert_eq!(depth_to_u16(2.0), u16::MAX);
    assert_eq!(depth_to_u16(f32::NAN), 0);
}

/// The depth buffer after drawing one screen-space triangle (no culling) on a 16x16 frame cleared to 1.
fn depth_of_triangle(positions: &[Vec3; 3]) -> Vec<f32> {
    let mesh = Mesh::new(positions, Indices::Sequential).unwrap();
    let mut color = vec![0u32; 16 * 16];
    let mut depth = vec![1f32; 16 * 16];
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], 16, 16).unwrap();
    let state = DrawState { cull: rastty_core::pipeline::Cull::None, ..DrawState::default() };
    draw(&mut target, &mesh, &ScreenSpace { width: 16.0, height: 16.0 }, &state).unwrap();
    depth
}

/// Depth is interpolated from plane equations in `f32`, which can round a hair past the vertices' range: with
/// vertices on pixel centres at depths 0, 0 and about 1e-30, pixels came out at -9.4e-38 before the depth buffer
/// clamped them (fuzzing finding F3). Stored depth never leaves `[0, 1]`.
#[test]
fn stored_depth_never_goes_below_zero() {
    // The case found: the centre of pixel (5, 5) is the vertex at depth 0, and was stored as -9.403955e-38.
    let found = [Vec3::new(12.5, 11.5, 1.248_072_9e-30), Vec3::new(5.5, 5.5, 0.0), Vec3::new(4.5, 2.5, 0.0)];
    let depth = depth_of_triangle(&found);
    assert_eq!(depth[5 * 16 + 5].to_bits(), 0.0f32.to_bits(), "exactly +0 at the vertex");
    assert!(depth.iter().all(|&z| (0.0..=1.0).contains(&z)), "{depth:?}");

    let mut rng = 0x2545_F491_4F6C_DD1Du64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 40) as f32 / (1u64 << 24) as f32
    };
    for _ in 0..2000 {
        let tiny = 1e-30 * (1.0 + next());
        let mut corner = |z: f32| Vec3::new((16.0 * next()).floor() + 0.5, (16.0 * next()).floor() + 0.5, z);
        let positions = [corner(tiny), corner(0.0), corner(0.0)];
        let depth = depth_of_triangle(&positions);
        assert!(depth.iter().all(|&z| (0.0..=1.0).contains(&z)), "{positions:?}: {depth:?}");
    }
}

/// [`ScreenSpace`] without its fragment stage: a depth-only shader.
struct DepthOnly(ScreenSpace);

impl Shader for DepthOnly {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    const FRAGMENT_STAGE: bool = false;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.0.position(mesh, i)
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        unreachable!("a depth-only shader's fragment stage never runs")
    }
}

/// How [`draw_in_bands`] draws.
#[derive(Clone, Copy, Debug)]
enum Pass {
    /// [`ScreenSpace`], with [`draw`].
    Shaded,
    /// [`DepthOnly`], with [`draw`]: the depth stage chosen per draw.
    DepthOnly,
    /// [`DepthOnly`], with [`draw_unspecialised`]: the depth stage chosen per pixel.
    DepthOnlyUnspecialised,
}

/// Draws `mesh` (screen-space positions) into a `width x height` frame in bands of `band` rows, each band into its
/// own rows of `depth` and of a colour buffer cleared to 0, as `pass` says; returns the draws' summed counts and
/// the colours.
fn draw_in_bands<T>(
    pass: Pass,
    mesh: &Mesh<'_>,
    state: &DrawState,
    depth: &mut [T],
    size: (u32, u32),
    band: u32,
) -> (DrawStats, Vec<u32>)
where
    for<'a> &'a mut [T]: DepthBuffer,
{
    let (width, height) = size;
    let (w, h) = (width as f32, height as f32);
    let (shader, depth_only_shader) =
        (ScreenSpace { width: w, height: h }, DepthOnly(ScreenSpace { width: w, height: h }));
    let mut color = vec![0u32; depth.len()];
    let mut stats = DrawStats::default();
    let values = band as usize * width as usize;
    for (i, (d, c)) in depth.chunks_mut(values).zip(color.chunks_mut(values)).enumerate() {
        let start = i as u32 * band;
        let rows = start..start + (d.len() / width as usize) as u32;
        let mut target = Target::band(Rgb888(c), d, width, height, rows).unwrap();
        stats += match pass {
            Pass::Shaded => draw(&mut target, mesh, &shader, state),
            Pass::DepthOnly => draw(&mut target, mesh, &depth_only_shader, state),
            Pass::DepthOnlyUnspecialised => draw_unspecialised(&mut target, mesh, &depth_only_shader, state),
        }
        .unwrap();
    }
    (stats, color)
}

/// A depth-only shader stores exactly the depths a shading one stores, counts the same fragments and writes no
/// colour: whether its rows are worked out several pixels at a time (edge values that fit `i32`) or pixel by pixel
/// (larger ones, `f32` edges), in bands, over stored depths of every kind (NaN, negative, -0.0, infinite), with
/// `f32` and `u16` depth, with the test on and off, with the depth stage chosen per draw and per pixel.
#[test]
fn depth_only_passes_store_what_colour_passes_store() {
    let size = (61u32, 37u32);
    let mut positions = Vec::new();
    // Small and medium triangles scattered over the frame, overlapping, some past its edges, depths from -0.2 to
    // 1.2; the frame's width is no multiple of the lanes, so groups of pixels reach past rows' ends.
    let mut seed = 12_345u32;
    let mut next = || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    for _ in 0..300 {
        let (cx, cy, r) = (next() * 70.0 - 5.0, next() * 46.0 - 5.0, 1.0 + next() * next() * 30.0);
        for _ in 0..3 {
            positions.push(Vec3::new(cx + (next() - 0.5) * r, cy + (next() - 0.5) * r, next() * 1.4 - 0.2));
        }
    }
    // The fuzzing case of `stored_depth_never_goes_below_zero`, whose depth rounds below zero at a pixel.
    positions.extend([Vec3::new(12.5, 11.5, 1.248_072_9e-30), Vec3::new(5.5, 5.5, 0.0), Vec3::new(4.5, 2.5, 0.0)]);
    // Triangles far larger than the frame: their edge values leave `i32`.
    positions.extend([
        Vec3::new(-9000.0, -7000.0, 0.25),
        Vec3::new(9000.0, -100.0, 0.5),
        Vec3::new(10.0, 9000.0, 0.05),
        Vec3::new(-3000.0, 40.0, 0.3),
        Vec3::new(30.0, -4000.0, 0.1),
        Vec3::new(5000.0, 5000.0, 0.7),
    ]);
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let pixels = (size.0 * size.1) as usize;
    let cleared = vec![1.0f32; pixels];
    let strewn: Vec<f32> = (0..pixels)
        .map(|i| match i % 23 {
            0 => f32::NAN,
            5 => -0.5,
            9 => -0.0,
            13 => f32::INFINITY,
            17 => 0.0,
            _ => 0.6,
        })
        .collect();
    let cleared16 = vec![u16::MAX; pixels];
    let strewn16: Vec<u16> = (0..pixels).map(|i| [u16::MAX, 0, 30_000, 50_000][i % 4]).collect();
    let mut stored_any = false;
    for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
        for depth_test in [DepthTest::Less, DepthTest::Off] {
            let state = DrawState { edges, depth_test, ..common::both_sides() };
            for band in [size.1, 5, 1] {
                for initial in [&cleared, &strewn] {
                    let mut shaded = initial.clone();
                    let (expected, colours) = draw_in_bands(Pass::Shaded, &mesh, &state, &mut shaded, size, band);
                    stored_any |= shaded != *initial && colours.iter().any(|&c| c != 0);
                    for pass in [Pass::DepthOnly, Pass::DepthOnlyUnspecialised] {
                        let mut depth_only = initial.clone();
                        let (stats, untouched) = draw_in_bands(pass, &mesh, &state, &mut depth_only, size, band);
                        let bits = |v: &[f32]| v.iter().map(|z| z.to_bits()).collect::<Vec<_>>();
                        let case = format!("{pass:?}, {edges:?}, {depth_test:?}, bands of {band}");
                        assert_eq!(bits(&depth_only), bits(&shaded), "{case}");
                        assert_eq!(stats, expected, "{case}");
                        assert!(untouched.iter().all(|&c| c == 0), "a depth-only shader wrote colour");
                    }
                }
                for initial in [&cleared16, &strewn16] {
                    let mut shaded = initial.clone();
                    let (expected, _) = draw_in_bands(Pass::Shaded, &mesh, &state, &mut shaded, size, band);
                    for pass in [Pass::DepthOnly, Pass::DepthOnlyUnspecialised] {
                        let mut depth_only = initial.clone();
                        let (stats, untouched) = draw_in_bands(pass, &mesh, &state, &mut depth_only, size, band);
                        let case = format!("u16, {pass:?}, {edges:?}, {depth_test:?}, bands of {band}");
                        assert_eq!(depth_only, shaded, "{case}");
                        assert_eq!(stats, expected, "{case}");
                        assert!(untouched.iter().all(|&c| c == 0), "a depth-only shader wrote colour");
                    }
                }
            }
        }
    }
    assert!(stored_any, "the draws stored depths");
}
