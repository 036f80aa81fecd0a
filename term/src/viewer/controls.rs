//! Keys and mouse gestures, and what they do.

use crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};

use crate::scene_render::SceneEffect;

/// Something the user asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Turn the model: yaw and pitch steps (in units of the key step).
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
    /// Next shading mode (models only).
    CycleShading,
    /// Switch one of a scene's effects on or off (scenes only).
    ToggleEffect(SceneEffect),
    /// Textures on / off.
    ToggleTexture,
    /// Wireframe on / off.
    ToggleWireframe,
    /// Turntable rotation on / off.
    ToggleTurntable,
    /// HUD on / off.
    ToggleHud,
    /// Key help on / off.
    ToggleHelp,
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
    "m                     shading mode (models)",
    "t                     texture on / off",
    "x                     wireframe",
    "1 2 3                 normal maps, specular, glow",
    "4 5                   shadows, ambient occlusion",
    "                      (1-5: scene files only)",
    "space                 turntable",
    "i                     info (HUD)",
    "?                     this help",
    "q / Esc / Ctrl-C      quit",
];

/// The action for an input event, if any. Only key presses count (some platforms also report releases).
pub fn action_for(event: &Event) -> Option<Action> {
    match event {
        Event::Key(key) => key_action(key),
        Event::Mouse(mouse) => mouse_action(mouse),
        Event::Resize(cols, rows) => Some(Action::Resize(*cols, *rows)),
        _ => None,
    }
}

fn key_action(key: &KeyEvent) -> Option<Action> {
    if key.kind != KeyEventKind::Press {
        return None;
    }
    let rotate = |yaw, pitch| Some(Action::Rotate { yaw, pitch });
    match key.code {
        KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => Some(Action::Quit),
        KeyCode::Left | KeyCode::Char('a' | 'h') => rotate(-1.0, 0.0),
        KeyCode::Right | KeyCode::Char('d' | 'l') => rotate(1.0, 0.0),
        KeyCode::Up | KeyCode::Char('w' | 'k') => rotate(0.0, -1.0),
        KeyCode::Down | KeyCode::Char('s' | 'j') => rotate(0.0, 1.0),
        KeyCode::Char('+' | '=') => Some(Action::Zoom(-1.0)),
        KeyCode::Char('-' | '_') => Some(Action::Zoom(1.0)),
        KeyCode::Char('r') => Some(Action::Reset),
        KeyCode::Char('p') => Some(Action::ToggleProjection),
        KeyCode::Char('m') => Some(Action::CycleShading),
        KeyCode::Char(c @ '1'..='5') => SceneEffect::from_key(c).map(Action::ToggleEffect),
        KeyCode::Char('t') => Some(Action::ToggleTexture),
        KeyCode::Char('x') => Some(Action::ToggleWireframe),
        KeyCode::Char(' ') => Some(Action::ToggleTurntable),
        KeyCode::Char('i') => Some(Action::ToggleHud),
        KeyCode::Char('?') => Some(Action::ToggleHelp),
        KeyCode::Char('q') | KeyCode::Esc => Some(Action::Quit),
        _ => None,
    }
}

fn mouse_action(mouse: &MouseEvent) -> Option<Action> {
    match mouse.kind {
        MouseEventKind::ScrollUp => Some(Action::Zoom(-1.0)),
        MouseEventKind::ScrollDown => Some(Action::Zoom(1.0)),
        MouseEventKind::Down(MouseButton::Left) => Some(Action::DragStart(mouse.column, mouse.row)),
        MouseEventKind::Up(MouseButton::Left) => Some(Action::DragEnd),
        MouseEventKind::Drag(MouseButton::Left) => Some(Action::DragTo(mouse.column, mouse.row)),
        _ => None,
    }
}
