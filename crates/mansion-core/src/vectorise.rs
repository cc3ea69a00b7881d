//! Label grid to exact orthogonal polygons.
//!
//! Each 4-connected component of a room label becomes one polygon whose rings follow the cell
//! edges. Rings keep a vertex wherever the boundary turns and wherever the label across the
//! boundary changes, so neighbouring rooms share their common wall as the very same vertex
//! sequence and no vertex of one room sits in the middle of another room's edge.
//!
//! Tracing runs along directed cell edges with the component on the left, so outer rings come out
//! counter-clockwise and holes clockwise (y up). At a diagonal pinch inside one component the
//! trace turns right, i.e. hugs the pinch as if the component went through it: the alternative
//! would make the outer ring touch itself, which OGC forbids, whereas this way the pinch becomes
//! a point where the outer ring meets a hole (or two holes meet), which OGC allows. The interior
//! stays connected because the component is 4-connected. Cells of other components, even with
//! the same label, never take part in a trace, so separate components never merge.

use crate::error::{CoreError, Result};
use crate::grid::{Grid, GridFrame, Label, EMPTY, OUTSIDE};

/// Grid vertex coordinates (`i` = x-line, `j` = y-line); the first vertex is not repeated.
pub type Ring = Vec<[i64; 2]>;

/// One 4-connected component of a label.
#[derive(Debug, Clone, PartialEq)]
pub struct LabelPolygon {
    pub label: Label,
    /// Counter-clockwise.
    pub outer: Ring,
    /// Clockwise.
    pub holes: Vec<Ring>,
}

const NO_COMP: u32 = u32::MAX;

// Sides of a cell, in the order rings leave a cell counter-clockwise: bottom, right, top, left.
// The boundary edge on side `s` is walked in direction `DIR[s]` (cell on the left), starts at
// cell corner `CORNER[s]` and ends at `CORNER[(s + 1) % 4]`; the cell across it is at
// `DIR[(s + 3) % 4]`.
const DIR: [[i64; 2]; 4] = [[1, 0], [0, 1], [-1, 0], [0, -1]];
const CORNER: [[i64; 2]; 4] = [[0, 0], [1, 0], [1, 1], [0, 1]];

/// 4-connected components of the cells `eligible` accepts, joining neighbours `same` accepts.
/// Components are numbered in order of their lowest cell index.
pub(crate) fn components(
    w: usize,
    h: usize,
    eligible: impl Fn(usize) -> bool,
    same: impl Fn(usize, usize) -> bool,
) -> (Vec<u32>, usize) {
    let mut comp = vec![NO_COMP; w * h];
    let mut stack = Vec::new();
    let mut count = 0u32;
    for start in 0..w * h {
        if comp[start] != NO_COMP || !eligible(start) {
            continue;
        }
        comp[start] = count;
        stack.push(start);
        while let Some(i) = stack.pop() {
            let (x, y) = (i % w, i / w);
            let mut visit = |j: usize| {
                if comp[j] == NO_COMP && same(i, j) {
                    comp[j] = count;
                    stack.push(j);
                }
            };
            if x > 0 {
                visit(i - 1);
            }
            if x + 1 < w {
                visit(i + 1);
            }
            if y > 0 {
                visit(i - w);
            }
            if y + 1 < h {
                visit(i + w);
            }
        }
        count += 1;
    }
    (comp, count as usize)
}

struct Tracer<'a> {
    w: usize,
    h: usize,
    comp: &'a [u32],
    /// Labels for T-junction vertices; `None` when only corners matter.
    labels: Option<&'a [Label]>,
    /// Bit `s` of cell `i`: the side-`s` edge of `i` is a boundary edge not traced yet.
    todo: Vec<u8>,
}

impl<'a> Tracer<'a> {
    #[inline]
    fn comp_at(&self, x: i64, y: i64) -> u32 {
        if x < 0 || y < 0 || x >= self.w as i64 || y >= self.h as i64 {
            NO_COMP
        } else {
            self.comp[y as usize * self.w + x as usize]
        }
    }

    #[inline]
    fn label_at(&self, labels: &[Label], x: i64, y: i64) -> Label {
        if x < 0 || y < 0 || x >= self.w as i64 || y >= self.h as i64 {
            OUTSIDE
        } else {
            labels[y as usize * self.w + x as usize]
        }
    }

