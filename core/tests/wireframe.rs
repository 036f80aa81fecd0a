//! Wireframe lines: one pixel per major-axis step, clipped in homogeneous space, depth-tested.

use crate::common;

use common::{Count, PlainDepth, PlainDepth16, ascii, assert_pattern, assert_same_depths};
use core::ops::Range;
use rastty_core::camera::{look_at, orthographic, perspective};
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{Cull, DepthTest, DrawState, LineStyle, Winding, draw_wireframe};

use rastty_core::target::{DepthBuffer, NoDepth, Rgb888, Target};

/// Screen pixels (x right, y down) of a `w x h` frame to clip space.
fn screen(w: f32, h: f32) -> Mat4 {
    Mat4::from_rows([2.0 / w, 0.0, 0.0, -1.0], [0.0, -2.0 / h, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0])
}

fn wire(w: u32, h: u32, positions: &[Vec3], clip_from_object: &Mat4, state: &DrawState) -> (Vec<u32>, u64) {
    let mesh = Mesh::new(positions, Indices::Sequential).unwrap();
    let mut counts = vec![0u32; (w * h) as usize];
    let mut target = Target::new(Count(&mut counts), NoDepth, w, h).unwrap();
    let stats = draw_wireframe(&mut target, &mesh, clip_from_object, &LineStyle::default(), state);
    (counts, stats.fragments)
}

fn no_cull() -> DrawState {
    DrawState { cull: Cull::None, depth_test: DepthTest::Off, ..DrawState::default() }
}

#[test]
fn triangle_outline() {
    let tri = [(0.5, 0.5), (0.5, 6.5), (6.5, 6.5)].map(|(x, y)| Vec3::new(x, y, 0.5));
    let (c, n) = wire(8, 8, &tri, &screen(8.0, 8.0), &no_cull());
    assert_pattern(
        &c,
        8,
        &["2.......", "##......", "#.#.....", "#..#....", "#...#...", "#....#..", "2#####2.", "........"],
    );
    // Each edge lights 7 pixels, end points included: the corners are lit by both of their edges.
    assert_eq!(n, 21);
}

#[test]
fn shared_edges_light_the_same_pixels_from_both_triangles() {
    // Triangles (a, b, c) and (a, c, d) of a quad; their shared diagonal a-c runs in opposite directions.
    let (a, b, c, d) = ((0.3, 0.2), (0.3, 6.7), (7.6, 6.1), (7.2, 0.4));
    let lit = |tri: [(f32, f32); 3]| {
        let positions = tri.map(|(x, y)| Vec3::new(x, y, 0.5));
        wire(8, 7, &positions, &screen(8.0, 7.0), &no_cull()).0
    };
    let (first, second) = (lit([a, b, c]), lit([c, a, d]));
    // Outside the diagonal the outlines meet only at its two end pixels, so the pixels lit by both triangles are
    // exactly the diagonal's 8 (one per column, x = 0.3 to 7.6) if both draws light the same ones.
    let both = first.iter().zip(&second).filter(|(p, q)| **p > 0 && **q > 0).count();
    assert_eq!(both, 8, "\n{}\n\n{}", ascii(&first, 8).join("\n"), ascii(&second, 8).join("\n"));
}

#[test]
fn lines_crossing_the_near_plane_are_clipped_not_wrapped() {
    // A triangle on the floor reaching behind the camera: drawn unclipped, its edges would wrap around and cross
    // the upper half of the picture. Clipped, every lit pixel is below the horizon (row 8 of 16).
    let projection = perspective(1.2, 1.0, 0.5, 50.0).unwrap();
    let floor = [Vec3::new(-3.0, -1.0, 3.0), Vec3::new(3.0, -1.0, 3.0), Vec3::new(0.0, -1.0, -20.0)];
    let (c, n) = wire(16, 16, &floor, &projection, &no_cull());
    assert!(n > 10, "{}", ascii(&c, 16).join("\n"));
    assert!(c[..16 * 8].iter().all(|&k| k == 0), "{}", ascii(&c, 16).join("\n"));
}

#[test]
fn culled_triangles_draw_no_edges() {
    let cw = [(0.5, 0.5), (6.5, 6.5), (0.5, 6.5)].map(|(x, y)| Vec3::new(x, y, 0.5));
    let back = DrawState { depth_test: DepthTest::Off, ..DrawState::default() };
    assert_eq!(wire(8, 8, &cw, &screen(8.0, 8.0), &back).1, 0);
    assert!(wire(8, 8, &cw, &screen(8.0, 8.0), &no_cull()).1 > 0);
}

