//! Constrained growth (Lopes et al. 2010, as used by the MANSION solver): rectangular growth, then
//! L-shaped growth, both capped at each room's target area. Gap filling is left to [`crate::cleanup`].
//!
//! The grid passed in has the round's region cells set to `EMPTY`; `EMPTY` therefore means "free in
//! this round" and no other cell is ever `EMPTY`.

use crate::grid::{Grid, Label, Walls, EMPTY};
use rand::Rng;
use serde::{Deserialize, Serialize};

/// Which side a room grows next in the rectangular phase.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GrowthRule {
    /// The side that keeps the room's centre closest to its seed (ties: the longest side). A room
    /// stays centred on its seed until a wall or a neighbour stops it on one side, then grows along
    /// the other axis; so a seed given as a room's centroid yields a room whose centroid is near
    /// it, which the longest-side rule does not (its rooms drift toward open space).
    #[default]
    Balanced,
    /// The longest free side first (Lopes et al. 2010), ties at random.
    Longest,
}

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

/// The rooms still growing in a phase, drawn with probability proportional to their target area.
#[derive(Default)]
struct Active {
    list: Vec<usize>,
    /// The sum of the listed rooms' weights, in list order; `None` once the list has changed.
    total: Option<f64>,
}

impl Active {
    /// List the growers still short of their targets.
    fn reset(&mut self, growers: &[Grower], area: &[usize]) {
        self.list.clear();
        self.list
            .extend((0..growers.len()).filter(|&k| (area[k] as f64) < growers[k].target));
        self.total = None;
    }

    fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// Drop the room at position `pos` (the list's order changes as in `Vec::swap_remove`).
    fn remove(&mut self, pos: usize) {
        self.list.swap_remove(pos);
        self.total = None;
    }

    /// Pick a position in the list with probability proportional to target area. The total is
    /// summed afresh (in list order, so exactly as before) only after the list has changed.
    fn pick<R: Rng>(&mut self, rng: &mut R, growers: &[Grower]) -> usize {
        let list = &self.list;
        let total = *self
            .total
            .get_or_insert_with(|| list.iter().map(|&k| growers[k].target.max(1.0)).sum());
        pick_weighted(rng, growers, list, total)
    }
}

