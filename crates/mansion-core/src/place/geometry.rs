//! Oriented footprints and the room they must fit in.
//!
//! Frames are nalgebra isometries (an object's local x is its right, local y its front). Exact
//! point distances are computed analytically in f64, because the free-space grid and the tests
//! that re-check it must agree to the last cell; box–box and box–wall tests go through parry
//! (f32), with the tolerances of the callers well above its precision.

use crate::error::{CoreError, Result};
use nalgebra::{Isometry2, Point2, Vector2};
use parry2d::math::{Pose, Vector};
use parry2d::query;
use parry2d::shape::{Cuboid, Segment};

pub type Iso = Isometry2<f64>;

/// The frame of an object at `center` with AI2-THOR yaw `yaw_deg` (0 faces +y, 90 faces +x).
pub fn frame(center: [f64; 2], yaw_deg: f64) -> Iso {
    Isometry2::new(Vector2::new(center[0], center[1]), -yaw_deg.to_radians())
}

/// The AI2-THOR yaw of a frame, in [0, 360).
pub fn yaw_of(iso: &Iso) -> f64 {
    let y = (-iso.rotation.angle()).to_degrees().rem_euclid(360.0);
    // snap float noise so that axis-aligned objects report exactly 0/90/180/270
    let r = y.round();
    let y = if (y - r).abs() < 1e-7 { r } else { y };
    if y >= 360.0 {
        0.0
    } else {
        y
    }
}

/// The yaw whose front points along `dir`.
pub fn yaw_facing(dir: Vector2<f64>) -> f64 {
    dir.x.atan2(dir.y).to_degrees().rem_euclid(360.0)
}

/// An oriented rectangle: `iso` places its centre and axes, `half` its half width and depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footprint {
    pub iso: Iso,
    pub half: [f64; 2],
}

impl Footprint {
    pub fn new(iso: Iso, width: f64, depth: f64) -> Self {
        Self {
            iso,
            half: [width / 2.0, depth / 2.0],
        }
    }

    pub fn center(&self) -> [f64; 2] {
        let t = self.iso.translation.vector;
        [t.x, t.y]
    }

    pub fn corners(&self) -> [Point2<f64>; 4] {
        let [hx, hy] = self.half;
        [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)].map(|(x, y)| self.iso * Point2::new(x, y))
    }

    /// Axis-aligned bounds: [min x, min y, max x, max y].
    pub fn aabb(&self) -> [f64; 4] {
        let c = self.corners();
        let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        for p in c {
            b[0] = b[0].min(p.x);
            b[1] = b[1].min(p.y);
            b[2] = b[2].max(p.x);
            b[3] = b[3].max(p.y);
        }
        b
    }

    /// `p` in the object's frame (x right, y front).
    pub fn local(&self, p: [f64; 2]) -> [f64; 2] {
        let l = self.iso.inverse_transform_point(&Point2::new(p[0], p[1]));
        [l.x, l.y]
    }

    /// Euclidean distance from `p` to the rectangle (0 inside).
    pub fn distance_to_point(&self, p: [f64; 2]) -> f64 {
        let [x, y] = self.local(p);
        let dx = (x.abs() - self.half[0]).max(0.0);
        let dy = (y.abs() - self.half[1]).max(0.0);
        dx.hypot(dy)
    }

    /// Whether `p` is on the front side: beyond the plane of the front face.
    pub fn in_front(&self, p: [f64; 2], eps: f64) -> bool {
        self.local(p)[1] >= self.half[1] + eps
    }

    fn parry(&self, shrink: f64) -> (Pose, Cuboid) {
        let t = self.iso.translation.vector;
        let pose = Pose::new(
            Vector::new(t.x as f32, t.y as f32),
            self.iso.rotation.angle() as f32,
        );
        let h = Vector::new(
            (self.half[0] - shrink).max(1e-4) as f32,
            (self.half[1] - shrink).max(1e-4) as f32,
        );
        (pose, Cuboid::new(h))
    }

    /// Whether the two rectangles come closer than `gap` (overlap when `gap` ≤ 0).
    pub fn conflicts(&self, other: &Footprint, gap: f64) -> bool {
        let (a, b) = (self.aabb(), other.aabb());
        if a[0] > b[2] + gap || b[0] > a[2] + gap || a[1] > b[3] + gap || b[1] > a[3] + gap {
            return false;
        }
        let (pa, ca) = self.parry(0.0);
        let (pb, cb) = other.parry(0.0);
        if gap <= 0.0 {
            return query::intersection_test(&pa, &ca, &pb, &cb).map_or(true, |i| i.intersecting);
        }
        query::distance(&pa, &ca, &pb, &cb).map_or(true, |d| (d.distance as f64) < gap)
    }

    /// Distance between the two rectangles (0 when they overlap).
    pub fn distance(&self, other: &Footprint) -> f64 {
        let (pa, ca) = self.parry(0.0);
        let (pb, cb) = other.parry(0.0);
        query::distance(&pa, &ca, &pb, &cb).map_or(0.0, |d| d.distance as f64)
    }

    pub fn area(&self) -> f64 {
        4.0 * self.half[0] * self.half[1]
    }
}

