//! Barycentric overshoot: every interpolated value lies within its triangle's vertex values (plus rounding), and
//! texture sampling never reads outside the texture, for slivers, far-off triangles and strong perspective.

use std::cell::Cell;

use super::Rng;
use rastty_core::math::{Mat4, Vec2, Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState, Fragment, Interpolation, Shader, Slopes, draw};
use rastty_core::target::{NoColor, Target};
use rastty_core::texture::{Bilinear, Clamp, Nearest, Repeat, Texture};

/// Interpolates four attributes (from the mesh's normals and UVs) and checks each fragment against the
/// triangle's per-attribute range.
struct Checker {
    clip_from_object: Mat4,
    /// (worst excess over the range, relative to the range's magnitude), and fragments seen.
    worst: Cell<f64>,
    fragments: Cell<u64>,
}

impl Shader for Checker {
    type Varyings = (Vec3, Vec2);
    /// Per attribute: (min, max).
    type Face = [(f32, f32); 5];
    const ATTRIBUTES: Attributes = Attributes { normals: true, uvs: true, colors: false };

    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.clip_from_object.project_point(mesh.position(i))
    }

    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> (Vec3, Vec2) {
        (mesh.normal(i), mesh.uv(i))
    }

    fn face(&self, mesh: &Mesh<'_>, t: [usize; 3]) -> [(f32, f32); 5] {
        let values = t.map(|i| {
            let (n, uv) = (mesh.normal(i), mesh.uv(i));
            [n.x, n.y, n.z, uv.x, uv.y]
        });
        core::array::from_fn(|k| {
            let (a, b, c) = (values[0][k], values[1][k], values[2][k]);
            (a.min(b).min(c), a.max(b).max(c))
        })
    }

    fn fragment(&self, _: &Fragment, range: &[(f32, f32); 5], v: &(Vec3, Vec2), _: &Slopes<Self::Varyings>) -> Vec3 {
        let got = [v.0.x, v.0.y, v.0.z, v.1.x, v.1.y];
        for (value, (lo, hi)) in got.iter().zip(range) {
            assert!(value.is_finite(), "non-finite varying {value}");
            let magnitude = f64::from(lo.abs().max(hi.abs())).max(f64::MIN_POSITIVE);
            let excess = (f64::from(*lo) - f64::from(*value)).max(f64::from(*value) - f64::from(*hi)).max(0.0);
            self.worst.set(self.worst.get().max(excess / magnitude));
        }
        self.fragments.set(self.fragments.get() + 1);
        Vec3::ZERO
    }
}

/// Draws triangles (screen-ish positions through `clip_from_object`) with random attributes around `offset`
/// and returns the worst relative excess over the vertex range.
fn worst_excess(
    tris: &[[Vec3; 3]],
    clip_from_object: Mat4,
    offset: f32,
    interpolation: Interpolation,
    rng: &mut Rng,
) -> (f64, u64) {
    let positions: Vec<Vec3> = tris.iter().flatten().copied().collect();
    let mut attr = || offset + rng.range(-1.0, 1.0) as f32 * offset.abs().max(1.0) * 1e-3;
    let normals: Vec<Vec3> = positions.iter().map(|_| Vec3::new(attr(), attr(), attr())).collect();
    let uvs: Vec<Vec2> = positions.iter().map(|_| Vec2::new(attr(), attr())).collect();
    let mesh =
        Mesh::new(&positions, Indices::Sequential).unwrap().with_normals(&normals).unwrap().with_uvs(&uvs).unwrap();
    let shader = Checker { clip_from_object, worst: Cell::new(0.0), fragments: Cell::new(0) };
    let mut target = Target::new(NoColor, rastty_core::target::NoDepth, 512, 512).unwrap();
    let state = DrawState { cull: Cull::None, interpolation, ..DrawState::default() };
    draw(&mut target, &mesh, &shader, &state).unwrap();
    (shader.worst.get(), shader.fragments.get())
}

/// Positions in pixels of a 512x512 frame to clip space. With `perspective`, `w = 1 + z` (z from 0 to 1000
/// gives corners with `w` a thousand times apart, drawn smaller the larger their `w`), otherwise `w = 1`.
fn screen(perspective: bool) -> Mat4 {
    let s = 2.0 / 512.0;
    let w_row = if perspective { [0.0, 0.0, 1.0, 1.0] } else { [0.0, 0.0, 0.0, 1.0] };
    Mat4::from_rows([s, 0.0, 0.0, -1.0], [0.0, -s, 0.0, 1.0], [0.0, 0.0, 0.0, 0.5], w_row)
}

