//! The PyO3 binding, imported as `mansion._core`: conversions, exceptions and GIL release only; all
//! logic lives in mansion-core. Inputs are copied into owned Rust data before the GIL is released,
//! and every call is wrapped so that a Rust panic surfaces as `mansion.MansionError`, never a crash.

use mansion_core::cut::grow_batch;
use mansion_core::grid::{Grid, Label, EMPTY, OUTSIDE};
use mansion_core::growth::GrowthRule;
use mansion_core::place::{
    place_room as core_place_room, place_rooms as core_place_rooms, PlacementRequest,
};
use mansion_core::raster::{rasterise as core_rasterise, FootprintSpec};
use mansion_core::region::{pad, unpad};
use mansion_core::seedplan::{request_json, HeuristicPlanner, SeedPlan, SeedPlanner, SeedRequest};
use mansion_core::solve::{label_adjacencies, solve_floor as core_solve, GraphSpec, SolveOptions};
use mansion_core::vectorise::{
    mask_outline as core_mask_outline, vectorise as core_vectorise, Ring,
};
use mansion_core::CoreError;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray2, PyArray3, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyType;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Raise one of the exception classes defined in `mansion.exceptions`.
fn raise(py: Python<'_>, class: &str, msg: String) -> PyErr {
    match py
        .import("mansion.exceptions")
        .and_then(|m| m.getattr(class))
        .and_then(|c| c.cast_into::<PyType>().map_err(PyErr::from))
    {
        Ok(cls) => PyErr::from_type(cls, msg),
        Err(_) => pyo3::exceptions::PyRuntimeError::new_err(msg),
    }
}

fn to_py(py: Python<'_>, e: CoreError) -> PyErr {
    let class = match e {
        CoreError::InvalidFootprint(_) | CoreError::InvalidInput(_) => "InvalidInputError",
        CoreError::Infeasible(_) => "InfeasibleLayoutError",
        CoreError::Planner(_) => "PlannerError",
    };
    raise(py, class, e.to_string())
}

/// Run core work without the GIL, turning panics into `MansionError`.
fn guarded<T: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, CoreError> + Send,
) -> PyResult<T> {
    let out = py.detach(|| catch_unwind(AssertUnwindSafe(f)));
    match out {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(to_py(py, e)),
        Err(panic) => {
            let what = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(raise(
                py,
                "MansionError",
                format!("internal error in the Rust core: {what}"),
            ))
        }
    }
}

fn parse<T: serde::de::DeserializeOwned>(py: Python<'_>, what: &str, json: &str) -> PyResult<T> {
    serde_json::from_str(json).map_err(|e| {
        raise(
            py,
            "InvalidInputError",
            format!("malformed {what} JSON: {e}"),
        )
    })
}

/// A Python seed planner: a callable taking the request JSON and returning the plan JSON.
struct PyPlanner {
    callback: Py<PyAny>,
}

impl SeedPlanner for PyPlanner {
    fn plan(&mut self, req: &SeedRequest) -> mansion_core::Result<SeedPlan> {
        let request = request_json(req);
        let reply: Result<String, String> = Python::attach(|py| {
            self.callback
                .call1(py, (request,))
                .and_then(|r| r.extract::<String>(py))
                .map_err(|e| e.value(py).to_string())
        });
        let reply = reply.map_err(CoreError::Planner)?;
        serde_json::from_str(&reply).map_err(|e| {
            CoreError::Planner(format!("seed plan is not valid JSON for the schema: {e}"))
        })
    }
}

