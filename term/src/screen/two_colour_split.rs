//! The best two colours for a cell of a few pixels: the split of its pixels into two groups, each shown in one
//! colour, with the least squared error in Oklab.
//!
//! With each group's colour its mean, the error of a split is `Σ|x|² - |S_a|²/n_a - |S_b|²/n_b` (`S` a group's
//! sum, `n` its size): the k-means objective for k = 2 (Lloyd, "Least squares quantization in PCM", 1982). A cell
//! has at most 8 pixels, so every split is tried (at most 128, visited in Gray-code order so that each step moves
//! one pixel): the result is the optimum, not the local one k-means iterations find.

use super::oklab::Oklab;

/// The most pixels a cell may have.
pub const MAX_CELL_PIXELS: usize = 8;

/// A cell's pixels split in two colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TwoColourSplit {
    /// Bit `i` set: pixel `i` shows `foreground`. Never holds more pixels than it leaves out, so the larger group
    /// is the background (ties: pixel 0 is in the background); 0 when the cell is one colour.
    pub pattern: u8,
    /// The colour of the pixels in `pattern`, `0x00RRGGBB` (equal to `background` when `pattern` is 0).
    pub foreground: u32,
    /// The colour of the other pixels.
    pub background: u32,
}

/// The split of `pixels` (`0x00RRGGBB`, at most [`MAX_CELL_PIXELS`]) with the least squared Oklab error.
///
/// A group whose pixels are all equal keeps that exact colour; otherwise its colour is its Oklab mean in 8-bit
/// sRGB. Among equally good splits the one-colour cell wins, then the first in Gray-code order.
///
/// # Panics
/// If `pixels` is empty or longer than [`MAX_CELL_PIXELS`].
pub fn split_two_colours(pixels: &[u32]) -> TwoColourSplit {
    assert!(
        (1..=MAX_CELL_PIXELS).contains(&pixels.len()),
        "a cell has 1 to {MAX_CELL_PIXELS} pixels, not {}",
        pixels.len()
    );
    let first = pixels[0];
    if pixels.iter().all(|&p| p == first) {
        return TwoColourSplit { pattern: 0, foreground: first, background: first };
    }
    let mut lab = [[0.0f32; 3]; MAX_CELL_PIXELS];
    for (to, &p) in lab.iter_mut().zip(pixels) {
        let [_, r, g, b] = p.to_be_bytes();
        let c = Oklab::from_srgb8(r, g, b);
        *to = [c.l, c.a, c.b];
    }
    let n = pixels.len();
    let total = lab[..n].iter().fold([0.0f32; 3], |s, c| add(s, *c));
    // Pixel 0 stays out of the moving group, so each split is visited once (its mirror image is the same split).
    let mut group = [0.0f32; 3];
    let mut group_len = 0usize;
    let mut pattern = 0u8;
    let mut best_pattern = 0u8;
    let mut best_score = norm_squared(total) / n as f32;
    for step in 1u32..(1 << (n - 1)) {
        let moved = step.trailing_zeros() as usize + 1;
        pattern ^= 1 << moved;
        if pattern & (1 << moved) != 0 {
            group = add(group, lab[moved]);
            group_len += 1;
        } else {
            group = sub(group, lab[moved]);
            group_len -= 1;
        }
        let rest = sub(total, group);
        let score = norm_squared(group) / group_len as f32 + norm_squared(rest) / (n - group_len) as f32;
        if score > best_score {
            best_score = score;
            best_pattern = pattern;
        }
    }
    if best_pattern == 0 {
        let colour = group_colour(pixels, &lab, u8::MAX);
        return TwoColourSplit { pattern: 0, foreground: colour, background: colour };
    }
    let mask = (u16::MAX >> (16 - n)) as u8;
    let foreground = if 2 * best_pattern.count_ones() as usize > n { mask & !best_pattern } else { best_pattern };
    TwoColourSplit {
        pattern: foreground,
        foreground: group_colour(pixels, &lab, foreground),
        background: group_colour(pixels, &lab, mask & !foreground),
    }
}

