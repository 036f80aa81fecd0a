//! Multisample anti-aliasing: coverage at four samples per pixel as exact and watertight as at pixel centres, one
//! shading per pixel, the shading of a pixel inside one triangle the single-sample one, bands equal to the frame,
//! lines on every sample, the depth test at every sample, and the resolve.

use crate::common;

use common::{ExactColor, Torus, Tri, both_sides, checker_texels, sample_coverage};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec2, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{DrawState, LineStyle, draw_wireframe};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, SAMPLE_POSITIONS, Samples, resolve_rgb888};
use rastty_core::texture::Texture;

/// A frame whose pixel coordinates survive the trip to NDC and back exactly (a power of two a side).
const SIZE: u32 = 64;
const SAMPLES: usize = 4;

/// Sample `s` of pixel `(x, y)` in 256ths of a pixel.
fn sample_point(x: u32, y: u32, s: usize) -> (i64, i64) {
    let (ox, oy) = SAMPLE_POSITIONS[s];
    (i64::from(x) * 256 + 128 + i64::from(ox) * 32, i64::from(y) * 256 + 128 + i64::from(oy) * 32)
}

/// Whether the triangle with corners `t` (256ths of a pixel, y down) covers the point `p`, in exact integers, by
/// the top-left rule as Direct3D states it (functional specification 11.3, 3.4.2.1): a point on an edge belongs to
/// the triangle when the edge is a top edge (horizontal, the triangle below it) or a left edge (not horizontal,
/// the triangle to its right). Written from that statement, not from the rasterizer's edge functions.
fn covers(t: [(i64, i64); 3], p: (i64, i64)) -> bool {
    let cross = |a: (i64, i64), b: (i64, i64), c: (i64, i64)| (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
    let area = cross(t[0], t[1], t[2]);
    if area == 0 {
        return false;
    }
    (0..3).all(|k| {
        let (a, b, third) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
        let side = cross(a, b, p) * area.signum();
        if side != 0 {
            return side > 0;
        }
        if a.1 == b.1 {
            third.1 > a.1
        } else {
            // The third corner right of the edge at its own height.
            -cross(a, b, third) * (b.1 - a.1).signum() > 0
        }
    })
}

/// xorshift32 (Marsaglia 2003).
fn next(state: &mut u32) -> u32 {
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    *state
}

/// Each sample of random triangles (large, small, slivers, partly outside the frame; both windings; snapped to 8,
/// 4, 2 and 0 sub-pixel bits) is covered exactly when the exact top-left test on the snapped corners says so, and
/// the draw counts one fragment per pixel with a covered sample.
#[test]
fn each_sample_is_covered_as_the_exact_test_says() {
    let mut rng = 0x2545_F491;
    let mut sliver_samples = 0;
    for i in 0..400 {
        // Corners in 256ths of a pixel, from 8 pixels left of and above the frame to 8 right of and below it.
        let corner =
            |rng: &mut u32| (i64::from(next(rng) % (80 * 256)) - 8 * 256, i64::from(next(rng) % (80 * 256)) - 8 * 256);
        let mut t = [corner(&mut rng), corner(&mut rng), corner(&mut rng)];
        match i % 4 {
            // Small: within 3 pixels of the first corner.
            1 => {
                for k in 1..3 {
                    t[k] = (t[0].0 + i64::from(next(&mut rng) % 768), t[0].1 + i64::from(next(&mut rng) % 768));
                }
            }
            // A sliver: the third corner a few 256ths off the line through the other two.
            2 => t[2] = ((t[0].0 + t[1].0) / 2 + i64::from(next(&mut rng) % 7) - 3, (t[0].1 + t[1].1) / 2),
            _ => {}
        }
        let bits = [8u8, 4, 2, 0][i / 4 % 4];
        // The rasterizer snaps to the nearest point of a grid of 2^-bits pixels (halves up).
        let step = 1i64 << (8 - bits);
        let snapped = t.map(|(x, y)| {
            let snap = |v: i64| (v + step / 2).div_euclid(step) * step;
            (snap(x), snap(y))
        });
        let tri: Tri = t.map(|(x, y)| (x as f32 / 256.0, y as f32 / 256.0));
        let state = DrawState { subpixel_bits: bits, ..both_sides() };
        let (counts, stats) = sample_coverage(SIZE, SIZE, 0..SIZE, Samples::Four, &[tri], &state);
        let mut pixels = 0;
        for y in 0..SIZE {
            for x in 0..SIZE {
                let first = ((y * SIZE + x) as usize) * SAMPLES;
                for s in 0..SAMPLES {
                    let expected = u32::from(covers(snapped, sample_point(x, y, s)));
                    assert_eq!(
                        counts[first + s],
                        expected,
                        "triangle {i} {t:?} ({bits} bits): pixel ({x}, {y}) sample {s}"
                    );
                }
                pixels += u64::from(counts[first..first + SAMPLES].contains(&1));
            }
        }
        assert_eq!(stats.fragments, pixels, "triangle {i}: one fragment per pixel with a covered sample");
        if i % 4 == 2 {
            sliver_samples += counts.iter().filter(|&&c| c == 1).count();
        }
    }
    // The slivers cover samples that their pixels' centres would miss: the test reaches them.
    assert!(sliver_samples > 100, "{sliver_samples}");
}

/// A rectangle cut into irregular triangles (a jittered grid, corners on sample positions among them, and a fan
/// around one corner) covers every sample inside it exactly once and none outside: inside means left of and on
/// its left edge, and on its top edge but not on its right or bottom edge, which pass through sample positions.
#[test]
fn triangles_sharing_edges_cover_each_sample_once() {
    // The rectangle's edges (256ths of a pixel) run through samples: x from pixel 4's sample at -3/8 to pixel
    // 57's at +3/8, y from pixel 3's sample at -3/8 to pixel 58's at +3/8.
    let (x0, x1, y0, y1) = (4 * 256 + 128 - 96, 57 * 256 + 128 + 96, 3 * 256 + 128 - 96, 58 * 256 + 128 + 96);
    const N: i64 = 7;
    let mut rng = 0x1234_5678;
    let mut grid = [[(0i64, 0i64); N as usize + 1]; N as usize + 1];
    for (j, row) in grid.iter_mut().enumerate() {
        for (i, p) in row.iter_mut().enumerate() {
            let (i, j) = (i as i64, j as i64);
            *p = (x0 + (x1 - x0) * i / N, y0 + (y1 - y0) * j / N);
            // Inner corners move by up to 1.5 pixels (the cells stay convex); every third lands on a sample
            // position.
            if (1..N).contains(&i) && (1..N).contains(&j) {
                p.0 += i64::from(next(&mut rng) % 768) - 384;
                p.1 += i64::from(next(&mut rng) % 768) - 384;
                if (i + j) % 3 == 0 {
                    let (px, py) = (p.0.div_euclid(256) as u32, p.1.div_euclid(256) as u32);
                    *p = sample_point(px, py, (i + 2 * j) as usize % SAMPLES);
                }
            }
        }
    }
    let corner = |p: (i64, i64)| (p.0 as f32 / 256.0, p.1 as f32 / 256.0);
    let mut tris: Vec<Tri> = Vec::new();
    for j in 0..N as usize {
        for i in 0..N as usize {
            let (a, b, c, d) = (grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]);
            if (i, j) == (3, 3) {
                // A fan of four triangles around a sample position inside the cell, alternately wound.
                let centre = sample_point(((a.0 + c.0) / 512) as u32, ((a.1 + c.1) / 512) as u32, 1);
                let ring = [a, b, c, d];
                for k in 0..ring.len() {
                    let (p, q) = (ring[k], ring[(k + 1) % ring.len()]);
                    tris.push(if k % 2 == 0 {
                        [corner(centre), corner(p), corner(q)]
                    } else {
                        [corner(q), corner(p), corner(centre)]
                    });
                }
            } else if (i + j) % 2 == 0 {
                tris.push([corner(a), corner(b), corner(c)]);
                tris.push([corner(a), corner(c), corner(d)]);
            } else {
                tris.push([corner(b), corner(d), corner(a)]);
                tris.push([corner(b), corner(c), corner(d)]);
            }
        }
    }
    let (counts, _) = sample_coverage(SIZE, SIZE, 0..SIZE, Samples::Four, &tris, &both_sides());
    let mut inside = 0;
    for y in 0..SIZE {
        for x in 0..SIZE {
            for s in 0..SAMPLES {
                let (px, py) = sample_point(x, y, s);
                let expected = u32::from((x0..x1).contains(&px) && (y0..y1).contains(&py));
                let count = counts[(y * SIZE + x) as usize * SAMPLES + s];
                assert_eq!(count, expected, "pixel ({x}, {y}) sample {s}");
                inside += expected;
            }
        }
    }
    // Pixels 4 to 57 across and 3 to 58 down; on the right edge sample 1 (+3/8 across) is outside, on the bottom
    // edge sample 3 (+3/8 down): samples 0 and 2 in 54 x 56 pixels, sample 1 in 53 x 56, sample 3 in 54 x 55.
    assert_eq!(inside, 2 * 54 * 56 + 53 * 56 + 54 * 55);
}