    fn new(w: usize, h: usize, comp: &'a [u32], labels: Option<&'a [Label]>) -> Self {
        // One pass without divisions; tracing then only clears bits.
        let mut todo = vec![0u8; w * h];
        for y in 0..h {
            for x in 0..w {
                let i = y * w + x;
                let c = comp[i];
                if c == NO_COMP {
                    continue;
                }
                todo[i] = u8::from(y == 0 || comp[i - w] != c)
                    | u8::from(x + 1 == w || comp[i + 1] != c) << 1
                    | u8::from(y + 1 == h || comp[i + w] != c) << 2
                    | u8::from(x == 0 || comp[i - 1] != c) << 3;
            }
        }
        Tracer {
            w,
            h,
            comp,
            labels,
            todo,
        }
    }

    /// Trace every ring, handing each to `emit` with the component it bounds, components' rings
    /// in order of the lowest cell they touch; so a component's first ring is its outer one (it
    /// runs along the bottom of the component's lowest cell, which faces the unbounded outside).
    fn trace_all(mut self, mut emit: impl FnMut(u32, usize, Ring)) {
        for i in 0..self.w * self.h {
            while self.todo[i] != 0 {
                let s = self.todo[i].trailing_zeros() as usize;
                let ring = self.trace(i, s);
                emit(self.comp[i], i, ring);
            }
        }
    }

    /// Walk the ring through the side-`s` edge of cell `i`, marking its edges done.
    fn trace(&mut self, i: usize, s: usize) -> Ring {
        let c = self.comp[i];
        let (x0, y0) = ((i % self.w) as i64, (i / self.w) as i64);
        let (mut x, mut y, mut s) = (x0, y0, s);
        let s0 = s;
        let mut ring = Ring::new();
        let mut lowest = 0;
        loop {
            self.todo[y as usize * self.w + x as usize] &= !(1 << s);
            let d = DIR[s];
            let r = DIR[(s + 3) & 3];
            let (alx, aly) = (x + d[0], y + d[1]);
            let (arx, ary) = (alx + r[0], aly + r[1]);
            let end = CORNER[(s + 1) & 3];
            let vertex = [x + end[0], y + end[1]];
            let keep;
            if self.comp_at(arx, ary) == c {
                // Turn right: also the pinch rule, see the module comment.
                (x, y, s) = (arx, ary, (s + 3) & 3);
                keep = true;
            } else if self.comp_at(alx, aly) == c {
                keep = match self.labels {
                    Some(l) => self.label_at(l, x + r[0], y + r[1]) != self.label_at(l, arx, ary),
                    None => false,
                };
                (x, y) = (alx, aly);
            } else {
                s = (s + 1) & 3;
                keep = true;
            }
            if keep {
                let low = match ring.get(lowest) {
                    Some(&[li, lj]) => (vertex[1], vertex[0]) < (lj, li),
                    None => true,
                };
                if low {
                    lowest = ring.len();
                }
                ring.push(vertex);
            }
            if (x, y, s) == (x0, y0, s0) {
                break;
            }
        }
        // Start every ring at its lowest-then-leftmost vertex so output does not depend on where
        // the scan happened to enter it.
        ring.rotate_left(lowest);
        ring
    }
}

/// One polygon per 4-connected component of every label except [`OUTSIDE`] and [`EMPTY`], sorted
/// by label and then by lowest cell index.
pub fn vectorise(grid: &Grid) -> Vec<LabelPolygon> {
    let (w, h) = (grid.w, grid.h);
    let cells = &grid.cells;
    let (comp, n) = components(
        w,
        h,
        |i| cells[i] != OUTSIDE && cells[i] != EMPTY,
        |i, j| cells[i] == cells[j],
    );
    let mut polys: Vec<LabelPolygon> = Vec::with_capacity(n);
    Tracer::new(w, h, &comp, Some(cells)).trace_all(|c, i, ring| {
        if c as usize == polys.len() {
            polys.push(LabelPolygon {
                label: cells[i],
                outer: ring,
                holes: Vec::new(),
            });
        } else {
            polys[c as usize].holes.push(ring);
        }
    });
    polys.sort_by_key(|p| p.label);
    polys
}

/// Ring vertices in plan metres.
pub fn ring_to_plan(ring: &Ring, frame: &GridFrame) -> Vec<[f64; 2]> {
    ring.iter().map(|&[i, j]| frame.vertex(i, j)).collect()
}

