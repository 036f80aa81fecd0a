//! Ambient occlusion benchmarks: [`AmbientOcclusion::apply`] on whole 800x800 frames rendered here first.
//!
//! Run with `cargo bench -p rastty-bench --bench occlusion`. Only the occlusion pass is timed: each iteration
//! starts from a fresh copy of the rendered colour (the copy is not timed).

use divan::{Bencher, black_box};
use rastty_core::camera::{look_at, perspective};
use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::occlusion::AmbientOcclusion;
use rastty_core::pipeline::DrawState;
use rastty_core::shading::{Light, LightKind, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};

fn main() {
    divan::main();
}

const SIZE: u32 = 800;

/// Triangles with per-vertex normals, built up from shapes.
#[derive(Default)]
struct Geometry {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    indices: Vec<u32>,
}

impl Geometry {
    /// A UV sphere of `radius` around `centre`, `rings x segments` quads, counter-clockwise from outside.
    fn sphere(&mut self, centre: Vec3, radius: f32, rings: u32, segments: u32) {
        let base = self.positions.len() as u32;
        for r in 0..=rings {
            let theta = std::f32::consts::PI * r as f32 / rings as f32;
            for g in 0..=segments {
                let phi = std::f32::consts::TAU * g as f32 / segments as f32;
                let n = Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
                self.positions.push(centre + n * radius);
                self.normals.push(n);
            }
        }
        let row = segments + 1;
        for r in 0..rings {
            for g in 0..segments {
                let (a, b) = (base + r * row + g, base + (r + 1) * row + g);
                self.indices.extend_from_slice(&[a, a + 1, b, a + 1, b + 1, b]);
            }
        }
    }

    /// A quad through four corners in counter-clockwise order seen from its front, with one flat normal.
    fn quad(&mut self, corners: [Vec3; 4]) {
        let base = self.positions.len() as u32;
        let n = (corners[1] - corners[0]).cross(corners[2] - corners[0]).try_normalize().unwrap();
        self.positions.extend_from_slice(&corners);
        self.normals.extend_from_slice(&[n; 4]);
        self.indices.extend_from_slice(&[base, base + 1, base + 2, base, base + 2, base + 3]);
    }

    /// An axis-aligned box from `lo` to `hi`: six outward-facing quads.
    fn cuboid(&mut self, lo: Vec3, hi: Vec3) {
        let p = |x: bool, y: bool, z: bool| {
            Vec3::new(if x { hi.x } else { lo.x }, if y { hi.y } else { lo.y }, if z { hi.z } else { lo.z })
        };
        let (f, t) = (false, true);
        self.quad([p(f, f, t), p(t, f, t), p(t, t, t), p(f, t, t)]);
        self.quad([p(t, f, f), p(f, f, f), p(f, t, f), p(t, t, f)]);
        self.quad([p(t, f, t), p(t, f, f), p(t, t, f), p(t, t, t)]);
        self.quad([p(f, f, f), p(f, f, t), p(f, t, t), p(f, t, f)]);
        self.quad([p(f, t, t), p(t, t, t), p(t, t, f), p(f, t, f)]);
        self.quad([p(f, f, f), p(t, f, f), p(t, f, t), p(f, f, t)]);
    }
}

/// A rendered frame to darken: its projection, depth and colour.
struct Frame {
    projection: Mat4,
    depth: Vec<f32>,
    color: Vec<u32>,
}

/// Renders `geometry` at 800x800 with per-pixel Lambert shading from `eye` towards `target`.
fn render(geometry: &Geometry, eye: Vec3, target: Vec3) -> Frame {
    let n = (SIZE * SIZE) as usize;
    let (mut color, mut depth) = (vec![0u32; n], vec![0f32; n]);
    let view = look_at(eye, target, Vec3::Y).unwrap();
    let projection = perspective(0.9, 1.0, 0.1, 100.0).unwrap();
    let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
    // Already unit length: built as is rather than normalised again.
    let to_light = Vec3::new(0.408_248_3, 0.816_496_6, 0.408_248_3);
    let lights = [Light { kind: LightKind::Directional { to_light }, color: Vec3::ONE, shadow: None }];
    let lighting =
        Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
    let mesh = Mesh::new(&geometry.positions, Indices::U32(&geometry.indices))
        .unwrap()
        .with_normals(&geometry.normals)
        .unwrap();
    let material = Material::plain(Vec3::new(0.9, 0.8, 0.7));
    let object = Object { mesh, tangents: None, transforms, shading: ShadingModel::Phong, material };
    let mut frame = Target::new(Rgb888(&mut color), &mut depth[..], SIZE, SIZE).unwrap();
    frame.clear(Vec3::ZERO);
    draw_mesh(&mut frame, &object, &lighting, &DrawState::default()).unwrap();
    Frame { projection, depth, color }
}

/// Times the default occlusion over the whole of `frame`.
fn occlude(bencher: Bencher, frame: &Frame) {
    let ao = AmbientOcclusion::DEFAULT;
    bencher.with_inputs(|| frame.color.clone()).bench_local_refs(|color| {
        ao.apply(&frame.projection, &frame.depth, 0..SIZE, color, 0..SIZE, SIZE, SIZE).unwrap();
        black_box(color);
    });
}

/// A sphere resting on a floor between two boxes, one touching it, seen from in front and above: contacts,
/// creases, open floor, curved and flat faces, and background across the top of the frame.
#[divan::bench]
fn sphere_boxes_floor_800x800(bencher: Bencher) {
    let mut g = Geometry::default();
    g.quad([
        Vec3::new(-6.0, -1.0, 4.0),
        Vec3::new(6.0, -1.0, 4.0),
        Vec3::new(6.0, -1.0, -6.0),
        Vec3::new(-6.0, -1.0, -6.0),
    ]);
    g.sphere(Vec3::ZERO, 1.0, 35, 36);
    g.cuboid(Vec3::new(1.0, -1.0, -0.8), Vec3::new(2.4, 0.2, 0.6));
    g.cuboid(Vec3::new(-2.6, -1.0, -1.6), Vec3::new(-1.3, 0.6, -0.4));
    occlude(bencher, &render(&g, Vec3::new(0.4, 1.3, 4.2), Vec3::new(0.0, -0.4, 0.0)));
}

/// The 2.5k-triangle sphere of the render benchmarks alone, filling most of the frame: nothing occludes it, but
/// every surface pixel is still searched.
#[divan::bench]
fn sphere_alone_800x800(bencher: Bencher) {
    let mut g = Geometry::default();
    g.sphere(Vec3::ZERO, 1.0, 35, 36);
    occlude(bencher, &render(&g, Vec3::new(0.0, 0.3, 2.6), Vec3::ZERO));
}
