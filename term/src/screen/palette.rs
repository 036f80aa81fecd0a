//! The terminal palettes assumed for the 256- and 16-colour modes, and exact nearest-colour search over them.
//!
//! Distances are measured in Oklab (see [`super::oklab`]). The exact search is the reference that the
//! lookup tables in [`super::palette_lut`] are built from and tested against.

use std::sync::OnceLock;

use super::oklab::Oklab;

/// The six channel levels of the xterm 6x6x6 colour cube (indices 16..=231).
pub const CUBE_LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];

/// The RGB values assumed for the 16 ANSI colours: xterm's defaults (`XTerm*color0..15`).
///
/// Real terminals let the user theme these, so 16-colour output can only ever be approximate.
pub const ANSI16_RGB: [(u8, u8, u8); 16] = [
    (0, 0, 0),       // 0 black
    (205, 0, 0),     // 1 red
    (0, 205, 0),     // 2 green
    (205, 205, 0),   // 3 yellow
    (0, 0, 238),     // 4 blue
    (205, 0, 205),   // 5 magenta
    (0, 205, 205),   // 6 cyan
    (229, 229, 229), // 7 white
    (127, 127, 127), // 8 bright black
    (255, 0, 0),     // 9 bright red
    (0, 255, 0),     // 10 bright green
    (255, 255, 0),   // 11 bright yellow
    (92, 92, 255),   // 12 bright blue
    (255, 0, 255),   // 13 bright magenta
    (0, 255, 255),   // 14 bright cyan
    (255, 255, 255), // 15 bright white
];

/// The RGB value of xterm palette entry `index` in 16..=255 (cube or grey ramp); 0..=15 give [`ANSI16_RGB`].
pub const fn xterm256_rgb(index: u8) -> (u8, u8, u8) {
    match index {
        0..=15 => ANSI16_RGB[index as usize],
        16..=231 => {
            let i = index - 16;
            (CUBE_LEVELS[(i / 36) as usize], CUBE_LEVELS[((i / 6) % 6) as usize], CUBE_LEVELS[(i % 6) as usize])
        }
        232..=255 => {
            let v = 8 + 10 * (index - 232);
            (v, v, v)
        }
    }
}

/// Palette entries 16..=255 in Oklab, in index order (entry `i` is palette index `16 + i`).
fn xterm240_oklab() -> &'static [Oklab; 240] {
    static TABLE: OnceLock<[Oklab; 240]> = OnceLock::new();
    TABLE.get_or_init(|| {
        std::array::from_fn(|i| {
            let (r, g, b) = xterm256_rgb(16 + i as u8);
            Oklab::from_srgb8(r, g, b)
        })
    })
}

/// The 16 ANSI colours in Oklab.
fn ansi16_oklab() -> &'static [Oklab; 16] {
    static TABLE: OnceLock<[Oklab; 16]> = OnceLock::new();
    TABLE.get_or_init(|| {
        std::array::from_fn(|i| {
            let (r, g, b) = ANSI16_RGB[i];
            Oklab::from_srgb8(r, g, b)
        })
    })
}

/// Palette entries (Oklab, index) sorted by lightness, for [`nearest_by_lightness`].
fn by_lightness(entries: impl Iterator<Item = (Oklab, u8)>) -> Vec<(Oklab, u8)> {
    let mut sorted: Vec<(Oklab, u8)> = entries.collect();
    sorted.sort_by(|a, b| a.0.l.total_cmp(&b.0.l).then(a.1.cmp(&b.1)));
    sorted
}

/// The same answer as the exhaustive search (lowest index on ties), found faster: candidates are visited in
/// order of lightness difference from `target`, and the search stops once that difference alone is larger
/// than the best distance so far.
fn nearest_by_lightness(sorted: &[(Oklab, u8)], target: Oklab) -> u8 {
    let start = sorted.partition_point(|(c, _)| c.l < target.l);
    let (mut below, mut above) = (start, start);
    let (mut best_distance, mut best) = (f32::INFINITY, u8::MAX);
    loop {
        let down = below.checked_sub(1).map(|i| (i, target.l - sorted[i].0.l));
        let up = sorted.get(above).map(|(c, _)| (above, c.l - target.l));
        let (i, gap) = match (down, up) {
            (None, None) => break,
            (Some(d), None) => d,
            (None, Some(u)) => u,
            (Some(d), Some(u)) => {
                if d.1 <= u.1 {
                    d
                } else {
                    u
                }
            }
        };
        if gap * gap > best_distance {
            break;
        }
        let (candidate, index) = sorted[i];
        let distance = candidate.distance_squared(target);
        if distance < best_distance || (distance == best_distance && index < best) {
            (best_distance, best) = (distance, index);
        }
        if i == above {
            above += 1;
        } else {
            below -= 1;
        }
    }
    if best_distance.is_finite() {
        best
    } else {
        // Only for a NaN target: answer like the exhaustive search, with the lowest index.
        sorted.iter().map(|&(_, index)| index).min().unwrap_or(0)
    }
}

