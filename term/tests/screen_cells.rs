//! Pixels to cells: the half-block, symbol and ASCII layouts, in every colour mode.
//!
//! Symbol cells are read back through the Unicode names of their characters (`unicode_names2`), not through the
//! renderer's own glyph tables: "QUADRANT UPPER LEFT AND LOWER RIGHT", "BLOCK SEXTANT-1246", "BRAILLE PATTERN
//! DOTS-1357" say which parts of the cell a character covers.

use proptest::prelude::*;
use proptest::test_runner::Config as ProptestConfig;
use rastty::screen::ascii_ramp::ASCII_RAMP;
use rastty::screen::half_block::UPPER_HALF_BLOCK;
use rastty::screen::symbol_glyphs::SYMBOL_SETS;
use rastty::screen::{Cell, CellGrid, CellMode, Color, ColorMode, PixelFrame, SymbolSet};

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
                    prop_assert_eq!(cell.ch == ' ', upper == background && lower == background);
                } else if mode.quantize(upper) == mode.quantize(lower) {
                    prop_assert_eq!(cell, Cell::new(' ', Color::Default, mode.quantize(lower)));
                } else {
                    prop_assert_eq!(cell, Cell::new(UPPER_HALF_BLOCK, mode.quantize(upper), mode.quantize(lower)));
                }
            }
        }
    }

    /// One cell per pixel: blank for the background, otherwise a visible ramp character in the pixel's quantised
    /// colour on the default background.
    #[test]
    fn ascii_layout((pixels, w, h) in image(), mode in prop::sample::select(MODES.to_vec()), background in 0u32..0x0100_0000) {
        let grid = CellMode::Ascii.to_cells(PixelFrame::new(&pixels, w, h), mode, background);
        prop_assert_eq!((grid.width, grid.height), (w, h));
        for (cell, &pixel) in grid.cells.iter().zip(&pixels) {
            if pixel == background {
                prop_assert_eq!(*cell, Cell::BLANK);
                continue;
            }
            prop_assert_eq!(cell.bg, Color::Default);
            prop_assert!(ASCII_RAMP[1..].contains(&(cell.ch as u8)), "{:?}", cell.ch);
            prop_assert_eq!(cell.fg, mode.quantize(pixel));
        }
    }

    /// A symbol cell of one or two colours shows every one of its pixels in that pixel's exact colour (true
    /// colour), read back through the character's Unicode name; a cell of more colours shows each pixel in the
    /// nearer of its two colours.
    #[test]
    fn symbol_cells_show_their_pixels((pixels, w, h) in image(), set in prop::sample::select(SYMBOL_SETS.to_vec()), background in 0u32..0x0100_0000) {
        let grid = CellMode::Symbols(set).to_cells(PixelFrame::new(&pixels, w, h), ColorMode::TrueColor, background);
        prop_assert_eq!((grid.width, grid.height), (w.div_ceil(2), h.div_ceil(set.rows())));
        for row in 0..grid.height {
            for col in 0..grid.width {
                let cell = *grid.get(row, col);
                prop_assert!(Cell::is_safe_char(cell.ch));
                let covered = covered_parts(set, cell.ch);
                let cell_pixels: Vec<u32> = (0..set.sub_pixels())
                    .map(|i| {
                        let (x, y) = (col * 2 + i % 2, row * set.rows() + i / 2);
                        if x < w && y < h { pixels[y * w + x] } else { background }
                    })
                    .collect();
                let mut distinct = cell_pixels.clone();
                distinct.sort_unstable();
                distinct.dedup();
                let shown: Vec<Color> = (0..set.sub_pixels())
                    .map(|i| if covered & (1 << i) != 0 { cell.fg } else { cell.bg })
                    .collect();
                if distinct.len() <= 2 {
                    let exact: Vec<Color> = cell_pixels.iter().map(|&p| ColorMode::TrueColor.quantize(p)).collect();
                    prop_assert_eq!(shown, exact, "{:?} cell ({}, {}) {:?}", set, row, col, cell);
                } else {
                    prop_assert!(covered != 0 && cell.fg != cell.bg);
                }
            }
        }
    }

    /// Without colour, background pixels are never lit, and a symbol cell sends no colour.
    #[test]
    fn symbol_cells_without_colour((pixels, w, h) in image(), set in prop::sample::select(SYMBOL_SETS.to_vec()), background in 0u32..0x0100_0000) {
        let grid = CellMode::Symbols(set).to_cells(PixelFrame::new(&pixels, w, h), ColorMode::None, background);
        for row in 0..grid.height {
            for col in 0..grid.width {
                let cell = *grid.get(row, col);
                prop_assert_eq!((cell.fg, cell.bg), (Color::Default, Color::Default));
                let covered = covered_parts(set, cell.ch);
                for i in 0..set.sub_pixels() {
                    let (x, y) = (col * 2 + i % 2, row * set.rows() + i / 2);
                    let is_background = x >= w || y >= h || pixels[y * w + x] == background;
                    prop_assert!(!(is_background && covered & (1 << i) != 0), "{:?} lights the background", cell.ch);
                }
            }
        }
    }

    /// In the palette modes a symbol cell's colours are palette entries, and a pattern is drawn only in two
    /// different ones.
    #[test]
    fn symbol_cells_in_palettes((pixels, w, h) in image(), set in prop::sample::select(SYMBOL_SETS.to_vec()), mode in prop::sample::select(vec![ColorMode::Ansi256, ColorMode::Ansi16])) {
        let grid = CellMode::Symbols(set).to_cells(PixelFrame::new(&pixels, w, h), mode, 0);
        for cell in &grid.cells {
            prop_assert!(matches!(cell.bg, Color::Indexed(_)));
            if cell.ch == ' ' {
                prop_assert_eq!(cell.fg, Color::Default);
            } else {
                prop_assert!(matches!(cell.fg, Color::Indexed(_)) && cell.fg != cell.bg);
            }
        }
    }

    /// A brighter grey never gets a sparser ramp character, in the modes that draw one.
    #[test]
    fn ramp_follows_brightness(a in 0u32..=255, b in 0u32..=255) {
        let (dark, light) = (a.min(b) * 0x010101, a.max(b) * 0x010101);
        let cells = CellMode::Ascii.to_cells(PixelFrame::new(&[dark, light], 2, 1), ColorMode::None, 0);
        prop_assert!(ramp_position(cells.cells[0].ch) <= ramp_position(cells.cells[1].ch));
        let blocks = CellMode::HalfBlock.to_cells(PixelFrame::new(&[dark, light, dark, light], 2, 2), ColorMode::None, 0);
        prop_assert!(ramp_position(blocks.cells[0].ch) <= ramp_position(blocks.cells[1].ch));
    }
}

