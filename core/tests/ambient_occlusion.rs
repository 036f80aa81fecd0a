//! Screen-space ambient occlusion: lone planes at any angle, convex edges and coarse distant depths stay exactly as
//! they were; inside corners darken, less so farther from the crease; background and `strength = 0` change nothing;
//! bands with [`AmbientOcclusion::margin_rows`] of depth around them equal the whole frame; bad input is refused
//! with the exact error; orthographic cameras work as perspective ones do; a scene scaled up or down darkens the
//! same; wide frames darken alike across the strips the work is split into.

use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::occlusion::{AmbientOcclusion, OcclusionError};
use rastty_core::pipeline::{Cull, DrawState, Fragment, Shader, Slopes, draw};
use rastty_core::target::{NoColor, Target};

/// The defaults, darkening the stored codes: these tests read each pixel's factor from its code. The darkening of
/// light is `occlusion::tests::darkening_applies_to_light_or_to_codes`.
const DEFAULT: AmbientOcclusion = AmbientOcclusion { space: ShadingSpace::Encoded, ..AmbientOcclusion::DEFAULT };

/// The colour of every drawn pixel before occlusion: 200 in each channel, so a factor shows as `channel / 200`.
const SURFACE: u32 = 0x00C8_C8C8;
/// The colour of background pixels: distinct in each channel, so any change to it shows.
const BACKGROUND: u32 = 0x0012_3456;

/// Positions from world space to clip space; nothing else (the test colours pixels from the depth afterwards).
struct DepthOnly {
    clip_from_world: Mat4,
}

impl Shader for DepthOnly {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_world.project_point(mesh.position(i))
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ZERO
    }
}

/// A rendered frame: the camera's projection, the depth buffer, and the colour before occlusion.
struct Scene {
    width: u32,
    height: u32,
    view: Mat4,
    projection: Mat4,
    depth: Vec<f32>,
}

impl Scene {
    /// Draws the quads (four corners each, in order around the edge) through `view` and `projection`.
    fn render(width: u32, height: u32, view: Mat4, projection: Mat4, quads: &[[Vec3; 4]]) -> Self {
        let positions: Vec<Vec3> = quads.iter().flat_map(|&[a, b, c, d]| [a, b, c, a, c, d]).collect();
        let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
        let mut depth = vec![0f32; (width * height) as usize];
        let mut target = Target::new(NoColor, &mut depth[..], width, height).unwrap();
        target.clear(Vec3::ZERO);
        let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
        let stats = draw(&mut target, &mesh, &DepthOnly { clip_from_world: projection * view }, &state).unwrap();
        assert_eq!(stats.rasterized, 2 * quads.len() as u64, "every triangle reaches the rasterizer");
        Self { width, height, view, projection, depth }
    }

    /// The colour before occlusion: [`SURFACE`] where something was drawn, [`BACKGROUND`] elsewhere.
    fn color(&self) -> Vec<u32> {
        self.depth.iter().map(|&d| if d < 1.0 { SURFACE } else { BACKGROUND }).collect()
    }

    /// The whole frame's colour after `ao`.
    fn occluded(&self, ao: &AmbientOcclusion) -> Vec<u32> {
        let mut color = self.color();
        let (w, h) = (self.width, self.height);
        ao.apply(&self.projection, &self.depth, 0..h, &mut color, 0..h, w, h).unwrap();
        color
    }

    /// The frame's colour after `ao` applied band by band, `band` rows at a time, each with `margin` rows of depth
    /// above and below (clamped to the frame).
    fn occluded_in_bands(&self, ao: &AmbientOcclusion, band: u32, margin: u32) -> Vec<u32> {
        let (w, h) = (self.width, self.height);
        let whole = self.color();
        let mut out = Vec::new();
        for start in (0..h).step_by(band as usize) {
            let rows = start..(start + band).min(h);
            let depth_rows = rows.start.saturating_sub(margin)..(rows.end + margin).min(h);
            let depth = &self.depth[(depth_rows.start * w) as usize..(depth_rows.end * w) as usize];
            let mut color = whole[(rows.start * w) as usize..(rows.end * w) as usize].to_vec();
            ao.apply(&self.projection, depth, depth_rows, &mut color, rows, w, h).unwrap();
            out.extend(color);
        }
        out
    }

