//! The core's side of the comparison: `draw_mesh` with per-pixel (Phong) shading, no highlights, one directional
//! light, into a target with memory for the mesh's screen positions, the way a user of the core draws a mesh.

use rastty_core::color::ShadingSpace;
use rastty_core::math::{Mat4, Vec3};
use rastty_core::mesh::{Indices, Mesh};
use rastty_core::pipeline::{DrawState, ScreenVertex};
use rastty_core::shading::{Light, Lighting, Material, Object, ShadingModel, Transforms, draw_mesh};
use rastty_core::target::{Rgb888, Target};
use rastty_core::texture::{FilterMode, Texture, WrapMode};

use super::scenes::{AMBIENT, DIFFUSE, PeerScene, to_light};

/// The frame's buffers and the memory for the mesh's screen positions, kept between frames.
pub struct CoreRenderer {
    color: Vec<u32>,
    depth: Vec<f32>,
    vertices: Vec<ScreenVertex>,
}

impl CoreRenderer {
    /// Buffers for `scene`'s frame size.
    pub fn new(scene: &PeerScene) -> Self {
        let n = (scene.width * scene.height) as usize;
        Self { color: vec![0; n], depth: vec![1.0; n], vertices: vec![ScreenVertex::UNSET; scene.positions.len()] }
    }

    /// Clears the buffers and draws `scene`.
    ///
    /// # Panics
    /// When the core refuses the draw (it cannot for the scenes made in [`super::scenes`]).
    pub fn render(&mut self, scene: &PeerScene) {
        let mut mesh = Mesh::new(&scene.positions, Indices::U32(&scene.indices))
            .and_then(|m| m.with_normals(&scene.normals))
            .expect("a valid mesh");
        let material = match (&scene.texture, &scene.uvs) {
            (Some(t), Some(uvs)) => {
                mesh = mesh.with_uvs(uvs).expect("texture coordinates for every position");
                Material {
                    diffuse: Some(Texture::new(&t.texels, t.width, t.height).expect("a valid texture")),
                    filter: FilterMode::Nearest,
                    wrap: WrapMode::Repeat,
                    ..Material::plain(Vec3::ONE)
                }
            }
            _ => Material::plain(scene.albedo(rastty_core::math::Vec2::ZERO)),
        };
        let object = Object {
            mesh,
            tangents: None,
            transforms: Transforms::new(Mat4::IDENTITY, scene.view(), scene.projection()),
            shading: ShadingModel::Phong,
            material,
        };
        let lights = [Light::directional(to_light(), Vec3::splat(DIFFUSE))];
        // The peers light the stored sRGB values.
        let lighting = Lighting {
            ambient: Vec3::splat(AMBIENT),
            lights: &lights,
            environment: None,
            space: ShadingSpace::Encoded,
        };
        let mut target = Target::new(Rgb888(&mut self.color), &mut self.depth[..], scene.width, scene.height)
            .expect("buffers of the frame's size")
            .with_vertex_memory(&mut self.vertices);
        target.clear(Vec3::ZERO);
        draw_mesh(&mut target, &object, &lighting, &DrawState::default()).expect("a draw the core accepts");
    }

    /// The last frame, `0x00RRGGBB`, top row first.
    pub fn pixels(&self) -> &[u32] {
        &self.color
    }
}
