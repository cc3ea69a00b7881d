//! Incremental reachability on a fine free-space grid.
//!
//! A cell is free when its centre is inside the room and the agent's disc there touches no wall
//! (the boundary without the door openings) and no object: the configuration space of a round
//! robot, sampled at cell centres. A flood fill (4-connected) from the free cells in the first
//! door's swing zone gives the reachable cells; the room passes when every door's swing zone
//! holds a reached cell and every object has a reached cell within the reach distance of its
//! footprint (in front of it when it has a front).
//!
//! The engine places objects one candidate at a time, so the grid counts, per cell, how many
//! objects block it: a candidate is added, tested and removed again without rebuilding anything.
//! When none of the cells a candidate blocks was reached, the reachable set cannot have changed
//! and the flood fill is skipped.

use super::geometry::{Footprint, Room, Wall};
use crate::error::{CoreError, Result};

/// Tolerance that keeps the engine conservative against an exact re-check: a cell is blocked
/// slightly before the disc touches, and reach is granted slightly short of the limit.
const EPS: f64 = 1e-6;

pub struct ReachGrid {
    pub origin: [f64; 2],
    pub cell: f64,
    pub w: usize,
    pub h: usize,
    radius: f64,
    reach: f64,
    /// Centre inside the room and clear of the walls by the agent's radius.
    open: Vec<bool>,
    /// Objects whose inflated footprint covers the cell.
    blocked: Vec<u16>,
    /// `stamp[i] == generation` marks cells reached by the last flood fill.
    stamp: Vec<u32>,
    generation: u32,
    queue: Vec<u32>,
    /// Open cells inside each door's swing zone.
    entrances: Vec<Vec<u32>>,
    pub flood_fills: usize,
}

impl ReachGrid {
    /// `walls` are the solid parts of the boundary, `zones` the doors' swing zones.
    pub fn new(
        room_id: &str,
        room: &Room,
        walls: &[Wall],
        zones: &[Footprint],
        radius: f64,
        reach: f64,
        cell: f64,
    ) -> Result<Self> {
        if !(cell > 0.0 && cell.is_finite() && radius >= 0.0 && reach > 0.0) {
            return Err(CoreError::InvalidInput(format!(
                "room {room_id}: cell {cell}, agent radius {radius} and reach {reach} must be positive"
            )));
        }
        let [x0, y0, x1, y1] = room.bounds;
        let w = ((x1 - x0) / cell).ceil() as usize;
        let h = ((y1 - y0) / cell).ceil() as usize;
        if w * h > 40_000_000 {
            return Err(CoreError::InvalidInput(format!(
                "room {room_id}: a {w}×{h} free-space grid is too large; use a coarser cell"
            )));
        }
        let mut g = Self {
            origin: [x0, y0],
            cell,
            w,
            h,
            radius,
            reach,
            open: vec![false; w * h],
            blocked: vec![0; w * h],
            stamp: vec![0; w * h],
            generation: 0,
            queue: Vec::with_capacity(w * h),
            entrances: Vec::new(),
            flood_fills: 0,
        };
        for y in 0..h {
            for x in 0..w {
                let p = g.center_of(x, y);
                g.open[y * w + x] = room.contains(p)
                    && walls
                        .iter()
                        .all(|wall| wall.distance_to_point(p) >= radius + EPS);
            }
        }
        for (k, z) in zones.iter().enumerate() {
            let cells: Vec<u32> = g
                .cells_within(z, 0.0)
                .into_iter()
                .filter(|&i| g.open[i as usize])
                .collect();
            if cells.is_empty() {
                return Err(CoreError::InvalidInput(format!(
                    "room {room_id}: door {k} leaves no free cell for an agent of radius {radius} m \
                     (is it narrower than the agent?)"
                )));
            }
            g.entrances.push(cells);
        }
        if g.entrances.is_empty() {
            return Err(CoreError::InvalidInput(format!(
                "room {room_id}: no door; reachability is measured from the entrance"
            )));
        }
        Ok(g)
    }