    /// Screen row of world point `p` (the row whose centres lie nearest it).
    fn row_of(&self, p: Vec3) -> u32 {
        let clip = (self.projection * self.view).project_point(p);
        let y = (1.0 - clip.y / clip.w) * 0.5 * self.height as f32;
        y.floor() as u32
    }
}

/// The factor each pixel's channels were multiplied by: `green / 200`.
fn factor(color: u32) -> f32 {
    ((color >> 8) & 0xFF) as f32 / 200.0
}

/// Asserts two frames `width` pixels wide are equal, naming the first pixel that differs and how many do.
#[track_caller]
fn assert_same(actual: &[u32], expected: &[u32], width: u32) {
    assert_eq!(actual.len(), expected.len());
    let differ: Vec<usize> = (0..actual.len()).filter(|&i| actual[i] != expected[i]).collect();
    if let Some(&i) = differ.first() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        panic!("{} pixels differ, first ({x}, {y}): {:06x}, expected {:06x}", differ.len(), actual[i], expected[i]);
    }
}

/// Mean factor over row `y` (every pixel of the row is surface).
fn row_factor(color: &[u32], width: u32, y: u32) -> f32 {
    let row = &color[(y * width) as usize..((y + 1) * width) as usize];
    row.iter().map(|&c| factor(c)).sum::<f32>() / width as f32
}

/// A floor (y = 0, z from -1 to 4) meeting a wall (z = -1, y from 0 up) along a crease parallel to x, seen from
/// in front and above: the crease is a screen row, floor below it, wall above.
fn corner_quads(wall_top: f32) -> [[Vec3; 4]; 2] {
    let floor = [
        Vec3::new(-20.0, 0.0, 4.0),
        Vec3::new(20.0, 0.0, 4.0),
        Vec3::new(20.0, 0.0, -1.0),
        Vec3::new(-20.0, 0.0, -1.0),
    ];
    let wall = [
        Vec3::new(-20.0, 0.0, -1.0),
        Vec3::new(20.0, 0.0, -1.0),
        Vec3::new(20.0, wall_top, -1.0),
        Vec3::new(-20.0, wall_top, -1.0),
    ];
    [floor, wall]
}

/// The corner seen through a perspective camera, 128x96.
fn perspective_corner() -> Scene {
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::new(0.0, 0.3, -1.0), Vec3::Y).unwrap();
    let projection = perspective(1.0, 128.0 / 96.0, 0.1, 20.0).unwrap();
    Scene::render(128, 96, view, projection, &corner_quads(10.0))
}

/// A unit cube standing on the floor of [`corner_quads`], in front of the wall: its five visible-or-not faces.
fn box_quads() -> [[Vec3; 4]; 5] {
    let (x0, x1, y0, y1, z0, z1) = (-0.5, 0.5, 0.0, 1.0, 0.0, 1.0);
    let p = |x, y, z| Vec3::new(x, y, z);
    [
        [p(x0, y1, z1), p(x1, y1, z1), p(x1, y1, z0), p(x0, y1, z0)],
        [p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1)],
        [p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0), p(x1, y0, z0)],
        [p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1), p(x0, y1, z0)],
        [p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1), p(x1, y0, z1)],
    ]
}

/// A box on a floor in front of a low wall, with background above the wall: creases, contacts, silhouettes and
/// sky, 128x96, perspective.
fn box_scene() -> Scene {
    let view = look_at(Vec3::new(1.2, 2.0, 3.5), Vec3::new(0.0, 0.5, 0.0), Vec3::Y).unwrap();
    let projection = perspective(1.0, 128.0 / 96.0, 0.1, 20.0).unwrap();
    let quads: Vec<[Vec3; 4]> = corner_quads(1.5).into_iter().chain(box_quads()).collect();
    Scene::render(128, 96, view, projection, &quads)
}

