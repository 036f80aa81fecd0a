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
/// The slowest and fastest an animation plays, times its own speed (`<` halves it, `>` doubles it).
const SPEEDS: (f32, f32) = (1.0 / 16.0, 16.0);
/// Degrees the environment turns per press of `v` or `V`.
const ENVIRONMENT_STEP_DEGREES: f32 = 30.0;

/// An animation of the scene, playing or paused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Playback {
    /// Its number.
    pub animation: usize,
    /// How many animations the scene has.
    pub count: usize,
    /// Seconds into it.
    pub time: f32,
    /// Times its own speed.
    pub speed: f32,
    /// Stopped where it is.
    pub paused: bool,
}

impl Playback {
    /// Animation `animation` of `count`, playing from `time` at its own speed.
    pub fn new(animation: usize, count: usize, time: f32) -> Self {
        Self { animation, count, time, speed: 1.0, paused: false }
    }

    /// Moves on by `seconds` of wall time, looping over an animation `length` seconds long.
    pub fn advance(&mut self, seconds: f32, length: f32) {
        if self.paused {
            return;
        }
        self.time += seconds * self.speed;
        self.time = if length > 0.0 { self.time.rem_euclid(length) } else { 0.0 };
    }
}

/// The viewer's state.
#[derive(Clone, Debug)]
pub struct ViewerState {
    /// The camera now.
    pub orbit: Orbit,
    /// The shading mode, effects, textures, wireframe and background now.
    pub options: PlanOptions,
    /// Turning by itself.
    pub turntable: bool,
    /// The animation, when the scene has any.
    pub playback: Option<Playback>,
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

    /// The state at start-up, for cells `cell_aspect` times as tall as wide, playing `playback`.
    pub fn new(orbit: Orbit, options: PlanOptions, cell_aspect: f32, playback: Option<Playback>) -> Self {
        Self {
            cell_aspect,
            orbit,
            options,
            turntable: false,
            playback,
            hud: false,
            help: false,
            drag: None,
            initial: (orbit, options),
        }
    }

    /// Shows another scene: seen by `orbit` (also what a reset goes back to) with `options`, playing `playback`.
    pub fn show(&mut self, orbit: Orbit, options: PlanOptions, playback: Option<Playback>) {
        self.orbit = orbit;
        self.options = options;
        self.initial = (orbit, options);
        self.playback = playback;
        self.drag = None;
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
            Action::TurnEnvironment(step) => {
                let turn = self.options.environment_turn + step as f32 * ENVIRONMENT_STEP_DEGREES.to_radians();
                self.options.environment_turn = turn.rem_euclid(core::f32::consts::TAU);
            }
            Action::ToggleEnvironmentBackground => {
                self.options.environment_background = !self.options.environment_background;
            }
            Action::ToggleTurntable => self.turntable = !self.turntable,
            Action::TogglePlayback => {
                let Some(p) = &mut self.playback else { return Effect::None };
                p.paused = !p.paused;
            }
            Action::StepAnimation(step) => {
                let Some(p) = &mut self.playback else { return Effect::None };
                let count = p.count.max(1) as i64;
                p.animation = (p.animation as i64 + i64::from(step)).rem_euclid(count) as usize;
                p.time = 0.0;
            }
            Action::ChangeSpeed(step) => {
                let Some(p) = &mut self.playback else { return Effect::None };
                p.speed = (p.speed * 2f32.powi(step)).clamp(SPEEDS.0, SPEEDS.1);
            }
            Action::ToggleHud => self.hud = !self.hud,
            Action::ToggleHelp => self.help = !self.help,
            // The viewer saves the picture itself: nothing of the state changes.
            Action::Resize(..) | Action::Capture | Action::StepFile(_) => {}
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
        ViewerState::new(Orbit::new(camera), PlanOptions::default(), 2.0, Some(Playback::new(0, 3, 0.0)))
    }

    #[test]
    fn animation_keys_pause_step_and_change_speed_and_time_loops() {
        let mut state = state();
        let p = |s: &ViewerState| s.playback.unwrap();
        state.playback.as_mut().unwrap().advance(2.5, 1.0);
        assert_eq!(p(&state).time, 0.5, "2.5 s into a 1 s animation is 0.5 s into its third loop");
        assert_eq!(state.apply(Action::TogglePlayback), Effect::Redraw);
        state.playback.as_mut().unwrap().advance(0.25, 1.0);
        assert_eq!((p(&state).paused, p(&state).time), (true, 0.5), "paused, it stays");
        state.apply(Action::StepAnimation(-1));
        assert_eq!((p(&state).animation, p(&state).time), (2, 0.0), "before the first, the last, from its start");
        state.apply(Action::StepAnimation(1));
        assert_eq!(p(&state).animation, 0);
        state.apply(Action::ChangeSpeed(1));
        state.apply(Action::TogglePlayback);
        state.playback.as_mut().unwrap().advance(0.25, 1.0);
        assert_eq!(p(&state).time, 0.5, "twice as fast");
        for _ in 0..10 {
            state.apply(Action::ChangeSpeed(-1));
        }
        assert_eq!(p(&state).speed, 1.0 / 16.0, "the slowest");
        let mut still = ViewerState::new(state.orbit, PlanOptions::default(), 2.0, None);
        assert_eq!(still.apply(Action::TogglePlayback), Effect::None, "nothing moves: nothing to do");
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
        assert_eq!(state.options.shading, ShadingMode::Material);
        assert_eq!(state.apply(Action::CycleShading), Effect::Redraw);
        assert_eq!(state.options.shading, ShadingMode::Unlit);
        for _ in 1..ShadingMode::ALL.len() {
            state.apply(Action::CycleShading);
        }
        assert_eq!(state.options.shading, ShadingMode::Material, "the cycle has every mode once");
    }

    #[test]
    fn v_turns_the_environment_and_b_shows_it_behind() {
        let mut state = state();
        assert_eq!(state.options.environment_turn, 0.0);
        assert_eq!(state.apply(Action::TurnEnvironment(1)), Effect::Redraw);
        assert!((state.options.environment_turn - 30f32.to_radians()).abs() < 1e-6);
        state.apply(Action::TurnEnvironment(-1));
        state.apply(Action::TurnEnvironment(-1));
        // Kept within one turn.
        assert!((state.options.environment_turn - 330f32.to_radians()).abs() < 1e-5);
        assert!(!state.options.environment_background);
        state.apply(Action::ToggleEnvironmentBackground);
        assert!(state.options.environment_background);
        state.apply(Action::ToggleEffect(SceneEffect::Environment));
        assert!(!state.options.effects.environment);
        // Reset brings the environment back to where it started.
        state.apply(Action::Reset);
        assert_eq!((state.options.environment_turn, state.options.environment_background), (0.0, false));
    }
}
