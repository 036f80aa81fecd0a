//! The reference renderer against closed-form answers: coverage of an edge through a pixel, exact interior
//! colours, depth order, the near-plane cut, perspective-correct texture coordinates, bilinear sampling, Blinn-Phong
//! lighting; and against rastty itself (the same scene from a model shown without a scene file, within 8-bit
//! rounding).
//!
//! `cargo test --release -p rastty-bench --test integration reference:: -- --ignored --nocapture` also renders the built-in model at
//! 320x240, writes `/tmp/reference.png` and `/tmp/rastty_default.png`, and prints the time and the PSNR.

use std::path::PathBuf;

use rastty_bench::reference::{
    Camera, ReferenceError, ReferenceImage, ReferenceLight, ReferenceLighting, ReferenceMaterial, ReferenceObject,
    ReferencePlace, ReferenceProjection, ReferenceScene, Renderer, SAMPLES_PER_AXIS, Shading, render, srgb,
};
use rastty_core::camera::CameraError;
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Vec2, Vec3};
use rastty_core::pipeline::Cull;
use rastty_core::texture::{MipFilter, WrapMode};
use rastty_scene::model::{DEFAULT_DIFFUSE, Model, ModelMaterial, Part, TextureImage};
use rastty_scene::scene_file::{SceneCamera, SceneData};
use rastty_scene::scene_render::{CameraOptions, PlanOptions, PreparedScene, ShadingMode, render_scene_image};

// ---------------------------------------------------------------------------------------------------------------
// Helpers

const N: u32 = SAMPLES_PER_AXIS;

/// An orthographic camera whose view box is the image itself: world `(x, -y)` is screen `(x, y)`, and `z = 0` is
/// at view depth 1 (depth = 1 - z).
/// An empty scene lit on the stored values: the tests below state the maths of coverage, depth and shading, and
/// [`light_averages_in_linear_light`] what linear light changes.
fn stored_scene(width: u32, height: u32, camera: Camera) -> ReferenceScene {
    ReferenceScene { space: ShadingSpace::Encoded, ..ReferenceScene::new(width, height, camera) }
}

fn pixel_camera(width: u32, height: u32) -> Camera {
    Camera {
        eye: [0.0, 0.0, 1.0],
        target: [0.0; 3],
        up: [0.0, 1.0, 0.0],
        projection: ReferenceProjection::Orthographic {
            left: 0.0,
            right: f64::from(width),
            bottom: -f64::from(height),
            top: 0.0,
            near: 0.0,
            far: 2.0,
        },
    }
}

/// A camera at the origin looking down `-z` with a 90-degree vertical field of view.
fn eye_camera(aspect: f64, near: f64, far: f64) -> Camera {
    Camera {
        eye: [0.0; 3],
        target: [0.0, 0.0, -1.0],
        up: [0.0, 1.0, 0.0],
        projection: ReferenceProjection::Perspective { fovy: std::f64::consts::FRAC_PI_2, aspect, near, far },
    }
}

/// The ray parameters of screen point `(x, y)` for [`eye_camera`]: the ray runs along `(sx, sy, -1)`.
fn eye_ray(x: f64, y: f64, width: u32, height: u32, aspect: f64) -> (f64, f64) {
    let ky = std::f64::consts::FRAC_PI_4.tan();
    ((2.0 * x / f64::from(width) - 1.0) * ky * aspect, (1.0 - 2.0 * y / f64::from(height)) * ky)
}

/// Screen position of sample `(k, l)` of pixel `(i, j)`.
fn sample_point(i: u32, j: u32, k: u32, l: u32) -> (f64, f64) {
    let f = |p: u32, s: u32| f64::from(p) + (f64::from(s) + 0.5) / f64::from(N);
    (f(i, k), f(j, l))
}

/// An unlit object of one colour, both faces drawn.
fn flat(positions: Vec<[f64; 3]>, indices: Vec<u32>, color: [f64; 3]) -> ReferenceObject {
    let mut o = ReferenceObject::new(positions, indices);
    o.material.color = color;
    o.shading = Shading::Unlit;
    o.cull = Cull::None;
    o
}

/// A rectangle `[x0, x1] x [y0, y1]` at height `z` in world space (counter-clockwise seen from `+z`).
fn rectangle(x0: f64, x1: f64, y0: f64, y1: f64, z: f64, color: [f64; 3]) -> ReferenceObject {
    flat(vec![[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]], vec![0, 1, 2, 0, 2, 3], color)
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tolerance)
}

fn mix(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [0, 1, 2].map(|i| a[i] * (1.0 - t) + b[i] * t)
}

const RED: [f64; 3] = [1.0, 0.0, 0.0];
const BLUE: [f64; 3] = [0.0, 0.0, 1.0];
const GREY: [f64; 3] = [0.2, 0.3, 0.4];

// ---------------------------------------------------------------------------------------------------------------
// Coverage

#[test]
fn an_edge_through_the_middle_of_a_pixel_column_covers_half_of_it() {
    let (w, h) = (8, 4);
    // Covers screen x <= 3.5 (world y runs from -100 to 100, so the whole height).
    let tri = flat(vec![[3.5, -100.0, 0.0], [3.5, 100.0, 0.0], [-100.0, 0.0, 0.0]], vec![0, 1, 2], RED);
    let scene = ReferenceScene { background: GREY, objects: vec![tri], ..stored_scene(w, h, pixel_camera(w, h)) };
    let image = render(&scene).unwrap();
    for y in 0..h {
        for x in 0..w {
            let p = image.index(x, y);
            let (coverage, rgb) = (image.coverage[p], image.rgb[p]);
            match x {
                0..=2 => assert!(coverage == 1.0 && rgb == RED && image.centre_covered[p], "inside ({x}, {y})"),
                3 => {
                    assert!((coverage - 0.5).abs() <= 1.0 / 256.0, "({x}, {y}): {coverage}");
                    assert_eq!(coverage, 0.5, "no sample lies on the edge");
                    assert!(close(rgb, mix(RED, GREY, 0.5), 1e-15), "({x}, {y}): {rgb:?}");
                    // The centre lies exactly on the edge, and triangles are closed.
                    assert!(image.centre_covered[p]);
                }
                _ => assert!(coverage == 0.0 && rgb == GREY && !image.centre_covered[p], "outside ({x}, {y})"),
            }
        }
    }
}

