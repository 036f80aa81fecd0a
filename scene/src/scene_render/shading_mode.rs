//! The shading modes a frame may be drawn in: the `--shading` option and the viewer's `m` key.

use rastty_core::shading::ShadingModel;

/// The shading modes offered to users. Each surface is shaded as its material says ([`Self::Material`]) unless a
/// front end asks for another mode, which then applies to every object.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ShadingMode {
    /// Each part by its material: glTF's metallic-roughness model for a physically based one
    /// ([`crate::scene_file::SceneObject::physically_based`]), per-pixel Blinn-Phong for the others.
    #[default]
    Material,
    /// Colours and textures, no lighting.
    Unlit,
    /// Lit once per triangle.
    Flat,
    /// Lit per vertex.
    Gouraud,
    /// Lit per pixel by the Blinn-Phong model.
    Phong,
    /// Lit per pixel by glTF's metallic-roughness model.
    MetallicRoughness,
    /// The depth buffer as grey levels.
    Depth,
    /// Surface normals as colours.
    Normals,
}

impl ShadingMode {
    /// All modes, in the viewer's cycling order.
    pub const ALL: [Self; 8] = [
        Self::Material,
        Self::Unlit,
        Self::Flat,
        Self::Gouraud,
        Self::Phong,
        Self::MetallicRoughness,
        Self::Depth,
        Self::Normals,
    ];

    /// The mode's name as given on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::Material => "material",
            Self::Unlit => "unlit",
            Self::Flat => "flat",
            Self::Gouraud => "gouraud",
            Self::Phong => "phong",
            Self::MetallicRoughness => "metallic-roughness",
            Self::Depth => "depth",
            Self::Normals => "normals",
        }
    }

    /// The next mode in cycling order (the viewer's `m` key).
    pub fn next(self) -> Self {
        let i = Self::ALL.iter().position(|&m| m == self).unwrap_or(0);
        Self::ALL[(i + 1) % Self::ALL.len()]
    }
}

impl std::str::FromStr for ShadingMode {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL.into_iter().find(|m| m.name() == s).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|m| m.name()).collect();
            format!("unknown shading mode {s:?} (expected one of: {})", names.join(", "))
        })
    }
}

impl ShadingMode {
    /// The core's shading model for this mode, for a part that is `physically_based` or not; the depth view maps
    /// the NDC depths `near` (white) to `far` (black).
    pub fn model(self, (near, far): (f32, f32), physically_based: bool) -> ShadingModel {
        match self {
            Self::Material if physically_based => ShadingModel::MetallicRoughness,
            Self::Material => ShadingModel::Phong,
            Self::Unlit => ShadingModel::Unlit,
            Self::Flat => ShadingModel::Flat,
            Self::Gouraud => ShadingModel::Gouraud,
            Self::Phong => ShadingModel::Phong,
            Self::MetallicRoughness => ShadingModel::MetallicRoughness,
            Self::Depth => ShadingModel::Depth { near, far },
            Self::Normals => ShadingModel::Normals,
        }
    }
}
