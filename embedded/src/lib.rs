//! rastty-core frames on any display of the `embedded-graphics` ecosystem.
//!
//! [`draw_frame`] renders a frame band by band into one band's worth of memory the caller lends
//! ([`BandMemory`]) and hands each finished band to a [`DrawTarget`](embedded_graphics_core::draw_target::DrawTarget)
//! through `fill_contiguous`, top to bottom: every display driver of the ecosystem takes it, at whatever speed its
//! bus allows, and the whole frame never needs to fit in RAM. The colour type is the display's own: RGB565 or RGB888
//! ([`DisplayColor`]), which the core writes directly (the pixels are those of the core's own [`Rgb565`] and
//! [`Rgb888`] targets). What is drawn into each band is the caller's: usually the band's draw from triangles
//! binned once a frame ([`rastty_core::pipeline::BandBins`], lent to each band's target as its
//! [`rastty_core::target::FrameGeometry`]).
//!
//! `no_std`, no allocation, no `unsafe`.
//!
//! [`Rgb565`]: rastty_core::target::Rgb565
//! [`Rgb888`]: rastty_core::target::Rgb888

#![no_std]

mod display_color;
mod error;
mod frame;

pub use display_color::DisplayColor;
pub use error::FrameError;
pub use frame::{BandMemory, draw_frame};