/// How far from the crease the surface seen along row `y` of a corner scene is (the same for the whole row: the
/// crease runs along x and the camera does not roll): the view ray through the row's middle meets the floor
/// (distance `z + 1`) or the wall (distance `y`).
fn crease_distance(scene: &Scene, y: u32) -> f32 {
    let world_from_clip = (scene.projection * scene.view).inverse().unwrap();
    let ndc_y = 1.0 - 2.0 * (y as f32 + 0.5) / scene.height as f32;
    let at = |z: f32| {
        let h = world_from_clip * Vec4::new(0.0, ndc_y, z, 1.0);
        Vec3::new(h.x / h.w, h.y / h.w, h.z / h.w)
    };
    let (near, far) = (at(0.0), at(1.0));
    let dir = far - near;
    // Where the ray meets the floor plane; if that is behind the wall, it meets the wall instead.
    let floor = near + dir * (-near.y / dir.y);
    if floor.z >= -1.0 {
        floor.z + 1.0
    } else {
        let wall = near + dir * ((-1.0 - near.z) / dir.z);
        wall.y
    }
}

/// Rows above and below a pixel whose searches its occlusion may come from: the cells of the rows it
/// interpolates between and, through the filter, one cell row (two pixel rows) beyond each.
const FILTER_ROWS: u32 = 3;

/// Checks a corner scene's occlusion row by row: exactly unchanged where the surface is farther than the radius
/// from the crease in the row and in the [`FILTER_ROWS`] on each side, every pixel darker within half the radius,
/// the darkest row next to the crease, and the mean factor never falling (beyond noise) as the rows move away
/// from it on either side.
fn check_corner(scene: &Scene) {
    let ao = DEFAULT;
    let out = scene.occluded(&ao);
    let (w, h) = (scene.width, scene.height);
    let distances: Vec<f32> = (0..h).map(|y| crease_distance(scene, y)).collect();
    let mut near_rows = 0;
    for y in 0..h {
        let distance = distances[y as usize];
        let around = &distances[y.saturating_sub(FILTER_ROWS) as usize..(y + FILTER_ROWS + 1).min(h) as usize];
        let row = &out[(y * w) as usize..((y + 1) * w) as usize];
        if around.iter().all(|&d| d > ao.radius * 1.01) {
            assert!(row.iter().all(|&c| c == SURFACE), "row {y}, {distance} from the crease, is unchanged");
        } else if distance < ao.radius * 0.5 {
            near_rows += 1;
            assert!(row.iter().all(|&c| c < SURFACE), "row {y}, {distance} from the crease, is darker everywhere");
        }
    }
    assert!(near_rows >= 4, "the scene shows the crease's neighbourhood ({near_rows} rows)");
    let crease = scene.row_of(Vec3::new(0.0, 0.0, -1.0));
    let means: Vec<f32> = (0..h).map(|y| row_factor(&out, w, y)).collect();
    let darkest = (0..h).min_by(|&a, &b| means[a as usize].total_cmp(&means[b as usize])).unwrap();
    assert!(darkest.abs_diff(crease) <= 1, "darkest row {darkest}, crease at row {crease}");
    // Cosine-weighted: a horizon h above the tangent plane hides sin^2 h of its slice, so a crease darkens less
    // than the sine alone would make it.
    assert!(means[darkest as usize] < 0.85, "the crease is clearly darker: {}", means[darkest as usize]);
    for y in darkest..h - 1 {
        assert!(means[y as usize + 1] >= means[y as usize] - 0.005, "rows {y}.. below the crease: {means:?}");
    }
    for y in 1..=darkest {
        assert!(means[y as usize - 1] >= means[y as usize] - 0.005, "rows ..{y} above the crease: {means:?}");
    }
}

#[test]
fn a_plane_facing_the_camera_is_unchanged() {
    // Analytic depth: one plane square to the view axis over the middle of the frame, background around it.
    let (w, h) = (96u32, 64u32);
    let depth: Vec<f32> =
        (0..w * h).map(|i| if (16..80).contains(&(i % w)) && (8..56).contains(&(i / w)) { 0.9 } else { 1.0 }).collect();
    let color: Vec<u32> = depth.iter().map(|&d| if d < 1.0 { SURFACE } else { BACKGROUND }).collect();
    let projection = perspective(1.0, 1.5, 0.1, 10.0).unwrap();
    let mut out = color.clone();
    DEFAULT.apply(&projection, &depth, 0..h, &mut out, 0..h, w, h).unwrap();
    assert_same(&out, &color, w);
}