/// A torus, textured and lit, with every triangle's corners its own (so that each can carry a colour of its own).
struct Unshared {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Vec<Vec2>,
    /// Each corner's colour: its triangle's number, as 16 levels a channel.
    ids: Vec<Vec3>,
}

impl Unshared {
    fn new() -> Self {
        let torus = Torus::new(1.0, 0.4, 24, 12);
        let corners: Vec<usize> = torus.indices.iter().map(|&i| usize::from(i)).collect();
        let id = |t: usize| Vec3::new((t % 16) as f32 / 15.0, (t / 16 % 16) as f32 / 15.0, (t / 256) as f32 / 15.0);
        Self {
            positions: corners.iter().map(|&i| torus.positions[i]).collect(),
            normals: corners.iter().map(|&i| torus.normals[i]).collect(),
            uvs: corners.iter().map(|&i| torus.uvs[i]).collect(),
            ids: (0..corners.len()).map(|c| id(c / 3)).collect(),
        }
    }
}

/// Draws `mesh` under `material` and `shading` into `samples` per pixel of rows `rows` of a `SIZE x SIZE` frame:
/// exact colours and depths.
fn render(
    mesh: Mesh<'_>,
    shading: ShadingModel,
    material: Material<'_>,
    samples: Samples,
    rows: core::ops::Range<u32>,
) -> (Vec<[u32; 3]>, Vec<f32>) {
    // The torus (1.4 across its outer rim) well inside the 0.9-radian view: the corners are background.
    let view = look_at(Vec3::new(0.6, 1.6, 3.2), Vec3::ZERO, Vec3::Y).unwrap();
    let transforms = Transforms::new(
        Mat4::from_axis_angle(Vec3::new(1.0, 0.2, 0.0), 0.7),
        view,
        perspective(0.9, 1.0, 0.5, 10.0).unwrap(),
    );
    let object = Object { mesh, tangents: None, transforms, shading, material };
    let sun = [Light::directional(Vec3::new(0.3, 1.0, 0.6), Vec3::ONE)];
    let lights = Lighting { ambient: Vec3::splat(0.1), lights: &sun, environment: None, space: ShadingSpace::Linear };
    let len = SIZE as usize * (rows.end - rows.start) as usize * samples.count();
    let (mut color, mut depth) = (vec![[0u32; 3]; len], vec![0f32; len]);
    let mut target = common::multisampled(ExactColor(&mut color), &mut depth[..], SIZE, SIZE, rows, samples);
    target.clear(Vec3::new(0.2, 0.3, 0.4));
    draw_mesh(&mut target, &object, &lights, &DrawState::default()).unwrap();
    (color, depth)
}

