//! Footprint to grid: validate the orthogonal outline, courtyards, cores and fixed walls, then
//! decide cell membership exactly at cell centres.
//!
//! Membership uses a half-open rule (a centre on a left or bottom boundary is in, on a right or
//! top boundary out) so that two shapes sharing a boundary never both claim a cell, and a core
//! touching the outline claims exactly the cells the outline would.

use serde::{Deserialize, Serialize};

use crate::error::{CoreError, Result};
use crate::grid::{Grid, GridFrame, Walls, EMPTY, OUTSIDE};

/// A stair or elevator box, cut out of the free region.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CoreSpec {
    pub id: String,
    #[serde(rename = "type")]
    pub kind: String,
    pub x: [f64; 2],
    pub y: [f64; 2],
}

/// A floor footprint in metres, y up.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct FootprintSpec {
    /// Outer outline, either orientation, closing vertex optional.
    pub polygon: Vec<[f64; 2]>,
    /// Courtyards: not part of the building.
    #[serde(default)]
    pub holes: Vec<Vec<[f64; 2]>>,
    /// Stair/elevator boxes cut out of the free region.
    #[serde(default)]
    pub cores: Vec<CoreSpec>,
    /// Load-bearing wall segments.
    #[serde(default)]
    pub fixed_walls: Vec<[[f64; 2]; 2]>,
}

/// A rasterised footprint.
#[derive(Debug, Clone, PartialEq)]
pub struct Raster {
    pub frame: GridFrame,
    /// [`EMPTY`] where the cell centre is inside the outline, outside every hole and outside
    /// every core; [`OUTSIDE`] elsewhere.
    pub free: Grid,
    /// Flat cell indices of each core, ascending, in the order of [`FootprintSpec::cores`].
    pub cores: Vec<Vec<usize>>,
    /// Fixed walls as blocked cell edges.
    pub walls: Walls,
}

/// Beyond this many cells per side the grid stops being a floor plan and starts being a memory
/// problem; the solver's cost grows with the cell count.
const MAX_SIDE: usize = 4096;
/// Relative slack on `extent / cell` so that an exact multiple, which floating point may round
/// up by an ulp, does not gain a whole column.
const SIDE_SLACK: f64 = 1e-9;
/// Grid-unit slack: fixed-wall endpoints must be this close to a grid line, and shape boundaries
/// this close to a cell centre or grid line are snapped onto it so that the half-open rule is not
/// decided by rounding noise.
const GRID_SNAP: f64 = 1e-6;

fn bad(msg: String) -> CoreError {
    CoreError::InvalidFootprint(msg)
}

fn pt(p: [f64; 2]) -> String {
    format!("({}, {})", p[0], p[1])
}

