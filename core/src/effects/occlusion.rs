//! Screen-space ambient occlusion (placeholder module: being written).

/// Screen-space ambient occlusion settings.
#[derive(Clone, Copy, Debug)]
pub struct AmbientOcclusion;
