//! Criterion benches of the solver, single-threaded (a one-thread rayon pool) so figures compare
//! across machines: (a) 100 candidates of a 7-room plan on a 64×64 grid, (b) the whole 10 × 100
//! budget of that plan, (c) `solve_floor` of a 500 m² office floor with about 20 rooms; (a) and (c)
//! again with width rules (rooms ≥ 1.0 m, the hub ≥ 1.5 m, and a floor-wide rule of 1.0 m); (c)'s
//! strict attempt (no rule lowered) with wider rules, with the default and the generator's budget.

use criterion::{criterion_group, criterion_main, Criterion};
use mansion_benches::{office, t2d_like, with_minimums, with_widths};
use mansion_core::seedplan::HeuristicPlanner;
use mansion_core::solve::{solve_floor, SolveOptions};
use std::hint::black_box;

fn one_thread() -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("thread pool")
}

fn bench(c: &mut Criterion) {
    let pool = one_thread();
    let (graph, fp, base) = t2d_like();
    let mut g = c.benchmark_group("t2d_64x64_7_rooms");
    g.sample_size(20);
    // flat mode: the 7 rooms grow as one round, so one retry is exactly 100 whole candidates
    let hundred = SolveOptions {
        hierarchical: false,
        retries: 1,
        batch: 100,
        exhaustive: true,
        ..base.clone()
    };
    g.bench_function("100_candidates", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&graph), &fp, &hundred, &mut HeuristicPlanner)
                    .expect("solvable")
            })
        })
    });
    let budget = SolveOptions {
        hierarchical: false,
        retries: 10,
        batch: 100,
        exhaustive: true,
        ..base.clone()
    };
    // the same hundred candidates with width rules: the width passes' cost per candidate
    let (wgraph, wfp, wbase) = with_widths(t2d_like(), 1.0, 1.5, 4);
    let wide = SolveOptions {
        hierarchical: false,
        retries: 1,
        batch: 100,
        exhaustive: true,
        ..wbase
    };
    g.bench_function("100_candidates_min_width", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&wgraph), &wfp, &wide, &mut HeuristicPlanner)
                    .expect("solvable")
            })
        })
    });
    g.bench_function("budget_10x100", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&graph), &fp, &budget, &mut HeuristicPlanner)
                    .expect("solvable")
            })
        })
    });
    g.bench_function("solve_floor_hierarchical", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&graph), &fp, &base, &mut HeuristicPlanner).expect("solvable")
            })
        })
    });
    g.finish();

    let (graph, fp, opts) = office();
    let mut g = c.benchmark_group("office_500m2_20_rooms");
    g.sample_size(10);
    g.bench_function("solve_floor", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&graph), &fp, &opts, &mut HeuristicPlanner).expect("solvable")
            })
        })
    });
    let (graph, fp, opts) = with_widths(office(), 1.0, 1.5, 2);
    g.bench_function("solve_floor_min_width", |b| {
        b.iter(|| {
            pool.install(|| {
                solve_floor(black_box(&graph), &fp, &opts, &mut HeuristicPlanner).expect("solvable")
            })
        })
    });
    // the same floor with design minimums on its rooms, without and with the repair pass that
    // brings rooms up to them, each round rebalanced too (what the two cost a floor)
    for (name, repair) in [("minimums_no_repair", false), ("minimums_repair", true)] {
        let (graph, fp, opts) = with_minimums(with_widths(office(), 1.0, 1.5, 2), repair);
        g.bench_function(name, |b| {
            b.iter(|| {
                pool.install(|| {
                    solve_floor(black_box(&graph), &fp, &opts, &mut HeuristicPlanner)
                        .expect("solvable")
                })
            })
        });
    }
    // the first attempt of a generated floor with wider rules (rooms ≥ 1.5 m, the hub ≥ 2.0 m)
    // than it can always meet: strictly (no rule lowered, 8 backtracks; a failure is timed like a
    // success, the generator then starts the floor again), and as the generator runs it now (two
    // backtracks under every rule, then a failing round's rules lowered where the search stands)
    let (graph, fp, opts) = with_widths(office(), 1.5, 2.0, 2);
    let strict = SolveOptions {
        relax_widths: false,
        ..opts.clone()
    };
    let budget = SolveOptions {
        strict_backtracks: Some(2),
        ..opts
    };
    for (name, o) in [
        ("strict_min_width", &strict),
        ("strict_budget_min_width", &budget),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                pool.install(|| solve_floor(black_box(&graph), &fp, o, &mut HeuristicPlanner).ok())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
