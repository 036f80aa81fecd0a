//! retrofire-core 0.4.0's side of the comparison: its `render` with a vertex and a fragment shader, the vertex
//! normal (and texture coordinates) as the varyings, back faces culled and its z-buffer.

use rastty_core::math::{Vec2, Vec3};
use retrofire_core::geom::{Tri, Vertex3, tri, vertex};
use retrofire_core::math::{Color4, Mat4, ProjMat3, Vec3 as RVec3, pt3, rgba, vec3};
use retrofire_core::render::ctx::FaceCull;
use retrofire_core::render::target::{Colorbuf, Framebuf};
use retrofire_core::render::tex::{TexCoord, uv};
use retrofire_core::render::{Context, Frag, Model, Ndc, Screen, render, shader};
use retrofire_core::util::pixfmt::Xrgb8888;
use retrofire_core::util::{Buf2, Dims};

use super::scenes::{PeerScene, to_light};
use super::{channel, light_factor};

/// The vertices with their varyings: the normal, and the texture coordinates when the scene is textured.
enum Vertices {
    Plain(Vec<Vertex3<RVec3>>),
    Textured(Vec<Vertex3<(RVec3, TexCoord)>>),
}

/// The scene in retrofire's types and the frame's buffers, kept between frames.
pub struct RetrofireRenderer {
    triangles: Vec<Tri<usize>>,
    vertices: Vertices,
    frame: Framebuf<Colorbuf<Buf2<u32>, Xrgb8888>, Buf2<f32>>,
    clip_from_model: ProjMat3<Model>,
    to_screen: Mat4<Ndc, Screen>,
}

impl RetrofireRenderer {
    /// `scene` in retrofire's types, and buffers of its frame size.
    pub fn new(scene: &PeerScene) -> Self {
        let triangles =
            scene.indices.chunks_exact(3).map(|t| tri(t[0] as usize, t[1] as usize, t[2] as usize)).collect();
        let normal = |i: usize| vec3(scene.normals[i].x, scene.normals[i].y, scene.normals[i].z);
        let position = |i: usize| pt3(scene.positions[i].x, scene.positions[i].y, scene.positions[i].z);
        let count = scene.positions.len();
        let vertices = match (&scene.uvs, &scene.texture) {
            (Some(uvs), Some(_)) => Vertices::Textured(
                (0..count).map(|i| vertex(position(i), (normal(i), uv(uvs[i].x, uvs[i].y)))).collect(),
            ),
            _ => Vertices::Plain((0..count).map(|i| vertex(position(i), normal(i))).collect()),
        };
        let rows = |m: rastty_core::math::Mat4| [0, 1, 2, 3].map(|i| m.row(i)).map(|r| [r.x, r.y, r.z, r.w]);
        let (w, h) = (scene.width as f32, scene.height as f32);
        let dims = Dims(scene.width, scene.height);
        Self {
            triangles,
            vertices,
            frame: Framebuf { color_buf: Colorbuf::new(Buf2::new(dims)), depth_buf: Buf2::new(dims) },
            clip_from_model: ProjMat3::new(rows(scene.projection() * scene.view())),
            // Row 0 at the top, as in the other renderers' frames.
            to_screen: Mat4::new([
                [w / 2.0, 0.0, 0.0, w / 2.0],
                [0.0, -h / 2.0, 0.0, h / 2.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ]),
        }
    }

    /// Clears the buffers and draws `scene`.
    pub fn render(&mut self, scene: &PeerScene) {
        self.frame.color_buf.buf.fill(0);
        // Its z-buffer holds reciprocal depths: 0 is infinitely far.
        self.frame.depth_buf.fill(0.0);
        // Back faces culled: `to_screen` turns y down, so a front face (counter-clockwise in NDC) is clockwise on
        // the screen, which retrofire calls a back face; culling its "front" faces culls the real back faces.
        // (Culling its "back" faces instead draws the far side: the picture then differs in 184,633 pixels of the
        // head's 800x800, against 1 this way.)
        let context = Context { face_cull: Some(FaceCull::Front), ..Context::default() };
        let l = to_light();
        let to_light = vec3(l.x, l.y, l.z);
        // Its fragment shader returns a `Color4`: the channels go straight in, as bytes.
        let shade = |n: RVec3, albedo: Vec3| -> Color4 {
            let light = light_factor(n.dot(&to_light), n.len());
            rgba(channel(albedo.x * light), channel(albedo.y * light), channel(albedo.z * light), 0xFF)
        };
        let (frame, mvp) = (&mut self.frame, &self.clip_from_model);
        match &self.vertices {
            Vertices::Plain(vertices) => {
                let albedo = scene.albedo(Vec2::ZERO);
                let shader = shader::new(
                    |v: Vertex3<RVec3>, mvp: &ProjMat3<Model>| vertex(mvp.apply(&v.pos), v.attrib),
                    |frag: Frag<RVec3>, _: &ProjMat3<Model>| shade(frag.var, albedo),
                );
                render(&self.triangles, vertices, &shader, mvp, self.to_screen, frame, &context);
            }
            Vertices::Textured(vertices) => {
                let shader = shader::new(
                    |v: Vertex3<(RVec3, TexCoord)>, mvp: &ProjMat3<Model>| vertex(mvp.apply(&v.pos), v.attrib),
                    |frag: Frag<(RVec3, TexCoord)>, _: &ProjMat3<Model>| {
                        let (n, t) = frag.var;
                        shade(n, scene.albedo(Vec2::new(t.u(), t.v())))
                    },
                );
                render(&self.triangles, vertices, &shader, mvp, self.to_screen, frame, &context);
            }
        }
    }

    /// The last frame, `0x00RRGGBB`, top row first.
    pub fn pixels(&self) -> &[u32] {
        self.frame.color_buf.buf.data()
    }
}
