//! The frame encoder at byte level, with the `vt100` terminal emulator as the oracle: whatever the encoder
//! writes, the emulated screen must end up showing exactly the cells of the frame (character, foreground,
//! background), in every colour mode, across random changes, multi-frame sequences and resizes.

use std::num::NonZeroU16;

use proptest::prelude::*;
use proptest::test_runner::Config as ProptestConfig;
use rastty::screen::encoder::{CLEAR_SCREEN, SYNC_BEGIN, SYNC_END};
use rastty::screen::{Cell, CellGrid, CellMode, Color, ColorMode, Encoder, PixelFrame, Tolerance, naive_full_frame};

// ---------------------------------------------------------------------------------------------------------
// The oracle.

/// A vt100 emulator of `grid`'s size.
fn terminal(width: usize, height: usize) -> vt100::Parser {
    vt100::Parser::new(dim(height), dim(width), 0)
}

fn dim(n: usize) -> NonZeroU16 {
    NonZeroU16::new(u16::try_from(n).expect("small grid")).expect("non-empty grid")
}

fn to_vt100(color: Color) -> vt100::Color {
    match color {
        Color::Rgb(r, g, b) => vt100::Color::Rgb(r, g, b),
        Color::Indexed(n) => vt100::Color::Idx(n),
        Color::Default => vt100::Color::Default,
    }
}

/// Panics unless the emulated screen shows exactly `grid` (a cleared cell counts as a space).
fn assert_screen_shows(parser: &vt100::Parser, grid: &CellGrid) {
    let screen = parser.screen();
    assert_eq!(screen.size(), (dim(grid.height), dim(grid.width)), "terminal size");
    for row in 0..grid.height {
        for col in 0..grid.width {
            let want = grid.get(row, col);
            let got = screen.cell(row as u16, col as u16).expect("cell inside the screen");
            let contents = if got.has_contents() { got.contents() } else { " " };
            let mut utf8 = [0u8; 4];
            let want_ch: &str = want.safe_ch().encode_utf8(&mut utf8);
            assert!(
                contents == want_ch
                    && got.fgcolor() == to_vt100(want.fg)
                    && got.bgcolor() == to_vt100(want.bg)
                    && !got.is_wide()
                    && !got.is_wide_continuation(),
                "cell ({row}, {col}): screen has {contents:?} fg {:?} bg {:?}, frame wants {want:?}",
                got.fgcolor(),
                got.bgcolor(),
            );
        }
    }
}

/// Checks rules every encoder output must keep, whatever the frame.
fn assert_well_formed(bytes: &[u8]) {
    assert!(!bytes.contains(&b'\n'), "emitted \\n");
    assert!(!bytes.contains(&b'\r'), "emitted \\r");
    assert!(std::str::from_utf8(bytes).is_ok(), "not UTF-8");
    if !bytes.is_empty() {
        assert!(bytes.starts_with(SYNC_BEGIN) && bytes.ends_with(SYNC_END), "missing synchronized-output brackets");
    }
}

/// Encodes `grid` with `encoder`, checks the output rules, feeds it to `parser` and returns the byte count.
fn encode_into(encoder: &mut Encoder, parser: &mut vt100::Parser, grid: &CellGrid) -> usize {
    let mut bytes = Vec::new();
    encoder.encode(grid, &mut bytes);
    assert_well_formed(&bytes);
    parser.process(&bytes);
    let screen = parser.screen();
    assert_eq!(
        (screen.fgcolor(), screen.bgcolor()),
        (vt100::Color::Default, vt100::Color::Default),
        "attributes left set"
    );
    bytes.len()
}

// ---------------------------------------------------------------------------------------------------------
// Strategies: grids whose cells come from a small per-case set of colours, so that runs of equal colours
// (and so skipped SGR parts and re-sent gaps) are common, in each colour mode.

const MODES: [ColorMode; 4] = [ColorMode::TrueColor, ColorMode::Ansi256, ColorMode::Ansi16, ColorMode::None];
const CHARS: [char; 8] = [' ', '▀', '.', '#', '@', '█', ':', '▄'];

fn color_in(mode: ColorMode) -> BoxedStrategy<Color> {
    match mode {
        ColorMode::TrueColor => prop_oneof![
            9 => any::<(u8, u8, u8)>().prop_map(|(r, g, b)| Color::Rgb(r, g, b)),
            1 => Just(Color::Default),
        ]
        .boxed(),
        ColorMode::Ansi256 => prop_oneof![9 => any::<u8>().prop_map(Color::Indexed), 1 => Just(Color::Default)].boxed(),
        ColorMode::Ansi16 => prop_oneof![9 => (0u8..16).prop_map(Color::Indexed), 1 => Just(Color::Default)].boxed(),
        ColorMode::None => Just(Color::Default).boxed(),
    }
}