/// A pixel whose centre and four samples one triangle covers gets, at every sample, exactly the colour the
/// single-sample draw gives it (one shading, at the centre, with the same arithmetic), and pixels on the torus's
/// outline get some samples of the background.
#[test]
fn a_pixel_inside_one_triangle_is_shaded_once_as_without_samples() {
    let torus = Unshared::new();
    let bare = Mesh::new(&torus.positions, Indices::Sequential).unwrap();
    let ids = bare.with_colors(&torus.ids).unwrap();
    let textured = bare.with_normals(&torus.normals).unwrap().with_uvs(&torus.uvs).unwrap();
    let texels = checker_texels();
    let material = Material { diffuse: Some(Texture::new(&texels, 8, 8).unwrap()), ..Material::plain(Vec3::ONE) };
    let plain = Material::plain(Vec3::ONE);
    let (id_samples, _) = render(ids, ShadingModel::Unlit, plain, Samples::Four, 0..SIZE);
    let (id_centres, _) = render(ids, ShadingModel::Unlit, plain, Samples::One, 0..SIZE);
    let (samples, _) = render(textured, ShadingModel::Phong, material, Samples::Four, 0..SIZE);
    let (centres, _) = render(textured, ShadingModel::Phong, material, Samples::One, 0..SIZE);
    let background = id_centres[0];
    let (mut inside, mut outline) = (0, 0);
    for (p, &centre) in id_centres.iter().enumerate() {
        let ids = &id_samples[p * SAMPLES..(p + 1) * SAMPLES];
        if centre != background && ids.iter().all(|&id| id == centre) {
            inside += 1;
            for s in 0..SAMPLES {
                assert_eq!(samples[p * SAMPLES + s], centres[p], "pixel {p} sample {s}");
            }
        } else if ids.contains(&background) && ids.iter().any(|&id| id != background) {
            outline += 1;
        }
    }
    assert!(inside > 500 && outline > 100, "{inside} inside, {outline} on the outline");
}

