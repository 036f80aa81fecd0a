//! Shadow maps: the depth bias holds against shadow acne (a lit surface shading itself) at every light angle up
//! to grazing, and against peter-panning (a shadow detached from its caster), and PCF softens only the edge; the
//! same for a point light among the objects, whose map is a cube, with shadows across its faces' seams.
//!
//! The scene is a ground square at `y = 0` and a unit cube standing on it, seen from straight above through an
//! orthographic camera, so that each pixel is a known point of the ground: 32 pixels per world unit.

use rastty_core::camera::{look_at, orthographic};
use rastty_core::color::ShadingSpace;
use rastty_core::math::BoundingSphere;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState, draw};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::shadow::{
    ShadowBias, ShadowError, ShadowMap, ShadowView, clear_shadow_depth, draw_shadow_caster, draw_shadow_caster_band,
};
use rastty_core::target::{NoColor, Rgb888, Target};

use crate::common::{Transformed, bits};

const SIZE: u32 = 128;
/// Pixels per world unit: the view spans `[-2, 2]` in x and z.
const SCALE: f32 = 32.0;
const MAP: u32 = 1024;

/// Axis-aligned quads as two triangles each, counter-clockwise seen from where `normal` points.
struct Quads {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    indices: Vec<u32>,
}

impl Quads {
    fn new() -> Self {
        Self { positions: vec![], normals: vec![], indices: vec![] }
    }

    /// A quad with corners `c`, `c + a`, `c + a + b`, `c + b`, facing `a x b`.
    fn quad(&mut self, c: Vec3, a: Vec3, b: Vec3) {
        let n = a.cross(b).normalize_or_zero();
        let base = self.positions.len() as u32;
        self.positions.extend([c, c + a, c + a + b, c + b]);
        self.normals.extend([n; 4]);
        self.indices.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }

    fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, Indices::U32(&self.indices)).unwrap().with_normals(&self.normals).unwrap()
    }
}

fn ground() -> Quads {
    let mut q = Quads::new();
    q.quad(Vec3::new(-2.0, 0.0, 2.0), Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -4.0));
    q
}

/// The unit cube `[-0.5, 0.5] x [0, 1] x [-0.5, 0.5]`, every face outward.
fn cube() -> Quads {
    let mut q = Quads::new();
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    let o = Vec3::new(-0.5, 0.0, -0.5);
    q.quad(o + y, z, x); // top
    q.quad(o, x, z); // bottom
    q.quad(o, y, x); // -z
    q.quad(o + z, x, y); // +z
    q.quad(o, z, y); // -x
    q.quad(o + x, y, z); // +x
    q
}

fn camera() -> (Mat4, Mat4) {
    let view = look_at(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)).unwrap();
    (view, orthographic(-2.0, 2.0, -2.0, 2.0, 1.0, 20.0).unwrap())
}

/// The bounds every shadow map is fitted to: the ground and the cube lie inside.
const BOUNDS: BoundingSphere = BoundingSphere { centre: Vec3::new(0.0, 0.5, 0.0), radius: 3.0 };

/// Renders the objects lit by one directional light shining from `to_light`, with a shadow map of the given
/// bias and PCF radius, or without shadows. Returns the pixels (row 0 at `z = -2`, column 0 at `x = -2`).
fn render(objects: &[&Quads], to_light: Vec3, shadow: Option<(ShadowBias, u32)>) -> Vec<u32> {
    render_lit(objects, Light::directional(to_light, Vec3::splat(0.8)), shadow)
}

