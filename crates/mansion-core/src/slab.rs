//! The corridor typology cut: a round whose parent keeps the leftover (a corridor, a ward wing,
//! a hall) laid out the way designers lay out hotels, wards, schools and offices, instead of grown
//! from seeds. The parent becomes a straight corridor across its region, and the children become
//! slabs side by side along it: on both sides (double-loaded) or on one (single-loaded, the
//! corridor at the region's edge).
//!
//! Why: grown rooms end where a neighbour stopped them, so wide rooms (a 3.2 m ward, a 5.4 m
//! classroom) rarely keep their clear width, and the parent keeps whatever no child reached.
//! Slabs are rectangles wherever the region is, as deep as the band beside the corridor and as
//! wide along it as their area needs. They are candidates like the grown ones: the same cleanup,
//! width and topology filter and energy decide whether they win ([`crate::cut`]).

use crate::cut::Prepared;
use crate::grid::{Grid, Label, EMPTY};

/// Corridor widths a slab layout tries, in cells, at least (the parent's own rule or clear width
/// when wider, up to [`MAX_CORRIDOR`]).
const MIN_CORRIDOR: usize = 3;
/// Widest corridor band, in cells (3 m on the 0.5 m grid: a hospital's 2.4 m ward corridor fits).
const MAX_CORRIDOR: usize = 6;
/// A side band shallower than this, in cells, holds no rooms.
const MIN_DEPTH: usize = 3;

/// One axis of the grid: the corridor runs along `u`, rooms sit across it in `v`.
#[derive(Clone, Copy)]
enum Axis {
    /// A corridor running east–west (`u` = x).
    X,
    /// A corridor running north–south (`u` = y).
    Y,
}

impl Axis {
    fn uv(self, c: usize, w: usize) -> (usize, usize) {
        match self {
            Axis::X => (c % w, c / w),
            Axis::Y => (c / w, c % w),
        }
    }
    fn uv_f(self, p: [f64; 2]) -> (f64, f64) {
        match self {
            Axis::X => (p[0], p[1]),
            Axis::Y => (p[1], p[0]),
        }
    }
}

/// The slab layouts of a round: for each axis, the corridor's position and the split of the
/// children between its two sides that best match the sides' cells to the children's targets.
/// Empty when the round's parent does not keep the leftover or it has fewer than two children.
/// `clear`: each label's clear width in cells (the corridor's is its width when wider than its
/// rule).
pub fn layouts(p: &Prepared, clear: &[usize]) -> Vec<Grid> {
    let Some((parent, _)) = p.spec.remainder else {
        return vec![];
    };
    let k = p.labels.len() - 1; // children: every label but the remainder, which is last
    if k < 2 {
        return vec![];
    }
    let rule = p.widths[parent as usize] as usize;
    let own = clear.get(parent as usize).copied().unwrap_or(0);
    let wc = rule.max(own).clamp(MIN_CORRIDOR, MAX_CORRIDOR);
    let mut out = Vec::new();
    for axis in [Axis::X, Axis::Y] {
        for rank in 0..VARIANTS {
            if let Some(g) = layout(p, clear, parent, k, wc, axis, rank) {
                out.push(g);
            }
        }
    }
    out
}

/// Corridor positions tried per axis, best matched first: a region's notches leave some of them
/// with strips the width rules reject.
const VARIANTS: usize = 3;

