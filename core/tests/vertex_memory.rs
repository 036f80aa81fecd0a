//! Vertex memory: a target that lends a draw memory for its vertices' screen positions
//! ([`Target::with_vertex_memory`]) gets the position stage run once per vertex into it, and the triangle loop
//! reads from it instead of the vertex cache. It must draw exactly what the vertex cache draws: colours, depths
//! and every count, whole frames and bands, clipped triangles, bad vertices, and memory too short for the mesh
//! (which the draw then leaves alone).

use crate::common;

use common::{AnyColor, AnyDepth, ExactColor, Torus, Transformed, checker_texels};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{DepthTest, DrawState, DrawStats, EdgeArithmetic, Interpolation, ScreenVertex, draw};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, draw_mesh};
use rastty_core::target::{ColorBuffer, DepthBuffer, FrameGeometry, SharedScreenVertices, Target, VertexMemory};
use rastty_core::texture::{FilterMode, Texture, WrapMode};

const W: u32 = 41;
const H: u32 = 29;
const BACKGROUND: Vec3 = Vec3::new(0.05, 0.1, 0.15);

/// One draw to compare.
#[derive(Clone, Copy, Debug)]
enum Scene {
    /// The torus, textured with a checker where the model reads texture coordinates.
    Torus { shading: ShadingModel, state: DrawState },
    /// Raw clip-space triangles over the frame, some of them with bad vertices (see [`raw_mesh`]).
    Raw,
}

/// Positions in clip space: a fan of good triangles over the frame, then triangles with a NaN, an infinite, an
/// all-zero (`w = 0`) and a behind-the-eye vertex; indices past the last vertex come last.
fn raw_mesh() -> (Vec<Vec3>, Vec<u32>) {
    let mut positions = Vec::new();
    let mut indices = Vec::new();
    for i in 0..24u32 {
        let (a, b) = (i as f32 * 0.26, (i + 1) as f32 * 0.26);
        let base = positions.len() as u32;
        positions.extend([
            Vec3::new(0.0, 0.0, 0.3),
            Vec3::new(a.cos(), a.sin(), 0.5),
            Vec3::new(b.cos(), b.sin(), 0.7),
        ]);
        indices.extend([base, base + 1, base + 2]);
    }
    for bad in
        [Vec3::new(f32::NAN, 0.0, 0.5), Vec3::new(f32::INFINITY, 0.2, 0.5), Vec3::ZERO, Vec3::new(0.3, 0.3, -2.0)]
    {
        let base = positions.len() as u32;
        positions.extend([bad, Vec3::new(0.9, -0.8, 0.4), Vec3::new(-0.7, 0.9, 0.6)]);
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 1]);
    }
    let n = positions.len() as u32;
    indices.extend([0, n, 1, n + 5, 2, 3]);
    (positions, indices)
}

/// Draws `scene` into `target` (cleared first); returns its counts.
fn draw_scene<M: VertexMemory>(target: &mut Target<AnyColor<'_>, AnyDepth<'_>, M>, scene: Scene) -> DrawStats {
    target.clear(BACKGROUND);
    match scene {
        Scene::Torus { shading, state } => draw_torus(target, &Torus::new(1.0, 0.4, 24, 12), shading, &state),
        Scene::Raw => {
            let (positions, indices) = raw_mesh();
            let mesh = Mesh::new(&positions, Indices::U32(&indices)).unwrap();
            let shader = Transformed { clip_from_object: Mat4::IDENTITY };
            draw(target, &mesh, &shader, &DrawState { cull: rastty_core::pipeline::Cull::None, ..DrawState::default() })
                .unwrap()
        }
    }
}

/// Draws `torus`, cut by the near plane and textured with a checker where the model reads texture coordinates,
/// into `target` (not cleared); returns its counts.
fn draw_torus<C: ColorBuffer, D: DepthBuffer, M: VertexMemory>(
    target: &mut Target<C, D, M>,
    torus: &Torus,
    shading: ShadingModel,
    state: &DrawState,
) -> DrawStats {
    let texels = checker_texels();
    let lights = [Light::directional(Vec3::new(0.3, 1.0, 0.6), Vec3::ONE)];
    let material = Material {
        specular: Vec3::splat(0.5),
        diffuse: Some(Texture::new(&texels, 8, 8).unwrap()),
        filter: FilterMode::Bilinear,
        wrap: WrapMode::Repeat,
        ..Material::default()
    };
    let lighting =
        Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
    let transforms = common::near_cut_torus_transforms(W, H);
    let object = Object { mesh: torus.mesh(), tangents: None, transforms, shading, material };
    draw_mesh(target, &object, &lighting, state).unwrap().1
}

