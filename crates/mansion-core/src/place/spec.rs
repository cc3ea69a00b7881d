//! The placement request and result, exchanged as JSON with Python.
//!
//! Coordinates are floor-plan metres (x right, y up). An object's yaw is AI2-THOR's rotation about
//! the vertical axis in degrees: yaw 0 faces +y of the plan (+z of the scene), yaw 90 faces +x.
//! Sizes are the asset's bounding box: width along the object's own x, depth along its front
//! axis, height.

use serde::{Deserialize, Serialize};

/// Where in the room the anchor of a group goes (the paper's global tag).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Tag {
    /// Back against a wall, facing into the room.
    Edge,
    /// Clear of every wall by `PlaceOptions::middle_margin`.
    Middle,
    /// Anywhere the hard constraints allow.
    #[default]
    Unconstrained,
}

/// Where a paired member sits in its partner's local frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// In front of the partner, facing it (a chair at a desk).
    Front,
    /// Behind the partner, facing it.
    Back,
    /// Beside the partner on its left, flush with its back, facing the same way (a nightstand).
    Left,
    /// As `Left`, on the right.
    Right,
    /// One on each side (`Left` and `Right`).
    Sides,
    /// `count` members spread over the four sides, facing the partner (chairs round a table).
    Around,
}

/// The structure of a plan item (the paper's structural constraint).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Structure {
    Single,
    /// `rows` × `cols` copies of the item (with its paired members), placed as one macro object
    /// and shrunk until it fits. Rows run along the item's front axis, columns across it; the
    /// gaps are the free space between neighbouring units (aisles).
    Matrix {
        rows: u32,
        cols: u32,
        #[serde(default = "default_row_gap")]
        row_gap: f64,
        #[serde(default = "default_col_gap")]
        col_gap: f64,
    },
    /// A member of `partner`'s group, placed in its frame.
    Paired {
        partner: String,
        side: Side,
        #[serde(default = "one")]
        count: u32,
        /// Fraction of the member's depth pushed under the partner (a chair tucked under a desk);
        /// a tucked pair may overlap and is exempt from the collision test between the two.
        #[serde(default)]
        tuck: f64,
    },
}

fn default_row_gap() -> f64 {
    0.8
}
fn default_col_gap() -> f64 {
    0.6
}
fn one() -> u32 {
    1
}

/// A relative constraint between an item and another item of the plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RelationKind {
    /// Footprints at most `PlaceOptions::near_distance` apart.
    Near,
    /// Centres at least `PlaceOptions::far_distance` apart.
    Far,
    /// The item's front points at the target's centre (within 45°).
    Face,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Relation {
    pub kind: RelationKind,
    pub target: String,
}

/// A small object to pack on top of a receptacle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SmallSpec {
    pub object_type: String,
    pub asset_id: String,
    /// width, depth, height in metres.
    pub size: [f64; 3],
}

/// One line of an object plan with its asset chosen.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ItemSpec {
    pub id: String,
    pub object_type: String,
    pub asset_id: String,
    /// width, depth, height in metres.
    pub size: [f64; 3],
    #[serde(default)]
    pub tag: Tag,
    #[serde(default = "single")]
    pub structure: Structure,
    #[serde(default)]
    pub relations: Vec<Relation>,
    /// Whether the object is used from one side (a wardrobe, a shelf); its interaction cell must
    /// then be in front of it.
    #[serde(default)]
    pub has_front: bool,
    /// Candidate small objects for its top, in order of preference; each placed copy of the item
    /// gets the ones that fit.
    #[serde(default)]
    pub small: Vec<SmallSpec>,
}

fn single() -> Structure {
    Structure::Single
}

/// A door on the room's boundary: the opening from `a` to `b`. Its zone (the door's width along
/// the wall, `depth` into the room) stays free of objects, and its free cells are the entrance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DoorSpec {
    pub a: [f64; 2],
    pub b: [f64; 2],
    /// How far the zone reaches into the room. `None`: as deep as the door is wide, the square
    /// a leaf swinging into this room sweeps. A door whose leaf swings into the other room, or
    /// an opening with no leaf, needs only an apron to step through, so the caller passes less.
    #[serde(default)]
    pub depth: Option<f64>,
    /// Whether the door must stay connected to the room's other entrances. A door that the
    /// empty room already cuts off from the rest (a neck narrower than the agent) is passed as
    /// `false`: its zone stays free, but the room is furnished from the doors that do connect.
    #[serde(default = "yes")]
    pub entrance: bool,
}

fn yes() -> bool {
    true
}

impl DoorSpec {
    /// A door whose leaf swings into the room (zone: the square of its width).
    pub fn swinging(a: [f64; 2], b: [f64; 2]) -> Self {
        Self {
            a,
            b,
            depth: None,
            entrance: true,
        }
    }
}