/// [`render`] under `light`, of any kind.
fn render_lit(objects: &[&Quads], light: Light<'_>, shadow: Option<(ShadowBias, u32)>) -> Vec<u32> {
    let depth_map: Vec<f32>;
    let light = match shadow {
        None => light,
        Some((bias, pcf)) => {
            let view = ShadowView::fit(light.kind, BOUNDS, MAP).unwrap();
            let mut map = vec![0.0; (view.rows() * MAP) as usize];
            clear_shadow_depth(&mut map);
            for o in objects {
                draw_shadow_caster(&view, &mut map, &o.mesh(), &Mat4::IDENTITY).unwrap();
            }
            depth_map = map;
            Light { shadow: Some(ShadowMap::new(view, &depth_map, bias, pcf).unwrap()), ..light }
        }
    };
    let lights = [light];
    let scene = Lighting { ambient: Vec3::splat(0.2), lights: &lights, environment: None, space: ShadingSpace::Linear };
    let (view, projection) = camera();
    let mut color = vec![0u32; (SIZE * SIZE) as usize];
    let mut depth = vec![0f32; (SIZE * SIZE) as usize];
    let mut target = crate::common::frame(Rgb888(&mut color), &mut depth[..], SIZE, SIZE);
    target.clear(Vec3::ZERO);
    for o in objects {
        let object = Object {
            mesh: o.mesh(),
            tangents: None,
            transforms: Transforms::new(Mat4::IDENTITY, view, projection),
            shading: ShadingModel::Phong,
            material: Material::plain(Vec3::ONE),
        };
        draw_mesh(&mut target, &object, &scene, &DrawState::default()).unwrap();
    }
    color
}

/// The world `(x, z)` of a pixel centre.
fn ground_point(column: u32, row: u32) -> (f32, f32) {
    ((column as f32 + 0.5) / SCALE - 2.0, (row as f32 + 0.5) / SCALE - 2.0)
}

#[test]
fn no_acne_on_a_plane_at_any_angle_up_to_grazing_with_or_without_pcf() {
    let plane = ground();
    for degrees in [0.0f32, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0] {
        for azimuth in [0.0f32, 0.7, 2.0] {
            let a = degrees.to_radians();
            let to_light = Vec3::new(a.sin() * azimuth.cos(), a.cos(), a.sin() * azimuth.sin());
            let lit = render(&[&plane], to_light, None);
            for pcf in [0, 1, 2] {
                let shadowed = render(&[&plane], to_light, Some((ShadowBias::DEFAULT, pcf)));
                let acne = lit.iter().zip(&shadowed).filter(|(a, b)| a != b).count();
                assert_eq!(acne, 0, "{degrees} degrees from the normal, azimuth {azimuth}, pcf {pcf}: {acne} pixels");
            }
        }
    }
}

#[test]
fn without_bias_the_plane_shows_acne() {
    // The test above must be able to fail: with the bias removed the same plane shades itself.
    let zero = ShadowBias { normal_offset: 0.0, slope_offset: 0.0, depth: 0.0 };
    let to_light = Vec3::new(0.6, 0.8, 0.0);
    let lit = render(&[&ground()], to_light, None);
    let shadowed = render(&[&ground()], to_light, Some((zero, 0)));
    let acne = lit.iter().zip(&shadowed).filter(|(a, b)| a != b).count();
    assert!(acne > 1000, "only {acne} pixels of acne without bias");
}

/// Light from the -x side at 45 degrees: the cube's shadow on the ground is the square `x in [0.5, 1.5]`,
/// `z in [-0.5, 0.5]`.
fn cube_scene(shadow: Option<(ShadowBias, u32)>) -> Vec<u32> {
    let to_light = Vec3::new(-1.0, 1.0, 0.0);
    render(&[&ground(), &cube()], to_light, shadow)
}

