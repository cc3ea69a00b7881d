//! Rooms brought up to their minimums once every cut round is done, and each round's rooms
//! toward their targets after it is cut (issue 14).
//!
//! Growth caps each room at its target, so a child seeded among siblings that reach theirs first
//! stops short, and the round's parent (a hub, a corridor) keeps the cells no child reached. The
//! rounds cannot see that a room ended below its design table's minimum area or clear width, or
//! longer than its proportions allow; this pass can, on the finished floor. A move is one of
//!
//! - a face: the cells one step beyond the room in one direction change hands, a row or a
//!   column of the room's width, so rooms stay rectangular where they were; from one neighbour
//!   (the donor), one straight run of it, or the whole face across all its neighbours;
//! - a slide: a donor that cannot spare the face's cells takes as many from the room beyond it,
//!   each of its lines across the face moving over by one cell (a corridor strip between short
//!   rooms and a hub with cells to spare);
//! - a hand-off: a piece of the room that no square of its clear width covers goes to the
//!   neighbour it shares most wall with.
//!
//! A move is taken only when
//!
//! - the room's shortfall (cells below its minimum area; when more than a tenth of it is narrower
//!   than its clear width, the cells beyond that tenth plus its length times the width it lacks
//!   short of one cell; box length beyond its aspect times its width) falls, and the rooms'
//!   total shortfall falls;
//! - no room gains a defect it did not have (below area, below width, too elongated, a sliver:
//!   more than a tenth of it in parts no 3 × 3 square covers, no 3 × 3 square at all) nor more
//!   cells under its solver width rule;
//! - every room that gives cells stays in one piece, its 2 × 2 blocks too where they were (no
//!   neck one cell wide), and every graph edge and every run of exterior wall of the rooms that
//!   reached the minimum contact still does;
//! - no cell crosses a fixed wall, cores never change, and with regions given no cell leaves
//!   its first-round region.
//!
//! The move that lowers the shortfall most (then moves fewest cells, then comes first) wins, and
//! the total shortfall falls with every move, so the pass ends. Everything is counted in cells
//! of the solver grid, so the result is deterministic.

use crate::grid::{Grid, Label, Walls, EMPTY, OUTSIDE};
use crate::topology::{coverage_of_sides, square_coverage, square_sides};

/// What a room must reach, per label (index = label).
pub struct Minimums<'a> {
    /// Minimum area in cells (0: none).
    pub cells: &'a [usize],
    /// Clear width in cells that nine tenths of the room must have (≤ 1: none).
    pub clear: &'a [usize],
    /// The solver's width rule in cells (≤ 1: none): never more cells under it than before.
    pub rule: &'a [usize],
    /// Longest box side over the shortest (≤ 0: none, as for circulation).
    pub aspect: &'a [f64],
    /// Labels that never change (cores).
    pub fixed: &'a [bool],
    /// Graph edges as label pairs.
    pub edges: &'a [(Label, Label)],
    /// Per label, its first-round region: cells move only within one (None: anywhere).
    pub region: Option<&'a [Label]>,
    /// Straight shared run, in cell edges, that realises an edge or a window wall.
    pub contact: u32,
}

/// Moves per room in one pass, and passes over the floor.
const MAX_STEPS: usize = 24;
const MAX_PASSES: usize = 3;
/// Side (cells) of the square a usable part of a room holds: 1.5 m at 0.5 m cells, what the
/// realism measure's "wider than 1 m" comes to on the grid.
const USABLE: usize = 3;
/// Share of a room that may lie in parts narrower than a width.
const TOLERANCE: f64 = 0.10;

type BBox = (usize, usize, usize, usize);
/// A move: its gain in shortfall, its size in cells, and each cell with the label it takes.
type Move = (usize, usize, Vec<(usize, Label)>);

/// One room's measures.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Measure {
    count: usize,
    bbox: BBox,
    /// Cells below the minimum area.
    short: usize,
    /// Below the clear width (more than a tenth of the room no square of it covers): its
    /// length times the cells of width it lacks short of one, plus the cells beyond the tenth
    /// that no square of the clear width covers.
    thin: usize,
    /// Box length beyond the aspect, times the box's short side (cells).
    long: usize,
    /// Cells under the solver's width rule.
    ruled: usize,
    sliver: bool,
    no_square: bool,
}

impl Measure {
    fn shortfall(&self) -> usize {
        self.short + self.thin + self.long
    }

    /// Defects as flags: below area, below width, elongated, sliver, no usable square.
    fn defects(&self) -> [bool; 5] {
        [
            self.short > 0,
            self.thin > 0,
            self.long > 0,
            self.sliver,
            self.no_square,
        ]
    }

    /// True when `after` has a defect `self` lacks, or more cells under the solver rule.
    fn worsened_by(&self, after: &Measure) -> bool {
        let (b, a) = (self.defects(), after.defects());
        (0..5).any(|k| a[k] && !b[k]) || after.ruled > self.ruled
    }
}

