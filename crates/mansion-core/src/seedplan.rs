//! Seed planners: what proposes, for each child of a cut round, a seed (point or box) and optionally
//! an area fraction. The LLM planner of the paper lives in Python and reaches the core through the
//! same trait; [`HeuristicPlanner`] is the offline default.

use crate::error::{CoreError, Result};
use crate::grid::{Grid, GridFrame, Label, OUTSIDE};
use crate::region::Region;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, HashMap};

/// One child of a round as a planner sees it.
#[derive(Debug, Clone)]
pub struct ChildInfo {
    pub label: Label,
    pub id: String,
    pub room_type: String,
    /// Area the child will cover in this round (its own plus its descendants'), in m².
    pub target_area: f64,
    /// The child's own area, in m².
    pub own_area: f64,
    /// Graph neighbours (ids).
    pub neighbours: Vec<String>,
    /// Rooms that later rounds cut out of this child, with their own areas in m².
    pub descendants: Vec<(String, f64)>,
    /// Labels outside the region this child (or a room later cut out of it) must touch.
    pub attract: Vec<Label>,
    /// Whether the graph joins this child to its parent.
    pub touches_parent: bool,
}

/// Everything a planner may look at for one round.
pub struct SeedRequest<'a> {
    pub round: usize,
    pub parent: Label,
    pub parent_id: String,
    pub children: Vec<ChildInfo>,
    pub parent_neighbours: Vec<String>,
    /// Labels outside the region that the parent must keep touching.
    pub parent_attract: Vec<Label>,
    /// The current layout (padded solver grid: solver cell (x, y) is frame cell (x − 1, y − 1)).
    pub grid: &'a Grid,
    /// Frame of the unpadded grid.
    pub frame: &'a GridFrame,
    pub region: &'a Region,
    /// Cells the solver keeps for the parent (its spine), which children cannot take.
    pub reserved: &'a [usize],
    /// Names of every label.
    pub names: &'a [String],
    /// Whether the parent should get a seed of its own and grow with its children.
    pub want_parent_seed: bool,
}

impl SeedRequest<'_> {
    /// Padded grid coordinates of a plan point.
    pub fn to_solver(&self, p: [f64; 2]) -> [f64; 2] {
        let g = self.frame.to_grid(p);
        [g[0] + 1.0, g[1] + 1.0]
    }

    /// Plan point (metres) of padded grid coordinates.
    pub fn to_plan(&self, g: [f64; 2]) -> [f64; 2] {
        self.frame.to_plan([g[0] - 1.0, g[1] - 1.0])
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SeedBox {
    pub x: [f64; 2],
    pub y: [f64; 2],
}

/// A child's seed, in metres: a point, or a box whose centre is used.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ChildSeed {
    #[serde(default)]
    pub point: Option<[f64; 2]>,
    #[serde(default, rename = "box")]
    pub bbox: Option<SeedBox>,
    #[serde(default)]
    pub fraction: Option<f64>,
}

impl ChildSeed {
    pub fn point(p: [f64; 2]) -> Self {
        ChildSeed {
            point: Some(p),
            bbox: None,
            fraction: None,
        }
    }

    /// The seed point this plan stands for.
    pub fn centre(&self) -> Option<[f64; 2]> {
        match (self.point, self.bbox) {
            (Some(p), _) => Some(p),
            (None, Some(b)) => Some([(b.x[0] + b.x[1]) / 2.0, (b.y[0] + b.y[1]) / 2.0]),
            _ => None,
        }
    }
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct SeedPlan {
    pub seeds: BTreeMap<String, ChildSeed>,
    #[serde(default)]
    pub parent_seed: Option<[f64; 2]>,
    /// Optional points for rooms that later rounds cut out of a child (by id). A child whose
    /// descendants have points grows this round from several seeds at once, its own and theirs,
    /// each with its own area, so the region takes the shape of the rooms it will hold instead of
    /// one blob around a single seed.
    #[serde(default)]
    pub descendant_seeds: BTreeMap<String, [f64; 2]>,
}

pub trait SeedPlanner {
    fn plan(&mut self, req: &SeedRequest) -> Result<SeedPlan>;
}

/// Check a plan against its request: a finite seed for every child and nothing else, fractions
/// in (0, 1] summing to at most 1.
pub fn validate_plan(plan: &SeedPlan, req: &SeedRequest) -> Result<()> {
    let bad = |m: String| Err(CoreError::Planner(m));
    for id in plan.seeds.keys() {
        if !req.children.iter().any(|c| &c.id == id) {
            return bad(format!(
                "seed plan names '{id}', which is not a child of '{}'",
                req.parent_id
            ));
        }
    }
    let mut total = 0.0;
    for c in &req.children {
        let Some(s) = plan.seeds.get(&c.id) else {
            return bad(format!("seed plan has no seed for '{}'", c.id));
        };
        match s.centre() {
            Some(p) if p[0].is_finite() && p[1].is_finite() => {}
            _ => {
                return bad(format!(
                    "seed of '{}' has neither a finite point nor a box",
                    c.id
                ))
            }
        }
        if let Some(f) = s.fraction {
            if !(f > 0.0 && f <= 1.0) {
                return bad(format!("area fraction {f} of '{}' is not in (0, 1]", c.id));
            }
            total += f;
        }
    }
    if total > 1.0 + 1e-6 {
        return bad(format!(
            "area fractions of the children of '{}' sum to {total:.3} > 1",
            req.parent_id
        ));
    }
    for (id, p) in &plan.descendant_seeds {
        if !req
            .children
            .iter()
            .any(|c| c.descendants.iter().any(|(d, _)| d == id))
        {
            return bad(format!(
                "seed plan has a descendant seed for '{id}', which no child of '{}' will hold",
                req.parent_id
            ));
        }
        if !(p[0].is_finite() && p[1].is_finite()) {
            return bad(format!("descendant seed of '{id}' is not finite"));
        }
    }
    if let Some(p) = plan.parent_seed {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return bad("parent seed is not finite".into());
        }
    }
    Ok(())
}