/// Pick an index among `active` rooms with probability proportional to their target area, given
/// the sum of their weights.
fn pick_weighted<R: Rng>(rng: &mut R, growers: &[Grower], active: &[usize], total: f64) -> usize {
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

/// A bit per cell, kept both row-major and column-major so that every line test of the growth
/// phases (a whole side free? which cells beside a room are free?) is a few word operations
/// instead of a loop over cells. This is what keeps a 64×64 candidate in tens of microseconds.
#[derive(Clone, Default)]
struct Bits {
    wr: usize,
    wc: usize,
    rows: Vec<u64>,
    cols: Vec<u64>,
}

impl Bits {
    fn new(w: usize, h: usize) -> Self {
        let (wr, wc) = (w.div_ceil(64), h.div_ceil(64));
        Bits {
            wr,
            wc,
            rows: vec![0; wr * h],
            cols: vec![0; wc * w],
        }
    }

    #[inline]
    fn set(&mut self, x: usize, y: usize) {
        self.rows[y * self.wr + x / 64] |= 1 << (x % 64);
        self.cols[x * self.wc + y / 64] |= 1 << (y % 64);
    }

    /// Set (`on`) or clear cells `a..=b` of row `y`.
    #[inline]
    fn row_span(&mut self, y: usize, a: usize, b: usize, on: bool) {
        let line = &mut self.rows[y * self.wr..(y + 1) * self.wr];
        span(line, a, b, on, &mut self.cols, self.wc, y);
    }

    /// Set (`on`) or clear cells `a..=b` of column `x`.
    #[inline]
    fn col_span(&mut self, x: usize, a: usize, b: usize, on: bool) {
        let line = &mut self.cols[x * self.wc..(x + 1) * self.wc];
        span(line, a, b, on, &mut self.rows, self.wr, x);
    }

    /// Set the cells of the rectangle `x0..=x1` × `y0..=y1`: a few words per row and per column.
    fn fill_rect(&mut self, x0: usize, y0: usize, x1: usize, y1: usize) {
        // each word's mask once, then or-ed into every line
        for i in x0 / 64..=x1 / 64 {
            let m = word_mask(i, x0, x1);
            for y in y0..=y1 {
                self.rows[y * self.wr + i] |= m;
            }
        }
        for i in y0 / 64..=y1 / 64 {
            let m = word_mask(i, y0, y1);
            for x in x0..=x1 {
                self.cols[x * self.wc + i] |= m;
            }
        }
    }

    /// All bits clear, shaped like `like`.
    fn clear_like(&mut self, like: &Bits) {
        (self.wr, self.wc) = (like.wr, like.wc);
        self.rows.clear();
        self.rows.resize(like.rows.len(), 0);
        self.cols.clear();
        self.cols.resize(like.cols.len(), 0);
    }

    #[inline]
    fn row(&self, y: usize) -> &[u64] {
        &self.rows[y * self.wr..(y + 1) * self.wr]
    }

    #[inline]
    fn col(&self, x: usize) -> &[u64] {
        &self.cols[x * self.wc..(x + 1) * self.wc]
    }
}

/// Mask of bits `a..=b` within word `i`.
#[inline]
fn word_mask(i: usize, a: usize, b: usize) -> u64 {
    let lo = a.max(i * 64) - i * 64;
    let hi = b.min(i * 64 + 63) - i * 64;
    (u64::MAX >> (63 - hi)) & (u64::MAX << lo)
}

/// Set or clear bits `a..=b` of one line, a few words at a time, and bit `at` of each crossing
/// line `t` in `a..=b` (stored `stride` words apart in `cross`), one at a time.
#[inline]
fn span(
    line: &mut [u64],
    a: usize,
    b: usize,
    on: bool,
    cross: &mut [u64],
    stride: usize,
    at: usize,
) {
    // (an index loop: iterator chains here compiled to slower code, `skip`/`take` to calls of
    // `Take::nth`)
    #[allow(clippy::needless_range_loop)]
    for i in a / 64..=b / 64 {
        let m = word_mask(i, a, b);
        line[i] = if on { line[i] | m } else { line[i] & !m };
    }
    // word `at / 64` of each crossing line `a..=b`
    let m = 1u64 << (at % 64);
    let (first, last) = (a * stride + at / 64, b * stride + at / 64);
    let cross = &mut cross[..=last];
    let mut i = first;
    if on {
        while i <= last {
            cross[i] |= m;
            i += stride;
        }
    } else {
        while i <= last {
            cross[i] &= !m;
            i += stride;
        }
    }
}

/// Are bits `a..=b` all set? (`a > b` is an empty range: true.)
#[inline]
fn all_set(words: &[u64], a: usize, b: usize) -> bool {
    a > b
        || (a / 64..=b / 64).all(|i| {
            let m = word_mask(i, a, b);
            words[i] & m == m
        })
}

/// Are bits `a..=b` all clear?
#[inline]
fn none_set(words: &[u64], a: usize, b: usize) -> bool {
    a > b || (a / 64..=b / 64).all(|i| words[i] & word_mask(i, a, b) == 0)
}

/// Call `emit(start, len)` for every maximal run of set bits in `f`, lowest first.
#[inline]
fn for_each_run(f: &[u64], mut emit: impl FnMut(usize, usize)) {
    // a run that reached the top bit of the previous word and may go on in this one
    let (mut open_start, mut open_len) = (0usize, 0usize);
    for (i, &word) in f.iter().enumerate() {
        let mut word = word;
        if open_len > 0 {
            let ones = (!word).trailing_zeros() as usize;
            open_len += ones;
            if ones == 64 {
                continue;
            }
            emit(open_start, open_len);
            open_len = 0;
            word &= u64::MAX << ones;
        }
        while word != 0 {
            let start = word.trailing_zeros() as usize;
            let ones = (!(word >> start)).trailing_zeros() as usize;
            if start + ones == 64 {
                (open_start, open_len) = (i * 64 + start, ones);
                break;
            }
            emit(i * 64 + start, ones);
            word &= !(((1u64 << ones) - 1) << start);
        }
    }
    if open_len > 0 {
        emit(open_start, open_len);
    }
}

/// Fixed walls as bits: `v` has the vertical edge left of cell (x, y) at (x, y) on a `(w + 1) × h`
/// grid, `h` the horizontal edge below cell (x, y) on a `w × (h + 1)` grid.
struct WallBits {
    v: Bits,
    h: Bits,
}

impl WallBits {
    fn new(walls: &Walls, w: usize, h: usize) -> Self {
        let mut v = Bits::new(w + 1, h);
        let mut hz = Bits::new(w, h + 1);
        if walls.any {
            for y in 0..h {
                for x in 0..=w {
                    if walls.v[y * (w + 1) + x] {
                        v.set(x, y);
                    }
                }
            }
            for y in 0..=h {
                for x in 0..w {
                    if walls.hz[y * w + x] {
                        hz.set(x, y);
                    }
                }
            }
        }
        WallBits { v, h: hz }
    }
}

/// What every candidate of a round starts from: the round's free cells and its fixed walls as
/// bits, built once per round rather than once per candidate.
pub struct Field {
    free: Bits,
    walls: Option<WallBits>,
}

impl Field {
    /// `grid` has the round's free cells `EMPTY`.
    pub fn new(grid: &Grid, walls: &Walls) -> Self {
        let (w, h) = (grid.w, grid.h);
        let mut free = Bits::new(w, h);
        for (y, row) in grid.cells.chunks_exact(w).enumerate() {
            for (x, &c) in row.iter().enumerate() {
                if c == EMPTY {
                    free.set(x, y);
                }
            }
        }
        Field {
            free,
            walls: walls.any.then(|| WallBits::new(walls, w, h)),
        }
    }
}

/// Buffers of [`grow_in`], reused from one candidate to the next.
#[derive(Default)]
pub struct GrowScratch {
    free: Bits,
    rooms: Vec<Bits>,
    area: Vec<usize>,
    bbox: Vec<(usize, usize, usize, usize)>,
    active: Active,
    /// Per room, the sides (bit `side`) not yet found shut in the rectangular phase.
    live: Vec<u8>,
    /// Seed cells as (x, y).
    seed_xy: Vec<(i64, i64)>,
    runs: RunScratch,
}

/// Grow every room from its seed cell. `seeds[k]` is the flat index of grower `k`'s seed, which must
/// be an `EMPTY` cell; seeds must be distinct. Returns each grower's area in cells.
pub fn grow<R: Rng>(
    grid: &mut Grid,
    walls: &Walls,
    growers: &[Grower],
    seeds: &[usize],
    rule: GrowthRule,
    rng: &mut R,
) -> Vec<usize> {
    let field = Field::new(grid, walls);
    let mut s = GrowScratch::default();
    grow_in(&field, &mut s, grid, walls, growers, seeds, rule, rng).to_vec()
}

/// [`grow`] from a prepared [`Field`] (of this very grid) with reused buffers.
// The hot path of every candidate: plain arguments, no per-call struct to assemble.
#[allow(clippy::too_many_arguments)]
pub fn grow_in<'s, R: Rng>(
    field: &Field,
    s: &'s mut GrowScratch,
    grid: &mut Grid,
    walls: &Walls,
    growers: &[Grower],
    seeds: &[usize],
    rule: GrowthRule,
    rng: &mut R,
) -> &'s [usize] {
    let w = grid.w;
    let n = growers.len();
    let wb = field.walls.as_ref();
    let free = &mut s.free;
    free.clone_from(&field.free);
    s.area.clear();
    s.area.resize(n, 1);
    let area = &mut s.area;
    // Inclusive bounding boxes (x0, y0, x1, y1). During the rectangular phase they are the rooms,
    // and only the free bits are kept up to date: the grid's cells and the rooms' own bits are
    // written once that phase is over.
    s.bbox.clear();
    s.bbox
        .extend(seeds.iter().map(|&c| (c % w, c / w, c % w, c / w)));
    let bbox = &mut s.bbox;
    for &(x, y, _, _) in bbox.iter() {
        debug_assert_eq!(grid.cells[y * w + x], EMPTY);
        free.row_span(y, x, x, false);
    }

    // --- rectangular growth: add a whole free line beside one side ---
    let active = &mut s.active;
    active.reset(growers, area);
    // A side found shut (or over the cap) stays so for the rest of the phase: cells only ever
    // get taken, walls stay, the room's steps on other sides only lengthen the line beside it (a
    // superset of the cells and walls tested) and the cap only tightens as the room and the line
    // grow. So each room keeps a mask of the sides still worth testing.
    s.live.clear();
    s.live.resize(n, 0b1111);
    let live = &mut s.live;
    s.seed_xy.clear();
    s.seed_xy
        .extend(seeds.iter().map(|&c| ((c % w) as i64, (c / w) as i64)));
    let seed_xy = &s.seed_xy;
    while !active.is_empty() {
        let pos = active.pick(rng, growers);
        let k = active.list[pos];
        let (x0, y0, x1, y1) = bbox[k];
        let (tall, wide) = (y1 - y0 + 1, x1 - x0 + 1);
        let len_of = |side: u8| if side < 2 { tall } else { wide };
        let was_live = live[k];
        // Each side is tested at most once a step, and only if it can matter: `state[side]` is 0
        // until tested, then 1 (open) or 2 (shut or over the cap).
        let mut state = [0u8; 4];
        let mut test = |side: u8| -> bool {
            let i = side as usize;
            if state[i] == 0 {
                let open = live[k] & 1 << side != 0
                    && side_open(free, wb, bbox[k], side)
                    && within_cap(area[k], len_of(side), growers[k].target);
                if !open {
                    live[k] &= !(1 << side);
                }
                state[i] = if open { 1 } else { 2 };
            }
            state[i] == 1
        };
        let kept = keep_sides(rule, bbox[k], seed_xy[k], was_live, &mut test);
        if kept == 0 {
            active.remove(pos);
            continue;
        }
        // as (length, side), the longer pair of sides first
        let order: [u8; 4] = if wide > tall {
            [2, 3, 0, 1]
        } else {
            [0, 1, 2, 3]
        };
        let mut sides = [(0usize, 0u8); 4];
        let mut n_open = 0;
        for side in order {
            if kept & 1 << side != 0 {
                sides[n_open] = (len_of(side), side);
                n_open += 1;
            }
        }
        let sides = &sides[..n_open];
        let best = sides.iter().map(|s| s.0).max().unwrap_or(0);
        let n_ties = sides.iter().filter(|s| s.0 == best).count();
        let pick = if n_ties > 1 {
            rng.random_range(0..n_ties)
        } else {
            0
        };
        let side = sides
            .iter()
            .filter(|s| s.0 == best)
            .nth(pick)
            .map_or(0, |s| s.1);
        match side {
            0 | 1 => {
                let x = if side == 0 { x0 - 1 } else { x1 + 1 };
                free.col_span(x, y0, y1, false);
                bbox[k] = (x0.min(x), y0, x1.max(x), y1);
            }
            _ => {
                let y = if side == 2 { y0 - 1 } else { y1 + 1 };
                free.row_span(y, x0, x1, false);
                bbox[k] = (x0, y0.min(y), x1, y1.max(y));
            }
        }
        area[k] += best;
        if area[k] as f64 >= growers[k].target {
            active.remove(pos);
        }
    }
    // the rectangles into the grid, and into the rooms' own bits for the L-shaped phase
    s.rooms.resize_with(n, Bits::default);
    for ((room, &(x0, y0, x1, y1)), g) in s.rooms.iter_mut().zip(bbox.iter()).zip(growers) {
        for y in y0..=y1 {
            grid.cells[y * w + x0..=y * w + x1].fill(g.label);
        }
        room.clear_like(&field.free);
        room.fill_rect(x0, y0, x1, y1);
    }

    // --- L-shaped growth: extend by the longest run of free cells beside the room's own cells ---
    active.reset(growers, area);
    s.runs.f.resize(free.wr.max(free.wc), 0);
    s.runs.zeros.resize(free.wr.max(free.wc), 0);
    while !active.is_empty() {
        let pos = active.pick(rng, growers);
        let k = active.list[pos];
        let label = growers[k].label;
        let room = &mut s.rooms[k];
        match best_run(
            grid,
            walls,
            wb,
            free,
            room,
            label,
            bbox[k],
            &mut s.runs,
            rng,
        ) {
            Some(run) if within_cap(area[k], run.len, growers[k].target) => {
                let (sx, sy) = (run.start % w, run.start / w);
                let (ex, ey) = if run.horizontal {
                    let ex = sx + run.len - 1;
                    take_row(grid, free, sy, sx, ex, label);
                    room.row_span(sy, sx, ex, true);
                    (ex, sy)
                } else {
                    let ey = sy + run.len - 1;
                    take_col(grid, free, sx, sy, ey, label);
                    room.col_span(sx, sy, ey, true);
                    (sx, ey)
                };
                area[k] += run.len;
                let (x0, y0, x1, y1) = bbox[k];
                bbox[k] = (x0.min(sx), y0.min(sy), x1.max(ex), y1.max(ey));
                if area[k] as f64 >= growers[k].target {
                    active.remove(pos);
                }
            }
            _ => {
                active.remove(pos);
            }
        }
    }
    &s.area
}

