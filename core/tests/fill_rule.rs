//! Coverage and the top-left fill rule, asserted as ASCII art (`#` = covered once, `2` = twice, `.` = not).

use crate::common;

use common::{assert_pattern, both_sides, coverage};
use rastty_core::pipeline::{Cull, DrawState, Winding};

#[test]
fn right_triangle_covers_centres_strictly_inside_and_on_top_left_edges() {
    // Corners on pixel corners: the centres on the hypotenuse x = y (its right edge) are left out.
    let (c, stats) = coverage(6, 6, &[[(0.0, 0.0), (0.0, 6.0), (6.0, 6.0)]], &both_sides());
    assert_pattern(&c, 6, &["......", "#.....", "##....", "###...", "####..", "#####."]);
    assert_eq!(stats.fragments, 15);
}

#[test]
fn top_edge_through_centres_is_included_bottom_edge_is_not() {
    // A rectangle from y = 0.5 to y = 2.5: its top edge runs through the centres of row 0, its bottom edge through
    // those of row 2. Top-left rule: row 0 in, row 2 out.
    let rect = [[(0.0, 0.5), (0.0, 2.5), (4.0, 2.5)], [(0.0, 0.5), (4.0, 2.5), (4.0, 0.5)]];
    let (c, _) = coverage(4, 4, &rect, &both_sides());
    assert_pattern(&c, 4, &["####", "####", "....", "...."]);
}

#[test]
fn left_edge_through_centres_is_included_right_edge_is_not() {
    let rect = [[(0.5, 0.0), (0.5, 4.0), (2.5, 4.0)], [(0.5, 0.0), (2.5, 4.0), (2.5, 0.0)]];
    let (c, _) = coverage(4, 4, &rect, &both_sides());
    assert_pattern(&c, 4, &["##..", "##..", "##..", "##.."]);
}

#[test]
fn quad_diagonal_is_covered_once() {
    // Two triangles sharing the diagonal of a square whose diagonal passes through pixel centres.
    let square = [[(0.0, 0.0), (0.0, 5.0), (5.0, 5.0)], [(0.0, 0.0), (5.0, 5.0), (5.0, 0.0)]];
    let (c, _) = coverage(5, 5, &square, &both_sides());
    assert_pattern(&c, 5, &["#####", "#####", "#####", "#####", "#####"]);
}

#[test]
fn four_triangles_meeting_at_a_pixel_centre_cover_it_once() {
    let centre = (2.5, 2.5);
    let fan = [
        [centre, (0.0, 0.0), (5.0, 0.0)],
        [centre, (5.0, 0.0), (5.0, 5.0)],
        [centre, (5.0, 5.0), (0.0, 5.0)],
        [centre, (0.0, 5.0), (0.0, 0.0)],
    ];
    let (c, _) = coverage(5, 5, &fan, &both_sides());
    assert_pattern(&c, 5, &["#####", "#####", "#####", "#####", "#####"]);
}

#[test]
fn winding_decides_culling() {
    // (0,0) (0,4) (4,4) in y-down screen space is counter-clockwise in y-up NDC: front-facing by default.
    let ccw = [[(0.0, 0.0), (0.0, 4.0), (4.0, 4.0)]];
    let cw = [[(0.0, 0.0), (4.0, 4.0), (0.0, 4.0)]];
    let back = DrawState::default();
    let (c, stats) = coverage(4, 4, &ccw, &back);
    assert_eq!((stats.rasterized, stats.culled), (1, 0));
    assert_pattern(&c, 4, &["....", "#...", "##..", "###."]);
    let (_, stats) = coverage(4, 4, &cw, &back);
    assert_eq!((stats.rasterized, stats.culled, stats.fragments), (0, 1, 0));
    let front = DrawState { cull: Cull::Front, ..DrawState::default() };
    assert_eq!(coverage(4, 4, &ccw, &front).1.culled, 1);
    assert_eq!(coverage(4, 4, &cw, &front).1.culled, 0);
    let clockwise_front = DrawState { front_face: Winding::Clockwise, ..DrawState::default() };
    assert_eq!(coverage(4, 4, &ccw, &clockwise_front).1.culled, 1);
    assert_eq!(coverage(4, 4, &cw, &clockwise_front).1.culled, 0);
}