/// Bring the rooms of `grid` (padded solver grid) up to `min` where a neighbour can give the
/// cells. Returns the number of moves made.
pub fn repair(grid: &mut Grid, walls: &Walls, min: &Minimums) -> usize {
    let n = min.cells.len();
    let mut moved = 0;
    for _ in 0..MAX_PASSES {
        let mut any = false;
        for r in 0..n {
            if min.fixed[r] {
                continue;
            }
            let r = r as Label;
            for _ in 0..MAX_STEPS {
                let Some(before) = measure(grid, r, None, min) else {
                    break;
                };
                if before.shortfall() == 0 {
                    break;
                }
                let grow = best_move(grid, walls, min, r, &before);
                let shed = best_shed(grid, walls, min, r, &before);
                // the larger gain wins, then the fewer cells, then growing
                let cells = match (grow, shed) {
                    (Some((g, k, cells)), Some((h, m, _, _))) if g > h || (g == h && k <= m) => {
                        cells
                    }
                    (_, Some((_, _, cells, d))) => cells.into_iter().map(|c| (c, d)).collect(),
                    (Some((_, _, cells)), None) => cells,
                    (None, None) => break,
                };
                for (c, to) in cells {
                    grid.cells[c] = to;
                }
                moved += 1;
                any = true;
            }
        }
        if !any {
            break;
        }
    }
    moved
}

/// The best face move for room `r`, if any passes: its gain, its size and its cells with the
/// labels they take.
fn best_move(
    grid: &mut Grid,
    walls: &Walls,
    min: &Minimums,
    r: Label,
    before: &Measure,
) -> Option<Move> {
    let w = grid.w;
    let (x0, y0, x1, y1) = before.bbox;
    let mut best: Option<Move> = None;
    let steps: [isize; 4] = [-1, 1, -(w as isize), w as isize];
    let mut faces: Vec<(Label, Vec<usize>)> = Vec::new();
    let mut cache: Vec<(Label, Donor)> = Vec::new();
    for &step in &steps {
        faces.clear();
        for y in y0..=y1 {
            for c in (y * w + x0)..=(y * w + x1) {
                if grid.cells[c] != r {
                    continue;
                }
                let x = (c as isize + step) as usize;
                let d = grid.cells[x];
                if d == r
                    || d == OUTSIDE
                    || d == EMPTY
                    || min.fixed[d as usize]
                    || min.region.is_some_and(|g| g[d as usize] != g[r as usize])
                {
                    continue;
                }
                // the new cell may not share a fixed wall with any cell of the room
                if walls.any
                    && [x - 1, x + 1, x - w, x + w]
                        .iter()
                        .any(|&m| grid.cells[m] == r && walls.blocked(x, m))
                {
                    continue;
                }
                match faces.iter_mut().find(|(l, _)| *l == d) {
                    Some((_, v)) => v.push(x),
                    None => faces.push((d, vec![x])),
                }
            }
        }
        for (d, _) in &faces {
            if !cache.iter().any(|(l, _)| l == d) {
                if let Some(donor) = Donor::new(grid, min, r, *d, before) {
                    cache.push((*d, donor));
                }
            }
        }
        // options: the whole face against one donor, each straight run of it on its own when it
        // has several (taking all of them may cut the donor or end one of its contacts), and the
        // whole face across every donor at once (a room can need two neighbours' cells to shed
        // a defect that either alone leaves)
        let mut options: Vec<Vec<(Label, Vec<usize>)>> = Vec::new();
        for (d, cells) in &faces {
            let along = if step.unsigned_abs() == 1 { w } else { 1 };
            let mut sorted = cells.clone();
            sorted.sort_unstable_by_key(|&c| {
                if along == 1 {
                    (c / w, c % w)
                } else {
                    (c % w, c / w)
                }
            });
            let mut runs: Vec<Vec<usize>> = Vec::new();
            for &c in &sorted {
                match runs.last_mut() {
                    Some(run) if run.last().is_some_and(|&p| p + along == c) => run.push(c),
                    _ => runs.push(vec![c]),
                }
            }
            options.push(vec![(*d, cells.clone())]);
            if runs.len() > 1 {
                options.extend(runs.into_iter().map(|run| vec![(*d, run)]));
            }
        }
        if faces.len() > 1 {
            options.push(faces.clone());
        }
        for option in options {
            let mut parts: Vec<(Label, &Donor, &[usize])> = Vec::with_capacity(option.len());
            for (d, cells) in &option {
                let Some((_, donor)) = cache.iter().find(|(l, _)| l == d) else {
                    break;
                };
                parts.push((*d, donor, cells));
            }
            if parts.len() < option.len() {
                continue;
            }
            let size: usize = option.iter().map(|(_, c)| c.len()).sum();
            let assigned = match try_move(grid, min, r, &parts, before) {
                Some(gain) => Some((
                    gain,
                    option
                        .iter()
                        .flat_map(|(_, c)| c.iter().map(|&c| (c, r)))
                        .collect(),
                )),
                // a donor that cannot spare the cells may slide over by them (see `push`)
                None if parts.len() == 1 => push(grid, walls, min, r, parts[0], step, before),
                None => None,
            };
            let Some((gain, cells)) = assigned else {
                continue;
            };
            let better = match &best {
                None => true,
                Some((g, k, _)) => gain > *g || (gain == *g && size < *k),
            };
            if better {
                best = Some((gain, size, cells));
            }
        }
    }
    best
}