/// In linear light a half-covered pixel holds half of each colour's light, encoded: red `1` and grey `0.2` give
/// `encode((1 + decode(0.2)) / 2)`, not the mean of the stored values; a texel half-way between black and white
/// is half of white's light.
#[test]
fn light_averages_in_linear_light() {
    let (w, h) = (8, 4);
    let tri = flat(vec![[3.5, -100.0, 0.0], [3.5, 100.0, 0.0], [-100.0, 0.0, 0.0]], vec![0, 1, 2], RED);
    let scene =
        ReferenceScene { background: GREY, objects: vec![tri], ..ReferenceScene::new(w, h, pixel_camera(w, h)) };
    assert_eq!(scene.space, ShadingSpace::Linear);
    let image = render(&scene).unwrap();
    let half = |a: f64, b: f64| srgb::encode((srgb::decode(a) + srgb::decode(b)) / 2.0);
    let want = [half(1.0, 0.2), half(0.0, 0.3), half(0.0, 0.4)];
    assert!(close(image.pixel(3, 1), want, 1e-14), "{:?} against {want:?}", image.pixel(3, 1));
    // Red's half: 0.5 plus half of grey's light (0.0331) encoded is 0.7462, against 0.6 for the stored values.
    assert!((image.pixel(3, 1)[0] - 0.7462).abs() < 1e-4, "{:?}", image.pixel(3, 1));
    assert!(close(image.pixel(0, 0), RED, 1e-15) && close(image.pixel(7, 0), GREY, 1e-15));
}

#[test]
fn an_edge_through_the_middle_of_a_pixel_column_in_perspective() {
    // Five columns: the middle of column 2 is the view axis, and the triangle's edge lies in the plane x = 0.
    let (w, h) = (5, 3);
    let tri = flat(vec![[0.0, -10.0, -2.0], [0.0, 10.0, -2.0], [-10.0, 0.0, -2.0]], vec![0, 1, 2], BLUE);
    let scene =
        ReferenceScene { background: GREY, objects: vec![tri], ..stored_scene(w, h, eye_camera(1.0, 0.5, 10.0)) };
    let image = render(&scene).unwrap();
    for y in 0..h {
        let row: Vec<f64> = (0..w).map(|x| image.coverage[image.index(x, y)]).collect();
        assert_eq!(row, [1.0, 1.0, 0.5, 0.0, 0.0]);
        assert!(close(image.pixel(2, y), mix(BLUE, GREY, 0.5), 1e-15));
        assert_eq!(image.pixel(1, y), BLUE);
        assert_eq!(image.pixel(3, y), GREY);
    }
}

#[test]
fn a_diagonal_edge_covers_the_samples_below_it() {
    // The line y = x (screen) through a 4x4 image: the samples strictly below it and those on it are covered.
    let (w, h) = (4, 4);
    let tri = flat(vec![[-1.0, 1.0, 0.0], [9.0, -9.0, 0.0], [-1.0, -9.0, 0.0]], vec![0, 1, 2], RED);
    let scene = ReferenceScene { objects: vec![tri], ..stored_scene(w, h, pixel_camera(w, h)) };
    let image = render(&scene).unwrap();
    for y in 0..h {
        for x in 0..w {
            let mut hits = 0;
            for l in 0..N {
                for k in 0..N {
                    let (sx, sy) = sample_point(x, y, k, l);
                    hits += u32::from(sy >= sx);
                }
            }
            let want = f64::from(hits) / f64::from(N * N);
            assert_eq!(image.coverage[image.index(x, y)], want, "({x}, {y})");
            assert!(close(image.pixel(x, y), mix([0.0; 3], RED, want), 1e-15));
            // Diagonal pixels: 136 of 256 (the 16 on the line count).
            if x == y {
                assert_eq!(want, 136.0 / 256.0);
            }
        }
    }
}

#[test]
fn shared_edges_leave_no_gap() {
    // A square of two triangles: samples exactly on their shared diagonal (x + y = 6) are covered too.
    let (w, h) = (6, 6);
    let square = rectangle(0.5, 5.5, -5.5, -0.5, 0.0, RED);
    let scene = ReferenceScene { background: GREY, objects: vec![square], ..stored_scene(w, h, pixel_camera(w, h)) };
    let image = render(&scene).unwrap();
    for y in 1..5 {
        for x in 1..5 {
            assert_eq!(image.coverage[image.index(x, y)], 1.0);
            assert_eq!(image.pixel(x, y), RED);
        }
    }
    // Half-covered border pixels.
    assert_eq!(image.coverage[image.index(0, 2)], 0.5);
    assert_eq!(image.coverage[image.index(0, 0)], 0.25);
}

// ---------------------------------------------------------------------------------------------------------------
// Depth

