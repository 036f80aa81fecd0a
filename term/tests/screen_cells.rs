//! Pixels to cells: the half-block and ASCII layouts, in every colour mode.

use proptest::prelude::*;
use proptest::test_runner::Config as ProptestConfig;
use rastty::screen::ascii_ramp::{ASCII_RAMP, ascii_cell};
use rastty::screen::half_block::UPPER_HALF_BLOCK;
use rastty::screen::{Cell, CellGrid, CellMode, Color, ColorMode, PixelFrame};

const MODES: [ColorMode; 4] = [ColorMode::TrueColor, ColorMode::Ansi256, ColorMode::Ansi16, ColorMode::None];

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig { cases, failure_persistence: None, ..ProptestConfig::default() }
}

/// A `w` x `h` image (1..=9 each) from a small random set of colours, so equal neighbours are common.
fn image() -> impl Strategy<Value = (Vec<u32>, usize, usize)> {
    (1usize..=9, 1usize..=9, prop::collection::vec(0u32..0x0100_0000, 1..4)).prop_flat_map(|(w, h, palette)| {
        prop::collection::vec(prop::sample::select(palette), w * h).prop_map(move |pixels| (pixels, w, h))
    })
}

fn ramp_position(ch: char) -> usize {
    ASCII_RAMP.iter().position(|&c| char::from(c) == ch).expect("a ramp character")
}

proptest! {
    #![proptest_config(config(600))]

    /// Cell (r, c) shows pixel (2r, c) over pixel (2r + 1, c), or over the background below an odd last row;
    /// equal colours (after quantisation) make a space on that background.
    #[test]
    fn half_block_layout((pixels, w, h) in image(), mode in prop::sample::select(MODES.to_vec()), background in 0u32..0x0100_0000) {
        let grid = CellMode::HalfBlock.to_cells(PixelFrame::new(&pixels, w, h), mode, background);
        prop_assert_eq!((grid.width, grid.height), (w, h.div_ceil(2)));
        for row in 0..grid.height {
            for col in 0..w {
                let upper = pixels[2 * row * w + col];
                let lower = if 2 * row + 1 < h { pixels[(2 * row + 1) * w + col] } else { background };
                let cell = *grid.get(row, col);
                prop_assert!(Cell::is_safe_char(cell.ch));
                if mode == ColorMode::None {
                    prop_assert_eq!((cell.fg, cell.bg), (Color::Default, Color::Default));
                    prop_assert!(ASCII_RAMP.contains(&(cell.ch as u8)));
                    if upper == lower {
                        prop_assert_eq!(cell, ascii_cell(upper, ColorMode::None));
                    }
                } else if mode.quantize(upper) == mode.quantize(lower) {
                    prop_assert_eq!(cell, Cell::new(' ', Color::Default, mode.quantize(lower)));
                } else {
                    prop_assert_eq!(cell, Cell::new(UPPER_HALF_BLOCK, mode.quantize(upper), mode.quantize(lower)));
                }
            }
        }
    }

    /// One cell per pixel, the ramp character in the pixel's quantised colour on the default background.
    #[test]
    fn ascii_layout((pixels, w, h) in image(), mode in prop::sample::select(MODES.to_vec())) {
        let grid = CellMode::Ascii.to_cells(PixelFrame::new(&pixels, w, h), mode, 0);
        prop_assert_eq!((grid.width, grid.height), (w, h));
        for (cell, &pixel) in grid.cells.iter().zip(&pixels) {
            prop_assert_eq!(cell.bg, Color::Default);
            prop_assert!(ASCII_RAMP.contains(&(cell.ch as u8)));
            let expected_fg = if cell.ch == ' ' || mode == ColorMode::None { Color::Default } else { mode.quantize(pixel) };
            prop_assert_eq!(cell.fg, expected_fg);
        }
    }

    /// A brighter grey never gets a sparser ramp character, in either cell mode.
    #[test]
    fn ramp_follows_brightness(a in 0u32..=255, b in 0u32..=255) {
        let (dark, light) = (a.min(b) * 0x010101, a.max(b) * 0x010101);
        let cells = CellMode::Ascii.to_cells(PixelFrame::new(&[dark, light], 2, 1), ColorMode::None, 0);
        prop_assert!(ramp_position(cells.cells[0].ch) <= ramp_position(cells.cells[1].ch));
        let blocks = CellMode::HalfBlock.to_cells(PixelFrame::new(&[dark, light, dark, light], 2, 2), ColorMode::None, 0);
        prop_assert!(ramp_position(blocks.cells[0].ch) <= ramp_position(blocks.cells[1].ch));
    }
}

#[test]
fn half_block_example_with_odd_height() {
    // 2 x 3 pixels: red/green over blue/green, then white/black over the (grey) background.
    let pixels = [0xFF0000, 0x00FF00, 0x0000FF, 0x00FF00, 0xFFFFFF, 0x000000];
    let grid = CellMode::HalfBlock.to_cells(PixelFrame::new(&pixels, 2, 3), ColorMode::TrueColor, 0x808080);
    let expected = CellGrid {
        width: 2,
        height: 2,
        cells: vec![
            Cell::new('▀', Color::Rgb(255, 0, 0), Color::Rgb(0, 0, 255)),
            Cell::new(' ', Color::Default, Color::Rgb(0, 255, 0)),
            Cell::new('▀', Color::Rgb(255, 255, 255), Color::Rgb(128, 128, 128)),
            Cell::new('▀', Color::Rgb(0, 0, 0), Color::Rgb(128, 128, 128)),
        ],
    };
    assert_eq!(grid, expected);

    let grid = CellMode::HalfBlock.to_cells(PixelFrame::new(&pixels, 2, 3), ColorMode::Ansi256, 0x808080);
    assert_eq!(grid.cells[0], Cell::new('▀', Color::Indexed(196), Color::Indexed(21)));
    assert_eq!(grid.cells[1], Cell::new(' ', Color::Default, Color::Indexed(46)));
    assert_eq!(grid.cells[2], Cell::new('▀', Color::Indexed(231), Color::Indexed(244)));
}

#[test]
fn refilling_a_grid_resizes_it() {
    let mut grid = CellGrid::blank(50, 50);
    CellMode::HalfBlock.fill_cells(&mut grid, PixelFrame::new(&[0; 12], 4, 3), ColorMode::Ansi16, 0);
    assert_eq!((grid.width, grid.height, grid.cells.len()), (4, 2, 8));
    assert_eq!(grid.rows().count(), 2);
    assert!(grid.rows().all(|row| row.len() == 4));
    CellMode::Ascii.fill_cells(&mut grid, PixelFrame::new(&[], 0, 0), ColorMode::Ansi16, 0);
    assert_eq!((grid.width, grid.height, grid.rows().count()), (0, 0, 0));
}

#[test]
#[should_panic(expected = "needs 6 pixels")]
fn pixel_frame_checks_its_length() {
    let _ = PixelFrame::new(&[0; 5], 3, 2);
}
