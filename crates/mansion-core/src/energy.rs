//! The paper's energy: per-room features of a candidate and their weighted sum.
//!
//! `e(r) = w_ratio·|area − a|/a + w_seed·z_seed + w_drift·d/√a + w_corner·max(0, n_int − 4)
//!        − w_wall·clamp01(wall)`
//! where `z_seed` is the centroid-to-seed distance `d` min–max normalised over the candidate's rooms
//! (the paper's term), `d/√a` the same distance in units of the room's own size (our addition: the
//! min–max form always spans 0..1 within a candidate, so it barely tells candidates apart),
//! `wall` is the share of the room's perimeter on the parent region's envelope (a fraction, so the
//! clamp means something) and `n_int` counts the room's corners strictly inside the parent region.
//! Two optional shape terms (weights 0 by default): `w_rect·(1 − area/bbox)` for rooms that fill
//! their bounding box badly and `w_aspect·max(0, long/short − 3)` for seeded rooms stretched
//! beyond 3 : 1.
//! The weights come from Python; the core only computes.

use crate::grid::{Grid, Label};
use crate::region::Region;
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Weights {
    pub ratio: f64,
    pub seed: f64,
    /// Absent from older weight files: 0, the paper's energy.
    #[serde(default)]
    pub drift: f64,
    pub wall: f64,
    pub corner: f64,
    /// Share of the room's bounding box it leaves empty (0 for a rectangle). Absent: 0.
    #[serde(default)]
    pub rect: f64,
    /// Bounding-box elongation beyond 3 : 1 (`max(0, long/short − 3)`), seeded rooms only, so a
    /// leftover corridor is not penalised for being long. Absent: 0.
    #[serde(default)]
    pub aspect: f64,
}

impl Default for Weights {
    /// The Python package's defaults (`mansion.EnergyWeights`, tuned on the T2D plans with even
    /// ids); the Python package owns them and documents how they were found.
    fn default() -> Self {
        Weights {
            ratio: 1.28,
            seed: 0.21,
            drift: 17.65,
            wall: 0.57,
            corner: 0.29,
            rect: 0.0,
            aspect: 0.0,
        }
    }
}

impl Weights {
    /// The values the MANSION authors released with their code (no drift term).
    pub fn paper() -> Self {
        Weights {
            ratio: 6.0,
            seed: 0.2,
            drift: 0.0,
            wall: 0.8,
            corner: 3.0,
            rect: 0.0,
            aspect: 0.0,
        }
    }
}

/// Raw and normalised features of one room in one candidate.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct RoomFeatures {
    /// Cells.
    pub area: usize,
    /// Centroid in grid units.
    pub centroid: [f64; 2],
    /// |area − target| / target.
    pub ratio: f64,
    /// Centroid-to-seed distance in cells (0 when the room has no seed).
    pub seed_dist: f64,
    /// Min–max normalised seed distance.
    pub seed: f64,
    /// Seed distance over √target: scale-free drift of the room from its seed.
    pub drift: f64,
    /// Share of the perimeter on the parent region's envelope, in [0, 1].
    pub wall: f64,
    /// max(0, interior corners − 4).
    pub corner: f64,
    /// 1 − area / bounding-box area.
    pub rect: f64,
    /// max(0, long side / short side − 3) of the bounding box; 0 for rooms without a seed.
    pub aspect: f64,
    /// This room's energy under the weights used.
    pub energy: f64,
}