#[test]
fn the_nearer_triangle_wins_in_either_order() {
    let (w, h) = (6, 6);
    // Red at depth 1 over the left two thirds, blue at depth 0.5 over the right two thirds.
    let far = rectangle(0.0, 4.0, -6.0, 0.0, 0.0, RED);
    let near = rectangle(2.0, 6.0, -6.0, 0.0, 0.5, BLUE);
    for objects in [vec![far.clone(), near.clone()], vec![near.clone(), far.clone()]] {
        let scene = ReferenceScene { background: GREY, objects, ..stored_scene(w, h, pixel_camera(w, h)) };
        let image = render(&scene).unwrap();
        for y in 0..h {
            assert_eq!(image.pixel(1, y), RED);
            assert_eq!(image.pixel(2, y), BLUE);
            assert_eq!(image.pixel(3, y), BLUE);
            assert_eq!(image.pixel(5, y), BLUE);
        }
    }
    // In perspective too, where the depth comes from the ray-plane intersection.
    let (w, h) = (8, 8);
    let far = flat(vec![[-9.0, -9.0, -4.0], [9.0, -9.0, -4.0], [0.0, 9.0, -4.0]], vec![0, 1, 2], RED);
    let near = flat(vec![[-2.0, -2.0, -3.0], [2.0, -2.0, -3.0], [0.0, 2.0, -3.0]], vec![0, 1, 2], BLUE);
    for objects in [vec![far.clone(), near.clone()], vec![near, far]] {
        let scene = ReferenceScene { objects, ..stored_scene(w, h, eye_camera(1.0, 0.1, 10.0)) };
        let renderer = Renderer::new(&scene).unwrap();
        assert_eq!(renderer.render().pixel(4, 4), BLUE);
        let hit = renderer.probe(4.0, 4.0).unwrap();
        assert_eq!(hit.color, BLUE);
        assert!((hit.depth - 3.0).abs() < 1e-15);
        assert_eq!(renderer.probe(0.5, 7.5).unwrap().color, RED);
    }
}

#[test]
fn an_exact_depth_tie_goes_to_the_first_drawn() {
    let (w, h) = (2, 2);
    let a = rectangle(0.0, 2.0, -2.0, 0.0, 0.0, RED);
    let b = rectangle(0.0, 2.0, -2.0, 0.0, 0.0, BLUE);
    let image =
        render(&ReferenceScene { objects: vec![a.clone(), b.clone()], ..stored_scene(w, h, pixel_camera(w, h)) });
    assert_eq!(image.unwrap().pixel(1, 1), RED);
    let image = render(&ReferenceScene { objects: vec![b, a], ..stored_scene(w, h, pixel_camera(w, h)) });
    assert_eq!(image.unwrap().pixel(1, 1), BLUE);
}

#[test]
fn a_triangle_crossing_the_near_plane_is_cut_exactly_at_it() {
    // A plane tilted so that its view depth is 1 + x: it runs from behind the eye (depth -9 at x = -10) to depth
    // 11. The ray (sx, sy, -1) meets it at depth t = 1 / (1 - sx); with near = 0.8 the cut is at sx = -0.25.
    let (w, h, aspect) = (20, 4, 1.0);
    let (near, far) = (0.8, 100.0);
    let plane = flat(
        vec![[-10.0, -10.0, 9.0], [10.0, -10.0, -11.0], [10.0, 10.0, -11.0], [-10.0, 10.0, 9.0]],
        vec![0, 1, 2, 0, 2, 3],
        RED,
    );
    let scene =
        ReferenceScene { background: GREY, objects: vec![plane], ..stored_scene(w, h, eye_camera(aspect, near, far)) };
    let renderer = Renderer::new(&scene).unwrap();
    let image = renderer.render();
    // Closed form per sample: visible when the hit depth is within [near, far] and the hit within the quad.
    let visible = |x: f64, y: f64| {
        let (sx, sy) = eye_ray(x, y, w, h, aspect);
        let t = 1.0 / (1.0 - sx);
        t > 0.0 && (near..=far).contains(&t) && (t * sx).abs() <= 10.0 && (t * sy).abs() <= 10.0
    };
    let mut cut_pixel = None;
    for y in 0..h {
        for x in 0..16 {
            let mut hits = 0;
            for l in 0..N {
                for k in 0..N {
                    let (px, py) = sample_point(x, y, k, l);
                    hits += u32::from(visible(px, py));
                }
            }
            let want = f64::from(hits) / f64::from(N * N);
            let p = image.index(x, y);
            assert_eq!(image.coverage[p], want, "({x}, {y})");
            assert!(close(image.rgb[p], mix(GREY, RED, want), 1e-15), "({x}, {y})");
            if want > 0.0 && want < 1.0 {
                cut_pixel = Some(x);
            }
        }
    }
    // The cut, at screen x = 10 (1 - 0.25 / kx) = 7.5, halves pixel 7; pixel 8, just beyond, is fully visible, and
    // pixel 6, just before, shows the background (the plane is there, but nearer than the near plane).
    assert_eq!(cut_pixel, Some(7));
    assert_eq!(image.coverage[image.index(7, 1)], 0.5);
    assert_eq!(image.pixel(8, 1), RED);
    assert_eq!(image.pixel(6, 1), GREY);
    assert_eq!(image.pixel(0, 1), GREY);
    // Just either side of the cut, by a millionth of a pixel.
    let x_cut = 10.0 * (1.0 - 0.25 / std::f64::consts::FRAC_PI_4.tan());
    let hit = renderer.probe(x_cut + 1e-6, 2.0).unwrap();
    assert!(hit.depth >= near && hit.depth - near < 1e-6, "{}", hit.depth);
    assert!(renderer.probe(x_cut - 1e-6, 2.0).is_none());
}