#[test]
fn a_rendered_plane_at_any_angle_is_unchanged() {
    // The floor alone, seen obliquely, and a plane tilted about two axes: nothing rises above their tangent planes.
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::new(0.0, 0.3, -1.0), Vec3::Y).unwrap();
    let projection = perspective(1.0, 128.0 / 96.0, 0.1, 20.0).unwrap();
    let floor = Scene::render(128, 96, view, projection, &corner_quads(10.0)[..1]);
    assert!(floor.depth.iter().filter(|&&d| d < 1.0).count() > 128 * 40, "the floor fills much of the frame");
    assert_same(&floor.occluded(&DEFAULT), &floor.color(), floor.width);

    let tilted =
        [Vec3::new(-1.0, -1.0, -0.8), Vec3::new(1.0, -1.0, 0.3), Vec3::new(1.0, 1.0, 0.9), Vec3::new(-1.0, 1.0, -0.2)];
    let view = look_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
    let plane = Scene::render(128, 96, view, projection, &[tilted]);
    assert_same(&plane.occluded(&DEFAULT), &plane.color(), plane.width);
}

#[test]
fn an_inside_corner_darkens_toward_the_crease() {
    check_corner(&perspective_corner());
}

#[test]
fn orthographic_corners_darken_too() {
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::new(0.0, 0.3, -1.0), Vec3::Y).unwrap();
    let projection = orthographic(-2.0, 2.0, -1.5, 1.5, 0.1, 20.0).unwrap();
    let scene = Scene::render(128, 96, view, projection, &corner_quads(10.0));
    check_corner(&scene);
    // Orthographic: the radius spans the same pixels at every depth, 0.5 * (2 / 3) * 96 / 2 = 16 rows; the limit
    // is 128 / 8 = 16, so the margin is 16 + 3 (the rows of cells a pixel depends on).
    assert_eq!(AmbientOcclusion::DEFAULT.margin_rows(&projection, 128, 96), 19);
    let narrow = AmbientOcclusion { radius: 0.3, ..DEFAULT };
    // 0.3 * (2 / 3) * 48 = 9.6 rows, rounded up, plus 3.
    assert_eq!(narrow.margin_rows(&projection, 128, 96), 13);
    assert_same(&scene.occluded_in_bands(&narrow, 10, 13), &scene.occluded(&narrow), 128);
}

#[test]
fn strength_scales_the_darkening_and_zero_changes_nothing() {
    let scene = box_scene();
    let off = AmbientOcclusion { strength: 0.0, ..DEFAULT };
    assert_same(&scene.occluded(&off), &scene.color(), 128);
    // As do no directions, no steps and no radius.
    for ao in [
        AmbientOcclusion { directions: 0, ..DEFAULT },
        AmbientOcclusion { steps: 0, ..DEFAULT },
        AmbientOcclusion { radius: 0.0, ..DEFAULT },
    ] {
        assert_same(&scene.occluded(&ao), &scene.color(), 128);
    }

    let full = scene.occluded(&DEFAULT);
    let half = scene.occluded(&AmbientOcclusion { strength: 0.5, ..DEFAULT });
    let darkened = full.iter().filter(|&&c| c != SURFACE && c != BACKGROUND).count();
    assert!(darkened > 200, "the box scene has occlusion to scale ({darkened} pixels)");
    for ((&f, &hf), &c) in full.iter().zip(&half).zip(&scene.color()) {
        if c == BACKGROUND {
            continue;
        }
        assert!(f <= hf && hf <= c, "full {f:06x} <= half {hf:06x} <= none {c:06x}");
        // Half strength darkens by half as much, to within the rounding of each.
        let (lost_full, lost_half) = (200.0 - factor(f) * 200.0, 200.0 - factor(hf) * 200.0);
        assert!((lost_half - lost_full * 0.5).abs() <= 1.0, "{lost_full} then {lost_half}");
    }
}