/// Solve one floor; arguments and result are JSON (see `_core.pyi`).
#[pyfunction]
#[pyo3(signature = (graph_json, footprint_json, options_json, seed_planner=None))]
fn solve_floor(
    py: Python<'_>,
    graph_json: &str,
    footprint_json: &str,
    options_json: &str,
    seed_planner: Option<Py<PyAny>>,
) -> PyResult<String> {
    let graph: GraphSpec = parse(py, "room graph", graph_json)?;
    let fp: FootprintSpec = parse(py, "footprint", footprint_json)?;
    let opts: SolveOptions = parse(py, "options", options_json)?;
    guarded(py, move || {
        let sol = match seed_planner {
            Some(cb) => core_solve(&graph, &fp, &opts, &mut PyPlanner { callback: cb })?,
            None => core_solve(&graph, &fp, &opts, &mut HeuristicPlanner)?,
        };
        serde_json::to_string(&sol).map_err(|e| CoreError::InvalidInput(e.to_string()))
    })
}

/// A rasterised footprint and its origin.
type RasterOut<'py> = (Bound<'py, PyArray2<i32>>, (f64, f64));

/// Rasterise a footprint: int32 (rows, cols) with row 0 at the bottom; -1 outside, -2 free, k ≥ 0
/// inside the k-th core. Returns the grid and its origin.
#[pyfunction]
fn rasterise<'py>(
    py: Python<'py>,
    footprint_json: &str,
    cell_size: f64,
) -> PyResult<RasterOut<'py>> {
    let fp: FootprintSpec = parse(py, "footprint", footprint_json)?;
    let r = guarded(py, move || core_rasterise(&fp, cell_size))?;
    let (w, h) = (r.frame.w, r.frame.h);
    let mut out = Array2::<i32>::from_elem((h, w), -1);
    for y in 0..h {
        for x in 0..w {
            if r.free.get(x, y) == EMPTY {
                out[[y, x]] = -2;
            }
        }
    }
    for (k, cells) in r.cores.iter().enumerate() {
        for &c in cells {
            out[[c / w, c % w]] = k as i32;
        }
    }
    Ok((out.into_pyarray(py), (r.frame.origin[0], r.frame.origin[1])))
}

type PyRing = Vec<(i64, i64)>;

fn ring_py(r: &Ring) -> PyRing {
    r.iter().map(|v| (v[0], v[1])).collect()
}

fn grid_from(labels: &PyReadonlyArray2<i32>) -> PyResult<Grid> {
    let a = labels.as_array();
    let (h, w) = (a.shape()[0], a.shape()[1]);
    let mut g = Grid::new(w, h, OUTSIDE);
    for y in 0..h {
        for x in 0..w {
            let v = a[[y, x]];
            if v >= 0 {
                if v as usize >= mansion_core::grid::MAX_ROOMS {
                    return Err(pyo3::exceptions::PyValueError::new_err(format!(
                        "label {v} is too large"
                    )));
                }
                g.set(x, y, v as Label);
            }
        }
    }
    Ok(g)
}

/// Outline of a boolean mask (row 0 at the bottom) in grid vertex coordinates: (outer, holes).
#[pyfunction]
fn mask_outline(py: Python<'_>, mask: PyReadonlyArray2<'_, u8>) -> PyResult<(PyRing, Vec<PyRing>)> {
    let a = mask.as_array();
    let (h, w) = (a.shape()[0], a.shape()[1]);
    let flat: Vec<bool> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (y, x)))
        .map(|(y, x)| a[[y, x]] != 0)
        .collect();
    let (outer, holes) = guarded(py, move || core_mask_outline(&flat, w, h))?;
    Ok((ring_py(&outer), holes.iter().map(ring_py).collect()))
}

/// A boolean mask as mansion-core's masks take it: row-major cells, width, height.
fn mask_cells(mask: &PyReadonlyArray2<'_, bool>) -> (Vec<bool>, usize, usize) {
    let a = mask.as_array();
    let (h, w) = (a.shape()[0], a.shape()[1]);
    (a.iter().copied().collect(), w, h)
}

/// Cells of a boolean mask that some `m` × `m` block of its cells covers.
#[pyfunction]
fn covered_cells(py: Python<'_>, mask: PyReadonlyArray2<'_, bool>, m: usize) -> PyResult<usize> {
    let (cells, w, h) = mask_cells(&mask);
    guarded(py, move || {
        Ok(mansion_core::masks::covered_cells(&cells, w, h, m))
    })
}