// ---------------------------------------------------------------------------------------------------------------
// Facing

#[test]
fn culling_follows_the_screen_winding_and_mirroring() {
    let (w, h) = (2, 2);
    // Counter-clockwise seen from the camera (+z): front-facing.
    let ccw = rectangle(0.0, 2.0, -2.0, 0.0, 0.0, RED);
    let drawn = |o: &ReferenceObject| {
        render(&ReferenceScene { objects: vec![o.clone()], ..stored_scene(w, h, pixel_camera(w, h)) })
    };
    for (cull, want) in [(Cull::None, true), (Cull::Back, true), (Cull::Front, false)] {
        let o = ReferenceObject { cull, ..ccw.clone() };
        assert_eq!(drawn(&o).unwrap().coverage[0] == 1.0, want, "{cull:?}");
    }
    // Mirrored in x (and moved back into view): the winding on screen flips, and so does which side is the front,
    // as in rastty.
    let mut mirrored = ReferenceObject { cull: Cull::Back, ..ccw.clone() };
    mirrored.model = [[-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [2.0, 0.0, 0.0, 1.0]];
    assert_eq!(drawn(&mirrored).unwrap().coverage[0], 1.0);
    // A genuinely back-facing triangle (clockwise on screen) is culled.
    let mut cw = ReferenceObject { cull: Cull::Back, ..ccw };
    cw.indices = vec![0, 2, 1, 0, 3, 2];
    assert_eq!(drawn(&cw).unwrap().coverage[0], 0.0);
}

// ---------------------------------------------------------------------------------------------------------------
// Interpolation and textures

/// A 256x1 red ramp: texel i has red i. Bilinear sampling at u in [0.5/256, 255.5/256] gives red
/// (256 u - 0.5) / 255 exactly (linear between texel centres).
fn ramp() -> TextureImage {
    TextureImage::new(256, 1, (0..256u32).map(|i| i << 16).collect())
}

#[test]
fn texture_coordinates_are_perspective_correct() {
    // A floor at y = -1 from depth 1 to 11, u running 0.1 to 0.9 with depth. The ray (sx, sy, -1) with sy < 0
    // meets it at depth t = -1 / sy, where u = 0.1 + 0.08 (t - 1): not linear in screen space.
    let (w, h, aspect) = (16, 16, 1.0);
    let mut floor = flat(
        vec![[-4.0, -1.0, -1.0], [4.0, -1.0, -1.0], [4.0, -1.0, -11.0], [-4.0, -1.0, -11.0]],
        vec![0, 1, 2, 0, 2, 3],
        [1.0; 3],
    );
    floor.uvs = Some(vec![[0.1, 0.5], [0.1, 0.5], [0.9, 0.5], [0.9, 0.5]]);
    floor.texture = Some(ramp());
    let scene = ReferenceScene { objects: vec![floor], ..stored_scene(w, h, eye_camera(aspect, 0.5, 20.0)) };
    let renderer = Renderer::new(&scene).unwrap();
    let image = renderer.render();
    // The closed form at a screen point: (u, red) if the ray hits the floor.
    let truth = |x: f64, y: f64| {
        let (sx, sy) = eye_ray(x, y, w, h, aspect);
        let t = -1.0 / sy;
        (sy < 0.0 && (1.0..=11.0).contains(&t) && (t * sx).abs() <= 4.0).then(|| {
            let u = 0.1 + 0.08 * (t - 1.0);
            (u, (256.0 * u - 0.5) / 255.0)
        })
    };
    let mut checked = 0;
    for j in 0..h {
        for i in 0..w {
            let (cx, cy) = (f64::from(i) + 0.5, f64::from(j) + 0.5);
            match (truth(cx, cy), renderer.probe(cx, cy)) {
                (Some((u, red)), Some(hit)) => {
                    let uv = hit.uv.unwrap();
                    assert!((uv[0] - u).abs() < 1e-14 && (uv[1] - 0.5).abs() < 1e-14, "({i}, {j}): {uv:?} vs {u}");
                    assert!((hit.color[0] - red).abs() < 1e-13, "({i}, {j})");
                    checked += 1;
                }
                (None, None) => {}
                (want, got) => panic!("({i}, {j}): {want:?} vs {got:?}"),
            }
            // The pixel: the mean over the samples of the closed form.
            let (mut hits, mut red) = (0, 0.0);
            for l in 0..N {
                for k in 0..N {
                    let (sx, sy) = sample_point(i, j, k, l);
                    if let Some((_, r)) = truth(sx, sy) {
                        hits += 1;
                        red += r;
                    }
                }
            }
            let p = image.index(i, j);
            assert_eq!(image.coverage[p], f64::from(hits) / 256.0, "({i}, {j})");
            assert!((image.rgb[p][0] - red / 256.0).abs() < 1e-13, "({i}, {j})");
        }
    }
    assert!(checked > 40, "{checked}");
    // Screen-linear interpolation would be far off: between rows 9 and 15 the centre of row 12 is not the mean.
    let u = |j: f64| truth(8.0, j).unwrap().0;
    assert!((u(12.5) - (u(9.5) + u(15.5)) / 2.0).abs() > 0.05);
}

#[test]
fn bilinear_sampling_is_exact_at_texel_centres_and_half_way() {
    // A 4x1 image showing a 2x1 texture across it: texel centres at screen x = 1 and 3, half-way at x = 2.
    let (w, h) = (4, 1);
    let mut quad = rectangle(0.0, 4.0, -1.0, 0.0, 0.0, [1.0; 3]);
    quad.uvs = Some(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    quad.texture = Some(TextureImage::new(2, 1, vec![0x010203, 0x020304]));
    quad.wrap = WrapMode::Clamp;
    let scene = ReferenceScene { objects: vec![quad], ..stored_scene(w, h, pixel_camera(w, h)) };
    let renderer = Renderer::new(&scene).unwrap();
    let at = |x: f64| renderer.probe(x, 0.5).unwrap().color;
    let c = |v: [f64; 3]| v.map(|x| x / 255.0);
    assert!(close(at(1.0), c([1.0, 2.0, 3.0]), 1e-17));
    assert!(close(at(3.0), c([2.0, 3.0, 4.0]), 1e-17));
    // 1.5, 2.5, 3.5 levels: no 8-bit value, so a quantised blend would be off by half a level.
    assert!(close(at(2.0), c([1.5, 2.5, 3.5]), 1e-17));
    // A quarter of the way.
    assert!(close(at(1.5), c([1.25, 2.25, 3.25]), 1e-17));
}

// ---------------------------------------------------------------------------------------------------------------
// ReferenceLighting

#[test]
fn a_flat_quad_facing_the_light_is_lit_exactly() {
    let (w, h) = (4, 4);
    let albedo = [0.8, 0.5, 0.25];
    let ambient = [0.1, 0.2, 0.05];
    let light = ReferenceLight { to_light: [0.0, 0.0, 1.0], color: [0.5, 0.6, 0.7], place: None };
    let behind = ReferenceLight { to_light: [0.0, 0.0, -1.0], color: [1.0; 3], place: None };
    let mut quad = rectangle(-1.0, 5.0, -5.0, 1.0, 0.0, albedo);
    quad.shading = Shading::Lit;
    quad.normals = Some(vec![[0.0, 0.0, 1.0]; 4]);
    let lighting = ReferenceLighting { ambient, lights: vec![light, behind] };
    let scene = ReferenceScene { lighting, objects: vec![quad.clone()], ..stored_scene(w, h, pixel_camera(w, h)) };
    let want = [0, 1, 2].map(|i| albedo[i] * (ambient[i] + light.color[i]));
    let image = render(&scene).unwrap();
    for y in 0..h {
        for x in 0..w {
            assert_eq!(image.pixel(x, y), want, "({x}, {y})");
        }
    }
    // Without normals the face normal is used: the same.
    let bare = ReferenceObject { normals: None, ..quad.clone() };
    assert_eq!(render(&ReferenceScene { objects: vec![bare], ..scene.clone() }).unwrap().pixel(2, 1), want);

    // With a highlight, at each pixel centre: h = normalize(l + v), v toward the eye at (0, 0, 1).
    let specular = [0.3, 0.2, 0.1];
    let lit = ReferenceObject {
        material: ReferenceMaterial { color: albedo, specular, shininess: 20.0, ..ReferenceMaterial::default() },
        ..quad
    };
    let scene = ReferenceScene { objects: vec![lit], ..scene };
    let renderer = Renderer::new(&scene).unwrap();
    for (x, y) in [(0.5, 0.5), (2.5, 1.5), (3.5, 3.5)] {
        let p = [x, -y, 0.0];
        let v = normalize([-p[0], -p[1], 1.0]);
        let half = normalize([v[0], v[1], v[2] + 1.0]);
        let n_dot_h: f64 = half[2];
        let want = [0, 1, 2].map(|i| want[i] + specular[i] * light.color[i] * n_dot_h.powf(20.0));
        let hit = renderer.probe(x, y).unwrap();
        assert!(close(hit.color, want, 1e-14), "({x}, {y}): {:?} vs {want:?}", hit.color);
        assert!(close(hit.world, p, 1e-15));
        assert_eq!(hit.normal, Some([0.0, 0.0, 1.0]));
    }
}

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|x| x / l)
}