/// Features of every round label (`labels[k]` has index `k` in `index`), given their targets in
/// cells and their planned seeds in grid units (`None`: the room has no seed and no seed term).
pub fn features(
    grid: &Grid,
    region: &Region,
    labels: &[Label],
    index: &[i16],
    targets: &[f64],
    seeds: &[Option<[f64; 2]>],
) -> Vec<RoomFeatures> {
    let n = labels.len();
    let w = grid.w;
    let mut area = vec![0usize; n];
    let mut sum = vec![[0f64; 2]; n];
    let mut perim = vec![0u32; n];
    let mut env = vec![0u32; n];
    // bounding boxes (x0, y0, x1, y1)
    let mut bbox = vec![(usize::MAX, usize::MAX, 0usize, 0usize); n];
    for &c in &region.cells {
        let c = c as usize;
        let l = grid.cells[c];
        let k = match index.get(l as usize) {
            Some(&k) if k >= 0 => k as usize,
            _ => continue,
        };
        area[k] += 1;
        let (x, y) = (c % w, c / w);
        sum[k][0] += x as f64 + 0.5;
        sum[k][1] += y as f64 + 0.5;
        let b = &mut bbox[k];
        *b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
        for nb in [c - 1, c + 1, c - w, c + w] {
            if grid.cells[nb] != l {
                perim[k] += 1;
                if !region.inside[nb] {
                    env[k] += 1;
                }
            }
        }
    }
    let corners = interior_corners(grid, region, index, n);
    let mut out = vec![RoomFeatures::default(); n];
    for k in 0..n {
        let f = &mut out[k];
        f.area = area[k];
        if area[k] > 0 {
            f.centroid = [sum[k][0] / area[k] as f64, sum[k][1] / area[k] as f64];
        }
        f.ratio = (area[k] as f64 - targets[k]).abs() / targets[k].max(1e-9);
        if let Some(s) = seeds[k] {
            f.seed_dist = ((f.centroid[0] - s[0]).powi(2) + (f.centroid[1] - s[1]).powi(2)).sqrt();
            f.drift = f.seed_dist / targets[k].max(1.0).sqrt();
        }
        f.wall = if perim[k] > 0 {
            (env[k] as f64 / perim[k] as f64).clamp(0.0, 1.0)
        } else {
            0.0
        };
        f.corner = (corners[k] as f64 - 4.0).max(0.0);
        if area[k] > 0 {
            let (x0, y0, x1, y1) = bbox[k];
            let (bw, bh) = ((x1 - x0 + 1) as f64, (y1 - y0 + 1) as f64);
            f.rect = 1.0 - area[k] as f64 / (bw * bh);
            if seeds[k].is_some() {
                f.aspect = (bw.max(bh) / bw.min(bh) - 3.0).max(0.0);
            }
        }
    }
    // min–max normalisation of the seed distance across the rooms that have seeds
    let seeded: Vec<f64> = (0..n)
        .filter(|&k| seeds[k].is_some())
        .map(|k| out[k].seed_dist)
        .collect();
    if let (Some(lo), Some(hi)) = (
        seeded.iter().cloned().reduce(f64::min),
        seeded.iter().cloned().reduce(f64::max),
    ) {
        for k in 0..n {
            if seeds[k].is_some() {
                out[k].seed = ((out[k].seed_dist - lo) / (hi - lo + 1e-9)).clamp(0.0, 1.0);
            }
        }
    }
    out
}

/// Count, per round label, the corners of its outline at grid vertices strictly inside the region
/// (all four cells around the vertex in the region).
fn interior_corners(grid: &Grid, region: &Region, index: &[i16], n: usize) -> Vec<u32> {
    let w = grid.w;
    let mut corners = vec![0u32; n];
    let (x0, y0, x1, y1) = region.bbox;
    // vertex (i, j) is the lower-left corner of cell (i, j)
    for j in (y0 + 1)..=y1 {
        for i in (x0 + 1)..=x1 {
            let (bl, br, tl, tr) = (
                (j - 1) * w + i - 1,
                (j - 1) * w + i,
                j * w + i - 1,
                j * w + i,
            );
            if !(region.inside[bl] && region.inside[br] && region.inside[tl] && region.inside[tr]) {
                continue;
            }
            let q = [
                grid.cells[bl],
                grid.cells[br],
                grid.cells[tl],
                grid.cells[tr],
            ];
            for (p, &l) in q.iter().enumerate() {
                if q[..p].contains(&l) {
                    continue; // count each label once per vertex
                }
                let k = match index.get(l as usize) {
                    Some(&k) if k >= 0 => k as usize,
                    _ => continue,
                };
                let m = q.iter().filter(|&&o| o == l).count();
                corners[k] += match m {
                    1 | 3 => 1,
                    // two diagonal cells meet at a pinch: a corner for each
                    2 if (q[0] == l && q[3] == l) || (q[1] == l && q[2] == l) => 2,
                    _ => 0,
                };
            }
        }
    }
    corners
}

