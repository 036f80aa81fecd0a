//! euc 0.5.3's side of the comparison: its `Pipeline` with the vertex normal (and texture coordinates) as the
//! varyings, its `Triangles` rasterizer with back faces culled and its z-buffer.

use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingEnabled, Triangles};
use euc::{Pipeline, Target};
use rastty_core::math::{Mat4, Vec2, Vec3};

use super::scenes::{PeerScene, to_light};
use super::{light_factor, pack};

/// The frame's buffers, kept between frames.
pub struct EucRenderer {
    color: Buffer2d<u32>,
    depth: Buffer2d<f32>,
}

/// The shading of the comparison, for euc.
struct Shading<'a> {
    scene: &'a PeerScene,
    clip_from_world: Mat4,
    to_light: vek::Vec3<f32>,
}

impl Shading<'_> {
    fn clip(&self, i: usize) -> [f32; 4] {
        let p = self.clip_from_world.project_point(self.scene.positions[i]);
        [p.x, p.y, p.z, p.w]
    }

    fn normal(&self, i: usize) -> vek::Vec3<f32> {
        let n = self.scene.normals[i];
        vek::Vec3::new(n.x, n.y, n.z)
    }

    #[inline(always)]
    fn shade(&self, normal: vek::Vec3<f32>, albedo: Vec3) -> u32 {
        pack(albedo * light_factor(normal.dot(self.to_light), normal.magnitude()))
    }
}

/// Untextured: the normal is the varying; the albedo, the same everywhere, is worked out once per frame.
struct Plain<'a>(Shading<'a>, Vec3);

impl Pipeline for Plain<'_> {
    type Vertex = u32;
    type VsOut = vek::Vec3<f32>;
    type Pixel = u32;

    #[inline(always)]
    fn vert(&self, i: &u32) -> ([f32; 4], Self::VsOut) {
        (self.0.clip(*i as usize), self.0.normal(*i as usize))
    }

    #[inline(always)]
    fn frag(&self, normal: &Self::VsOut) -> u32 {
        self.0.shade(*normal, self.1)
    }
}

/// Textured: the normal and the texture coordinates.
struct Textured<'a>(Shading<'a>, &'a [Vec2]);

impl Pipeline for Textured<'_> {
    type Vertex = u32;
    type VsOut = (vek::Vec3<f32>, vek::Vec2<f32>);
    type Pixel = u32;

    #[inline(always)]
    fn vert(&self, i: &u32) -> ([f32; 4], Self::VsOut) {
        let (i, uv) = (*i as usize, self.1[*i as usize]);
        (self.0.clip(i), (self.0.normal(i), vek::Vec2::new(uv.x, uv.y)))
    }

    #[inline(always)]
    fn frag(&self, (normal, uv): &Self::VsOut) -> u32 {
        self.0.shade(*normal, self.0.scene.albedo(Vec2::new(uv.x, uv.y)))
    }
}

impl EucRenderer {
    /// Buffers for `scene`'s frame size.
    pub fn new(scene: &PeerScene) -> Self {
        let size = [scene.width as usize, scene.height as usize];
        Self { color: Buffer2d::new(size, 0), depth: Buffer2d::new(size, 1.0) }
    }

    /// Clears the buffers and draws `scene`.
    pub fn render(&mut self, scene: &PeerScene) {
        self.color.clear(0);
        self.depth.clear(1.0);
        let l = to_light();
        let shading = Shading {
            scene,
            clip_from_world: scene.projection() * scene.view(),
            to_light: vek::Vec3::new(l.x, l.y, l.z),
        };
        type Culled<'d> = Triangles<'d, Buffer2d<f32>, BackfaceCullingEnabled>;
        match &scene.uvs {
            Some(uvs) if scene.texture.is_some() => {
                Textured(shading, uvs).draw::<Culled<'_>, _>(&scene.indices, &mut self.color, Some(&mut self.depth));
            }
            _ => Plain(shading, scene.albedo(Vec2::ZERO)).draw::<Culled<'_>, _>(
                &scene.indices,
                &mut self.color,
                Some(&mut self.depth),
            ),
        }
    }

    /// The last frame, `0x00RRGGBB`, top row first.
    pub fn pixels(&self) -> &[u32] {
        self.color.as_ref()
    }
}