#[test]
fn normals_are_interpolated_and_renormalised() {
    // Normals tilted +-45 degrees about y at the left and right edges: half-way between them the interpolated
    // normal is (0, 0, 1/sqrt 2), renormalised to (0, 0, 1).
    let (w, h) = (4, 1);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let mut quad = rectangle(0.0, 4.0, -1.0, 0.0, 0.0, [1.0; 3]);
    quad.shading = Shading::Lit;
    quad.normals = Some(vec![[-s, 0.0, s], [s, 0.0, s], [s, 0.0, s], [-s, 0.0, s]]);
    let lighting =
        ReferenceLighting { ambient: [0.0; 3], lights: vec![ReferenceLight::directional([0.0, 0.0, 2.0], [1.0; 3])] };
    let scene = ReferenceScene { lighting, objects: vec![quad], ..stored_scene(w, h, pixel_camera(w, h)) };
    let renderer = Renderer::new(&scene).unwrap();
    let middle = renderer.probe(2.0, 0.5).unwrap();
    assert!(close(middle.normal.unwrap(), [0.0, 0.0, 1.0], 1e-15));
    assert!(close(middle.color, [1.0; 3], 1e-15));
    // At x = 1 the normal is (-1/2 s, 0, s) normalised: n.l = 2 / sqrt 5.
    let quarter = renderer.probe(1.0, 0.5).unwrap();
    assert!(close(quarter.color, [2.0 / 5f64.sqrt(); 3], 1e-15), "{:?}", quarter.color);
}

// ---------------------------------------------------------------------------------------------------------------
// Errors

