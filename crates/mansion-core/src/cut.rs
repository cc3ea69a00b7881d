//! The topology-aware cutting node: adaptive seed sampling, a batch of candidates per retry (grow,
//! clean, check topology, score), retries with growing radii, and the Monte Carlo fallback.
//!
//! Candidates are independent, so a batch runs in parallel with rayon; each candidate draws from its
//! own RNG derived from `(rng_seed, round, retry, index)`, and the winner is the lowest energy with
//! ties to the lowest index, so the result never depends on the thread count.

use crate::cleanup::{self, Scratch};
use crate::energy::{self, RoomFeatures, Weights};
use crate::grid::{Grid, Label, Walls, EMPTY};
use crate::growth::{self, Field, GrowScratch, Grower, GrowthRule};
use crate::region::Region;
use crate::topology;
use rand::{Rng, SeedableRng};
use rand_xoshiro::Xoshiro256PlusPlus;
use rayon::prelude::*;
use std::collections::BTreeMap;

/// One cut round as the solver hands it to the cutting node. Coordinates are grid units of the
/// (padded) solver grid.
#[derive(Debug, Clone)]
pub struct RoundSpec {
    /// The label whose cells are cut.
    pub parent: Label,
    /// Rooms grown from seeds: the children, plus the parent when it has a seed of its own.
    pub growers: Vec<Grower>,
    /// Planned seed of each grower.
    pub planned: Vec<[f64; 2]>,
    /// The parent, when it keeps the leftover instead of growing; its target in cells.
    pub remainder: Option<(Label, f64)>,
    /// Cells kept for the remainder parent before growth (its spine to the rooms it must reach),
    /// which no child may take.
    pub reserved: Vec<usize>,
    /// Labels that no later round cuts: fixed walls and minimum width apply to them now.
    pub final_labels: Vec<Label>,
    /// Graph edges to check after this round (both ends exist, one of them in this round), with the
    /// names used in diagnostics.
    pub required: Vec<(Label, Label)>,
    /// Names of every label on the floor, for diagnostics.
    pub names: Vec<String>,
}

/// Sampling and scoring settings of the cutting node.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CutOptions {
    pub retries: usize,
    pub batch: usize,
    /// Radius multipliers, one per retry (the last one repeats).
    pub gammas: Vec<f64>,
    /// r_base in R⁰ = r_base + k·a_r/|Ω(parent)|, in cells (the paper fixes 2).
    pub r_base: f64,
    pub k: f64,
    /// Minimum distance between the seeds of one candidate, in cells.
    pub seed_separation: f64,
    /// Candidates tried by the Monte Carlo fallback.
    pub fallback_samples: usize,
    /// Shared wall needed for an edge to count as realised, in cell edges.
    pub min_contact: u32,
    /// Minimum room width in cells for every room, if any.
    pub min_width: Option<usize>,
    /// Each label's own minimum width in cells (indexed by label; 0 or 1, or a label past the
    /// end: no rule of its own). A room's rule is the larger of this and `min_width`.
    #[serde(default)]
    pub widths: Vec<usize>,
    pub weights: Weights,
    pub rng_seed: u64,
    /// Run every retry and keep the best survivor overall, instead of stopping at the first retry
    /// with a survivor (the paper's rule). Costs the whole budget; benchmarks use it.
    pub exhaustive: bool,
    /// Side choice of the rectangular growth phase.
    pub growth: GrowthRule,
    /// Refine each round's winner by moving the walls between its rooms one cell at a time while
    /// the energy falls ([`Prepared::refine`]). Absent: off, the paper's cutting node.
    #[serde(default)]
    pub refine_walls: bool,
}

use serde::{Deserialize, Serialize};

impl Default for CutOptions {
    fn default() -> Self {
        CutOptions {
            retries: 10,
            batch: 100,
            // the Python package's SolverSettings defaults, chosen by measurement there
            gammas: vec![0.25, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0],
            r_base: 2.0,
            k: 8.0,
            seed_separation: 2.0,
            fallback_samples: 400,
            min_contact: 2,
            min_width: None,
            widths: Vec::new(),
            weights: Weights::default(),
            rng_seed: 0,
            exhaustive: false,
            growth: GrowthRule::default(),
            refine_walls: false,
        }
    }
}

