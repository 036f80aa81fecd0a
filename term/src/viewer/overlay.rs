//! Text drawn over the picture: the HUD, the key help, and the notice for a terminal too small to draw in.
//!
//! Every character drawn here is checked by [`Cell::is_safe_char`]; anything else (including whatever a model
//! file's name holds) becomes `?`.

use rastty::screen::{Cell, CellGrid, Color};

const TEXT: Color = Color::Rgb(235, 235, 235);
const PANEL: Color = Color::Rgb(30, 34, 44);

/// Writes `text` at (`row`, `col`) on the panel colour, clipped to the grid.
pub fn put_text(grid: &mut CellGrid, row: usize, col: usize, text: &str) {
    if row >= grid.height {
        return;
    }
    for (i, ch) in text.chars().enumerate() {
        let c = col + i;
        if c >= grid.width {
            break;
        }
        let ch = if Cell::is_safe_char(ch) && ch != '\0' { ch } else { '?' };
        *grid.get_mut(row, c) = Cell::new(ch, TEXT, PANEL);
    }
}

/// Draws lines of text in a box at the top-left corner.
pub fn draw_hud(grid: &mut CellGrid, lines: &[String]) {
    let width = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0) + 2;
    for (row, line) in lines.iter().enumerate() {
        put_text(grid, row, 0, &format!(" {line:<w$} ", w = width - 2));
    }
}

/// Draws lines of text in a box in the middle of the grid.
pub fn draw_centered_box(grid: &mut CellGrid, lines: &[&str]) {
    let inner = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    let (width, height) = (inner + 4, lines.len() + 2);
    let top = grid.height.saturating_sub(height) / 2;
    let left = grid.width.saturating_sub(width) / 2;
    put_text(grid, top, left, &" ".repeat(width));
    for (i, line) in lines.iter().enumerate() {
        put_text(grid, top + 1 + i, left, &format!("  {line:<inner$}  "));
    }
    put_text(grid, top + height - 1, left, &" ".repeat(width));
}

/// The whole grid as a short notice (for a terminal too small to draw in), wrapped at spaces to the width and
/// centred; words longer than the width are cut.
pub fn notice(width: usize, height: usize, text: &str) -> CellGrid {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.chars().take(width).collect()),
        }
    }
    let mut grid = CellGrid::blank(width, height);
    let top = height.saturating_sub(lines.len()) / 2;
    for (i, line) in lines.iter().take(height).enumerate() {
        put_text(&mut grid, top + i, width.saturating_sub(line.chars().count()) / 2, line);
    }
    grid
}