/// Bands of 1 to 64 rows get the frame's samples and depths, bit for bit.
#[test]
fn a_band_gets_the_frames_samples() {
    let torus = Unshared::new();
    let textured = Mesh::new(&torus.positions, Indices::Sequential)
        .unwrap()
        .with_normals(&torus.normals)
        .unwrap()
        .with_uvs(&torus.uvs)
        .unwrap();
    let texels = checker_texels();
    let material = Material { diffuse: Some(Texture::new(&texels, 8, 8).unwrap()), ..Material::plain(Vec3::ONE) };
    let (frame, frame_depth) = render(textured, ShadingModel::Phong, material, Samples::Four, 0..SIZE);
    for height in [1, 3, 7, 16, 64] {
        for y0 in (0..SIZE).step_by(height as usize) {
            let rows = y0..(y0 + height).min(SIZE);
            let (band, depth) = render(textured, ShadingModel::Phong, material, Samples::Four, rows.clone());
            let start = (y0 * SIZE) as usize * SAMPLES;
            assert!(band == frame[start..start + band.len()], "band {rows:?}: colours");
            let same_depths = depth.iter().zip(&frame_depth[start..]).all(|(a, b)| a.to_bits() == b.to_bits());
            assert!(same_depths, "band {rows:?}: depths");
        }
    }
}

/// A wireframe drawn into four samples per pixel lights every sample of the pixels it lights without them, so its
/// resolved picture is the single-sample one.
#[test]
fn lines_write_every_sample_of_their_pixels() {
    let torus = Torus::new(1.0, 0.4, 16, 8);
    let mesh = torus.mesh();
    let view = look_at(Vec3::new(0.0, 1.5, 2.5), Vec3::ZERO, Vec3::Y).unwrap();
    let clip_from_object = perspective(0.9, 1.0, 0.5, 10.0).unwrap() * view;
    let style = LineStyle { color: Vec3::new(1.0, 0.5, 0.25), ..LineStyle::default() };
    let draw = |samples: Samples| {
        let len = (SIZE * SIZE) as usize * samples.count();
        let (mut color, mut depth) = (vec![0u32; len], vec![0f32; len]);
        let mut target = common::multisampled(Rgb888(&mut color), &mut depth[..], SIZE, SIZE, 0..SIZE, samples);
        target.clear(Vec3::ZERO);
        let stats = draw_wireframe(&mut target, &mesh, &clip_from_object, &style, &DrawState::default());
        (color, stats.fragments)
    };
    let (single, single_fragments) = draw(Samples::One);
    let (multi, multi_fragments) = draw(Samples::Four);
    assert_eq!(multi_fragments, single_fragments);
    assert!(single_fragments > 200, "{single_fragments}");
    let mut resolved = vec![0u32; (SIZE * SIZE) as usize];
    resolve_rgb888(&multi, Samples::Four, ShadingSpace::Linear, &mut resolved).unwrap();
    assert!(resolved == single);
    // Four equal samples: each pixel's samples are its single-sample colour.
    assert!(multi.chunks_exact(SAMPLES).zip(&single).all(|(s, &p)| s.iter().all(|&v| v == p)));
}