/// Wall moves [`Prepared::refine`] may make per room of a round.
pub const REFINE_STEPS: usize = 4;

/// What the cutting node returns for a round.
#[derive(Debug, Clone)]
pub struct CutOutcome {
    pub grid: Grid,
    /// Retry that produced the winner, or None when the fallback did.
    pub retry: Option<usize>,
    pub fallback: bool,
    pub candidates: usize,
    /// Rejected candidates counted by reason.
    pub rejected: BTreeMap<String, usize>,
    /// Features of every round label of the winner, in `labels()` order.
    pub features: Vec<(Label, RoomFeatures)>,
    pub energy: f64,
}

/// A surviving candidate: energy, index in its batch, grid and per-room features.
type Survivor = (f64, usize, Grid, Vec<RoomFeatures>);
/// A scored candidate or why it was rejected.
type Scored = Result<(f64, Grid, Vec<RoomFeatures>), Reject>;

/// Why a candidate failed the filter.
#[derive(Debug, Clone, PartialEq)]
pub enum Reject {
    NoSeeds,
    Unfilled,
    Missing(Label),
    Disconnected(Label),
    Straddles(Label),
    TooNarrow(Label),
    Necked(Label),
    Adjacency(Label, Label),
}

impl Reject {
    fn describe(&self, names: &[String]) -> String {
        let n = |l: &Label| {
            names
                .get(*l as usize)
                .cloned()
                .unwrap_or_else(|| format!("#{l}"))
        };
        match self {
            Reject::NoSeeds => "no free cells left for every seed".into(),
            Reject::Unfilled => "cells left unassigned".into(),
            Reject::Missing(l) => format!("room '{}' vanished", n(l)),
            Reject::Disconnected(l) => format!("room '{}' in several pieces", n(l)),
            Reject::Straddles(l) => format!("room '{}' straddles a fixed wall", n(l)),
            Reject::TooNarrow(l) => format!("room '{}' narrower than the minimum width", n(l)),
            Reject::Necked(l) => format!("room '{}' in parts joined by a one-cell neck", n(l)),
            Reject::Adjacency(a, b) => format!("no shared wall between '{}' and '{}'", n(a), n(b)),
        }
    }
}

/// Buffers a rayon worker reuses from one candidate to the next.
pub struct Workspace {
    pub clean: Scratch,
    pub grow: GrowScratch,
}

impl Workspace {
    pub fn new(cells: usize) -> Self {
        Workspace {
            clean: Scratch::new(cells),
            grow: GrowScratch::default(),
        }
    }
}

/// A round prepared once and shared by all its candidates.
pub struct Prepared<'a> {
    pub spec: &'a RoundSpec,
    pub walls: &'a Walls,
    pub opts: &'a CutOptions,
    pub region: Region,
    /// The layout with the region emptied.
    pub base: Grid,
    /// `base` as growth sees it.
    pub field: Field,
    /// Round labels: growers, then the remainder label if any.
    pub labels: Vec<Label>,
    pub targets: Vec<f64>,
    pub seeds: Vec<Option<[f64; 2]>>,
    /// label → position in `labels`, or -1.
    pub index: Vec<i16>,
    /// Width rule in cells of each label (indexed by label): final round labels only, ≤ 1 for
    /// none.
    pub widths: Vec<u16>,
    /// Does any round label have a width rule? (Candidates without one skip the width passes.)
    pub width_rules: bool,
    pub round: u64,
}