/// The sides (bit `side`: 0 left, 1 right, 2 down, 3 up) a rectangular step of the box
/// `(x0, y0, x1, y1)` grown from `seed` may take under `rule`; `test(side)` says whether a side is
/// open (free, no wall, within the cap) and `live` has every side that may be. Each rule needs only
/// some sides tested: the longest-side rule the shorter pair only when neither longer side is open,
/// the balanced rule the sides in order of how far off the seed they would move the box's centre.
#[inline]
fn keep_sides(
    rule: GrowthRule,
    (x0, y0, x1, y1): (usize, usize, usize, usize),
    (sx, sy): (i64, i64),
    live: u8,
    test: &mut impl FnMut(u8) -> bool,
) -> u8 {
    let (tall, wide) = (y1 - y0 + 1, x1 - x0 + 1);
    let mut kept = 0u8;
    match rule {
        GrowthRule::Longest => {
            // only the longest open sides can be chosen
            let (long, short) = if wide > tall {
                ([2u8, 3], [0u8, 1])
            } else {
                ([0, 1], [2, 3])
            };
            for side in long {
                if test(side) {
                    kept |= 1 << side;
                }
            }
            if tall == wide || kept == 0 {
                for side in short {
                    if test(side) {
                        kept |= 1 << side;
                    }
                }
            }
        }
        GrowthRule::Balanced => {
            // Keep the open sides whose new bounding box is centred closest to the seed cell
            // (squared offsets in half cells, so they compare exactly as integers); among those,
            // prefer an axis still open at both ends: a step that cannot be balanced by its
            // opposite side later pulls the room off its seed for good.
            let (a, b, c, d) = (x0 as i64, y0 as i64, x1 as i64, y1 as i64);
            let off2 = |dx: i64, dy: i64| dx * dx + dy * dy;
            let offs = [
                off2(a - 1 + c - 2 * sx, b + d - 2 * sy),
                off2(a + c + 1 - 2 * sx, b + d - 2 * sy),
                off2(a + c - 2 * sx, b - 1 + d - 2 * sy),
                off2(a + c - 2 * sx, b + d + 1 - 2 * sy),
            ];
            // the closest sides first, a group of equally close sides at a time
            let mut rest = live;
            while rest != 0 && kept == 0 {
                let closest = (0..4u8)
                    .filter(|&i| rest & 1 << i != 0)
                    .map(|i| offs[i as usize])
                    .min()
                    .unwrap_or(0);
                for side in 0..4u8 {
                    if rest & 1 << side != 0 && offs[side as usize] == closest {
                        rest &= !(1 << side);
                        if test(side) {
                            kept |= 1 << side;
                        }
                    }
                }
            }
            if kept.count_ones() > 1 {
                let mut both_open = 0u8;
                for side in 0..4u8 {
                    if kept & 1 << side != 0 && test(side ^ 1) {
                        both_open |= 1 << side;
                    }
                }
                if both_open != 0 {
                    kept = both_open;
                }
            }
        }
    }
    kept
}