fn layout(
    p: &Prepared,
    clear: &[usize],
    parent: Label,
    k: usize,
    wc: usize,
    axis: Axis,
    rank: usize,
) -> Option<Grid> {
    let w = p.region.w;
    // the region's cells the round hands out (the spine the parent keeps is laid out afresh)
    let free: Vec<usize> = p
        .region
        .cells
        .iter()
        .map(|&c| c as usize)
        .filter(|&c| p.base.cells[c] == EMPTY || p.base.cells[c] == parent)
        .collect();
    let (mut u0, mut u1, mut v0, mut v1) = (usize::MAX, 0, usize::MAX, 0);
    for &c in &free {
        let (u, v) = axis.uv(c, w);
        u0 = u0.min(u);
        u1 = u1.max(u);
        v0 = v0.min(v);
        v1 = v1.max(v);
    }
    if free.is_empty() || v1 + 1 - v0 < wc + MIN_DEPTH || u1 + 1 - u0 < 2 * MIN_DEPTH {
        return None;
    }
    let mut rows = vec![0usize; v1 + 2 - v0];
    for &c in &free {
        rows[axis.uv(c, w).1 - v0 + 1] += 1;
    }
    for i in 1..rows.len() {
        rows[i] += rows[i - 1]; // rows[i]: free cells with v < v0 + i
    }
    let below = |v: usize| rows[v - v0];
    let total = free.len();
    // children in order across the corridor (by their seeds), targets prefix-summed
    let mut across: Vec<usize> = (0..k).collect();
    let seed = |i: usize| axis.uv_f(p.seeds[i].unwrap_or([0.0, 0.0]));
    across.sort_by(|&a, &b| seed(a).1.total_cmp(&seed(b).1).then(a.cmp(&b)));
    let mut sums = vec![0.0; k + 1];
    for (j, &i) in across.iter().enumerate() {
        sums[j + 1] = sums[j] + p.targets[i];
    }
    // the deepest clear width among the first m children (low) and the rest (high)
    let mut deep_low = vec![MIN_DEPTH; k + 1];
    let mut deep_high = vec![MIN_DEPTH; k + 1];
    for j in 0..k {
        deep_low[j + 1] = deep_low[j].max(least(p, clear, across[j]));
        deep_high[k - 1 - j] = deep_high[k - j].max(least(p, clear, across[k - 1 - j]));
    }
    // the corridor at rows [vc, vc + wc) and the first m children below it
    let mut ranked: Vec<(f64, usize, usize)> = Vec::new();
    for vc in v0..=(v1 + 1 - wc) {
        let mut best: Option<(f64, usize, usize)> = None;
        let low = below(vc) as f64;
        let high = (total - below(vc + wc)) as f64;
        let (dl, dh) = (vc - v0, v1 + 1 - (vc + wc));
        for m in 0..=k {
            // a side holding rooms must be deep enough for them; one without none
            if (m > 0 && dl < deep_low[m]) || (m < k && dh < deep_high[m]) {
                continue;
            }
            let cost = (sums[m] - low).abs() + (sums[k] - sums[m] - high).abs();
            if best.is_none_or(|(b, _, _)| cost < b) {
                best = Some((cost, vc, m));
            }
        }
        ranked.extend(best);
    }
    ranked.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let (_, vc, m) = *ranked.get(rank)?;
    let mut grid = p.base.clone();
    for &c in &free {
        grid.cells[c] = EMPTY;
    }
    let band = |v: usize| v >= vc && v < vc + wc;
    // the corridor keeps only the columns where the region is its full width: a shallower piece
    // of it (a notch of the region) would be narrower than its rule, and goes to the rooms beside
    let mut depth = vec![0usize; u1 + 1 - u0];
    for &c in &free {
        let (u, v) = axis.uv(c, w);
        if band(v) {
            depth[u - u0] += 1;
        }
    }
    for &c in &free {
        let (u, v) = axis.uv(c, w);
        if band(v) && depth[u - u0] == wc {
            grid.cells[c] = parent;
        }
    }
    // the corridor reaches what the parent must touch outside the region (a core, the corridor
    // it branches from): a stub across the side band, where a slab boundary will fall
    let mut stubs: Vec<(usize, bool)> = Vec::new(); // (u, on the low side)
    for &(a, b) in &p.spec.required {
        let other = if a == parent {
            b
        } else if b == parent {
            a
        } else {
            continue;
        };
        if p.index.get(other as usize).is_some_and(|&i| i >= 0) {
            continue; // a child of this round
        }
        let touching: Vec<usize> = free
            .iter()
            .copied()
            .filter(|&c| {
                p.region
                    .neighbours(c)
                    .iter()
                    .any(|&n| grid.cells[n] == other)
            })
            .collect();
        if touching.iter().any(|&c| grid.cells[c] == parent) {
            continue;
        }
        // the contact cell nearest the band
        let gap = |c: usize| {
            let v = axis.uv(c, w).1;
            if v < vc {
                vc - v
            } else {
                (v + 1).saturating_sub(vc + wc)
            }
        };
        let Some(&end) = touching.iter().min_by_key(|&&c| (gap(c), c)) else {
            continue;
        };
        let (ue, ve) = axis.uv(end, w);
        if band(ve) {
            // a notch of the band the corridor left to the rooms: the band's rows from the contact
            // to the nearest column where the corridor is whole
            let Some(full) = (0..depth.len())
                .filter(|&i| depth[i] == wc)
                .min_by_key(|&i| (i + u0).abs_diff(ue))
            else {
                continue;
            };
            let (a, b) = (ue.min(full + u0), ue.max(full + u0));
            for &c in &free {
                let (u, v) = axis.uv(c, w);
                if band(v) && u >= a && u <= b {
                    grid.cells[c] = parent;
                }
            }
            continue;
        }
        let low = ve < vc;
        let width = MIN_CORRIDOR.min(u1 + 1 - u0);
        let us = ue.saturating_sub(width / 2).max(u0).min(u1 + 1 - width);
        for &c in &free {
            let (u, v) = axis.uv(c, w);
            let between = if low {
                v >= ve && v < vc
            } else {
                v >= vc + wc && v <= ve
            };
            if u >= us && u < us + width && between {
                grid.cells[c] = parent;
            }
        }
        stubs.push((us, low));
        stubs.push((us + width, low));
    }
    // each side: its children along the corridor by their seeds, each a run of whole columns
    // holding its share of the side's cells
    for (rooms, low) in [(&across[..m], true), (&across[m..], false)] {
        if rooms.is_empty() {
            continue;
        }
        let side = |v: usize| if low { v < vc } else { v >= vc + wc };
        let mut cols = vec![0usize; u1 + 1 - u0];
        for &c in &free {
            let (u, v) = axis.uv(c, w);
            if side(v) && grid.cells[c] == EMPTY {
                cols[u - u0] += 1;
            }
        }
        let mut order: Vec<usize> = rooms.to_vec();
        order.sort_by(|&a, &b| seed(a).0.total_cmp(&seed(b).0).then(a.cmp(&b)));
        let owner = columns(p, clear, &order, &cols, &stubs, u0, low)?;
        for &c in &free {
            let (u, v) = axis.uv(c, w);
            if side(v) && grid.cells[c] == EMPTY {
                grid.cells[c] = p.labels[owner[u - u0]];
            }
        }
    }
    // cells left over (a notch of the corridor band) join the room beside them across the band
    let step = match axis {
        Axis::X => w,
        Axis::Y => 1,
    };
    for &c in &free {
        if grid.cells[c] != EMPTY {
            continue;
        }
        for dir in [false, true] {
            let mut q = c;
            loop {
                q = if dir { q + step } else { q - step };
                if !p.region.inside[q] || grid.cells[q] != EMPTY {
                    break;
                }
            }
            let l = grid.cells[q];
            if p.region.inside[q] && l != parent && p.index.get(l as usize).is_some_and(|&i| i >= 0)
            {
                grid.cells[c] = l;
                break;
            }
        }
    }
    Some(grid)
}