/// (rows, columns) of the box of a boolean mask's cells, its cells, and for each of `sides` the
/// cells some block of that side covers.
#[pyfunction]
fn box_cover(
    py: Python<'_>,
    mask: PyReadonlyArray2<'_, bool>,
    sides: Vec<usize>,
) -> PyResult<(usize, usize, usize, Vec<usize>)> {
    let (cells, w, h) = mask_cells(&mask);
    guarded(py, move || {
        Ok(mansion_core::masks::box_cover(&cells, w, h, &sides))
    })
}

/// Number of 4-connected pieces of a boolean mask's cells.
#[pyfunction]
fn mask_pieces(py: Python<'_>, mask: PyReadonlyArray2<'_, bool>) -> PyResult<usize> {
    let (cells, w, h) = mask_cells(&mask);
    guarded(py, move || Ok(mansion_core::masks::pieces(&cells, w, h)))
}

/// (cells no 2 × 2 block of a boolean mask covers, pieces those blocks make joined by a side).
#[pyfunction]
fn mask_passable(py: Python<'_>, mask: PyReadonlyArray2<'_, bool>) -> PyResult<(usize, usize)> {
    let (cells, w, h) = mask_cells(&mask);
    guarded(py, move || Ok(mansion_core::masks::passable(&cells, w, h)))
}

/// An int32 label grid as mansion-core's masks take it: row-major cells, width, height.
fn label_cells(labels: &PyReadonlyArray2<'_, i32>) -> (Vec<i32>, usize, usize) {
    let a = labels.as_array();
    let (h, w) = (a.shape()[0], a.shape()[1]);
    (a.iter().copied().collect(), w, h)
}

/// (shared cell edges, longest straight run of them) of each pair of labels in `pairs` in an
/// int32 label grid (negative = no room), as `adjacencies` measures them; (0, 0) where none.
#[pyfunction]
fn pair_walls(
    py: Python<'_>,
    labels: PyReadonlyArray2<'_, i32>,
    pairs: Vec<(i32, i32)>,
) -> PyResult<Vec<(u32, u32)>> {
    let (cells, w, h) = label_cells(&labels);
    guarded(py, move || {
        Ok(mansion_core::masks::pair_walls(&cells, w, h, &pairs))
    })
}

/// Per label of an int32 label grid, in label order: (label, cells, sum of the cells' centres'
/// x, of their y), cell (r, c) centred at (ox + (c + 0.5) s, oy + (r + 0.5) s), summed row by row.
#[pyfunction]
fn cell_sums(
    py: Python<'_>,
    labels: PyReadonlyArray2<'_, i32>,
    ox: f64,
    oy: f64,
    s: f64,
) -> PyResult<Vec<(i32, usize, f64, f64)>> {
    let (cells, w, h) = label_cells(&labels);
    guarded(py, move || {
        Ok(mansion_core::masks::cell_sums(&cells, w, h, ox, oy, s))
    })
}

/// (h, w, row, column, cells of `own` held) of each rectangle of cells inside `region` (both
/// boolean masks of one shape) within its box `(r0, r1, c0, c1)` (rows r0..r1, columns c0..c1):
/// sides at least `side`, `lo` to `hi` cells, long side at most `stretch` times the short; an
/// int64 array (n, 5).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn mask_windows<'py>(
    py: Python<'py>,
    region: PyReadonlyArray2<'py, bool>,
    own: PyReadonlyArray2<'py, bool>,
    side: usize,
    lo: i64,
    hi: i64,
    stretch: f64,
    bounds: (usize, usize, usize, usize),
) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let (cells, w, h) = mask_cells(&region);
    let (mine, ow, oh) = mask_cells(&own);
    if (ow, oh) != (w, h)
        || bounds.1 > h
        || bounds.3 > w
        || bounds.0 > bounds.1
        || bounds.2 > bounds.3
    {
        return Err(pyo3::exceptions::PyValueError::new_err(
            "masks or box of different shapes",
        ));
    }
    let rows = guarded(py, move || {
        Ok(mansion_core::masks::windows(
            &cells, &mine, w, h, side, lo, hi, stretch, bounds,
        ))
    })?;
    let flat: Vec<i64> = rows.iter().flatten().copied().collect();
    Ok(Array2::from_shape_vec((rows.len(), 5), flat)
        .expect("five columns a row")
        .into_pyarray(py))
}

