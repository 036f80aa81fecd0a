//! Why a report could not be made: the one error of the timing and terminal reports.

use std::fmt;
use std::io;

use rastty_scene::scene_file::OpenError;
use rastty_scene::scene_render::SceneRenderError;

/// Why a report could not be made.
#[derive(Debug)]
pub enum ReportError {
    /// The built-in model did not load.
    Load(OpenError),
    /// A frame could not be planned or drawn.
    Render(SceneRenderError),
    /// The report's set-up cannot be measured: no frame to measure, a frame size the renderer does not take, or
    /// shadow maps not drawn or reused as a configuration needs.
    Setup(String),
    /// The report could not be written.
    Write(io::Error),
}

impl fmt::Display for ReportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Load(e) => e.fmt(f),
            Self::Render(e) => e.fmt(f),
            Self::Setup(e) => f.write_str(e),
            Self::Write(e) => write!(f, "cannot write the report: {e}"),
        }
    }
}

impl std::error::Error for ReportError {}

impl From<io::Error> for ReportError {
    fn from(e: io::Error) -> Self {
        Self::Write(e)
    }
}

impl From<SceneRenderError> for ReportError {
    fn from(e: SceneRenderError) -> Self {
        Self::Render(e)
    }
}
