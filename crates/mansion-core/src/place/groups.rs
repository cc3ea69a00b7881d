//! Normalising a plan into groups, and the shapes the engine places.
//!
//! A group is an anchor (an item that is not paired) and the members paired with it, each member
//! at a fixed pose in the anchor's frame. A shape is what one search places at once: one object,
//! a whole group, or a matrix of group units as one macro object; its entries are poses in the
//! shape's frame, and its bounds are what the candidate generator fits against walls.

use super::geometry::{frame, Footprint, Iso};
use super::spec::{ItemSpec, Side, Structure, Tag};
use crate::error::{CoreError, Result};
use nalgebra::{Isometry2, Vector2};
use std::collections::HashMap;

/// A paired member at its pose in the anchor's frame.
#[derive(Debug, Clone)]
pub struct Member {
    pub item: usize,
    pub local: Iso,
    pub tucked: bool,
}

#[derive(Debug, Clone)]
pub struct Group {
    pub anchor: usize,
    pub members: Vec<Member>,
    pub tag: Tag,
    /// rows, cols, row gap, col gap.
    pub matrix: Option<(u32, u32, f64, f64)>,
}

impl Group {
    /// The paper's order: edge+matrix ≻ edge ≻ matrix ≻ middle ≻ free.
    pub fn priority(&self) -> u8 {
        match (self.tag, self.matrix.is_some()) {
            (Tag::Edge, true) => 0,
            (Tag::Edge, false) => 1,
            (_, true) => 2,
            (Tag::Middle, false) => 3,
            (Tag::Unconstrained, false) => 4,
        }
    }
}

/// One object of a shape: its item, its pose in the shape's frame, and the entry it is tucked
/// under (an index into the same shape), if any.
#[derive(Debug, Clone)]
pub struct Entry {
    pub item: usize,
    pub local: Iso,
    pub tucked_under: Option<usize>,
    /// Index of the group anchor's entry (itself for an anchor).
    pub anchor: usize,
}

#[derive(Debug, Clone)]
pub struct Shape {
    pub entries: Vec<Entry>,
    /// [min x, min y, max x, max y] of every entry's footprint in the shape's frame.
    pub bounds: [f64; 4],
}

impl Shape {
    pub fn footprint(&self, items: &[ItemSpec], shape_frame: &Iso, k: usize) -> Footprint {
        let e = &self.entries[k];
        let s = items[e.item].size;
        Footprint::new(shape_frame * e.local, s[0], s[1])
    }

    /// The bounds as one footprint (the macro object).
    pub fn hull(&self, shape_frame: &Iso) -> Footprint {
        let [x0, y0, x1, y1] = self.bounds;
        let c = Isometry2::translation((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        Footprint::new(shape_frame * c, x1 - x0, y1 - y0)
    }

    fn from_entries(items: &[ItemSpec], entries: Vec<Entry>) -> Self {
        let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        for e in &entries {
            let s = items[e.item].size;
            let a = Footprint::new(e.local, s[0], s[1]).aabb();
            b = [
                b[0].min(a[0]),
                b[1].min(a[1]),
                b[2].max(a[2]),
                b[3].max(a[3]),
            ];
        }
        Self { entries, bounds: b }
    }
}

fn check_item(room: &str, it: &ItemSpec) -> Result<()> {
    if it.size.iter().any(|v| !(v.is_finite() && *v > 0.0)) {
        return Err(CoreError::InvalidInput(format!(
            "room {room}: item {} has size {:?}; width, depth and height must be positive",
            it.id, it.size
        )));
    }
    if let Structure::Matrix {
        rows,
        cols,
        row_gap,
        col_gap,
    } = it.structure
    {
        if rows == 0 || cols == 0 || !(row_gap >= 0.0 && col_gap >= 0.0) {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: matrix item {} needs rows, cols ≥ 1 and gaps ≥ 0",
                it.id
            )));
        }
    }
    for s in &it.small {
        if s.size.iter().any(|v| !(v.is_finite() && *v > 0.0)) {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: small object {} on {} has size {:?}",
                s.object_type, it.id, s.size
            )));
        }
    }
    Ok(())
}

