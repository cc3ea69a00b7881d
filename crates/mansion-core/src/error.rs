//! The one error type of the core. Every message names the room, edge, core or coordinate at fault,
//! because these strings reach users unchanged through the Python exceptions.

use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum CoreError {
    /// The footprint outline, holes, cores or fixed walls are not usable geometry.
    #[error("invalid footprint: {0}")]
    InvalidFootprint(String),
    /// The room graph or the options are malformed (unknown ids, missing hub, bad areas...).
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// The inputs are well formed but no retry and no fallback produced a valid layout.
    #[error("infeasible layout: {0}")]
    Infeasible(String),
    /// A seed planner (for example a Python callback) failed or returned something unusable.
    #[error("seed planner failed: {0}")]
    Planner(String),
}

pub type Result<T> = std::result::Result<T, CoreError>;