impl<'a> Prepared<'a> {
    pub fn new(
        grid: &Grid,
        walls: &'a Walls,
        spec: &'a RoundSpec,
        opts: &'a CutOptions,
        n_labels: usize,
        round: u64,
    ) -> Self {
        let region = Region::of_label(grid, spec.parent);
        let mut base = grid.clone();
        for &c in &region.cells {
            base.cells[c as usize] = EMPTY;
        }
        if let Some((parent, _)) = spec.remainder {
            for &c in &spec.reserved {
                base.cells[c] = parent;
            }
        }
        // A label may have several growers (a child growing with its descendants' seeds): it is
        // one room for the filter and the energy, with the summed target and the area-weighted
        // mean of the seeds.
        let mut labels: Vec<Label> = Vec::with_capacity(spec.growers.len() + 1);
        let mut targets: Vec<f64> = Vec::with_capacity(spec.growers.len() + 1);
        let mut sums: Vec<[f64; 2]> = Vec::with_capacity(spec.growers.len());
        for (g, p) in spec.growers.iter().zip(&spec.planned) {
            let k = match labels.iter().position(|&l| l == g.label) {
                Some(k) => k,
                None => {
                    labels.push(g.label);
                    targets.push(0.0);
                    sums.push([0.0; 2]);
                    labels.len() - 1
                }
            };
            targets[k] += g.target;
            sums[k][0] += p[0] * g.target;
            sums[k][1] += p[1] * g.target;
        }
        let mut seeds: Vec<Option<[f64; 2]>> = sums
            .iter()
            .zip(&targets)
            .map(|(s, &t)| Some([s[0] / t.max(1e-9), s[1] / t.max(1e-9)]))
            .collect();
        if let Some((l, t)) = spec.remainder {
            labels.push(l);
            targets.push(t);
            seeds.push(None);
        }
        let mut index = vec![-1i16; n_labels];
        for (k, &l) in labels.iter().enumerate() {
            index[l as usize] = k as i16;
        }
        let field = Field::new(&base, walls);
        let mut widths = vec![0u16; n_labels];
        for &l in &labels {
            if spec.final_labels.contains(&l) {
                let own = opts.widths.get(l as usize).copied().unwrap_or(0);
                widths[l as usize] =
                    own.max(opts.min_width.unwrap_or(0)).min(u16::MAX as usize) as u16;
            }
        }
        let width_rules = widths.iter().any(|&w| w > 1);
        Prepared {
            spec,
            walls,
            opts,
            region,
            base,
            field,
            labels,
            targets,
            seeds,
            index,
            widths,
            width_rules,
            round,
        }
    }

    /// Perturbation radius of each grower at retry `j`.
    fn radii(&self, j: usize) -> Vec<f64> {
        let o = self.opts;
        let gamma = o.gammas.get(j).or(o.gammas.last()).copied().unwrap_or(1.0);
        let area = self.region.len().max(1) as f64;
        self.spec
            .growers
            .iter()
            .map(|g| gamma * (o.r_base + o.k * g.target / area))
            .collect()
    }

    fn in_region(&self, p: [f64; 2]) -> Option<usize> {
        if p[0] < 0.0 || p[1] < 0.0 {
            return None;
        }
        let (x, y) = (p[0] as usize, p[1] as usize);
        if x >= self.region.w || y >= self.region.h {
            return None;
        }
        let c = y * self.region.w + x;
        (self.base.cells[c] == EMPTY).then_some(c)
    }

    /// The region cell nearest to `p` that is not taken.
    fn nearest_free(&self, p: [f64; 2], taken: &[usize]) -> Option<usize> {
        let w = self.region.w;
        self.region
            .cells
            .iter()
            .map(|&c| c as usize)
            .filter(|&c| self.base.cells[c] == EMPTY && !taken.contains(&c))
            .min_by(|&a, &b| {
                let da = dist2(centre(a, w), p);
                let db = dist2(centre(b, w), p);
                da.total_cmp(&db).then(a.cmp(&b))
            })
    }

    /// Seed cells for one candidate: each planned seed perturbed inside its disc, kept in the region
    /// and apart from the others; `radii == None` keeps the planned seeds as they are.
    pub fn sample_seeds<R: Rng>(&self, rng: &mut R, radii: Option<&[f64]>) -> Option<Vec<usize>> {
        let w = self.region.w;
        let sep2 = self.opts.seed_separation * self.opts.seed_separation;
        let mut out: Vec<usize> = Vec::with_capacity(self.spec.growers.len());
        for (k, &p) in self.spec.planned.iter().enumerate() {
            let mut chosen = None;
            if let Some(radii) = radii {
                for _ in 0..32 {
                    let r = radii[k] * rng.random::<f64>().sqrt();
                    let t = rng.random::<f64>() * std::f64::consts::TAU;
                    let q = [p[0] + r * t.cos(), p[1] + r * t.sin()];
                    if let Some(c) = self.in_region(q) {
                        if !out.contains(&c)
                            && out
                                .iter()
                                .all(|&o| dist2(centre(o, w), centre(c, w)) >= sep2)
                        {
                            chosen = Some(c);
                            break;
                        }
                    }
                }
            }
            let c = match chosen {
                Some(c) => c,
                None => match self.in_region(p) {
                    Some(c) if !out.contains(&c) => c,
                    _ => self.nearest_free(p, &out)?,
                },
            };
            out.push(c);
        }
        Some(out)
    }

