//! Pixel images in the terminal: a frame sent whole, as an image, rather than as cells.
//!
//! | protocol | module |
//! |---|---|
//! | kitty graphics: zlib-compressed RGB in base64 chunks, one image replaced in place per frame | [`kitty`] |
//! | Sixel: a palette per frame ([`frame_palette`]) and six pixel rows per band | [`sixel`] |
//! | iTerm2 inline images: a PNG in one escape sequence | [`iterm2`] |
//!
//! Inside tmux, kitty's and iTerm2's strings reach the terminal through tmux's pass-through ([`passthrough`]).
//!
//! [`graphics_protocol::GraphicsProtocol`] is the viewer's choice among them (or cells), and writes a frame with
//! the one chosen.

pub mod frame_palette;
pub mod graphics_protocol;
mod image_size;
pub mod iterm2;
pub mod kitty;
pub mod passthrough;
pub mod sixel;

pub use graphics_protocol::{FrameImage, GraphicsProtocol};
pub use image_size::{
    ASSUMED_CELL_WIDTH, DEFAULT_CELL_ASPECT, MAX_IMAGE_PIXELS, MIN_IMAGE_PIXELS, image_size, moving_image_cap,
};
pub use passthrough::Passthrough;
