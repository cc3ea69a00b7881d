//! Spur removal and hole filling, as the paper defines them, restricted to one round's region.
//!
//! A spur cell has at most one same-room 4-neighbour and touches another room or the outside. Every
//! pass empties all spurs at once; passes repeat until none is left. Each empty connected component
//! then goes to the room sharing the longest boundary with it. This fill-then-clean cycle repeats
//! up to [`MAX_CYCLES`] times, because filling can create new spurs.

use crate::grid::{Grid, Label, Walls, EMPTY, OUTSIDE};
use crate::region::Region;

/// The paper's cap on fill-then-clean cycles.
pub const MAX_CYCLES: usize = 20;

/// Reusable buffers, so the hot path of a candidate allocates nothing per call.
#[derive(Debug, Default, Clone)]
pub struct Scratch {
    pub stamp: Vec<u32>,
    pub epoch: u32,
    pub queue: Vec<usize>,
    pub list: Vec<usize>,
    pub next: Vec<usize>,
    pub counts: Vec<(Label, u32)>,
    /// Runs of one label along a row: (first x, last x, id), for piece counting.
    pub runs: Vec<(u32, u32, u32)>,
    /// Union–find parents of those runs.
    pub parent: Vec<u32>,
    /// Empty cells to fill.
    pub holes: Vec<usize>,
}

impl Scratch {
    pub fn new(cells: usize) -> Self {
        Scratch {
            stamp: vec![0; cells],
            ..Default::default()
        }
    }

    /// A fresh stamp value; cells stamped with an older value count as unvisited.
    pub fn bump(&mut self) -> u32 {
        if self.epoch == u32::MAX {
            self.stamp.iter_mut().for_each(|s| *s = 0);
            self.epoch = 0;
        }
        self.epoch += 1;
        self.epoch
    }
}

#[inline]
fn is_spur(grid: &Grid, i: usize) -> bool {
    let l = grid.cells[i];
    if l == EMPTY || l == OUTSIDE {
        return false;
    }
    let w = grid.w;
    let mut same = 0;
    let mut foreign = false;
    for n in [i - 1, i + 1, i - w, i + w] {
        let m = grid.cells[n];
        if m == l {
            same += 1;
        } else if m != EMPTY {
            foreign = true;
        }
    }
    same <= 1 && foreign
}

/// [`is_spur`] from a cell's label and its four neighbours' labels, without branches.
#[inline]
fn spur_of(l: Label, around: [Label; 4]) -> bool {
    let same = around.iter().map(|&m| (m == l) as u8).sum::<u8>();
    let foreign = around
        .iter()
        .fold(false, |f, &m| f | ((m != l) & (m != EMPTY)));
    (l < EMPTY) & (same <= 1) & foreign
}

/// The region's spur cells, ascending, into `out`. Rows of the region's box are read as five
/// shifted slices, sixteen cells at a time, so the test compiles to vector compares and most
/// chunks (no spur) cost a handful of instructions.
fn find_spurs(grid: &Grid, region: &Region, out: &mut Vec<usize>) {
    const CHUNK: usize = 16;
    out.clear();
    let w = grid.w;
    let (x0, y0, x1, y1) = region.bbox;
    let n = x1 - x0 + 1;
    for y in y0..=y1 {
        let i = y * w + x0;
        let line = |from: usize| &grid.cells[from..from + n];
        let (c, l, r, d, u) = (line(i), line(i - 1), line(i + 1), line(i - w), line(i + w));
        let inside = &region.inside[i..i + n];
        let mut at = 0;
        while at + CHUNK <= n {
            // fixed-length arrays so that the loop below is unrolled into vector compares
            let part = |s: &[Label]| -> [Label; CHUNK] {
                s[at..at + CHUNK].try_into().expect("a whole chunk")
            };
            let (c, l, r, d, u) = (part(c), part(l), part(r), part(d), part(u));
            let mut any = false;
            let mut flags = [false; CHUNK];
            for j in 0..CHUNK {
                flags[j] = spur_of(c[j], [l[j], r[j], d[j], u[j]]);
                any |= flags[j];
            }
            if any {
                out.extend(
                    (0..CHUNK)
                        .filter(|&j| flags[j] && inside[at + j])
                        .map(|j| i + at + j),
                );
            }
            at += CHUNK;
        }
        for k in at..n {
            if inside[k] && spur_of(c[k], [l[k], r[k], d[k], u[k]]) {
                out.push(i + k);
            }
        }
    }
}

/// Empty every spur cell of the region, pass after pass, until none is left. Returns the number of
/// cells emptied.
pub fn remove_spurs(grid: &mut Grid, region: &Region, s: &mut Scratch) -> usize {
    let w = grid.w;
    let mut removed = 0;
    find_spurs(grid, region, &mut s.list);
    while !s.list.is_empty() {
        // all spurs of one pass go at once; only their old neighbours can become spurs next
        s.next.clear();
        for &c in &s.list {
            let l = grid.cells[c];
            if l == EMPTY {
                continue;
            }
            grid.cells[c] = EMPTY;
            removed += 1;
            for n in [c - 1, c + 1, c - w, c + w] {
                if grid.cells[n] == l && region.inside[n] {
                    s.next.push(n);
                }
            }
        }
        s.list.clear();
        for &n in &s.next {
            if is_spur(grid, n) {
                s.list.push(n);
            }
        }
        s.list.sort_unstable();
        s.list.dedup();
    }
    removed
}