/// The best hand-off of a part of room `r` narrower than its clear width, if any passes: each
/// 4-connected piece of the cells its clear width's squares leave uncovered may go to the
/// neighbour it shares most wall with (a strip along a corridor widens the corridor, a nub
/// joins the room beside it). Returns the gain, the size, the cells and the neighbour.
fn best_shed(
    grid: &mut Grid,
    walls: &Walls,
    min: &Minimums,
    r: Label,
    before: &Measure,
) -> Option<(usize, usize, Vec<usize>, Label)> {
    if before.thin == 0 {
        return None;
    }
    let ri = r as usize;
    let narrow = uncovered_cells(grid, before.bbox, r, min.clear[ri]);
    let keep = before.count - narrow.len();
    if keep == 0 || keep < min.cells.get(ri).copied().unwrap_or(0) {
        return None;
    }
    let w = grid.w;
    let mut seen = vec![false; narrow.len()];
    let mut best: Option<(usize, usize, Vec<usize>, Label)> = None;
    for start in 0..narrow.len() {
        if seen[start] {
            continue;
        }
        // one piece: a flood over the narrow cells (sorted, so membership is a binary search)
        seen[start] = true;
        let mut piece = vec![narrow[start]];
        let mut k = 0;
        while k < piece.len() {
            let c = piece[k];
            k += 1;
            for m in [c - 1, c + 1, c - w, c + w] {
                if let Ok(i) = narrow.binary_search(&m) {
                    if !seen[i] {
                        seen[i] = true;
                        piece.push(m);
                    }
                }
            }
        }
        // the neighbour with the most wall along the piece; none across a fixed wall, which
        // would then run inside it
        let mut contact: Vec<(Label, usize, bool)> = Vec::new();
        for &c in &piece {
            for m in [c - 1, c + 1, c - w, c + w] {
                let d = grid.cells[m];
                if d == r
                    || d == OUTSIDE
                    || d == EMPTY
                    || min.fixed[d as usize]
                    || min.region.is_some_and(|g| g[d as usize] != g[ri])
                {
                    continue;
                }
                let blocked = walls.any && walls.blocked(c, m);
                match contact.iter_mut().find(|(l, _, _)| *l == d) {
                    Some(e) => {
                        e.1 += 1;
                        e.2 |= blocked;
                    }
                    None => contact.push((d, 1, blocked)),
                }
            }
        }
        let Some(&(d, _, _)) = contact
            .iter()
            .filter(|(_, _, blocked)| !blocked)
            .max_by_key(|(l, n, _)| (*n, std::cmp::Reverse(*l)))
        else {
            continue;
        };
        let Some(before_d) = measure(grid, d, None, min) else {
            continue;
        };
        let Some(giver) = Donor::new(grid, min, d, r, &before_d) else {
            continue;
        };
        let Some(gain) = try_shed(grid, min, r, d, &giver, &piece, &before_d) else {
            continue;
        };
        let better = match &best {
            None => true,
            Some((g, n, _, _)) => gain > *g || (gain == *g && piece.len() < *n),
        };
        if better {
            best = Some((gain, piece.len(), piece, d));
        }
    }
    best
}

/// Hand `cells` of room `r` (measured in `giver`) to neighbour `d` tentatively; the gain in
/// shortfall when every condition holds. The grid is left as it was.
fn try_shed(
    grid: &mut Grid,
    min: &Minimums,
    r: Label,
    d: Label,
    giver: &Donor,
    cells: &[usize],
    before_d: &Measure,
) -> Option<usize> {
    for &c in cells {
        grid.cells[c] = d;
    }
    let verdict = (|| {
        let before_r = &giver.before;
        let after_r = measure(grid, r, Some(before_r.bbox), min)?;
        if before_r.worsened_by(&after_r) || after_r.shortfall() >= before_r.shortfall() {
            return None;
        }
        let grown = cells
            .iter()
            .fold(before_d.bbox, |b, &c| extend(b, c, grid.w));
        let after_d = measure(grid, d, Some(grown), min)?;
        if before_d.worsened_by(&after_d) {
            return None;
        }
        let was = before_r.shortfall() + before_d.shortfall();
        let now = after_r.shortfall() + after_d.shortfall();
        if now >= was
            || !connected(grid, r, after_r.bbox)
            || (giver.whole && !blocks_connected(grid, r, after_r.bbox))
        {
            return None;
        }
        if giver
            .kept
            .iter()
            .any(|&(a, b)| !has_contact(grid, a, b, giver.both, min.contact))
        {
            return None;
        }
        Some(was - now)
    })();
    for &c in cells {
        grid.cells[c] = r;
    }
    verdict
}