/// The offline seed planner: places children greedily, largest first, on the region cell that best
/// (a) lies about half a room-width from the neighbours the child must touch, (b) keeps large rooms
/// along the exterior envelope, (c) keeps clear of seeds already placed, and (d) leaves the parent
/// the contacts it must keep.
#[derive(Debug, Default, Clone)]
pub struct HeuristicPlanner;

impl SeedPlanner for HeuristicPlanner {
    fn plan(&mut self, req: &SeedRequest) -> Result<SeedPlan> {
        let region = req.region;
        let grid = req.grid;
        let w = grid.w;
        let cells: Vec<usize> = region.cells.iter().map(|&c| c as usize).collect();
        if cells.is_empty() {
            return Err(CoreError::Planner(format!(
                "'{}' has no cells to cut",
                req.parent_id
            )));
        }
        let cell_area = req.frame.cell * req.frame.cell;
        let n_cells = cells.len() as f64;
        let total_target: f64 = req
            .children
            .iter()
            .map(|c| c.target_area)
            .sum::<f64>()
            .max(1e-9);

        // distance (in cells, within the region) to the exterior envelope, or to any envelope when
        // the region does not touch the outside
        let exterior: Vec<usize> = cells
            .iter()
            .copied()
            .filter(|&c| {
                [c - 1, c + 1, c - w, c + w]
                    .iter()
                    .any(|&n| grid.cells[n] == OUTSIDE)
            })
            .collect();
        let envelope_sources = if exterior.is_empty() {
            cells
                .iter()
                .copied()
                .filter(|&c| region.on_envelope(c))
                .collect()
        } else {
            exterior
        };
        let d_env = region.distances(&envelope_sources);
        // children that open onto the parent should hug its spine without sitting on it
        let d_spine = (!req.reserved.is_empty()).then(|| region.distances(req.reserved));
        let mut fields: HashMap<Label, Vec<u32>> = HashMap::new();
        let mut field = |l: Label| -> Vec<u32> {
            fields
                .entry(l)
                .or_insert_with(|| {
                    let src: Vec<usize> = cells
                        .iter()
                        .copied()
                        .filter(|&c| {
                            [c - 1, c + 1, c - w, c + w]
                                .iter()
                                .any(|&n| grid.cells[n] == l)
                        })
                        .collect();
                    region.distances(&src)
                })
                .clone()
        };

        let mut order: Vec<usize> = (0..req.children.len()).collect();
        order.sort_by(|&a, &b| {
            req.children[b]
                .target_area
                .total_cmp(&req.children[a].target_area)
                .then(a.cmp(&b))
        });
        let max_target = req
            .children
            .iter()
            .map(|c| c.target_area)
            .fold(0.0, f64::max)
            .max(1e-9);
        let mut placed: Vec<(usize, f64)> = Vec::new(); // (cell, side in cells)
        let mut plan = SeedPlan::default();
        for &k in &order {
            let child = &req.children[k];
            // the child's size in cells (its share of the region, if the areas overflow it)
            let t = (child.target_area / cell_area)
                .min(child.target_area / total_target * n_cells)
                .clamp(1.0, n_cells);
            let side = t.sqrt();
            let inset = side / 2.0;
            let attract: Vec<Vec<u32>> = child.attract.iter().map(|&l| field(l)).collect();
            let avoid: Vec<Vec<u32>> = req
                .parent_attract
                .iter()
                .filter(|l| !child.attract.contains(l))
                .map(|&l| field(l))
                .collect();
            let big = child.target_area / max_target;
            let mut best = (f64::INFINITY, cells[0]);
            for (pos, &c) in cells.iter().enumerate() {
                let mut cost = 0.0;
                for f in &attract {
                    let d = f[pos] as f64;
                    cost += 2.0 * (d - inset).max(0.0) / side;
                }
                let de = d_env[pos] as f64;
                cost += big * (de - inset).abs() / side;
                // keep half a room from the region's envelope at least, so the room has space
                if de + 0.5 < inset.min(2.0) {
                    cost += 1.0;
                }
                if let Some(ds) = &d_spine {
                    if child.touches_parent {
                        let d = ds[pos] as f64;
                        cost += (d - inset).max(0.0) / side + 2.0 * (inset - d).max(0.0) / side;
                    }
                }
                for f in &avoid {
                    let d = f[pos] as f64;
                    if d < inset {
                        cost += (inset - d) / side;
                    }
                }
                let (cx, cy) = ((c % w) as f64, (c / w) as f64);
                for &(q, qs) in &placed {
                    let (qx, qy) = ((q % w) as f64, (q / w) as f64);
                    let d = ((cx - qx).powi(2) + (cy - qy).powi(2)).sqrt();
                    let ideal = 0.5 * (side + qs);
                    if d < ideal {
                        cost += 3.0 * (ideal - d) / ideal;
                    }
                }
                if cost < best.0 {
                    best = (cost, c);
                }
            }
            placed.push((best.1, side));
            let g = [(best.1 % w) as f64 + 0.5, (best.1 / w) as f64 + 0.5];
            plan.seeds
                .insert(child.id.clone(), ChildSeed::point(req.to_plan(g)));
        }
        if req.want_parent_seed {
            // the parent grows from the region cell farthest from every child seed (the first such
            // cell on ties); each cell's distance is computed once
            let gap = |c: usize| {
                placed
                    .iter()
                    .map(|&(q, _)| {
                        (((c % w) as f64 - (q % w) as f64).powi(2)
                            + ((c / w) as f64 - (q / w) as f64).powi(2))
                        .sqrt()
                    })
                    .fold(f64::INFINITY, f64::min)
            };
            let mut far = (f64::NEG_INFINITY, cells[0]);
            for &c in &cells {
                let d = gap(c);
                if d.total_cmp(&far.0).is_gt() {
                    far = (d, c);
                }
            }
            let far = far.1;
            plan.parent_seed = Some(req.to_plan([(far % w) as f64 + 0.5, (far / w) as f64 + 0.5]));
        }
        Ok(plan)
    }
}