/// A cell drawn from `colors` and [`CHARS`] by three random indices.
fn pick_cell(colors: &[Color], (ch, fg, bg): (usize, usize, usize)) -> Cell {
    Cell::new(CHARS[ch % CHARS.len()], colors[fg % colors.len()], colors[bg % colors.len()])
}

fn cell_choice() -> impl Strategy<Value = (usize, usize, usize)> {
    (0..CHARS.len(), 0usize..8, 0usize..8)
}

/// A `width` x `height` grid in `mode` plus its colour set.
fn grid_in(mode: ColorMode, width: usize, height: usize) -> impl Strategy<Value = (CellGrid, Vec<Color>)> {
    (prop::collection::vec(color_in(mode), 1..5), prop::collection::vec(cell_choice(), width * height)).prop_map(
        move |(colors, choices)| {
            let cells = choices.into_iter().map(|c| pick_cell(&colors, c)).collect();
            (CellGrid { width, height, cells }, colors)
        },
    )
}

/// A first frame and a sequence of later frames, each a random set of cell changes to the one before.
fn frame_sequence(mode: ColorMode) -> impl Strategy<Value = Vec<CellGrid>> {
    (1usize..=14, 1usize..=6)
        .prop_flat_map(move |(w, h)| {
            let changes = prop::collection::vec((0..w * h, cell_choice(), any::<bool>()), 0..=w * h);
            (grid_in(mode, w, h), prop::collection::vec(changes, 1..4))
        })
        .prop_map(|((first, colors), steps)| {
            let mut frames = vec![first];
            for step in steps {
                let mut next = frames.last().cloned().unwrap_or_default();
                for (at, choice, blank) in step {
                    next.cells[at] = if blank { Cell::BLANK } else { pick_cell(&colors, choice) };
                }
                frames.push(next);
            }
            frames
        })
}

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig { cases, failure_persistence: None, ..ProptestConfig::default() }
}

/// Runs a frame sequence through one encoder and one emulator, checking the screen after every frame.
fn check_sequence(frames: &[CellGrid]) {
    let mut encoder = Encoder::new();
    let mut parser = terminal(frames[0].width, frames[0].height);
    let mut previous: Option<&CellGrid> = None;
    for frame in frames {
        let sent = encode_into(&mut encoder, &mut parser, frame);
        assert_screen_shows(&parser, frame);
        // Never worse than the naive frame, apart from the brackets, reset and clear.
        let overhead = SYNC_BEGIN.len() + SYNC_END.len() + 4 + CLEAR_SCREEN.len();
        assert!(sent <= naive_full_frame(frame).len() + overhead, "{sent} bytes for a frame");
        if previous == Some(frame) {
            assert_eq!(sent, 0, "an unchanged frame must encode to nothing");
        }
        // Sending the same frame again is always free.
        assert_eq!(encode_into(&mut encoder, &mut parser, frame), 0);
        previous = Some(frame);
    }
}

// ---------------------------------------------------------------------------------------------------------
// Properties.

proptest! {
    #![proptest_config(config(2500))]

    /// Frame 1 in full, then deltas: the screen equals each frame exactly (truecolor).
    #[test]
    fn deltas_reproduce_frames_truecolor(frames in frame_sequence(ColorMode::TrueColor)) {
        check_sequence(&frames);
    }

    /// Same, with 256-colour indices (0..=255).
    #[test]
    fn deltas_reproduce_frames_ansi256(frames in frame_sequence(ColorMode::Ansi256)) {
        check_sequence(&frames);
    }

    /// Same, with the 16 ANSI colours.
    #[test]
    fn deltas_reproduce_frames_ansi16(frames in frame_sequence(ColorMode::Ansi16)) {
        check_sequence(&frames);
    }

    /// Same, with no colours at all.
    #[test]
    fn deltas_reproduce_frames_no_color(frames in frame_sequence(ColorMode::None)) {
        check_sequence(&frames);
    }
}

