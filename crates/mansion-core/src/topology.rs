//! The topology filter `Topo(L, G)`: shared walls between rooms, connectedness, fixed walls and
//! minimum width, measured on the cells a round can change.

use crate::cleanup::Scratch;
use crate::grid::{Grid, Label, Walls, EMPTY, OUTSIDE};
use crate::region::Region;

/// Shared boundary between pairs of rooms where at least one room is a round label.
///
/// Stored densely as `round index × label`; a pair of two round labels lives in the row of the
/// smaller label, so each pair has exactly one slot.
#[derive(Debug, Clone)]
pub struct Contacts {
    n_labels: usize,
    /// Total shared boundary in cell edges.
    pub total: Vec<u32>,
    /// Longest straight shared segment in cell edges (what a door needs).
    pub longest: Vec<u32>,
}

impl Contacts {
    #[inline]
    fn slot(&self, index: &[i16], a: Label, b: Label) -> Option<usize> {
        let (ia, ib) = (index[a as usize], index[b as usize]);
        if ia >= 0 && (ib < 0 || a < b) {
            Some(ia as usize * self.n_labels + b as usize)
        } else if ib >= 0 {
            Some(ib as usize * self.n_labels + a as usize)
        } else {
            None
        }
    }

    /// `(total, longest)` shared cell edges between `a` and `b`; zero when neither is a round label.
    pub fn get(&self, index: &[i16], a: Label, b: Label) -> (u32, u32) {
        match self.slot(index, a, b) {
            Some(s) => (self.total[s], self.longest[s]),
            None => (0, 0),
        }
    }
}

#[inline]
fn is_room(l: Label) -> bool {
    l != OUTSIDE && l != EMPTY
}

/// Measure contacts along every cell edge that touches the region. `index[label]` is the label's
/// position among the round labels, or -1; `n_round` is how many round labels there are.
pub fn measure_contacts(grid: &Grid, region: &Region, index: &[i16], n_round: usize) -> Contacts {
    let n_labels = index.len();
    let mut c = Contacts {
        n_labels,
        total: vec![0; n_round * n_labels],
        longest: vec![0; n_round * n_labels],
    };
    let w = grid.w;
    let (x0, y0, x1, y1) = region.bbox;
    // edges between row y and row y + 1, scanned along x so straight runs are contiguous
    for y in (y0 - 1)..=y1 {
        let mut run_slot = usize::MAX;
        let mut run = 0u32;
        for x in x0..=x1 {
            let (i, j) = (y * w + x, (y + 1) * w + x);
            let slot = edge_slot(grid, region, &c, index, i, j);
            advance(&mut c, slot, &mut run_slot, &mut run);
        }
    }
    // edges between column x and column x + 1, scanned along y
    for x in (x0 - 1)..=x1 {
        let mut run_slot = usize::MAX;
        let mut run = 0u32;
        for y in y0..=y1 {
            let (i, j) = (y * w + x, y * w + x + 1);
            let slot = edge_slot(grid, region, &c, index, i, j);
            advance(&mut c, slot, &mut run_slot, &mut run);
        }
    }
    c
}

#[inline]
fn edge_slot(
    grid: &Grid,
    region: &Region,
    c: &Contacts,
    index: &[i16],
    i: usize,
    j: usize,
) -> usize {
    let (a, b) = (grid.cells[i], grid.cells[j]);
    if a == b || !is_room(a) || !is_room(b) || !(region.inside[i] || region.inside[j]) {
        return usize::MAX;
    }
    c.slot(index, a, b).unwrap_or(usize::MAX)
}

#[inline]
fn advance(c: &mut Contacts, slot: usize, run_slot: &mut usize, run: &mut u32) {
    if slot == usize::MAX {
        *run_slot = usize::MAX;
        *run = 0;
        return;
    }
    if slot == *run_slot {
        *run += 1;
    } else {
        *run_slot = slot;
        *run = 1;
    }
    c.total[slot] += 1;
    if *run > c.longest[slot] {
        c.longest[slot] = *run;
    }
}

/// Number of 4-connected pieces of every round label inside the region, in one pass
/// (`index[label]` is the label's round position or -1).
pub fn pieces_all(
    grid: &Grid,
    region: &Region,
    index: &[i16],
    n_round: usize,
    s: &mut Scratch,
) -> Vec<u32> {
    let w = grid.w;
    let epoch = s.bump();
    let mut out = vec![0u32; n_round];
    for &start in &region.cells {
        let start = start as usize;
        if s.stamp[start] == epoch {
            continue;
        }
        let label = grid.cells[start];
        match index.get(label as usize) {
            Some(&k) if k >= 0 => out[k as usize] += 1,
            _ => continue,
        }
        s.queue.clear();
        s.queue.push(start);
        s.stamp[start] = epoch;
        while let Some(c) = s.queue.pop() {
            for nb in [c - 1, c + 1, c - w, c + w] {
                if grid.cells[nb] == label && s.stamp[nb] != epoch && region.inside[nb] {
                    s.stamp[nb] = epoch;
                    s.queue.push(nb);
                }
            }
        }
    }
    out
}

