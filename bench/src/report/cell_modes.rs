//! (Part of `rastty-bench terminal`.) Every cell mode and pixel graphics protocol at one terminal size: the same
//! turntable of the built-in model as the main table, drawn as half-blocks, quadrants, sextants, octants, Braille
//! and ASCII, and as kitty, Sixel and iTerm2 images, with the bytes each sends and the time each frame takes to render,
//! to turn into cells and to encode (an image: its whole bytes, every frame).
//!
//! The frame rate is the program's own: one over the median of render + cells + encode per frame, what one
//! thread of the viewer could make if the terminal and the link took every byte at once.

use std::io::{self, Write};
use std::time::Duration;

use super::error::ReportError;
use super::median;
use super::turntable::{Turntable, TurntableFrame, mean};
use rastty::graphics::GraphicsProtocol;
use rastty::graphics::frame_palette::Dither;
use rastty::screen::{CellMode, ColorMode, Encoder};
use rastty_scene::scene_render::PreparedScene;

/// The terminal size of the table, in cells.
pub const SIZE: (u16, u16) = (120, 40);
/// The colour modes of the table.
pub const COLOR_MODES: [ColorMode; 2] = [ColorMode::TrueColor, ColorMode::None];

/// The pixel graphics protocols of the table (true colour, undithered).
pub const PROTOCOLS: [GraphicsProtocol; 3] =
    [GraphicsProtocol::Kitty, GraphicsProtocol::Sixel, GraphicsProtocol::Iterm2];

/// The figures of one cell mode and colour mode, or one protocol.
#[derive(Clone, Debug, PartialEq)]
pub struct ModeRow {
    /// Cells, or the protocol of the images.
    pub graphics: GraphicsProtocol,
    /// The cell mode (with [`GraphicsProtocol::Cells`]).
    pub cell_mode: CellMode,
    /// The colour mode.
    pub colors: ColorMode,
    /// Pixels rendered per frame (width, height).
    pub pixels: (usize, usize),
    /// Bytes of the first frame, the encoder's full redraw.
    pub first_frame_bytes: usize,
    /// Encoder bytes of each frame after the first.
    pub delta_bytes: Vec<usize>,
    /// Render time of each frame after the first.
    pub render: Vec<Duration>,
    /// Pixels-to-cells time of each frame after the first.
    pub cells: Vec<Duration>,
    /// Encode time of each frame after the first.
    pub encode: Vec<Duration>,
}

impl ModeRow {
    /// The mode's name: the cell mode's, or the protocol's.
    pub fn name(&self) -> &'static str {
        match self.graphics {
            GraphicsProtocol::Cells => self.cell_mode.name(),
            protocol => protocol.name(),
        }
    }

    /// Mean encoder bytes per frame after the first.
    pub fn mean_delta_bytes(&self) -> f64 {
        mean(&self.delta_bytes)
    }

    /// The median of each frame's render + cells + encode time.
    pub fn median_frame(&self) -> Duration {
        let totals: Vec<Duration> =
            self.render.iter().zip(&self.cells).zip(&self.encode).map(|((r, c), e)| *r + *c + *e).collect();
        median(&totals)
    }

    /// Frames per second at [`Self::median_frame`] (0 when no frame was measured).
    pub fn frame_rate(&self) -> f64 {
        let seconds = self.median_frame().as_secs_f64();
        if seconds > 0.0 { 1.0 / seconds } else { 0.0 }
    }
}