#[test]
fn zero_area_triangles_produce_nothing() {
    let cases = [
        [(0.0, 0.0), (2.0, 2.0), (4.0, 4.0)], // collinear
        [(1.0, 1.0), (1.0, 1.0), (3.0, 2.0)], // repeated vertex
        [(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)], // a point
        // Collinear once snapped to 1/256 px: the middle vertex is 1/1024 px off the line.
        [(0.0, 0.0), (2.0, 2.0 + 1.0 / 1024.0), (4.0, 4.0)],
    ];
    for tri in cases {
        let (c, stats) = coverage(5, 5, &[tri], &both_sides());
        assert!(c.iter().all(|&n| n == 0), "{tri:?}");
        assert_eq!((stats.degenerate, stats.fragments), (1, 0), "{tri:?}");
    }
}

#[test]
fn subpixel_bits_decide_where_vertices_snap() {
    // A rectangle whose right edge is at x = 1.5 + 1/64, just right of column 1's centre.
    let r = 1.5 + 1.0 / 64.0;
    let rect = [[(0.0, 0.0), (0.0, 2.0), (r, 2.0)], [(0.0, 0.0), (r, 2.0), (r, 0.0)]];
    let bits = |subpixel_bits| coverage(3, 2, &rect, &DrawState { subpixel_bits, ..both_sides() }).0;
    // 8 bits represent the edge exactly: column 1 is inside.
    assert_pattern(&bits(8), 3, &["##.", "##."]);
    // 4 bits snap it onto the centre itself (24.25/16 -> 24/16): a right edge, so column 1 is out.
    assert_pattern(&bits(4), 3, &["#..", "#.."]);
    // 0 bits round it to x = 2: column 1 is in again.
    assert_pattern(&bits(0), 3, &["##.", "##."]);
}

#[test]
fn pixels_outside_the_frame_are_never_visited() {
    let (c, stats) = coverage(4, 3, &[[(-10.0, -10.0), (-10.0, 20.0), (20.0, -10.0)]], &both_sides());
    assert_pattern(&c, 4, &["####", "####", "####"]);
    assert_eq!(stats.fragments, 12);
}

#[test]
fn float_edges_follow_the_same_fill_rule_on_exact_inputs() {
    use rastty_core::pipeline::EdgeArithmetic;
    // Corners on pixel corners and edges through centres are exact in f32 too: the same pixels as fixed point.
    let float = DrawState { edges: EdgeArithmetic::Float, ..both_sides() };
    let rect = [[(0.0, 0.5), (0.0, 2.5), (4.0, 2.5)], [(0.0, 0.5), (4.0, 2.5), (4.0, 0.5)]];
    assert_pattern(&coverage(4, 4, &rect, &float).0, 4, &["####", "####", "....", "...."]);
    let square = [[(0.0, 0.0), (0.0, 5.0), (5.0, 5.0)], [(0.0, 0.0), (5.0, 5.0), (5.0, 0.0)]];
    assert_pattern(&coverage(5, 5, &square, &float).0, 5, &["#####", "#####", "#####", "#####", "#####"]);
    let (c, stats) = coverage(6, 6, &[[(0.0, 0.0), (0.0, 6.0), (6.0, 6.0)]], &float);
    assert_pattern(&c, 6, &["......", "#.....", "##....", "###...", "####..", "#####."]);
    assert_eq!(stats.fragments, 15);
    // No snapping: an edge 1/1024 px right of a centre includes it, where 8-bit snapping moves the edge onto the
    // centre itself (a right edge: excluded).
    let r = 1.5 + 1.0 / 1024.0;
    let rect = [[(0.0, 0.0), (0.0, 2.0), (r, 2.0)], [(0.0, 0.0), (r, 2.0), (r, 0.0)]];
    assert_pattern(&coverage(3, 2, &rect, &float).0, 3, &["##.", "##."]);
    assert_pattern(&coverage(3, 2, &rect, &both_sides()).0, 3, &["#..", "#.."]);
}
