//! Wireframe lines: one pixel per major-axis step, clipped in homogeneous space, depth-tested.

mod common;

use common::{Count, ascii, assert_pattern};
use rasterm_core::camera::perspective;
use rasterm_core::math::{Mat4, Vec3};
use rasterm_core::mesh::{Indices, Mesh};
use rasterm_core::pipeline::{Cull, DepthTest, DrawState, LineStyle, draw_wireframe};
use rasterm_core::target::{NoDepth, Target};

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
