//! Depth formats: how close two surfaces may be and still be told apart, for `u16` and `f32` depth, with near
//! 0.1 and far 1000, at distances 10, 100 and 1000.
//!
//! NDC depth is `z(d) = f / (f - n) * (1 - n / d)`, so `dz/dd = f n / ((f - n) d^2)`: a depth step of `q` is a
//! distance step of about `q (f - n) d^2 / (f n)`. For `u16`, `q = 1/65535`; for `f32` near `z = 1`, one unit in
//! the last place, `2^-24`, plus the rounding of the projection itself.

use rastty_core::camera::perspective;
use rastty_core::math::{Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{DrawState, Fragment, Shader, Slopes, draw};
use rastty_core::target::{DepthBuffer, Target};

use super::common::Count;

const NEAR: f32 = 0.1;
const FAR: f32 = 1000.0;

/// A full-frame square facing the camera at distance `d`, seen through the test's projection.
struct Plane;

impl Shader for Plane {
    type Varyings = ();
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        perspective(1.0, 1.0, NEAR, FAR).unwrap().project_point(mesh.position(i))
    }
    fn varyings(&self, _: &Mesh<'_>, _: usize) {}
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &(), _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ONE
    }
}

/// What a depth buffer stores for a plane facing the camera at distance `d` that fills a 4x4 frame (the clear
/// value if the plane's depth is not below it).
fn stored<T: Copy + Default>(d: f32) -> T
where
    for<'a> &'a mut [T]: DepthBuffer,
{
    // Wide enough to cover the frame at any distance (the field of view is 1 radian).
    let quad = [(-d, -d), (d, -d), (d, d), (-d, -d), (d, d), (-d, d)].map(|(x, y)| Vec3::new(x, y, -d));
    let mesh = Mesh::new(&quad, Indices::Sequential).unwrap();
    let (mut counts, mut depth) = ([0u32; 16], [T::default(); 16]);
    let mut target = Target::new(Count(&mut counts), &mut depth[..], 4, 4).unwrap();
    target.clear(Vec3::ZERO);
    draw(&mut target, &mesh, &Plane, &DrawState::default()).unwrap();
    depth[5]
}

/// Whether the format tells a surface at `near_d` from one at `far_d` (behind it): the nearer stores a smaller
/// depth, so the depth test keeps it whichever is drawn first.
fn resolved<T: Copy + Default + PartialOrd>(near_d: f32, far_d: f32) -> bool
where
    for<'a> &'a mut [T]: DepthBuffer,
{
    stored::<T>(near_d) < stored::<T>(far_d)
}

/// The smallest gap (found by bisection, relative precision 1e-3) at distance `d` that the format resolves, up to
/// 99% of the way to the far plane (a surface at the far plane itself has depth 1, the clear value, and is never
/// drawn); `None` when even that is not resolved.
fn smallest_gap(d: f32, resolves: impl Fn(f32, f32) -> bool) -> Option<f32> {
    let limit = 0.99 * (FAR - d);
    if limit <= 0.0 || !resolves(d, d + limit) {
        return None;
    }
    let (mut lo, mut hi) = (0.0f32, limit);
    while hi - lo > hi * 1e-3 {
        let mid = 0.5 * (lo + hi);
        if resolves(d, d + mid) { hi = mid } else { lo = mid }
    }
    Some(hi)
}

/// The gap that is resolved wherever near `d` the first surface lies: the largest of the smallest resolved gaps
/// from 40 start points spread over a few depth steps around `d` (the smallest gap from one start point depends on
/// where it falls between two depth levels, anywhere from nearly 0 to one whole step).
fn guaranteed_gap(d: f32, step_estimate: f32, resolves: impl Fn(f32, f32) -> bool + Copy) -> Option<f32> {
    (0..40)
        .map(|i| smallest_gap(d + step_estimate * i as f32 / 10.0, resolves))
        .try_fold(0.0f32, |m, g| Some(m.max(g?)))
}

/// The distance step one depth step `q` makes at distance `d`.
fn predicted(q: f64, d: f64) -> f64 {
    let (n, f) = (f64::from(NEAR), f64::from(FAR));
    q * (f - n) * d * d / (f * n)
}

/// Measured resolvable steps agree with the analysis: u16 resolves 0.0153 at 10 and 1.53 at 100, and nothing near
/// 1000 (one u16 step there spans 150 units, more than is left before the far plane); f32 resolves steps a few
/// ULPs of depth wide everywhere.
#[test]
fn resolvable_depth_steps_of_u16_and_f32() {
    let u16_step = |d: f32| predicted(1.0 / 65535.0, f64::from(d));
    // One unit in the last place of a depth near 1 (2^-24).
    let f32_step = |d: f32| predicted(f64::from(f32::EPSILON) / 2.0, f64::from(d));
    let u16_gap = |d: f32| guaranteed_gap(d, u16_step(d) as f32, resolved::<u16>);
    let f32_gap = |d: f32| guaranteed_gap(d, f32_step(d) as f32, resolved::<f32>);

    for d in [10.0f32, 100.0] {
        // u16: one quantisation step, 0.0153 at 10 and 1.53 at 100 (the start points reach a few steps beyond d,
        // where steps are up to 13% longer).
        let measured = f64::from(u16_gap(d).expect("u16 resolves something"));
        eprintln!("u16 at {d}: resolves {measured:.4} (one step: {:.4})", u16_step(d));
        assert!(measured > 0.8 * u16_step(d) && measured < 1.25 * u16_step(d), "u16 at {d}: {measured}");
        // f32: a few units in the last place (the projection's own rounding adds to the storage's).
        let measured = f64::from(f32_gap(d).expect("f32 resolves something"));
        eprintln!("f32 at {d}: resolves {measured:.3e} (one ULP: {:.3e})", f32_step(d));
        assert!(measured > 0.5 * f32_step(d) && measured < 8.0 * f32_step(d), "f32 at {d}: {measured}");
    }
    // Near 1000, the far plane: one u16 step spans 150 units, more than is left, so u16 separates nothing; f32
    // still resolves fractions of a unit.
    assert_eq!(smallest_gap(990.0, resolved::<u16>), None, "u16 resolves a gap at 990");
    let measured = f64::from(f32_gap(990.0).expect("f32 resolves something at 990"));
    eprintln!("f32 at 990: resolves {measured:.3e} (one ULP: {:.3e})", f32_step(990.0));
    assert!(measured > 0.5 * f32_step(990.0) && measured < 8.0 * f32_step(990.0), "f32 at 990: {measured}");
}
