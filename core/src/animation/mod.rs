//! Models that move: keyframed values, node transforms, morph targets and skins, over slices the caller owns.
//!
//! What a glTF 2.0 animation needs, without allocation, so that a microcontroller can pose a mesh into its own
//! buffers and the program uses the same code:
//!
//! | step | here | what it computes |
//! |---|---|---|
//! | sample | [`Keyframes`] | a channel's value at a time: `STEP`, `LINEAR` (spherical for rotations) or `CUBICSPLINE` |
//! | place | [`Trs`], [`world_matrices`] | each node's local matrix from its translation, rotation and scale, then its world matrix through its parents |
//! | deform | [`deform`] | a mesh's vertices morphed by weighted targets, then placed by one matrix or skinned by its joints' matrices ([`joint_matrix`]) |
//!
//! The formulas are those of the glTF 2.0 specification (section 3.11, "Animations", and appendix C,
//! "KeyInterpolation"); the tests check each against values worked out by hand.

mod deform;
mod hierarchy;
mod keyframes;
mod trs;

pub use deform::{DeformError, Deformed, Influences, MorphTarget, Placement, Skin, Source, deform, joint_matrix};
pub use hierarchy::{HierarchyError, world_matrices};
pub use keyframes::{KeyInterpolation, KeyframeError, Keyframes};
pub use trs::Trs;