#[test]
fn the_shadow_is_where_geometry_puts_it_and_touches_its_caster() {
    let lit_ground = render(&[&ground()], Vec3::new(-1.0, 1.0, 0.0), None)[0];
    let pixels = cube_scene(Some((ShadowBias::DEFAULT, 0)));
    // Unlit ground: ambient 0.2 on white, in linear light: 0.2 encodes to 123.55 / 255, code 124.
    let dark = 0x7C7C7C;
    assert_ne!(lit_ground, dark);
    // Pixels whose centre is at least 1.5 map texels (6 / 1024 world units each, 0.19 pixel) from the shadow's
    // outline must be exactly lit or exactly dark; the ground right at the cube's foot (x just above 0.5) is
    // dark: the shadow does not detach (peter-panning).
    let margin = 1.5 * 6.0 / MAP as f32;
    let mut checked = 0;
    for row in 0..SIZE {
        for column in 0..SIZE {
            let (x, z) = ground_point(column, row);
            if x.abs() < 0.5 + margin && z.abs() < 0.5 + margin {
                continue; // the cube itself, seen from above
            }
            let inside = x > 0.5 + margin && x < 1.5 - margin && z.abs() < 0.5 - margin;
            let outside = x > 1.5 + margin || x < 0.5 - margin || z.abs() > 0.5 + margin;
            let p = pixels[(row * SIZE + column) as usize];
            if inside {
                assert_eq!(p, dark, "shadowed ground lit at x = {x}, z = {z}");
                checked += 1;
            } else if outside {
                assert_eq!(p, lit_ground, "lit ground shadowed at x = {x}, z = {z}");
                checked += 1;
            }
        }
    }
    assert!(checked > 15_000, "{checked}");
    // The first column of ground past the cube's +x face, centre at x = 0.5 + 1/64: in shadow.
    let first = (0.5 + 2.0) * SCALE;
    assert_eq!(first, 80.0);
    for row in 50..78 {
        assert_eq!(pixels[(row * SIZE + 80) as usize], dark, "gap at the cube's foot, row {row}");
    }
}

#[test]
fn a_large_bias_detaches_the_shadow() {
    // The check above must be able to fail: a depth bias of a quarter of the map's depth range lets the light
    // through below the cube's top, and the foot of the shadow turns lit.
    let huge = ShadowBias { depth: 0.25, ..ShadowBias::DEFAULT };
    let pixels = cube_scene(Some((huge, 0)));
    let lit_at_foot = (50..78).filter(|row| pixels[(row * SIZE + 80) as usize] != 0x333333).count();
    assert!(lit_at_foot > 20, "{lit_at_foot}");
}

#[test]
fn pcf_softens_the_edge_and_nothing_else() {
    let hard = cube_scene(Some((ShadowBias::DEFAULT, 0)));
    let soft = cube_scene(Some((ShadowBias::DEFAULT, 2)));
    // Five texels of filter, 0.2 pixel each: only pixels within a pixel of the outline may change, and some must
    // show an intermediate level.
    let mut changed = 0;
    let mut between = 0;
    for row in 0..SIZE {
        for column in 0..SIZE {
            let i = (row * SIZE + column) as usize;
            if hard[i] == soft[i] {
                continue;
            }
            changed += 1;
            let (x, z) = ground_point(column, row);
            let near_edge =
                (x - 1.5).abs() < 1.0 / SCALE || (z.abs() - 0.5).abs() < 1.0 / SCALE || (x - 0.5).abs() < 1.0 / SCALE;
            assert!(near_edge, "PCF changed a pixel away from the shadow's edge at x = {x}, z = {z}");
            let level = soft[i] & 0xFF;
            between += usize::from(level > 0x33 && level < (hard.iter().map(|p| p & 0xFF).max().unwrap()));
        }
    }
    assert!(changed > 0 && between > 0, "changed {changed}, intermediate {between}");
}

