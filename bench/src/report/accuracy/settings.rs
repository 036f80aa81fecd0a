//! The quality knobs: each setting changes one of them from the default.

use rastty_core::color::ShadingSpace;
use rastty_core::environment::Prefiltering;
use rastty_core::pipeline::{DrawState, EdgeArithmetic, Interpolation};
use rastty_core::target::Samples;
use rastty_core::texture::{Anisotropy, FilterMode, MipFilter};

/// How lit surfaces are shaded (unlit ones ignore it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LitShading {
    /// Once per triangle.
    Flat,
    /// Per vertex.
    Gouraud,
    /// Per pixel.
    Phong,
}

/// Depth buffer format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthFormat {
    /// 32-bit float.
    F32,
    /// 16-bit fixed point.
    U16,
}

/// One point in the space of knobs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Setting {
    /// Its name in tables and charts.
    pub name: &'static str,
    /// Which knob it turns, and to what.
    pub knob: &'static str,
    /// Sub-pixel bits of vertex snapping.
    pub subpixel_bits: u8,
    /// Edge-function arithmetic.
    pub edges: EdgeArithmetic,
    /// Varying interpolation.
    pub interpolation: Interpolation,
    /// Texture filter.
    pub filter: FilterMode,
    /// How textures choose among their levels of detail.
    pub mip_filter: MipFilter,
    /// Linear light, or light on the stored sRGB codes.
    pub space: ShadingSpace,
    /// Shading of lit surfaces.
    pub shading: LitShading,
    /// Samples per pixel along each axis, each shaded (supersampling).
    pub supersample: u32,
    /// Coverage and depth samples per pixel, shaded once (multisampling).
    pub multisample: Samples,
    /// Depth format.
    pub depth: DepthFormat,
    /// How the environment's specular light is prefiltered (scenes with an environment).
    pub prefiltering: Prefiltering,
}

/// rastty's defaults: 8 sub-pixel bits, fixed-point edges, perspective-correct, bilinear, trilinear mipmaps,
/// per-pixel lighting, linear light, one sample per pixel (neither supersampled nor multisampled), `f32` depth,
/// the environment prefiltered as the program does ([`Prefiltering::DEFAULT`]: 256x128, 6 levels, 64 samples).
pub const DEFAULT: Setting = Setting {
    name: "default",
    knob: "-",
    subpixel_bits: 8,
    edges: EdgeArithmetic::FixedPoint,
    interpolation: Interpolation::PerspectiveCorrect,
    filter: FilterMode::Bilinear,
    mip_filter: MipFilter::Linear,
    space: ShadingSpace::Linear,
    shading: LitShading::Phong,
    supersample: 1,
    multisample: Samples::One,
    depth: DepthFormat::F32,
    prefiltering: Prefiltering::DEFAULT,
};

/// The default prefiltering with one field changed.
const fn prefiltered(height: u32, levels: u32, samples: u32) -> Prefiltering {
    Prefiltering { height, levels, samples }
}

/// Every setting measured: the default, then one knob at a time.
pub const ALL: [Setting; 25] = [
    DEFAULT,
    Setting { name: "0 sub-pixel bits", knob: "sub-pixel bits", subpixel_bits: 0, ..DEFAULT },
    Setting { name: "4 sub-pixel bits", knob: "sub-pixel bits", subpixel_bits: 4, ..DEFAULT },
    Setting { name: "f32 edges", knob: "edge arithmetic", edges: EdgeArithmetic::Float, ..DEFAULT },
    Setting { name: "affine", knob: "interpolation", interpolation: Interpolation::Affine, ..DEFAULT },
    Setting { name: "nearest", knob: "texture filter", filter: FilterMode::Nearest, ..DEFAULT },
    Setting { name: "mipmaps off", knob: "mipmaps", mip_filter: MipFilter::Off, ..DEFAULT },
    Setting { name: "nearest level", knob: "mipmaps", mip_filter: MipFilter::Nearest, ..DEFAULT },
    Setting { name: "anisotropic 2", knob: "mipmaps", mip_filter: MipFilter::Anisotropic(Anisotropy::X2), ..DEFAULT },
    Setting { name: "anisotropic 4", knob: "mipmaps", mip_filter: MipFilter::Anisotropic(Anisotropy::X4), ..DEFAULT },
    Setting { name: "anisotropic 8", knob: "mipmaps", mip_filter: MipFilter::Anisotropic(Anisotropy::X8), ..DEFAULT },
    Setting { name: "anisotropic 16", knob: "mipmaps", mip_filter: MipFilter::Anisotropic(Anisotropy::X16), ..DEFAULT },
    Setting { name: "sRGB-coded light", knob: "shading space", space: ShadingSpace::Encoded, ..DEFAULT },
    Setting { name: "flat", knob: "shading", shading: LitShading::Flat, ..DEFAULT },
    Setting { name: "Gouraud", knob: "shading", shading: LitShading::Gouraud, ..DEFAULT },
    Setting { name: "4x MSAA", knob: "anti-aliasing", multisample: Samples::Four, ..DEFAULT },
    Setting { name: "2x2 SSAA", knob: "anti-aliasing", supersample: 2, ..DEFAULT },
    Setting { name: "4x4 SSAA", knob: "anti-aliasing", supersample: 4, ..DEFAULT },
    Setting { name: "u16 depth", knob: "depth buffer", depth: DepthFormat::U16, ..DEFAULT },
    Setting { name: "env 128x64", knob: "environment size", prefiltering: prefiltered(64, 6, 64), ..DEFAULT },
    Setting { name: "env 512x256", knob: "environment size", prefiltering: prefiltered(256, 6, 64), ..DEFAULT },
    Setting { name: "env 4 levels", knob: "environment levels", prefiltering: prefiltered(128, 4, 64), ..DEFAULT },
    Setting { name: "env 10 levels", knob: "environment levels", prefiltering: prefiltered(128, 10, 64), ..DEFAULT },
    Setting { name: "env 16 samples", knob: "prefilter samples", prefiltering: prefiltered(128, 6, 16), ..DEFAULT },
    Setting { name: "env 256 samples", knob: "prefilter samples", prefiltering: prefiltered(128, 6, 256), ..DEFAULT },
];

impl Setting {
    /// The core draw state of this setting.
    pub fn draw_state(&self) -> DrawState {
        DrawState {
            subpixel_bits: self.subpixel_bits,
            edges: self.edges,
            interpolation: self.interpolation,
            ..DrawState::default()
        }
    }

    /// True for the default setting.
    pub fn is_default(&self) -> bool {
        *self == DEFAULT
    }
}
