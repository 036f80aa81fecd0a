//! The plan as text: what `rastty render SCENE.toml --explain` prints.

use std::fmt;

use rastty_core::color::{ShadingSpace, pack_rgb888};

use super::ScenePlan;
use super::camera::PlaneSource;
use super::lights::{LightName, ShortNumber, ShortTriple};
use crate::escaped::Escaped;
use crate::scene_file::{LightFalloff, SceneLightKind, SceneProjection};

impl fmt::Display for ScenePlan {
    /// The frame (with the space it is lit in, in which the ambient and light colours are given), the lights, then
    /// the passes in the order they run, with one line per draw of the forward pass
    /// (its object and part, escaped, and its [`rastty_core::shading::Variant`]). Only what the frame uses
    /// appears, and the lights left out are named with the reason.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (width, height) = self.size;
        let c = &self.camera;
        let lens = match c.lens {
            SceneProjection::Perspective { fov_degrees } => {
                format!("perspective, fov {} degrees", ShortNumber(fov_degrees))
            }
            SceneProjection::Orthographic { height } => format!("orthographic, {} units high", ShortNumber(height)),
        };
        let source = |s: PlaneSource| match s {
            PlaneSource::Given => "given",
            PlaneSource::Derived => "around the scene",
        };
        writeln!(
            f,
            "frame {width}x{height}: {lens}; near {} ({}), far {} ({}); background #{:06x}; {}; ambient {}",
            ShortNumber(c.near),
            source(c.near_source),
            ShortNumber(c.far),
            source(c.far_source),
            pack_rgb888(self.background),
            match self.space {
                ShadingSpace::Linear => "linear light",
                ShadingSpace::Encoded => "light on sRGB codes",
            },
            ShortTriple(self.ambient)
        )?;
        if self.lights.is_empty() && self.dropped_lights.is_empty() && self.environment.is_none() {
            writeln!(f, "lights: none (ambient light only)")?;
        } else {
            writeln!(f, "lights:")?;
        }
        for light in &self.lights {
            let shadows = if light.shadow_pass.is_some() { ", casts shadows" } else { "" };
            let falloff = match light.source.kind {
                SceneLightKind::Point { falloff, .. } | SceneLightKind::Spot { falloff, .. } => falloff,
                SceneLightKind::Directional { .. } => LightFalloff::None,
            };
            let falloff = match falloff {
                LightFalloff::None => String::new(),
                LightFalloff::InverseSquare { range: None } => ", falling off by the inverse square".to_owned(),
                LightFalloff::InverseSquare { range: Some(r) } => {
                    format!(", falling off by the inverse square to range {}", ShortNumber(r))
                }
            };
            let cone = match light.source.kind {
                SceneLightKind::Spot { inner, outer, .. } => {
                    format!(", cone {} to {} degrees", ShortNumber(inner.to_degrees()), ShortNumber(outer.to_degrees()))
                }
                _ => String::new(),
            };
            let (name, color) = (self.light_name(light), ShortTriple(light.color));
            writeln!(f, "  {name}: colour {color}{falloff}{cone}{shadows}")?;
        }
        if let Some(environment) = &self.environment {
            let turn = match ShortNumber(environment.turn.to_degrees()).to_string().as_str() {
                "0" => String::new(),
                degrees => format!(", turned {degrees} degrees"),
            };
            let background = if environment.background { ", shown behind the objects" } else { "" };
            let readers = self.draws.iter().filter(|d| d.variant.environment).count();
            let reflected = match readers {
                0 => "reflected by no draw (no metallic-roughness surface)".to_owned(),
                n => format!("reflected by {n} metallic-roughness draw{}", if n == 1 { "" } else { "s" }),
            };
            writeln!(f, "  environment {}{turn}{background}: {reflected}", environment.description)?;
        }
        for light in &self.dropped_lights {
            let why = if light.source.intensity == 0.0 { "intensity 0" } else { "black colour" };
            let name = LightName { number: light.number, light: &light.source };
            writeln!(f, "  {name}: dropped, it sheds no light ({why})")?;
        }
        writeln!(f, "passes:")?;
        let mut step = 0;
        let mut next = || {
            step += 1;
            step
        };
        for pass in &self.shadow_passes {
            let light = &self.lights[pass.light];
            let side = 2 * pass.pcf_radius + 1;
            let plural = if pass.casters == 1 { "" } else { "s" };
            writeln!(
                f,
                "  {}. shadow map of {}: {}, {} caster{plural}, pcf {side}x{side}",
                next(),
                self.light_name(light),
                pass.texels(),
                pass.casters
            )?;
        }
        let plural = if self.draws.len() == 1 { "" } else { "s" };
        let wireframe = if self.wireframe { ", with wireframe lines" } else { "" };
        let textures = if self.textures { "" } else { ", diffuse textures off" };
        let samples = match self.samples().count() {
            1 => String::new(),
            n => format!(", {n} samples per pixel (shaded once, averaged)"),
        };
        writeln!(f, "  {}. forward: {} draw{plural}{wireframe}{textures}{samples}", next(), self.draws.len())?;
        for draw in &self.draws {
            writeln!(f, "       {}: {}", Escaped(&draw.label), draw.variant)?;
        }
        if let Some(o) = &self.ambient_occlusion {
            writeln!(
                f,
                "  {}. ambient occlusion: from the depth buffer, {} directions x {} steps within {} units, strength {}",
                next(),
                o.directions,
                o.steps,
                ShortNumber(o.radius),
                ShortNumber(o.strength)
            )?;
        }
        Ok(())
    }
}
