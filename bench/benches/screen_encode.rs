//! Frame-encoder timing for a 200x60-cell terminal (a 200x120-pixel half-block frame).
//!
//! `cargo bench -p rastty-bench --bench screen_encode`. Before the timings it prints the byte counts of the
//! benchmarked frames next to the naive full frame, and how long the 256-colour lookup table took to build.

use std::hint::black_box;
use std::time::Instant;

use rastty::screen::palette_lut::{nearest_ansi16, nearest_xterm256};
use rastty::screen::{CellGrid, CellMode, ColorMode, Encoder, PixelFrame, naive_full_frame};

const COLS: usize = 200;
const ROWS: usize = 60;
/// Share of cells that change between the two benchmarked frames.
const CHANGED: f64 = 0.3;

const MODES: [ColorMode; 4] = [ColorMode::TrueColor, ColorMode::Ansi256, ColorMode::Ansi16, ColorMode::None];

/// A small deterministic generator (SplitMix64), so every run benchmarks the same frames.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// A shaded-looking frame: a dark background with a smooth colour gradient in a disc.
fn scene_pixels() -> Vec<u32> {
    let (width, height) = CellMode::HalfBlock.pixel_size(COLS, ROWS);
    let mut pixels = vec![0x0010_1018; width * height];
    for y in 0..height {
        for x in 0..width {
            let (dx, dy) = (x as f32 - width as f32 / 2.0, (y as f32 - height as f32 / 2.0) * 2.0);
            if dx * dx + dy * dy < (height as f32 * 0.9).powi(2) {
                let r = (x * 255 / width) as u32;
                let g = (y * 255 / height) as u32;
                let b = 255 - r / 2;
                pixels[y * width + x] = (r << 16) | (g << 8) | b;
            }
        }
    }
    pixels
}

/// The frame pair: the scene, and the scene with `CHANGED` of its cells' pixels replaced by other colours.
fn frames(mode: ColorMode) -> (CellGrid, CellGrid) {
    let (width, height) = CellMode::HalfBlock.pixel_size(COLS, ROWS);
    let before = scene_pixels();
    let mut after = before.clone();
    let mut rng = SplitMix(0x5EED);
    for col in 0..COLS {
        for row in 0..ROWS {
            if (rng.next() % 1000) as f64 / 1000.0 < CHANGED {
                for y in [2 * row, 2 * row + 1] {
                    after[y * width + col] = (rng.next() & 0x00FF_FFFF) as u32;
                }
            }
        }
    }
    let grid = |pixels: &[u32]| CellMode::HalfBlock.to_cells(PixelFrame::new(pixels, width, height), mode, 0);
    (grid(&before), grid(&after))
}

/// An encoder that has just sent `shown`.
fn encoder_showing(shown: &CellGrid) -> Encoder {
    let mut encoder = Encoder::new();
    encoder.encode(shown, &mut Vec::new());
    encoder
}

/// Encoding the 30%-changed frame as a delta.
#[divan::bench(args = MODES)]
fn encode_delta_30_percent(bencher: divan::Bencher, mode: ColorMode) {
    let (before, after) = frames(mode);
    let primed = encoder_showing(&before);
    bencher
        .with_inputs(|| (primed.clone(), Vec::with_capacity(256 * 1024)))
        .bench_local_refs(|(encoder, out)| encoder.encode(black_box(&after), out));
}

/// Encoding the first frame (full redraw).
#[divan::bench(args = MODES)]
fn encode_full_redraw(bencher: divan::Bencher, mode: ColorMode) {
    let (frame, _) = frames(mode);
    bencher
        .with_inputs(|| (Encoder::new(), Vec::with_capacity(512 * 1024)))
        .bench_local_refs(|(encoder, out)| encoder.encode(black_box(&frame), out));
}

/// Pixels to half-block cells (200x120 pixels).
#[divan::bench(args = MODES)]
fn half_block_cells(bencher: divan::Bencher, mode: ColorMode) {
    let (width, height) = CellMode::HalfBlock.pixel_size(COLS, ROWS);
    let pixels = scene_pixels();
    let mut grid = CellGrid::default();
    bencher.bench_local(|| {
        CellMode::HalfBlock.fill_cells(&mut grid, PixelFrame::new(black_box(&pixels), width, height), mode, 0)
    });
}

fn main() {
    let started = Instant::now();
    black_box(nearest_xterm256(1, 2, 3));
    let xterm_build = started.elapsed();
    let started = Instant::now();
    black_box(nearest_ansi16(1, 2, 3));
    println!("lookup tables built in {xterm_build:?} (256 colours) and {:?} (16 colours)", started.elapsed());
    for mode in MODES {
        let (before, after) = frames(mode);
        let changed = before.cells.iter().zip(&after.cells).filter(|(a, b)| a != b).count();
        let mut encoder = Encoder::new();
        let (mut full, mut delta) = (Vec::new(), Vec::new());
        encoder.encode(&before, &mut full);
        encoder.encode(&after, &mut delta);
        println!(
            "{mode:>9}: first frame {} bytes, {changed} cells changed -> delta {} bytes; naive full frame {} bytes",
            full.len(),
            delta.len(),
            naive_full_frame(&after).len(),
        );
    }
    divan::main();
}
