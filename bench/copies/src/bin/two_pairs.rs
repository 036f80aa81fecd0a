//! Draws the octahedron into two pairs of buffers: `Rgb888` colour and `f32` depth, as `one_pair` does, then
//! `Rgb565` colour and `u16` depth (a display's), band by band.
//!
//! The first draw is written out here again, not called from the library: each crate compiles the generic
//! functions it instantiates, so a draw in the library would give this program a second copy of the pipeline
//! (45 pixel loops instead of 30), which is not what is measured.

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

    const ROWS: u32 = 16;
    let (mut band_color, mut band_depth) = (vec![0u16; (WIDTH * ROWS) as usize], vec![0u16; (WIDTH * ROWS) as usize]);
    let mut sum = Vec::new();
    for y0 in (0..HEIGHT).step_by(ROWS as usize) {
        let rows = y0..(y0 + ROWS).min(HEIGHT);
        let mut band =
            Target::band(Rgb565(&mut band_color), &mut band_depth[..], WIDTH, HEIGHT, rows).expect("a valid band");
        band.clear(Vec3::ZERO);
        draw_mesh(&mut band, &object, &lighting, &DrawState::default()).expect("a valid draw");
        sum.extend(band_color.iter().flat_map(|c| c.to_le_bytes()));
    }
    println!("{:08x}", checksum(sum));
}