    pub fn center_of(&self, x: usize, y: usize) -> [f64; 2] {
        [
            self.origin[0] + (x as f64 + 0.5) * self.cell,
            self.origin[1] + (y as f64 + 0.5) * self.cell,
        ]
    }

    pub fn center(&self, i: u32) -> [f64; 2] {
        let i = i as usize;
        self.center_of(i % self.w, i / self.w)
    }

    /// Cells whose centre lies closer than `dist` to the footprint (inside it when `dist` is 0).
    pub fn cells_within(&self, fp: &Footprint, dist: f64) -> Vec<u32> {
        let b = fp.aabb();
        let lo_x = (((b[0] - dist - self.origin[0]) / self.cell)
            .floor()
            .max(0.0)) as usize;
        let lo_y = (((b[1] - dist - self.origin[1]) / self.cell)
            .floor()
            .max(0.0)) as usize;
        let hi_x = (((b[2] + dist - self.origin[0]) / self.cell).ceil() as usize).min(self.w);
        let hi_y = (((b[3] + dist - self.origin[1]) / self.cell).ceil() as usize).min(self.h);
        let mut out = Vec::new();
        for y in lo_y..hi_y {
            for x in lo_x..hi_x {
                let d = fp.distance_to_point(self.center_of(x, y));
                if (dist == 0.0 && d == 0.0) || d < dist {
                    out.push((y * self.w + x) as u32);
                }
            }
        }
        out
    }

    /// Mark the cells the agent's disc cannot occupy beside this footprint; returns them so that
    /// `unblock` can undo it.
    pub fn block(&mut self, fp: &Footprint) -> Vec<u32> {
        let cells = self.cells_within(fp, self.radius + EPS);
        for &i in &cells {
            self.blocked[i as usize] += 1;
        }
        cells
    }

    pub fn unblock(&mut self, cells: &[u32]) {
        for &i in cells {
            self.blocked[i as usize] -= 1;
        }
    }

    /// The cells from which the agent reaches the footprint.
    pub fn interaction_cells(&self, fp: &Footprint, has_front: bool) -> Vec<u32> {
        self.cells_within(fp, self.reach - EPS)
            .into_iter()
            .filter(|&i| self.open[i as usize])
            .filter(|&i| !has_front || fp.in_front(self.center(i), EPS))
            .collect()
    }

    fn free(&self, i: usize) -> bool {
        self.open[i] && self.blocked[i] == 0
    }

    /// Whether any of `cells` was reached by the last flood fill (and is still free).
    pub fn touches_reached(&self, cells: &[u32]) -> bool {
        cells
            .iter()
            .any(|&i| self.stamp[i as usize] == self.generation)
    }

    pub fn reached(&self, i: u32) -> bool {
        self.stamp[i as usize] == self.generation && self.free(i as usize)
    }

    /// Flood fill from the first door's free entrance cells.
    pub fn flood(&mut self) {
        self.flood_fills += 1;
        self.generation += 1;
        let gen = self.generation;
        self.queue.clear();
        for &i in &self.entrances[0] {
            if self.free(i as usize) && self.stamp[i as usize] != gen {
                self.stamp[i as usize] = gen;
                self.queue.push(i);
            }
        }
        let (w, h) = (self.w, self.h);
        let mut head = 0;
        while head < self.queue.len() {
            let i = self.queue[head] as usize;
            head += 1;
            let (x, y) = (i % w, i / w);
            let visit = |j: usize, q: &mut Vec<u32>, stamp: &mut Vec<u32>| {
                if stamp[j] != gen && self.open[j] && self.blocked[j] == 0 {
                    stamp[j] = gen;
                    q.push(j as u32);
                }
            };
            if x > 0 {
                visit(i - 1, &mut self.queue, &mut self.stamp);
            }
            if x + 1 < w {
                visit(i + 1, &mut self.queue, &mut self.stamp);
            }
            if y > 0 {
                visit(i - w, &mut self.queue, &mut self.stamp);
            }
            if y + 1 < h {
                visit(i + w, &mut self.queue, &mut self.stamp);
            }
        }
    }