/// [`nearest_xterm256_exact`], found faster by a lightness-pruned search (used to fill lookup tables).
pub fn nearest_xterm256_pruned(color: Oklab) -> u8 {
    static SORTED: OnceLock<Vec<(Oklab, u8)>> = OnceLock::new();
    let sorted = SORTED.get_or_init(|| by_lightness(xterm240_oklab().iter().zip(16..=255).map(|(&c, i)| (c, i))));
    nearest_by_lightness(sorted, color)
}

/// [`nearest_ansi16_exact`], found faster by a lightness-pruned search (used to fill lookup tables).
pub fn nearest_ansi16_pruned(color: Oklab) -> u8 {
    static SORTED: OnceLock<Vec<(Oklab, u8)>> = OnceLock::new();
    let sorted = SORTED.get_or_init(|| by_lightness(ansi16_oklab().iter().zip(0..16).map(|(&c, i)| (c, i))));
    nearest_by_lightness(sorted, color)
}

/// Position of the entry of `candidates` nearest to `target` (the first one on ties).
#[inline]
fn nearest_index(candidates: &[Oklab], target: Oklab) -> usize {
    let mut best = 0;
    let mut best_distance = f32::INFINITY;
    for (i, candidate) in candidates.iter().enumerate() {
        let distance = candidate.distance_squared(target);
        if distance < best_distance {
            best = i;
            best_distance = distance;
        }
    }
    best
}

/// The 256-colour palette index (16..=255: cube or grey ramp) nearest to `color` in Oklab, by exhaustive search.
///
/// Indices 0..=15 are never returned: their RGB values differ between terminal themes.
pub fn nearest_xterm256_exact(color: Oklab) -> u8 {
    16 + nearest_index(xterm240_oklab(), color) as u8
}

/// The ANSI colour index (0..=15) nearest to `color` in Oklab, by exhaustive search over [`ANSI16_RGB`].
pub fn nearest_ansi16_exact(color: Oklab) -> u8 {
    nearest_index(ansi16_oklab(), color) as u8
}

/// Oklab distance (ΔE, not squared) between an sRGB colour and the palette entry `index`.
pub fn oklab_distance_to_entry(rgb: (u8, u8, u8), index: u8) -> f32 {
    let (r, g, b) = xterm256_rgb(index);
    Oklab::from_srgb8(rgb.0, rgb.1, rgb.2).distance_squared(Oklab::from_srgb8(r, g, b)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_and_grey_ramp_follow_the_xterm_formulas() {
        assert_eq!(xterm256_rgb(16), (0, 0, 0));
        assert_eq!(xterm256_rgb(21), (0, 0, 255));
        assert_eq!(xterm256_rgb(196), (255, 0, 0));
        assert_eq!(xterm256_rgb(231), (255, 255, 255));
        assert_eq!(xterm256_rgb(232), (8, 8, 8));
        assert_eq!(xterm256_rgb(255), (238, 238, 238));
        assert_eq!(xterm256_rgb(9), (255, 0, 0));
    }

    #[test]
    fn palette_colours_map_to_themselves() {
        for index in 16..=255u8 {
            let (r, g, b) = xterm256_rgb(index);
            let found = nearest_xterm256_exact(Oklab::from_srgb8(r, g, b));
            // Cube black (16) and white (231) have no duplicates, so every entry is its own nearest.
            assert_eq!(found, index);
        }
        for (index, &(r, g, b)) in ANSI16_RGB.iter().enumerate() {
            assert_eq!(nearest_ansi16_exact(Oklab::from_srgb8(r, g, b)) as usize, index);
        }
    }

    #[test]
    fn pruned_search_agrees_with_the_exhaustive_one() {
        for r in (0..=255u8).step_by(15) {
            for g in (0..=255u8).step_by(5) {
                for b in (0..=255u8).step_by(15) {
                    let lab = Oklab::from_srgb8(r, g, b);
                    assert_eq!(nearest_xterm256_pruned(lab), nearest_xterm256_exact(lab), "{:?}", (r, g, b));
                    assert_eq!(nearest_ansi16_pruned(lab), nearest_ansi16_exact(lab), "{:?}", (r, g, b));
                }
            }
        }
    }

    #[test]
    fn nan_gets_the_same_answer_from_both_searches() {
        let nan = Oklab { l: f32::NAN, a: 0.0, b: 0.0 };
        assert_eq!(nearest_xterm256_pruned(nan), nearest_xterm256_exact(nan));
        assert_eq!(nearest_ansi16_pruned(nan), nearest_ansi16_exact(nan));
    }

    #[test]
    fn greys_prefer_the_grey_ramp_between_cube_levels() {
        // 50 lies between cube levels 0 and 95; the ramp has 48.
        assert_eq!(nearest_xterm256_exact(Oklab::from_srgb8(50, 50, 50)), 232 + 4);
    }
}