/// An edge's pixels resolve to the mean light of their samples: a white triangle over black covering two of a
/// pixel's four samples gives half the light, code 188.
#[test]
fn an_edge_pixel_resolves_to_its_samples_mean_light() {
    // A vertical edge at x = 10.5 px: samples at -3/8 and -1/8 of pixel 10 lie left of it, +1/8 and +3/8 right.
    let tri: Tri = [(10.5, -20.0), (40.0, 30.0), (10.5, 80.0)];
    let positions: Vec<Vec3> = tri.iter().map(|&(x, y)| Vec3::new(x, y, 0.5)).collect();
    let mesh = Mesh::new(&positions, Indices::Sequential).unwrap();
    let len = (SIZE * SIZE) as usize * SAMPLES;
    let (mut color, mut depth) = (vec![0u32; len], vec![0f32; len]);
    let mut target = common::multisampled(Rgb888(&mut color), &mut depth[..], SIZE, SIZE, 0..SIZE, Samples::Four);
    target.clear(Vec3::ZERO);
    let shader = common::ScreenSpace { width: SIZE as f32, height: SIZE as f32 };
    rastty_core::pipeline::draw(&mut target, &mesh, &shader, &both_sides()).unwrap();
    let mut pixels = vec![0u32; (SIZE * SIZE) as usize];
    resolve_rgb888(&color, Samples::Four, ShadingSpace::Linear, &mut pixels).unwrap();
    let row = 30 * SIZE as usize;
    // Samples 1 (+3/8) and 3 (+1/8) of pixel 10 are right of the edge, 0 (-1/8) and 2 (-3/8) left of it.
    assert_eq!(&color[(row + 10) * SAMPLES..(row + 11) * SAMPLES], &[0, 0xFFFFFF, 0, 0xFFFFFF]);
    assert_eq!(&pixels[row + 9..row + 12], &[0, 0xBCBCBC, 0xFFFFFF]);
}

/// The depth test holds at every sample: a square drawn first, nearer, keeps all of its samples against a larger
/// one drawn behind it afterwards, with the depths the single-sample draw stores. The near square spans pixels 16
/// to 47 both ways (its edges on pixel boundaries, every sample of those pixels inside), so exactly 32 x 32 x 4
/// samples are its.
#[test]
fn a_nearer_triangle_keeps_its_samples_against_one_drawn_later() {
    const NEAR: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    const FAR: Vec3 = Vec3::new(0.0, 0.0, 1.0);
    let square = |half: f32, z: f32| {
        [(-half, -half), (half, -half), (half, half), (-half, -half), (half, half), (-half, half)]
            .map(|(x, y)| Vec3::new(x, y, z))
    };
    let (near, far) = (square(0.5, -1.5), square(1.0, -2.5));
    let draw = |samples: Samples| {
        let len = (SIZE * SIZE) as usize * samples.count();
        let (mut color, mut depth) = (vec![[0u32; 3]; len], vec![0f32; len]);
        let mut target = common::multisampled(ExactColor(&mut color), &mut depth[..], SIZE, SIZE, 0..SIZE, samples);
        target.clear(Vec3::ZERO);
        let projection = rastty_core::camera::orthographic(-1.0, 1.0, -1.0, 1.0, 1.0, 3.0).unwrap();
        let transforms = Transforms::new(Mat4::IDENTITY, Mat4::IDENTITY, projection);
        let lights = Lighting { ambient: Vec3::ONE, lights: &[], environment: None, space: ShadingSpace::Linear };
        for (positions, color) in [(&near, NEAR), (&far, FAR)] {
            let mesh = Mesh::new(positions, Indices::Sequential).unwrap();
            let object = Object {
                mesh,
                tangents: None,
                transforms,
                shading: ShadingModel::Unlit,
                material: Material::plain(color),
            };
            draw_mesh(&mut target, &object, &lights, &DrawState::default()).unwrap();
        }
        (color, depth)
    };
    let (centres, centre_depths) = draw(Samples::One);
    let (samples, sample_depths) = draw(Samples::Four);
    let near_color = centres[(SIZE * SIZE / 2 + SIZE / 2) as usize];
    let far_color = centres[0];
    assert_ne!(near_color, far_color);
    assert_eq!(samples.iter().filter(|&&c| c == near_color).count(), 32 * 32 * SAMPLES);
    for (p, centre_depth) in centre_depths.iter().enumerate() {
        let (x, y) = (p as u32 % SIZE, p as u32 / SIZE);
        let inside = (16..48).contains(&x) && (16..48).contains(&y);
        for s in 0..SAMPLES {
            let i = p * SAMPLES + s;
            assert_eq!(samples[i], if inside { near_color } else { far_color }, "pixel ({x}, {y}) sample {s}");
            assert_eq!(sample_depths[i].to_bits(), centre_depth.to_bits(), "pixel ({x}, {y}) sample {s}");
        }
    }
}
