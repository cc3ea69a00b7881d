//! Label grids: the raster on which rooms grow.
//!
//! Cell `(x, y)` is column `x`, row `y`; row 0 is the *bottom* row so that grid and plan share the
//! y-up convention. Storage is row-major: `index = y * w + x`.

use serde::{Deserialize, Serialize};

/// A room index on a floor (position in the solver's room list), or one of the two markers below.
pub type Label = u16;
/// Not part of the free region (outside the footprint, or in a courtyard).
pub const OUTSIDE: Label = u16::MAX;
/// Free but not yet given to any room.
pub const EMPTY: Label = u16::MAX - 1;
/// Largest usable room label.
pub const MAX_ROOMS: usize = (u16::MAX - 2) as usize;

/// Where a grid sits in the plan: cell `(x, y)` covers
/// `[origin.x + x*cell, origin.x + (x+1)*cell] × [origin.y + y*cell, origin.y + (y+1)*cell]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GridFrame {
    pub origin: [f64; 2],
    pub cell: f64,
    pub w: usize,
    pub h: usize,
}

impl GridFrame {
    /// Centre of cell `(x, y)` in metres.
    pub fn centre(&self, x: usize, y: usize) -> [f64; 2] {
        [
            self.origin[0] + (x as f64 + 0.5) * self.cell,
            self.origin[1] + (y as f64 + 0.5) * self.cell,
        ]
    }

    /// Plan point (metres) to continuous grid coordinates (cell units, cell centres at `.5`).
    pub fn to_grid(&self, p: [f64; 2]) -> [f64; 2] {
        [
            (p[0] - self.origin[0]) / self.cell,
            (p[1] - self.origin[1]) / self.cell,
        ]
    }

    /// Continuous grid coordinates back to metres.
    pub fn to_plan(&self, g: [f64; 2]) -> [f64; 2] {
        [
            self.origin[0] + g[0] * self.cell,
            self.origin[1] + g[1] * self.cell,
        ]
    }

    /// Grid vertex `(i, j)` (a cell corner) in metres.
    pub fn vertex(&self, i: i64, j: i64) -> [f64; 2] {
        [
            self.origin[0] + i as f64 * self.cell,
            self.origin[1] + j as f64 * self.cell,
        ]
    }
}

/// A dense label grid.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grid {
    pub w: usize,
    pub h: usize,
    pub cells: Vec<Label>,
}

impl Grid {
    pub fn new(w: usize, h: usize, fill: Label) -> Self {
        Grid {
            w,
            h,
            cells: vec![fill; w * h],
        }
    }

    #[inline]
    pub fn idx(&self, x: usize, y: usize) -> usize {
        y * self.w + x
    }

    #[inline]
    pub fn get(&self, x: usize, y: usize) -> Label {
        self.cells[y * self.w + x]
    }

    #[inline]
    pub fn set(&mut self, x: usize, y: usize, l: Label) {
        let i = y * self.w + x;
        self.cells[i] = l;
    }

    /// Label at signed coordinates; anything off the grid reads as [`OUTSIDE`].
    #[inline]
    pub fn get_or_outside(&self, x: i64, y: i64) -> Label {
        if x < 0 || y < 0 || x >= self.w as i64 || y >= self.h as i64 {
            OUTSIDE
        } else {
            self.cells[y as usize * self.w + x as usize]
        }
    }

    /// Number of cells carrying `l`.
    pub fn count(&self, l: Label) -> usize {
        self.cells.iter().filter(|&&c| c == l).count()
    }
}

/// Fixed (load-bearing) walls as blocked cell edges.
///
/// `v[y * (w + 1) + x]` is the vertical edge on the left of cell `(x, y)` (between columns `x - 1`
/// and `x`); `h[y * w + x]` is the horizontal edge below cell `(x, y)` (between rows `y - 1` and
/// `y`). No room may own the cells on both sides of a blocked edge.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Walls {
    pub w: usize,
    pub h: usize,
    pub v: Vec<bool>,
    pub hz: Vec<bool>,
    /// Whether any edge is blocked at all, so that wall-free floors skip every wall test.
    pub any: bool,
}

impl Walls {
    pub fn none(w: usize, h: usize) -> Self {
        Walls {
            w,
            h,
            v: vec![false; (w + 1) * h],
            hz: vec![false; w * (h + 1)],
            any: false,
        }
    }

    /// Is the edge between cell `a` and its 4-neighbour `b` (flat indices on a `w`-wide grid)
    /// blocked? `a` and `b` must be 4-neighbours.
    #[inline]
    pub fn blocked(&self, a: usize, b: usize) -> bool {
        if !self.any {
            return false;
        }
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        if hi == lo + 1 {
            // horizontal neighbours: the vertical edge left of `hi`
            let (x, y) = (hi % self.w, hi / self.w);
            self.v[y * (self.w + 1) + x]
        } else {
            // vertical neighbours: the horizontal edge below `hi`
            self.hz[hi]
        }
    }

    pub fn block_vertical(&mut self, x: usize, y: usize) {
        self.v[y * (self.w + 1) + x] = true;
        self.any = true;
    }

    pub fn block_horizontal(&mut self, x: usize, y: usize) {
        self.hz[y * self.w + x] = true;
        self.any = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_round_trips_points() {
        let f = GridFrame {
            origin: [1.0, -2.0],
            cell: 0.5,
            w: 4,
            h: 3,
        };
        assert_eq!(f.centre(0, 0), [1.25, -1.75]);
        let g = f.to_grid([2.0, -1.0]);
        assert_eq!(g, [2.0, 2.0]);
        assert_eq!(f.to_plan(g), [2.0, -1.0]);
    }

    #[test]
    fn walls_block_both_directions() {
        let mut w = Walls::none(3, 2);
        w.block_vertical(1, 0); // between (0,0) and (1,0)
        w.block_horizontal(2, 1); // between (2,0) and (2,1)
        assert!(w.blocked(0, 1) && w.blocked(1, 0));
        assert!(w.blocked(2, 5) && w.blocked(5, 2));
        assert!(!w.blocked(1, 2));
        assert!(!w.blocked(0, 3));
    }

    #[test]
    fn off_grid_reads_outside() {
        let g = Grid::new(2, 2, EMPTY);
        assert_eq!(g.get_or_outside(-1, 0), OUTSIDE);
        assert_eq!(g.get_or_outside(1, 1), EMPTY);
        assert_eq!(g.get_or_outside(2, 1), OUTSIDE);
    }
}
