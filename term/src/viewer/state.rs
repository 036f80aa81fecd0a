//! What the viewer shows and how input changes it.

use rastty_scene::scene_render::{Orbit, PlanOptions};

use super::controls::Action;

/// Degrees per rotation key press.
const KEY_STEP_DEGREES: f32 = 10.0;
/// Degrees per cell of mouse drag horizontally; vertically times the cell aspect (rows are taller).
const DRAG_DEGREES_PER_CELL: f32 = 2.5;
/// Distance factor per zoom step.
const ZOOM_FACTOR: f32 = 1.12;
/// Turntable speed in degrees per second.
pub const TURNTABLE_DEGREES_PER_SECOND: f32 = 40.0;

/// The viewer's state.
#[derive(Clone, Debug)]
pub struct ViewerState {
    /// The camera now.
    pub orbit: Orbit,
    /// The shading mode, effects, textures, wireframe and background now.
    pub options: PlanOptions,
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
    initial: (Orbit, PlanOptions),
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
    /// Cells are now `cell_aspect` times as tall as wide (the terminal said so after a resize).
    pub fn set_cell_aspect(&mut self, cell_aspect: f32) {
        self.cell_aspect = cell_aspect;
    }

    /// The state at start-up, for cells `cell_aspect` times as tall as wide.
    pub fn new(orbit: Orbit, options: PlanOptions, cell_aspect: f32) -> Self {
        Self {
            cell_aspect,
            orbit,
            options,
            turntable: false,
            hud: false,
            help: false,
            drag: None,
            initial: (orbit, options),
        }
    }

    /// Applies an action.
    pub fn apply(&mut self, action: Action) -> Effect {
        match action {
            Action::Rotate { yaw, pitch } => {
                let step = KEY_STEP_DEGREES.to_radians();
                self.orbit.rotate(yaw * step, pitch * step);
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
                self.orbit.rotate(dx * step, dy * self.cell_aspect * step);
            }
            Action::DragEnd => {
                self.drag = None;
                return Effect::None;
            }
            Action::Zoom(steps) => self.orbit.zoom(rastty_core::math::float::pow(ZOOM_FACTOR, steps)),
            Action::Reset => {
                (self.orbit, self.options) = self.initial;
                self.turntable = false;
            }
            Action::ToggleProjection => self.orbit.toggle_projection(),
            Action::CycleShading => self.options.shading = self.options.shading.next(),
            Action::ToggleEffect(effect) => self.options.effects.toggle(effect),
            Action::ToggleTexture => self.options.textures = !self.options.textures,
            Action::ToggleWireframe => self.options.wireframe = !self.options.wireframe,
            Action::ToggleMultisample => self.options.multisample = !self.options.multisample,
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
        self.orbit.rotate((TURNTABLE_DEGREES_PER_SECOND * seconds).to_radians(), 0.0);
    }
}

#[cfg(test)]
mod tests {
    use rastty_core::math::Vec3;

    use super::*;
    use rastty_scene::scene_file::{SceneCamera, SceneProjection};
    use rastty_scene::scene_render::{SceneEffect, ShadingMode};

    fn state() -> ViewerState {
        let camera = SceneCamera {
            position: Vec3::new(0.0, 1.0, 4.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
            projection: SceneProjection::Perspective { fov_degrees: 40.0 },
            near: None,
            far: None,
        };
        ViewerState::new(Orbit::new(camera), PlanOptions::default(), 2.0)
    }

    #[test]
    fn digits_toggle_effects_and_reset_restores_them() {
        let mut state = state();
        assert_eq!(state.apply(Action::ToggleEffect(SceneEffect::Shadows)), Effect::Redraw);
        assert!(!state.options.effects.shadows);
        state.apply(Action::Rotate { yaw: 1.0, pitch: 0.0 });
        state.apply(Action::Reset);
        assert!(state.options.effects.shadows);
        assert_eq!(state.orbit, self::state().orbit);
    }

    #[test]
    fn m_cycles_the_shading_mode_of_every_object() {
        let mut state = state();
        assert_eq!(state.options.shading, ShadingMode::Phong);
        assert_eq!(state.apply(Action::CycleShading), Effect::Redraw);
        assert_eq!(state.options.shading, ShadingMode::Depth);
        for _ in 1..ShadingMode::ALL.len() {
            state.apply(Action::CycleShading);
        }
        assert_eq!(state.options.shading, ShadingMode::Phong, "the cycle has every mode once");
    }
}