/// A wall segment of the room's boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wall {
    pub a: [f64; 2],
    pub b: [f64; 2],
}

impl Wall {
    pub fn len(&self) -> f64 {
        (self.b[0] - self.a[0]).hypot(self.b[1] - self.a[1])
    }

    pub fn is_empty(&self) -> bool {
        self.len() <= 0.0
    }

    pub fn dir(&self) -> Vector2<f64> {
        Vector2::new(self.b[0] - self.a[0], self.b[1] - self.a[1]) / self.len()
    }

    pub fn distance_to_point(&self, p: [f64; 2]) -> f64 {
        let (ax, ay) = (self.a[0], self.a[1]);
        let (dx, dy) = (self.b[0] - ax, self.b[1] - ay);
        let l2 = dx * dx + dy * dy;
        let t = if l2 > 0.0 {
            (((p[0] - ax) * dx + (p[1] - ay) * dy) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p[0] - ax - t * dx).hypot(p[1] - ay - t * dy)
    }

    fn parry(&self) -> Segment {
        Segment::new(
            Vector::new(self.a[0] as f32, self.a[1] as f32),
            Vector::new(self.b[0] as f32, self.b[1] as f32),
        )
    }
}

/// The room: its outline as walls, with each wall's inward normal.
#[derive(Debug, Clone)]
pub struct Room {
    pub outline: Vec<[f64; 2]>,
    pub walls: Vec<Wall>,
    /// Unit normals pointing into the room, one per wall.
    pub inward: Vec<Vector2<f64>>,
    pub bounds: [f64; 4],
    pub area: f64,
    pub centroid: [f64; 2],
}

impl Room {
    pub fn new(id: &str, polygon: &[[f64; 2]]) -> Result<Self> {
        let mut outline: Vec<[f64; 2]> = Vec::with_capacity(polygon.len());
        for &p in polygon {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(CoreError::InvalidInput(format!(
                    "room {id}: vertex {p:?} is not a finite coordinate"
                )));
            }
            if outline
                .last()
                .is_none_or(|q| (q[0] - p[0]).hypot(q[1] - p[1]) > 1e-9)
            {
                outline.push(p);
            }
        }
        if outline.len() > 1 {
            let (f, l) = (outline[0], outline[outline.len() - 1]);
            if (f[0] - l[0]).hypot(f[1] - l[1]) <= 1e-9 {
                outline.pop();
            }
        }
        if outline.len() < 3 {
            return Err(CoreError::InvalidInput(format!(
                "room {id}: the polygon needs at least 3 distinct vertices"
            )));
        }
        let n = outline.len();
        let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
        for i in 0..n {
            let (p, q) = (outline[i], outline[(i + 1) % n]);
            let c = p[0] * q[1] - q[0] * p[1];
            a2 += c;
            cx += (p[0] + q[0]) * c;
            cy += (p[1] + q[1]) * c;
        }
        if a2.abs() < 1e-9 {
            return Err(CoreError::InvalidInput(format!(
                "room {id}: the polygon has no area"
            )));
        }
        let ccw = a2 > 0.0;
        let walls: Vec<Wall> = (0..n)
            .map(|i| Wall {
                a: outline[i],
                b: outline[(i + 1) % n],
            })
            .collect();
        let inward = walls
            .iter()
            .map(|w| {
                let d = w.dir();
                if ccw {
                    Vector2::new(-d.y, d.x)
                } else {
                    Vector2::new(d.y, -d.x)
                }
            })
            .collect();
        let mut bounds = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        for p in &outline {
            bounds[0] = bounds[0].min(p[0]);
            bounds[1] = bounds[1].min(p[1]);
            bounds[2] = bounds[2].max(p[0]);
            bounds[3] = bounds[3].max(p[1]);
        }
        Ok(Self {
            centroid: [cx / (3.0 * a2), cy / (3.0 * a2)],
            area: a2.abs() / 2.0,
            outline,
            walls,
            inward,
            bounds,
        })
    }

