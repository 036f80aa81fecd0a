//! The scene both programs draw: an octahedron under one light, seen from a camera (no drawing here, so each
//! program compiles the draws it makes itself).

use rastty_core::*;

/// Corners of the octahedron.
pub const POSITIONS: [Vec3; 6] = [
    Vec3::new(1.0, 0.0, 0.0),
    Vec3::new(-1.0, 0.0, 0.0),
    Vec3::new(0.0, 1.0, 0.0),
    Vec3::new(0.0, -1.0, 0.0),
    Vec3::new(0.0, 0.0, 1.0),
    Vec3::new(0.0, 0.0, -1.0),
];

/// Its eight faces, counter-clockwise seen from outside.
pub const INDICES: [u16; 24] = [0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5];

/// The frame's size.
pub const WIDTH: u32 = 64;
/// The frame's size.
pub const HEIGHT: u32 = 48;

/// The octahedron, Phong-shaded with vertex normals, from a camera three units away.
pub fn object(mesh: Mesh<'_>) -> Object<'_> {
    let view = look_at(Vec3::new(1.0, 1.5, 3.0), Vec3::ZERO, Vec3::Y).expect("a valid camera");
    let projection = perspective(0.9, WIDTH as f32 / HEIGHT as f32, 0.1, 10.0).expect("a valid projection");
    let transforms = Transforms::new(Mat4::IDENTITY, view, projection);
    Object { mesh, tangents: None, transforms, shading: ShadingModel::Phong, material: Material::default() }
}

/// One white light from above.
pub fn lights() -> [Light<'static>; 1] {
    [Light::directional(Vec3::new(0.3, 1.0, 0.5), Vec3::ONE)]
}

/// FNV-1a over bytes: what the programs print, so that nothing they draw is optimised away.
pub fn checksum(bytes: impl IntoIterator<Item = u8>) -> u32 {
    bytes.into_iter().fold(0x811c_9dc5, |h, b| (h ^ u32::from(b)).wrapping_mul(0x0100_0193))
}