#[test]
fn background_is_unchanged_and_occludes_nothing() {
    let scene = box_scene();
    let color = scene.color();
    let background = color.iter().filter(|&&c| c == BACKGROUND).count();
    assert!(background > 128 * 10, "sky above the wall ({background} pixels)");
    let out = scene.occluded(&DEFAULT);
    for (i, (&before, &after)) in color.iter().zip(&out).enumerate() {
        if before == BACKGROUND {
            assert_eq!(after, BACKGROUND, "background pixel {i}");
        }
    }
}

#[test]
fn background_at_the_far_plane_right_behind_a_surface_occludes_nothing() {
    // A floor ending just short of the far plane: the background beyond its far edge reconstructs to points a
    // few hundredths of a unit above the floor, well inside the radius. Taken as surface, they would darken the
    // floor's far edge.
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::new(0.0, 0.3, -1.0), Vec3::Y).unwrap();
    let p = Vec3::new;
    let floor = [p(-1.5, 0.0, 2.0), p(1.5, 0.0, 2.0), p(1.5, 0.0, -1.0), p(-1.5, 0.0, -1.0)];
    let far = floor.iter().map(|&c| -view.transform_point(c).z).fold(0.0, f32::max) + 0.02;
    let projection = perspective(1.0, 128.0 / 96.0, 0.1, far).unwrap();
    let scene = Scene::render(128, 96, view, projection, &[floor]);
    let color = scene.color();
    assert!(color.iter().filter(|&&c| c == SURFACE).count() > 128 * 20, "the floor fills much of the frame");
    assert_same(&scene.occluded(&DEFAULT), &color, 128);
    // The same depths with the background moved onto the far plane as if it were surface: the far edge darkens.
    let mut closed = scene.depth.clone();
    closed.iter_mut().filter(|d| **d >= 1.0).for_each(|d| *d = 0.999_999);
    let mut out = vec![SURFACE; closed.len()];
    DEFAULT.apply(&projection, &closed, 0..96, &mut out, 0..96, 128, 96).unwrap();
    assert!(out.iter().zip(&color).any(|(&o, &c)| c == SURFACE && o < SURFACE), "a far-plane surface occludes");
}

#[test]
fn convex_edges_are_not_darkened() {
    // A lone box seen from above one of its corners: three faces meeting at convex edges, nothing rising above
    // any of them. The normals at the edges come from the side that continues each face.
    let view = look_at(Vec3::new(1.6, 2.2, 2.4), Vec3::new(0.0, 0.5, 0.5), Vec3::Y).unwrap();
    let projection = perspective(1.0, 1.0, 0.1, 20.0).unwrap();
    let scene = Scene::render(96, 96, view, projection, &box_quads());
    assert_same(&scene.occluded(&DEFAULT), &scene.color(), 96);
}

#[test]
fn a_surface_far_in_front_casts_no_halo() {
    // A square 3 units in front of a wall: farther apart than the radius, so neither occludes the other.
    let view = look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
    let projection = perspective(1.0, 1.0, 0.1, 20.0).unwrap();
    let p = Vec3::new;
    let wall = [p(-9.0, -9.0, -1.0), p(9.0, -9.0, -1.0), p(9.0, 9.0, -1.0), p(-9.0, 9.0, -1.0)];
    let square = [p(-0.5, -0.5, 2.0), p(0.5, -0.5, 2.0), p(0.5, 0.5, 2.0), p(-0.5, 0.5, 2.0)];
    let scene = Scene::render(96, 96, view, projection, &[wall, square]);
    assert_same(&scene.occluded(&DEFAULT), &scene.color(), 96);
}

#[test]
fn bands_with_the_margin_equal_the_whole_frame() {
    let scene = box_scene();
    let ao = DEFAULT;
    let whole = scene.occluded(&ao);
    let margin = ao.margin_rows(&scene.projection, scene.width, scene.height);
    // Perspective: the radius near the camera spans more than the limit, 128 / 8 = 16 rows, plus 3.
    assert_eq!(margin, 19);
    // Below the limit: 0.02 at the near plane 0.5 spans 0.02 / tan(0.5) * 48 / 0.5 = 3.51 rows, so 4 + 3.
    let near = perspective(1.0, 128.0 / 96.0, 0.5, 20.0).unwrap();
    assert_eq!(AmbientOcclusion { radius: 0.02, ..ao }.margin_rows(&near, 128, 96), 7);
    for band in [1, 13, 16, 40] {
        assert_same(&scene.occluded_in_bands(&ao, band, margin), &whole, 128);
    }
    // Without the margin, samples across band edges go missing and some pixels differ.
    assert_ne!(scene.occluded_in_bands(&ao, 16, 0), whole);
}

