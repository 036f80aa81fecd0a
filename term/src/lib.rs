//! A frame in a terminal: the last step of rastty's road from a file to the screen (the steps before it are
//! [`rastty_scene`]'s), as a library for the `rastty` program, its measurements, and any tool that shows pixels in a
//! terminal.
//!
//! | step | module | what happens |
//! |---|---|---|
//! | cells | [`screen`] | the frame as terminal cells (half blocks, quadrants, sextants, Braille, ASCII) in true colour, 256 or 16 colours, diffed against the last frame and written, within a tolerance while it moves |
//! | images | [`graphics`] | the frame as one image in the kitty, Sixel or iTerm2 protocol, for terminals that show pixels, sized to the cells it covers |
//!
//! The `rastty` program (`src/main.rs`, its modules private) adds the viewer (terminal set-up and restore, keys, the
//! camera's orbit, pacing over slow links), the command line and `rastty render`'s files.

pub mod graphics;
pub mod screen;
