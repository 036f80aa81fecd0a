//! Which effects a frame may use: the switches the viewer's digit keys flip, and the other choices (shading mode,
//! textures, wireframe, background) a front end makes for a scene.

use rastty_core::math::Vec3;

use super::ShadingMode;

/// An effect a scene may call for, which can be switched off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneEffect {
    /// Normal maps (tangent- or object-space).
    NormalMaps,
    /// Highlights, with their specular maps.
    Specular,
    /// Glow (emission) maps.
    GlowMaps,
    /// Shadow maps: every shadow pass, and the shadow lookups of the forward pass.
    Shadows,
    /// Ambient occlusion: the pass after the forward pass, and the occlusion maps of models (glTF).
    AmbientOcclusion,
    /// Environment light, which metallic-roughness surfaces reflect.
    Environment,
}

impl SceneEffect {
    /// Every effect, in the order of the viewer's keys `1` to `6`.
    pub const ALL: [Self; 6] =
        [Self::NormalMaps, Self::Specular, Self::GlowMaps, Self::Shadows, Self::AmbientOcclusion, Self::Environment];

    /// Its name in messages and the viewer's HUD.
    pub fn name(self) -> &'static str {
        match self {
            Self::NormalMaps => "normal maps",
            Self::Specular => "specular",
            Self::GlowMaps => "glow maps",
            Self::Shadows => "shadows",
            Self::AmbientOcclusion => "ambient occlusion",
            Self::Environment => "environment light",
        }
    }

    /// Its name on the command line (`rastty render --without shadows,normal-maps`).
    pub fn option_name(self) -> &'static str {
        match self {
            Self::NormalMaps => "normal-maps",
            Self::Specular => "specular",
            Self::GlowMaps => "glow-maps",
            Self::Shadows => "shadows",
            Self::AmbientOcclusion => "ambient-occlusion",
            Self::Environment => "environment",
        }
    }

    /// The viewer's key for it: `'1'` to `'6'`.
    pub fn key(self) -> char {
        match self {
            Self::NormalMaps => '1',
            Self::Specular => '2',
            Self::GlowMaps => '3',
            Self::Shadows => '4',
            Self::AmbientOcclusion => '5',
            Self::Environment => '6',
        }
    }

    /// The effect of a viewer key, if it is one of `'1'` to `'6'`.
    pub fn from_key(key: char) -> Option<Self> {
        Self::ALL.into_iter().find(|e| e.key() == key)
    }
}

impl std::str::FromStr for SceneEffect {
    type Err = String;

    /// Parses an [`Self::option_name`].
    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL.into_iter().find(|e| e.option_name() == s).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|e| e.option_name()).collect();
            format!("unknown effect {s:?} (expected one of: {})", names.join(", "))
        })
    }
}

/// Which effects are allowed. An effect switched off is left out of the [`super::ScenePlan`]: its passes are not
/// run and its maps not sampled, so it costs nothing. An effect switched on is used only where the scene calls for
/// it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EffectToggles {
    /// Normal maps.
    pub normal_maps: bool,
    /// Highlights and specular maps.
    pub specular: bool,
    /// Glow maps.
    pub glow_maps: bool,
    /// Shadow passes and lookups.
    pub shadows: bool,
    /// Ambient occlusion: its pass and occlusion maps.
    pub ambient_occlusion: bool,
    /// Environment light.
    pub environment: bool,
}

impl EffectToggles {
    /// Everything on: the scene as written.
    pub const ALL_ON: Self = Self {
        normal_maps: true,
        specular: true,
        glow_maps: true,
        shadows: true,
        ambient_occlusion: true,
        environment: true,
    };

    /// Whether `effect` is on.
    pub fn get(&self, effect: SceneEffect) -> bool {
        match effect {
            SceneEffect::NormalMaps => self.normal_maps,
            SceneEffect::Specular => self.specular,
            SceneEffect::GlowMaps => self.glow_maps,
            SceneEffect::Shadows => self.shadows,
            SceneEffect::AmbientOcclusion => self.ambient_occlusion,
            SceneEffect::Environment => self.environment,
        }
    }

    /// Switches `effect` to `on`.
    pub fn set(&mut self, effect: SceneEffect, on: bool) {
        let flag = match effect {
            SceneEffect::NormalMaps => &mut self.normal_maps,
            SceneEffect::Specular => &mut self.specular,
            SceneEffect::GlowMaps => &mut self.glow_maps,
            SceneEffect::Shadows => &mut self.shadows,
            SceneEffect::AmbientOcclusion => &mut self.ambient_occlusion,
            SceneEffect::Environment => &mut self.environment,
        };
        *flag = on;
    }

    /// Flips `effect`.
    pub fn toggle(&mut self, effect: SceneEffect) {
        self.set(effect, !self.get(effect));
    }

    /// Every effect on but those in `off`.
    pub fn all_but(off: &[SceneEffect]) -> Self {
        let mut toggles = Self::ALL_ON;
        for &effect in off {
            toggles.set(effect, false);
        }
        toggles
    }
}

impl Default for EffectToggles {
    /// [`Self::ALL_ON`].
    fn default() -> Self {
        Self::ALL_ON
    }
}

/// Everything a front end chooses about a scene's frame besides the camera and the size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanOptions {
    /// How objects are shaded: each by its material ([`ShadingMode::Material`]), or every one alike.
    pub shading: ShadingMode,
    /// The effects allowed.
    pub effects: EffectToggles,
    /// Diffuse textures (the scene's and the MTL files'); off draws each part in its colour.
    pub textures: bool,
    /// Triangle edges drawn over the forward pass.
    pub wireframe: bool,
    /// A background colour instead of the scene's.
    pub background: Option<Vec3>,
    /// Four samples per pixel (multisample anti-aliasing): smooth edges, each pixel still shaded once per triangle.
    pub multisample: bool,
    /// How far the environment is turned about the vertical axis, in radians (counter-clockwise seen from above).
    pub environment_turn: f32,
    /// The environment shown behind the objects instead of the background colour (when the scene has one).
    pub environment_background: bool,
}

impl Default for PlanOptions {
    /// The scene as written: each object shaded by its material, every effect, textures, no wireframe, the
    /// scene's background colour, one sample per pixel, the environment not turned.
    fn default() -> Self {
        Self {
            shading: ShadingMode::Material,
            effects: EffectToggles::ALL_ON,
            textures: true,
            wireframe: false,
            background: None,
            multisample: false,
            environment_turn: 0.0,
            environment_background: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_one_to_five_name_each_effect_once() {
        let keys: String = SceneEffect::ALL.iter().map(|e| e.key()).collect();
        assert_eq!(keys, "123456");
        for effect in SceneEffect::ALL {
            assert_eq!(SceneEffect::from_key(effect.key()), Some(effect));
        }
        assert_eq!(SceneEffect::from_key('7'), None);
        for effect in SceneEffect::ALL {
            assert_eq!(effect.option_name().parse(), Ok(effect));
        }
        assert!("shadow".parse::<SceneEffect>().unwrap_err().contains("shadows"));
    }

    #[test]
    fn toggling_flips_one_effect() {
        let mut t = EffectToggles::ALL_ON;
        t.toggle(SceneEffect::Shadows);
        assert!(!t.shadows && t.normal_maps && t.specular && t.glow_maps && t.ambient_occlusion);
        t.toggle(SceneEffect::Shadows);
        assert_eq!(t, EffectToggles::ALL_ON);
    }
}