/// Signed shoelace area in cells; positive for counter-clockwise.
pub fn ring_area(ring: &Ring) -> f64 {
    let n = ring.len();
    let twice: i64 = (0..n)
        .map(|k| {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum();
    twice as f64 / 2.0
}

/// Outer ring and holes of the single 4-connected `true` region of a `w × h` row-major mask.
pub fn mask_outline(mask: &[bool], w: usize, h: usize) -> Result<(Ring, Vec<Ring>)> {
    if mask.len() != w * h {
        return Err(CoreError::InvalidInput(format!(
            "mask has {} cells but a {w} × {h} grid needs {}",
            mask.len(),
            w * h
        )));
    }
    let (comp, n) = components(w, h, |i| mask[i], |_, j| mask[j]);
    match n {
        0 => return Err(CoreError::InvalidInput("mask is empty".into())),
        1 => {}
        _ => {
            return Err(CoreError::InvalidInput(format!(
                "mask has {n} separate 4-connected regions; expected exactly one"
            )))
        }
    }
    let mut outer = None;
    let mut holes = Vec::new();
    Tracer::new(w, h, &comp, None).trace_all(|_, _, ring| {
        if outer.is_none() {
            outer = Some(ring);
        } else {
            holes.push(ring);
        }
    });
    Ok((outer.expect("a non-empty mask has a boundary"), holes))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Grid from rows written top-down; `.` is OUTSIDE, `_` EMPTY, digits/letters are labels.
    fn grid(rows: &[&str]) -> Grid {
        let h = rows.len();
        let w = rows[0].len();
        let mut g = Grid::new(w, h, OUTSIDE);
        for (r, row) in rows.iter().enumerate() {
            for (x, ch) in row.chars().enumerate() {
                let l = match ch {
                    '.' => OUTSIDE,
                    '_' => EMPTY,
                    c => c.to_digit(36).unwrap() as Label,
                };
                g.set(x, h - 1 - r, l);
            }
        }
        g
    }

    fn area(p: &LabelPolygon) -> f64 {
        ring_area(&p.outer) + p.holes.iter().map(ring_area).sum::<f64>()
    }

    /// Does `v` lie on some edge of `ring` (including its end points)?
    fn on_ring(ring: &Ring, v: [i64; 2]) -> bool {
        (0..ring.len()).any(|k| {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            let (x0, x1) = (a[0].min(b[0]), a[0].max(b[0]));
            let (y0, y1) = (a[1].min(b[1]), a[1].max(b[1]));
            (x0..=x1).contains(&v[0]) && (y0..=y1).contains(&v[1])
        })
    }

    fn rings(p: &LabelPolygon) -> impl Iterator<Item = &Ring> {
        std::iter::once(&p.outer).chain(p.holes.iter())
    }

    /// Structural checks every output must pass: axis-aligned non-degenerate edges, no vertex
    /// visited twice by one ring, orientations, areas matching cell counts, a vertex shared by
    /// rings of one polygon at most at pinches (never along an edge), and the shared-vertex
    /// property between all polygons.
    fn check(g: &Grid, polys: &[LabelPolygon]) {
        let mut per_label = std::collections::HashMap::<Label, f64>::new();
        for p in polys {
            assert!(
                ring_area(&p.outer) > 0.0,
                "outer ring not counter-clockwise: {p:?}"
            );
            for hole in &p.holes {
                assert!(ring_area(hole) < 0.0, "hole not clockwise: {p:?}");
            }
            for ring in rings(p) {
                assert!(ring.len() >= 4);
                for k in 0..ring.len() {
                    let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                    assert!(
                        (a[0] == b[0]) != (a[1] == b[1]),
                        "bad edge {a:?}-{b:?} in {p:?}"
                    );
                }
                let mut seen = ring.clone();
                seen.sort_unstable();
                seen.dedup();
                assert_eq!(seen.len(), ring.len(), "ring revisits a vertex: {ring:?}");
            }
            // Rings of one polygon meet only at shared vertices, never along a stretch of edge,
            // and a shared vertex is never met by a third ring.
            let all: Vec<&Ring> = rings(p).collect();
            for (a, ra) in all.iter().enumerate() {
                for rb in &all[a + 1..] {
                    for &v in ra.iter() {
                        if on_ring(rb, v) {
                            assert!(rb.contains(&v), "{v:?} on an edge of another ring in {p:?}");
                        }
                    }
                }
            }
            *per_label.entry(p.label).or_default() += area(p);
        }
        for (&l, &a) in &per_label {
            assert_eq!(a, g.count(l) as f64, "label {l}");
        }
        let labels: usize = g
            .cells
            .iter()
            .filter(|&&c| c != OUTSIDE && c != EMPTY)
            .count();
        assert_eq!(per_label.values().sum::<f64>(), labels as f64);
        for (ia, a) in polys.iter().enumerate() {
            for (ib, b) in polys.iter().enumerate() {
                if ia == ib {
                    continue;
                }
                for ra in rings(a) {
                    for &v in ra {
                        for rb in rings(b) {
                            if on_ring(rb, v) {
                                assert!(rb.contains(&v), "{v:?} of {a:?} is mid-edge on {b:?}");
                            }
                        }
                    }
                }
            }
        }
        // Polygon by polygon, the rings read even-odd at cell centres give back exactly the
        // component, and edges of one polygon meet only at vertices they both have.
        let (comp, n) = components(
            g.w,
            g.h,
            |i| g.cells[i] != OUTSIDE && g.cells[i] != EMPTY,
            |i, j| g.cells[i] == g.cells[j],
        );
        assert_eq!(n, polys.len());
        for p in polys {
            // Outer rings start at the bottom-left corner of the component's lowest cell.
            let start = p.outer[0][1] as usize * g.w + p.outer[0][0] as usize;
            assert_eq!(g.cells[start], p.label);
            for (i, &ci) in comp.iter().enumerate() {
                let (cx, cy) = ((i % g.w) as f64 + 0.5, (i / g.w) as f64 + 0.5);
                let mut inside = false;
                for ring in rings(p) {
                    for k in 0..ring.len() {
                        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                        let (y0, y1) = (a[1].min(b[1]) as f64, a[1].max(b[1]) as f64);
                        if a[0] == b[0] && y0 < cy && cy < y1 && (a[0] as f64) > cx {
                            inside = !inside;
                        }
                    }
                }
                let member = ci == comp[start];
                assert_eq!(inside, member, "cell {i} vs polygon {p:?}");
            }
            let edges: Vec<(usize, usize, [i64; 2], [i64; 2])> = rings(p)
                .enumerate()
                .flat_map(|(r, ring)| {
                    (0..ring.len()).map(move |k| (r, k, ring[k], ring[(k + 1) % ring.len()]))
                })
                .collect();
            for (ea, &(ra, ka, a0, a1)) in edges.iter().enumerate() {
                for &(rb, kb, b0, b1) in &edges[ea + 1..] {
                    let lo = [
                        a0[0].min(a1[0]).max(b0[0].min(b1[0])),
                        a0[1].min(a1[1]).max(b0[1].min(b1[1])),
                    ];
                    let hi = [
                        a0[0].max(a1[0]).min(b0[0].max(b1[0])),
                        a0[1].max(a1[1]).min(b0[1].max(b1[1])),
                    ];
                    if lo[0] > hi[0] || lo[1] > hi[1] {
                        continue;
                    }
                    assert_eq!(lo, hi, "edges overlap along a stretch in {p:?}");
                    assert!(
                        (lo == a0 || lo == a1) && (lo == b0 || lo == b1),
                        "edges cross at {lo:?} in {p:?}"
                    );
                    if ra == rb {
                        let n = rings(p).nth(ra).unwrap().len();
                        let d = (ka + n - kb) % n;
                        assert!(d == 1 || d == n - 1, "ring touches itself at {lo:?}");
                    }
                }
            }
        }
        // Same label: ordered by lowest cell, i.e. by the start vertex read row-major.
        for pair in polys.windows(2) {
            let key = |p: &LabelPolygon| (p.label, p.outer[0][1], p.outer[0][0]);
            assert!(key(&pair[0]) < key(&pair[1]), "order: {pair:?}");
        }
        let mut sorted = polys.to_vec();
        sorted.sort_by_key(|p| p.label);
        assert_eq!(sorted, polys, "not sorted by label");
    }

    #[test]
    fn single_cell() {
        let g = grid(&["1"]);
        let p = vectorise(&g);
        assert_eq!(
            p,
            [LabelPolygon {
                label: 1,
                outer: vec![[0, 0], [1, 0], [1, 1], [0, 1]],
                holes: vec![],
            }]
        );
        check(&g, &p);
    }

    #[test]
    fn markers_are_skipped() {
        let g = grid(&["._", "_."]);
        assert!(vectorise(&g).is_empty());
        assert!(vectorise(&Grid::new(0, 0, OUTSIDE)).is_empty());
    }

    #[test]
    fn rectangle() {
        let g = grid(&["...", ".11", ".11", ".11"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].outer, vec![[1, 0], [3, 0], [3, 3], [1, 3]]);
        check(&g, &p);
    }

    #[test]
    fn l_shape() {
        let g = grid(&["1..", "1..", "111"]);
        let p = vectorise(&g);
        assert_eq!(
            p[0].outer,
            vec![[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]]
        );
        assert_eq!(area(&p[0]), 5.0);
        check(&g, &p);
    }

    #[test]
    fn t_junctions_against_markers() {
        // The bottom edge of room 1 borders OUTSIDE then EMPTY: a vertex where they change.
        let g = grid(&["11", "._"]);
        let p = vectorise(&g);
        assert_eq!(p[0].outer, vec![[0, 1], [1, 1], [2, 1], [2, 2], [0, 2]]);
        check(&g, &p);
    }

    #[test]
    fn room_with_hole() {
        let g = grid(&["1111", "1221", "1221", "1111"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].label, 1);
        assert_eq!(p[0].outer, vec![[0, 0], [4, 0], [4, 4], [0, 4]]);
        assert_eq!(p[0].holes, vec![vec![[1, 1], [1, 3], [3, 3], [3, 1]]]);
        assert_eq!(p[1].outer, vec![[1, 1], [3, 1], [3, 3], [1, 3]]);
        assert_eq!(area(&p[0]), 12.0);
        check(&g, &p);
    }

    #[test]
    fn shared_partial_edge() {
        // Room 1 is 3 wide, room 2 sits on its top over columns 1..3 and overhangs to 4.
        let g = grid(&[".2222", ".2222", "111..", "111.."]);
        let p = vectorise(&g);
        assert_eq!(p[0].outer, vec![[0, 0], [3, 0], [3, 2], [1, 2], [0, 2]]);
        assert_eq!(p[1].outer, vec![[1, 2], [3, 2], [5, 2], [5, 4], [1, 4]]);
        // The shared wall (1,2)-(3,2) appears as the same vertex sequence, reversed.
        let a = &p[0].outer;
        let b = &p[1].outer;
        assert_eq!(&a[2..4], &[[3, 2], [1, 2]]);
        assert_eq!(&b[0..2], &[[1, 2], [3, 2]]);
        check(&g, &p);
    }

    #[test]
    fn three_rooms_meet() {
        let g = grid(&["2233", "2233", "1111"]);
        let p = vectorise(&g);
        assert_eq!(p[0].outer, vec![[0, 0], [4, 0], [4, 1], [2, 1], [0, 1]]);
        assert_eq!(p[1].outer, vec![[0, 1], [2, 1], [2, 3], [0, 3]]);
        assert_eq!(p[2].outer, vec![[2, 1], [4, 1], [4, 3], [2, 3]]);
        check(&g, &p);
    }

    #[test]
    fn checkerboard_pinch() {
        let g = grid(&["21", "12"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 4);
        let outers: Vec<(Label, Ring)> = p.iter().map(|q| (q.label, q.outer.clone())).collect();
        assert_eq!(
            outers,
            [
                (1, vec![[0, 0], [1, 0], [1, 1], [0, 1]]),
                (1, vec![[1, 1], [2, 1], [2, 2], [1, 2]]),
                (2, vec![[1, 0], [2, 0], [2, 1], [1, 1]]),
                (2, vec![[0, 1], [1, 1], [1, 2], [0, 2]]),
            ]
        );
        check(&g, &p);
    }

    #[test]
    fn u_whose_arms_touch_diagonally() {
        // The arms of the U meet only at vertex (2, 2): the enclosed cell becomes a hole touching
        // the outer ring at that vertex, and no ring visits a vertex twice.
        let g = grid(&["11.", "1.1", "111"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 1);
        assert_eq!(
            p[0].outer,
            vec![[0, 0], [3, 0], [3, 2], [2, 2], [2, 3], [0, 3]]
        );
        assert_eq!(p[0].holes, vec![vec![[1, 1], [1, 2], [2, 2], [2, 1]]]);
        assert_eq!(area(&p[0]), 7.0);
        check(&g, &p);
        // Same with the enclosed cell owned by another room, which comes out as its own square.
        let g = grid(&["11.", "121", "111"]);
        let p = vectorise(&g);
        assert_eq!(p[0].holes, vec![vec![[1, 1], [1, 2], [2, 2], [2, 1]]]);
        assert_eq!(p[1].outer, vec![[1, 1], [2, 1], [2, 2], [1, 2]]);
        check(&g, &p);
    }

    #[test]
    fn holes_touching_each_other_at_a_pinch() {
        let g = grid(&["11111", "1.111", "11.11", "11111"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].holes.len(), 2);
        assert_eq!(area(&p[0]), 18.0);
        check(&g, &p);
    }

    #[test]
    fn same_label_components_are_separate() {
        let g = grid(&["1.1", "1.1"]);
        let p = vectorise(&g);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].outer[0], [0, 0]);
        assert_eq!(p[1].outer[0], [2, 0]);
        check(&g, &p);
    }

    #[test]
    fn ring_helpers() {
        let r: Ring = vec![[0, 0], [2, 0], [2, 1], [0, 1]];
        assert_eq!(ring_area(&r), 2.0);
        let rev: Ring = r.iter().rev().copied().collect();
        assert_eq!(ring_area(&rev), -2.0);
        let f = GridFrame {
            origin: [1.0, 2.0],
            cell: 0.5,
            w: 2,
            h: 1,
        };
        assert_eq!(
            ring_to_plan(&r, &f),
            vec![[1.0, 2.0], [2.0, 2.0], [2.0, 2.5], [1.0, 2.5]]
        );
    }

    #[test]
    fn mask_outline_shapes_and_errors() {
        let (outer, holes) = mask_outline(&[true], 1, 1).unwrap();
        assert_eq!(outer, vec![[0, 0], [1, 0], [1, 1], [0, 1]]);
        assert!(holes.is_empty());
        // Ring with a hole, rows bottom-up.
        #[rustfmt::skip]
        let m = [
            true, true, true,
            true, false, true,
            true, true, true,
        ];
        let (outer, holes) = mask_outline(&m, 3, 3).unwrap();
        assert_eq!(outer, vec![[0, 0], [3, 0], [3, 3], [0, 3]]);
        assert_eq!(holes, vec![vec![[1, 1], [1, 2], [2, 2], [2, 1]]]);
        let err = |m: &[bool], w, h| match mask_outline(m, w, h) {
            Err(CoreError::InvalidInput(s)) => s,
            other => panic!("{other:?}"),
        };
        assert!(err(&[false; 4], 2, 2).contains("empty"));
        assert!(err(&[], 0, 0).contains("empty"));
        assert!(err(&[true, false, false, true], 2, 2).contains("2 separate"));
        assert!(err(&[true, false, true, false, true], 5, 1).contains("3 separate"));
        assert!(err(&[true], 2, 1).contains("1 cells"));
    }

    /// Tiny LCG so the test needs no dependency.
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> u32 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 33) as u32
        }
    }

    #[test]
    fn random_grids() {
        let mut rng = Lcg(12345);
        for round in 0..300 {
            let w = 1 + rng.next() as usize % 12;
            let h = 1 + rng.next() as usize % 12;
            let k = 1 + rng.next() % 5;
            let mut g = Grid::new(w, h, OUTSIDE);
            for c in &mut g.cells {
                let r = rng.next() % (k + 2);
                *c = match r {
                    0 => OUTSIDE,
                    1 if round % 2 == 0 => EMPTY,
                    _ => (r % k) as Label,
                };
            }
            let p = vectorise(&g);
            check(&g, &p);
        }
    }

    #[test]
    fn random_masks_match_vectorise() {
        let mut rng = Lcg(99);
        let mut tested = 0;
        while tested < 200 {
            let w = 1 + rng.next() as usize % 10;
            let h = 1 + rng.next() as usize % 10;
            let mask: Vec<bool> = (0..w * h).map(|_| rng.next() % 3 < 2).collect();
            let Ok((outer, holes)) = mask_outline(&mask, w, h) else {
                continue;
            };
            tested += 1;
            let mut g = Grid::new(w, h, OUTSIDE);
            for (c, &m) in g.cells.iter_mut().zip(&mask) {
                if m {
                    *c = 0;
                }
            }
            // With one label against OUTSIDE only, there are no T-junctions: same rings.
            let p = vectorise(&g);
            assert_eq!(p.len(), 1);
            assert_eq!(p[0].outer, outer);
            assert_eq!(p[0].holes, holes);
        }
    }
}