/// A nearly horizontal edge crosses the target's first and last rows billions of columns away: the column range
/// derived from those crossings saturates instead of overflowing, and the edge along row 0 is drawn in full.
#[test]
fn nearly_horizontal_edges_with_far_row_crossings_are_drawn() {
    let tri = [Vec3::new(-2000.0, 1.0, 0.5), Vec3::new(2000.0, 0.99999994, 0.5), Vec3::new(0.0, -0.5, 0.5)];
    let (c, _) = wire(8, 8, &tri, &Mat4::IDENTITY, &no_cull());
    assert!(c[..8].iter().all(|&n| n > 0), "row 0 is lit:\n{}", ascii(&c, 8).join("\n"));
}

/// The wireframe of `positions` drawn into the rows `rows` of a `w x h` frame: the pixels lit and the draw's fragments.
fn wire_into<D: DepthBuffer>(
    (w, h, rows): (u32, u32, Range<u32>),
    lit: &mut [u32],
    depth: D,
    positions: &[Vec3],
    clip_from_object: &Mat4,
    (style, state): (&LineStyle, &DrawState),
) -> u64 {
    let mesh = Mesh::new(positions, Indices::Sequential).unwrap();
    let mut target = Target::band(Count(lit), depth, w, h, rows).unwrap();
    target.clear(Vec3::ZERO);
    draw_wireframe(&mut target, &mesh, clip_from_object, style, state).fragments
}

/// Draws the wireframe of `positions` whole into the library's `&mut [f32]` and `&mut [u16]`, and in `bands` into
/// a caller's own buffers ([`PlainDepth`], [`PlainDepth16`]); asserts that each band lights the frame's pixels and
/// stores its depths bit for bit, and returns the frame's `f32` depths, `u16` depths and lit pixels.
fn wire_depths(
    (w, h): (u32, u32),
    bands: &[(u32, u32)],
    positions: &[Vec3],
    clip_from_object: &Mat4,
    pen: (&LineStyle, &DrawState),
) -> (Vec<f32>, Vec<u16>, Vec<u32>) {
    let n = (w * h) as usize;
    let (mut lit, mut lit16, mut depth, mut depth16) = (vec![0; n], vec![0; n], vec![0f32; n], vec![0u16; n]);
    let fragments = wire_into((w, h, 0..h), &mut lit, &mut depth[..], positions, clip_from_object, pen);
    wire_into((w, h, 0..h), &mut lit16, &mut depth16[..], positions, clip_from_object, pen);
    let mut band_fragments = 0;
    for &(y0, y1) in bands {
        let rows = (y0 * w) as usize..(y1 * w) as usize;
        let (mut band_lit, mut band_depth) = (vec![0; rows.len()], vec![0f32; rows.len()]);
        let band = (w, h, y0..y1);
        band_fragments +=
            wire_into(band.clone(), &mut band_lit, PlainDepth(&mut band_depth), positions, clip_from_object, pen);
        let what = format!("band {y0}..{y1}");
        assert_same_depths(&format!("{what}, f32"), &band_depth, &depth[rows.clone()], w as usize, y0 as usize);
        assert_eq!(band_lit, lit[rows.clone()], "{what}: lit pixels");
        let (mut band_lit, mut band_depth16) = (vec![0; rows.len()], vec![0u16; rows.len()]);
        wire_into(band, &mut band_lit, PlainDepth16(&mut band_depth16), positions, clip_from_object, pen);
        assert_same_depths(&format!("{what}, u16"), &band_depth16, &depth16[rows.clone()], w as usize, y0 as usize);
        assert_eq!(band_lit, lit16[rows], "{what}: lit pixels over u16 depth");
    }
    assert_eq!(band_fragments, fragments, "the bands light the frame's pixels");
    (depth, depth16, lit)
}

/// Fuzzing finding F5, the case found (`band 0..11: depth (0, 0) = -7.637109e1, the whole frame has 0e0`): a
/// depth bias of 77.4 takes a line at depth 0.99999994 far below the near plane. The library's `f32` buffer
/// stored 0 but a caller's own buffer (the fuzz target's band) stored -76.37, because the clamp lived in one buffer
/// type. Now the pipeline clamps, once, for every buffer: each lit pixel stores exactly +0, in `f32` and `u16`,
/// whole and in the bands the fuzz target drew (its flat-shaded triangle left out: the line alone reproduces it).
#[test]
fn a_depth_bias_past_the_near_plane_stores_0_in_every_buffer() {
    let view = look_at(
        Vec3::new(-60.191406, 45.875, -97.93359),
        Vec3::new(92.08594, 16941.281, -124.14453),
        Vec3::new(114.875, -1e20, -70.76953),
    )
    .unwrap();
    let projection = orthographic(3.2382813, 5.6078584e28, 3.000073e-26, 16384.5, -3.393218e25, 111.765625).unwrap();
    let clip = projection * view * Mat4::from_scale(Vec3::new(16384.5, -69.34375, 4.65829e-13));
    let positions = [
        Vec3::new(-16.0, -885.97125, -28.0),
        Vec3::new(95.578125, -59.17578, 87.19531),
        Vec3::new(-111.0, -6.0, 6.656178e31),
    ];
    let state = DrawState { cull: Cull::Back, front_face: Winding::Clockwise, ..DrawState::default() };
    let style = LineStyle { color: Vec3::ONE, depth_bias: 77.37109 };
    let bands = [(0, 11), (11, 21), (21, 22)];
    let (depth, depth16, lit) = wire_depths((61, 22), &bands, &positions, &clip, (&style, &state));
    let lit_pixels: Vec<usize> = (0..lit.len()).filter(|&i| lit[i] > 0).collect();
    assert_eq!(lit_pixels, (0..22).map(|y| y * 61).collect::<Vec<_>>(), "column 0 is lit");
    for i in lit_pixels {
        assert_eq!(depth[i].to_bits(), 0, "pixel {i}: {:e}", depth[i]);
        assert_eq!(depth16[i], 0);
    }
}