/// The fewest cells across a room's slab: its clear width, or its width rule when wider (2 at
/// least).
fn least(p: &Prepared, clear: &[usize], i: usize) -> usize {
    let l = p.labels[i] as usize;
    (p.widths[l] as usize)
        .max(clear.get(l).copied().unwrap_or(0))
        .max(2)
}

/// The owner of each column of one side: the side's rooms in order along the corridor, each a run
/// of whole columns holding its share of the side's cells and at least as many columns as its
/// width rule, a room boundary at each stub's edge. None when the side is too short for the
/// rooms' rules.
fn columns(
    p: &Prepared,
    clear: &[usize],
    order: &[usize],
    cols: &[usize],
    stubs: &[(usize, bool)],
    u0: usize,
    low: bool,
) -> Option<Vec<usize>> {
    let span: Vec<usize> = (0..cols.len()).filter(|&u| cols[u] > 0).collect();
    let (first, last) = (*span.first()?, *span.last()?);
    let min_cols = |i: usize| least(p, clear, i);
    let need: usize = order.iter().map(|&i| min_cols(i)).sum();
    if need > last + 1 - first {
        return None;
    }
    let cap: usize = cols.iter().sum();
    let want: f64 = order.iter().map(|&i| p.targets[i]).sum();
    let scale = cap as f64 / want.max(1e-9);
    let mut owner = vec![order[0]; cols.len()];
    let (mut j, mut cum, mut bound) = (0, 0.0, p.targets[order[0]] * scale);
    let mut run = 0usize;
    for u in first..=last {
        // the columns the rooms after this one still need
        let rest: usize = order[j + 1..].iter().map(|&i| min_cols(i)).sum();
        let forced = stubs.iter().any(|&(s, l)| l == low && s == u + u0);
        let half = cols[u] as f64 / 2.0;
        let full = run >= min_cols(order[j]);
        if j + 1 < order.len() && full && (cum + half >= bound || forced || last + 1 - u <= rest) {
            j += 1;
            bound += p.targets[order[j]] * scale;
            run = 0;
        }
        owner[u] = order[j];
        cum += cols[u] as f64;
        run += 1;
    }
    (j + 1 == order.len()).then_some(owner)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cut::{cut, leftover_round, CutOptions, RoundSpec};
    use crate::grid::Walls;
    use crate::region::parse_rows;

    /// A 20 × 13 wing (parent 0, keeping the leftover) beside a stair (5) at its west end, cut
    /// into four rooms seeded two by two: south-west, south-east, north-west, north-east.
    fn wing() -> (Grid, RoundSpec) {
        let mut rows = vec!["5".to_string() + &"0".repeat(20); 13];
        rows[0] = "#".to_string() + &"0".repeat(20);
        let rows: Vec<&str> = rows.iter().map(|r| r.as_str()).collect();
        let grid = parse_rows(&rows);
        // padded grid: the wing's cells are x in 2..=21, y in 1..=13
        let seeds = [[6.0, 4.0], [17.0, 4.0], [6.0, 11.0], [17.0, 11.0]];
        let required = vec![(0, 1), (0, 2), (0, 3), (0, 4), (0, 5)];
        let names = ["wing", "a", "b", "c", "d", "stair"];
        let spec = leftover_round(50.0, seeds.to_vec(), 60.0, required, &names);
        (grid, spec)
    }

    fn options(slabs: bool) -> CutOptions {
        CutOptions {
            widths: vec![3; 6],
            clear: vec![0, 4, 4, 4, 4, 0],
            slabs,
            batch: 8,
            ..CutOptions::default()
        }
    }

    /// Cells, bounding box (x0, y0, x1, y1) of a label.
    fn extent(g: &Grid, l: Label) -> (usize, (usize, usize, usize, usize)) {
        let (mut n, mut b) = (0, (usize::MAX, usize::MAX, 0, 0));
        for (c, &x) in g.cells.iter().enumerate() {
            if x == l {
                let (u, v) = (c % g.w, c / g.w);
                n += 1;
                b = (b.0.min(u), b.1.min(v), b.2.max(u), b.3.max(v));
            }
        }
        (n, b)
    }

    #[test]
    fn a_wing_is_laid_out_as_rectangles_along_a_corridor_that_reaches_the_stair() {
        let (grid, spec) = wing();
        let walls = Walls::none(grid.w, grid.h);
        let opts = options(true);
        let p = Prepared::new(&grid, &walls, &spec, &opts, 6, 0);
        let layouts = layouts(&p, &opts.clear);
        // up to three corridor positions on each axis; those too shallow for the rooms' clear
        // widths are not tried
        assert!(!layouts.is_empty() && layouts.len() <= 2 * VARIANTS);
        let mut passed = 0;
        for g in layouts {
            for l in 1..=4 {
                let (n, (x0, y0, x1, y1)) = extent(&g, l);
                assert_eq!(n, (x1 + 1 - x0) * (y1 + 1 - y0), "room {l} is a rectangle");
                assert!(
                    x1 + 1 - x0 >= 4 && y1 + 1 - y0 >= 4,
                    "room {l} keeps its clear width"
                );
            }
            // the same filter as every candidate: rooms whole, every edge realised (the corridor
            // touches each room and the stair), widths kept
            if p.finish(g, &mut crate::cleanup::Scratch::new(grid.cells.len()))
                .is_ok()
            {
                passed += 1;
            }
        }
        assert!(passed > 0, "some slab layout passes the candidate filter");
    }

    #[test]
    fn slabs_on_a_wing_lower_the_energy_and_are_repeatable() {
        let (grid, spec) = wing();
        let walls = Walls::none(grid.w, grid.h);
        let grown = cut(&grid, &walls, &spec, &options(false), 6, 0).expect("grown");
        let slab = cut(&grid, &walls, &spec, &options(true), 6, 0).expect("with slabs");
        // the same grown candidates are drawn either way; here a slab layout wins (energy 7.3
        // against 62.6 for the best grown one), its rooms rectangles
        assert!(
            slab.energy < grown.energy,
            "{} >= {}",
            slab.energy,
            grown.energy
        );
        for l in 1..=4 {
            let (n, (x0, y0, x1, y1)) = extent(&slab.grid, l);
            assert_eq!(n, (x1 + 1 - x0) * (y1 + 1 - y0), "room {l} is a rectangle");
        }
        let again = cut(&grid, &walls, &spec, &options(true), 6, 0).expect("again");
        assert_eq!(again.grid.cells, slab.grid.cells);
    }

    #[test]
    fn no_slabs_without_a_leftover_parent_or_with_one_child() {
        let (grid, mut spec) = wing();
        let walls = Walls::none(grid.w, grid.h);
        let opts = options(true);
        spec.remainder = None;
        assert!(layouts(
            &Prepared::new(&grid, &walls, &spec, &opts, 6, 0),
            &opts.clear
        )
        .is_empty());
        let (grid, mut spec) = wing();
        spec.growers.truncate(1);
        spec.planned.truncate(1);
        assert!(layouts(
            &Prepared::new(&grid, &walls, &spec, &opts, 6, 0),
            &opts.clear
        )
        .is_empty());
    }
}