#[test]
fn the_defaults() {
    let ao = AmbientOcclusion::default();
    assert_eq!(
        ao,
        AmbientOcclusion { radius: 0.5, strength: 1.0, directions: 4, steps: 3, space: ShadingSpace::Linear }
    );
}

#[test]
fn bad_input_is_refused_with_the_exact_error() {
    let (w, h) = (8u32, 6u32);
    let projection = perspective(1.0, 1.0, 0.1, 10.0).unwrap();
    let depth = vec![0.5f32; 48];
    let mut color = vec![SURFACE; 48];
    let ao = DEFAULT;
    let run = |ao: &AmbientOcclusion, projection: &Mat4, depth: &[f32], depth_rows, color: &mut [u32], rows, w, h| {
        ao.apply(projection, depth, depth_rows, color, rows, w, h)
    };
    use OcclusionError as E;
    assert_eq!(run(&ao, &projection, &depth, 0..6, &mut color, 0..6, w, h), Ok(()));
    assert_eq!(
        run(&ao, &projection, &depth[..40], 0..6, &mut color, 0..6, w, h),
        Err(E::DepthLength { expected: 48, actual: 40 })
    );
    assert_eq!(
        run(&ao, &projection, &depth, 0..6, &mut color[..47], 0..6, w, h),
        Err(E::ColorLength { expected: 48, actual: 47 })
    );
    assert_eq!(run(&ao, &projection, &depth[..24], 1..4, &mut color[..16], 2..4, w, h), Ok(()));
    assert_eq!(
        run(&ao, &projection, &depth[..24], 1..4, &mut color[..16], 0..2, w, h),
        Err(E::DepthRows { depth_rows: 1..4, rows: 0..2, height: 6 })
    );
    assert_eq!(
        run(&ao, &projection, &depth[..24], 1..4, &mut color[..16], 3..5, w, h),
        Err(E::DepthRows { depth_rows: 1..4, rows: 3..5, height: 6 })
    );
    assert_eq!(
        run(&ao, &projection, &[0.5; 56], 0..7, &mut color[..8], 0..1, w, h),
        Err(E::DepthRows { depth_rows: 0..7, rows: 0..1, height: 6 })
    );
    assert_eq!(
        run(&ao, &projection, &depth, 0..6, &mut color[..0], 3..3, w, h),
        Err(E::Rows { rows: 3..3, height: 6 })
    );
    assert_eq!(
        run(&ao, &projection, &depth, 0..6, &mut color[..8], 6..7, w, h),
        Err(E::Rows { rows: 6..7, height: 6 })
    );
    assert_eq!(run(&ao, &projection, &depth, 0..6, &mut color, 0..6, 0, h), Err(E::Frame { width: 0, height: 6 }));
    assert_eq!(
        run(&ao, &projection, &depth, 0..6, &mut color, 0..6, w, 9000),
        Err(E::Frame { width: 8, height: 9000 })
    );
    let singular = Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0));
    assert_eq!(run(&ao, &singular, &depth, 0..6, &mut color, 0..6, w, h), Err(E::Projection));
    for bad in [f32::NAN, f32::INFINITY, -0.5] {
        let r = AmbientOcclusion { radius: bad, ..ao };
        assert_eq!(run(&r, &projection, &depth, 0..6, &mut color, 0..6, w, h), Err(E::Settings), "radius {bad}");
        let s = AmbientOcclusion { strength: bad, ..ao };
        assert_eq!(run(&s, &projection, &depth, 0..6, &mut color, 0..6, w, h), Err(E::Settings), "strength {bad}");
    }
    assert!(color.iter().all(|&c| c == SURFACE), "refused calls (and a flat depth) change nothing");
    assert_eq!(
        E::DepthRows { depth_rows: 1..4, rows: 0..2, height: 6 }.to_string(),
        "depth rows 1..4 do not contain rows 0..2 within a 6-row frame"
    );
    assert_eq!(
        E::DepthLength { expected: 48, actual: 40 }.to_string(),
        "the depth slice holds 40 values, its rows have 48 pixels"
    );
}

