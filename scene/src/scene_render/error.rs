//! Why a scene could not be planned or drawn.

use std::fmt;

use rastty_core::camera::CameraError;
use rastty_core::mesh::TangentError;
use rastty_core::occlusion::OcclusionError;
use rastty_core::shading::ShadingError;
use rastty_core::shadow::ShadowError;
use rastty_core::target::TargetError;
use rastty_core::texture::TextureError;

use crate::escaped::Escaped;

/// A scene that could not be planned or drawn. Its [`Display`](fmt::Display) is one line, with the text that
/// came from files (object and part names) escaped.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneRenderError {
    /// No object has a finite vertex, so the scene has no extent to frame.
    Empty,
    /// The camera settings do not make a camera.
    Camera(CameraError),
    /// A light's shadow map could not be set up (a light the core cannot place a camera at).
    Shadow {
        /// The light, by its place in the file and what it is (`light 2 (point at [1.2, 2.2, 1])`).
        light: String,
        /// What the core said.
        error: ShadowError,
    },
    /// Tangents for a tangent-space normal map could not be computed.
    Tangents {
        /// The object (raw).
        object: String,
        /// What the core said.
        error: TangentError,
    },
    /// An image could not be handed to the core.
    Texture {
        /// The object and part (raw).
        draw: String,
        /// What the core said.
        error: TextureError,
    },
    /// The core refused a draw.
    Draw {
        /// The object and part (raw).
        draw: String,
        /// What the core said.
        error: ShadingError,
    },
    /// The core refused the ambient occlusion step.
    Occlusion(OcclusionError),
    /// The frame's buffers are unusable, or not the size the plan was made for.
    Target(String),
}

impl fmt::Display for SceneRenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty => f.write_str("the scene has no finite vertex to draw"),
            Self::Camera(e) => write!(f, "bad camera: {e}"),
            Self::Shadow { light, error } => write!(f, "{}: cannot cast shadows: {error}", Escaped(light)),
            Self::Tangents { object, error } => {
                write!(f, "{}: no tangents for its normal map: {error}", Escaped(object))
            }
            Self::Texture { draw, error } => write!(f, "{}: bad image: {error}", Escaped(draw)),
            Self::Draw { draw, error } => write!(f, "{}: cannot draw: {error}", Escaped(draw)),
            Self::Occlusion(e) => write!(f, "cannot apply ambient occlusion: {e}"),
            Self::Target(e) => write!(f, "bad frame: {e}"),
        }
    }
}

impl std::error::Error for SceneRenderError {}

impl From<CameraError> for SceneRenderError {
    fn from(e: CameraError) -> Self {
        Self::Camera(e)
    }
}

impl From<TargetError> for SceneRenderError {
    fn from(e: TargetError) -> Self {
        Self::Target(e.to_string())
    }
}