/// Room `r` takes `cells` from donor `d`, which takes as many one step further on from the room
/// beyond it, `e`: each line of `d` across the face slides by one cell, so a corridor strip
/// between short rooms and a hub that kept too much moves over rather than narrowing. Every
/// line must end on the same `e`. Returns the gain and the cells with their new labels.
fn push(
    grid: &mut Grid,
    walls: &Walls,
    min: &Minimums,
    r: Label,
    (d, donor, cells): (Label, &Donor, &[usize]),
    step: isize,
    before: &Measure,
) -> Option<(usize, Vec<(usize, Label)>)> {
    let w = grid.w;
    let mut e = None;
    let mut far = Vec::with_capacity(cells.len());
    for &x in cells {
        let mut y = x;
        while grid.cells[y] == d {
            y = (y as isize + step) as usize;
        }
        let l = grid.cells[y];
        if l == r
            || l == OUTSIDE
            || l == EMPTY
            || min.fixed[l as usize]
            || min.region.is_some_and(|g| g[l as usize] != g[d as usize])
            || *e.get_or_insert(l) != l
        {
            return None;
        }
        // the cell joining `d` may not share a fixed wall with it
        if walls.any
            && [y - 1, y + 1, y - w, y + w]
                .iter()
                .any(|&m| grid.cells[m] == d && walls.blocked(y, m))
        {
            return None;
        }
        far.push(y);
    }
    let e = e?;
    let behind = Donor::new(grid, min, d, e, &donor.before)?;
    for &x in cells {
        grid.cells[x] = r;
    }
    for &y in &far {
        grid.cells[y] = d;
    }
    let verdict = (|| {
        let grown = cells.iter().fold(before.bbox, |b, &c| extend(b, c, w));
        let after_r = measure(grid, r, Some(grown), min)?;
        if before.worsened_by(&after_r) || after_r.shortfall() >= before.shortfall() {
            return None;
        }
        let moved = far.iter().fold(donor.before.bbox, |b, &c| extend(b, c, w));
        let after_d = measure(grid, d, Some(moved), min)?;
        let after_e = measure(grid, e, Some(behind.before.bbox), min)?;
        if donor.before.worsened_by(&after_d) || behind.before.worsened_by(&after_e) {
            return None;
        }
        let was = before.shortfall() + donor.before.shortfall() + behind.before.shortfall();
        let now = after_r.shortfall() + after_d.shortfall() + after_e.shortfall();
        if now >= was {
            return None;
        }
        for (l, bbox, whole) in [
            (d, after_d.bbox, donor.whole),
            (e, after_e.bbox, behind.whole),
        ] {
            if !connected(grid, l, bbox) || (whole && !blocks_connected(grid, l, bbox)) {
                return None;
            }
        }
        let all = (
            donor.both.0.min(behind.both.0),
            donor.both.1.min(behind.both.1),
            donor.both.2.max(behind.both.2),
            donor.both.3.max(behind.both.3),
        );
        let all = far.iter().fold(all, |b, &c| extend(b, c, w));
        if donor
            .kept
            .iter()
            .chain(&behind.kept)
            .any(|&(a, b)| !has_contact(grid, a, b, all, min.contact))
        {
            return None;
        }
        Some(was - now)
    })();
    for &y in &far {
        grid.cells[y] = e;
    }
    for &x in cells {
        grid.cells[x] = d;
    }
    let gain = verdict?;
    Some((
        gain,
        cells
            .iter()
            .map(|&x| (x, r))
            .chain(far.iter().map(|&y| (y, d)))
            .collect(),
    ))
}

/// A donor as it stands before any move of this step: its measures, and the contacts of the two
/// rooms that reach the minimum (each must still reach it after a move).
struct Donor {
    before: Measure,
    /// A box holding every cell of the room and of the donor, before and after a move.
    both: BBox,
    kept: Vec<(Label, Label)>,
    /// The donor's 2 × 2 blocks form one piece (an agent two cells wide crosses it).
    whole: bool,
}

impl Donor {
    fn new(grid: &Grid, min: &Minimums, r: Label, d: Label, before_r: &Measure) -> Option<Donor> {
        let before = measure(grid, d, None, min)?;
        let both = (
            before_r.bbox.0.min(before.bbox.0),
            before_r.bbox.1.min(before.bbox.1),
            before_r.bbox.2.max(before.bbox.2),
            before_r.bbox.3.max(before.bbox.3),
        );
        let kept = min
            .edges
            .iter()
            .copied()
            .filter(|&(a, b)| a == r || b == r || a == d || b == d)
            .chain([(r, OUTSIDE), (d, OUTSIDE)])
            .filter(|&(a, b)| has_contact(grid, a, b, both, min.contact))
            .collect();
        let whole = blocks_connected(grid, d, before.bbox);
        Some(Donor {
            before,
            both,
            kept,
            whole,
        })
    }
}

