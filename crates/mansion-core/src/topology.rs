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
///
/// Both edge directions are read a row at a time, so each line is contiguous memory whose equal
/// stretches (most of it: the inside of rooms) are skipped several cells at a time.
pub fn measure_contacts(grid: &Grid, region: &Region, index: &[i16], n_round: usize) -> Contacts {
    let n_labels = index.len();
    let mut c = Contacts {
        n_labels,
        total: vec![0; n_round * n_labels],
        longest: vec![0; n_round * n_labels],
    };
    let w = grid.w;
    let (x0, y0, x1, y1) = region.bbox;
    // edges between row y and row y + 1, runs along x
    for y in (y0 - 1)..=y1 {
        let (lo, hi) = (y * w + x0, (y + 1) * w + x0);
        let n = x1 - x0 + 1;
        let mut run = Run::NONE;
        for_each_diff(&grid.cells[lo..lo + n], &grid.cells[hi..hi + n], |j| {
            let slot = edge_slot(grid, region, &c, index, lo + j, hi + j);
            run.advance(&mut c, slot, j);
        });
    }
    // edges between column x and column x + 1, runs along y: one run per column, carried from
    // row to row
    let mut runs = vec![Run::NONE; x1 - x0 + 2];
    for y in y0..=y1 {
        let lo = y * w + x0 - 1;
        let n = x1 - x0 + 2;
        for_each_diff(
            &grid.cells[lo..lo + n],
            &grid.cells[lo + 1..lo + 1 + n],
            |j| {
                let slot = edge_slot(grid, region, &c, index, lo + j, lo + j + 1);
                runs[j].advance(&mut c, slot, y);
            },
        );
    }
    c
}

/// Call `f(j)` for every position where the two lines differ, lowest first, skipping equal
/// stretches eight cells at a time.
#[inline]
fn for_each_diff(a: &[Label], b: &[Label], mut f: impl FnMut(usize)) {
    let chunks = a.len() / 8;
    for (k, (ca, cb)) in a.chunks_exact(8).zip(b.chunks_exact(8)).enumerate() {
        if ca != cb {
            for j in (0..8).filter(|&j| ca[j] != cb[j]) {
                f(k * 8 + j);
            }
        }
    }
    for j in (chunks * 8..a.len()).filter(|&j| a[j] != b[j]) {
        f(j);
    }
}

/// A straight stretch of shared wall being followed along a line.
#[derive(Debug, Clone, Copy)]
struct Run {
    /// Contact slot of the stretch, or `usize::MAX` for none.
    slot: usize,
    len: u32,
    /// Position along the line of the stretch's last edge.
    at: usize,
}

impl Run {
    const NONE: Run = Run {
        slot: usize::MAX,
        len: 0,
        at: 0,
    };