/// Member poses in the anchor's frame for one paired item. `gap` separates untucked members
/// from the anchor.
fn member_poses(anchor: &ItemSpec, member: &ItemSpec, gap: f64) -> Vec<(Iso, bool)> {
    let Structure::Paired {
        side, count, tuck, ..
    } = member.structure
    else {
        return Vec::new();
    };
    let [wa, da, _] = anchor.size;
    let [wm, dm, _] = member.size;
    let tucked = tuck > 0.0;
    // how far the member's centre sits from the anchor's face it is pushed against
    let off = |depth: f64| {
        if tucked {
            depth / 2.0 - tuck * depth
        } else {
            depth / 2.0 + gap
        }
    };
    let back_flush = -da / 2.0 + dm / 2.0;
    let beside = wa / 2.0 + gap + wm / 2.0;
    match side {
        Side::Front => (0..count.max(1))
            .map(|k| (spread(k, count.max(1), wa), da / 2.0 + off(dm), 180.0))
            .map(|(x, y, yaw)| (frame([x, y], yaw), tucked))
            .collect(),
        Side::Back => (0..count.max(1))
            .map(|k| (spread(k, count.max(1), wa), -da / 2.0 - off(dm), 0.0))
            .map(|(x, y, yaw)| (frame([x, y], yaw), tucked))
            .collect(),
        Side::Left => vec![(frame([-beside, back_flush], 0.0), false)],
        Side::Right => vec![(frame([beside, back_flush], 0.0), false)],
        Side::Sides => vec![
            (frame([-beside, back_flush], 0.0), false),
            (frame([beside, back_flush], 0.0), false),
        ],
        Side::Around => {
            // fill front, back, left, right in turn, as many per side as fit along it
            let fits = |len: f64| ((len + 0.05) / (wm + 0.05)).floor().max(0.0) as u32;
            let caps = [fits(wa).max(1), fits(wa).max(1), fits(da), fits(da)];
            let mut per = [0u32; 4];
            let mut left = count;
            while left > 0 && per.iter().zip(&caps).any(|(p, c)| p < c) {
                for s in 0..4 {
                    if left > 0 && per[s] < caps[s] {
                        per[s] += 1;
                        left -= 1;
                    }
                }
            }
            let mut out = Vec::new();
            for k in 0..per[0] {
                out.push(frame([spread(k, per[0], wa), da / 2.0 + off(dm)], 180.0));
            }
            for k in 0..per[1] {
                out.push(frame([spread(k, per[1], wa), -da / 2.0 - off(dm)], 0.0));
            }
            for k in 0..per[2] {
                out.push(frame([-wa / 2.0 - off(dm), spread(k, per[2], da)], 90.0));
            }
            for k in 0..per[3] {
                out.push(frame([wa / 2.0 + off(dm), spread(k, per[3], da)], 270.0));
            }
            out.into_iter().map(|f| (f, tucked)).collect()
        }
    }
}

/// Centre of the k-th of n equal slots along a side of length `len` centred on 0.
fn spread(k: u32, n: u32, len: f64) -> f64 {
    -len / 2.0 + (k as f64 + 0.5) * len / n as f64
}

/// The groups of a plan, in placement order (stable within a priority).
pub fn normalise(room: &str, items: &[ItemSpec], gap: f64) -> Result<Vec<Group>> {
    let mut index: HashMap<&str, usize> = HashMap::new();
    for (i, it) in items.iter().enumerate() {
        check_item(room, it)?;
        if index.insert(it.id.as_str(), i).is_some() {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: item id {} appears twice",
                it.id
            )));
        }
    }
    for it in items {
        for r in &it.relations {
            if !index.contains_key(r.target.as_str()) {
                return Err(CoreError::InvalidInput(format!(
                    "room {room}: item {} relates to {}, which is not in the plan",
                    it.id, r.target
                )));
            }
        }
    }
    let mut groups: Vec<Group> = Vec::new();
    let mut group_of: HashMap<usize, usize> = HashMap::new();
    for (i, it) in items.iter().enumerate() {
        let matrix = match it.structure {
            Structure::Paired { .. } => continue,
            Structure::Single => None,
            Structure::Matrix {
                rows,
                cols,
                row_gap,
                col_gap,
            } => Some((rows, cols, row_gap, col_gap)),
        };
        group_of.insert(i, groups.len());
        groups.push(Group {
            anchor: i,
            members: Vec::new(),
            tag: it.tag,
            matrix,
        });
    }
    for (i, it) in items.iter().enumerate() {
        let Structure::Paired { partner, tuck, .. } = &it.structure else {
            continue;
        };
        if !(0.0..1.0).contains(tuck) {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: item {} has tuck {tuck}; it must be in [0, 1)",
                it.id
            )));
        }
        let Some(&p) = index.get(partner.as_str()) else {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: item {} is paired with {partner}, which is not in the plan",
                it.id
            )));
        };
        let Some(&g) = group_of.get(&p) else {
            return Err(CoreError::InvalidInput(format!(
                "room {room}: item {} is paired with {partner}, which is itself paired; \
                 pair members with the anchor",
                it.id
            )));
        };
        for (local, tucked) in member_poses(&items[p], it, gap) {
            groups[g].members.push(Member {
                item: i,
                local,
                tucked,
            });
        }
    }
    groups.sort_by_key(Group::priority);
    Ok(groups)
}

