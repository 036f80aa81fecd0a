//! A rectangle of terminal cells: one frame as the terminal should show it.

use super::cell::Cell;

/// A `width` x `height` grid of cells, row-major, row 0 at the top.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CellGrid {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// `width * height` cells, row-major.
    pub cells: Vec<Cell>,
}

impl CellGrid {
    /// A grid filled with `cell`.
    pub fn filled(width: usize, height: usize, cell: Cell) -> Self {
        CellGrid { width, height, cells: vec![cell; width * height] }
    }

    /// A grid of [`Cell::BLANK`].
    pub fn blank(width: usize, height: usize) -> Self {
        Self::filled(width, height, Cell::BLANK)
    }

    /// Resizes to `width` x `height` and fills every cell with `cell`, reusing the allocation.
    pub fn reset(&mut self, width: usize, height: usize, cell: Cell) {
        self.width = width;
        self.height = height;
        self.cells.clear();
        self.cells.resize(width * height, cell);
    }

    /// Sets the cells of the top-left `columns` x `rows` (at most the grid) to `cell`.
    pub fn fill(&mut self, columns: usize, rows: usize, cell: Cell) {
        let columns = columns.min(self.width);
        for row in self.cells.chunks_exact_mut(self.width.max(1)).take(rows) {
            row[..columns].fill(cell);
        }
    }

    /// Whether the grid has `width` x `height` cells.
    pub fn same_size(&self, other: &CellGrid) -> bool {
        self.width == other.width && self.height == other.height
    }

    /// The cell at `row`, `col`.
    ///
    /// # Panics
    /// If the position is outside the grid.
    pub fn get(&self, row: usize, col: usize) -> &Cell {
        assert!(row < self.height && col < self.width, "cell ({row}, {col}) outside {}x{}", self.width, self.height);
        &self.cells[row * self.width + col]
    }

    /// The cell at `row`, `col`, mutably.
    ///
    /// # Panics
    /// If the position is outside the grid.
    pub fn get_mut(&mut self, row: usize, col: usize) -> &mut Cell {
        assert!(row < self.height && col < self.width, "cell ({row}, {col}) outside {}x{}", self.width, self.height);
        &mut self.cells[row * self.width + col]
    }

    /// The cells of row `row`.
    ///
    /// # Panics
    /// If `row >= height`.
    pub fn row(&self, row: usize) -> &[Cell] {
        assert!(row < self.height, "row {row} outside height {}", self.height);
        &self.cells[row * self.width..(row + 1) * self.width]
    }

    /// Iterates over the rows, top to bottom (nothing when `width` is 0).
    pub fn rows(&self) -> impl Iterator<Item = &[Cell]> {
        self.cells.chunks_exact(self.width.max(1)).take(if self.width == 0 { 0 } else { self.height })
    }
}
