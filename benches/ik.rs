//! Speed of the leg IK solvers on the default walk's own targets (one cycle, both legs, in
//! frame order, so the iterative solvers warm-start from the previous frame as in the walk).
//! Figures and machine in `benches/README.md`.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use gaitlab::analysis::ik::{IkTarget, collect_targets};
use gaitlab::config::presets;
use gaitlab::model::ik::{IkSettings, IkSolverKind, LegSolver};
use std::hint::black_box;

fn setup() -> (Vec<IkTarget>, IkSettings, f64, f64) {
    let params = presets::params("default").unwrap().unwrap();
    // Past start-up: cycles 2 and 3 of the walk.
    let all = collect_targets(&params, 3.0, 60.0).unwrap();
    let targets = all[all.len() / 3..].to_vec();
    let r = params.resolve();
    (targets, r.ik, r.dims.thigh, r.dims.shank)
}

fn legs(settings: IkSettings, thigh: f64, shank: f64) -> [LegSolver; 2] {
    [LegSolver::new(settings, thigh, shank, 1.0), LegSolver::new(settings, thigh, shank, -1.0)]
}

fn solve_all(legs: &mut [LegSolver; 2], targets: &[IkTarget]) -> u64 {
    let mut iterations = 0;
    for t in targets {
        let a = legs[t.side.index()].solve(black_box(&t.question));
        iterations += u64::from(a.iterations);
    }
    iterations
}

fn per_solve(c: &mut Criterion) {
    let (targets, settings, thigh, shank) = setup();
    let mut group = c.benchmark_group("ik solve on the walk's targets (warm-started, 0.1 mm)");
    group.throughput(Throughput::Elements(targets.len() as u64));
    for solver in [IkSolverKind::Analytic, IkSolverKind::Ccd, IkSolverKind::Fabrik, IkSolverKind::JacobianDls] {
        let settings = IkSettings { solver, ..settings };
        // Warm: a pass over the targets first, as the walk would have made.
        let mut solvers = legs(settings, thigh, shank);
        let iterations = solve_all(&mut solvers, &targets);
        println!("{}: {:.2} iterations per solve", solver.name(), iterations as f64 / targets.len() as f64);
        group.bench_function(solver.name(), |b| b.iter(|| solve_all(&mut solvers, &targets)));
    }
    group.finish();

    // The bare analytic solve, no leg-frame bookkeeping: the walk's own call.
    let questions: Vec<_> = targets.iter().map(|t| t.question).collect();
    let mut group = c.benchmark_group("analytic two-bone solve");
    group.throughput(Throughput::Elements(questions.len() as u64));
    group.bench_function("solve_two_bone", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for q in &questions {
                let s = gaitlab::model::ik::solve_two_bone(q.hip, black_box(q.target), thigh, shank, q.reference);
                sum += s.middle.x;
            }
            sum
        });
    });
    group.finish();
}

fn gradient_full(c: &mut Criterion) {
    let (targets, settings, thigh, shank) = setup();
    // Seed 002's settings: 100 random restarts on the first frame, 100 perturbations of
    // ±15° on every frame, δ0 = 5 down to ε = 1e-4.
    let mut full = IkSettings { solver: IkSolverKind::Gradient, ..settings };
    full.gradient.restarts = 100;
    full.gradient.perturbations = 100;
    let mut group = c.benchmark_group("gradient (seed 002 settings) per frame, both legs");
    group.sample_size(10);
    // A frame after the first: perturbations only.
    let frames: Vec<[IkTarget; 2]> = targets.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
    let mut solvers = legs(full, thigh, shank);
    solve_all(&mut solvers, &targets[..2]);
    let mut next = 0;
    group.bench_function("frame (100 perturbations a leg)", |b| {
        b.iter(|| {
            let frame = &frames[next % frames.len()];
            next += 1;
            solve_all(&mut solvers, frame)
        });
    });
    group.bench_function("first frame (100 restarts + 100 perturbations a leg)", |b| {
        b.iter_batched(
            || legs(full, thigh, shank),
            |mut fresh| solve_all(&mut fresh, &targets[..2]),
            BatchSize::SmallInput,
        );
    });
    group.finish();
}

criterion_group!(benches, per_solve, gradient_full);
criterion_main!(benches);
