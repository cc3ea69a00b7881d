//! Run the 64×64 seven-room budget repeatedly, for profilers (`perf record`, callgrind).
use mansion_benches::{t2d_like, with_widths};
use mansion_core::seedplan::HeuristicPlanner;
use mansion_core::solve::{solve_floor, SolveOptions};

fn main() {
    // a second argument `widths` adds width rules (rooms ≥ 1.0 m, hub ≥ 1.5 m, floor 1.0 m)
    let widths = std::env::args().nth(2).is_some_and(|a| a == "widths");
    let (graph, fp, base) = if widths {
        with_widths(t2d_like(), 1.0, 1.5, 4)
    } else {
        t2d_like()
    };
    let opts = SolveOptions {
        hierarchical: false,
        retries: 10,
        batch: 100,
        exhaustive: true,
        ..base
    };
    let reps: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let t = std::time::Instant::now();
    for _ in 0..reps {
        solve_floor(&graph, &fp, &opts, &mut HeuristicPlanner).expect("solvable");
    }
    let per = t.elapsed().as_secs_f64() / reps as f64;
    println!(
        "{:.1} ms per 10x100 budget, {:.1} µs per candidate",
        per * 1e3,
        per * 1e6 / 1000.0
    );
}
