//! Property tests: random triangles of any size and any `w`, with any attributes. Never a panic, never a write
//! outside the target, covered pixels inside the triangle's bounding box, every colour finite, and a band of rows
//! drawn alone equal to those rows of the whole frame.

use proptest::prelude::*;
use rastty_core::math::{Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{Cull, DepthTest, DrawState, Fragment, Interpolation, Shader, Slopes, draw};
use rastty_core::target::{ColorBuffer, Target};

const W: u32 = 16;
const H: u32 = 12;

/// Positions are clip space as given (`w` from the colours' x), varyings the normals.
struct Raw;

impl Shader for Raw {
    type Varyings = Vec3;
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes { normals: true, uvs: false, colors: true };
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        mesh.position(i).extend(mesh.color(i).x)
    }
    fn varyings(&self, mesh: &Mesh<'_>, i: usize) -> Vec3 {
        mesh.normal(i)
    }
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), v: &Vec3, _: &Slopes<Self::Varyings>) -> Vec3 {
        *v
    }
}

/// Records every write: panics on an index outside the buffer (Rust's bounds check), keeps the colour.
struct Recorder<'a>(&'a mut [Option<Vec3>]);

impl ColorBuffer for Recorder<'_> {
    fn pixel_count(&self) -> Option<usize> {
        Some(self.0.len())
    }
    fn write(&mut self, index: usize, c: Vec3) {
        self.0[index] = Some(c);
    }
    fn fill(&mut self, _: Vec3) {
        self.0.fill(None);
    }
}

/// Any f32 with magnitudes from 1e-30 to 1e30, a few special values, rarely non-finite.
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![
        8 => (-1.0f32..1.0, -30i32..30).prop_map(|(m, e)| m * 10f32.powi(e)),
        4 => -3.0f32..3.0,
        1 => Just(0.0f32),
        1 => Just(f32::NAN),
        1 => Just(f32::INFINITY),
        1 => Just(-1e30f32),
    ]
}

fn vertex() -> impl Strategy<Value = (Vec3, f32, Vec3)> {
    (
        (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        prop_oneof![4 => 0.01f32..10.0, 1 => coordinate()],
        (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
    )
}

fn state() -> impl Strategy<Value = DrawState> {
    (0u8..=8, any::<bool>(), any::<bool>(), 0usize..3).prop_map(|(bits, affine, depth, cull)| DrawState {
        subpixel_bits: bits,
        interpolation: if affine { Interpolation::Affine } else { Interpolation::PerspectiveCorrect },
        depth_test: if depth { DepthTest::Less } else { DepthTest::Off },
        cull: [Cull::None, Cull::Back, Cull::Front][cull],
        ..DrawState::default()
    })
}

fn render(
    mesh: &Mesh<'_>,
    state: &DrawState,
    rows: core::ops::Range<u32>,
) -> (Vec<Option<Vec3>>, rastty_core::pipeline::DrawStats) {
    let n = (W * (rows.end - rows.start)) as usize;
    let (mut colors, mut depth) = (vec![None; n], vec![0f32; n]);
    let mut target = Target::band(Recorder(&mut colors), &mut depth[..], W, H, rows).unwrap();
    target.clear(Vec3::ZERO);
    let stats = draw(&mut target, mesh, &Raw, state).unwrap();
    (colors, stats)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    #[test]
    fn random_triangles_are_drawn_safely(tri in [vertex(), vertex(), vertex()], state in state(), band in 0u32..H) {
        let positions = tri.map(|v| v.0);
        let colors = tri.map(|v| Vec3::new(v.1, 0.0, 0.0));
        let normals = tri.map(|v| v.2);
        let mesh = Mesh::new(&positions, Indices::Sequential).unwrap()
            .with_colors(&colors).unwrap()
            .with_normals(&normals).unwrap();
        let (frame, stats) = render(&mesh, &state, 0..H);
        prop_assert_eq!(stats.invalid + stats.outside + stats.culled + stats.degenerate + stats.rasterized, 1);
        let written = frame.iter().filter(|c| c.is_some()).count() as u64;
        prop_assert!(written <= stats.fragments);

        // Every colour written is finite.
        for c in frame.iter().flatten() {
            prop_assert!(c.is_finite(), "colour {:?}", c);
        }

        // With every corner in front of the camera, covered centres lie in the projected bounding box, widened by
        // the half grid step (2^-(bits+1) px) that snapping may move a corner.
        let clip: Vec<Vec4> = positions.iter().zip(&colors).map(|(p, c)| p.extend(c.x)).collect();
        if clip.iter().all(|p| p.is_finite() && p.w > 0.0) {
            let screen: Vec<(f64, f64)> = clip.iter().map(|p| {
                let (x, y) = (f64::from(p.x) / f64::from(p.w), f64::from(p.y) / f64::from(p.w));
                ((x + 1.0) * f64::from(W) / 2.0, (1.0 - y) * f64::from(H) / 2.0)
            }).collect();
            let slack = 0.5 / f64::from(1u32 << state.subpixel_bits) + 1e-3;
            let (x0, x1) = screen.iter().fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.0), b.max(p.0)));
            let (y0, y1) = screen.iter().fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
            for (i, c) in frame.iter().enumerate() {
                if c.is_some() {
                    let (cx, cy) = ((i as u32 % W) as f64 + 0.5, (i as u32 / W) as f64 + 0.5);
                    prop_assert!(cx >= x0 - slack && cx <= x1 + slack && cy >= y0 - slack && cy <= y1 + slack,
                        "pixel ({}, {}) outside [{}, {}] x [{}, {}]", cx, cy, x0, x1, y0, y1);
                }
            }
        }

        // One band of rows drawn alone: exactly those rows of the whole frame.
        let rows = band..(band + 3).min(H);
        let (part, _) = render(&mesh, &state, rows.clone());
        let whole = &frame[(rows.start * W) as usize..(rows.end * W) as usize];
        prop_assert!(part.iter().zip(whole).all(|(a, b)| a.map(|c| [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()]) == b.map(|c| [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()])));
    }
}
