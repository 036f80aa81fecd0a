//! Keys and mouse gestures, and what they do.

use super::input_decoder::{Input, Key, MouseKind};

use rastty_scene::scene_render::SceneEffect;

/// Something the user asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Orbit the camera: yaw and pitch steps (in units of the key step).
    Rotate {
        /// Steps about the vertical axis (+ turns the front to the right).
        yaw: f32,
        /// Steps about the horizontal axis (+ tilts the top toward the camera).
        pitch: f32,
    },
    /// The left button went down at (column, row): a drag may start.
    DragStart(u16, u16),
    /// The pointer moved to (column, row) with the left button held: orbit by the movement.
    DragTo(u16, u16),
    /// The left button went up.
    DragEnd,
    /// Move closer (negative) or farther (positive), in zoom steps.
    Zoom(f32),
    /// Back to the starting view.
    Reset,
    /// Perspective / orthographic.
    ToggleProjection,
    /// Next shading mode, for every object.
    CycleShading,
    /// Switch one of the effects on or off.
    ToggleEffect(SceneEffect),
    /// Textures on / off.
    ToggleTexture,
    /// Wireframe on / off.
    ToggleWireframe,
    /// Multisample anti-aliasing on / off.
    ToggleMultisample,
    /// Turn the environment about the vertical axis by one step (+1 counter-clockwise seen from above, -1 back).
    TurnEnvironment(i32),
    /// The environment shown behind the objects, or the background colour.
    ToggleEnvironmentBackground,
    /// Turntable rotation on / off.
    ToggleTurntable,
    /// Play / pause the animation.
    TogglePlayback,
    /// The next (+1) or previous (-1) animation, from its start.
    StepAnimation(i32),
    /// Play the animation twice as fast (+1) or half as fast (-1).
    ChangeSpeed(i32),
    /// HUD on / off.
    ToggleHud,
    /// Key help on / off.
    ToggleHelp,
    /// Save the view as a PNG file.
    Capture,
    /// Show the next (+1) or previous (-1) file.
    StepFile(i32),
    /// The terminal was resized to (columns, rows).
    Resize(u16, u16),
    /// Leave.
    Quit,
}

/// The key help, one line per entry (plain ASCII so every terminal shows it).
pub const HELP: &[&str] = &[
    "arrows / wasd / hjkl  rotate",
    "+ / - / mouse wheel   zoom",
    "drag with the mouse   orbit",
    "r                     reset view",
    "p                     perspective / ortho",
    "m                     shading mode",
    "t                     texture on / off",
    "x                     wireframe",
    "e                     smooth edges (4x MSAA)",
    "1 2 3                 normal maps, specular, glow",
    "4 5 6                 shadows, ambient occlusion, environment",
    "v V                   turn the environment",
    "b                     environment as background",
    "space                 turntable",
    "o                     play / pause animation",
    ", .                   previous / next animation",
    "< >                   slower / faster animation",
    "] [                   next / previous file",
    "c                     save the view as a PNG",
    "i                     info (HUD)",
    "?                     this help",
    "q / Esc / Ctrl-C      quit",
];

/// The action for an input event, if any.
pub fn action_for(input: &Input) -> Option<Action> {
    match *input {
        Input::Key(key) => key_action(key),
        Input::Mouse { kind, column, row } => Some(match kind {
            MouseKind::ScrollUp => Action::Zoom(-1.0),
            MouseKind::ScrollDown => Action::Zoom(1.0),
            MouseKind::Press => Action::DragStart(column, row),
            MouseKind::Release => Action::DragEnd,
            MouseKind::Drag => Action::DragTo(column, row),
        }),
        // The frame writer's business, not the user's.
        Input::StatusOk => None,
        // Answers to the start-up probe (or late ones): not the user's either.
        Input::DeviceAttributes { .. } | Input::CellPixels { .. } | Input::GraphicsReply { .. } => None,
    }
}

fn key_action(key: Key) -> Option<Action> {
    let rotate = |yaw, pitch| Some(Action::Rotate { yaw, pitch });
    match key {
        Key::CtrlC | Key::Esc | Key::Char('q') => Some(Action::Quit),
        Key::Left | Key::Char('a' | 'h') => rotate(-1.0, 0.0),
        Key::Right | Key::Char('d' | 'l') => rotate(1.0, 0.0),
        Key::Up | Key::Char('w' | 'k') => rotate(0.0, -1.0),
        Key::Down | Key::Char('s' | 'j') => rotate(0.0, 1.0),
        Key::Char('+' | '=') => Some(Action::Zoom(-1.0)),
        Key::Char('-' | '_') => Some(Action::Zoom(1.0)),
        Key::Char('r') => Some(Action::Reset),
        Key::Char('p') => Some(Action::ToggleProjection),
        Key::Char('m') => Some(Action::CycleShading),
        Key::Char(c @ '1'..='6') => SceneEffect::from_key(c).map(Action::ToggleEffect),
        Key::Char('t') => Some(Action::ToggleTexture),
        Key::Char('x') => Some(Action::ToggleWireframe),
        Key::Char('e') => Some(Action::ToggleMultisample),
        Key::Char('v') => Some(Action::TurnEnvironment(1)),
        Key::Char('V') => Some(Action::TurnEnvironment(-1)),
        Key::Char('b') => Some(Action::ToggleEnvironmentBackground),
        Key::Char(' ') => Some(Action::ToggleTurntable),
        Key::Char('o') => Some(Action::TogglePlayback),
        Key::Char('.') => Some(Action::StepAnimation(1)),
        Key::Char(',') => Some(Action::StepAnimation(-1)),
        Key::Char('>') => Some(Action::ChangeSpeed(1)),
        Key::Char('<') => Some(Action::ChangeSpeed(-1)),
        Key::Char('i') => Some(Action::ToggleHud),
        Key::Char('?') => Some(Action::ToggleHelp),
        Key::Char('c') => Some(Action::Capture),
        Key::Char(']') => Some(Action::StepFile(1)),
        Key::Char('[') => Some(Action::StepFile(-1)),
        Key::Char(_) => None,
    }
}