/// Is the line of cells beside side `side` (0: left, 1: right, 2: down, 3: up) of the box
/// `(x0, y0, x1, y1)` all free, with no fixed wall between it and the box nor across it?
#[inline]
fn side_open(
    free: &Bits,
    wb: Option<&WallBits>,
    (x0, y0, x1, y1): (usize, usize, usize, usize),
    side: u8,
) -> bool {
    match side {
        0 => {
            all_set(free.col(x0 - 1), y0, y1)
                && wb.is_none_or(|b| {
                    none_set(b.v.col(x0), y0, y1) && none_set(b.h.col(x0 - 1), y0 + 1, y1)
                })
        }
        1 => {
            all_set(free.col(x1 + 1), y0, y1)
                && wb.is_none_or(|b| {
                    none_set(b.v.col(x1 + 1), y0, y1) && none_set(b.h.col(x1 + 1), y0 + 1, y1)
                })
        }
        2 => {
            all_set(free.row(y0 - 1), x0, x1)
                && wb.is_none_or(|b| {
                    none_set(b.h.row(y0), x0, x1) && none_set(b.v.row(y0 - 1), x0 + 1, x1)
                })
        }
        _ => {
            all_set(free.row(y1 + 1), x0, x1)
                && wb.is_none_or(|b| {
                    none_set(b.h.row(y1 + 1), x0, x1) && none_set(b.v.row(y1 + 1), x0 + 1, x1)
                })
        }
    }
}