    /// Even–odd point in polygon.
    pub fn contains(&self, p: [f64; 2]) -> bool {
        let mut inside = false;
        let n = self.outline.len();
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.outline[i], self.outline[j]);
            if (a[1] > p[1]) != (b[1] > p[1])
                && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
            {
                inside = !inside;
            }
            j = i;
        }
        inside
    }

    /// Whether the footprint lies inside the room: its centre is inside and no wall touches it
    /// (shrunk by `tolerance`, so an object flush against a wall still fits).
    pub fn holds(&self, fp: &Footprint, tolerance: f64) -> bool {
        let b = fp.aabb();
        if b[0] < self.bounds[0] - tolerance
            || b[1] < self.bounds[1] - tolerance
            || b[2] > self.bounds[2] + tolerance
            || b[3] > self.bounds[3] + tolerance
        {
            return false;
        }
        if !self.contains(fp.center()) {
            return false;
        }
        let (pose, cuboid) = fp.parry(tolerance);
        let id = Pose::IDENTITY;
        self.walls.iter().all(|w| {
            let wb = [
                w.a[0].min(w.b[0]),
                w.a[1].min(w.b[1]),
                w.a[0].max(w.b[0]),
                w.a[1].max(w.b[1]),
            ];
            if wb[0] > b[2] || b[0] > wb[2] || wb[1] > b[3] || b[1] > wb[3] {
                return true;
            }
            !query::intersection_test(&pose, &cuboid, &id, &w.parry())
                .map_or(true, |i| i.intersecting)
        })
    }

    /// Smallest distance from the footprint to any wall.
    pub fn wall_distance(&self, fp: &Footprint) -> f64 {
        let (pose, cuboid) = fp.parry(0.0);
        let id = Pose::IDENTITY;
        self.walls
            .iter()
            .map(|w| {
                query::distance(&pose, &cuboid, &id, &w.parry()).map_or(0.0, |d| d.distance as f64)
            })
            .fold(f64::MAX, f64::min)
    }

    /// Distinct yaws that face away from a wall: the natural orientations of the room.
    pub fn axis_yaws(&self) -> Vec<f64> {
        let mut out: Vec<f64> = Vec::new();
        for n in &self.inward {
            let y = (yaw_facing(*n) * 1e6).round() / 1e6 % 360.0;
            if !out.iter().any(|o| (o - y).abs() < 1e-3) {
                out.push(y);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yaw_zero_faces_plus_y_and_ninety_plus_x() {
        let f = frame([1.0, 2.0], 0.0);
        let p = f * Point2::new(0.0, 1.0);
        assert!((p.x - 1.0).abs() < 1e-12 && (p.y - 3.0).abs() < 1e-12);
        let f = frame([0.0, 0.0], 90.0);
        let p = f * Point2::new(0.0, 1.0);
        assert!((p.x - 1.0).abs() < 1e-12 && p.y.abs() < 1e-12);
        assert_eq!(yaw_of(&f), 90.0);
        assert_eq!(yaw_facing(Vector2::new(-1.0, 0.0)), 270.0);
    }

    #[test]
    fn footprint_distance_and_front() {
        let fp = Footprint::new(frame([0.0, 0.0], 90.0), 2.0, 1.0);
        // rotated: width along y, depth along x, front towards +x
        assert!((fp.distance_to_point([1.5, 0.0]) - 1.0).abs() < 1e-12);
        assert_eq!(fp.distance_to_point([0.2, 0.9]), 0.0);
        assert!(fp.in_front([0.8, 0.0], 0.0));
        assert!(!fp.in_front([-0.8, 0.0], 0.0));
    }

    #[test]
    fn conflicts_respect_gap() {
        let a = Footprint::new(frame([0.0, 0.0], 0.0), 1.0, 1.0);
        let b = Footprint::new(frame([1.05, 0.0], 0.0), 1.0, 1.0);
        assert!(!a.conflicts(&b, 0.0));
        assert!(a.conflicts(&b, 0.1));
        assert!(!a.conflicts(&b, 0.02));
        let c = Footprint::new(frame([0.9, 0.0], 45.0), 1.0, 1.0);
        assert!(a.conflicts(&c, 0.0));
    }

    #[test]
    fn room_holds_only_inner_footprints() {
        // an L: the notch at top right is outside
        let room = Room::new(
            "l",
            &[
                [0.0, 0.0],
                [4.0, 0.0],
                [4.0, 2.0],
                [2.0, 2.0],
                [2.0, 4.0],
                [0.0, 4.0],
            ],
        )
        .unwrap();
        assert!((room.area - 12.0).abs() < 1e-9);
        assert!(room.holds(&Footprint::new(frame([1.0, 1.0], 0.0), 1.0, 1.0), 1e-3));
        // flush against the left wall
        assert!(room.holds(&Footprint::new(frame([0.5, 3.0], 0.0), 1.0, 1.0), 1e-3));
        // straddles the reflex corner
        assert!(!room.holds(&Footprint::new(frame([2.2, 2.2], 0.0), 1.0, 1.0), 1e-3));
        assert!(!room.holds(&Footprint::new(frame([3.0, 3.0], 0.0), 0.5, 0.5), 1e-3));
        assert_eq!(room.axis_yaws().len(), 4);
    }

    #[test]
    fn degenerate_rooms_are_rejected() {
        assert!(Room::new("r", &[[0.0, 0.0], [1.0, 0.0]]).is_err());
        assert!(Room::new("r", &[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).is_err());
    }
}