/// The request as JSON for planners outside Rust (the Python seed planners): the region and the
/// current layout as polygons in metres, the children with their areas and graph neighbours.
pub fn request_json(req: &SeedRequest) -> String {
    use crate::region::unpad;
    use crate::vectorise::{ring_to_plan, vectorise};
    let frame = req.frame;
    let layout = unpad(req.grid);
    let mut mask = layout.clone();
    for c in mask.cells.iter_mut() {
        *c = if *c == req.parent { 0 } else { OUTSIDE };
    }
    let poly = |p: &crate::vectorise::LabelPolygon| {
        serde_json::json!({
            "polygon": ring_to_plan(&p.outer, frame),
            "holes": p.holes.iter().map(|h| ring_to_plan(h, frame)).collect::<Vec<_>>(),
        })
    };
    let region_polys = vectorise(&mask);
    let mut region = region_polys
        .iter()
        .max_by_key(|p| p.outer.len())
        .map(poly)
        .unwrap_or_else(|| serde_json::json!({"polygon": [], "holes": []}));
    let cell_area = frame.cell * frame.cell;
    region["area"] = serde_json::json!(req.region.len() as f64 * cell_area);
    region["cells"] = serde_json::json!(req.region.len());
    let rooms: Vec<serde_json::Value> = vectorise(&layout)
        .iter()
        .filter(|p| (p.label as usize) < req.names.len())
        .map(|p| {
            let mut v = poly(p);
            v["id"] = serde_json::json!(req.names[p.label as usize]);
            v
        })
        .collect();
    let children: Vec<serde_json::Value> = req
        .children
        .iter()
        .map(|c| {
            serde_json::json!({
                "id": c.id, "room_type": c.room_type, "target_area": c.target_area,
                "own_area": c.own_area, "neighbours": c.neighbours,
                "descendants": c.descendants.iter()
                    .map(|(id, area)| serde_json::json!({"id": id, "area": area}))
                    .collect::<Vec<_>>(),
            })
        })
        .collect();
    serde_json::json!({
        "round": req.round,
        "parent": req.parent_id,
        "cell_size": frame.cell,
        "region": region,
        "layout": {"rooms": rooms},
        "children": children,
        "parent_neighbours": req.parent_neighbours,
        "want_parent_seed": req.want_parent_seed,
    })
    .to_string()
}