proptest! {
    #![proptest_config(config(1000))]

    /// Within a tolerance, the screen shows exactly what the encoder says it shows, and each of its cells is
    /// within the tolerance of the frame's; then steps limited in bytes, each drawing at least one cell, reach
    /// the last frame exactly.
    #[test]
    fn tolerant_frames_then_limited_steps_end_exact(
        frames in frame_sequence(ColorMode::TrueColor),
        delta_e in 0.0f32..0.3,
        limit in 1usize..300,
    ) {
        let tolerance = Tolerance::new(delta_e);
        let mut encoder = Encoder::new();
        let mut parser = terminal(frames[0].width, frames[0].height);
        for frame in &frames {
            let mut bytes = Vec::new();
            encoder.encode_within(frame, tolerance, &mut bytes);
            assert_well_formed(&bytes);
            parser.process(&bytes);
            let shown = encoder.shown().expect("a frame was encoded").clone();
            assert_screen_shows(&parser, &shown);
            for (i, (shown, wanted)) in shown.cells.iter().zip(&frame.cells).enumerate() {
                prop_assert!(tolerance.accepts(shown, wanted), "cell {i}: {shown:?} for {wanted:?}");
            }
        }
        let last = frames.last().expect("at least one frame");
        // One cell, its cursor move and colours, and a frame's opening and closing bytes.
        let slack = 160;
        for step in 1..=last.cells.len() + 1 {
            let mut bytes = Vec::new();
            let complete = encoder.encode_limited(last, limit, &mut bytes);
            assert_well_formed(&bytes);
            prop_assert!(bytes.len() <= limit + slack, "{} bytes for a limit of {limit}", bytes.len());
            parser.process(&bytes);
            assert_screen_shows(&parser, encoder.shown().expect("shown"));
            if complete {
                assert_screen_shows(&parser, last);
                return Ok(());
            }
            prop_assert!(step <= last.cells.len(), "no progress after {step} steps");
        }
    }
}