#[test]
fn a_map_drawn_in_bands_is_the_map_drawn_whole() {
    let (ground, cube) = (ground(), cube());
    let kind = Light::directional(Vec3::new(0.4, 1.0, 0.3), Vec3::ONE).kind;
    let view = ShadowView::fit(kind, BOUNDS, 64).unwrap();
    // The ground and the cube inside the bounds, and the cube four times larger, reaching past the map's near and
    // far planes (cut there, its depths clamped to the map's range).
    let casters = [(&ground, Mat4::IDENTITY), (&cube, Mat4::IDENTITY), (&cube, Mat4::from_scale(Vec3::splat(4.0)))];
    let mut whole = vec![0.0; 64 * 64];
    clear_shadow_depth(&mut whole);
    let mut clipped = 0;
    for (o, model) in &casters {
        clipped += draw_shadow_caster(&view, &mut whole, &o.mesh(), model).unwrap().clipped;
    }
    assert!(whole.iter().any(|&d| d < 1.0), "the casters are in the map");
    assert!(clipped > 0, "the large cube is cut");
    for height in 1..=64 {
        let mut banded = vec![0.0; 64 * 64];
        clear_shadow_depth(&mut banded);
        for y0 in (0..64).step_by(height) {
            let y1 = (y0 + height).min(64);
            let band = &mut banded[y0 * 64..y1 * 64];
            for (o, model) in &casters {
                draw_shadow_caster_band(&view, band, y0 as u32..y1 as u32, &o.mesh(), model).unwrap();
            }
        }
        assert!(bits(&banded) == bits(&whole), "bands of {height} rows");
    }
    let mesh = cube.mesh();
    let mut band = vec![1.0; 64 * 4];
    let refused = draw_shadow_caster_band(&view, &mut band, 62..66, &mesh, &Mat4::IDENTITY);
    assert_eq!(refused, Err(ShadowError::Rows { start: 62, end: 66, height: 64 }));
    assert_eq!(refused.unwrap_err().to_string(), "rows 62..66 are not a band of a map 64 texels high");
    let refused = draw_shadow_caster_band(&view, &mut band, 3..3, &mesh, &Mat4::IDENTITY);
    assert_eq!(refused, Err(ShadowError::Rows { start: 3, end: 3, height: 64 }));
    let refused = draw_shadow_caster_band(&view, &mut band, 0..3, &mesh, &Mat4::IDENTITY);
    assert_eq!(refused, Err(ShadowError::Buffer { expected: 64 * 3, actual: 64 * 4 }));
}

/// A point light among the objects: beside the cube, lower than its top, off its axes, so that the cube's shadow
/// reaches the ground's edge and crosses the seam between two faces of the light's cube map.
const LAMP: Vec3 = Vec3::new(-1.3, 0.8, -0.9);

fn lamp(position: Vec3) -> Light<'static> {
    Light::point(position, Vec3::splat(0.8))
}

/// Whether the segment from ground point `q` to `light` passes through the unit cube (slab test: Kay and Kajiya,
/// "Ray Tracing Complex Scenes", SIGGRAPH 1986).
fn blocked(q: Vec3, light: Vec3) -> bool {
    let d = light - q;
    let (mut enter, mut leave) = (0.0f32, 1.0f32);
    for (o, d, lo, hi) in [(q.x, d.x, -0.5, 0.5), (q.y, d.y, 0.0, 1.0), (q.z, d.z, -0.5, 0.5)] {
        if d == 0.0 {
            if o < lo || o > hi {
                return false;
            }
            continue;
        }
        let (a, b) = ((lo - o) / d, (hi - o) / d);
        enter = enter.max(a.min(b));
        leave = leave.min(a.max(b));
    }
    enter <= leave
}

