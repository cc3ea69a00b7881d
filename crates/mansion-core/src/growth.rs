//! Constrained growth (Lopes et al. 2010, as used by the MANSION solver): rectangular growth, then
//! L-shaped growth, both capped at each room's target area. Gap filling is left to [`crate::cleanup`].
//!
//! The grid passed in has the round's region cells set to `EMPTY`; `EMPTY` therefore means "free in
//! this round" and no other cell is ever `EMPTY`.

use crate::grid::{Grid, Label, Walls, EMPTY};
use rand::Rng;

/// One room growing in a round.
#[derive(Debug, Clone, Copy)]
pub struct Grower {
    pub label: Label,
    /// Target area in cells.
    pub target: f64,
}

/// Would adding `add` cells to a room of `area` cells bring it closer to (or keep it within) its
/// target? Both growth phases share this cap so no room overgrows (the released code capped only
/// the rectangular phase, and its rooms overgrew).
#[inline]
fn within_cap(area: usize, add: usize, target: f64) -> bool {
    let after = (area + add) as f64;
    after <= target || after - target < target - area as f64
}

/// Pick an index among `active` rooms with probability proportional to their target area.
fn pick_weighted<R: Rng>(rng: &mut R, growers: &[Grower], active: &[usize]) -> usize {
    let total: f64 = active.iter().map(|&k| growers[k].target.max(1.0)).sum();
    let mut u = rng.random::<f64>() * total;
    for (pos, &k) in active.iter().enumerate() {
        u -= growers[k].target.max(1.0);
        if u <= 0.0 {
            return pos;
        }
    }
    active.len() - 1
}

/// Can cell `c` join room `label` without straddling a fixed wall?
#[inline]
fn wall_ok(grid: &Grid, walls: &Walls, c: usize, label: Label) -> bool {
    if !walls.any {
        return true;
    }
    let w = grid.w;
    [c - 1, c + 1, c - w, c + w]
        .iter()
        .all(|&n| grid.cells[n] != label || !walls.blocked(c, n))
}

/// Grow every room from its seed cell. `seeds[k]` is the flat index of grower `k`'s seed, which must
/// be an `EMPTY` cell; seeds must be distinct. Returns each grower's area in cells.
pub fn grow<R: Rng>(
    grid: &mut Grid,
    walls: &Walls,
    growers: &[Grower],
    seeds: &[usize],
    rng: &mut R,
) -> Vec<usize> {
    let w = grid.w;
    let n = growers.len();
    let mut area = vec![0usize; n];
    // Inclusive bounding boxes (x0, y0, x1, y1); during the rectangular phase they are the rooms.
    let mut bbox = vec![(0usize, 0usize, 0usize, 0usize); n];
    for k in 0..n {
        let s = seeds[k];
        debug_assert_eq!(grid.cells[s], EMPTY);
        grid.cells[s] = growers[k].label;
        area[k] = 1;
        bbox[k] = (s % w, s / w, s % w, s / w);
    }

    // --- rectangular growth: add a whole free line beside one side, longest side first ---
    let mut active: Vec<usize> = (0..n).filter(|&k| (area[k] as f64) < growers[k].target).collect();
    let mut sides: Vec<(usize, u8)> = Vec::with_capacity(4);
    while !active.is_empty() {
        let pos = pick_weighted(rng, growers, &active);
        let k = active[pos];
        let label = growers[k].label;
        let (x0, y0, x1, y1) = bbox[k];
        sides.clear();
        // side 0: left, 1: right, 2: down, 3: up
        for side in 0u8..4 {
            let (len, ok) = match side {
                0 => (y1 - y0 + 1, line_free(grid, walls, (x0 - 1, y0), (0, 1), y1 - y0 + 1, 1)),
                1 => (y1 - y0 + 1, line_free(grid, walls, (x1 + 1, y0), (0, 1), y1 - y0 + 1, -1)),
                2 => (x1 - x0 + 1, line_free(grid, walls, (x0, y0 - 1), (1, 0), x1 - x0 + 1, w as isize)),
                _ => (x1 - x0 + 1, line_free(grid, walls, (x0, y1 + 1), (1, 0), x1 - x0 + 1, -(w as isize))),
            };
            if ok && within_cap(area[k], len, growers[k].target) {
                sides.push((len, side));
            }
        }
        if sides.is_empty() {
            active.swap_remove(pos);
            continue;
        }
        let best = sides.iter().map(|s| s.0).max().unwrap_or(0);
        let ties: Vec<u8> = sides.iter().filter(|s| s.0 == best).map(|s| s.1).collect();
        let side = ties[rng.random_range(0..ties.len())];
        let (nx0, ny0, nx1, ny1) = match side {
            0 => (x0 - 1, y0, x0 - 1, y1),
            1 => (x1 + 1, y0, x1 + 1, y1),
            2 => (x0, y0 - 1, x1, y0 - 1),
            _ => (x0, y1 + 1, x1, y1 + 1),
        };
        for y in ny0..=ny1 {
            for x in nx0..=nx1 {
                grid.cells[y * w + x] = label;
            }
        }
        area[k] += best;
        bbox[k] = (x0.min(nx0), y0.min(ny0), x1.max(nx1), y1.max(ny1));
        if area[k] as f64 >= growers[k].target {
            active.swap_remove(pos);
        }
    }

    // --- L-shaped growth: extend by the longest run of free cells beside the room's own cells ---
    let mut active: Vec<usize> = (0..n).filter(|&k| (area[k] as f64) < growers[k].target).collect();
    while !active.is_empty() {
        let pos = pick_weighted(rng, growers, &active);
        let k = active[pos];
        let label = growers[k].label;
        match best_run(grid, walls, label, bbox[k], rng) {
            Some(run) if within_cap(area[k], run.len, growers[k].target) => {
                let step = if run.horizontal { 1 } else { w };
                for t in 0..run.len {
                    grid.cells[run.start + t * step] = label;
                }
                area[k] += run.len;
                let (sx, sy) = (run.start % w, run.start / w);
                let end = run.start + (run.len - 1) * step;
                let (ex, ey) = (end % w, end / w);
                let (x0, y0, x1, y1) = bbox[k];
                bbox[k] = (x0.min(sx), y0.min(sy), x1.max(ex), y1.max(ey));
                if area[k] as f64 >= growers[k].target {
                    active.swap_remove(pos);
                }
            }
            _ => {
                active.swap_remove(pos);
            }
        }
    }
    area
}