/// Exact polygons of a label grid (row 0 at the bottom; negative = no room):
/// a list of (label, outer ring, holes) in grid vertex coordinates.
#[pyfunction]
fn vectorise(
    py: Python<'_>,
    labels: PyReadonlyArray2<'_, i32>,
) -> PyResult<Vec<(i64, PyRing, Vec<PyRing>)>> {
    let g = grid_from(&labels)?;
    let polys = guarded(py, move || Ok(core_vectorise(&g)))?;
    Ok(polys
        .iter()
        .map(|p| {
            (
                p.label as i64,
                ring_py(&p.outer),
                p.holes.iter().map(ring_py).collect(),
            )
        })
        .collect())
}

/// The shared walls of a label grid (row 0 at the bottom; negative = no room), as the solver
/// measures a layout's: (label a, label b, shared cell edges, longest straight run of them), a < b.
#[pyfunction]
fn adjacencies(
    py: Python<'_>,
    labels: PyReadonlyArray2<'_, i32>,
) -> PyResult<Vec<(i64, i64, u32, u32)>> {
    let g = grid_from(&labels)?;
    let pairs = guarded(py, move || {
        Ok(label_adjacencies(&g, mansion_core::grid::MAX_ROOMS))
    })?;
    Ok(pairs
        .into_iter()
        .map(|(a, b, t, l)| (a as i64, b as i64, t, l))
        .collect())
}

/// The growth stage of `batch` candidates (grow, then spur removal and hole filling), for
/// benchmarks: `labels` int32 (rows, cols), row 0 bottom, -1 outside; the cells equal to `region`
/// are cut into `len(targets)` rooms labelled after the largest label present, seeded around
/// `seeds` ((m, 2) cell units, x then y) within `radius` cells, with the rectangular phase's
/// `growth` rule ("balanced" or "longest"). Returns int32 (batch, rows, cols).
#[pyfunction]
#[pyo3(signature = (labels, region, seeds, targets, batch, rng_seed, radius, growth = "balanced"))]
#[allow(clippy::too_many_arguments)]
fn grow_candidates<'py>(
    py: Python<'py>,
    labels: PyReadonlyArray2<'py, i32>,
    region: i32,
    seeds: PyReadonlyArray2<'py, f64>,
    targets: PyReadonlyArray1<'py, f64>,
    batch: usize,
    rng_seed: u64,
    radius: f64,
    growth: &str,
) -> PyResult<Bound<'py, PyArray3<i32>>> {
    let growth = match growth {
        "balanced" => GrowthRule::Balanced,
        "longest" => GrowthRule::Longest,
        other => {
            return Err(raise(
                py,
                "InvalidInputError",
                format!("growth must be 'balanced' or 'longest', got {other:?}"),
            ))
        }
    };
    let g = grid_from(&labels)?;
    let s = seeds.as_array();
    if s.shape().len() != 2 || s.shape()[1] != 2 || s.shape()[0] != targets.len()? {
        return Err(raise(
            py,
            "InvalidInputError",
            "seeds must be (m, 2) with one row per target".into(),
        ));
    }
    if region < 0 {
        return Err(raise(
            py,
            "InvalidInputError",
            "region must be a label ≥ 0".into(),
        ));
    }
    let seeds: Vec<[f64; 2]> = (0..s.shape()[0])
        .map(|k| [s[[k, 0]] + 1.0, s[[k, 1]] + 1.0])
        .collect();
    let targets: Vec<f64> = targets.as_array().to_vec();
    let first = g
        .cells
        .iter()
        .filter(|&&c| c != OUTSIDE)
        .max()
        .map_or(0, |&m| m + 1)
        .max(region as Label + 1);
    let (w, h) = (g.w, g.h);
    let grids = guarded(py, move || {
        let padded = pad(&g, OUTSIDE);
        Ok(grow_batch(
            &padded,
            region as Label,
            first,
            &seeds,
            &targets,
            batch,
            rng_seed,
            radius,
            growth,
        ))
    })?;
    let mut out = Array3::<i32>::from_elem((grids.len(), h, w), -1);
    for (b, gp) in grids.iter().enumerate() {
        let gu = unpad(gp);
        for y in 0..h {
            for x in 0..w {
                let l = gu.get(x, y);
                if l != OUTSIDE && l != EMPTY {
                    out[[b, y, x]] = l as i32;
                }
            }
        }
    }
    Ok(out.into_pyarray(py))
}

