//! What the viewer shows and how input changes it.

use crate::scene::{Appearance, OrbitCamera};
use crate::scene_render::{EffectToggles, SceneOrbit};

use super::controls::Action;

/// Degrees per rotation key press.
const KEY_STEP_DEGREES: f32 = 10.0;
/// Degrees per cell of mouse drag horizontally; vertically times the cell aspect (rows are taller).
const DRAG_DEGREES_PER_CELL: f32 = 2.5;
/// Distance factor per zoom step.
const ZOOM_FACTOR: f32 = 1.12;
/// Distance limits, in model radii.
const MIN_DISTANCE: f32 = 0.3;
const MAX_DISTANCE: f32 = 40.0;
/// Turntable speed in degrees per second.
pub const TURNTABLE_DEGREES_PER_SECOND: f32 = 40.0;

/// The camera of what the viewer shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewerCamera {
    /// A single model, fitted and turned in front of a fixed camera.
    Model(OrbitCamera),
    /// A scene file's camera, orbiting its target.
    Scene(SceneOrbit),
}

impl ViewerCamera {
    /// Turns by `yaw` and `pitch` radians: the model about the screen's axes, or the scene's eye about its target
    /// (so that the scene appears to turn the same way).
    pub fn rotate(&mut self, yaw: f32, pitch: f32) {
        match self {
            Self::Model(c) => c.rotate(yaw, pitch),
            Self::Scene(o) => o.rotate(yaw, pitch),
        }
    }

    /// Zooms by `steps` zoom steps (negative: closer).
    pub fn zoom(&mut self, steps: f32) {
        let factor = rastty_core::math::float::pow(ZOOM_FACTOR, steps);
        match self {
            Self::Model(c) => c.distance = (c.distance * factor).clamp(MIN_DISTANCE, MAX_DISTANCE),
            Self::Scene(o) => o.zoom(factor),
        }
    }

    /// Perspective / orthographic.
    pub fn toggle_projection(&mut self) {
        match self {
            Self::Model(c) => c.lens = c.lens.toggled(),
            Self::Scene(o) => o.toggle_projection(),
        }
    }

    /// True for an orthographic lens.
    pub fn is_orthographic(&self) -> bool {
        match self {
            Self::Model(c) => c.lens.is_orthographic(),
            Self::Scene(o) => o.is_orthographic(),
        }
    }
}

/// The viewer's state.
#[derive(Clone, Debug)]
pub struct ViewerState {
    /// The camera now.
    pub camera: ViewerCamera,
    /// The look now (for a scene: textures, wireframe and background; its shading mode is not used).
    pub appearance: Appearance,
    /// The effects switched on (scenes only).
    pub effects: EffectToggles,
    /// Turning by itself.
    pub turntable: bool,
    /// Showing the HUD.
    pub hud: bool,
    /// Showing the key help.
    pub help: bool,
    /// Where a drag last was.
    drag: Option<(u16, u16)>,
    /// Cell height over width, so a vertical drag turns as far per pixel as a horizontal one.
    cell_aspect: f32,
    initial: (ViewerCamera, Appearance, EffectToggles),
}

/// What an action asks of the loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effect {
    /// Nothing visible changed.
    None,
    /// Draw a new frame.
    Redraw,
    /// Leave.
    Quit,
}

impl ViewerState {
    /// The state at start-up, for cells `cell_aspect` times as tall as wide, with every effect on.
    pub fn new(camera: ViewerCamera, appearance: Appearance, cell_aspect: f32) -> Self {
        let effects = EffectToggles::ALL_ON;
        Self {
            cell_aspect,
            camera,
            appearance,
            effects,
            turntable: false,
            hud: false,
            help: false,
            drag: None,
            initial: (camera, appearance, effects),
        }
    }

    /// The same state with `effects` switched on at the start (and after a reset).
    pub fn with_effects(mut self, effects: EffectToggles) -> Self {
        self.effects = effects;
        self.initial.2 = effects;
        self
    }