/// A square of the floor that stays free of objects and must stay reachable from the doors: where
/// the agent spawns, or lands when it leaves a stair or lift core into this room.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ClearSpec {
    pub center: [f64; 2],
    /// Side of the square, in metres.
    pub size: f64,
    /// As `DoorSpec::entrance`: `false` keeps the square free without requiring it reached.
    #[serde(default = "yes")]
    pub entrance: bool,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PlaceOptions {
    /// Radius of the agent's disc; free space is the room shrunk by it. AI2-THOR's LoCoBot and
    /// the paper's robots fit in 0.25 m.
    pub agent_radius: f64,
    /// Side of a free-space grid cell.
    pub cell: f64,
    /// An object is reachable when a free cell connected to the doors is this close to it.
    pub reach_distance: f64,
    /// Minimum distance between the footprints of two objects that are not a tucked pair.
    pub object_gap: f64,
    /// Distance between a wall and the back of an object against it.
    pub wall_gap: f64,
    /// Minimum distance from a `middle` group to every wall.
    pub middle_margin: f64,
    pub near_distance: f64,
    pub far_distance: f64,
    /// Candidate poses sampled per search (structured edge candidates come on top).
    pub samples: usize,
    /// At most this many candidates per search get the (costlier) reachability test.
    pub reach_tests: usize,
    /// Margin kept free around the edge of a receptacle's top when packing small objects.
    pub top_margin: f64,
    pub seed: u64,
}

impl Default for PlaceOptions {
    fn default() -> Self {
        Self {
            agent_radius: 0.25,
            cell: 0.05,
            reach_distance: 0.5,
            object_gap: 0.02,
            wall_gap: 0.01,
            middle_margin: 0.6,
            near_distance: 1.0,
            far_distance: 2.0,
            samples: 900,
            reach_tests: 40,
            top_margin: 0.03,
            seed: 0,
        }
    }
}

/// Everything needed to furnish one room.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlacementRequest {
    pub room_id: String,
    /// The room outline, counter-clockwise or clockwise, without repeating the first vertex.
    pub polygon: Vec<[f64; 2]>,
    #[serde(default)]
    pub doors: Vec<DoorSpec>,
    /// Spots kept free and reachable besides the doors (they join the entrances).
    #[serde(default)]
    pub keep_clear: Vec<ClearSpec>,
    pub items: Vec<ItemSpec>,
    #[serde(default)]
    pub options: PlaceOptions,
}

/// A small object placed on a receptacle's top: `center` in plan coordinates, `elevation` the
/// height of its bottom above the floor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlacedChild {
    pub id: String,
    pub object_type: String,
    pub asset_id: String,
    pub size: [f64; 3],
    pub center: [f64; 2],
    pub elevation: f64,
    pub yaw: f64,
}

/// A floor object of the result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlacedObject {
    pub id: String,
    /// The plan item it instantiates.
    pub item: String,
    pub object_type: String,
    pub asset_id: String,
    pub size: [f64; 3],
    pub center: [f64; 2],
    pub yaw: f64,
    pub has_front: bool,
    /// The anchor object of its group (itself for an anchor).
    pub group: String,
    /// The object it is paired with and tucked under, if any (exempt from the collision count).
    pub tucked_under: Option<String>,
    /// Centre of a free cell, connected to the doors, from which the agent reaches the object.
    pub interaction: [f64; 2],
    pub children: Vec<PlacedChild>,
}

/// A plan item (or some of its copies) that could not be placed, and why.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Dropped {
    pub item: String,
    pub count: u32,
    pub reason: String,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MatrixOutcome {
    pub item: String,
    pub requested: [u32; 2],
    pub placed: [u32; 2],
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
pub struct PlacementStats {
    pub candidates: usize,
    pub reach_tests: usize,
    pub flood_fills: usize,
    pub seconds: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Placement {
    pub room_id: String,
    pub objects: Vec<PlacedObject>,
    pub dropped: Vec<Dropped>,
    pub matrices: Vec<MatrixOutcome>,
    pub stats: PlacementStats,
}

impl Structure {
    pub fn matrix(rows: u32, cols: u32, row_gap: f64, col_gap: f64) -> Self {
        Self::Matrix {
            rows,
            cols,
            row_gap,
            col_gap,
        }
    }

    pub fn paired(partner: &str, side: Side, count: u32, tuck: f64) -> Self {
        Self::Paired {
            partner: partner.into(),
            side,
            count,
            tuck,
        }
    }
}

impl ItemSpec {
    /// An item with no relations, no front and nothing on top; the asset id is `<type>_1`.
    pub fn new(
        id: &str,
        object_type: &str,
        size: [f64; 3],
        tag: Tag,
        structure: Structure,
    ) -> Self {
        Self {
            id: id.into(),
            object_type: object_type.into(),
            asset_id: format!("{object_type}_1"),
            size,
            tag,
            structure,
            relations: Vec::new(),
            has_front: false,
            small: Vec::new(),
        }
    }
}