/// Furnish one room: the request and the result are JSON (see `_core.pyi`).
#[pyfunction]
fn place_room(py: Python<'_>, request_json: &str) -> PyResult<String> {
    let req: PlacementRequest = parse(py, "placement request", request_json)?;
    guarded(py, move || {
        let out = core_place_room(&req)?;
        serde_json::to_string(&out).map_err(|e| CoreError::InvalidInput(e.to_string()))
    })
}

/// Furnish many rooms in parallel. Returns one JSON string per room: the placement, or
/// `{"error": {"kind": <exception class>, "message": ...}}` for a room that failed, so one bad
/// room does not cost the others.
#[pyfunction]
fn place_rooms(py: Python<'_>, requests_json: Vec<String>) -> PyResult<Vec<String>> {
    let mut reqs = Vec::with_capacity(requests_json.len());
    for (k, r) in requests_json.iter().enumerate() {
        reqs.push(parse::<PlacementRequest>(
            py,
            &format!("placement request {k}"),
            r,
        )?);
    }
    guarded(py, move || {
        Ok(core_place_rooms(&reqs)
            .into_iter()
            .map(|r| match r {
                Ok(p) => serde_json::to_string(&p)
                    .unwrap_or_else(|e| error_json("MansionError", &e.to_string())),
                Err(e) => {
                    let kind = match e {
                        CoreError::InvalidFootprint(_) | CoreError::InvalidInput(_) => {
                            "InvalidInputError"
                        }
                        CoreError::Infeasible(_) => "InfeasibleLayoutError",
                        CoreError::Planner(_) => "PlannerError",
                    };
                    error_json(kind, &e.to_string())
                }
            })
            .collect())
    })
}

fn error_json(kind: &str, message: &str) -> String {
    serde_json::json!({"error": {"kind": kind, "message": message}}).to_string()
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(solve_floor, m)?)?;
    m.add_function(wrap_pyfunction!(rasterise, m)?)?;
    m.add_function(wrap_pyfunction!(mask_outline, m)?)?;
    m.add_function(wrap_pyfunction!(vectorise, m)?)?;
    m.add_function(wrap_pyfunction!(adjacencies, m)?)?;
    m.add_function(wrap_pyfunction!(covered_cells, m)?)?;
    m.add_function(wrap_pyfunction!(box_cover, m)?)?;
    m.add_function(wrap_pyfunction!(mask_pieces, m)?)?;
    m.add_function(wrap_pyfunction!(mask_passable, m)?)?;
    m.add_function(wrap_pyfunction!(mask_windows, m)?)?;
    m.add_function(wrap_pyfunction!(pair_walls, m)?)?;
    m.add_function(wrap_pyfunction!(cell_sums, m)?)?;
    m.add_function(wrap_pyfunction!(grow_candidates, m)?)?;
    m.add_function(wrap_pyfunction!(place_room, m)?)?;
    m.add_function(wrap_pyfunction!(place_rooms, m)?)?;
    Ok(())
}
