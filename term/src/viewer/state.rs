//! What the viewer shows and how input changes it.

use crate::scene::{Appearance, OrbitCamera};

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

/// The viewer's state.
#[derive(Clone, Debug)]
pub struct ViewerState {
    /// The camera now.
    pub camera: OrbitCamera,
    /// The look now.
    pub appearance: Appearance,
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
    initial: (OrbitCamera, Appearance),
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
    /// The state at start-up, for cells `cell_aspect` times as tall as wide.
    pub fn new(camera: OrbitCamera, appearance: Appearance, cell_aspect: f32) -> Self {
        Self {
            cell_aspect,
            camera,
            appearance,
            turntable: false,
            hud: false,
            help: false,
            drag: None,
            initial: (camera, appearance),
        }
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
            Action::Zoom(steps) => {
                let distance = self.camera.distance * rasterm_core::math::float::pow(ZOOM_FACTOR, steps);
                self.camera.distance = distance.clamp(MIN_DISTANCE, MAX_DISTANCE);
            }
            Action::Reset => {
                (self.camera, self.appearance) = self.initial;
                self.turntable = false;
            }
            Action::ToggleProjection => self.camera.lens = self.camera.lens.toggled(),
            Action::CycleShading => self.appearance.shading = self.appearance.shading.next(),
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