/// Apply the move (cells taken from one or more donors) tentatively; its gain in shortfall when
/// every condition holds. The grid is left as it was. The cheap tests on the growing room come
/// first.
fn try_move(
    grid: &mut Grid,
    min: &Minimums,
    r: Label,
    parts: &[(Label, &Donor, &[usize])],
    before_r: &Measure,
) -> Option<usize> {
    for (_, _, cells) in parts {
        for &c in cells.iter() {
            grid.cells[c] = r;
        }
    }
    let verdict = (|| {
        let grown = parts
            .iter()
            .flat_map(|(_, _, cells)| cells.iter())
            .fold(before_r.bbox, |b, &c| extend(b, c, grid.w));
        let after_r = measure(grid, r, Some(grown), min)?;
        if before_r.worsened_by(&after_r) || after_r.shortfall() >= before_r.shortfall() {
            return None;
        }
        let (mut was, mut now) = (before_r.shortfall(), after_r.shortfall());
        let mut after_ds = Vec::with_capacity(parts.len());
        for (d, donor, _) in parts {
            let after_d = measure(grid, *d, Some(donor.before.bbox), min)?;
            if donor.before.worsened_by(&after_d) {
                return None;
            }
            was += donor.before.shortfall();
            now += after_d.shortfall();
            after_ds.push(after_d);
        }
        if now >= was {
            return None;
        }
        for ((d, donor, _), after_d) in parts.iter().zip(&after_ds) {
            if !connected(grid, *d, after_d.bbox)
                || (donor.whole && !blocks_connected(grid, *d, after_d.bbox))
                || donor
                    .kept
                    .iter()
                    .any(|&(a, b)| !has_contact(grid, a, b, donor.both, min.contact))
            {
                return None;
            }
        }
        Some(was - now)
    })();
    for (d, _, cells) in parts {
        for &c in cells.iter() {
            grid.cells[c] = *d;
        }
    }
    verdict
}

fn extend(b: BBox, c: usize, w: usize) -> BBox {
    let (x, y) = (c % w, c / w);
    (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y))
}