/// Give cells `a..=b` of row `y` to `label`.
#[inline]
fn take_row(grid: &mut Grid, free: &mut Bits, y: usize, a: usize, b: usize, label: Label) {
    grid.cells[y * grid.w + a..=y * grid.w + b].fill(label);
    free.row_span(y, a, b, false);
}

/// Give cells `a..=b` of column `x` to `label`.
#[inline]
fn take_col(grid: &mut Grid, free: &mut Bits, x: usize, a: usize, b: usize, label: Label) {
    for y in a..=b {
        grid.cells[y * grid.w + x] = label;
    }
    free.col_span(x, a, b, false);
}

/// A run of free cells to add in the L-shaped phase.
#[derive(Debug, Clone, Copy)]
struct Run {
    start: usize,
    len: usize,
    horizontal: bool,
}

#[derive(Default)]
struct RunScratch {
    f: Vec<u64>,
    /// As many zero words as `f` has.
    zeros: Vec<u64>,
    /// Lines worth reading: (line, whether the free cells lie after it).
    lines: Vec<(usize, bool)>,
    best: Vec<Run>,
}

/// The lines `at` in `a..=b` (of `words` words each in `room` and `free`) where some room cell
/// has a free cell on the line before (`(at, false)`) or after (`(at, true)`), in that order.
fn touching(
    room: &[u64],
    free: &[u64],
    words: usize,
    a: usize,
    b: usize,
    out: &mut Vec<(usize, bool)>,
) {
    out.clear();
    let rooms = &room[a * words..(b + 1) * words];
    let below = &free[(a - 1) * words..b * words];
    let above = &free[(a + 1) * words..(b + 2) * words];
    // lines of one or two words (grids up to 128 cells across) get a fully unrolled loop
    match words {
        1 => touching_n::<1>(rooms, below, above, a, out),
        2 => touching_n::<2>(rooms, below, above, a, out),
        _ => {
            let lines = rooms.chunks_exact(words);
            let (lo, hi) = (below.chunks_exact(words), above.chunks_exact(words));
            for (k, ((r, lo), hi)) in lines.zip(lo).zip(hi).enumerate() {
                let meets = |f: &[u64]| r.iter().zip(f).any(|(x, y)| x & y != 0);
                touch(out, a + k, meets(lo), meets(hi));
            }
        }
    }
}

#[inline]
fn touching_n<const N: usize>(
    rooms: &[u64],
    below: &[u64],
    above: &[u64],
    a: usize,
    out: &mut Vec<(usize, bool)>,
) {
    let lines = rooms.chunks_exact(N);
    let (lo, hi) = (below.chunks_exact(N), above.chunks_exact(N));
    for (k, ((r, lo), hi)) in lines.zip(lo).zip(hi).enumerate() {
        let (mut m_lo, mut m_hi) = (0, 0);
        for i in 0..N {
            m_lo |= r[i] & lo[i];
            m_hi |= r[i] & hi[i];
        }
        touch(out, a + k, m_lo != 0, m_hi != 0);
    }
}

#[inline]
fn touch(out: &mut Vec<(usize, bool)>, at: usize, before: bool, after: bool) {
    if before {
        out.push((at, false));
    }
    if after {
        out.push((at, true));
    }
}

/// Keep `run` if it is at least as long as the best so far (runs of one cell only make spurs).
#[inline]
fn offer(run: Run, best_len: &mut usize, best: &mut Vec<Run>) {
    if run.len > *best_len {
        *best_len = run.len;
        best.clear();
    }
    if run.len == *best_len && run.len > 1 {
        best.push(run);
    }
}

/// The longest run (at least two cells) of free cells lying directly beyond the room's own cells on
/// one side; ties broken at random.
#[allow(clippy::too_many_arguments)]
fn best_run<R: Rng>(
    grid: &Grid,
    walls: &Walls,
    wb: Option<&WallBits>,
    free: &Bits,
    room: &Bits,
    label: Label,
    bbox: (usize, usize, usize, usize),
    s: &mut RunScratch,
    rng: &mut R,
) -> Option<Run> {
    let w = grid.w;
    let (x0, y0, x1, y1) = bbox;
    s.best.clear();
    let mut best_len = 1usize;
    // One line of candidate cells: without walls its maximal runs are the runs; with walls each
    // cell is vetted and runs split where a wall crosses the line.
    let mut line = |f: &[u64], sep: Option<&[u64]>, cell: &dyn Fn(usize) -> usize, horizontal| {
        if wb.is_none() {
            for_each_run(f, |p, len| {
                let run = Run {
                    start: cell(p),
                    len,
                    horizontal,
                };
                offer(run, &mut best_len, &mut s.best);
            });
        } else {
            scan_runs(
                f,
                sep,
                cell,
                horizontal,
                grid,
                walls,
                label,
                &mut best_len,
                &mut s.best,
            );
        }
    };
    // Few lines hold a candidate cell (most lie inside the room or against other rooms), so the
    // lines are first screened as whole words, then only those few are read cell by cell; the
    // walls' words read as zero when there are none.
    let no_walls = &s.zeros[..free.wr.max(free.wc)];
    // rows beyond the bottom and top of the room's cells: runs along x, split by vertical walls
    touching(&room.rows, &free.rows, free.wr, y0, y1, &mut s.lines);
    for &(y, up) in &s.lines {
        let ty = if up { y + 1 } else { y - 1 };
        let (rr, fr) = (room.row(y), free.row(ty));
        // the edge between the room cell and the new cell must be open
        let shut = wb.map_or(no_walls, |b| b.h.row(if up { ty } else { y }));
        let mut any = 0;
        for i in 0..free.wr {
            s.f[i] = rr[i] & fr[i] & !shut[i];
            any |= s.f[i];
        }
        if any != 0 {
            line(
                &s.f[..free.wr],
                wb.map(|b| b.v.row(ty)),
                &|x| ty * w + x,
                true,
            );
        }
    }
    // columns beyond the left and right of the room's cells: runs along y, split by horizontal walls
    touching(&room.cols, &free.cols, free.wc, x0, x1, &mut s.lines);
    for &(x, right) in &s.lines {
        let tx = if right { x + 1 } else { x - 1 };
        let (rc, fc) = (room.col(x), free.col(tx));
        let shut = wb.map_or(no_walls, |b| b.v.col(if right { tx } else { x }));
        let mut any = 0;
        for i in 0..free.wc {
            s.f[i] = rc[i] & fc[i] & !shut[i];
            any |= s.f[i];
        }
        if any != 0 {
            line(
                &s.f[..free.wc],
                wb.map(|b| b.h.col(tx)),
                &|y| y * w + tx,
                false,
            );
        }
    }
    if s.best.is_empty() {
        None
    } else {
        let i = if s.best.len() > 1 {
            rng.random_range(0..s.best.len())
        } else {
            0
        };
        Some(s.best[i])
    }
}