    /// Edge `at` of the line has contact slot `slot` (`usize::MAX`: no contact). Edges not offered
    /// between two calls broke the stretch.
    #[inline]
    fn advance(&mut self, c: &mut Contacts, slot: usize, at: usize) {
        if slot == usize::MAX {
            self.slot = usize::MAX;
            return;
        }
        if slot == self.slot && at == self.at + 1 {
            self.len += 1;
        } else {
            self.slot = slot;
            self.len = 1;
        }
        self.at = at;
        c.total[slot] += 1;
        if self.len > c.longest[slot] {
            c.longest[slot] = self.len;
        }
    }
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

/// Number of 4-connected pieces of every round label inside the region, in one pass
/// (`index[label]` is the label's round position or -1).
///
/// Works on runs rather than cells: each row's runs of one label are joined (union–find) with the
/// runs of the same label they touch in the row below; a label's pieces are its runs less the
/// joins that merged two pieces.
pub fn pieces_all(
    grid: &Grid,
    region: &Region,
    index: &[i16],
    n_round: usize,
    s: &mut Scratch,
) -> Vec<u32> {
    let w = grid.w;
    let (x0, y0, x1, y1) = region.bbox;
    let mut out = vec![0u32; n_round];
    let round = |i: usize| match index.get(grid.cells[i] as usize) {
        Some(&k) if k >= 0 && region.inside[i] => Some(k as usize),
        _ => None,
    };
    // (first x, last x, run id); the previous row's runs are `runs[below.clone()]`
    let runs = &mut s.runs;
    let parent = &mut s.parent;
    runs.clear();
    parent.clear();
    let mut below = 0..0;
    for y in y0..=y1 {
        let row = y * w;
        let start = runs.len();
        let mut p = below.start;
        let mut x = x0;
        while x <= x1 {
            let Some(k) = round(row + x) else {
                x += 1;
                continue;
            };
            let l = grid.cells[row + x];
            let mut end = x;
            while end < x1 && grid.cells[row + end + 1] == l && region.inside[row + end + 1] {
                end += 1;
            }
            let id = parent.len() as u32;
            parent.push(id);
            runs.push((x as u32, end as u32, id));
            out[k] += 1;
            // runs below that end left of this one cannot touch it or any later run of the row
            while p < below.end && (runs[p].1 as usize) < x {
                p += 1;
            }
            let mut q = p;
            while q < below.end && (runs[q].0 as usize) <= end {
                let (bx, _, bid) = runs[q];
                if grid.cells[row - w + bx as usize] == l && union(parent, id, bid) {
                    out[k] -= 1;
                }
                q += 1;
            }
            x = end + 1;
        }
        below = start..runs.len();
    }
    out
}

/// Join the sets of `a` and `b`; false when they were one set already.
#[inline]
fn union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra == rb {
        return false;
    }
    parent[ra as usize] = rb;
    true
}

#[inline]
fn find(parent: &mut [u32], mut a: u32) -> u32 {
    while parent[a as usize] != a {
        let up = parent[parent[a as usize] as usize];
        parent[a as usize] = up;
        a = up;
    }
    a
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
    let bw = x1 - x0 + 1;
    let cover = square_coverage(grid, region.bbox, label, width);
    (y0..=y1).all(|y| {
        (x0..=x1)
            .all(|x| grid.cells[y * grid.w + x] != label || cover[(y - y0) * (bw + 1) + x - x0] > 0)
    })
}

/// How many `width × width` squares of `label` cover each cell of `bbox` (row-major, row stride
/// the box's width plus one): the side of the largest same-label square ending at each cell
/// (dynamic programming), each big enough square stamped onto a 2-D difference array whose
/// prefix sums are the counts.
pub fn square_coverage(
    grid: &Grid,
    bbox: (usize, usize, usize, usize),
    label: Label,
    width: usize,
) -> Vec<i32> {
    let (x0, y0, x1, y1) = bbox;
    let sides = square_sides(grid, bbox, label);
    coverage_of_sides(&sides, x1 - x0 + 1, y1 - y0 + 1, width)
}

/// The side of the largest `label` square ending (bottom-right) at each cell of `bbox`, row by
/// row (0 off the label): the dynamic programme behind [`square_coverage`], which a caller
/// judging one room at several widths runs once.
pub fn square_sides(grid: &Grid, bbox: (usize, usize, usize, usize), label: Label) -> Vec<u16> {
    let (x0, y0, x1, y1) = bbox;
    let (bw, bh) = (x1 - x0 + 1, y1 - y0 + 1);
    let mut sq = vec![0u16; bw * bh];
    for y in 0..bh {
        for x in 0..bw {
            if grid.cells[(y + y0) * grid.w + x + x0] != label {
                continue;
            }
            sq[y * bw + x] = if x == 0 || y == 0 {
                1
            } else {
                1 + sq[y * bw + x - 1]
                    .min(sq[(y - 1) * bw + x])
                    .min(sq[(y - 1) * bw + x - 1])
            };
        }
    }
    sq
}