/// Measures of room `l`, searching `within` (its bounding box or a box holding it; None: the
/// whole grid). None when the room has no cell.
fn measure(grid: &Grid, l: Label, within: Option<BBox>, min: &Minimums) -> Option<Measure> {
    let w = grid.w;
    let (sx0, sy0, sx1, sy1) = within.unwrap_or((0, 0, w - 1, grid.h - 1));
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    let mut count = 0;
    for y in sy0..=sy1 {
        for x in sx0..=sx1 {
            if grid.cells[y * w + x] == l {
                count += 1;
                x0 = x0.min(x);
                y0 = y0.min(y);
                x1 = x1.max(x);
                y1 = y1.max(y);
            }
        }
    }
    if count == 0 {
        return None;
    }
    let bbox = (x0, y0, x1, y1);
    let li = l as usize;
    let tolerated = (TOLERANCE * count as f64).floor() as usize;
    let clear = min.clear.get(li).copied().unwrap_or(0);
    let (bw, bh) = (x1 - x0 + 1, y1 - y0 + 1);
    let (short_side, long_side) = (bw.min(bh), bw.max(bh));
    // how far the room's own clear width falls short of the rule, along its length: widening
    // lowers it, lengthening a room that is still too narrow does not
    // the square sides are worked out once and each width's count kept: a room is judged at
    // its clear width (several times while halving), its rule and the usable square
    let mut squares = Squares::new(grid, bbox, l);
    let thin = if clear > 1 && squares.uncovered(clear) > tolerated {
        // the widest square side below the rule that still covers all but the tenth (the share
        // it leaves uncovered grows with the side, so halving finds it)
        let (mut lo, mut hi) = (0, clear);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if squares.uncovered(mid) <= tolerated {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        // the widths it lacks below the rule along its length, plus the cells the rule's
        // squares leave uncovered beyond the tenth: widening one stretch of a room counts
        let own = lo;
        (clear - own - 1) * long_side + squares.uncovered(clear) - tolerated
    } else {
        0
    };
    let rule = min.rule.get(li).copied().unwrap_or(0);
    let ruled = if rule > 1 { squares.uncovered(rule) } else { 0 };
    let usable = squares.uncovered(USABLE);
    let aspect = min.aspect.get(li).copied().unwrap_or(0.0);
    let long = if aspect > 0.0 && long_side as f64 > aspect * short_side as f64 {
        ((long_side as f64 - aspect * short_side as f64).ceil() as usize) * short_side
    } else {
        0
    };
    Some(Measure {
        count,
        bbox,
        short: min
            .cells
            .get(li)
            .copied()
            .unwrap_or(0)
            .saturating_sub(count),
        thin,
        long,
        ruled,
        sliver: usable > tolerated,
        no_square: usable == count,
    })
}

/// Room `l`'s squares inside its bounding box, for counting the cells no square of a width
/// covers at several widths: the squares' sides are worked out once ([`square_sides`]).
struct Squares {
    sides: Vec<u16>,
    bw: usize,
    bh: usize,
    /// (width, uncovered cells) already counted
    counted: Vec<(usize, usize)>,
}

impl Squares {
    fn new(grid: &Grid, bbox: BBox, l: Label) -> Self {
        let (x0, y0, x1, y1) = bbox;
        Squares {
            sides: square_sides(grid, bbox, l),
            bw: x1 - x0 + 1,
            bh: y1 - y0 + 1,
            counted: Vec::new(),
        }
    }

    /// The cells of the room that no `width × width` square of it covers.
    fn uncovered(&mut self, width: usize) -> usize {
        if let Some(&(_, n)) = self.counted.iter().find(|&&(w, _)| w == width) {
            return n;
        }
        let (bw, bh) = (self.bw, self.bh);
        let cover = coverage_of_sides(&self.sides, bw, bh, width);
        let n = (0..bh)
            .flat_map(|y| (0..bw).map(move |x| (x, y)))
            .filter(|&(x, y)| self.sides[y * bw + x] > 0 && cover[y * (bw + 1) + x] <= 0)
            .count();
        self.counted.push((width, n));
        n
    }
}

/// The cells (grid indices) of room `l` inside `bbox` that no `width × width` square of the room
/// covers.
fn uncovered_cells(grid: &Grid, bbox: BBox, l: Label, width: usize) -> Vec<usize> {
    let (x0, y0, x1, y1) = bbox;
    let bw = x1 - x0 + 1;
    let cover = square_coverage(grid, bbox, l, width);
    (y0..=y1)
        .flat_map(|y| (x0..=x1).map(move |x| y * grid.w + x))
        .filter(|&c| {
            grid.cells[c] == l && cover[(c / grid.w - y0) * (bw + 1) + c % grid.w - x0] <= 0
        })
        .collect()
}

/// Do the 2 × 2 blocks of room `l` (inside `bbox`) form one edge-connected set (or none)? A
/// room whose parts meet only through a neck one cell wide fails, as in
/// [`crate::cleanup::necked_room`]: blocks are named by their bottom-right cell, and two blocks
/// whose names are edge neighbours overlap in a passage two cells wide.
fn blocks_connected(grid: &Grid, l: Label, bbox: BBox) -> bool {
    let w = grid.w;
    let (x0, y0, x1, y1) = bbox;
    let bw = x1 - x0 + 1;
    let local = |c: usize| (c / w - y0) * bw + (c % w - x0);
    let mut block = vec![false; bw * (y1 - y0 + 1)];
    let mut start = None;
    let mut total = 0usize;
    for y in (y0 + 1)..=y1 {
        for c in (y * w + x0 + 1)..=(y * w + x1) {
            if grid.cells[c] == l
                && grid.cells[c - 1] == l
                && grid.cells[c - w] == l
                && grid.cells[c - w - 1] == l
            {
                block[local(c)] = true;
                total += 1;
                start.get_or_insert(c);
            }
        }
    }
    let Some(start) = start else {
        return true;
    };
    block[local(start)] = false;
    let mut stack = vec![start];
    let mut reached = 1usize;
    while let Some(c) = stack.pop() {
        for m in [c - 1, c + 1, c - w, c + w] {
            // a block's name lies in the box past its first row and column
            let (mx, my) = (m % w, m / w);
            if mx > x0 && mx <= x1 && my > y0 && my <= y1 && block[local(m)] {
                block[local(m)] = false;
                reached += 1;
                stack.push(m);
            }
        }
    }
    reached == total
}

/// Is room `l` (inside `bbox`) one 4-connected piece?
fn connected(grid: &Grid, l: Label, bbox: BBox) -> bool {
    let w = grid.w;
    let (x0, y0, x1, y1) = bbox;
    let bw = x1 - x0 + 1;
    let local = |c: usize| (c / w - y0) * bw + (c % w - x0);
    let mut seen = vec![false; bw * (y1 - y0 + 1)];
    let mut total = 0usize;
    let mut start = None;
    for y in y0..=y1 {
        for c in (y * w + x0)..=(y * w + x1) {
            if grid.cells[c] == l {
                total += 1;
                start.get_or_insert(c);
            }
        }
    }
    let Some(start) = start else {
        return true;
    };
    seen[local(start)] = true;
    let mut stack = vec![start];
    let mut reached = 1usize;
    while let Some(c) = stack.pop() {
        for m in [c - 1, c + 1, c - w, c + w] {
            // a cell of the room lies in its box, so the box test only guards the index
            if grid.cells[m] == l && !seen[local(m)] {
                seen[local(m)] = true;
                reached += 1;
                stack.push(m);
            }
        }
    }
    reached == total
}

/// Whether rooms `a` and `b` (`b` may be [`OUTSIDE`]) share a straight run of at least `need`
/// cell edges among the edges of the cells in `bbox` (which must hold every cell of `a` or of
/// `b`). The repair asks this of every relation a move must keep, for every move it tries, so
/// the scan stops at the first run long enough and reads the grid row by row (the runs along a
/// column are kept per column instead of walking down it).
fn has_contact(grid: &Grid, a: Label, b: Label, bbox: BBox, need: u32) -> bool {
    if need == 0 {
        return true;
    }
    let w = grid.w;
    let (x0, y0, x1, y1) = (
        bbox.0.saturating_sub(1),
        bbox.1.saturating_sub(1),
        (bbox.2 + 1).min(w - 1),
        (bbox.3 + 1).min(grid.h - 1),
    );
    let pair = |p: Label, q: Label| (p == a && q == b) || (p == b && q == a);
    // edges between rows y and y + 1, runs along x
    for y in y0..y1 {
        let (row, up) = (&grid.cells[y * w..], &grid.cells[(y + 1) * w..]);
        let mut run = 0u32;
        for x in x0..=x1 {
            if pair(row[x], up[x]) {
                run += 1;
                if run >= need {
                    return true;
                }
            } else {
                run = 0;
            }
        }
    }
    // edges between columns x and x + 1, runs along y: one run per column, row by row
    let mut runs = vec![0u32; x1 - x0];
    for y in y0..=y1 {
        let row = &grid.cells[y * w..];
        for (i, x) in (x0..x1).enumerate() {
            if pair(row[x], row[x + 1]) {
                runs[i] += 1;
                if runs[i] >= need {
                    return true;
                }
            } else {
                runs[i] = 0;
            }
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::region::parse_rows;

    /// No fixed walls on a grid of up to `w × h` cells (tests' grids are smaller).
    fn open(w: usize, h: usize) -> Walls {
        Walls::none(w + 2, h + 2)
    }

    fn minimums<'a>(
        cells: &'a [usize],
        clear: &'a [usize],
        rule: &'a [usize],
        aspect: &'a [f64],
        fixed: &'a [bool],
        edges: &'a [(Label, Label)],
    ) -> Minimums<'a> {
        Minimums {
            cells,
            clear,
            rule,
            aspect,
            fixed,
            edges,
            region: None,
            contact: 2,
        }
    }

    #[test]
    fn a_donor_keeps_no_neck_one_cell_wide() {
        // room 1 (2 wide) asks 3 cells of clear width; the hall's column beside it is half of
        // the hall's only two-cell passage between its top and bottom, so it gives nothing
        let rows = [
            "########", "#110000#", "#110000#", "#110000#", "#1100###", "#1100###", "#110000#",
            "#110000#", "#110000#", "########",
        ];
        let (cells, clear, rule) = ([4, 4], [0, 3], [0, 0]);
        let (aspect, fixed) = ([0.0, 0.0], [false, false]);
        let mut g = parse_rows(&rows);
        let before = g.clone();
        let moved = repair(
            &mut g,
            &open(8, 10),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1)]),
        );
        assert_eq!(moved, 0);
        assert_eq!(g, before);
        // without the passage's walls, the hall gives the column
        let rows = [
            "########", "#110000#", "#110000#", "#110000#", "#110000#", "#110000#", "#110000#",
            "#110000#", "#110000#", "########",
        ];
        let mut g = parse_rows(&rows);
        let moved = repair(
            &mut g,
            &open(8, 10),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1)]),
        );
        assert!(moved >= 1);
        assert!(blocks_connected(&g, 0, (0, 0, 7, 9)));
    }

    #[test]
    fn a_strip_between_a_narrow_room_and_a_hall_slides_over() {
        // room 1 asks 3 cells of clear width; the strip (2) beside it must stay 2 cells wide,
        // so it cannot give a column, but it can slide into the hall, which has columns to spare
        let rows = [
            "##########",
            "#11220000#",
            "#11220000#",
            "#11220000#",
            "#11220000#",
            "#11220000#",
            "#11220000#",
            "##########",
        ];
        let (cells, clear, rule) = ([0, 0, 0], [0, 3, 2], [0, 0, 0]);
        let (aspect, fixed) = ([0.0, 0.0, 0.0], [false, false, false]);
        let mut g = parse_rows(&rows);
        let moved = repair(
            &mut g,
            &open(10, 8),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 2), (2, 1)]),
        );
        assert_eq!(moved, 1);
        assert_eq!(
            g,
            parse_rows(&[
                "##########",
                "#11122000#",
                "#11122000#",
                "#11122000#",
                "#11122000#",
                "#11122000#",
                "#11122000#",
                "##########",
            ])
        );
    }

    #[test]
    fn blocks_connected_finds_a_one_cell_neck() {
        let necked = parse_rows(&["######", "#11#1#", "#1111#", "#11#1#", "######"]);
        assert!(blocks_connected(&necked, 1, (0, 0, 5, 4)));
        let split = parse_rows(&["#######", "#11#11#", "#11111#", "#11#11#", "#######"]);
        assert!(!blocks_connected(&split, 1, (0, 0, 6, 4)));
    }

    #[test]
    fn cells_stay_in_their_first_round_region_when_asked() {
        // room 1 is short; the hall (0) could give a row, but the hall is another first-round
        // region than room 1 and room 2 (cut from room 2's region), which has none to spare
        let rows = [
            "#######", "#11122#", "#11122#", "#11122#", "#00000#", "#00000#", "#######",
        ];
        let (cells, clear, rule) = ([4, 12, 6], [0, 0, 0], [0, 0, 0]);
        let (aspect, fixed) = ([0.0, 0.0, 0.0], [false, false, false]);
        let region: [Label; 3] = [0, 2, 2];
        let mut g = parse_rows(&rows);
        let before = g.clone();
        let kept = Minimums {
            region: Some(&region),
            ..minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 2), (2, 1)])
        };
        assert_eq!(repair(&mut g, &open(7, 7), &kept), 0);
        assert_eq!(g, before);
        // without regions the hall gives its row
        let free = minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 2), (2, 1)]);
        assert!(repair(&mut g, &open(7, 7), &free) >= 1);
        assert!(g.count(1) >= 12);
    }

    #[test]
    fn a_short_room_takes_a_row_from_the_hall_that_kept_it() {
        // room 1 (3 × 3 = 9 cells) must reach 12 cells; the hall (0) keeps plenty below it
        let mut g = parse_rows(&[
            "#######", "#11100#", "#11100#", "#11100#", "#00000#", "#00000#", "#######",
        ]);
        let before = g.clone();
        let (cells, clear, rule) = ([4, 12], [0, 0], [0, 0]);
        let (aspect, fixed) = ([0.0, 3.0], [false, false]);
        let moved = repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1)]),
        );
        assert!(moved >= 1);
        assert!(g.count(1) >= 12, "room 1 has {} cells", g.count(1));
        assert_eq!(g.count(0) + g.count(1), before.count(0) + before.count(1));
        // still rectangular: its cells fill its box
        let m = measure(
            &g,
            1,
            None,
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[]),
        )
        .unwrap();
        let (x0, y0, x1, y1) = m.bbox;
        assert_eq!(m.count, (x1 - x0 + 1) * (y1 - y0 + 1));
    }

    #[test]
    fn a_donor_at_its_own_minimum_gives_nothing() {
        let mut g = parse_rows(&["#######", "#11100#", "#11100#", "#11100#", "#######"]);
        let before = g.clone();
        // the hall needs all of its 6 cells
        let (cells, clear, rule, aspect, fixed) =
            ([6, 12], [0, 0], [0, 0], [0.0, 0.0], [false, false]);
        let moved = repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[]),
        );
        assert_eq!(moved, 0);
        assert_eq!(g, before);
    }

    #[test]
    fn a_room_too_narrow_for_its_clear_width_widens_without_cutting_the_corridor_in_two() {
        // room 1 is 2 cells wide and must be 3; the corridor (0) may not be split
        let mut g = parse_rows(&[
            "########", "#110000#", "#110000#", "#110000#", "#110000#", "########",
        ]);
        let (cells, clear, rule, aspect, fixed) =
            ([0, 0], [0, 3], [0, 0], [0.0, 0.0], [false, false]);
        repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1)]),
        );
        let m = minimums(&cells, &clear, &rule, &aspect, &fixed, &[]);
        assert_eq!(measure(&g, 1, None, &m).unwrap().thin, 0);
        assert!(connected(&g, 0, measure(&g, 0, None, &m).unwrap().bbox));
    }

    #[test]
    fn a_realised_edge_holds() {
        // room 1 (4 cells) must reach 6. The hall needs all it has, so only room 2 could give
        // its left column, and that would end room 2's two-edge contact with the hall (edge 0–2).
        let rows = ["######", "#1122#", "#1122#", "#0000#", "######"];
        let (cells, clear, rule, aspect, fixed) =
            ([4, 6, 1], [0, 0, 0], [0, 0, 0], [0.0; 3], [false; 3]);
        let mut g = parse_rows(&rows);
        let before = g.clone();
        let moved = repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1), (0, 2)]),
        );
        assert_eq!((moved, &g), (0, &before));
        // without that edge the column moves
        let mut g = parse_rows(&rows);
        let moved = repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[(0, 1)]),
        );
        assert_eq!((moved, g.count(1)), (1, 6));
    }

    #[test]
    fn no_cell_crosses_a_fixed_wall() {
        // room 1 (6 cells) must reach 9: the hall's row below would do it in one move, but a
        // fixed wall runs between them, so it grows sideways
        let mut g = parse_rows(&[
            "#######", "#11100#", "#11100#", "#00000#", "#00000#", "#######",
        ]);
        let mut walls = Walls::none(g.w, g.h);
        // parse_rows pads a ring and puts the first row on top: room 1 holds rows y = 4, 5
        for x in 2..=6 {
            walls.block_horizontal(x, 4);
        }
        let (cells, clear, rule, aspect, fixed) = ([1, 9], [0, 0], [0, 0], [0.0; 2], [false; 2]);
        repair(
            &mut g,
            &walls,
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[]),
        );
        assert!(g.count(1) >= 9);
        for x in 2..=6 {
            assert_ne!(
                g.get(x, 3),
                1,
                "room 1 crossed the fixed wall at column {x}"
            );
        }
        // without the wall the row below is the bigger gain and is taken
        let mut g = parse_rows(&[
            "#######", "#11100#", "#11100#", "#00000#", "#00000#", "#######",
        ]);
        repair(
            &mut g,
            &open(7, 7),
            &minimums(&cells, &clear, &rule, &aspect, &fixed, &[]),
        );
        assert_eq!(g.get(2, 3), 1);
    }
}