    /// Monte Carlo seeds: uniform in the region, larger rooms first, each the best of a few draws
    /// by distance to the seeds already placed relative to the rooms' sizes (repulsion).
    pub fn sample_fallback_seeds<R: Rng>(&self, rng: &mut R) -> Option<Vec<usize>> {
        let w = self.region.w;
        let n = self.spec.growers.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| {
            self.spec.growers[b]
                .target
                .total_cmp(&self.spec.growers[a].target)
                .then(a.cmp(&b))
        });
        let mut seeds = vec![usize::MAX; n];
        let mut placed: Vec<usize> = Vec::with_capacity(n);
        for &k in &order {
            let mut best: Option<(f64, usize)> = None;
            for _ in 0..8 {
                let c = self.region.cells[rng.random_range(0..self.region.len())] as usize;
                if self.base.cells[c] != EMPTY || placed.iter().any(|&o| seeds[o] == c) {
                    continue;
                }
                let rk = self.spec.growers[k].target.sqrt();
                let score = placed
                    .iter()
                    .map(|&o| {
                        dist2(centre(seeds[o], w), centre(c, w)).sqrt()
                            / (rk + self.spec.growers[o].target.sqrt())
                    })
                    .fold(f64::INFINITY, f64::min);
                if best.is_none_or(|(s, _)| score > s) {
                    best = Some((score, c));
                }
            }
            let (_, c) = best?;
            seeds[k] = c;
            placed.push(k);
        }
        Some(seeds)
    }

    /// One candidate: grow from the seeds, hand the leftover to the parent or to the neighbours,
    /// clean, check the topology and score.
    pub fn candidate(
        &self,
        seeds: &[usize],
        rng: &mut Xoshiro256PlusPlus,
        ws: &mut Workspace,
    ) -> Result<(f64, Grid, Vec<RoomFeatures>), Reject> {
        let grid = self.grow(seeds, rng, ws);
        self.finish(grid, &mut ws.clean)
    }

    /// Growth alone: a copy of the base layout with the growers grown from `seeds`.
    fn grow(&self, seeds: &[usize], rng: &mut Xoshiro256PlusPlus, ws: &mut Workspace) -> Grid {
        let mut grid = self.base.clone();
        growth::grow_in(
            &self.field,
            &mut ws.grow,
            &mut grid,
            self.walls,
            &self.spec.growers,
            seeds,
            self.opts.growth,
            rng,
        );
        grid
    }

    /// Everything after growth; public so benchmarks and references can share it.
    pub fn finish(
        &self,
        mut grid: Grid,
        s: &mut Scratch,
    ) -> Result<(f64, Grid, Vec<RoomFeatures>), Reject> {
        if let Some((parent, _)) = self.spec.remainder {
            cleanup::assign_remainder(&mut grid, &self.region, self.walls, parent, s);
        }
        if !cleanup::clean(&mut grid, &self.region, self.walls, s) {
            return Err(Reject::Unfilled);
        }
        let mut too_narrow = false;
        if self.width_rules {
            match cleanup::clean_widths(
                &mut grid,
                &self.region,
                self.walls,
                &self.index,
                &self.widths,
                s,
            ) {
                None => return Err(Reject::Unfilled),
                Some(clean) => too_narrow = !clean,
            }
        }
        self.check(&grid, s)?;
        if too_narrow {
            // `s.thin` still holds the cells the last width pass could not fix
            let l = s.thin.first().map_or(self.spec.parent, |&c| grid.cells[c]);
            return Err(Reject::TooNarrow(l));
        }
        if self.width_rules {
            if let Some(l) = cleanup::necked_room(&grid, &self.region, &self.widths, s) {
                return Err(Reject::Necked(l));
            }
        }
        let mut feats = energy::features(
            &grid,
            &self.region,
            &self.labels,
            &self.index,
            &self.targets,
            &self.seeds,
        );
        let e = energy::score(&mut feats, &self.opts.weights);
        Ok((e, grid, feats))
    }

    /// Local refinement of a round's winner: the wall between two of its rooms moves by one cell
    /// into the room that is better off (area over target, relative), giving its row of cells
    /// along the shared wall to the room worse off, when one of the two is off its target on that
    /// side (the giver over it or the taker short of it); every such move is finished like a
    /// candidate (cleanup, width passes, topology filter, energy) and the best one that lowers
    /// the energy is kept, until none does or [`REFINE_STEPS`] per room are spent. Why: a round
    /// often has few survivors (rooms that must all reach a corridor, ensuites that must keep
    /// their width), and the best of them can leave a room at a third of its area; growth alone
    /// never revisits a wall once it has stopped. Deterministic (fixed order, strict improvement).
    pub fn refine(
        &self,
        best: (f64, Grid, Vec<RoomFeatures>),
        s: &mut Scratch,
    ) -> (f64, Grid, Vec<RoomFeatures>) {
        let mut best = best;
        let w = best.1.w;
        let n = best.1.cells.len();
        let mut reserved = vec![false; n];
        for &c in &self.spec.reserved {
            if c < n {
                reserved[c] = true;
            }
        }
        let steps = REFINE_STEPS * self.labels.len();
        for _ in 0..steps {
            let (energy, grid, feats) = &best;
            let share = |k: usize| feats[k].area as f64 / self.targets[k].max(1e-9);
            let mut improved: Option<(f64, Grid, Vec<RoomFeatures>)> = None;
            for (ka, &a) in self.labels.iter().enumerate() {
                for (kb, &b) in self.labels.iter().enumerate() {
                    // a wall moves from the room better off towards one worse off, and only
                    // when one of them is off its target on that side
                    if kb == ka || share(kb) <= share(ka) || (share(ka) >= 1.0 && share(kb) <= 1.0)
                    {
                        continue;
                    }
                    // the four directions a wall can move in: b's cells whose neighbour on the
                    // other side (c - d) is a
                    for d in 0..4 {
                        let from = |c: usize| -> Option<usize> {
                            match d {
                                0 => (!c.is_multiple_of(w)).then(|| c - 1),
                                1 => (!(c + 1).is_multiple_of(w)).then_some(c + 1),
                                2 => (c >= w).then(|| c - w),
                                _ => (c + w < n).then_some(c + w),
                            }
                        };
                        let moved: Vec<usize> = self
                            .region
                            .cells
                            .iter()
                            .map(|&c| c as usize)
                            .filter(|&c| grid.cells[c] == b)
                            .filter(|&c| from(c).is_some_and(|o| grid.cells[o] == a))
                            .collect();
                        if moved.is_empty() || moved.iter().any(|&c| reserved[c]) {
                            continue;
                        }
                        let mut g = grid.clone();
                        for &c in &moved {
                            g.cells[c] = a;
                        }
                        if let Ok((e, g, f)) = self.finish(g, s) {
                            let bar = improved.as_ref().map_or(*energy - 1e-9, |m| m.0);
                            if e < bar {
                                improved = Some((e, g, f));
                            }
                        }
                    }
                }
            }
            match improved {
                Some(m) => best = m,
                None => break,
            }
        }
        best
    }

    /// The topology filter (width rules are tested in [`Prepared::finish`], where the width
    /// passes already know the answer).
    pub fn check(&self, grid: &Grid, s: &mut Scratch) -> Result<(), Reject> {
        let pieces = topology::pieces_all(grid, &self.region, &self.index, self.labels.len(), s);
        for (&l, &n) in self.labels.iter().zip(&pieces) {
            match n {
                0 => return Err(Reject::Missing(l)),
                1 => {}
                _ => return Err(Reject::Disconnected(l)),
            }
        }
        for &l in &self.spec.final_labels {
            if topology::straddles(grid, &self.region, self.walls, l) {
                return Err(Reject::Straddles(l));
            }
        }
        let contacts =
            topology::measure_contacts(grid, &self.region, &self.index, self.labels.len());
        for &(a, b) in &self.spec.required {
            if contacts.get(&self.index, a, b).1 < self.opts.min_contact {
                return Err(Reject::Adjacency(a, b));
            }
        }
        Ok(())
    }

    fn rng(&self, retry: u64, i: u64) -> Xoshiro256PlusPlus {
        let mut h = self.opts.rng_seed;
        for v in [self.round, retry, i] {
            h = splitmix(h ^ splitmix(v));
        }
        Xoshiro256PlusPlus::seed_from_u64(h)
    }

    /// Run `count` candidates in parallel; seeds come from `seeder`. Returns the best survivor.
    fn batch<F>(
        &self,
        retry: u64,
        count: usize,
        rejected: &mut BTreeMap<String, usize>,
        seeder: F,
    ) -> Option<Survivor>
    where
        F: Fn(usize, &mut Xoshiro256PlusPlus) -> Option<Vec<usize>> + Sync,
    {
        let cells = self.base.cells.len();
        let results: Vec<Scored> = (0..count)
            .into_par_iter()
            .map_init(
                || Workspace::new(cells),
                |s, i| {
                    let mut rng = self.rng(retry, i as u64);
                    match seeder(i, &mut rng) {
                        Some(seeds) => self.candidate(&seeds, &mut rng, s),
                        None => Err(Reject::NoSeeds),
                    }
                },
            )
            .collect();
        let mut best: Option<Survivor> = None;
        for (i, r) in results.into_iter().enumerate() {
            match r {
                Ok((e, g, f)) => {
                    if best.as_ref().is_none_or(|b| e < b.0) {
                        best = Some((e, i, g, f));
                    }
                }
                Err(why) => *rejected.entry(why.describe(&self.spec.names)).or_insert(0) += 1,
            }
        }
        best
    }
}