    /// Every door reaches the first one.
    pub fn doors_connected(&self) -> bool {
        self.entrances
            .iter()
            .all(|cells| cells.iter().any(|&i| self.reached(i)))
    }

    /// The first reached cell among `cells`.
    pub fn first_reached(&self, cells: &[u32]) -> Option<u32> {
        cells.iter().copied().find(|&i| self.reached(i))
    }

    /// Whether the free cell `i` is open room (inside and clear of the walls).
    pub fn is_open(&self, i: u32) -> bool {
        self.open[i as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::super::geometry::frame;
    use super::*;

    fn square(side: f64) -> (Room, Vec<Wall>, Vec<Footprint>) {
        let room = Room::new("r", &[[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]).unwrap();
        // one 1 m door on the bottom wall from x 0.5 to 1.5; its zone is the square above it
        let walls = vec![
            Wall {
                a: [0.0, 0.0],
                b: [0.5, 0.0],
            },
            Wall {
                a: [1.5, 0.0],
                b: [side, 0.0],
            },
            Wall {
                a: [side, 0.0],
                b: [side, side],
            },
            Wall {
                a: [side, side],
                b: [0.0, side],
            },
            Wall {
                a: [0.0, side],
                b: [0.0, 0.0],
            },
        ];
        let zone = Footprint::new(frame([1.0, 0.5], 0.0), 1.0, 1.0);
        (room, walls, vec![zone])
    }

    #[test]
    fn a_wall_across_the_room_cuts_the_far_side_off() {
        let (room, walls, zones) = square(4.0);
        let mut g = ReachGrid::new("r", &room, &walls, &zones, 0.25, 0.5, 0.05).unwrap();
        g.flood();
        let far = Footprint::new(frame([2.0, 3.8], 0.0), 0.5, 0.4);
        let cells = g.interaction_cells(&far, true);
        // the object faces +y, into the wall: nothing in front of it
        assert!(cells.is_empty());
        let cells = g.interaction_cells(&far, false);
        assert!(g.first_reached(&cells).is_some());
        // a 4 m wide barrier at y = 2 leaves the top half unreachable
        let barrier = Footprint::new(frame([2.0, 2.0], 0.0), 4.0, 0.2);
        let undo = g.block(&barrier);
        assert!(g.touches_reached(&undo));
        g.flood();
        assert!(g.doors_connected());
        assert!(g.first_reached(&cells).is_none());
        g.unblock(&undo);
        g.flood();
        assert!(g.first_reached(&cells).is_some());
    }

    #[test]
    fn a_gap_narrower_than_the_agent_blocks_it() {
        let (room, walls, zones) = square(4.0);
        let mut g = ReachGrid::new("r", &room, &walls, &zones, 0.25, 0.5, 0.05).unwrap();
        let target = Footprint::new(frame([2.0, 3.5], 0.0), 0.4, 0.4);
        let cells = g.interaction_cells(&target, false);
        // two half-barriers leaving a 0.45 m gap in the middle (the agent needs 0.5 m)
        let left = Footprint::new(frame([0.9, 2.0], 0.0), 1.8, 0.2);
        let right = Footprint::new(frame([3.125, 2.0], 0.0), 1.75, 0.2);
        g.block(&left);
        let undo = g.block(&right);
        g.flood();
        assert!(g.first_reached(&cells).is_none());
        // widen the gap to 0.7 m
        g.unblock(&undo);
        g.block(&Footprint::new(frame([3.25, 2.0], 0.0), 1.5, 0.2));
        g.flood();
        assert!(g.first_reached(&cells).is_some());
    }

    #[test]
    fn a_door_narrower_than_the_agent_is_an_error() {
        let (room, walls, _) = square(4.0);
        // a zone hugging the solid part of the bottom wall has no cell the agent fits in
        let zone = Footprint::new(frame([3.0, 0.1], 0.0), 0.4, 0.2);
        assert!(ReachGrid::new("r", &room, &walls, &[zone], 0.25, 0.5, 0.05).is_err());
        assert!(ReachGrid::new("r", &room, &walls, &[], 0.25, 0.5, 0.05).is_err());
    }
}