/// Slivers, thin triangles far from the origin, and triangles whose corners have very different `w`, with
/// attributes like 10^6 +- 10^3: the worst overshoot is within a few ULPs of the attribute's magnitude.
#[test]
fn interpolated_values_stay_within_their_vertices_range() {
    let mut rng = Rng::new(7);
    // Allowed excess, relative to the values' magnitude: four units in the last place of an f32.
    let tolerance = 4.0 * f64::from(f32::EPSILON);
    let mut fragments = 0;
    for offset in [0.0f32, 1.0, -37.5, 1e6, -3e7] {
        for perspective in [false, true] {
            for interpolation in [Interpolation::PerspectiveCorrect, Interpolation::Affine] {
                let mut tris = Vec::new();
                for _ in 0..40 {
                    // A sliver: long, a fraction of a pixel wide, anywhere in the frame.
                    let (cx, cy) = (rng.range(20.0, 490.0) as f32, rng.range(20.0, 490.0) as f32);
                    let angle = rng.range(0.0, std::f64::consts::PI);
                    let (dx, dy) = ((angle.cos() * 300.0) as f32, (angle.sin() * 300.0) as f32);
                    let width = rng.range(0.01, 0.6) as f32;
                    let z = rng.range(0.0, 50.0) as f32;
                    tris.push([
                        Vec3::new(cx - dx, cy - dy, z),
                        Vec3::new(cx + dx, cy + dy, rng.range(0.0, 50.0) as f32),
                        Vec3::new(cx - dy / 300.0 * width, cy + dx / 300.0 * width, z),
                    ]);
                    // A big triangle with corners at very different depths.
                    tris.push([
                        Vec3::new(rng.range(0.0, 512.0) as f32, rng.range(0.0, 512.0) as f32, 0.0),
                        Vec3::new(rng.range(0.0, 512.0) as f32, rng.range(0.0, 512.0) as f32, 1000.0),
                        Vec3::new(rng.range(0.0, 512.0) as f32, rng.range(0.0, 512.0) as f32, 3.0),
                    ]);
                }
                let (worst, n) = worst_excess(&tris, screen(perspective), offset, interpolation, &mut rng);
                assert!(
                    worst <= tolerance,
                    "offset {offset}, perspective {perspective}, {interpolation:?}: excess {worst:e} of the magnitude"
                );
                fragments += n;
            }
        }
    }
    assert!(fragments > 100_000, "only {fragments} fragments checked");
}

/// Any texture coordinate, however large, NaN or infinite, samples inside the texture: an all-white texture
/// always gives exactly white (a read past the texels would give black).
#[test]
fn texture_reads_stay_inside_the_texture() {
    let mut rng = Rng::new(11);
    let sizes = [(1u32, 1u32), (3, 5), (7, 1), (1, 9), (256, 256), (255, 3)];
    let specials = [0.0, -0.0, 1.0, -1.0, 0.5, 1e-7, -1e-7, 0.999_999_9, 8_388_608.0, 1e30, -1e30, f32::MAX, f32::MIN];
    let specials_nan = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    for (w, h) in sizes {
        let texels = vec![0xFF_FFFFu32; (w * h) as usize];
        let t = Texture::new(&texels, w, h).unwrap();
        let check = |uv: Vec2| {
            for c in [
                t.sample::<Nearest, Repeat>(uv),
                t.sample::<Nearest, Clamp>(uv),
                t.sample::<Bilinear, Repeat>(uv),
                t.sample::<Bilinear, Clamp>(uv),
            ] {
                assert_eq!(c, Vec3::ONE, "{w}x{h} at {uv:?}");
            }
        };
        for &u in specials.iter().chain(&specials_nan) {
            for &v in specials.iter().chain(&specials_nan) {
                check(Vec2::new(u, v));
            }
        }
        for _ in 0..20_000 {
            let magnitude = 10f64.powf(rng.range(-8.0, 12.0));
            check(Vec2::new(rng.range(-magnitude, magnitude) as f32, rng.range(-magnitude, magnitude) as f32));
        }
    }
}