/// What a draw left: colours, depth bits and counts.
type Picture = (Vec<[u32; 3]>, Vec<u32>, DrawStats);

/// Rows `rows` of `scene`: through the vertex cache when `memory` is `None`, otherwise with that many screen
/// vertices of memory (filled with garbage from an earlier draw of another scene, which must not matter).
fn picture(scene: Scene, rows: core::ops::Range<u32>, memory: Option<usize>) -> Picture {
    let n = (W * (rows.end - rows.start)) as usize;
    let (mut color, mut depth) = (vec![[0u32; 3]; n], vec![0f32; n]);
    let target = common::band(ExactColor(&mut color), &mut depth[..], W, H, rows.clone());
    let stats = match memory {
        None => draw_scene(&mut { target }, scene),
        Some(len) => {
            let mut memory = vec![ScreenVertex::UNSET; len];
            let (mut c, mut d) = (vec![[0u32; 3]; n], vec![0f32; n]);
            let mut other = common::band(ExactColor(&mut c), &mut d[..], W, H, rows).with_vertex_memory(&mut memory);
            draw_scene(&mut other, if matches!(scene, Scene::Raw) { torus(ShadingModel::Flat) } else { Scene::Raw });
            draw_scene(&mut target.with_vertex_memory(&mut memory), scene)
        }
    };
    (color, depth.iter().map(|z| z.to_bits()).collect(), stats)
}

fn torus(shading: ShadingModel) -> Scene {
    Scene::Torus { shading, state: DrawState::default() }
}

fn vertex_count(scene: Scene) -> usize {
    match scene {
        Scene::Torus { .. } => Torus::new(1.0, 0.4, 24, 12).positions.len(),
        Scene::Raw => raw_mesh().0.len(),
    }
}

fn assert_same(name: &str, expected: &Picture, actual: &Picture) {
    assert_eq!(expected.2, actual.2, "{name}: counts");
    assert!(expected.0 == actual.0, "{name}: colours differ");
    assert!(expected.1 == actual.1, "{name}: depths differ");
}

#[test]
fn a_draw_with_vertex_memory_draws_what_the_vertex_cache_draws() {
    let mut scenes = vec![Scene::Raw];
    for shading in [ShadingModel::Phong, ShadingModel::Gouraud, ShadingModel::Flat, ShadingModel::Unlit] {
        for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
            for depth_test in [DepthTest::Less, DepthTest::Off] {
                for interpolation in [Interpolation::PerspectiveCorrect, Interpolation::Affine] {
                    let state = DrawState { edges, depth_test, interpolation, ..DrawState::default() };
                    scenes.push(Scene::Torus { shading, state });
                }
            }
        }
    }
    let mut clipped = 0;
    for scene in scenes {
        let n = vertex_count(scene);
        for rows in [0..H, 0..1, 7..16, H - 3..H] {
            let expected = picture(scene, rows.clone(), None);
            clipped += expected.2.clipped;
            // Exactly the mesh's vertices, more, and too few (the draw then uses the cache).
            for memory in [n, n + 5, n - 1] {
                let name = format!("{scene:?}, rows {rows:?}, memory for {memory} of {n} vertices");
                assert_same(&name, &expected, &picture(scene, rows.clone(), Some(memory)));
            }
        }
    }
    assert!(clipped > 0, "the near plane cuts the torus");
}

#[test]
fn bad_vertices_are_counted_alike_with_vertex_memory() {
    let (positions, _) = raw_mesh();
    let expected = picture(Scene::Raw, 0..H, None);
    let with_memory = picture(Scene::Raw, 0..H, Some(positions.len()));
    assert_same("raw triangles", &expected, &with_memory);
    let stats = with_memory.2;
    // The NaN and infinite vertices' triangles and the two indices past the end are invalid; every input
    // triangle is counted once.
    assert_eq!(stats.invalid, 2 * 2 + 2, "{stats:?}");
    assert_eq!(
        stats.triangles_in,
        stats.invalid + stats.outside + stats.culled + stats.degenerate + stats.rasterized,
        "{stats:?}"
    );
    assert!(stats.clipped >= 2, "the vertex behind the eye is clipped: {stats:?}");
    assert!(stats.fragments > 0, "{stats:?}");
}

