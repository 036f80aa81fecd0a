//! What a compiled surface shader can draw: the shading models and light kinds its code includes.
//!
//! [`super::SurfaceShader`]'s last parameter is a set of these bits (by default [`ALL`]). A draw compiled for
//! fewer leaves the other stages out of the program: a firmware that draws one kind of surface links the code of
//! that one (its variant is checked against the set when the shader is made). A draw without texture coordinates
//! (`U` absent) compiles no map code at all; with them, a diffuse map needs no bit, mipmapped maps need
//! [`MIPMAPS`] and the other maps [`LIGHTING_MAPS`].

/// Unlit shading (material or vertex colours).
pub const UNLIT: u32 = 1;
/// Flat shading: light once per triangle.
pub const FLAT: u32 = 1 << 1;
/// Gouraud shading: light once per vertex.
pub const GOURAUD: u32 = 1 << 2;
/// Per-pixel lighting.
pub const PER_PIXEL: u32 = 1 << 3;
/// The depth and normals views.
pub const VIEWS: u32 = 1 << 4;
/// Point and spot lights (directional lights are always compiled in).
pub const POINT_LIGHTS: u32 = 1 << 5;
/// Shadow maps (read by per-pixel lighting).
pub const SHADOWS: u32 = 1 << 6;
/// Alpha cut-outs ([`super::Material::alpha_cutoff`] with a diffuse map): without it the pixel loop compiles
/// without the discard.
pub const CUTOUT: u32 = 1 << 7;
/// Two-sided per-pixel lighting ([`super::Variant::two_sided`]: a draw that keeps back faces).
pub const TWO_SIDED: u32 = 1 << 8;
/// Mipmapped maps ([`super::Variant::mip_filter`]): the slopes of the texture coordinates and the levels of
/// detail.
pub const MIPMAPS: u32 = 1 << 9;
/// Shading in linear light ([`crate::color::ShadingSpace::Linear`]): the sRGB decoding of colour maps and the
/// encoding of each pixel, and their tables.
pub const LINEAR_LIGHT: u32 = 1 << 10;
/// The maps beyond the diffuse (albedo) map: normal, specular, glow, occlusion and metallic-roughness maps. A
/// shader that carries texture coordinates without it reads a diffuse map alone; where batches hold one fragment
/// and it is compiled without [`MIPMAPS`] and [`SHADOWS`] too, it then lights every Blinn-Phong fragment in scalar
/// maths and compiles no batch stages for that lighting.
pub const LIGHTING_MAPS: u32 = 1 << 11;
/// glTF's metallic-roughness model ([`super::ShadingModel::MetallicRoughness`]), lit per pixel.
pub const METALLIC_ROUGHNESS: u32 = 1 << 12;
/// Everything: what [`super::draw_mesh`] compiles.
pub const ALL: u32 = UNLIT
    | FLAT
    | GOURAUD
    | PER_PIXEL
    | VIEWS
    | POINT_LIGHTS
    | SHADOWS
    | CUTOUT
    | TWO_SIDED
    | MIPMAPS
    | LINEAR_LIGHT
    | LIGHTING_MAPS
    | METALLIC_ROUGHNESS;

/// True when `caps` holds `bit`: a constant in a shader compiled for `caps`, so the code it guards is left out
/// when false.
#[inline(always)]
pub(crate) const fn has(caps: u32, bit: u32) -> bool {
    caps & bit != 0
}