    /// True when a scene file is shown (not a single model).
    pub fn is_scene(&self) -> bool {
        matches!(self.camera, ViewerCamera::Scene(_))
    }

    /// Applies an action.
    pub fn apply(&mut self, action: Action) -> Effect {
        match action {
            Action::Rotate { yaw, pitch } => {
                let step = KEY_STEP_DEGREES.to_radians();
                self.camera.rotate(yaw * step, pitch * step);
            }
            Action::DragStart(column, row) => {
                self.drag = Some((column, row));
                return Effect::None;
            }
            Action::DragTo(column, row) => {
                let Some((c0, r0)) = self.drag.replace((column, row)) else { return Effect::None };
                let (dx, dy) = (f32::from(column) - f32::from(c0), f32::from(row) - f32::from(r0));
                if dx == 0.0 && dy == 0.0 {
                    return Effect::None;
                }
                let step = DRAG_DEGREES_PER_CELL.to_radians();
                self.camera.rotate(dx * step, dy * self.cell_aspect * step);
            }
            Action::DragEnd => {
                self.drag = None;
                return Effect::None;
            }
            Action::Zoom(steps) => self.camera.zoom(steps),
            Action::Reset => {
                (self.camera, self.appearance, self.effects) = self.initial;
                self.turntable = false;
            }
            Action::ToggleProjection => self.camera.toggle_projection(),
            // A scene's surfaces have one shading (its materials and lights): the shading modes are for models.
            Action::CycleShading if self.is_scene() => return Effect::None,
            Action::CycleShading => self.appearance.shading = self.appearance.shading.next(),
            // Effects are a scene's; a single model has none of them.
            Action::ToggleEffect(_) if !self.is_scene() => return Effect::None,
            Action::ToggleEffect(effect) => self.effects.toggle(effect),
            Action::ToggleTexture => self.appearance.textures = !self.appearance.textures,
            Action::ToggleWireframe => self.appearance.wireframe = !self.appearance.wireframe,
            Action::ToggleTurntable => self.turntable = !self.turntable,
            Action::ToggleHud => self.hud = !self.hud,
            Action::ToggleHelp => self.help = !self.help,
            Action::Resize(..) => {}
            Action::Quit => return Effect::Quit,
        }
        Effect::Redraw
    }

    /// Advances the turntable by `seconds`.
    pub fn spin(&mut self, seconds: f32) {
        self.camera.rotate((TURNTABLE_DEGREES_PER_SECOND * seconds).to_radians(), 0.0);
    }
}

#[cfg(test)]
mod tests {
    use rastty_core::math::Vec3;

    use super::*;
    use crate::scene_file::{Projection, SceneCamera};
    use crate::scene_render::SceneEffect;

    fn scene_state() -> ViewerState {
        let camera = SceneCamera {
            position: Vec3::new(0.0, 1.0, 4.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection: Projection::Perspective { fov_degrees: 40.0 },
            near: None,
            far: None,
        };
        ViewerState::new(ViewerCamera::Scene(SceneOrbit::new(camera)), Appearance::default(), 2.0)
    }

    #[test]
    fn digits_toggle_a_scenes_effects_and_reset_restores_them() {
        let mut state = scene_state();
        assert_eq!(state.apply(Action::ToggleEffect(SceneEffect::Shadows)), Effect::Redraw);
        assert!(!state.effects.shadows);
        state.apply(Action::Rotate { yaw: 1.0, pitch: 0.0 });
        state.apply(Action::Reset);
        assert!(state.effects.shadows);
        assert_eq!(state.camera, scene_state().camera);
    }

    #[test]
    fn shading_modes_are_for_models_and_effects_for_scenes() {
        let mut scene = scene_state();
        assert_eq!(scene.apply(Action::CycleShading), Effect::None);
        let mut model = ViewerState::new(ViewerCamera::Model(OrbitCamera::default()), Appearance::default(), 2.0);
        assert_eq!(model.apply(Action::ToggleEffect(SceneEffect::Shadows)), Effect::None);
        assert_eq!(model.apply(Action::CycleShading), Effect::Redraw);
    }
}