/// Run the cutting node on one round.
pub fn cut(
    grid: &Grid,
    walls: &Walls,
    spec: &RoundSpec,
    opts: &CutOptions,
    n_labels: usize,
    round: u64,
) -> crate::Result<CutOutcome> {
    let p = Prepared::new(grid, walls, spec, opts, n_labels, round);
    let children = || -> Vec<&str> {
        spec.growers
            .iter()
            .map(|g| spec.names[g.label as usize].as_str())
            .collect()
    };
    // a region too small or too narrow for its rooms' width squares rejects every candidate:
    // fail the round without drawing any (same outcome, none of the cost)
    if p.width_rules {
        if let Some(l) = cleanup::width_squares_misfit(&p.region, &p.labels, &p.widths) {
            return Err(crate::CoreError::Infeasible(format!(
                "cutting '{}' into {:?}: the region cannot hold a {} × {} cell square for room '{}' \
                 beside the other rooms' (minimum widths)",
                spec.names[spec.parent as usize],
                children(),
                p.widths[l as usize],
                p.widths[l as usize],
                spec.names[l as usize],
            )));
        }
    }
    let mut rejected = BTreeMap::new();
    let mut candidates = 0;
    let finish = |best: Survivor,
                  retry: Option<usize>,
                  candidates: usize,
                  rejected: BTreeMap<String, usize>| {
        let (energy, _, grid, feats) = best;
        let (energy, grid, feats) = if opts.refine_walls {
            p.refine((energy, grid, feats), &mut Scratch::new(p.base.cells.len()))
        } else {
            (energy, grid, feats)
        };
        CutOutcome {
            grid,
            retry,
            fallback: retry.is_none(),
            candidates,
            rejected,
            features: p.labels.iter().copied().zip(feats).collect(),
            energy,
        }
    };
    let mut kept: Option<(Survivor, usize)> = None;
    for j in 0..opts.retries.max(1) {
        let radii = p.radii(j);
        let best = p.batch(j as u64, opts.batch.max(1), &mut rejected, |i, rng| {
            // the first candidate of the first retry keeps the planned seeds unperturbed
            if j == 0 && i == 0 {
                p.sample_seeds(rng, None)
            } else {
                p.sample_seeds(rng, Some(&radii))
            }
        });
        candidates += opts.batch.max(1);
        if let Some(b) = best {
            if !opts.exhaustive {
                return Ok(finish(b, Some(j), candidates, rejected));
            }
            if kept.as_ref().is_none_or(|(k, _)| b.0 < k.0) {
                kept = Some((b, j));
            }
        }
    }
    if let Some((b, j)) = kept {
        return Ok(finish(b, Some(j), candidates, rejected));
    }
    // Monte Carlo fallback, in batches so memory stays bounded
    let mut done = 0;
    let mut retry_tag = opts.retries as u64;
    while done < opts.fallback_samples {
        let count = opts.batch.max(1).min(opts.fallback_samples - done);
        let best = p.batch(retry_tag, count, &mut rejected, |_, rng| {
            p.sample_fallback_seeds(rng)
        });
        candidates += count;
        done += count;
        retry_tag += 1;
        if let Some(b) = best {
            return Ok(finish(b, None, candidates, rejected));
        }
    }
    let children = children();
    let reasons: Vec<String> = {
        let mut v: Vec<(&String, &usize)> = rejected.iter().collect();
        v.sort_by(|a, b| b.1.cmp(a.1));
        v.iter()
            .take(4)
            .map(|(r, n)| format!("{n} × {r}"))
            .collect()
    };
    Err(crate::CoreError::Infeasible(format!(
        "cutting '{}' into {:?}: {} retries × {} candidates and {} Monte Carlo candidates were all rejected ({})",
        spec.names[spec.parent as usize],
        children,
        opts.retries,
        opts.batch,
        opts.fallback_samples,
        reasons.join("; ")
    )))
}

