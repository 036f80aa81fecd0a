//! Why a frame could not be rendered.

use core::fmt;

use rastty_core::camera::CameraError;
use rastty_core::mesh::MeshError;
use rastty_core::pipeline::DrawError;
use rastty_core::target::TargetError;
use rastty_core::texture::TextureError;

/// Why the scene could not be rendered (never, with these constants; returned rather than unwrapped so that the
/// firmware reports it).
#[derive(Clone, Debug, PartialEq)]
pub enum SceneError {
    /// The camera constants do not make a camera.
    Camera(CameraError),
    /// The model arrays do not make a mesh.
    Mesh(MeshError),
    /// The texture's arrays do not make a texture.
    Texture(TextureError),
    /// A band's buffers do not fit its rows.
    Target(TargetError),
    /// A draw failed.
    Draw(DrawError),
    /// The bands have more than one sample a pixel, which a display cannot take.
    Multisampled,
    /// The effects resolved to another shader variant than the one [`Scene::draw`](crate::Scene::draw) runs.
    Variant,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Camera(e) => write!(f, "camera: {e}"),
            Self::Mesh(e) => write!(f, "mesh: {e}"),
            Self::Texture(e) => write!(f, "texture: {e}"),
            Self::Target(e) => write!(f, "target: {e}"),
            Self::Draw(e) => write!(f, "draw: {e}"),
            Self::Multisampled => f.write_str("the bands have more than one sample a pixel"),
            Self::Variant => f.write_str("the effects resolve to another shader variant than the scene draws"),
        }
    }
}