#[test]
fn bad_scenes_are_errors() {
    let camera = pixel_camera(2, 2);
    assert_eq!(render(&stored_scene(0, 2, camera)).unwrap_err(), ReferenceError::Size { width: 0, height: 2 });
    let same = Camera { eye: [0.0; 3], ..camera };
    assert_eq!(render(&stored_scene(2, 2, same)).unwrap_err(), ReferenceError::Camera(CameraError::EyeAtTarget));
    let fov = Camera {
        projection: ReferenceProjection::Perspective { fovy: 4.0, aspect: 1.0, near: 1.0, far: 2.0 },
        ..camera
    };
    assert_eq!(render(&stored_scene(2, 2, fov)).unwrap_err(), ReferenceError::Camera(CameraError::FieldOfView));
    let bad = ReferenceObject::new(vec![[0.0; 3]], vec![0, 0, 1]);
    let e = render(&ReferenceScene { objects: vec![bad], ..stored_scene(2, 2, camera) }).unwrap_err();
    assert!(matches!(&e, ReferenceError::Object { object: 0, .. }), "{e}");
    assert_eq!(e.to_string(), "object 0: index 1 is out of range for 1 vertices");
    let scene = model_scene(one_quad_model());
    let depth = PlanOptions { shading: ShadingMode::Depth, ..PlanOptions::default() };
    let wireframe = PlanOptions { wireframe: true, ..PlanOptions::default() };
    for options in [depth, wireframe] {
        assert!(matches!(
            ReferenceScene::from_scene(&scene, &scene.camera(), &options, (4, 4), 1.0),
            Err(ReferenceError::Unsupported(_))
        ));
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Against rastty

/// A quad in the xy plane facing +z, with normals, texture coordinates and a texture (a 4x4 checker of two
/// greys 8 levels apart: bilinear filtering shows, but varies little across a pixel).
fn one_quad_model() -> Model {
    let texture =
        TextureImage::new(4, 4, (0..16u32).map(|i| if (i + i / 4) % 2 == 0 { 0xD0C0B0 } else { 0xC8B8A8 }).collect());
    Model {
        positions: vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ],
        normals: vec![Vec3::Z; 4],
        uvs: Some(vec![Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0)]),
        colors: None,
        tangents: None,
        indices: vec![0, 1, 2, 0, 2, 3],
        parts: vec![Part { name: "quad".into(), indices: 0..6, material: Some(0) }],
        materials: vec![ModelMaterial {
            name: "m".into(),
            diffuse: DEFAULT_DIFFUSE,
            texture: Some(texture),
            ..ModelMaterial::default()
        }],
        warnings: Vec::new(),
        rig: None,
        cameras: Vec::new(),
        lights: Vec::new(),
    }
}

/// `model` shown without a scene file, as rastty prepares it (one object fitted into the unit sphere, the viewer's
/// camera and lights), with its maps sampled without mipmaps.
fn model_scene(model: Model) -> PreparedScene {
    let mut data = SceneData::from_model(model, PathBuf::from("test.obj"));
    // The reference's probe samples the texture at a pixel centre, as rastty does without mipmaps; with them a
    // minified pixel is an average over its footprint (what the reference's image, not its probe, gives).
    for object in &mut data.objects {
        object.material.mip_filter = MipFilter::Off;
    }
    PreparedScene::new(data).unwrap()
}

/// The camera of `--yaw`, `--pitch` and `--distance` (in radii), and `--fov` or `--ortho`.
fn camera(scene: &PreparedScene, yaw: f32, pitch: f32, distance: f32, fov: f32, orthographic: bool) -> SceneCamera {
    let options = CameraOptions {
        yaw_degrees: Some(yaw),
        pitch_degrees: Some(pitch),
        distance: Some(distance),
        fov_degrees: Some(fov),
        orthographic,
        ..CameraOptions::default()
    };
    options.orbit(scene).camera
}

/// rastty's picture of `scene` (one sample per pixel), as `0x00RRGGBB` pixels, and its background packed the same
/// way.
fn rastty_pixels(
    scene: &PreparedScene,
    size: (u32, u32),
    camera: &SceneCamera,
    options: &PlanOptions,
) -> (Vec<u32>, u32) {
    let image = render_scene_image(scene, camera, size, 1, options).unwrap();
    (image.pixels, rastty_core::color::pack_rgb888(image.plan.background))
}

/// rastty's image and the reference of the same scene.
fn both(
    scene: &PreparedScene,
    size: (u32, u32),
    camera: &SceneCamera,
    options: &PlanOptions,
) -> (Vec<u32>, ReferenceImage) {
    let reference = ReferenceScene::from_scene(scene, camera, options, size, f64::from(size.0) / f64::from(size.1));
    let reference = render(&reference.unwrap()).unwrap();
    (rastty_pixels(scene, size, camera, options).0, reference)
}

/// Compares rastty's pixels with the reference: at every pixel centre the reference's probe and rastty agree on
/// coverage (except in pixels the reference finds partly covered, where rastty's fill rule and sub-pixel snapping
/// may decide a centre near an edge the other way) and on colour within `centre_levels` (8-bit rounding, rastty's
/// f32 and 8-bit texture filter). Returns how many centres were compared and the largest difference, in levels.
fn agree(
    scene: &PreparedScene,
    size: (u32, u32),
    camera: &SceneCamera,
    options: &PlanOptions,
    centre_levels: f64,
) -> (usize, f64) {
    let reference =
        ReferenceScene::from_scene(scene, camera, options, size, f64::from(size.0) / f64::from(size.1)).unwrap();
    let renderer = Renderer::new(&reference).unwrap();
    let image = renderer.render();
    let (pixels, background) = rastty_pixels(scene, size, camera, options);
    let (mut compared, mut worst) = (0, 0.0f64);
    for y in 0..size.1 {
        for x in 0..size.0 {
            let p = image.index(x, y);
            let got = [16, 8, 0].map(|s| f64::from((pixels[p] >> s) & 0xFF) / 255.0);
            let hit = renderer.probe(f64::from(x) + 0.5, f64::from(y) + 0.5);
            assert_eq!(hit.is_some(), image.centre_covered[p]);
            let partial = image.coverage[p] > 0.0 && image.coverage[p] < 1.0;
            match hit {
                Some(hit) if pixels[p] != background => {
                    let d = (0..3).map(|c| (got[c] - hit.color[c]).abs() * 255.0).fold(0.0, f64::max);
                    assert!(d <= centre_levels, "({x}, {y}): {got:?} vs {:?}", hit.color);
                    (compared, worst) = (compared + 1, worst.max(d));
                }
                None if pixels[p] == background => {}
                _ => assert!(partial, "({x}, {y}): coverage of the centre differs"),
            }
        }
    }
    (compared, worst)
}