/// Fuzzing finding F6, the case found (`band 0..54: depth (0, 2) = -2.3069382e-2, the whole frame has 0e0`), with
/// no depth bias: an edge cut by the near plane ends at depth 0 inside pixel (0, 2), whose centre lies beyond that
/// end, and its depth was extrapolated past the end to -0.023. The end pixel stores the end's depth, exactly +0.
#[test]
fn a_line_cut_by_the_near_plane_ends_at_depth_0() {
    let view = look_at(
        Vec3::new(-102.63281, 44.378906, 15.8203125),
        Vec3::new(-45.632813, 118.35547, -1.1754944e-38),
        Vec3::new(-30.0, 52.558594, -2.7656486e-9),
    )
    .unwrap();
    let projection = orthographic(22.085938, -3.4028235e38, 97.01953, -61.0, 68.0, 57.09375).unwrap();
    let positions = [
        Vec3::new(10.0, 1e20, 107.0),
        Vec3::new(-4.501585e-20, 70.36328, 74.046875),
        Vec3::new(-35.714844, -99.0, -100.83984),
    ];
    let state = DrawState { cull: Cull::Back, front_face: Winding::CounterClockwise, ..DrawState::default() };
    let style = LineStyle { color: Vec3::ONE, depth_bias: 3.0677848e-20 };
    let bands: Vec<(u32, u32)> = (0..54).map(|y| (y, y + 1)).collect();
    let (depth, _, lit) = wire_depths((20, 54), &bands, &positions, &(projection * view), (&style, &state));
    assert_eq!((0..lit.len()).filter(|&i| lit[i] > 0).collect::<Vec<_>>(), [0, 20, 40], "rows 0 to 2 of column 0");
    assert_eq!(depth[40].to_bits(), 0, "the near end: {:e}", depth[40]);
    assert!(depth[0] > depth[20] && depth[20] > 0.0 && depth[0] < 1.0, "{:?}", &depth[..41]);
}

/// A line whose end lies inside a pixel short of its centre gives that pixel the end's depth: a segment from
/// x = 2.3 (depth 0.75) to x = 2.4 (depth 0.5) lights pixel 2, whose centre is 0.1 past the far end. Extrapolated
/// it was at depth 0.25 and showed through a surface at 0.4 that hides the whole segment.
#[test]
fn an_end_pixel_takes_the_end_points_depth_not_an_extrapolation() {
    let segment = [Vec3::new(2.3, 1.5, 0.75), Vec3::new(2.4, 1.5, 0.5), Vec3::new(2.3, 1.5, 0.75)];
    let pen =
        (&LineStyle { color: Vec3::ONE, depth_bias: 0.0 }, &DrawState { cull: Cull::None, ..DrawState::default() });
    let bands = [(0, 1), (1, 2), (2, 3)];
    let (depth, depth16, lit) = wire_depths((4, 3), &bands, &segment, &screen(4.0, 3.0), pen);
    // The edge back from the end lights it again at the same depth, which fails the less test.
    assert_eq!(lit, [0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0], "pixel (2, 1) only");
    assert_eq!(depth[6], 0.5);
    assert_eq!(depth16[6], 32768);

    // Behind a surface at depth 0.4, nothing of it shows.
    let mut color = [0u32; 12];
    let mut surface = [0.4f32; 12];
    let mut target = Target::new(Rgb888(&mut color), &mut surface[..], 4, 3).unwrap();
    let mesh = Mesh::new(&segment, Indices::Sequential).unwrap();
    assert_eq!(draw_wireframe(&mut target, &mesh, &screen(4.0, 3.0), pen.0, pen.1).fragments, 0);
    assert!(color.iter().all(|&c| c == 0));
}