/// Fill in each room's energy and return the candidate's total (lower is better).
pub fn score(feats: &mut [RoomFeatures], w: &Weights) -> f64 {
    let mut total = 0.0;
    for f in feats.iter_mut() {
        f.energy = w.ratio * f.ratio + w.seed * f.seed + w.drift * f.drift + w.corner * f.corner
            - w.wall * f.wall;
        // shape terms only when weighted, so the energy without them is bit for bit the paper's
        if w.rect != 0.0 || w.aspect != 0.0 {
            f.energy += w.rect * f.rect + w.aspect * f.aspect;
        }
        total += f.energy;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::OUTSIDE;
    use crate::region::pad;

    fn grid_of(rows: &[&str]) -> (Grid, Region) {
        let h = rows.len();
        let w = rows[0].len();
        let mut g = Grid::new(w, h, 0);
        for (r, row) in rows.iter().enumerate() {
            for (x, ch) in row.chars().enumerate() {
                g.set(x, h - 1 - r, ch.to_digit(10).unwrap() as Label);
            }
        }
        let g = pad(&g, OUTSIDE);
        let mut m = g.clone();
        for c in m.cells.iter_mut() {
            *c = if *c == OUTSIDE { OUTSIDE } else { 0 };
        }
        (g, Region::of_label(&m, 0))
    }

    #[test]
    fn features_of_two_rectangles() {
        let (g, r) = grid_of(&["1122", "1122"]);
        let index = [-1i16, 0, 1];
        let f = features(
            &g,
            &r,
            &[1, 2],
            &index,
            &[4.0, 2.0],
            &[Some([2.0, 2.0]), Some([4.0, 2.0])],
        );
        assert_eq!(f[0].area, 4);
        assert_eq!(f[0].centroid, [2.0, 2.0]); // padded grid units
        assert_eq!(f[0].ratio, 0.0);
        assert_eq!(f[1].ratio, 1.0);
        // room 1: perimeter 8, of which 6 on the region's envelope
        assert!((f[0].wall - 0.75).abs() < 1e-12);
        assert_eq!(f[0].corner, 0.0);
        assert!(f[0].seed_dist < 1e-12 && f[1].seed_dist < 1e-12);
    }

    #[test]
    fn an_l_room_inside_the_region_has_extra_corners() {
        // room 1 is a plus-like blob with 8 interior corners... here an L of 6 interior corners
        let (g, r) = grid_of(&["00000", "01100", "01110", "01110", "00000"]);
        let index = [0i16, 1];
        let f = features(
            &g,
            &r,
            &[0, 1],
            &index,
            &[17.0, 8.0],
            &[None, Some([2.5, 2.5])],
        );
        assert_eq!(f[1].area, 8);
        assert_eq!(f[1].corner, 2.0);
        assert_eq!(f[1].wall, 0.0);
    }

    #[test]
    fn score_is_the_weighted_sum() {
        let mut f = vec![RoomFeatures {
            ratio: 0.5,
            seed: 1.0,
            drift: 0.5,
            wall: 0.25,
            corner: 2.0,
            ..Default::default()
        }];
        let e = score(&mut f, &Weights::paper());
        assert!((e - (3.0 + 0.2 + 6.0 - 0.2)).abs() < 1e-12);
        let w = Weights {
            drift: 2.0,
            ..Weights::paper()
        };
        let e = score(&mut f, &w);
        assert!((e - (3.0 + 0.2 + 1.0 + 6.0 - 0.2)).abs() < 1e-12);
        assert_eq!(f[0].energy, e);
    }
}