/// Walk the set bits of `f` (candidate cells along one line), joining consecutive bits into runs
/// unless a wall (`sep` bit at the later position) separates them, and keep the longest runs.
#[allow(clippy::too_many_arguments)]
#[inline]
fn scan_runs(
    f: &[u64],
    sep: Option<&[u64]>,
    cell: &dyn Fn(usize) -> usize,
    horizontal: bool,
    grid: &Grid,
    walls: &Walls,
    label: Label,
    best_len: &mut usize,
    best: &mut Vec<Run>,
) {
    let mut run_start = usize::MAX;
    let mut prev = usize::MAX;
    let mut len = 0usize;
    let mut close = |start: usize, len: usize| {
        let run = Run {
            start: cell(start),
            len,
            horizontal,
        };
        offer(run, best_len, best);
    };
    for (i, &w0) in f.iter().enumerate() {
        let mut word = w0;
        while word != 0 {
            let bit = word.trailing_zeros() as usize;
            word &= word - 1;
            let p = i * 64 + bit;
            // a new cell must not sit across a fixed wall from another cell of the same room
            if walls.any && !wall_ok(grid, walls, cell(p), label) {
                continue;
            }
            let joined =
                len > 0 && p == prev + 1 && sep.is_none_or(|sp| sp[p / 64] & (1 << (p % 64)) == 0);
            if joined {
                len += 1;
            } else {
                if len > 0 {
                    close(run_start, len);
                }
                run_start = p;
                len = 1;
            }
            prev = p;
        }
    }
    if len > 0 {
        close(run_start, len);
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

    const RULES: [GrowthRule; 2] = [GrowthRule::Balanced, GrowthRule::Longest];

    #[test]
    fn single_room_grows_to_its_target_as_a_rectangle() {
        for rule in RULES {
            let mut g = setup(10, 10);
            let walls = Walls::none(g.w, g.h);
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(1);
            let seed = g.idx(5, 5);
            let area = grow(
                &mut g,
                &walls,
                &[Grower {
                    label: 1,
                    target: 20.0,
                }],
                &[seed],
                rule,
                &mut rng,
            );
            assert!((18..=22).contains(&area[0]), "{rule:?}: area {}", area[0]);
            assert_eq!(g.count(1), area[0]);
        }
    }

    /// Centroid and bounding box (x0, y0, x1, y1) of a label's cells.
    fn shape_of(g: &Grid, label: Label) -> ([f64; 2], (usize, usize, usize, usize)) {
        let (mut sx, mut sy, mut n) = (0.0, 0.0, 0.0);
        let mut bb = (usize::MAX, usize::MAX, 0, 0);
        for y in 0..g.h {
            for x in 0..g.w {
                if g.get(x, y) == label {
                    sx += x as f64;
                    sy += y as f64;
                    n += 1.0;
                    bb = (bb.0.min(x), bb.1.min(y), bb.2.max(x), bb.3.max(y));
                }
            }
        }
        ([sx / n, sy / n], bb)
    }

    /// One room grown by the balanced rule on an open `w × h` region.
    fn grow_balanced(w: usize, h: usize, seed: (usize, usize), target: f64) -> Grid {
        let mut g = setup(w, h);
        let walls = Walls::none(g.w, g.h);
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        let seed = g.idx(seed.0, seed.1);
        let grower = Grower { label: 1, target };
        grow(
            &mut g,
            &walls,
            &[grower],
            &[seed],
            GrowthRule::Balanced,
            &mut rng,
        );
        g
    }

    #[test]
    fn balanced_growth_stays_centred_on_its_seed_in_open_space() {
        let g = grow_balanced(21, 21, (11, 11), 49.0);
        // a 7×7 square around the seed
        let (c, bb) = shape_of(&g, 1);
        assert_eq!(bb, (8, 8, 14, 14));
        assert_eq!(c, [11.0, 11.0]);
    }

    #[test]
    fn balanced_growth_stopped_by_a_wall_grows_along_it() {
        // The seed sits 2 cells from the region's left edge: the room takes the 5 columns the seed
        // centres and grows up and down for the rest, keeping its centroid on the seed.
        let g = grow_balanced(20, 20, (3, 10), 55.0);
        let (c, bb) = shape_of(&g, 1);
        assert_eq!((bb.0, bb.2), (1, 5), "bbox {bb:?}");
        assert_eq!(bb.3 - bb.1 + 1, 11, "bbox {bb:?}");
        assert_eq!(c, [3.0, 10.0]);
    }

    #[test]
    fn rooms_never_overlap_and_respect_targets() {
        let mut g = setup(16, 12);
        let walls = Walls::none(g.w, g.h);
        let growers = [
            Grower {
                label: 1,
                target: 80.0,
            },
            Grower {
                label: 2,
                target: 60.0,
            },
            Grower {
                label: 3,
                target: 52.0,
            },
        ];
        let seeds = [g.idx(3, 3), g.idx(12, 4), g.idx(8, 10)];
        for s in 0..40u64 {
            let mut gg = g.clone();
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(s);
            let rule = RULES[s as usize % 2];
            let area = grow(&mut gg, &walls, &growers, &seeds, rule, &mut rng);
            for (k, gr) in growers.iter().enumerate() {
                assert_eq!(gg.count(gr.label), area[k]);
                assert!(
                    (area[k] as f64) < gr.target * 1.5,
                    "room {k} overgrew: {}",
                    area[k]
                );
            }
        }
        let _ = &mut g;
    }

    #[test]
    fn growth_never_straddles_a_fixed_wall() {
        let g = setup(10, 6);
        let mut walls = Walls::none(g.w, g.h);
        // a full-height wall on the grid line left of padded column 5
        for y in 1..7 {
            walls.block_vertical(5, y);
        }
        for rule in RULES {
            let mut g = g.clone();
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(3);
            let seed = g.idx(2, 3);
            grow(
                &mut g,
                &walls,
                &[Grower {
                    label: 1,
                    target: 60.0,
                }],
                &[seed],
                rule,
                &mut rng,
            );
            for y in 1..7 {
                assert!(
                    g.get(5, y) != 1,
                    "{rule:?}: room crossed the wall at row {y}"
                );
            }
            assert!(g.count(1) <= 24);
        }
    }

    #[test]
    fn runs_of_bits_match_a_bit_by_bit_walk() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(5);
        for case in 0..2000 {
            let words = 1 + case % 3;
            // sparse, dense and all-ones words, so runs cross word boundaries
            let f: Vec<u64> = (0..words)
                .map(|_| match rng.random_range(0..4) {
                    0 => rng.random::<u64>() & rng.random::<u64>(),
                    1 => rng.random::<u64>() | rng.random::<u64>(),
                    2 => u64::MAX,
                    _ => u64::MAX << rng.random_range(0..64),
                })
                .collect();
            let mut want = Vec::new();
            let mut run: Option<(usize, usize)> = None;
            for p in 0..words * 64 {
                if f[p / 64] >> (p % 64) & 1 == 1 {
                    run = Some(run.map_or((p, 1), |(s, l)| (s, l + 1)));
                } else if let Some(r) = run.take() {
                    want.push(r);
                }
            }
            want.extend(run);
            let mut got = Vec::new();
            for_each_run(&f, |s, l| got.push((s, l)));
            assert_eq!(got, want, "{f:x?}");
        }
    }

    #[test]
    fn touching_lines_match_a_cell_by_cell_test() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(7);
        let mut got = Vec::new();
        for words in 1..=3 {
            for _ in 0..300 {
                let n = rng.random_range(3..12);
                let mut bits = |p: u64| -> Vec<u64> {
                    (0..n * words)
                        .map(|_| (0..p).fold(u64::MAX, |m, _| m & rng.random::<u64>()))
                        .collect()
                };
                let (room, free) = (bits(3), bits(2));
                let (a, b) = (1, n - 2);
                touching(&room, &free, words, a, b, &mut got);
                let meets = |r: usize, f: usize| {
                    (0..words).any(|i| room[r * words + i] & free[f * words + i] != 0)
                };
                let want: Vec<(usize, bool)> = (a..=b)
                    .flat_map(|at| [(at, false), (at, true)])
                    .filter(|&(at, after)| meets(at, if after { at + 1 } else { at - 1 }))
                    .collect();
                assert_eq!(got, want);
            }
        }
    }

    #[test]
    fn spans_set_and_clear_rows_and_columns_alike() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(9);
        let (w, h) = (130, 70);
        let mut spans = Bits::new(w, h);
        let mut cells = Bits::new(w, h);
        for _ in 0..500 {
            let on = rng.random_range(0..3) > 0;
            let (along, across) = if rng.random() { (w, h) } else { (h, w) };
            let a = rng.random_range(0..along);
            let b = rng.random_range(a..along);
            let at = rng.random_range(0..across);
            if along == w {
                spans.row_span(at, a, b, on);
            } else {
                spans.col_span(at, a, b, on);
            }
            for t in a..=b {
                let (x, y) = if along == w { (t, at) } else { (at, t) };
                let (r, c) = (y * cells.wr + x / 64, x * cells.wc + y / 64);
                if on {
                    cells.set(x, y);
                } else {
                    cells.rows[r] &= !(1 << (x % 64));
                    cells.cols[c] &= !(1 << (y % 64));
                }
            }
            assert!(spans.rows == cells.rows && spans.cols == cells.cols);
        }
    }

    #[test]
    fn rectangles_fill_rows_and_columns_alike() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(11);
        for (w, h) in [(10, 7), (66, 66), (130, 70)] {
            for _ in 0..200 {
                let x0 = rng.random_range(0..w);
                let x1 = rng.random_range(x0..w);
                let y0 = rng.random_range(0..h);
                let y1 = rng.random_range(y0..h);
                // a used buffer of another shape, cleared to this one
                let mut fast = Bits::new(h + 3, w + 5);
                fast.rows.fill(u64::MAX);
                fast.cols.fill(u64::MAX);
                fast.clear_like(&Bits::new(w, h));
                fast.fill_rect(x0, y0, x1, y1);
                let mut slow = Bits::new(w, h);
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        slow.set(x, y);
                    }
                }
                assert!(fast.rows == slow.rows && fast.cols == slow.cols);
            }
        }
    }

    #[test]
    fn weighted_picks_with_a_kept_total_match_a_fresh_sum() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(13);
        for case in 0..300 {
            let n = rng.random_range(1..25);
            let growers: Vec<Grower> = (0..n)
                .map(|k| Grower {
                    label: k as Label,
                    target: rng.random::<f64>() * 300.0 + if case % 3 == 0 { 0.0 } else { 0.3 },
                })
                .collect();
            let area = vec![0usize; n];
            let mut active = Active::default();
            active.reset(&growers, &area);
            let mut list = active.list.clone();
            let (mut fast, mut slow) = (
                Xoshiro256PlusPlus::seed_from_u64(case),
                Xoshiro256PlusPlus::seed_from_u64(case),
            );
            while !list.is_empty() {
                let total: f64 = list.iter().map(|&k| growers[k].target.max(1.0)).sum();
                let want = pick_weighted(&mut slow, &growers, &list, total);
                let got = active.pick(&mut fast, &growers);
                assert_eq!(got, want);
                // drop the picked room now and then, as the growth loops do
                if rng.random_range(0..4) == 0 {
                    active.remove(got);
                    list.swap_remove(want);
                }
                assert_eq!(active.list, list);
            }
            assert!(active.is_empty());
        }
    }

    /// The side selection as first written: every side tested in a fixed order, then the
    /// balanced rule's keys computed for all open sides.
    fn keep_sides_simply(
        rule: GrowthRule,
        (x0, y0, x1, y1): (usize, usize, usize, usize),
        (sx, sy): (i64, i64),
        open: [bool; 4],
    ) -> u8 {
        let (tall, wide) = (y1 - y0 + 1, x1 - x0 + 1);
        let order: [u8; 4] = if wide > tall {
            [2, 3, 0, 1]
        } else {
            [0, 1, 2, 3]
        };
        let mut sides = Vec::new();
        for (tested, &side) in order.iter().enumerate() {
            if rule == GrowthRule::Longest && tested == 2 && tall != wide && !sides.is_empty() {
                break;
            }
            if open[side as usize] {
                sides.push(side);
            }
        }
        if rule == GrowthRule::Balanced {
            let off = |side: u8| -> i64 {
                let (a, b, c, d) = (x0 as i64, y0 as i64, x1 as i64, y1 as i64);
                let (a, b, c, d) = match side {
                    0 => (a - 1, b, c, d),
                    1 => (a, b, c + 1, d),
                    2 => (a, b - 1, c, d),
                    _ => (a, b, c, d + 1),
                };
                let (dx, dy) = (a + c - 2 * sx, b + d - 2 * sy);
                dx * dx + dy * dy
            };
            let mask = sides.iter().fold(0u8, |m, s| m | 1 << s);
            let key = |side: u8| (off(side), u8::from(mask & 1 << (side ^ 1) == 0));
            let closest = sides.iter().map(|&s| key(s)).min().unwrap_or((0, 0));
            sides.retain(|&s| key(s) == closest);
        }
        sides.iter().fold(0u8, |m, s| m | 1 << s)
    }

    #[test]
    fn side_selection_matches_testing_every_side() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(17);
        for _ in 0..20_000 {
            let x0 = rng.random_range(1..20);
            let y0 = rng.random_range(1..20);
            let x1 = x0 + rng.random_range(0..6);
            let y1 = y0 + rng.random_range(0..6);
            // seeds inside the box, or just off it, so offsets tie often
            let sx = rng.random_range(x0 as i64 - 1..=x1 as i64 + 1);
            let sy = rng.random_range(y0 as i64 - 1..=y1 as i64 + 1);
            let open = [0; 4].map(|_| rng.random_range(0..3) > 0);
            // sides known shut may be left out of `live`; open ones never are
            let live = (0..4u8).fold(0u8, |m, i| {
                if open[i as usize] || rng.random() {
                    m | 1 << i
                } else {
                    m
                }
            });
            for rule in RULES {
                let mut test = |side: u8| open[side as usize];
                let got = keep_sides(rule, (x0, y0, x1, y1), (sx, sy), live, &mut test);
                let want = keep_sides_simply(rule, (x0, y0, x1, y1), (sx, sy), open);
                assert_eq!(
                    got,
                    want,
                    "{rule:?} box {:?} seed {:?} open {open:?} live {live:b}",
                    (x0, y0, x1, y1),
                    (sx, sy)
                );
            }
        }
    }

    #[test]
    fn same_seed_same_growth() {
        let g = setup(12, 12);
        let walls = Walls::none(g.w, g.h);
        let growers = [
            Grower {
                label: 1,
                target: 50.0,
            },
            Grower {
                label: 2,
                target: 60.0,
            },
        ];
        let seeds = [g.idx(3, 3), g.idx(9, 9)];
        let run = |s| {
            let mut gg = g.clone();
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(s);
            grow(
                &mut gg,
                &walls,
                &growers,
                &seeds,
                GrowthRule::Longest,
                &mut rng,
            );
            gg
        };
        assert_eq!(run(7), run(7));
    }
}