#[test]
fn a_point_light_among_the_objects_casts_through_a_cube_map() {
    let view = ShadowView::fit(lamp(LAMP).kind, BOUNDS, MAP).unwrap();
    assert_eq!(view.faces(), 6, "the lamp is inside the bounds");
    let lit = render_lit(&[&ground(), &cube()], lamp(LAMP), None);
    let dark = 0x7C7C7C; // ambient 0.2 on white in linear light (see above)
    for pcf in [0, 1] {
        let pixels = render_lit(&[&ground(), &cube()], lamp(LAMP), Some((ShadowBias::DEFAULT, pcf)));
        let (mut checked, mut shadowed) = (0, 0);
        let mut faces = [0; 6];
        for row in 0..SIZE {
            for column in 0..SIZE {
                let (x, z) = ground_point(column, row);
                let q = Vec3::new(x, 0.0, z);
                // A map texel is 2 * 1.008 / 1024 of the distance to the lamp wide; the lookup moves the point up
                // to (0.6 + 1.5) * (1 + pcf) texels off the ground, which shifts the outline by that times the
                // tangent of the light's angle; plus the filter's reach and a texel and a half of rasterization.
                let distance = (LAMP - q).length();
                let texel = 2.0 * 1.008 * distance / MAP as f32;
                let tangent = Vec3::new(LAMP.x - x, 0.0, LAMP.z - z).length() / LAMP.y;
                let margin = texel * (2.1 * (1 + pcf) as f32 * tangent + pcf as f32 + 1.5);
                if x.abs() < 0.5 + margin && z.abs() < 0.5 + margin {
                    continue; // the cube itself, seen from above
                }
                let around = [(0.0, 0.0), (margin, 0.0), (-margin, 0.0), (0.0, margin), (0.0, -margin)];
                let verdicts = around.map(|(dx, dz)| blocked(Vec3::new(x + dx, 0.0, z + dz), LAMP));
                if verdicts.iter().any(|&v| v != verdicts[0]) {
                    continue; // near the outline
                }
                let i = (row * SIZE + column) as usize;
                if verdicts[0] {
                    assert_eq!(pixels[i], dark, "pcf {pcf}: shadowed ground lit at x = {x}, z = {z}");
                    shadowed += 1;
                    faces[view.face_of(q) as usize] += 1;
                } else {
                    assert_eq!(pixels[i], lit[i], "pcf {pcf}: lit ground shadowed at x = {x}, z = {z}");
                }
                checked += 1;
            }
        }
        assert!(checked > 12_000 && shadowed > 1500, "pcf {pcf}: {checked} checked, {shadowed} in shadow");
        // The shadow lies across the seam between the +x and the +z faces.
        assert!(faces[0] > 200 && faces[4] > 200, "pcf {pcf}: shadowed pixels by face {faces:?}");
        // The ground at the cube's foot on the far side from the lamp, centres 1/64 from its +x face: in shadow.
        for row in 52..76 {
            assert_eq!(pixels[(row * SIZE + 80) as usize], dark, "pcf {pcf}: gap at the cube's foot, row {row}");
        }
    }
}

#[test]
fn no_acne_under_a_point_light_among_the_objects() {
    let plane = ground();
    // High over the middle, low over a corner (grazing the far side of the ground at 87 degrees), and on a seam.
    for position in [Vec3::new(0.0, 1.5, 0.0), Vec3::new(-1.5, 0.15, 1.2), Vec3::new(0.7, 0.7, -0.4)] {
        let lit = render_lit(&[&plane], lamp(position), None);
        for pcf in [0, 1, 2] {
            let shadowed = render_lit(&[&plane], lamp(position), Some((ShadowBias::DEFAULT, pcf)));
            let acne = lit.iter().zip(&shadowed).filter(|(a, b)| a != b).count();
            assert_eq!(acne, 0, "lamp at {position:?}, pcf {pcf}: {acne} pixels");
        }
    }
    // The test can fail: without the bias the plane shades itself.
    let zero = ShadowBias { normal_offset: 0.0, slope_offset: 0.0, depth: 0.0 };
    let position = Vec3::new(0.0, 1.5, 0.0);
    let lit = render_lit(&[&plane], lamp(position), None);
    let shadowed = render_lit(&[&plane], lamp(position), Some((zero, 0)));
    let acne = lit.iter().zip(&shadowed).filter(|(a, b)| a != b).count();
    assert!(acne > 1000, "only {acne} pixels of acne without bias");
}

#[test]
fn a_large_bias_detaches_the_shadow_of_a_point_light() {
    // The foot check above can fail: a depth bias of a quarter of the map's range lets the light through.
    let huge = ShadowBias { depth: 0.25, ..ShadowBias::DEFAULT };
    let pixels = render_lit(&[&ground(), &cube()], lamp(LAMP), Some((huge, 0)));
    let lit_at_foot = (52..76).filter(|row| pixels[(row * SIZE + 80) as usize] != 0x7C7C7C).count();
    assert!(lit_at_foot > 20, "{lit_at_foot}");
}

