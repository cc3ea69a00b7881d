//! Small objects on a receptacle's top: shelf packing of their footprints in the top's frame.
//!
//! Objects are taken in the order given (the planner's preference); each goes into the first row
//! with room, else into a new row behind, trying both orientations. Objects that fit nowhere are
//! skipped, never squeezed.

/// Where one small object goes: its index in the input, its centre in the receptacle's frame,
/// and whether it is turned by 90°.
#[derive(Debug, Clone, PartialEq)]
pub struct Packed {
    pub index: usize,
    pub center: [f64; 2],
    pub turned: bool,
}

struct Row {
    y0: f64,
    depth: f64,
    used: f64,
}

/// Pack `sizes` (width, depth) on a `width` × `depth` top, keeping `margin` free at its edges
/// and `gap` between objects.
pub fn pack_top(width: f64, depth: f64, margin: f64, gap: f64, sizes: &[[f64; 2]]) -> Vec<Packed> {
    let (w, d) = (width - 2.0 * margin, depth - 2.0 * margin);
    let mut out = Vec::new();
    if w <= 0.0 || d <= 0.0 {
        return out;
    }
    let mut rows: Vec<Row> = Vec::new();
    for (index, s) in sizes.iter().enumerate() {
        for turned in [false, true] {
            let (ow, od) = if turned { (s[1], s[0]) } else { (s[0], s[1]) };
            if ow > w || od > d {
                continue;
            }
            let n = rows.len();
            // an existing row: the last one may grow deeper while the top has room
            let slot = rows.iter().enumerate().position(|(k, r)| {
                let x = if r.used > 0.0 { r.used + gap } else { 0.0 };
                x + ow <= w && (od <= r.depth || (k + 1 == n && r.y0 + od <= d))
            });
            let k = match slot {
                Some(k) => k,
                None => {
                    let y0 = rows.last().map_or(0.0, |r| r.y0 + r.depth + gap);
                    if y0 + od > d {
                        continue;
                    }
                    rows.push(Row {
                        y0,
                        depth: 0.0,
                        used: 0.0,
                    });
                    rows.len() - 1
                }
            };
            let r = &mut rows[k];
            let x = if r.used > 0.0 { r.used + gap } else { 0.0 };
            r.used = x + ow;
            r.depth = r.depth.max(od);
            out.push(Packed {
                index,
                center: [-w / 2.0 + x + ow / 2.0, -d / 2.0 + r.y0 + od / 2.0],
                turned,
            });
            break;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn overlap(a: &Packed, sa: [f64; 2], b: &Packed, sb: [f64; 2]) -> bool {
        let ext = |p: &Packed, s: [f64; 2]| if p.turned { [s[1], s[0]] } else { s };
        let (ea, eb) = (ext(a, sa), ext(b, sb));
        (a.center[0] - b.center[0]).abs() < (ea[0] + eb[0]) / 2.0 - 1e-9
            && (a.center[1] - b.center[1]).abs() < (ea[1] + eb[1]) / 2.0 - 1e-9
    }

    #[test]
    fn packs_without_overlap_inside_the_margin() {
        let sizes = [
            [0.3, 0.2],
            [0.3, 0.2],
            [0.2, 0.2],
            [0.5, 0.1],
            [0.6, 0.6],
            [0.1, 0.1],
        ];
        let p = pack_top(1.0, 0.6, 0.03, 0.02, &sizes);
        // the 0.6 × 0.6 object cannot fit a 0.94 × 0.54 usable top in either orientation
        assert!(p.iter().all(|q| q.index != 4));
        assert_eq!(p.len(), 5);
        for (i, a) in p.iter().enumerate() {
            let s = sizes[a.index];
            let e = if a.turned { [s[1], s[0]] } else { s };
            assert!(a.center[0].abs() + e[0] / 2.0 <= 0.47 + 1e-9);
            assert!(a.center[1].abs() + e[1] / 2.0 <= 0.27 + 1e-9);
            for b in &p[i + 1..] {
                assert!(!overlap(a, s, b, sizes[b.index]));
            }
        }
    }

    #[test]
    fn a_tiny_top_takes_nothing() {
        assert!(pack_top(0.05, 0.05, 0.03, 0.02, &[[0.01, 0.01]]).is_empty());
    }
}