proptest! {
    #![proptest_config(config(1000))]

    /// A resized frame (the emulator resized as the terminal would be) is a full redraw that shows the new
    /// frame exactly, and deltas after it work.
    #[test]
    fn resize_redraws_everything(
        (first, (second, colors)) in (
            prop::sample::select(MODES.to_vec()),
            (1usize..=14, 1usize..=6),
            (1usize..=14, 1usize..=6),
        )
            .prop_flat_map(|(mode, (w1, h1), (w2, h2))| (grid_in(mode, w1, h1).prop_map(|g| g.0), grid_in(mode, w2, h2))),
    ) {
        let ((w1, h1), (w2, h2)) = ((first.width, first.height), (second.width, second.height));
        let mut encoder = Encoder::new();
        let mut parser = terminal(w1, h1);
        encode_into(&mut encoder, &mut parser, &first);
        assert_screen_shows(&parser, &first);

        parser.set_size(dim(h2), dim(w2));
        let mut bytes = Vec::new();
        encoder.encode(&second, &mut bytes);
        assert_well_formed(&bytes);
        if (w1, h1) != (w2, h2) {
            let clear = [SYNC_BEGIN, b"\x1b[0m", CLEAR_SCREEN].concat();
            prop_assert!(bytes.starts_with(&clear), "a resize must clear the screen");
        }
        parser.process(&bytes);
        assert_screen_shows(&parser, &second);

        let mut third = second.clone();
        let last = third.cells.len() - 1;
        third.cells[last] = pick_cell(&colors, (1, 0, 1));
        third.cells[0] = Cell::BLANK;
        encode_into(&mut encoder, &mut parser, &third);
        assert_screen_shows(&parser, &third);
    }

    /// After `invalidate`, the next frame is a full redraw even when the grid did not change, and it repairs a
    /// screen that something else scribbled over.
    #[test]
    fn invalidate_forces_a_full_redraw(frames in frame_sequence(ColorMode::TrueColor)) {
        let frame = &frames[0];
        let mut encoder = Encoder::new();
        let mut parser = terminal(frame.width, frame.height);
        encode_into(&mut encoder, &mut parser, frame);
        parser.process(b"\x1b[H\x1b[31;44mgarbage that wraps around the screen and beyond its end, \x1b[1mbold\x1b[0m");
        encoder.invalidate();
        let mut bytes = Vec::new();
        encoder.encode(frame, &mut bytes);
        prop_assert!(bytes.windows(CLEAR_SCREEN.len()).any(|w| w == CLEAR_SCREEN));
        parser.process(&bytes);
        assert_screen_shows(&parser, frame);
    }

    /// The naive baseline also draws frames correctly (on a terminal in any state).
    #[test]
    fn naive_frame_reproduces_frames(frames in frame_sequence(ColorMode::Ansi256)) {
        let mut parser = terminal(frames[0].width, frames[0].height);
        for frame in &frames {
            let bytes = naive_full_frame(frame);
            assert!(!bytes.contains(&b'\n'));
            parser.process(&bytes);
            assert_screen_shows(&parser, frame);
        }
    }

    /// Pixels to cells to bytes to screen, in both cell modes and every colour mode, with odd heights.
    #[test]
    fn pixel_frames_end_to_end(
        mode in prop::sample::select(MODES.to_vec()),
        cell_mode in prop::sample::select(vec![CellMode::HalfBlock, CellMode::Ascii]),
        (w, h) in (1usize..=12, 1usize..=11),
        palette in prop::collection::vec(0u32..0x0100_0000, 1..5),
        picks in prop::collection::vec((any::<prop::sample::Index>(), any::<prop::sample::Index>()), 132),
        background in 0u32..0x0100_0000,
    ) {
        let first: Vec<u32> = picks.iter().take(w * h).map(|(i, _)| palette[i.index(palette.len())]).collect();
        let second: Vec<u32> = picks.iter().take(w * h).map(|(_, i)| palette[i.index(palette.len())]).collect();
        let mut encoder = Encoder::new();
        let (cols, rows) = cell_mode.grid_size(w, h);
        let mut parser = terminal(cols, rows);
        let mut grid = CellGrid::default();
        for pixels in [&first, &second] {
            cell_mode.fill_cells(&mut grid, PixelFrame::new(pixels, w, h), mode, background);
            prop_assert_eq!((grid.width, grid.height), (cols, rows));
            let mut bytes = Vec::new();
            encoder.encode(&grid, &mut bytes);
            assert_well_formed(&bytes);
            if mode == ColorMode::None {
                // No colour codes: the only SGR is the reset before the clear.
                let text = String::from_utf8(bytes.clone()).unwrap();
                prop_assert_eq!(text.matches('m').count(), text.matches("\x1b[0m").count());
            }
            parser.process(&bytes);
            assert_screen_shows(&parser, &grid);
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// Fixed cases.

/// Every character the encoder lets through is one column wide in the emulator, `▀` included, so cursor
/// tracking holds.
#[test]
fn every_safe_character_is_one_column_wide() {
    let safe: Vec<char> = (' '..='~').chain('\u{2500}'..='\u{259F}').chain('\u{2800}'..='\u{28FF}').collect();
    assert!(safe.iter().all(|&ch| Cell::is_safe_char(ch)));
    let width = 64;
    for chunk in safe.chunks(width) {
        let mut grid = CellGrid::filled(width, 1, Cell::new('x', Color::Indexed(1), Color::Default));
        for (cell, &ch) in grid.cells.iter_mut().zip(chunk) {
            cell.ch = ch;
        }
        let mut parser = terminal(width, 1);
        encode_into(&mut Encoder::new(), &mut parser, &grid);
        assert_screen_shows(&parser, &grid);
    }
}

/// Control characters in cells are replaced, so the emulator never sees them.
#[test]
fn control_characters_are_replaced() {
    let mut grid = CellGrid::blank(6, 2);
    for (cell, ch) in grid.cells.iter_mut().zip(['\x1b', '\n', '\r', '\x07', '\u{9b}', '中', '\u{301}']) {
        cell.ch = ch;
    }
    let mut parser = terminal(6, 2);
    encode_into(&mut Encoder::new(), &mut parser, &grid);
    assert_screen_shows(&parser, &grid);
    assert_eq!(parser.screen().cell(0, 0).unwrap().contents(), "?");
    assert_eq!(parser.screen().cursor_position().0, 1, "no line feed happened");
}

/// An unchanged frame appends nothing, also to a non-empty buffer, and also for an empty grid.
#[test]
fn unchanged_frames_append_zero_bytes() {
    let grid = CellGrid::filled(200, 60, Cell::new('▀', Color::Rgb(1, 2, 3), Color::Indexed(200)));
    let mut encoder = Encoder::new();
    let mut out = Vec::new();
    encoder.encode(&grid, &mut out);
    let after_first = out.len();
    assert!(after_first > 0);
    encoder.encode(&grid, &mut out);
    encoder.encode(&grid.clone(), &mut out);
    assert_eq!(out.len(), after_first);

    let empty = CellGrid::blank(0, 0);
    let mut encoder = Encoder::new();
    let mut out = Vec::new();
    encoder.encode(&empty, &mut out);
    assert!(!out.is_empty(), "the first frame clears the screen");
    out.clear();
    encoder.encode(&empty, &mut out);
    assert!(out.is_empty());
}

/// A frame where nothing but one cell changed costs a handful of bytes, far below the naive frame.
#[test]
fn small_changes_cost_few_bytes() {
    let mut grid = CellGrid::filled(200, 60, Cell::new('▀', Color::Rgb(10, 20, 30), Color::Rgb(40, 50, 60)));
    let mut encoder = Encoder::new();
    let mut parser = terminal(200, 60);
    encode_into(&mut encoder, &mut parser, &grid);
    grid.get_mut(30, 100).fg = Color::Rgb(255, 255, 255);
    let sent = encode_into(&mut encoder, &mut parser, &grid);
    assert_screen_shows(&parser, &grid);
    let expected = "\x1b[?2026h\x1b[31;101H\x1b[38;2;255;255;255;48;2;40;50;60m▀\x1b[0m\x1b[?2026l";
    assert_eq!(sent, expected.len());
    assert!(naive_full_frame(&grid).len() > 200 * 60 * 20);
}
