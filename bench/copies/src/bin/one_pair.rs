//! Draws the octahedron into one pair of buffers: `Rgb888` colour and `f32` depth.

use rastty_copies::*;
use rastty_core::*;

fn main() {
    let mesh = Mesh::new(&POSITIONS, Indices::U16(&INDICES)).expect("a valid mesh").with_normals(&POSITIONS);
    let object = object(mesh.expect("valid normals"));
    let lights = lights();
    let lighting =
        Lighting { ambient: Vec3::splat(0.1), lights: &lights, environment: None, space: ShadingSpace::Linear };
    let pixels = (WIDTH * HEIGHT) as usize;
    let (mut color, mut depth) = (vec![0u32; pixels], vec![0f32; pixels]);
    let mut target = Target::new(Rgb888(&mut color), &mut depth[..], WIDTH, HEIGHT).expect("a valid frame");
    target.clear(Vec3::ZERO);
    draw_mesh(&mut target, &object, &lighting, &DrawState::default()).expect("a valid draw");
    println!("{:08x}", checksum(color.iter().flat_map(|c| c.to_le_bytes())));
}