#[test]
fn a_cube_map_holds_each_face_drawn_alone_in_bands_across_its_seams() {
    const FACE: u32 = 48;
    let (ground, cube) = (ground(), cube());
    let view = ShadowView::fit(lamp(LAMP).kind, BOUNDS, FACE).unwrap();
    assert_eq!(view.rows(), 6 * FACE);
    // The ground and the cube, and a small cube wholly in the lamp's +y face, which the other faces skip.
    let above = Mat4::from_translation(LAMP + Vec3::new(0.0, 1.0, 0.0)) * Mat4::from_scale(Vec3::splat(0.1));
    let casters = [(&ground, Mat4::IDENTITY), (&cube, Mat4::IDENTITY), (&cube, above)];
    let texels = (FACE * FACE) as usize;
    let mut whole = vec![0.0; 6 * texels];
    clear_shadow_depth(&mut whole);
    for (o, model) in &casters {
        let stats = draw_shadow_caster(&view, &mut whole, &o.mesh(), model).unwrap();
        assert_eq!(stats.triangles_in, 6 * o.mesh().triangle_count() as u64);
    }
    let small = draw_shadow_caster(&view, &mut vec![1.0; 6 * texels], &cube.mesh(), &above).unwrap();
    assert_eq!(small.outside, 5 * 12, "five faces skip the small cube: {small:?}");
    assert!(small.fragments > 0);
    // Each face holds what the pipeline draws through that face's projection, as any caller would draw it.
    let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
    for face in 0..6 {
        let mut alone = vec![1.0; texels];
        let mut target = Target::new(NoColor, &mut alone[..], FACE, FACE).unwrap();
        for (o, model) in &casters {
            let clip_from_object = view.clip_from_world(face).unwrap() * *model;
            draw(&mut target, &o.mesh(), &Transformed { clip_from_object }, &state).unwrap();
        }
        let held = &whole[face as usize * texels..(face as usize + 1) * texels];
        assert!(bits(held) == bits(&alone), "face {face}");
        assert!(held.iter().any(|&d| d < 1.0), "face {face} sees something");
    }
    // Bands of any height, across the seams, make the map drawn whole.
    for height in [1, 7, 48, 50, 100, 288] {
        let mut banded = vec![0.0; 6 * texels];
        clear_shadow_depth(&mut banded);
        for y0 in (0..6 * FACE as usize).step_by(height) {
            let y1 = (y0 + height).min(6 * FACE as usize);
            let band = &mut banded[y0 * FACE as usize..y1 * FACE as usize];
            for (o, model) in &casters {
                draw_shadow_caster_band(&view, band, y0 as u32..y1 as u32, &o.mesh(), model).unwrap();
            }
        }
        assert!(bits(&banded) == bits(&whole), "bands of {height} rows");
    }
    let refused = draw_shadow_caster_band(&view, &mut [1.0; 48 * 4], 286..290, &cube.mesh(), &Mat4::IDENTITY);
    assert_eq!(refused, Err(ShadowError::Rows { start: 286, end: 290, height: 288 }));
    // The lookups of a cube map with window ranges, across its seams, are those without.
    let (mut near, mut far) = (vec![0.0; 6 * texels], vec![0.0; 6 * texels]);
    for (y0, y1) in [(0u32, 40u32), (40, 100), (100, 288)] {
        let span = y0 as usize * FACE as usize..y1 as usize * FACE as usize;
        let (n, f) = (&mut near[span.clone()], &mut far[span]);
        rastty_core::shadow::window_ranges_band(&whole, FACE, 1, y0..y1, n, f).unwrap();
    }
    let plain = ShadowMap::new(view, &whole, ShadowBias::DEFAULT, 1).unwrap();
    let windows = rastty_core::shadow::WindowRanges::new(&near, &far, FACE, 1).unwrap();
    let ranged = plain.with_windows(windows).unwrap();
    let mut seen = [false; 6];
    for i in 0..20_000 {
        let t = i as f32 / 20_000.0;
        let p = Vec3::new(4.0 * (t * 37.0).fract() - 2.0, 1.2 * (t * 11.0).fract(), 4.0 * t - 2.0);
        let n = Vec3::Y;
        let n_dot_l = (LAMP - p).normalize_or_zero().y;
        let (a, b) = (plain.light_reaching(p, n, n_dot_l), ranged.light_reaching(p, n, n_dot_l));
        assert_eq!(a.to_bits(), b.to_bits(), "at {p:?}");
        seen[view.face_of(p) as usize] = true;
    }
    assert!(seen.iter().all(|&s| s), "lookups in every face: {seen:?}");
}