#[test]
fn from_scene_draws_what_rastty_draws() {
    let scene = model_scene(one_quad_model());
    let ortho = camera(&scene, -20.0, 35.0, 3.5, 30.0, true);
    for shading in [ShadingMode::Phong, ShadingMode::Unlit] {
        for camera in [scene.camera(), ortho] {
            let options = PlanOptions { shading, ..PlanOptions::default() };
            let (compared, worst) = agree(&scene, (24, 18), &camera, &options, 1.5);
            assert!(compared > 50, "{compared}");
            assert!(worst > 0.0 || shading == ShadingMode::Unlit);
            // Whole pixels: within a few levels (the light and the checker vary a little across a pixel).
            let (pixels, reference) = both(&scene, (24, 18), &camera, &options);
            for (p, &c) in pixels.iter().enumerate() {
                let got = [16, 8, 0].map(|s| f64::from((c >> s) & 0xFF) / 255.0);
                if reference.coverage[p] == 1.0 {
                    assert!(close(got, reference.rgb[p], 2.0 / 255.0), "{shading:?} pixel {p}");
                }
            }
        }
    }
}

#[test]
fn from_scene_draws_the_builtin_model_as_rastty_does() {
    let scene = model_scene(rastty_scene::builtin::builtin_model().unwrap());
    // Within 1.5 levels, as the quad: rastty decodes texels before blending them, within and between its levels
    // of detail, as the reference does.
    let (compared, worst) = agree(&scene, (40, 30), &scene.camera(), &PlanOptions::default(), 1.5);
    assert!(compared > 150, "{compared}");
    println!("{compared} pixel centres within {worst:.2} levels");
}

/// Two placed Spots (one with her own material, one bronze over her texture and clamped), a placed camera, a
/// world light and the viewer's lights in camera space, a background and an ambient light of the file's.
const TWO_SPOTS: &str = r#"
background = "203040"
ambient = [0.1, 0.12, 0.15]
viewer_lights = true

[camera]
position = [0.5, 1.5, 4]
target = [0, 0.3, 0]
fov = 45

[[lights]]
type = "directional"
direction = [-1, -2, -1.5]
color = [1, 0.9, 0.8]
intensity = 0.8

[[objects]]
mesh = "builtin:spot"
translate = [-0.6, 0, 0]
rotate = [0, 30, 0]
scale = 0.8

[[objects]]
mesh = "builtin:spot"
translate = [0.7, 0.2, -0.5]
rotate = [10, -40, 0]
scale = [0.7, 0.9, 0.7]

[objects.material]
color = [0.8, 0.5, 0.25]
specular = [0.9, 0.7, 0.4]
shininess = 60
wrap = "clamp"
"#;

fn scene_file(text: &str) -> PreparedScene {
    PreparedScene::new(rastty_scene::scene_file::parse(text, "test.toml").unwrap().load().unwrap()).unwrap()
}

#[test]
fn from_scene_draws_a_scene_file_as_rastty_does() {
    let scene = scene_file(TWO_SPOTS);
    let orbited = CameraOptions { yaw_degrees: Some(50.0), orthographic: true, ..CameraOptions::default() };
    let orbited = orbited.orbit(&scene).camera;
    // Untextured: Spot's texture, minified here, has edges so sharp that moving a pixel centre by rastty's
    // sub-pixel step (1/256 pixel) can change the colour by 35 levels. (So can a crease of the bronze Spot's
    // normals under its sharp highlight: these views have no pixel centre on one.)
    let options = PlanOptions { textures: false, ..PlanOptions::default() };
    // Landscape and portrait (the field of view, or height, spans the shorter side), perspective and orthographic.
    for (camera, size) in [(scene.camera(), (40, 30)), (scene.camera(), (24, 36)), (orbited, (36, 24))] {
        let reference = ReferenceScene::from_scene(&scene, &camera, &options, size, 1.0).unwrap();
        assert_eq!(reference.objects.len(), 2);
        assert_eq!(reference.lighting.lights.len(), 3);
        let (compared, worst) = agree(&scene, size, &camera, &options, 2.0);
        assert!(compared > 50, "{size:?}: {compared}");
        println!("{size:?}: {compared} pixel centres within {worst:.2} levels");
    }
    // Point and spot lights, falling off by the inverse square within a range, the spot in camera space.
    let lamps = TWO_SPOTS.replace(
        "type = \"directional\"\ndirection = [-1, -2, -1.5]\ncolor = [1, 0.9, 0.8]\nintensity = 0.8",
        "type = \"point\"\nposition = [0, 3, 2]\nfalloff = \"inverse-square\"\nrange = 9\nintensity = 6\n\n\
         [[lights]]\ntype = \"spot\"\nposition = [0.5, 0.5, 1]\ndirection = [0, -0.3, -1]\ninner_angle = 10\n\
         outer_angle = 25\nfalloff = \"inverse-square\"\nintensity = 4\nspace = \"camera\"",
    );
    let scene = scene_file(&lamps);
    let camera = scene.camera();
    let reference = ReferenceScene::from_scene(&scene, &camera, &options, (40, 30), 40.0 / 30.0).unwrap();
    assert!(reference.lighting.lights.iter().filter(|l| l.place.is_some()).count() == 2);
    let (compared, worst) = agree(&scene, (40, 30), &camera, &options, 2.0);
    assert!(compared > 50, "{compared}");
    println!("point and spot lights: {compared} pixel centres within {worst:.2} levels");
    // What the reference does not draw.
    let shadows = TWO_SPOTS.replace("intensity = 0.8", "intensity = 0.8\nshadows = true");
    let scene = scene_file(&shadows);
    let refused = ReferenceScene::from_scene(&scene, &scene.camera(), &PlanOptions::default(), (8, 8), 1.0);
    assert_eq!(refused.unwrap_err(), ReferenceError::Unsupported("shadows"));
}

