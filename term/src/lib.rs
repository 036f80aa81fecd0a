//! The terminal side of rastty: frames shown in a terminal, and the viewer that shows a scene and follows the keys.
//!
//! The road from a file to a frame is [`rastty_scene`]'s; this crate takes the frame on to the terminal:
//!
//! | step | module | what happens |
//! |---|---|---|
//! | cells | [`screen`] | the frame as terminal cells (half blocks, quadrants, sextants, Braille, ASCII) in true colour, 256 or 16 colours, diffed against the last frame and written |
//! | images | [`graphics`] | the frame as one image in the kitty, Sixel or iTerm2 protocol, for terminals that show pixels |
//! | viewer | [`viewer`] | the interactive loop: terminal set-up and restore, keys, the camera's orbit, pacing over slow links |
//!
//! The `rastty` program (`src/main.rs`) adds the command line and `rastty render`'s files (a PNG, or a turntable as
//! GIF, APNG or numbered PNGs, and `--stats`).

pub mod graphics;
pub mod screen;
pub mod viewer;