/// Give every empty component of the region to the room (among region labels) that shares the
/// longest boundary with it; fixed walls split components and do not count as shared boundary.
/// Returns false when some component touches no region room (it stays empty).
pub fn fill_holes(grid: &mut Grid, region: &Region, walls: &Walls, s: &mut Scratch) -> bool {
    let w = grid.w;
    let epoch = s.bump();
    let mut all_filled = true;
    let mut holes = std::mem::take(&mut s.holes);
    find_empty(grid, region, &mut holes);
    for &start in &holes {
        // cells of a component already filled (or found unfillable) carry this epoch's stamp
        if s.stamp[start] == epoch {
            continue;
        }
        s.queue.clear();
        s.list.clear();
        s.counts.clear();
        s.queue.push(start);
        s.stamp[start] = epoch;
        while let Some(c) = s.queue.pop() {
            s.list.push(c);
            for n in [c - 1, c + 1, c - w, c + w] {
                if walls.blocked(c, n) {
                    continue;
                }
                let m = grid.cells[n];
                if m == EMPTY {
                    if s.stamp[n] != epoch {
                        s.stamp[n] = epoch;
                        s.queue.push(n);
                    }
                } else if m != OUTSIDE && region.inside[n] {
                    match s.counts.iter_mut().find(|(l, _)| *l == m) {
                        Some(e) => e.1 += 1,
                        None => s.counts.push((m, 1)),
                    }
                }
            }
        }
        // longest shared boundary wins; ties go to the lower label so results are deterministic
        let winner = s
            .counts
            .iter()
            .max_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(&a.0)))
            .map(|e| e.0);
        match winner {
            Some(l) => {
                for &c in &s.list {
                    grid.cells[c] = l;
                }
            }
            None => all_filled = false,
        }
    }
    s.holes = holes;
    all_filled
}

/// The region's `EMPTY` cells, ascending, into `out`; rows are read sixteen cells at a time
/// since most hold none.
fn find_empty(grid: &Grid, region: &Region, out: &mut Vec<usize>) {
    const CHUNK: usize = 16;
    out.clear();
    let (x0, y0, x1, y1) = region.bbox;
    for y in y0..=y1 {
        let first = y * grid.w + x0;
        let row = &grid.cells[first..=y * grid.w + x1];
        for (k, chunk) in row.chunks(CHUNK).enumerate() {
            if chunk.iter().fold(false, |any, &c| any | (c == EMPTY)) {
                out.extend(
                    (0..chunk.len())
                        .map(|j| first + k * CHUNK + j)
                        .filter(|&i| grid.cells[i] == EMPTY && region.inside[i]),
                );
            }
        }
    }
}

/// Leftover cells of a round go to the parent, which keeps only its largest connected piece; the
/// other pieces are emptied for hole filling to hand to the children around them.
pub fn assign_remainder(
    grid: &mut Grid,
    region: &Region,
    walls: &Walls,
    parent: Label,
    s: &mut Scratch,
) {
    for &c in &region.cells {
        if grid.cells[c as usize] == EMPTY {
            grid.cells[c as usize] = parent;
        }
    }
    keep_largest_piece(grid, region, walls, parent, s);
}

/// Empty every 4-connected piece of `label` inside the region except the largest.
pub fn keep_largest_piece(
    grid: &mut Grid,
    region: &Region,
    walls: &Walls,
    label: Label,
    s: &mut Scratch,
) {
    let w = grid.w;
    let epoch = s.bump();
    let mut pieces: Vec<(usize, usize)> = Vec::new(); // (start, size)
    for &start in &region.cells {
        let start = start as usize;
        if grid.cells[start] != label || s.stamp[start] == epoch {
            continue;
        }
        s.queue.clear();
        s.queue.push(start);
        s.stamp[start] = epoch;
        let mut size = 0;
        while let Some(c) = s.queue.pop() {
            size += 1;
            for n in [c - 1, c + 1, c - w, c + w] {
                if grid.cells[n] == label
                    && s.stamp[n] != epoch
                    && region.inside[n]
                    && !walls.blocked(c, n)
                {
                    s.stamp[n] = epoch;
                    s.queue.push(n);
                }
            }
        }
        pieces.push((start, size));
    }
    if pieces.len() <= 1 {
        return;
    }
    let keep = pieces
        .iter()
        .enumerate()
        .max_by(|a, b| a.1 .1.cmp(&b.1 .1).then(b.0.cmp(&a.0)))
        .map(|(k, _)| k)
        .unwrap_or(0);
    let epoch = s.bump();
    for (k, &(start, _)) in pieces.iter().enumerate() {
        if k == keep {
            continue;
        }
        s.queue.clear();
        s.queue.push(start);
        s.stamp[start] = epoch;
        while let Some(c) = s.queue.pop() {
            grid.cells[c] = EMPTY;
            for n in [c - 1, c + 1, c - w, c + w] {
                if grid.cells[n] == label
                    && s.stamp[n] != epoch
                    && region.inside[n]
                    && !walls.blocked(c, n)
                {
                    s.stamp[n] = epoch;
                    s.queue.push(n);
                }
            }
        }
    }
}