/// The frame drawn in bands, each band's target lent `shared` (computed with `compute_matrix` in two parts,
/// recorded as computed with `key_matrix`).
fn banded_with_shared(state: &DrawState, compute_matrix: &Mat4, key_matrix: &Mat4) -> Picture {
    let torus = Torus::new(1.0, 0.4, 24, 12);
    let n = torus.positions.len();
    let mut vertices = vec![ScreenVertex::UNSET; n];
    let (head, tail) = vertices.split_at_mut(n / 3);
    let bits = state.subpixel_bits;
    SharedScreenVertices::compute(&torus.positions, compute_matrix, (W, H), bits, 0, head).unwrap();
    SharedScreenVertices::compute(&torus.positions, compute_matrix, (W, H), bits, n / 3, tail).unwrap();
    let shared = SharedScreenVertices::new(&vertices, &torus.positions, key_matrix, (W, H), bits);
    let (mut color, mut depth) = (vec![[0u32; 3]; (W * H) as usize], vec![0f32; (W * H) as usize]);
    let mut stats = DrawStats::default();
    let (mut color_rest, mut depth_rest) = (&mut color[..], &mut depth[..]);
    for rows in [0..1, 1..9, 9..H - 3, H - 3..H] {
        let len = (W * (rows.end - rows.start)) as usize;
        let (c, c_rest) = std::mem::take(&mut color_rest).split_at_mut(len);
        let (d, d_rest) = std::mem::take(&mut depth_rest).split_at_mut(len);
        (color_rest, depth_rest) = (c_rest, d_rest);
        let mut band = common::band(ExactColor(c), d, W, H, rows);
        let mut target = band.for_draw(FrameGeometry { vertices: Some(shared), bins: &[] });
        target.clear(BACKGROUND);
        stats += draw_torus(&mut target, &torus, ShadingModel::Phong, state);
    }
    (color, depth.iter().map(|z| z.to_bits()).collect(), stats)
}

/// The frame's screen vertices computed once, in two parts, and lent to every band give the pixels and depths of
/// the whole frame drawn through the vertex cache, for both edge arithmetics and depth tests. Every triangle is
/// counted once per band and the fragments are the same; a band counts the triangles outside its rows as
/// rasterized (set-up finds no centre) where its own outcodes would have rejected them.
#[test]
fn a_frame_drawn_in_bands_from_shared_screen_vertices_draws_the_whole_frame() {
    let matrix = common::near_cut_torus_transforms(W, H).clip_from_object;
    for edges in [EdgeArithmetic::FixedPoint, EdgeArithmetic::Float] {
        for depth_test in [DepthTest::Less, DepthTest::Off] {
            let state = DrawState { edges, depth_test, ..DrawState::default() };
            let expected = picture(Scene::Torus { shading: ShadingModel::Phong, state }, 0..H, None);
            let banded = banded_with_shared(&state, &matrix, &matrix);
            let name = format!("{edges:?}, {depth_test:?}");
            assert!(expected.0 == banded.0, "{name}: colours differ");
            assert!(expected.1 == banded.1, "{name}: depths differ");
            assert_eq!(banded.2.triangles_in, 4 * expected.2.triangles_in, "{name}");
            assert_eq!(banded.2.fragments, expected.2.fragments, "{name}");
            assert!(expected.2.clipped > 0, "{name}: the near plane cuts the torus");
        }
    }
}

/// The shared vertices are read when they are the draw's, and only then: vertices computed with another matrix
/// but recorded as the draw's change the picture; recorded as another matrix's, the draw ignores them.
#[test]
fn shared_screen_vertices_are_used_only_for_the_draw_they_were_computed_for() {
    let state = DrawState::default();
    let matrix = common::near_cut_torus_transforms(W, H).clip_from_object;
    let other = Mat4::from_scale(Vec3::splat(0.5)) * matrix;
    let expected = picture(Scene::Torus { shading: ShadingModel::Phong, state }, 0..H, None);
    let read = banded_with_shared(&state, &other, &matrix);
    assert!(expected.0 != read.0, "vertices recorded as the draw's are read");
    let ignored = banded_with_shared(&state, &other, &other);
    assert!(expected.0 == ignored.0 && expected.1 == ignored.1, "vertices of another matrix are ignored");
}
