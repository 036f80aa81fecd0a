//! Watertightness: triangles that share edges or vertices cover every pixel centre once, at any size.

use super::Rng;
use super::common::{Tri, ascii, both_sides, coverage};

/// Where a pixel centre is relative to a polygon.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Place {
    Inside,
    Outside,
    Boundary,
}

/// Whether `(x, y)` is inside the simple polygon `poly` by more than `margin` pixels, outside by more than
/// `margin`, or too close to its boundary to say (crossing-number test, distance to the nearest edge).
fn place(poly: &[(f64, f64)], x: f64, y: f64, margin: f64) -> Place {
    let n = poly.len();
    let mut inside = false;
    let mut distance = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if (a.1 > y) != (b.1 > y) && x < a.0 + (y - a.1) * (b.0 - a.0) / (b.1 - a.1) {
            inside = !inside;
        }
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let t = (((x - a.0) * dx + (y - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        let (px, py) = (a.0 + t * dx - x, a.1 + t * dy - y);
        distance = distance.min((px * px + py * py).sqrt());
    }
    match (distance > margin, inside) {
        (false, _) => Place::Boundary,
        (true, true) => Place::Inside,
        (true, false) => Place::Outside,
    }
}

/// Renders `tris` and checks every pixel of a `w x h` frame against the polygon they tile: exactly once inside,
/// never outside, at most once near the boundary (where the top-left rule decides).
#[track_caller]
fn assert_tiles(w: u32, h: u32, tris: &[Tri], outline: &[(f64, f64)], what: &str) {
    let (counts, _) = coverage(w, h, tris, &both_sides());
    let mut errors = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let c = counts[(y * w + x) as usize];
            let expected = place(outline, f64::from(x) + 0.5, f64::from(y) + 0.5, 0.01);
            let ok = match expected {
                Place::Inside => c == 1,
                Place::Outside => c == 0,
                Place::Boundary => c <= 1,
            };
            if !ok {
                errors.push((x, y, c, expected));
            }
        }
    }
    assert!(
        errors.is_empty(),
        "{what}: {} pixels wrong, first {:?}\n{}",
        errors.len(),
        &errors[..errors.len().min(5)],
        ascii(&counts, w).join("\n")
    );
}

/// N = 16..200 triangles around a centre in the frame, outer vertices on a circle of radius 10 to 10^7 pixels
/// with sub-pixel jitter: every pixel inside the fan exactly once, 0 exceptions at every radius. Beyond the guard
/// band (±16384 px) the fan's triangles are clipped, and the shared edges must still close.
#[test]
fn fans_of_any_radius_cover_each_pixel_once() {
    let (w, h) = (64u32, 48u32);
    let mut rng = Rng::new(1);
    for radius in [10.0, 31.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7] {
        for n in [16usize, 37, 64, 200] {
            let centre = (f64::from(w) / 2.0 + rng.range(-3.0, 3.0), f64::from(h) / 2.0 + rng.range(-3.0, 3.0));
            let outline: Vec<(f64, f64)> = (0..n)
                .map(|k| {
                    let angle = std::f64::consts::TAU * (k as f64 + rng.range(-0.2, 0.2)) / n as f64;
                    let r = radius * (1.0 + rng.range(-1e-3, 1e-3)) + rng.range(-0.5, 0.5);
                    (centre.0 + r * angle.cos(), centre.1 + r * angle.sin())
                })
                .collect();
            let f = |p: (f64, f64)| (p.0 as f32, p.1 as f32);
            let tris: Vec<Tri> = (0..n).map(|k| [f(centre), f(outline[k]), f(outline[(k + 1) % n])]).collect();
            // The outline as the f32 vertices the renderer receives.
            let outline: Vec<(f64, f64)> = tris.iter().map(|t| (f64::from(t[1].0), f64::from(t[1].1))).collect();
            assert_tiles(w, h, &tris, &outline, &format!("fan of {n} at radius {radius}"));
        }
    }
}

/// Four tiny triangles meeting at a pixel centre, the meeting point shifted by -1/256, 0, +1/256 pixel in x and
/// y: the centre is covered exactly once.
#[test]
fn four_triangles_meeting_at_a_pixel_centre_cover_it_once() {
    let step = 1.0 / 256.0;
    for sx in [-step, 0.0, step] {
        for sy in [-step, 0.0, step] {
            let p = (10.5 + sx, 7.5 + sy);
            let a = 0.3;
            let fan = [
                [p, (p.0 + a, p.1), (p.0, p.1 + a)],
                [p, (p.0, p.1 + a), (p.0 - a, p.1)],
                [p, (p.0 - a, p.1), (p.0, p.1 - a)],
                [p, (p.0, p.1 - a), (p.0 + a, p.1)],
            ];
            let (counts, _) = coverage(20, 15, &fan, &both_sides());
            assert_eq!(counts[7 * 20 + 10], 1, "meeting point shifted by ({sx}, {sy})");
            assert_eq!(counts.iter().sum::<u32>(), 1, "only that pixel: shifted by ({sx}, {sy})");
        }
    }
}

/// Two triangles sharing a diagonal, at 49 sub-pixel offsets and 26 rotations: no pixel twice, no gap.
#[test]
fn quads_split_along_a_diagonal_have_no_cracks_or_overlaps() {
    let (w, h) = (40u32, 40u32);
    for i in 0..7 {
        for j in 0..7 {
            for r in 0..26 {
                let (ox, oy) = (20.0 + f64::from(i) / 7.0, 20.0 + f64::from(j) / 7.0);
                let angle = f64::from(r) * 7.0_f64.to_radians();
                let (c, s) = (angle.cos(), angle.sin());
                let corner = |x: f64, y: f64| (ox + 13.0 * (x * c - y * s), oy + 9.0 * (x * s + y * c));
                let q = [corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0)];
                let f = |p: (f64, f64)| (p.0 as f32, p.1 as f32);
                let tris = [[f(q[0]), f(q[1]), f(q[2])], [f(q[0]), f(q[2]), f(q[3])]];
                let outline: Vec<(f64, f64)> =
                    [q[0], q[1], q[2], q[3]].iter().map(|&p| (f64::from(f(p).0), f64::from(f(p).1))).collect();
                assert_tiles(w, h, &tris, &outline, &format!("offset ({i}/7, {j}/7), rotation {}", r * 7));
            }
        }
    }
}