/// The fill-then-clean cycle: fill holes, remove spurs, repeat until a pass removes no spur or
/// [`MAX_CYCLES`] is reached; always ends on a fill so no cell is left empty when avoidable.
/// Returns false when empty cells remain that no region room touches.
pub fn clean(grid: &mut Grid, region: &Region, walls: &Walls, s: &mut Scratch) -> bool {
    for _ in 0..MAX_CYCLES {
        if !fill_holes(grid, region, walls, s) {
            return false;
        }
        if remove_spurs(grid, region, s) == 0 {
            return true;
        }
    }
    fill_holes(grid, region, walls, s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::parse_rows;

    /// Parse rows written top row first (as they read), `.` empty, `#` outside, digits rooms.
    fn parse(rows: &[&str]) -> Grid {
        parse_rows(rows)
    }

    fn region_all(g: &Grid) -> Region {
        // every non-outside cell is in the region
        let mut marked = g.clone();
        for c in marked.cells.iter_mut() {
            *c = if *c == OUTSIDE { OUTSIDE } else { 0 };
        }
        Region::of_label(&marked, 0)
    }

    #[test]
    fn spur_chain_is_eaten_back_to_the_body() {
        let mut g = parse(&["1111222", "1111...", "1111...", "1111..."]);
        // a one-cell-wide tail of room 2 along the top row is all spur
        let r = region_all(&g);
        let mut s = Scratch::new(g.cells.len());
        let removed = remove_spurs(&mut g, &r, &mut s);
        assert_eq!(removed, 3);
        assert_eq!(g.count(2), 0);
        assert_eq!(g.count(1), 16);
    }

    #[test]
    fn spurs_found_a_row_at_a_time_are_the_spur_cells() {
        use rand::SeedableRng;
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(13);
        let mut got = Vec::new();
        let mut with_spurs = 0;
        for _ in 0..3000 {
            let (g, r, _, _) = crate::region::random_case(&mut rng);
            if r.is_empty() {
                continue;
            }
            find_spurs(&g, &r, &mut got);
            let want: Vec<usize> = (r.cells.iter().map(|&c| c as usize))
                .filter(|&c| is_spur(&g, c))
                .collect();
            assert_eq!(got, want);
            with_spurs += !want.is_empty() as usize;
        }
        assert!(with_spurs > 300, "only {with_spurs} grids had spurs");
    }

    #[test]
    fn hole_goes_to_the_room_with_the_longest_boundary() {
        let mut g = parse(&["11122", "1..22", "11122"]);
        let r = region_all(&g);
        let mut s = Scratch::new(g.cells.len());
        let walls = Walls::none(g.w, g.h);
        assert!(fill_holes(&mut g, &r, &walls, &mut s));
        // the empty pair touches room 1 on 3 edges and room 2 on 1 edge
        assert_eq!(g.count(EMPTY), 0);
        assert_eq!(g.count(1), 9);
    }

    #[test]
    fn fixed_wall_splits_a_hole() {
        let mut g = parse(&["1..2", "1..2"]);
        let mut walls = Walls::none(g.w, g.h);
        // wall between columns 2 and 3 of the padded grid (between the two empty columns)
        walls.block_vertical(3, 1);
        walls.block_vertical(3, 2);
        let r = region_all(&g);
        let mut s = Scratch::new(g.cells.len());
        assert!(fill_holes(&mut g, &r, &walls, &mut s));
        assert_eq!(g.count(1), 4);
        assert_eq!(g.count(2), 4);
    }

    #[test]
    fn remainder_keeps_its_largest_piece() {
        let mut g = parse(&["1..22", "11122", "..222"]);
        let r = region_all(&g);
        let mut s = Scratch::new(g.cells.len());
        let walls = Walls::none(g.w, g.h);
        assign_remainder(&mut g, &r, &walls, 9, &mut s);
        assert_eq!(g.count(9), 2);
        assert_eq!(g.count(EMPTY), 2);
        assert!(clean(&mut g, &r, &walls, &mut s));
        assert_eq!(g.count(EMPTY), 0);
    }

    #[test]
    fn clean_terminates_and_fills_everything() {
        let mut g = parse(&["1.1.1", ".2.2.", "1.1.1", ".2.2."]);
        let r = region_all(&g);
        let mut s = Scratch::new(g.cells.len());
        let walls = Walls::none(g.w, g.h);
        clean(&mut g, &r, &walls, &mut s);
        assert_eq!(g.count(EMPTY), 0);
    }
}