/// The colour of the pixels in `pattern`: their shared colour, or their Oklab mean.
fn group_colour(pixels: &[u32], lab: &[[f32; 3]; MAX_CELL_PIXELS], pattern: u8) -> u32 {
    let members = || (0..pixels.len()).filter(move |&i| pattern & (1 << i) != 0);
    let first = members().next().map_or(0, |i| pixels[i]);
    if members().all(|i| pixels[i] == first) {
        return first;
    }
    let (sum, len) = members().fold(([0.0f32; 3], 0u32), |(s, k), i| (add(s, lab[i]), k + 1));
    let mean = sum.map(|c| c / len as f32);
    Oklab { l: mean[0], a: mean[1], b: mean[2] }.to_srgb8()
}

fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn norm_squared(a: [f32; 3]) -> f32 {
    a[0] * a[0] + a[1] * a[1] + a[2] * a[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_colour_is_kept_exactly() {
        let split = split_two_colours(&[0x123456; 6]);
        assert_eq!(split, TwoColourSplit { pattern: 0, foreground: 0x123456, background: 0x123456 });
    }

    #[test]
    fn two_colours_split_exactly_with_the_smaller_group_in_front() {
        let (a, b) = (0xFF0000, 0x0000FF);
        let split = split_two_colours(&[a, a, b, a, a, b, a, a]);
        assert_eq!(split, TwoColourSplit { pattern: 0b0010_0100, foreground: b, background: a });
        let split = split_two_colours(&[b, a, a, a]);
        assert_eq!(split, TwoColourSplit { pattern: 0b0001, foreground: b, background: a });
    }

    #[test]
    fn the_odd_pixel_out_goes_to_its_own_group() {
        // Three near-whites and a black: black alone, the whites averaged.
        let split = split_two_colours(&[0xFEFEFE, 0xFCFCFC, 0x000000, 0xFEFEFE]);
        assert_eq!(split.pattern, 0b0100);
        assert_eq!(split.foreground, 0);
        assert!((0xFCFCFC..=0xFEFEFE).contains(&split.background), "{:06x}", split.background);
    }

    /// The squared Oklab error of showing the pixels in `pattern` and the others each in their group's mean.
    fn error_of(pixels: &[u32], pattern: u8) -> f32 {
        let lab: Vec<[f32; 3]> = pixels
            .iter()
            .map(|p| {
                let [_, r, g, b] = p.to_be_bytes();
                let c = Oklab::from_srgb8(r, g, b);
                [c.l, c.a, c.b]
            })
            .collect();
        [true, false]
            .iter()
            .map(|&inside| {
                let group: Vec<[f32; 3]> =
                    (0..pixels.len()).filter(|&i| (pattern & (1 << i) != 0) == inside).map(|i| lab[i]).collect();
                if group.is_empty() {
                    return 0.0;
                }
                let mean = group.iter().fold([0.0; 3], |s, c| add(s, *c)).map(|c| c / group.len() as f32);
                group.iter().map(|c| norm_squared(sub(*c, mean))).sum::<f32>()
            })
            .sum()
    }

    #[test]
    fn no_split_is_better_than_the_chosen_one() {
        // Cells of random pixels from small palettes and from the whole cube, every size up to 8.
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for case in 0..3000 {
            let n = 1 + case % MAX_CELL_PIXELS;
            let palette: Vec<u32> = (0..1 + case % 5).map(|_| next() as u32 & 0xFF_FFFF).collect();
            let pixels: Vec<u32> =
                (0..n)
                    .map(|_| {
                        if case % 2 == 0 { palette[next() as usize % palette.len()] } else { next() as u32 & 0xFF_FFFF }
                    })
                    .collect();
            let split = split_two_colours(&pixels);
            let chosen = error_of(&pixels, split.pattern);
            let best = (0..1u16 << n).map(|p| error_of(&pixels, p as u8)).fold(f32::INFINITY, f32::min);
            assert!(chosen <= best + 1e-5, "{pixels:06x?}: chosen {chosen}, best {best}");
            assert!(2 * split.pattern.count_ones() as usize <= n);
        }
    }
}