/// The anchor alone.
pub fn single_shape(items: &[ItemSpec], item: usize) -> Shape {
    Shape::from_entries(
        items,
        vec![Entry {
            item,
            local: Iso::identity(),
            tucked_under: None,
            anchor: 0,
        }],
    )
}

/// The anchor and its members; members that collide with the anchor (untucked) or with an
/// earlier member are left out and returned as the second value.
pub fn group_shape(items: &[ItemSpec], g: &Group, gap: f64) -> (Shape, Vec<usize>) {
    let mut entries = vec![Entry {
        item: g.anchor,
        local: Iso::identity(),
        tucked_under: None,
        anchor: 0,
    }];
    let mut left_out = Vec::new();
    for m in &g.members {
        let e = Entry {
            item: m.item,
            local: m.local,
            tucked_under: m.tucked.then_some(0),
            anchor: 0,
        };
        if conflicts_within(items, &entries, &e, gap) {
            left_out.push(m.item);
        } else {
            entries.push(e);
        }
    }
    (Shape::from_entries(items, entries), left_out)
}

fn conflicts_within(items: &[ItemSpec], entries: &[Entry], e: &Entry, gap: f64) -> bool {
    let s = items[e.item].size;
    let fp = Footprint::new(e.local, s[0], s[1]);
    entries.iter().enumerate().any(|(k, o)| {
        if e.tucked_under == Some(k) {
            return false;
        }
        let so = items[o.item].size;
        fp.conflicts(&Footprint::new(o.local, so[0], so[1]), gap)
    })
}

/// `rows` × `cols` units of the group (anchor + members that fit), as one macro object centred
/// on its frame's origin. Rows advance along the front axis, columns along the right axis.
pub fn matrix_shape(items: &[ItemSpec], g: &Group, rows: u32, cols: u32, gap: f64) -> Shape {
    let (_, _, row_gap, col_gap) = g.matrix.unwrap_or((1, 1, 0.0, 0.0));
    let (unit, _) = group_shape(items, g, gap);
    let [x0, y0, x1, y1] = unit.bounds;
    let (pw, pd) = (x1 - x0 + col_gap, y1 - y0 + row_gap);
    let (total_w, total_d) = (cols as f64 * pw - col_gap, rows as f64 * pd - row_gap);
    let mut entries = Vec::new();
    for r in 0..rows {
        for c in 0..cols {
            let shift = Vector2::new(
                c as f64 * pw - x0 - total_w / 2.0,
                r as f64 * pd - y0 - total_d / 2.0,
            );
            let offset = Isometry2::new(shift, 0.0);
            let base = entries.len();
            for e in &unit.entries {
                entries.push(Entry {
                    item: e.item,
                    local: offset * e.local,
                    tucked_under: e.tucked_under.map(|t| base + t),
                    anchor: base,
                });
            }
        }
    }
    Shape::from_entries(items, entries)
}