#[test]
fn depth_rounding_on_a_distant_plane_does_not_occlude() {
    // Near 0.01 and far 1000: at 30 to 100 units the f32 depths of a floor are coarse enough that neighbouring
    // points wobble above and below the plane. The angle bias absorbs that (without it, over a thousand pixels of
    // each floor darken).
    for (distance, radius) in [(30.0, 2.0), (100.0, 5.0)] {
        let view = look_at(Vec3::new(0.0, distance * 0.5, distance), Vec3::ZERO, Vec3::Y).unwrap();
        let projection = perspective(1.0, 128.0 / 96.0, 0.01, 1000.0).unwrap();
        let s = distance * 3.0;
        let floor = [Vec3::new(-s, 0.0, s), Vec3::new(s, 0.0, s), Vec3::new(s, 0.0, -s), Vec3::new(-s, 0.0, -s)];
        let scene = Scene::render(128, 96, view, projection, &[floor]);
        assert!(scene.depth.iter().filter(|&&d| d < 1.0).count() > 128 * 40, "the floor fills much of the frame");
        assert_same(&scene.occluded(&AmbientOcclusion { radius, ..DEFAULT }), &scene.color(), 128);
    }
}

#[test]
fn the_scale_of_the_scene_does_not_matter() {
    // The corner scaled from a thousandth to ten thousand times its size, camera, clip planes and radius with it:
    // the same NDC depths up to rounding, so the same darkening. (Unscaled products of view-space differences
    // underflow f32 a few hundred units from the camera.)
    let reference = perspective_corner().occluded(&DEFAULT);
    for s in [0.001f32, 1000.0, 10_000.0] {
        let view = look_at(Vec3::new(0.0, 1.5, 2.5) * s, Vec3::new(0.0, 0.3, -1.0) * s, Vec3::Y).unwrap();
        let projection = perspective(1.0, 128.0 / 96.0, 0.1 * s, 20.0 * s).unwrap();
        let scene = Scene::render(128, 96, view, projection, &corner_quads(10.0).map(|q| q.map(|p| p * s)));
        let out = scene.occluded(&AmbientOcclusion { radius: 0.5 * s, ..DEFAULT });
        for (i, (&a, &b)) in out.iter().zip(&reference).enumerate() {
            assert!(((a >> 8) & 0xFF).abs_diff((b >> 8) & 0xFF) <= 1, "scale {s}, pixel {i}: {a:06x}, {b:06x}");
        }
    }
}

#[test]
fn columns_far_apart_darken_alike() {
    // An orthographic corner 400 pixels wide: every row has one depth, so away from the sides (farther than the
    // reach of 16 pixels and the 3 of the filter) every column darkens as the one 4 pixels on (the period of the
    // turned directions), within rounding. The columns cross the seams between strips of cells (128 pixels).
    let (w, h) = (400u32, 96u32);
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::new(0.0, 0.3, -1.0), Vec3::Y).unwrap();
    let projection = orthographic(-6.25, 6.25, -1.5, 1.5, 0.1, 20.0).unwrap();
    let mut scene = Scene::render(w, h, view, projection, &corner_quads(10.0));
    for row in scene.depth.chunks_exact_mut(w as usize) {
        let middle = row[w as usize / 2];
        row.fill(middle);
    }
    let out = scene.occluded(&DEFAULT);
    let darkened = out.iter().filter(|&&c| c != SURFACE && c != BACKGROUND).count();
    assert!(darkened > 400 * 8, "the crease darkens ({darkened} pixels)");
    for y in 0..h {
        for x in 20..w - 24 {
            let (a, b) = (out[(y * w + x) as usize], out[(y * w + x + 4) as usize]);
            assert!(((a >> 8) & 0xFF).abs_diff((b >> 8) & 0xFF) <= 1, "({x}, {y}): {a:06x}, 4 on: {b:06x}");
        }
    }
}
