//! The uniform grid of the shallow-water solver: nx × ny cells of Δx × Δy [m] from the corner
//! `origin` [m], stored with [`GHOST`] layers of ghost cells on every side, row after row (x
//! fastest). Cell (i, j) of the domain, 0 ≤ i < nx and 0 ≤ j < ny, has its centre at
//! x = x₀ + (i + ½) Δx, y = y₀ + (j + ½) Δy; ghost cells have i or j in −2, −1 or nx, nx + 1.

use serde::{Deserialize, Serialize};

/// Ghost layers on each side: the limited slope of the first ghost cell needs the second.
pub const GHOST: usize = 2;

/// A uniform 2D grid.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Grid {
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// Cell size along x [m].
    pub dx: f64,
    /// Cell size along y [m].
    pub dy: f64,
    /// Lower-left corner of the domain [m].
    pub origin: [f64; 2],
}

impl Grid {
    /// A grid of `cells` over the rectangle `min` to `max` [m].
    pub fn new(cells: [usize; 2], min: [f64; 2], max: [f64; 2]) -> Grid {
        Grid {
            nx: cells[0],
            ny: cells[1],
            dx: (max[0] - min[0]) / cells[0] as f64,
            dy: (max[1] - min[1]) / cells[1] as f64,
            origin: min,
        }
    }

    /// Cells of the domain (ghosts not counted).
    pub fn cells(&self) -> usize {
        self.nx * self.ny
    }

    /// Entries of one stored row (ghosts included).
    pub fn stride(&self) -> usize {
        self.nx + 2 * GHOST
    }

    /// Entries of a stored field (ghosts included).
    pub fn len(&self) -> usize {
        self.stride() * (self.ny + 2 * GHOST)
    }

    /// Whether the grid has no cells.
    pub fn is_empty(&self) -> bool {
        self.cells() == 0
    }

    /// Storage index of cell (i, j); ghosts have i or j in −2..0 or n..n + 2.
    pub fn index(&self, i: isize, j: isize) -> usize {
        let g = GHOST as isize;
        ((j + g) as usize) * self.stride() + (i + g) as usize
    }

    /// Storage index of domain cell (i, j).
    pub fn at(&self, i: usize, j: usize) -> usize {
        (j + GHOST) * self.stride() + i + GHOST
    }

    /// Centre of cell (i, j) [m] (ghosts too).
    pub fn centre(&self, i: isize, j: isize) -> [f64; 2] {
        [
            self.origin[0] + (i as f64 + 0.5) * self.dx,
            self.origin[1] + (j as f64 + 0.5) * self.dy,
        ]
    }

    /// Upper-right corner of the domain [m].
    pub fn max(&self) -> [f64; 2] {
        [
            self.origin[0] + self.nx as f64 * self.dx,
            self.origin[1] + self.ny as f64 * self.dy,
        ]
    }

    /// The domain cell holding the point (x, y) [m], if it is inside.
    pub fn cell_of(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let fi = (x - self.origin[0]) / self.dx;
        let fj = (y - self.origin[1]) / self.dy;
        if !(fi >= 0.0 && fj >= 0.0) {
            return None;
        }
        let (i, j) = (fi as usize, fj as usize);
        (i < self.nx && j < self.ny).then_some((i, j))
    }

    /// A field of the domain's cells (x fastest, no ghosts) from a stored one.
    pub fn interior<T: Copy>(&self, field: &[T]) -> Vec<T> {
        let mut out = Vec::with_capacity(self.cells());
        for j in 0..self.ny {
            let k = self.at(0, j);
            out.extend_from_slice(&field[k..k + self.nx]);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_centres_and_cells_agree() {
        let g = Grid::new([4, 3], [10.0, -1.0], [12.0, 0.5]);
        assert_eq!((g.dx, g.dy), (0.5, 0.5));
        assert_eq!(g.len(), 8 * 7);
        assert_eq!(g.index(-2, -2), 0);
        assert_eq!(g.at(0, 0), g.index(0, 0));
        assert_eq!(g.at(3, 2), 4 * 8 + 5);
        assert_eq!(g.centre(0, 0), [10.25, -0.75]);
        assert_eq!(g.cell_of(11.9, 0.4), Some((3, 2)));
        assert_eq!(g.cell_of(12.1, 0.4), None);
        assert_eq!(g.cell_of(9.99, 0.0), None);
        let field: Vec<usize> = (0..g.len()).collect();
        let inner = g.interior(&field);
        assert_eq!(inner.len(), 12);
        assert_eq!(inner[0], g.at(0, 0));
        assert_eq!(inner[11], g.at(3, 2));
    }
}