/// Measures every cell mode in [`COLOR_MODES`] and every protocol in [`PROTOCOLS`] at [`SIZE`]: a first frame,
/// then `frames` frames making one turn.
///
/// # Errors
/// [`ReportError::Setup`] for zero frames; [`ReportError::Render`].
pub fn measure(scene: &PreparedScene, frames: usize) -> Result<Vec<ModeRow>, ReportError> {
    if frames == 0 {
        return Err(ReportError::Setup("the turntable needs at least one frame".into()));
    }
    let mut runs: Vec<(Turntable<'_>, GraphicsProtocol, CellMode, ColorMode)> = Vec::new();
    for colors in COLOR_MODES {
        for cell_mode in CellMode::ALL {
            let turntable = Turntable::new(scene, SIZE, cell_mode, colors, frames);
            runs.push((turntable, GraphicsProtocol::Cells, cell_mode, colors));
        }
    }
    for protocol in PROTOCOLS {
        runs.push((
            Turntable::images(scene, SIZE, protocol, frames),
            protocol,
            CellMode::HalfBlock,
            ColorMode::TrueColor,
        ));
    }
    let mut rows = Vec::new();
    for (mut turntable, graphics, cell_mode, colors) in runs {
        let mut encoder = Encoder::new();
        let mut bytes = Vec::new();
        let mut encode = |frame: &TurntableFrame, bytes: &mut Vec<u8>| match &frame.image {
            Some(image) => graphics.write_image(bytes, image, Dither::None),
            None => encoder.encode(&frame.grid, bytes),
        };
        encode(&turntable.next_frame()?, &mut bytes);
        let mut row = ModeRow {
            graphics,
            cell_mode,
            colors,
            pixels: turntable.pixel_size(),
            first_frame_bytes: bytes.len(),
            delta_bytes: Vec::with_capacity(frames),
            render: Vec::with_capacity(frames),
            cells: Vec::with_capacity(frames),
            encode: Vec::with_capacity(frames),
        };
        for _ in 0..frames {
            let frame = turntable.next_frame()?;
            bytes.clear();
            let start = std::time::Instant::now();
            encode(&frame, &mut bytes);
            row.encode.push(start.elapsed());
            row.render.push(frame.render);
            row.cells.push(frame.cells);
            row.delta_bytes.push(bytes.len());
        }
        rows.push(row);
    }
    Ok(rows)
}

/// Writes the table of `rows`.
///
/// # Errors
/// When `out` fails.
pub fn write_table(out: &mut dyn Write, rows: &[ModeRow], frames: usize) -> io::Result<()> {
    let (cols, lines) = SIZE;
    writeln!(out)?;
    writeln!(out, "### Every cell mode and pixel protocol at {cols}x{lines} cells")?;
    writeln!(out)?;
    writeln!(
        out,
        "The same turntable ({frames} frames after a full redraw) in each cell mode, and as images (sized as for a \
         terminal that does not give its pixel size, true colour, Sixel undithered; every frame sent whole). ms: \
         medians per frame; frames/s: one over the median of render + cells + encode, the program's own rate on one \
         thread of the viewer."
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "| mode | colours | pixels | first frame B | mean delta B | render ms | cells ms | encode ms | frames/s |"
    )?;
    writeln!(out, "|---|---|---|---:|---:|---:|---:|---:|---:|")?;
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    for row in rows {
        writeln!(
            out,
            "| {} | {} | {}x{} | {} | {:.0} | {:.3} | {:.3} | {:.3} | {:.0} |",
            row.name(),
            if row.graphics == GraphicsProtocol::Cells { row.colors.name() } else { "truecolor" },
            row.pixels.0,
            row.pixels.1,
            row.first_frame_bytes,
            row.mean_delta_bytes(),
            ms(median(&row.render)),
            ms(median(&row.cells)),
            ms(median(&row.encode)),
            row.frame_rate(),
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::turntable::builtin_scene;

    #[test]
    fn every_mode_is_measured_at_its_own_pixel_size() {
        let scene = builtin_scene().expect("built-in model");
        let rows = measure(&scene, 2).unwrap();
        assert_eq!(rows.len(), CellMode::ALL.len() * COLOR_MODES.len() + PROTOCOLS.len());
        for row in &rows {
            let (cols, lines) = (usize::from(SIZE.0), usize::from(SIZE.1));
            let pixels = match row.graphics {
                GraphicsProtocol::Cells => row.cell_mode.pixel_size(cols, lines),
                protocol => rastty::graphics::image_size(
                    protocol,
                    SIZE,
                    None,
                    crate::report::turntable::CELL_ASPECT,
                    rastty::graphics::MAX_IMAGE_PIXELS,
                ),
            };
            assert_eq!(row.pixels, pixels, "{}", row.name());
            assert_eq!((row.delta_bytes.len(), row.render.len(), row.cells.len(), row.encode.len()), (2, 2, 2, 2));
            assert!(row.first_frame_bytes > 0 && row.delta_bytes.iter().all(|&b| b > 0), "{row:?}");
            assert!(row.frame_rate() > 0.0);
        }
        // Without colour no mode sends a colour escape, so the same picture costs fewer bytes.
        let bytes =
            |mode, colors| rows.iter().find(|r| r.cell_mode == mode && r.colors == colors).unwrap().first_frame_bytes;
        for mode in CellMode::ALL {
            assert!(bytes(mode, ColorMode::None) < bytes(mode, ColorMode::TrueColor), "{mode}");
        }
        let mut text = Vec::new();
        write_table(&mut text, &rows, 2).unwrap();
        let text = String::from_utf8(text).unwrap();
        assert_eq!(text.lines().filter(|l| l.starts_with("| ") && !l.starts_with("| mode")).count(), rows.len());
        assert!(text.contains("| braille | truecolor | 240x160 |"), "{text}");
        // 120 x 40 cells of 8 x 16 pixels, 960 x 640, scaled to the viewer's cap: 678 x 452.
        assert!(text.contains("| kitty | truecolor | 678x452 |"), "{text}");
    }
}
