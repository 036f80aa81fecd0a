//! Slivers: triangles 1000 pixels long and 0.01 pixel wide at every angle, against an exact integer reference.

use super::common::{ascii, both_sides, coverage};

const W: u32 = 1024;
const H: u32 = 1024;
/// Sub-pixel bits of the default state.
const BITS: u32 = 8;

/// A vertex as the rasterizer sees it: the screen position the test shader and the viewport compute in `f32`,
/// snapped to 1/256 pixel (round half up), in units of 1/256 pixel.
fn snap(x: f32, y: f32) -> (i128, i128) {
    let (w, h) = (W as f32, H as f32);
    let (ndc_x, ndc_y) = (2.0 * x / w - 1.0, 1.0 - 2.0 * y / h);
    let (sx, sy) = ((ndc_x + 1.0) * (w * 0.5), (1.0 - ndc_y) * (h * 0.5));
    let s = (1u32 << BITS) as f64;
    ((f64::from(sx) * s + 0.5).floor() as i128, (f64::from(sy) * s + 0.5).floor() as i128)
}

/// Exact coverage of the snapped triangle: every pixel centre tested with `i128` edge functions and the top-left
/// rule, written independently of the rasterizer (no incremental stepping, no bounding-box tricks).
fn exact_coverage(tri: [(f32, f32); 3]) -> Vec<u32> {
    let mut v = tri.map(|(x, y)| snap(x, y));
    // Doubled units: pixel centres (i + 1/2) are then whole numbers.
    for p in &mut v {
        *p = (2 * p.0, 2 * p.1);
    }
    let area = (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[1].1 - v[0].1) * (v[2].0 - v[0].0);
    let mut out = vec![0u32; (W * H) as usize];
    if area == 0 {
        return out;
    }
    if area < 0 {
        v.swap(0, 1);
    }
    let unit = 2i128 << BITS; // one pixel in doubled units
    // The snapped triangle's bounding box, in pixels (generously rounded outward).
    let lo_x = (v.iter().map(|p| p.0).min().unwrap_or(0) / unit - 1).max(0);
    let hi_x = (v.iter().map(|p| p.0).max().unwrap_or(0) / unit + 1).min(i128::from(W) - 1);
    let lo_y = (v.iter().map(|p| p.1).min().unwrap_or(0) / unit - 1).max(0);
    let hi_y = (v.iter().map(|p| p.1).max().unwrap_or(0) / unit + 1).min(i128::from(H) - 1);
    for py in lo_y..=hi_y {
        let cy = py * unit + unit / 2;
        for px in lo_x..=hi_x {
            let cx = px * unit + unit / 2;
            let inside = (0..3).all(|k| {
                let (a, b) = (v[(k + 1) % 3], v[(k + 2) % 3]);
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let e = dx * (cy - a.1) - dy * (cx - a.0);
                let top_left = dy < 0 || (dy == 0 && dx > 0);
                e > 0 || (e == 0 && top_left)
            });
            if inside {
                out[(py * i128::from(W) + px) as usize] = 1;
            }
        }
    }
    out
}

/// 1000 px long, 0.01 px wide, at 0..180 degrees in steps of 1.5 (and a few at exact multiples of 45): the covered
/// pixels equal the exact reference's, pixel for pixel.
#[test]
fn slivers_at_every_angle_match_exact_integer_coverage() {
    let mut total = 0u32;
    for step in 0..=120 {
        let angle = f64::from(step) * 1.5_f64.to_radians();
        let (dx, dy) = (angle.cos(), angle.sin());
        let (cx, cy) = (512.3, 511.7);
        let a = (cx - 500.0 * dx, cy - 500.0 * dy);
        let b = (cx + 500.0 * dx, cy + 500.0 * dy);
        // The third vertex 0.01 px off the middle of the long side.
        let c = (cx - 0.01 * dy, cy + 0.01 * dx);
        let f = |p: (f64, f64)| (p.0 as f32, p.1 as f32);
        let tri = [f(a), f(b), f(c)];
        let (counts, _) = coverage(W, H, &[tri], &both_sides());
        let expected = exact_coverage(tri);
        let covered: u32 = counts.iter().sum();
        if counts != expected {
            let first = counts.iter().zip(&expected).position(|(p, q)| p != q).unwrap_or(0) as u32;
            let (x, y) = (first % W, first / W);
            let x0 = x.saturating_sub(4).min(W - 9);
            let window = |c: &[u32]| -> Vec<String> {
                (y.saturating_sub(2)..(y + 3).min(H))
                    .map(|r| ascii(&c[(r * W + x0) as usize..(r * W + x0 + 9) as usize], 9).concat())
                    .collect()
            };
            panic!(
                "angle {:.1}: first difference at ({x}, {y})\nrendered:\n{}\nexact:\n{}",
                angle.to_degrees(),
                window(&counts).join("\n"),
                window(&expected).join("\n")
            );
        }
        total += covered;
    }
    // The slivers are thin but not empty: the test compares real coverage.
    assert!(total > 100, "only {total} pixels covered in all");
}
