//! Object placement with guaranteed reachability (the paper's supplement, "Object Placement").
//!
//! `spec` is the JSON contract with Python; `groups` turns a plan into anchor-and-member groups
//! and the shapes placed at once; `geometry` holds the oriented footprints and the room;
//! `reach` the incremental free-space flood fill; `engine` the priority-aware search; `packing`
//! the small objects on receptacle tops.

pub mod engine;
pub mod geometry;
pub mod groups;
pub mod packing;
pub mod reach;
pub mod spec;

pub use engine::place_room;
pub use spec::{Placement, PlacementRequest};

use crate::error::Result;
use rayon::prelude::*;

/// Furnish many rooms in parallel; each result is independent of the thread count (every room
/// draws from its own seeded generator).
pub fn place_rooms(requests: &[PlacementRequest]) -> Vec<Result<Placement>> {
    requests.par_iter().map(place_room).collect()
}