fn finite(p: [f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// A validated orthogonal ring: no duplicate or collinear vertices, edges alternate between
/// horizontal and vertical, coordinates snapped so every edge is exactly axis-aligned.
struct CleanRing {
    /// "outline" or "hole 2", for messages.
    name: String,
    pts: Vec<[f64; 2]>,
    /// Index in the caller's vertex list of each kept vertex, so messages point at their input.
    orig: Vec<usize>,
}

impl CleanRing {
    fn len(&self) -> usize {
        self.pts.len()
    }

    fn edge(&self, k: usize) -> ([f64; 2], [f64; 2]) {
        (self.pts[k], self.pts[(k + 1) % self.len()])
    }

    fn describe_edge(&self, k: usize) -> String {
        let (a, b) = self.edge(k);
        format!("edge {} from {} to {}", self.orig[k], pt(a), pt(b))
    }

    /// Even-odd test for a point known not to lie on the ring.
    fn contains(&self, p: [f64; 2]) -> bool {
        let mut inside = false;
        for k in 0..self.len() {
            let (a, b) = self.edge(k);
            if a[0] == b[0] {
                let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
                if lo <= p[1] && p[1] < hi && a[0] > p[0] {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// First edge running through the open box `[x0, x1] × [y0, y1]`, if any.
    fn edge_through_box(&self, b: [f64; 4]) -> Option<usize> {
        (0..self.len()).find(|&k| {
            let (p, q) = self.edge(k);
            let (ex0, ex1) = (p[0].min(q[0]), p[0].max(q[0]));
            let (ey0, ey1) = (p[1].min(q[1]), p[1].max(q[1]));
            let x_hit = if ex0 == ex1 {
                b[0] < ex0 && ex0 < b[1]
            } else {
                ex0.max(b[0]) < ex1.min(b[1])
            };
            let y_hit = if ey0 == ey1 {
                b[2] < ey0 && ey0 < b[3]
            } else {
                ey0.max(b[2]) < ey1.min(b[3])
            };
            x_hit && y_hit
        })
    }
}

fn clean_ring(raw: &[[f64; 2]], name: &str, tol: f64) -> Result<CleanRing> {
    if let Some((i, p)) = raw.iter().enumerate().find(|(_, p)| !finite(**p)) {
        return Err(bad(format!("{name} vertex {i} {} is not finite", pt(*p))));
    }
    let n = raw.len();
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() <= tol && (a[1] - b[1]).abs() <= tol;
    // Keeping the last vertex of each run of duplicates means edge `orig[k]` of the input really
    // is the edge leaving kept vertex k, and a repeated closing vertex drops out the same way.
    let kept: Vec<usize> = (0..n)
        .filter(|&i| !near(raw[i], raw[(i + 1) % n]))
        .collect();
    if kept.len() < 4 {
        return Err(bad(format!(
            "{name} has only {} distinct vertices; at least 4 are needed",
            kept.len().max(usize::from(n > 0))
        )));
    }
    let m = kept.len();
    let mut horiz = vec![false; m];
    let mut forward = vec![false; m];
    for k in 0..m {
        let (a, b) = (raw[kept[k]], raw[kept[(k + 1) % m]]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        if dy.abs() <= tol {
            horiz[k] = true;
            forward[k] = dx > 0.0;
        } else if dx.abs() <= tol {
            forward[k] = dy > 0.0;
        } else {
            return Err(bad(format!(
                "{name} edge {} from {} to {} is not axis-aligned",
                kept[k],
                pt(a),
                pt(b)
            )));
        }
    }
    let mut corners = Vec::with_capacity(m);
    for k in 0..m {
        let prev = (k + m - 1) % m;
        if horiz[prev] != horiz[k] {
            corners.push(k);
        } else if forward[prev] != forward[k] {
            let e = |j: usize| {
                format!(
                    "edge {} from {} to {}",
                    kept[j],
                    pt(raw[kept[j]]),
                    pt(raw[kept[(j + 1) % m]])
                )
            };
            return Err(bad(format!(
                "{name} is self-intersecting: {} folds back onto {}",
                e(prev),
                e(k)
            )));
        }
    }
    let c = corners.len();
    if c < 4 {
        return Err(bad(format!("{name} has zero area")));
    }
    // A merged edge spans several nearly collinear input edges; its snapped coordinate is the
    // mean of its two end vertices, and each corner takes one coordinate from each of its edges.
    let edge_coord = |t: usize| {
        let (a, b) = (raw[kept[corners[t]]], raw[kept[corners[(t + 1) % c]]]);
        if horiz[corners[t]] {
            0.5 * (a[1] + b[1])
        } else {
            0.5 * (a[0] + b[0])
        }
    };
    let mut pts = Vec::with_capacity(c);
    for t in 0..c {
        let (inc, out) = ((t + c - 1) % c, t);
        let (ci, co) = (edge_coord(inc), edge_coord(out));
        pts.push(if horiz[corners[out]] {
            [ci, co]
        } else {
            [co, ci]
        });
    }
    let ring = CleanRing {
        name: name.to_string(),
        pts,
        orig: corners.iter().map(|&k| kept[k]).collect(),
    };
    let area2: f64 = (0..c)
        .map(|k| {
            let (a, b) = ring.edge(k);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum();
    if area2 == 0.0 {
        return Err(bad(format!("{name} has zero area")));
    }
    Ok(ring)
}

/// An edge as its (degenerate) bounding box; axis-aligned segments intersect iff their boxes do.
struct Seg {
    ring: usize,
    k: usize,
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

/// Sweep over x to find a pair of closed segments that meet, ignoring pairs `skip` accepts.
fn first_meeting(
    rings: &[&CleanRing],
    skip: impl Fn(&Seg, &Seg) -> bool,
) -> Option<(usize, usize, usize, usize)> {
    let mut segs = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        for k in 0..ring.len() {
            let (a, b) = ring.edge(k);
            segs.push(Seg {
                ring: r,
                k,
                x0: a[0].min(b[0]),
                x1: a[0].max(b[0]),
                y0: a[1].min(b[1]),
                y1: a[1].max(b[1]),
            });
        }
    }
    segs.sort_by(|a, b| a.x0.total_cmp(&b.x0));
    for i in 0..segs.len() {
        let a = &segs[i];
        for b in segs[i + 1..].iter().take_while(|b| b.x0 <= a.x1) {
            if a.y0 <= b.y1 && b.y0 <= a.y1 && !skip(a, b) {
                return Some((a.ring, a.k, b.ring, b.k));
            }
        }
    }
    None
}

fn check_simple(ring: &CleanRing) -> Result<()> {
    let n = ring.len();
    let adjacent = |a: &Seg, b: &Seg| {
        let d = (a.k + n - b.k) % n;
        d == 1 || d == n - 1
    };
    match first_meeting(&[ring], adjacent) {
        None => Ok(()),
        Some((_, i, _, j)) => {
            let (i, j) = (i.min(j), i.max(j));
            Err(bad(format!(
                "{} is self-intersecting: {} touches or crosses {}",
                ring.name,
                ring.describe_edge(i),
                ring.describe_edge(j)
            )))
        }
    }
}

/// Holes must lie strictly inside the outline and apart from each other; rings are already simple.
fn check_holes(outline: &CleanRing, holes: &[CleanRing]) -> Result<()> {
    let mut rings = vec![outline];
    rings.extend(holes.iter());
    if let Some((r0, k0, r1, k1)) = first_meeting(&rings, |a, b| a.ring == b.ring) {
        let ((r0, k0), (r1, k1)) = if r0 < r1 {
            ((r0, k0), (r1, k1))
        } else {
            ((r1, k1), (r0, k0))
        };
        let (a, b) = (rings[r0], rings[r1]);
        return Err(bad(if r0 == 0 {
            format!(
                "{} is not strictly inside the outline: its {} touches or crosses outline {}",
                b.name,
                b.describe_edge(k1),
                a.describe_edge(k0)
            )
        } else {
            format!(
                "{} and {} overlap or touch: {} of {} meets {} of {}",
                a.name,
                b.name,
                a.describe_edge(k0),
                a.name,
                b.describe_edge(k1),
                b.name
            )
        }));
    }
    // With no boundary contact, one vertex decides containment of a whole ring.
    for h in holes {
        if !outline.contains(h.pts[0]) {
            return Err(bad(format!("{} lies outside the outline", h.name)));
        }
    }
    for a in holes {
        for b in holes {
            if !std::ptr::eq(a, b) && b.contains(a.pts[0]) {
                return Err(bad(format!(
                    "{} lies inside {}; holes must not overlap",
                    a.name, b.name
                )));
            }
        }
    }
    Ok(())
}

fn snap_grid(u: f64) -> f64 {
    let r = (2.0 * u).round();
    if (2.0 * u - r).abs() <= 2.0 * GRID_SNAP {
        0.5 * r
    } else {
        u
    }
}

/// Cells whose centre `c + 0.5` lies in `[lo, hi)`, clipped to `0..n`.
fn centre_range(lo: f64, hi: f64, n: usize) -> std::ops::Range<usize> {
    let first = (lo - 0.5).ceil().clamp(0.0, n as f64) as usize;
    let end = (hi - 0.5).ceil().clamp(0.0, n as f64) as usize;
    first..end.max(first)
}

fn grid_side(extent: f64, cell: f64) -> f64 {
    let r = extent / cell;
    (r * (1.0 - SIDE_SLACK)).ceil().max(1.0)
}

fn core_box_text(c: &CoreSpec) -> String {
    format!(
        "core '{}' box x=[{}, {}] y=[{}, {}]",
        c.id, c.x[0], c.x[1], c.y[0], c.y[1]
    )
}

fn check_cores(
    cores: &[CoreSpec],
    outline: &CleanRing,
    holes: &[CleanRing],
    tol: f64,
) -> Result<()> {
    for (i, c) in cores.iter().enumerate() {
        if c.id.is_empty() {
            return Err(bad(format!("core {i} has an empty id")));
        }
        if let Some(j) = cores[..i].iter().position(|o| o.id == c.id) {
            return Err(bad(format!(
                "core id '{}' is used twice (cores {j} and {i})",
                c.id
            )));
        }
        if c.kind != "stair" && c.kind != "elevator" {
            return Err(bad(format!(
                "core '{}' has type '{}'; expected 'stair' or 'elevator'",
                c.id, c.kind
            )));
        }
        if !(finite(c.x) && finite(c.y)) {
            return Err(bad(format!("{} is not finite", core_box_text(c))));
        }
        if !(c.x[0] < c.x[1] && c.y[0] < c.y[1]) {
            return Err(bad(format!(
                "{} is empty or inverted (need x0 < x1 and y0 < y1)",
                core_box_text(c)
            )));
        }
        // Shrinking by the tolerance lets a box flush with a wall pass despite rounding noise.
        let inner = [c.x[0] + tol, c.x[1] - tol, c.y[0] + tol, c.y[1] - tol];
        let centre = [0.5 * (c.x[0] + c.x[1]), 0.5 * (c.y[0] + c.y[1])];
        // No boundary runs through the open box, so its interior lies wholly on one side of each
        // ring and the centre decides which.
        if let Some(k) = outline.edge_through_box(inner) {
            return Err(bad(format!(
                "{} lies outside the footprint: outline {} runs through it",
                core_box_text(c),
                outline.describe_edge(k)
            )));
        }
        if !outline.contains(centre) {
            return Err(bad(format!(
                "{} lies outside the footprint",
                core_box_text(c)
            )));
        }
        for h in holes {
            if h.edge_through_box(inner).is_some() || h.contains(centre) {
                return Err(bad(format!("{} overlaps {}", core_box_text(c), h.name)));
            }
        }
        for o in &cores[..i] {
            if o.x[0].max(inner[0]) < o.x[1].min(inner[1])
                && o.y[0].max(inner[2]) < o.y[1].min(inner[3])
            {
                return Err(bad(format!(
                    "{} overlaps core '{}'",
                    core_box_text(c),
                    o.id
                )));
            }
        }
    }
    Ok(())
}

/// Even-odd scanline over cell-centre rows. Each vertical edge toggles parity at the first
/// column whose centre is at or right of it, in every row whose centre line it spans; a running
/// XOR along each row then says inside or out. No per-row crossing lists or sorting, so the cost
/// is one toggle per (edge, row) plus one pass over the cells.
fn fill_rings(free: &mut Grid, rings: &[&CleanRing], frame: &GridFrame) {
    let (w, h) = (frame.w, frame.h);
    let stride = w + 1;
    let mut toggle = vec![false; stride * h];
    for ring in rings {
        for k in 0..ring.len() {
            let (a, b) = ring.edge(k);
            if a[0] != b[0] {
                continue;
            }
            let (ga, gb) = (frame.to_grid(a), frame.to_grid(b));
            let col = centre_range(snap_grid(ga[0]), f64::INFINITY, w).start;
            let v0 = snap_grid(ga[1].min(gb[1]));
            let v1 = snap_grid(ga[1].max(gb[1]));
            for y in centre_range(v0, v1, h) {
                let t = &mut toggle[y * stride + col];
                *t = !*t;
            }
        }
    }
    for y in 0..h {
        let mut inside = false;
        for x in 0..w {
            inside ^= toggle[y * stride + x];
            if inside {
                free.cells[y * w + x] = EMPTY;
            }
        }
    }
}

fn map_walls(walls: &[[[f64; 2]; 2]], frame: &GridFrame) -> Result<Walls> {
    let (w, h, cell) = (frame.w, frame.h, frame.cell);
    let mut out = Walls::none(w, h);
    let tol = GRID_SNAP * cell;
    for (i, seg) in walls.iter().enumerate() {
        let [a, b] = *seg;
        let desc = format!("fixed wall {i} from {} to {}", pt(a), pt(b));
        if !(finite(a) && finite(b)) {
            return Err(bad(format!("{desc} is not finite")));
        }
        let (dx, dy) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
        if dx <= tol && dy <= tol {
            return Err(bad(format!("{desc} has zero length")));
        }
        if dx > tol && dy > tol {
            return Err(bad(format!("{desc} is not axis-aligned")));
        }
        let mut g = [[0i64; 2]; 2];
        for (e, p) in [a, b].iter().enumerate() {
            for axis in 0..2 {
                let u = (p[axis] - frame.origin[axis]) / cell;
                let r = u.round();
                if (u - r).abs() > GRID_SNAP {
                    return Err(bad(format!(
                        "{desc}: endpoint {} has {} = {} off the grid lines (origin {}, cell size {})",
                        pt(*p),
                        ["x", "y"][axis],
                        p[axis],
                        frame.origin[axis],
                        cell
                    )));
                }
                g[e][axis] = r as i64;
            }
        }
        let clip =
            |lo: i64, hi: i64, n: usize| lo.max(0) as usize..(hi.min(n as i64).max(0) as usize);
        if g[0][0] == g[1][0] {
            let x = g[0][0];
            if (0..=w as i64).contains(&x) {
                for y in clip(g[0][1].min(g[1][1]), g[0][1].max(g[1][1]), h) {
                    out.block_vertical(x as usize, y);
                }
            }
        } else {
            let y = g[0][1];
            if (0..=h as i64).contains(&y) {
                for x in clip(g[0][0].min(g[1][0]), g[0][0].max(g[1][0]), w) {
                    out.block_horizontal(x, y as usize);
                }
            }
        }
    }
    Ok(out)
}

/// Validate a footprint and rasterise it at `cell` metres per cell.
pub fn rasterise(fp: &FootprintSpec, cell: f64) -> Result<Raster> {
    if !(cell.is_finite() && cell > 0.0) {
        return Err(bad(format!("cell size must be finite and > 0, got {cell}")));
    }
    let scale = fp
        .polygon
        .iter()
        .chain(fp.holes.iter().flatten())
        .flat_map(|p| [p[0].abs(), p[1].abs()])
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let tol = 1e-9 * scale;
    let outline = clean_ring(&fp.polygon, "outline", tol)?;
    check_simple(&outline)?;
    let holes = fp
        .holes
        .iter()
        .enumerate()
        .map(|(i, h)| {
            let r = clean_ring(h, &format!("hole {i}"), tol)?;
            check_simple(&r)?;
            Ok(r)
        })
        .collect::<Result<Vec<_>>>()?;
    check_holes(&outline, &holes)?;

    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &outline.pts {
        for a in 0..2 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    let (gw, gh) = (
        grid_side(hi[0] - lo[0], cell),
        grid_side(hi[1] - lo[1], cell),
    );
    if gw > MAX_SIDE as f64 || gh > MAX_SIDE as f64 {
        let need = (hi[0] - lo[0]).max(hi[1] - lo[1]) / MAX_SIDE as f64;
        return Err(bad(format!(
            "a {} × {} m footprint at cell size {cell} needs a {gw:.0} × {gh:.0} grid, above the \
             {MAX_SIDE} × {MAX_SIDE} limit; use a cell size of at least {need}",
            hi[0] - lo[0],
            hi[1] - lo[1]
        )));
    }
    let frame = GridFrame {
        origin: lo,
        cell,
        w: gw as usize,
        h: gh as usize,
    };
    check_cores(&fp.cores, &outline, &holes, tol)?;

    let mut free = Grid::new(frame.w, frame.h, OUTSIDE);
    let mut rings = vec![&outline];
    rings.extend(holes.iter());
    fill_rings(&mut free, &rings, &frame);

    let mut cores = Vec::with_capacity(fp.cores.len());
    for c in &fp.cores {
        let g0 = frame.to_grid([c.x[0], c.y[0]]);
        let g1 = frame.to_grid([c.x[1], c.y[1]]);
        let xs = centre_range(snap_grid(g0[0]), snap_grid(g1[0]), frame.w);
        let ys = centre_range(snap_grid(g0[1]), snap_grid(g1[1]), frame.h);
        // Cores are validated disjoint and inside the region, so testing for EMPTY only guards
        // against tolerance slivers; it never lets two cores share a cell.
        let cells: Vec<usize> = ys
            .flat_map(|y| xs.clone().map(move |x| y * frame.w + x))
            .filter(|&i| free.cells[i] == EMPTY)
            .collect();
        if cells.is_empty() {
            return Err(bad(format!(
                "core '{}' is smaller than one cell at cell size {cell}: its box x=[{}, {}] y=[{}, {}] \
                 covers no cell centre",
                c.id, c.x[0], c.x[1], c.y[0], c.y[1]
            )));
        }
        cores.push(cells);
    }
    for &i in cores.iter().flatten() {
        free.cells[i] = OUTSIDE;
    }
    if !free.cells.contains(&EMPTY) {
        return Err(bad(format!(
            "the free region contains no cell centre at cell size {cell}; use a smaller cell size"
        )));
    }
    let walls = map_walls(&fp.fixed_walls, &frame)?;
    Ok(Raster {
        frame,
        free,
        cores,
        walls,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fp(poly: &[[f64; 2]]) -> FootprintSpec {
        FootprintSpec {
            polygon: poly.to_vec(),
            ..Default::default()
        }
    }

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
        vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
    }

    fn core(id: &str, kind: &str, x: [f64; 2], y: [f64; 2]) -> CoreSpec {
        CoreSpec {
            id: id.into(),
            kind: kind.into(),
            x,
            y,
        }
    }

    fn err(f: &FootprintSpec, cell: f64) -> String {
        match rasterise(f, cell) {
            Err(CoreError::InvalidFootprint(m)) => m,
            other => panic!("expected InvalidFootprint, got {other:?}"),
        }
    }

    fn assert_err(f: &FootprintSpec, cell: f64, parts: &[&str]) {
        let m = err(f, cell);
        for p in parts {
            assert!(m.contains(p), "message {m:?} lacks {p:?}");
        }
    }

    /// Rows top-down as strings, `#` free and `.` not, for readable shape assertions.
    fn picture(g: &Grid) -> Vec<String> {
        (0..g.h)
            .rev()
            .map(|y| {
                (0..g.w)
                    .map(|x| if g.get(x, y) == EMPTY { '#' } else { '.' })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn rectangle_counts() {
        let r = rasterise(&fp(&rect(0.0, 0.0, 10.0, 5.0)), 0.5).unwrap();
        assert_eq!((r.frame.w, r.frame.h), (20, 10));
        assert_eq!(r.frame.origin, [0.0, 0.0]);
        assert_eq!(r.free.count(EMPTY), 200);
        assert!(r.cores.is_empty() && !r.walls.any);
        // 10 / 0.1 is 100.00000000000001 in floating point: no extra column.
        let r = rasterise(&fp(&rect(-3.0, 2.0, 7.0, 2.3)), 0.1).unwrap();
        assert_eq!((r.frame.w, r.frame.h), (100, 3));
        assert_eq!(r.frame.origin, [-3.0, 2.0]);
        assert_eq!(r.free.count(EMPTY), 300);
    }

    #[test]
    fn closing_vertex_duplicates_and_collinear_points_are_ignored() {
        let poly = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [0.0, 0.0],
        ];
        let r = rasterise(&fp(&poly), 1.0).unwrap();
        assert_eq!(r.free.count(EMPTY), 4);
    }

    #[test]
    fn l_shape_exact_at_centres() {
        let l = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 2.0],
            [2.0, 2.0],
            [2.0, 4.0],
            [0.0, 4.0],
        ];
        let r = rasterise(&fp(&l), 1.0).unwrap();
        assert_eq!(picture(&r.free), ["##..", "##..", "####", "####"]);
        // Vertices off the grid: only centres count.
        let l = [
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.2],
            [1.3, 1.2],
            [1.3, 3.0],
            [0.0, 3.0],
        ];
        let r = rasterise(&fp(&l), 1.0).unwrap();
        assert_eq!(picture(&r.free), ["#..", "#..", "###"]);
    }

    #[test]
    fn vertices_off_the_grid() {
        let r = rasterise(&fp(&rect(0.0, 0.0, 2.3, 1.1)), 0.5).unwrap();
        assert_eq!((r.frame.w, r.frame.h), (5, 3));
        assert_eq!(picture(&r.free), [".....", "#####", "#####"]);
        // A boundary exactly on a centre line: left/bottom in, right/top out.
        let poly = [[0.1, 0.1], [1.35, 0.1], [1.35, 0.85], [0.1, 0.85]];
        let r = rasterise(&fp(&poly), 0.5).unwrap();
        assert_eq!((r.frame.w, r.frame.h), (3, 2));
        assert_eq!(picture(&r.free), ["...", "##."]);
    }

    #[test]
    fn hole_is_cut_out() {
        let mut f = fp(&rect(0.0, 0.0, 6.0, 6.0));
        f.holes.push(rect(2.0, 2.0, 4.0, 4.0));
        let r = rasterise(&f, 1.0).unwrap();
        assert_eq!(r.free.count(EMPTY), 32);
        assert_eq!(
            picture(&r.free),
            ["######", "######", "##..##", "##..##", "######", "######"]
        );
    }

    #[test]
    fn cores_are_cut_out() {
        let mut f = fp(&rect(0.0, 0.0, 10.0, 10.0));
        f.cores.push(core("s1", "stair", [0.0, 2.0], [0.0, 3.0]));
        f.cores
            .push(core("lift", "elevator", [8.0, 10.0], [8.0, 10.0]));
        f.cores.push(core("s2", "stair", [2.0, 3.0], [0.0, 1.0])); // touches s1
        let r = rasterise(&f, 1.0).unwrap();
        assert_eq!(r.cores[0], vec![0, 1, 10, 11, 20, 21]);
        assert_eq!(r.cores[1], vec![88, 89, 98, 99]);
        assert_eq!(r.cores[2], vec![2]);
        assert_eq!(r.free.count(EMPTY), 100 - 11);
        for &i in r.cores.iter().flatten() {
            assert_eq!(r.free.cells[i], OUTSIDE);
        }
        // Finer cells: 0.5 m gives four times as many.
        let r = rasterise(&f, 0.5).unwrap();
        assert_eq!(
            r.cores.iter().map(Vec::len).collect::<Vec<_>>(),
            [24, 16, 4]
        );
        assert_eq!(r.free.count(EMPTY), 400 - 44);
    }

    #[test]
    fn core_in_a_notch_or_beside_a_hole() {
        // A core filling a notch has all four corners on the outline but lies outside.
        let u = [
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 3.0],
            [2.0, 3.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ];
        let mut f = fp(&u);
        f.cores.push(core("c", "stair", [1.0, 2.0], [1.0, 3.0]));
        assert_err(
            &f,
            0.5,
            &["core 'c' box x=[1, 2] y=[1, 3] lies outside the footprint"],
        );
        f.cores[0] = core("c", "stair", [1.0, 2.0], [0.0, 1.0]);
        assert_eq!(rasterise(&f, 0.5).unwrap().cores[0].len(), 4);

        let mut f = fp(&rect(0.0, 0.0, 6.0, 6.0));
        f.holes.push(rect(2.0, 2.0, 4.0, 4.0));
        f.cores.push(core("c", "stair", [2.0, 4.0], [0.0, 2.0]));
        assert_eq!(rasterise(&f, 1.0).unwrap().cores[0], vec![2, 3, 8, 9]);
        f.cores[0] = core("c", "stair", [2.5, 3.5], [2.5, 3.5]);
        assert_err(&f, 1.0, &["core 'c'", "overlaps hole 0"]);
        f.cores[0] = core("c", "stair", [1.0, 5.0], [1.0, 5.0]);
        assert_err(&f, 1.0, &["core 'c'", "overlaps hole 0"]);
        f.cores[0] = core("c", "stair", [1.0, 3.0], [1.0, 3.0]);
        assert_err(&f, 1.0, &["core 'c'", "overlaps hole 0"]);
    }

    #[test]
    fn clockwise_outline_matches_counter_clockwise() {
        let ccw = vec![
            [0.0, 0.0],
            [5.0, 0.0],
            [5.0, 2.2],
            [3.3, 2.2],
            [3.3, 4.0],
            [0.0, 4.0],
        ];
        let cw: Vec<_> = ccw.iter().rev().copied().collect();
        let hole_ccw = rect(1.0, 1.0, 2.0, 3.0);
        let hole_cw: Vec<_> = hole_ccw.iter().rev().copied().collect();
        let mut a = fp(&ccw);
        a.holes.push(hole_ccw);
        let mut b = fp(&cw);
        b.holes.push(hole_cw);
        assert_eq!(rasterise(&a, 0.5).unwrap(), rasterise(&b, 0.5).unwrap());
    }

    #[test]
    fn fixed_walls_block_edges() {
        let mut f = fp(&rect(0.0, 0.0, 5.0, 4.0));
        f.fixed_walls = vec![
            [[2.0, 0.0], [2.0, 3.0]],   // vertical, grid x-line 2, rows 0..3
            [[4.0, 2.0], [1.0, 2.0]],   // horizontal, reversed, y-line 2, columns 1..4
            [[0.0, 1.0], [0.0, 2.0]],   // on the border: recorded, harmless
            [[5.0, -2.0], [5.0, 10.0]], // on the right border, clipped to rows 0..4
            [[-3.0, 4.0], [1.0, 4.0]],  // top border, clipped to column 0
            [[9.0, 0.0], [9.0, 4.0]],   // wholly off the grid
        ];
        let r = rasterise(&f, 1.0).unwrap();
        let w = &r.walls;
        let v: Vec<(usize, usize)> = (0..4)
            .flat_map(|y| (0..=5).map(move |x| (x, y)))
            .filter(|&(x, y)| w.v[y * 6 + x])
            .collect();
        assert_eq!(
            v,
            [
                (2, 0),
                (5, 0),
                (0, 1),
                (2, 1),
                (5, 1),
                (2, 2),
                (5, 2),
                (5, 3)
            ]
        );
        let hz: Vec<(usize, usize)> = (0..=4)
            .flat_map(|y| (0..5).map(move |x| (x, y)))
            .filter(|&(x, y)| w.hz[y * 5 + x])
            .collect();
        assert_eq!(hz, [(1, 2), (2, 2), (3, 2), (0, 4)]);
        assert!(w.blocked(1, 2) && w.blocked(11, 6) && !w.blocked(12, 13));
        // Half-cell grid: 2.5 m is grid line 5.
        f.fixed_walls = vec![[[2.5, 0.0], [2.5, 1.0]]];
        let r = rasterise(&f, 0.5).unwrap();
        assert!(r.walls.v[11 + 5] && r.walls.v[5] && !r.walls.v[2 * 11 + 5]);
    }

    #[test]
    fn bad_cell_sizes_and_sizes() {
        let f = fp(&rect(0.0, 0.0, 10.0, 10.0));
        for c in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_err(&f, c, &["cell size must be finite and > 0"]);
        }
        assert_err(&f, 0.001, &["above the 4096 × 4096 limit", "at least"]);
        assert!(rasterise(&fp(&rect(0.0, 0.0, 4096.0, 1.0)), 1.0).is_ok());
        let thin = fp(&rect(0.0, 0.0, 10.0, 0.2));
        assert_err(&thin, 1.0, &["free region contains no cell"]);
    }

    #[test]
    fn outline_errors() {
        assert_err(
            &fp(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
            1.0,
            &["outline has only 3 distinct vertices"],
        );
        assert_err(
            &fp(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [1.0, 1.0], [0.0, 0.0]]),
            1.0,
            &["only 3 distinct"],
        );
        assert_err(
            &fp(&[[0.0, 0.0], [1.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]]),
            1.0,
            &["outline vertex 2 (1, NaN) is not finite"],
        );
        assert_err(
            &fp(&[[0.0, 0.0], [1.0, 0.0], [f64::INFINITY, 1.0], [0.0, 1.0]]),
            1.0,
            &["vertex 2", "not finite"],
        );
        assert_err(
            &fp(&[
                [0.0, 0.0],
                [1.0, 0.0],
                [1.0, 1.5],
                [1.0, 0.0],
                [2.0, 1.5],
                [0.0, 1.5],
            ]),
            1.0,
            &["outline edge 3 from (1, 0) to (2, 1.5) is not axis-aligned"],
        );
        // Folding back on itself along a line.
        assert_err(
            &fp(&[[0.0, 0.0], [3.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
            1.0,
            &[
                "outline is self-intersecting",
                "edge 0",
                "edge 1",
                "folds back",
            ],
        );
        // A bow tie of two rectangles crossing.
        let cross = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 3.0],
            [3.0, 3.0],
            [3.0, 1.0],
            [-1.0, 1.0],
            [-1.0, 2.0],
            [0.0, 2.0],
        ];
        assert_err(
            &fp(&cross),
            1.0,
            &["outline is self-intersecting: edge 4 from (3, 1) to (-1, 1) touches or crosses edge 7 from (0, 2) to (0, 0)"],
        );
        // Two squares touching at a corner.
        let eight = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 2.0],
            [1.0, 2.0],
            [1.0, 1.0],
            [0.0, 1.0],
        ];
        assert_err(&fp(&eight), 1.0, &["outline is self-intersecting"]);
        // Zero area: everything on one line.
        assert_err(
            &fp(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]),
            1.0,
            &["outline is self-intersecting"],
        );
    }

    #[test]
    fn hole_errors() {
        let mut f = fp(&rect(0.0, 0.0, 6.0, 6.0));
        f.holes = vec![vec![[1.0, 1.0], [2.0, 1.0], [2.0, 2.0]]];
        assert_err(&f, 1.0, &["hole 0 has only 3 distinct vertices"]);
        f.holes = vec![
            rect(1.0, 1.0, 2.0, 2.0),
            vec![[3.0, 3.0], [4.0, 3.0], [4.0, 4.0], [3.5, 5.0]],
        ];
        assert_err(
            &f,
            1.0,
            &["hole 1 edge 2 from (4, 4) to (3.5, 5) is not axis-aligned"],
        );
        f.holes = vec![rect(4.0, 4.0, 7.0, 5.0)];
        assert_err(
            &f,
            1.0,
            &[
                "hole 0 is not strictly inside the outline",
                "outline edge 1",
            ],
        );
        f.holes = vec![rect(0.0, 2.0, 1.0, 3.0)];
        assert_err(&f, 1.0, &["hole 0 is not strictly inside the outline"]);
        f.holes = vec![rect(7.0, 7.0, 8.0, 8.0)];
        assert_err(&f, 1.0, &["hole 0 lies outside the outline"]);
        f.holes = vec![rect(1.0, 1.0, 3.0, 3.0), rect(2.0, 2.0, 4.0, 4.0)];
        assert_err(&f, 1.0, &["hole 0 and hole 1 overlap or touch"]);
        f.holes = vec![rect(1.0, 1.0, 2.0, 2.0), rect(2.0, 2.0, 4.0, 4.0)];
        assert_err(&f, 1.0, &["hole 0 and hole 1 overlap or touch"]);
        f.holes = vec![rect(3.0, 3.0, 4.0, 4.0), rect(1.0, 1.0, 5.0, 5.0)];
        assert_err(&f, 1.0, &["hole 0 lies inside hole 1"]);
        f.holes = vec![rect(1.0, 1.0, 2.0, 2.0), rect(1.0, 1.0, 2.0, 2.0)];
        assert_err(&f, 1.0, &["hole 0 and hole 1 overlap or touch"]);
        f.holes = vec![vec![
            [1.0, 1.0],
            [3.0, 1.0],
            [3.0, 3.0],
            [2.0, 3.0],
            [2.0, 0.5],
            [1.0, 0.5],
        ]];
        assert_err(&f, 1.0, &["hole 0 is self-intersecting"]);
        f.holes = vec![rect(0.0, 0.0, 6.0, 6.0)];
        assert_err(&f, 1.0, &["hole 0 is not strictly inside the outline"]);
    }

    #[test]
    fn core_errors() {
        let mut f = fp(&rect(0.0, 0.0, 6.0, 6.0));
        let cases: Vec<(Vec<CoreSpec>, Vec<&str>)> = vec![
            (
                vec![core("", "stair", [0.0, 1.0], [0.0, 1.0])],
                vec!["core 0 has an empty id"],
            ),
            (
                vec![
                    core("a", "stair", [0.0, 1.0], [0.0, 1.0]),
                    core("a", "stair", [2.0, 3.0], [0.0, 1.0]),
                ],
                vec!["core id 'a' is used twice (cores 0 and 1)"],
            ),
            (
                vec![core("r", "ramp", [0.0, 1.0], [0.0, 1.0])],
                vec!["core 'r' has type 'ramp'", "'stair' or 'elevator'"],
            ),
            (
                vec![core("n", "stair", [0.0, f64::NAN], [0.0, 1.0])],
                vec!["core 'n' box", "is not finite"],
            ),
            (
                vec![core("i", "stair", [2.0, 1.0], [0.0, 1.0])],
                vec!["core 'i' box x=[2, 1] y=[0, 1] is empty or inverted"],
            ),
            (
                vec![core("z", "stair", [1.0, 1.0], [0.0, 1.0])],
                vec!["core 'z'", "empty or inverted"],
            ),
            (
                vec![core("lift1", "elevator", [5.0, 7.0], [0.0, 1.0])],
                vec!["core 'lift1' box x=[5, 7] y=[0, 1] lies outside the footprint"],
            ),
            (
                vec![core("far", "elevator", [8.0, 9.0], [8.0, 9.0])],
                vec!["core 'far' box x=[8, 9] y=[8, 9] lies outside the footprint"],
            ),
            (
                vec![
                    core("a", "stair", [0.0, 2.0], [0.0, 2.0]),
                    core("b", "elevator", [1.0, 3.0], [1.0, 3.0]),
                ],
                vec!["core 'b'", "overlaps core 'a'"],
            ),
            (
                vec![core("x", "stair", [1.3, 1.45], [1.3, 1.45])],
                vec!["core 'x' is smaller than one cell at cell size 0.5"],
            ),
        ];
        for (cores, parts) in cases {
            f.cores = cores;
            assert_err(&f, 0.5, &parts);
        }
        // A core eating the whole floor leaves no free cell.
        f.cores = vec![core("all", "stair", [0.0, 6.0], [0.0, 6.0])];
        assert_err(&f, 1.0, &["free region contains no cell"]);
    }

    #[test]
    fn wall_errors() {
        let mut f = fp(&rect(0.0, 0.0, 6.0, 6.0));
        f.fixed_walls = vec![[[1.0, 0.0], [1.0, 2.0]], [[1.0, 1.0], [2.0, 2.0]]];
        assert_err(
            &f,
            1.0,
            &["fixed wall 1 from (1, 1) to (2, 2) is not axis-aligned"],
        );
        f.fixed_walls = vec![[[1.0, 1.0], [1.0, 1.0]]];
        assert_err(&f, 1.0, &["fixed wall 0", "zero length"]);
        f.fixed_walls = vec![[[1.25, 0.0], [1.25, 2.0]]];
        assert_err(&f, 0.5, &["fixed wall 0", "x = 1.25", "cell size 0.5"]);
        f.fixed_walls = vec![[[1.0, 0.0], [1.0, 2.3]]];
        assert_err(&f, 0.5, &["fixed wall 0", "y = 2.3", "cell size 0.5"]);
        f.fixed_walls = vec![[[1.0, 0.0], [1.0, f64::INFINITY]]];
        assert_err(&f, 0.5, &["fixed wall 0", "not finite"]);
    }

    #[test]
    fn large_comb_rasterises() {
        // 200 × 200 cells with 100 teeth: exercises the scanline on many edges.
        let mut poly = vec![[0.0, 0.0], [200.0, 0.0]];
        for t in (0..100).rev() {
            let x = 2.0 * t as f64;
            poly.push([x + 2.0, 200.0]);
            poly.push([x + 1.0, 200.0]);
            poly.push([x + 1.0, 10.0]);
            poly.push([x, 10.0]);
        }
        let r = rasterise(&fp(&poly), 1.0).unwrap();
        assert_eq!((r.frame.w, r.frame.h), (200, 200));
        assert_eq!(r.free.count(EMPTY), 200 * 10 + 100 * 190);
    }
}
