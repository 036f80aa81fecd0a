//! Fixed-function settings of a draw.

use super::DrawError;
use crate::mesh::{Attributes, Mesh};

/// Which winding counts as front-facing, judged in NDC (`+y` up) as seen by the camera.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Winding {
    /// Counter-clockwise triangles face the camera (the OpenGL and OBJ convention).
    #[default]
    CounterClockwise,
    /// Clockwise triangles face the camera.
    Clockwise,
}

impl Winding {
    /// The other winding.
    pub fn flipped(self) -> Self {
        match self {
            Self::CounterClockwise => Self::Clockwise,
            Self::Clockwise => Self::CounterClockwise,
        }
    }
}

/// Which triangles to discard by facing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Draw both sides.
    None,
    /// Discard triangles facing away from the camera.
    #[default]
    Back,
    /// Discard triangles facing the camera.
    Front,
}

/// The depth test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DepthTest {
    /// Keep a fragment when its depth is less than the stored one, and store it (see [`crate::target`]).
    #[default]
    Less,
    /// Neither read nor write the depth buffer.
    Off,
}

/// How varyings are interpolated across a triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Interpolation {
    /// Perspective-correct: linear in 3D, so textures do not swim. One division per pixel.
    #[default]
    PerspectiveCorrect,
    /// Linear in screen space: exact when every vertex has the same `w` (an orthographic projection), a
    /// visible approximation otherwise. No division per pixel.
    Affine,
}

/// How edge functions are computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EdgeArithmetic {
    /// Vertices snapped to the sub-pixel grid, edge functions exact in integers: watertight, with the top-left rule
    /// applied exactly.
    #[default]
    FixedPoint,
    /// Edge functions in `f32` from unsnapped positions, as simple rasterizers compute them: no snapping
    /// (`subpixel_bits` does not apply), but rounding can leave a crack or a doubled pixel on shared edges. For
    /// measuring what exactness is worth.
    Float,
}

/// The per-draw fixed-function choices as `--explain` prints them: `perspective-correct, depth less, cull back`.
#[derive(Clone, Copy, Debug)]
pub struct FixedFunction<'a>(pub &'a DrawState);

impl core::fmt::Display for FixedFunction<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let s = self.0;
        f.write_str(match s.interpolation {
            Interpolation::PerspectiveCorrect => "perspective-correct",
            Interpolation::Affine => "affine",
        })?;
        f.write_str(match s.depth_test {
            DepthTest::Less => ", depth less",
            DepthTest::Off => ", depth off",
        })?;
        f.write_str(match s.cull {
            Cull::None => ", cull none",
            Cull::Back => ", cull back",
            Cull::Front => ", cull front",
        })
    }
}

/// Largest supported number of sub-pixel bits.
pub const MAX_SUBPIXEL_BITS: u8 = 8;

/// The fixed-function state of a draw.
///
/// # Examples
/// ```
/// use rastty_core::pipeline::{Cull, DrawState};
/// let state = DrawState { cull: Cull::None, ..DrawState::default() };
/// assert_eq!(state.subpixel_bits, 8);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DrawState {
    /// Which faces to discard.
    pub cull: Cull,
    /// Which winding faces the camera.
    pub front_face: Winding,
    /// The depth test.
    pub depth_test: DepthTest,
    /// How varyings are interpolated.
    pub interpolation: Interpolation,
    /// Fractional bits of the fixed-point screen coordinates that vertices snap to, `0..=8` (D3D uses 8, Vulkan
    /// requires at least 4). More bits place edges more precisely; fewer make slivers pop.
    pub subpixel_bits: u8,
    /// Integer or `f32` edge functions.
    pub edges: EdgeArithmetic,
}

impl DrawState {
    /// The default state, usable in constants: back faces culled (counter-clockwise is front), depth test `less`,
    /// perspective-correct interpolation, [`MAX_SUBPIXEL_BITS`] of sub-pixel precision, fixed-point edges.
    pub const DEFAULT: Self = Self {
        cull: Cull::Back,
        front_face: Winding::CounterClockwise,
        depth_test: DepthTest::Less,
        interpolation: Interpolation::PerspectiveCorrect,
        subpixel_bits: MAX_SUBPIXEL_BITS,
        edges: EdgeArithmetic::FixedPoint,
    };

    /// Whether a draw of `mesh` with this state by a shader that reads `needed` may run.
    pub(crate) fn check(&self, mesh: &Mesh<'_>, needed: Attributes) -> Result<(), DrawError> {
        let present = mesh.attributes();
        if !present.contains(needed) {
            return Err(DrawError::MissingAttributes { needed, present });
        }
        if self.subpixel_bits > MAX_SUBPIXEL_BITS {
            return Err(DrawError::SubpixelBits(self.subpixel_bits));
        }
        Ok(())
    }
}

impl Default for DrawState {
    /// [`DrawState::DEFAULT`].
    fn default() -> Self {
        Self::DEFAULT
    }
}