/// The next smaller matrix: drop a column when there are at least as many columns as rows.
pub fn downgrade(rows: u32, cols: u32) -> (u32, u32) {
    if cols >= rows {
        (rows, cols - 1)
    } else {
        (rows - 1, cols)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::place::spec::{Relation, RelationKind};

    fn item(id: &str, size: [f64; 3], tag: Tag, structure: Structure) -> ItemSpec {
        ItemSpec::new(id, id, size, tag, structure)
    }

    fn paired(partner: &str, side: Side, count: u32, tuck: f64) -> Structure {
        Structure::paired(partner, side, count, tuck)
    }

    #[test]
    fn priority_order_follows_the_paper() {
        let m = Structure::Matrix {
            rows: 2,
            cols: 2,
            row_gap: 0.8,
            col_gap: 0.6,
        };
        let items = vec![
            item(
                "free",
                [1.0, 1.0, 1.0],
                Tag::Unconstrained,
                Structure::Single,
            ),
            item("mid", [1.0, 1.0, 1.0], Tag::Middle, Structure::Single),
            item("mat", [1.0, 1.0, 1.0], Tag::Middle, m.clone()),
            item("edge", [1.0, 1.0, 1.0], Tag::Edge, Structure::Single),
            item("edgemat", [1.0, 1.0, 1.0], Tag::Edge, m),
        ];
        let order: Vec<&str> = normalise("r", &items, 0.02)
            .unwrap()
            .iter()
            .map(|g| items[g.anchor].id.as_str())
            .collect();
        assert_eq!(order, ["edgemat", "edge", "mat", "mid", "free"]);
    }

    #[test]
    fn members_sit_in_the_anchor_frame() {
        let items = vec![
            item("bed", [1.6, 2.0, 0.6], Tag::Edge, Structure::Single),
            item(
                "stand",
                [0.5, 0.4, 0.5],
                Tag::Edge,
                paired("bed", Side::Sides, 1, 0.0),
            ),
            item(
                "chair",
                [0.5, 0.5, 0.9],
                Tag::Edge,
                paired("bed", Side::Front, 1, 0.4),
            ),
        ];
        let groups = normalise("r", &items, 0.02).unwrap();
        assert_eq!(groups.len(), 1);
        let (shape, left_out) = group_shape(&items, &groups[0], 0.02);
        assert!(left_out.is_empty());
        assert_eq!(shape.entries.len(), 4);
        // nightstands flush with the bed's back, 0.02 m beside it
        let s = shape.entries[1].local.translation.vector;
        assert!((s.x + 1.07).abs() < 1e-9 && (s.y + 0.8).abs() < 1e-9);
        // the chair is pushed 40 % of its depth under the bed's front and faces it
        let c = &shape.entries[3];
        assert_eq!(c.tucked_under, Some(0));
        assert!((c.local.translation.vector.y - (1.0 + 0.25 - 0.2)).abs() < 1e-9);
        assert!((super::super::geometry::yaw_of(&c.local) - 180.0).abs() < 1e-9);
        assert!((shape.bounds[1] + 1.0).abs() < 1e-9);
    }

    #[test]
    fn around_fills_the_sides_in_turn_and_matrices_tile_units() {
        let items = vec![
            item(
                "table",
                [1.0, 1.0, 0.75],
                Tag::Middle,
                Structure::Matrix {
                    rows: 2,
                    cols: 3,
                    row_gap: 0.8,
                    col_gap: 0.6,
                },
            ),
            item(
                "chair",
                [0.45, 0.45, 0.9],
                Tag::Middle,
                paired("table", Side::Around, 4, 0.3),
            ),
        ];
        let groups = normalise("r", &items, 0.02).unwrap();
        let (unit, left_out) = group_shape(&items, &groups[0], 0.02);
        assert!(left_out.is_empty());
        assert_eq!(unit.entries.len(), 5);
        let m = matrix_shape(&items, &groups[0], 2, 3, 0.02);
        assert_eq!(m.entries.len(), 30);
        let (uw, ud) = (
            unit.bounds[2] - unit.bounds[0],
            unit.bounds[3] - unit.bounds[1],
        );
        assert!((m.bounds[2] - m.bounds[0] - (3.0 * uw + 1.2)).abs() < 1e-9);
        assert!((m.bounds[3] - m.bounds[1] - (2.0 * ud + 0.8)).abs() < 1e-9);
        assert!((m.bounds[0] + m.bounds[2]).abs() < 1e-9);
        assert_eq!(downgrade(2, 3), (2, 2));
        assert_eq!(downgrade(3, 2), (2, 2));
    }

    #[test]
    fn malformed_plans_are_named() {
        let mut items = vec![
            item("a", [1.0, 1.0, 1.0], Tag::Edge, Structure::Single),
            item(
                "b",
                [1.0, 1.0, 1.0],
                Tag::Edge,
                paired("zzz", Side::Front, 1, 0.0),
            ),
        ];
        let err = normalise("kitchen", &items, 0.02).unwrap_err().to_string();
        assert!(err.contains("kitchen") && err.contains("zzz"), "{err}");
        items[1].structure = paired("a", Side::Front, 1, 0.0);
        items.push(item(
            "c",
            [1.0, 1.0, 1.0],
            Tag::Edge,
            paired("b", Side::Front, 1, 0.0),
        ));
        assert!(normalise("r", &items, 0.02).is_err());
        items.pop();
        items[0].relations.push(Relation {
            kind: RelationKind::Near,
            target: "nope".into(),
        });
        assert!(normalise("r", &items, 0.02).is_err());
        items[0].relations.clear();
        items[0].size[0] = -1.0;
        assert!(normalise("r", &items, 0.02).is_err());
    }
}
