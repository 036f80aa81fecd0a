//! The lookup-table quantisers against the exact nearest-colour search in Oklab.
//!
//! Figures: the share of colours where the table picks a different palette entry than the exact search,
//! and the excess Oklab distance (ΔE of the table's pick minus ΔE of the exact pick), mean over all colours
//! checked and maximum. The normal run checks a lattice of 86^3 colours (every channel value divisible
//! by 3, both ends included); the ignored test checks all 2^24 colours:
//! `cargo test -p rastty --release --test integration screen_palette:: -- --ignored --nocapture`.

use rastty::screen::oklab::Oklab;
use rastty::screen::palette::{nearest_ansi16_exact, nearest_xterm256_exact, oklab_distance_to_entry};
use rastty::screen::palette_lut::{nearest_ansi16, nearest_xterm256};

#[derive(Debug, Default)]
struct LutError {
    colours: u64,
    mismatches: u64,
    excess_sum: f64,
    excess_max: f32,
    worst: (u8, u8, u8),
}

impl LutError {
    fn add(&mut self, rgb: (u8, u8, u8), table: u8, exact: u8) {
        self.colours += 1;
        if table != exact {
            self.mismatches += 1;
            let excess = oklab_distance_to_entry(rgb, table) - oklab_distance_to_entry(rgb, exact);
            assert!(excess >= -1e-6, "the exact search lost to the table at {rgb:?}");
            self.excess_sum += f64::from(excess);
            if excess > self.excess_max {
                self.excess_max = excess;
                self.worst = rgb;
            }
        }
    }

    fn mismatch_share(&self) -> f64 {
        self.mismatches as f64 / self.colours as f64
    }

    fn mean_excess(&self) -> f64 {
        self.excess_sum / self.colours as f64
    }

    fn report(&self, name: &str) {
        println!(
            "{name}: {} colours, {:.3}% differ from the exact search, mean excess ΔE {:.6}, max excess ΔE {:.4} at {:?}",
            self.colours,
            100.0 * self.mismatch_share(),
            self.mean_excess(),
            self.excess_max,
            self.worst,
        );
    }
}

/// Compares both tables with the exact search on every colour whose channels are all in `values`.
fn measure(values: &[u8]) -> (LutError, LutError) {
    let (mut xterm, mut ansi) = (LutError::default(), LutError::default());
    for &r in values {
        for &g in values {
            for &b in values {
                let lab = Oklab::from_srgb8(r, g, b);
                xterm.add((r, g, b), nearest_xterm256(r, g, b), nearest_xterm256_exact(lab));
                ansi.add((r, g, b), nearest_ansi16(r, g, b), nearest_ansi16_exact(lab));
            }
        }
    }
    (xterm, ansi)
}

/// Bounds that hold for the full 2^24 measurement with some margin; a regression in the table layout
/// (resolution, level spacing, representatives) breaks them.
fn assert_within_bounds(xterm: &LutError, ansi: &LutError) {
    assert!(xterm.mismatch_share() < 0.09, "256-colour mismatch share {}", xterm.mismatch_share());
    assert!(xterm.mean_excess() < 0.0003, "256-colour mean excess {}", xterm.mean_excess());
    assert!(xterm.excess_max < 0.02, "256-colour max excess {} at {:?}", xterm.excess_max, xterm.worst);
    assert!(ansi.mismatch_share() < 0.03, "16-colour mismatch share {}", ansi.mismatch_share());
    assert!(ansi.mean_excess() < 0.0001, "16-colour mean excess {}", ansi.mean_excess());
    assert!(ansi.excess_max < 0.02, "16-colour max excess {} at {:?}", ansi.excess_max, ansi.worst);
}

#[test]
fn lookup_tables_stay_close_to_the_exact_search() {
    let values: Vec<u8> = (0..=255).step_by(3).collect();
    let (xterm, ansi) = measure(&values);
    xterm.report("256 colours, 86^3 lattice");
    ansi.report("16 colours, 86^3 lattice");
    assert_within_bounds(&xterm, &ansi);
}

#[test]
fn greys_and_primaries_quantise_sensibly() {
    assert_eq!(nearest_xterm256(0, 0, 0), 16);
    assert_eq!(nearest_xterm256(255, 255, 255), 231);
    assert_eq!(nearest_xterm256(255, 0, 0), 196);
    assert_eq!(nearest_xterm256(128, 128, 128), 244); // grey 128 is ramp entry 232 + 12
    for v in 0..=255u8 {
        let index = nearest_xterm256(v, v, v);
        let (r, g, b) = rastty::screen::palette::xterm256_rgb(index);
        assert!(r == g && g == b, "grey {v} became a tinted {index}");
    }
    assert_eq!(nearest_ansi16(0, 0, 0), 0);
    assert_eq!(nearest_ansi16(255, 255, 255), 15);
    assert_eq!(nearest_ansi16(0, 0, 255), 4);
}

#[test]
#[ignore = "all 2^24 colours: run in release with --ignored --nocapture to print the figures"]
fn lookup_tables_against_the_exact_search_for_every_colour() {
    let values: Vec<u8> = (0..=255).collect();
    let (xterm, ansi) = measure(&values);
    xterm.report("256 colours, all 2^24");
    ansi.report("16 colours, all 2^24");
    assert_within_bounds(&xterm, &ansi);
}