/// [`square_coverage`] from the square sides of a `bw × bh` box ([`square_sides`]).
pub fn coverage_of_sides(sides: &[u16], bw: usize, bh: usize, width: usize) -> Vec<i32> {
    let mut diff = vec![0i32; (bw + 1) * (bh + 1)];
    for y in 0..bh {
        for x in 0..bw {
            if (sides[y * bw + x] as usize) < width.max(1) {
                continue;
            }
            let (ax, ay) = (x + 1 - width, y + 1 - width);
            diff[ay * (bw + 1) + ax] += 1;
            diff[ay * (bw + 1) + x + 1] -= 1;
            diff[(y + 1) * (bw + 1) + ax] -= 1;
            diff[(y + 1) * (bw + 1) + x + 1] += 1;
        }
    }
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
    diff
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::{parse_rows, random_case};

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

    /// Contacts by definition: every edge touching the region between a round room and another
    /// room, with straight stretches followed along each grid line.
    fn contacts_ref(g: &Grid, r: &Region, index: &[i16], n_round: usize) -> Contacts {
        let mut c = Contacts {
            n_labels: index.len(),
            total: vec![0; n_round * index.len()],
            longest: vec![0; n_round * index.len()],
        };
        let w = g.w;
        let mut lines: Vec<Vec<(usize, usize)>> = Vec::new();
        for y in 0..g.h - 1 {
            lines.push((0..w).map(|x| (y * w + x, (y + 1) * w + x)).collect());
        }
        for x in 0..w - 1 {
            lines.push((0..g.h).map(|y| (y * w + x, y * w + x + 1)).collect());
        }
        for line in lines {
            let mut prev = None;
            let mut run = 0;
            for (i, j) in line {
                let (a, b) = (g.cells[i], g.cells[j]);
                let slot = (a != b && is_room(a) && is_room(b) && (r.inside[i] || r.inside[j]))
                    .then(|| c.slot(index, a, b))
                    .flatten();
                run = if slot.is_some() && slot == prev {
                    run + 1
                } else {
                    1
                };
                prev = slot;
                if let Some(s) = slot {
                    c.total[s] += 1;
                    c.longest[s] = c.longest[s].max(run);
                }
            }
        }
        c
    }

    /// Pieces by definition: a flood fill from every unvisited region cell of a round label.
    fn pieces_ref(g: &Grid, r: &Region, index: &[i16], n_round: usize) -> Vec<u32> {
        let mut seen = vec![false; g.cells.len()];
        let mut out = vec![0; n_round];
        for &c in &r.cells {
            let c = c as usize;
            let l = g.cells[c];
            let k = index.get(l as usize).copied().unwrap_or(-1);
            if seen[c] || k < 0 {
                continue;
            }
            out[k as usize] += 1;
            let mut stack = vec![c];
            seen[c] = true;
            while let Some(c) = stack.pop() {
                for n in [c - 1, c + 1, c - g.w, c + g.w] {
                    if !seen[n] && r.inside[n] && g.cells[n] == l {
                        seen[n] = true;
                        stack.push(n);
                    }
                }
            }
        }
        out
    }

    #[test]
    fn contacts_and_pieces_match_their_definitions_on_random_grids() {
        use rand::SeedableRng;
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(11);
        let mut s = Scratch::new(0);
        for _ in 0..3000 {
            let (g, r, index, n_round) = random_case(&mut rng);
            if r.is_empty() {
                continue;
            }
            s.stamp.resize(g.cells.len(), 0);
            let (got, want) = (
                measure_contacts(&g, &r, &index, n_round),
                contacts_ref(&g, &r, &index, n_round),
            );
            assert_eq!((got.total, got.longest), (want.total, want.longest));
            assert_eq!(
                pieces_all(&g, &r, &index, n_round, &mut s),
                pieces_ref(&g, &r, &index, n_round)
            );
        }
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
