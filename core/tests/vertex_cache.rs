//! The post-transform vertex cache: how often the vertex stage runs per triangle on grid meshes of every row
//! stride, including strides that are multiples of the cache size (plus or minus one).

use std::cell::Cell;

use rastty_core::math::{Vec3, Vec4};
use rastty_core::mesh::{Attributes, Indices, Mesh};
use rastty_core::pipeline::{Cull, DrawState, Fragment, Shader, Slopes, draw};
use rastty_core::target::{NoColor, NoDepth, Target};

/// Counts position and varyings runs; positions are already in clip space, all of them inside the frame.
#[derive(Default)]
struct Counting {
    positions: Cell<u64>,
    varyings: Cell<u64>,
}

impl Shader for Counting {
    type Varyings = f32;
    type Face = ();
    const ATTRIBUTES: Attributes = Attributes::NONE;
    fn position(&self, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        self.positions.set(self.positions.get() + 1);
        mesh.position(i).extend(1.0)
    }
    fn varyings(&self, _: &Mesh<'_>, i: usize) -> f32 {
        self.varyings.set(self.varyings.get() + 1);
        i as f32
    }
    fn face(&self, _: &Mesh<'_>, _: [usize; 3]) {}
    fn fragment(&self, _: &Fragment, _: &(), _: &f32, _: &Slopes<Self::Varyings>) -> Vec3 {
        Vec3::ONE
    }
}

/// A `columns x rows` grid of quads over the frame, two triangles each, in row order.
fn grid(columns: u32, rows: u32) -> (Vec<Vec3>, Vec<u32>) {
    let stride = columns + 1;
    let positions = (0..=rows)
        .flat_map(|r| {
            (0..=columns).map(move |c| {
                Vec3::new(-1.0 + 2.0 * c as f32 / columns as f32, -1.0 + 2.0 * r as f32 / rows as f32, 0.5)
            })
        })
        .collect();
    let mut indices = Vec::new();
    for r in 0..rows {
        for c in 0..columns {
            let (a, b) = (r * stride + c, (r + 1) * stride + c);
            indices.extend_from_slice(&[a, a + 1, b, a + 1, b + 1, b]);
        }
    }
    (positions, indices)
}

#[test]
fn grids_of_every_row_stride_run_the_vertex_stage_about_once_per_triangle() {
    let state = DrawState { cull: Cull::None, ..DrawState::DEFAULT };
    // Row strides (columns + 1) of 31, 32, 33, 63, 64, 65 among others: with the vertex index modulo 32 as the
    // slot, those put a triangle's upper and lower vertices in one slot and reused nothing (3 runs per triangle).
    for columns in [30, 31, 32, 47, 62, 63, 64, 100, 224] {
        let (positions, indices) = grid(columns, 8);
        let mesh = Mesh::new(&positions, Indices::U32(&indices)).unwrap();
        let shader = Counting::default();
        let mut target = Target::new(NoColor, NoDepth, 512, 64).unwrap();
        let stats = draw(&mut target, &mesh, &shader, &state).unwrap();
        assert_eq!(stats.rasterized, stats.triangles_in, "every triangle is drawn");
        let triangles = stats.triangles_in as f64;
        let positions_per_triangle = shader.positions.get() as f64 / triangles;
        let varyings_per_triangle = shader.varyings.get() as f64 / triangles;
        println!("{columns} columns: {positions_per_triangle:.3} position, {varyings_per_triangle:.3} varyings runs");
        // Each vertex is shared by up to six triangles; 32 entries cannot hold a whole row, so a vertex runs once
        // for the strip above it and once for the strip below: about one run per triangle.
        assert!(positions_per_triangle < 1.1, "{columns} columns: {positions_per_triangle:.3} position runs");
        assert!(varyings_per_triangle < 1.1, "{columns} columns: {varyings_per_triangle:.3} varyings runs");
    }
}