/// The parts of a cell (bit `row * 2 + col`) that `ch` covers, from its Unicode name.
fn covered_parts(set: SymbolSet, ch: char) -> u8 {
    if ch == ' ' {
        return 0;
    }
    let name = unicode_names2::name(ch).map(|n| n.to_string()).unwrap_or_default();
    let rows = set.rows() as u8;
    let column = |col: u8| (0..rows).fold(0u8, |m, r| m | 1 << (r * 2 + col));
    match name.as_str() {
        "FULL BLOCK" => return (u16::MAX >> (16 - 2 * rows)) as u8,
        "LEFT HALF BLOCK" => return column(0),
        "RIGHT HALF BLOCK" => return column(1),
        "UPPER HALF BLOCK" if set == SymbolSet::Quadrant => return 0b0011,
        "LOWER HALF BLOCK" if set == SymbolSet::Quadrant => return 0b1100,
        _ => {}
    }
    // An octant cell's rows are quarters of it: the blocks that cover whole quarters, by rows and columns.
    if set == SymbolSet::Octant {
        let rows = |from: u8, to: u8, columns: u8| (from..to).fold(0u8, |m, r| m | columns << (2 * r));
        let (both, left, right) = (0b11, 0b01, 0b10);
        let covered = match name.as_str() {
            "UPPER HALF BLOCK" => Some(rows(0, 2, both)),
            "LOWER HALF BLOCK" => Some(rows(2, 4, both)),
            "UPPER ONE QUARTER BLOCK" => Some(rows(0, 1, both)),
            "LOWER ONE QUARTER BLOCK" => Some(rows(3, 4, both)),
            "UPPER THREE QUARTERS BLOCK" => Some(rows(0, 3, both)),
            "LOWER THREE QUARTERS BLOCK" => Some(rows(1, 4, both)),
            "MIDDLE LEFT ONE QUARTER BLOCK" => Some(rows(1, 3, left)),
            "MIDDLE RIGHT ONE QUARTER BLOCK" => Some(rows(1, 3, right)),
            "LEFT HALF UPPER ONE QUARTER BLOCK" => Some(rows(0, 1, left)),
            "RIGHT HALF UPPER ONE QUARTER BLOCK" => Some(rows(0, 1, right)),
            "LEFT HALF LOWER ONE QUARTER BLOCK" => Some(rows(3, 4, left)),
            "RIGHT HALF LOWER ONE QUARTER BLOCK" => Some(rows(3, 4, right)),
            _ => None,
        };
        if let Some(covered) = covered {
            return covered;
        }
    }
    if let Some(quadrants) = name.strip_prefix("QUADRANT ") {
        // A quadrant is one part of a 2x2 cell, two rows of a 2x4 one.
        let part = |bit: u8| if set == SymbolSet::Octant { (1 | 1 << 2) << (bit / 2 * 4 + bit % 2) } else { 1 << bit };
        return quadrants.split(" AND ").fold(0, |m, q| {
            m | match q {
                "UPPER LEFT" => part(0),
                "UPPER RIGHT" => part(1),
                "LOWER LEFT" => part(2),
                "LOWER RIGHT" => part(3),
                _ => panic!("{ch:?}: unknown quadrant in {name:?}"),
            }
        });
    }
    // Sextants and octants number their parts 1 to 6 or 8 row by row; Braille numbers its dots 1-2-3 down the left
    // column, 4-5-6 down the right, then 7 (left) and 8 (right) below.
    let (digits, part_of) = if let (SymbolSet::Sextant, Some(d)) = (set, name.strip_prefix("BLOCK SEXTANT-")) {
        (d, [0u8, 1, 2, 3, 4, 5, 0, 0])
    } else if let (SymbolSet::Octant, Some(d)) = (set, name.strip_prefix("BLOCK OCTANT-")) {
        (d, [0u8, 1, 2, 3, 4, 5, 6, 7])
    } else if let (SymbolSet::Braille, Some(d)) = (set, name.strip_prefix("BRAILLE PATTERN DOTS-")) {
        (d, [0u8, 2, 4, 1, 3, 5, 6, 7])
    } else {
        panic!("{ch:?} ({name:?}) is not a {set:?} character")
    };
    digits.bytes().fold(0, |m, d| m | 1 << part_of[usize::from(d - b'1')])
}

#[test]
fn every_symbol_pattern_reads_back() {
    for set in SYMBOL_SETS {
        for pattern in 0..(1u16 << set.sub_pixels()) {
            let pattern = pattern as u8;
            assert_eq!(covered_parts(set, set.glyph(pattern)), pattern, "{set:?} {pattern:#010b}");
        }
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
