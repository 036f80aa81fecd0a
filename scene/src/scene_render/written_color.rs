//! Colours as a scene writes them (sRGB-encoded, as shown on a screen) turned into the values a draw lights with.

use rastty_core::color::{ShadingSpace, srgb_to_linear};
use rastty_core::math::Vec3;

/// The colour `written` (sRGB-encoded: a scene file's colours, an MTL material's, a light's before its
/// intensity) as a draw lit in `space` takes it: decoded to linear light, or as written.
///
/// # Examples
/// ```
/// use rastty_scene::scene_render::lit_color;
/// use rastty_core::{color::ShadingSpace, math::Vec3};
/// assert_eq!(lit_color(Vec3::new(1.0, 0.0, 0.5), ShadingSpace::Encoded), Vec3::new(1.0, 0.0, 0.5));
/// let linear = lit_color(Vec3::new(1.0, 0.0, 0.5), ShadingSpace::Linear);
/// assert_eq!((linear.x, linear.y), (1.0, 0.0));
/// assert!((linear.z - 0.214).abs() < 1e-3);
/// ```
pub fn lit_color(written: Vec3, space: ShadingSpace) -> Vec3 {
    match space {
        ShadingSpace::Linear => written.map(srgb_to_linear),
        ShadingSpace::Encoded => written,
    }
}