#[inline]
fn centre(c: usize, w: usize) -> [f64; 2] {
    [(c % w) as f64 + 0.5, (c / w) as f64 + 0.5]
}

#[inline]
fn dist2(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
}

/// SplitMix64: spreads structured inputs (round, retry, index) into independent RNG seeds.
#[inline]
pub fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Grow and clean `batch` candidates of one region without the topology filter or the score: the
/// growth stage on its own, as the Python benchmark compares it with a numpy reference.
///
/// `grid` is a padded solver grid; the cells labelled `region` are cut into `targets.len()` new
/// rooms labelled `first_label..`, seeded around `seeds` (padded grid units) within `radius` cells;
/// the leftover stays `region`.
#[allow(clippy::too_many_arguments)]
pub fn grow_batch(
    grid: &Grid,
    region: Label,
    first_label: Label,
    seeds: &[[f64; 2]],
    targets: &[f64],
    batch: usize,
    rng_seed: u64,
    radius: f64,
    growth: GrowthRule,
) -> Vec<Grid> {
    let walls = Walls::none(grid.w, grid.h);
    let cells = grid.cells.iter().filter(|&&c| c == region).count() as f64;
    let growers: Vec<Grower> = targets
        .iter()
        .enumerate()
        .map(|(k, &t)| Grower {
            label: first_label + k as Label,
            target: t,
        })
        .collect();
    let n_labels = first_label as usize + targets.len();
    let spec = RoundSpec {
        parent: region,
        growers,
        planned: seeds.to_vec(),
        remainder: Some((region, (cells - targets.iter().sum::<f64>()).max(1.0))),
        final_labels: vec![],
        required: vec![],
        reserved: vec![],
        names: vec![String::new(); n_labels],
    };
    let opts = CutOptions {
        rng_seed,
        r_base: radius,
        k: 0.0,
        gammas: vec![1.0],
        growth,
        ..CutOptions::default()
    };
    let p = Prepared::new(grid, &walls, &spec, &opts, n_labels, 0);
    let radii = p.radii(0);
    let n = grid.cells.len();
    (0..batch)
        .into_par_iter()
        .map_init(
            || Workspace::new(n),
            |ws, i| {
                let mut rng = p.rng(0, i as u64);
                match p.sample_seeds(&mut rng, Some(&radii)) {
                    Some(seeds) => {
                        let mut g = p.grow(&seeds, &mut rng, ws);
                        let s = &mut ws.clean;
                        cleanup::assign_remainder(&mut g, &p.region, &walls, region, s);
                        cleanup::clean(&mut g, &p.region, &walls, s);
                        g
                    }
                    None => p.base.clone(),
                }
            },
        )
        .collect()
}