/// Is the line of `len` cells starting at `start` and stepping by `dir` all free, and can it join
/// the room on its `back` side (flat offset from a line cell to the room cell behind it) without
/// straddling a fixed wall?
#[inline]
fn line_free(
    grid: &Grid,
    walls: &Walls,
    start: (usize, usize),
    dir: (usize, usize),
    len: usize,
    back: isize,
) -> bool {
    let w = grid.w;
    let s = start.1 * w + start.0;
    let step = dir.1 * w + dir.0;
    for t in 0..len {
        let c = s + t * step;
        if grid.cells[c] != EMPTY {
            return false;
        }
        if walls.any {
            let behind = (c as isize + back) as usize;
            if walls.blocked(c, behind) || (t > 0 && walls.blocked(c, c - step)) {
                return false;
            }
        }
    }
    true
}

/// A run of free cells to add in the L-shaped phase.
#[derive(Debug, Clone, Copy)]
struct Run {
    start: usize,
    len: usize,
    horizontal: bool,
}

/// The longest run (at least two cells) of free cells lying directly beyond the room's own cells on
/// one side; ties broken at random.
fn best_run<R: Rng>(
    grid: &Grid,
    walls: &Walls,
    label: Label,
    bbox: (usize, usize, usize, usize),
    rng: &mut R,
) -> Option<Run> {
    let w = grid.w;
    let (x0, y0, x1, y1) = bbox;
    let mut best: Vec<Run> = Vec::new();
    let mut best_len = 1usize; // runs of one cell only make spurs
    let consider = |run: Run, best: &mut Vec<Run>, best_len: &mut usize| {
        if run.len > *best_len {
            *best_len = run.len;
            best.clear();
            best.push(run);
        } else if run.len == *best_len && *best_len > 1 {
            best.push(run);
        }
    };
    let frontier = |c: usize, back: usize| -> bool {
        grid.cells[c] == EMPTY
            && grid.cells[back] == label
            && (!walls.any || (!walls.blocked(c, back) && wall_ok(grid, walls, c, label)))
    };
    // rows beyond the bottom and top edges of the room's cells
    for y in y0..=y1 {
        for (dy, horizontal) in [(-1isize, true), (1, true)] {
            let fy = (y as isize + dy) as usize;
            let mut run_start = usize::MAX;
            let mut run_len = 0usize;
            for x in x0..=x1 + 1 {
                let c = fy * w + x;
                let ok = x <= x1
                    && frontier(c, y * w + x)
                    && (run_len == 0 || !walls.blocked(c, c - 1));
                if ok {
                    if run_len == 0 {
                        run_start = c;
                    }
                    run_len += 1;
                } else {
                    if run_len > 0 {
                        consider(Run { start: run_start, len: run_len, horizontal }, &mut best, &mut best_len);
                    }
                    run_len = 0;
                    // a cell that failed only because of the wall to its left may start a new run
                    if x <= x1 && frontier(c, y * w + x) {
                        run_start = c;
                        run_len = 1;
                    }
                }
            }
        }
    }
    // columns beyond the left and right edges
    for x in x0..=x1 {
        for dx in [-1isize, 1] {
            let fx = (x as isize + dx) as usize;
            let mut run_start = usize::MAX;
            let mut run_len = 0usize;
            for y in y0..=y1 + 1 {
                let c = y * w + fx;
                let ok = y <= y1
                    && frontier(c, y * w + x)
                    && (run_len == 0 || !walls.blocked(c, c - w));
                if ok {
                    if run_len == 0 {
                        run_start = c;
                    }
                    run_len += 1;
                } else {
                    if run_len > 0 {
                        consider(Run { start: run_start, len: run_len, horizontal: false }, &mut best, &mut best_len);
                    }
                    run_len = 0;
                    if y <= y1 && frontier(c, y * w + x) {
                        run_start = c;
                        run_len = 1;
                    }
                }
            }
        }
    }
    if best.is_empty() {
        None
    } else {
        Some(best[rng.random_range(0..best.len())])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::OUTSIDE;
    use crate::region::{pad, Region};
    use rand::SeedableRng;
    use rand_xoshiro::Xoshiro256PlusPlus;

    fn setup(w: usize, h: usize) -> Grid {
        let g = pad(&Grid::new(w, h, 0), OUTSIDE);
        let r = Region::of_label(&g, 0);
        let mut g = g;
        for &c in &r.cells {
            g.cells[c as usize] = EMPTY;
        }
        g
    }

    #[test]
    fn single_room_grows_to_its_target_as_a_rectangle() {
        let mut g = setup(10, 10);
        let walls = Walls::none(g.w, g.h);
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(1);
        let seed = g.idx(5, 5);
        let area = grow(&mut g, &walls, &[Grower { label: 1, target: 20.0 }], &[seed], &mut rng);
        assert!((18..=22).contains(&area[0]), "area {}", area[0]);
        assert_eq!(g.count(1), area[0]);
    }

    #[test]
    fn rooms_never_overlap_and_respect_targets() {
        let mut g = setup(16, 12);
        let walls = Walls::none(g.w, g.h);
        let growers = [
            Grower { label: 1, target: 80.0 },
            Grower { label: 2, target: 60.0 },
            Grower { label: 3, target: 52.0 },
        ];
        let seeds = [g.idx(3, 3), g.idx(12, 4), g.idx(8, 10)];
        for s in 0..20u64 {
            let mut gg = g.clone();
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(s);
            let area = grow(&mut gg, &walls, &growers, &seeds, &mut rng);
            for (k, gr) in growers.iter().enumerate() {
                assert_eq!(gg.count(gr.label), area[k]);
                assert!((area[k] as f64) < gr.target * 1.5, "room {k} overgrew: {}", area[k]);
            }
        }
        let _ = &mut g;
    }

    #[test]
    fn growth_never_straddles_a_fixed_wall() {
        let mut g = setup(10, 6);
        let mut walls = Walls::none(g.w, g.h);
        // a full-height wall on the grid line left of padded column 5
        for y in 1..7 {
            walls.block_vertical(5, y);
        }
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(3);
        let seed = g.idx(2, 3);
        grow(&mut g, &walls, &[Grower { label: 1, target: 60.0 }], &[seed], &mut rng);
        for y in 1..7 {
            assert!(g.get(5, y) != 1, "room crossed the wall at row {y}");
        }
        assert!(g.count(1) <= 24);
    }

    #[test]
    fn same_seed_same_growth() {
        let g = setup(12, 12);
        let walls = Walls::none(g.w, g.h);
        let growers = [Grower { label: 1, target: 50.0 }, Grower { label: 2, target: 60.0 }];
        let seeds = [g.idx(3, 3), g.idx(9, 9)];
        let run = |s| {
            let mut gg = g.clone();
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(s);
            grow(&mut gg, &walls, &growers, &seeds, &mut rng);
            gg
        };
        assert_eq!(run(7), run(7));
    }
}