/// Does `label` own the cells on both sides of a fixed wall somewhere in the region?
pub fn straddles(grid: &Grid, region: &Region, walls: &Walls, label: Label) -> bool {
    if !walls.any {
        return false;
    }
    let w = grid.w;
    region.cells.iter().any(|&c| {
        let c = c as usize;
        grid.cells[c] == label
            && ((grid.cells[c + 1] == label && walls.blocked(c, c + 1))
                || (grid.cells[c + w] == label && walls.blocked(c, c + w)))
    })
}

/// Is every cell of `label` covered by some `width × width` square of the same label? (A room
/// narrower than that somewhere fails.)
pub fn min_width_ok(grid: &Grid, region: &Region, label: Label, width: usize) -> bool {
    if width <= 1 {
        return true;
    }
    let (x0, y0, x1, y1) = region.bbox;
    let (bw, bh) = (x1 - x0 + 1, y1 - y0 + 1);
    // side of the largest same-label square whose top-right cell is (x, y)
    let mut sq = vec![0u16; bw * bh];
    // covered[.] counts squares of side `width` covering a cell, via a 2-D difference array
    let mut diff = vec![0i32; (bw + 1) * (bh + 1)];
    for y in 0..bh {
        for x in 0..bw {
            let c = (y + y0) * grid.w + x + x0;
            if grid.cells[c] != label {
                continue;
            }
            let v = if x == 0 || y == 0 {
                1
            } else {
                1 + sq[y * bw + x - 1]
                    .min(sq[(y - 1) * bw + x])
                    .min(sq[(y - 1) * bw + x - 1])
            };
            sq[y * bw + x] = v;
            if v as usize >= width {
                let (ax, ay) = (x + 1 - width, y + 1 - width);
                diff[ay * (bw + 1) + ax] += 1;
                diff[ay * (bw + 1) + x + 1] -= 1;
                diff[(y + 1) * (bw + 1) + ax] -= 1;
                diff[(y + 1) * (bw + 1) + x + 1] += 1;
            }
        }
    }
    // prefix sums turn the difference array into coverage counts
    for y in 0..=bh {
        for x in 1..=bw {
            diff[y * (bw + 1) + x] += diff[y * (bw + 1) + x - 1];
        }
    }
    for y in 1..=bh {
        for x in 0..=bw {
            diff[y * (bw + 1) + x] += diff[(y - 1) * (bw + 1) + x];
        }
    }
    for y in 0..bh {
        for x in 0..bw {
            let c = (y + y0) * grid.w + x + x0;
            if grid.cells[c] == label && diff[y * (bw + 1) + x] <= 0 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::parse_rows;

    fn parse(rows: &[&str]) -> Grid {
        parse_rows(rows)
    }

    fn region_of(g: &Grid, labels: &[Label]) -> Region {
        let mut m = g.clone();
        for c in m.cells.iter_mut() {
            *c = if labels.contains(c) { 0 } else { OUTSIDE };
        }
        Region::of_label(&m, 0)
    }

    #[test]
    fn contacts_measure_total_and_longest_straight_run() {
        // rooms 1 and 2 share a vertical wall of 3 edges and, after a step, 1 more edge
        let g = parse(&["1122", "1112", "1122", "1122"]);
        let r = region_of(&g, &[1, 2]);
        let index = [-1i16, 0, 1];
        let c = measure_contacts(&g, &r, &index, 2);
        let (total, longest) = c.get(&index, 1, 2);
        assert_eq!(total, 6);
        assert_eq!(longest, 2);
        assert_eq!(c.get(&index, 2, 1), (total, longest));
    }

    #[test]
    fn contacts_with_rooms_outside_the_region() {
        let g = parse(&["3333", "1122", "1122"]);
        let r = region_of(&g, &[1, 2]);
        let index = [-1i16, 0, 1, -1];
        let c = measure_contacts(&g, &r, &index, 2);
        assert_eq!(c.get(&index, 1, 3), (2, 2));
        assert_eq!(c.get(&index, 3, 2), (2, 2));
    }

    #[test]
    fn pieces_counts_components() {
        let g = parse(&["1221", "1221"]);
        let r = region_of(&g, &[1, 2]);
        let mut s = Scratch::new(g.cells.len());
        let index = [-1i16, 0, 1];
        assert_eq!(pieces_all(&g, &r, &index, 2, &mut s), vec![2, 1]);
        assert_eq!((g.count(1), g.count(2)), (4, 4));
    }

    #[test]
    fn min_width_detects_a_thin_neck() {
        let g = parse(&["1111", "1111", "1100", "1100"]);
        let r = region_of(&g, &[1]);
        assert!(min_width_ok(&g, &r, 1, 2));
        // a one-cell tail at the bottom left cannot be covered by a 2x2 square
        let g = parse(&["1111", "1111", "1000"]);
        let r = region_of(&g, &[1]);
        assert!(!min_width_ok(&g, &r, 1, 2));
        assert!(min_width_ok(&g, &r, 1, 1));
        // a neck one cell wide between two 2x2 blocks
        let g = parse(&["1101", "1111", "1101"]);
        let r = region_of(&g, &[1]);
        assert!(!min_width_ok(&g, &r, 1, 2));
    }

    #[test]
    fn straddle_detection() {
        let g = parse(&["1122"]);
        let r = region_of(&g, &[1, 2]);
        let mut walls = Walls::none(g.w, g.h);
        walls.block_vertical(2, 1); // between padded columns 1 and 2: both room 1
        assert!(straddles(&g, &r, &walls, 1));
        assert!(!straddles(&g, &r, &walls, 2));
    }
}