#[test]
#[ignore = "slow in debug builds: run with --release -- --ignored"]
fn builtin_model_320x240() {
    let scene = model_scene(rastty_scene::builtin::builtin_model().unwrap());
    let (camera, options, size) = (scene.camera(), PlanOptions::default(), (320, 240));
    let (compared, worst) = agree(&scene, size, &camera, &options, 2.0);
    println!("single samples at pixel centres: {compared} within {worst:.2} levels of rastty");
    let reference_scene = ReferenceScene::from_scene(&scene, &camera, &options, size, 320.0 / 240.0).unwrap();
    let triangles: usize = reference_scene.objects.iter().map(|o| o.indices.len() / 3).sum();
    let start = std::time::Instant::now();
    let reference = render(&reference_scene).unwrap();
    let elapsed = start.elapsed();
    let (pixels, background) = rastty_pixels(&scene, size, &camera, &options);
    let psnr = reference.psnr_rgb888(&pixels).unwrap();
    // Fully covered pixels only (no edge in them): shading and texture differences without anti-aliasing.
    let inside: Vec<usize> = (0..pixels.len()).filter(|&p| reference.coverage[p] == 1.0).collect();
    let interior = ReferenceImage {
        width: inside.len() as u32,
        height: 1,
        rgb: inside.iter().map(|&p| reference.rgb[p]).collect(),
        centre_covered: vec![true; inside.len()],
        coverage: vec![1.0; inside.len()],
    };
    let interior_psnr = interior.psnr_rgb888(&inside.iter().map(|&p| pixels[p]).collect::<Vec<_>>()).unwrap();
    // Pixel centres rastty decided differently (it leaves exactly the background where it draws nothing).
    let disagree = (0..pixels.len()).filter(|&p| reference.centre_covered[p] != (pixels[p] != background)).count();
    let centres = reference.centre_covered.iter().filter(|&&c| c).count();
    let covered: f64 = reference.coverage.iter().sum();
    println!(
        "reference: {triangles} triangles, 320x240 x 256 samples in {:.2} s\n\
         PSNR against rastty: {psnr:.2} dB over the image, {interior_psnr:.2} dB over the {} fully covered pixels\n\
         {centres} pixel centres covered ({disagree} decided differently by rastty), {covered:.1} pixels of coverage",
        elapsed.as_secs_f64(),
        inside.len(),
    );
    rastty_scene::png_file::write_png(std::path::Path::new("/tmp/reference.png"), 320, 240, &reference.to_rgb888())
        .unwrap();
    rastty_scene::png_file::write_png(std::path::Path::new("/tmp/rastty_default.png"), 320, 240, &pixels).unwrap();
    assert!(psnr > 25.0, "{psnr}");
}

#[test]
fn a_placed_light_weakens_by_the_inverse_square_its_range_and_its_cone() {
    let place = |inverse_square, cone| ReferencePlace { position: [0.0, 2.0, 0.0], inverse_square, cone };
    let light = |place| ReferenceLight { to_light: [0.0; 3], color: [1.0; 3], place: Some(place) };
    // 2 units below the light: 1/4; with range 4, the window 1 - (2/4)^4 = 15/16 too.
    assert_eq!(light(place(None, None)).toward([0.0, 0.0, 0.0]), ([0.0, 1.0, 0.0], 1.0));
    assert_eq!(light(place(Some(None), None)).toward([0.0, 0.0, 0.0]), ([0.0, 1.0, 0.0], 0.25));
    assert_eq!(light(place(Some(Some(4.0)), None)).toward([0.0, 0.0, 0.0]).1, 0.25 * 15.0 / 16.0);
    assert_eq!(light(place(Some(Some(2.0)), None)).toward([0.0, -1.0, 0.0]).1, 0.0);
    // A spot pointing down with inner 0 and outer 60 degrees: on the axis all of it; at 41.4 degrees (cosine 3/4)
    // a quarter; beyond 60 degrees nothing.
    let cone = Some(([0.0, -1.0, 0.0], 0.0, std::f64::consts::FRAC_PI_3));
    assert!((light(place(None, cone)).toward([0.0, 0.0, 0.0]).1 - 1.0).abs() < 1e-12);
    let sin = (1.0f64 - 0.75 * 0.75).sqrt();
    assert!((light(place(None, cone)).toward([2.0 * sin / 0.75, 0.0, 0.0]).1 - 0.25).abs() < 1e-12);
    assert_eq!(light(place(None, cone)).toward([4.0, 0.0, 0.0]).1, 0.0);
}
