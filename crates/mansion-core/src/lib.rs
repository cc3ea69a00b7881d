//! mansion-core: the pure-Rust geometry engine of mansion.
//!
//! The single-floor solver of the MANSION paper: rasterise a footprint, cut it round by round with
//! seeded constrained growth, clean spurs and holes, filter candidates by topology, score them with
//! the energy, and vectorise the winner. No Python here; `mansion-py` binds it.

pub mod error;
pub mod grid;

pub use error::{CoreError, Result};
pub use grid::{Grid, GridFrame, Label, Walls, EMPTY, OUTSIDE};
pub mod cleanup;
pub mod cut;
pub mod energy;
pub mod growth;
pub mod masks;
pub mod place;
pub mod raster;
pub mod region;
pub mod repair;
pub mod seedplan;
pub mod slab;
pub mod solve;
pub mod topology;
pub mod vectorise;
