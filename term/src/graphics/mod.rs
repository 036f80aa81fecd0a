//! Pixel images in the terminal: a frame sent whole, as an image, rather than as cells.
//!
//! | protocol | module |
//! |---|---|
//! | kitty graphics: zlib-compressed RGB in base64 chunks, one image replaced in place per frame | [`kitty`] |
//! | Sixel: a palette per frame ([`frame_palette`]) and six pixel rows per band | [`sixel`] |
//! | iTerm2 inline images: a PNG in one escape sequence | [`iterm2`] |

pub mod frame_palette;
pub mod iterm2;
pub mod kitty;
pub mod sixel;
