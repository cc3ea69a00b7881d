//! The parent region of a cut round, precomputed once per round and shared by every candidate.

use crate::grid::{Grid, Label};

/// The cells being cut in one round.
///
/// Solver grids carry a ring of `OUTSIDE` cells around their border, so every region cell has four
/// in-bounds neighbours at `i ± 1` and `i ± w`; the hot loops rely on that instead of bounds checks.
#[derive(Debug, Clone)]
pub struct Region {
    pub w: usize,
    pub h: usize,
    /// Flat indices of the region's cells, ascending.
    pub cells: Vec<u32>,
    /// `inside[i]` is true for region cells.
    pub inside: Vec<bool>,
    /// Bounding box of the region, inclusive: `(x0, y0, x1, y1)`.
    pub bbox: (usize, usize, usize, usize),
}

impl Region {
    /// The cells of `grid` labelled `label`.
    ///
    /// # Panics
    /// If a region cell lies on the grid border (solver grids are padded, so this is a bug).
    pub fn of_label(grid: &Grid, label: Label) -> Region {
        let (w, h) = (grid.w, grid.h);
        let mut inside = vec![false; w * h];
        let mut cells = Vec::new();
        let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
        for (i, &l) in grid.cells.iter().enumerate() {
            if l == label {
                let (x, y) = (i % w, i / w);
                assert!(
                    x > 0 && y > 0 && x + 1 < w && y + 1 < h,
                    "solver grids must be padded with an OUTSIDE ring"
                );
                inside[i] = true;
                cells.push(i as u32);
                x0 = x0.min(x);
                y0 = y0.min(y);
                x1 = x1.max(x);
                y1 = y1.max(y);
            }
        }
        Region {
            w,
            h,
            cells,
            inside,
            bbox: (x0, y0, x1, y1),
        }
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// The bounding box `(x0, y0, x1, y1)` (inclusive) and the cell count of the region's cells
    /// that `grid` labels `label` in a candidate, or None when it has none.
    pub fn label_box(
        &self,
        grid: &Grid,
        label: Label,
    ) -> Option<((usize, usize, usize, usize), usize)> {
        let (mut x0, mut y0, mut x1, mut y1, mut n) = (usize::MAX, usize::MAX, 0, 0, 0usize);
        for &c in &self.cells {
            let c = c as usize;
            if grid.cells[c] == label {
                let (x, y) = (c % grid.w, c / grid.w);
                x0 = x0.min(x);
                y0 = y0.min(y);
                x1 = x1.max(x);
                y1 = y1.max(y);
                n += 1;
            }
        }
        (n > 0).then_some(((x0, y0, x1, y1), n))
    }

    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    /// The four neighbour offsets of a flat index (left, right, down, up).
    #[inline]
    pub fn neighbours(&self, i: usize) -> [usize; 4] {
        [i - 1, i + 1, i - self.w, i + self.w]
    }

    /// Multi-source breadth-first distance (in cell steps, inside the region) from `sources` (flat
    /// indices), indexed like `cells`; cells the sources cannot reach get `w + h`.
    pub fn distances(&self, sources: &[usize]) -> Vec<u32> {
        let w = self.w;
        let mut dist = vec![u32::MAX; self.inside.len()];
        let mut queue = std::collections::VecDeque::new();
        for &s in sources {
            if dist[s] == u32::MAX {
                dist[s] = 0;
                queue.push_back(s);
            }
        }
        while let Some(c) = queue.pop_front() {
            let d = dist[c] + 1;
            for n in [c - 1, c + 1, c - w, c + w] {
                if self.inside[n] && dist[n] == u32::MAX {
                    dist[n] = d;
                    queue.push_back(n);
                }
            }
        }
        let far = (self.w + self.h) as u32;
        self.cells
            .iter()
            .map(|&c| dist[c as usize].min(far))
            .collect()
    }

    /// Is the region cell `i` on the region's envelope (a 4-neighbour outside the region)?
    #[inline]
    pub fn on_envelope(&self, i: usize) -> bool {
        self.neighbours(i).iter().any(|&n| !self.inside[n])
    }
}

/// Add a ring of `fill` cells around a grid.
pub fn pad(grid: &Grid, fill: Label) -> Grid {
    let mut out = Grid::new(grid.w + 2, grid.h + 2, fill);
    for y in 0..grid.h {
        let src = &grid.cells[y * grid.w..(y + 1) * grid.w];
        let dst = (y + 1) * out.w + 1;
        out.cells[dst..dst + grid.w].copy_from_slice(src);
    }
    out
}

/// Remove the ring that [`pad`] added.
pub fn unpad(grid: &Grid) -> Grid {
    let (w, h) = (grid.w - 2, grid.h - 2);
    let mut out = Grid::new(w, h, 0);
    for y in 0..h {
        let src = (y + 1) * grid.w + 1;
        out.cells[y * w..(y + 1) * w].copy_from_slice(&grid.cells[src..src + w]);
    }
    out
}

/// A padded grid from rows written top row first (as they read): `.` empty, `#` outside, digits
/// rooms. For unit tests across the crate.
#[cfg(test)]
pub fn parse_rows(rows: &[&str]) -> Grid {
    use crate::grid::{EMPTY, OUTSIDE};
    let h = rows.len();
    let w = rows[0].len();
    let mut g = Grid::new(w, h, EMPTY);
    for (r, row) in rows.iter().enumerate() {
        for (x, ch) in row.chars().enumerate() {
            let l = match ch {
                '.' => EMPTY,
                '#' => OUTSIDE,
                d => d.to_digit(10).expect("test grid cell") as Label,
            };
            g.set(x, h - 1 - r, l);
        }
    }
    pad(&g, OUTSIDE)
}

/// A padded grid of overlapping random rectangles of labels 0..6, `EMPTY` and `OUTSIDE`, a
/// random region in it, and a random choice of round labels.
#[cfg(test)]
pub fn random_case(rng: &mut impl rand::Rng) -> (Grid, Region, Vec<i16>, usize) {
    let (w, h) = (rng.random_range(3..80), rng.random_range(3..40));
    use crate::grid::{EMPTY, OUTSIDE};
    let mut g = Grid::new(w, h, 0);
    let mut m = Grid::new(w, h, 0);
    for _ in 0..rng.random_range(1..30) {
        let (ax, ay) = (rng.random_range(0..w), rng.random_range(0..h));
        let (bx, by) = (rng.random_range(ax..w), rng.random_range(ay..h));
        let l = match rng.random_range(0..9) {
            7 => EMPTY,
            8 => OUTSIDE,
            l => l,
        };
        let inside = rng.random_range(0..4) > 0;
        for y in ay..=by {
            for x in ax..=bx {
                g.set(x, y, l);
                m.set(x, y, if inside { 0 } else { OUTSIDE });
            }
        }
    }
    let (g, m) = (pad(&g, OUTSIDE), pad(&m, OUTSIDE));
    let r = Region::of_label(&m, 0);
    let mut index = vec![-1i16; 7];
    let mut n_round = 0;
    for k in index.iter_mut() {
        if rng.random() {
            *k = n_round as i16;
            n_round += 1;
        }
    }
    (g, r, index, n_round)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::{EMPTY, OUTSIDE};

    #[test]
    fn pad_and_unpad_round_trip() {
        let mut g = Grid::new(3, 2, EMPTY);
        g.set(2, 1, 7);
        let p = pad(&g, OUTSIDE);
        assert_eq!((p.w, p.h), (5, 4));
        assert_eq!(p.get(0, 0), OUTSIDE);
        assert_eq!(p.get(3, 2), 7);
        assert_eq!(unpad(&p), g);
    }

    #[test]
    fn region_of_label_and_envelope() {
        let mut g = pad(&Grid::new(3, 3, 1), OUTSIDE);
        g.set(2, 2, 2); // centre cell of the padded 5x5 grid
        let r = Region::of_label(&g, 1);
        assert_eq!(r.len(), 8);
        assert_eq!(r.bbox, (1, 1, 3, 3));
        assert!(r.on_envelope(g.idx(1, 1)));
        // the cells around the centre touch label 2, which is outside the region
        assert!(r.on_envelope(g.idx(2, 1)));
    }
}
