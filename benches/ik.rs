//! Speed of the leg IK solvers on the default walk's own targets (one cycle, both legs, in
//! frame order, so the iterative solvers warm-start from the previous frame as in the walk).
//! Figures and machine in `benches/README.md`.

#[path = "ik/peers.rs"]
mod peers;

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use gaitlab::analysis::ik::{IkTarget, collect_targets, random_targets};
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

/// Every solver and both peers on one target set: the walk's targets warm-started, or random
/// reachable ones each from the rest pose (`cold`). Prints iterations and misses once, then
/// times a pass over the set.
fn against_peers(
    c: &mut Criterion,
    name: &str,
    targets: &[IkTarget],
    settings: IkSettings,
    leg: (f64, f64),
    cold: bool,
) {
    let (thigh, shank) = leg;
    let tol = settings.tolerance;
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(targets.len() as u64));
    group.sample_size(20);
    let n = targets.len() as f64;
    for solver in [IkSolverKind::Analytic, IkSolverKind::Ccd, IkSolverKind::Fabrik, IkSolverKind::JacobianDls] {
        let settings = IkSettings { solver, ..settings };
        let mut solvers = legs(settings, thigh, shank);
        let mut pass = move |targets: &[IkTarget]| {
            let (mut iterations, mut missed) = (0u64, 0u32);
            for t in targets {
                let leg = &mut solvers[t.side.index()];
                if cold {
                    leg.forget();
                }
                let a = leg.solve(black_box(&t.question));
                iterations += u64::from(a.iterations);
                missed += u32::from(!a.reached);
            }
            (iterations, missed)
        };
        let (iterations, missed) = pass(targets);
        println!("{name} / {}: {:.2} iterations per solve, {missed} missed", solver.name(), iterations as f64 / n);
        group.bench_function(solver.name(), |b| b.iter(|| pass(targets)));
    }
    let mut rebirth = [peers::Rebirth::new(thigh, shank), peers::Rebirth::new(thigh, shank)];
    let mut rebirth_pass = move |targets: &[IkTarget]| {
        let (mut iterations, mut missed) = (0u64, 0u32);
        for t in targets {
            let (it, error) = rebirth[t.side.index()].solve(black_box(&t.question), cold, tol);
            iterations += u64::from(it);
            missed += u32::from(error > tol);
        }
        (iterations, missed)
    };
    let (iterations, missed) = rebirth_pass(targets);
    println!("{name} / rebirth-ik: {:.2} iterations per solve, {missed} missed", iterations as f64 / n);
    group.bench_function("rebirth-ik fabrik", |b| b.iter(|| rebirth_pass(targets)));
    // k's chain is the right leg; the walk's left-leg targets are mirrored onto it.
    let mirror = |t: &IkTarget| {
        let mut q = t.question;
        if q.side_sign < 0.0 {
            q.target.z = 2.0 * q.hip.z - q.target.z;
        }
        q
    };
    let questions: Vec<_> = targets.iter().map(mirror).collect();
    let mut k_leg =
        [peers::KLeg::new(thigh, shank, &settings.limits, tol), peers::KLeg::new(thigh, shank, &settings.limits, tol)];
    let (mut iterations, mut missed) = (0u64, 0u32);
    for (t, q) in targets.iter().zip(&questions) {
        let (it, error) = k_leg[t.side.index()].count(q, cold, tol);
        iterations += u64::from(it);
        missed += u32::from(error > tol);
    }
    println!("{name} / k: {:.2} iterations per solve, {missed} missed", iterations as f64 / n);
    group.bench_function("k jacobian", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (t, q) in targets.iter().zip(&questions) {
                sum += k_leg[t.side.index()].solve(black_box(q), cold);
            }
            sum
        });
    });
    group.finish();
}

fn peers(c: &mut Criterion) {
    let (targets, settings, thigh, shank) = setup();
    against_peers(c, "ik peers, the walk's targets (warm)", &targets, settings, (thigh, shank), false);
    let random = random_targets(1000, 19, thigh, shank, &settings.limits);
    against_peers(c, "ik peers, 1000 random reachable targets (cold)", &random, settings, (thigh, shank), true);
}

criterion_group!(benches, per_solve, gradient_full);
criterion_group!(peer_benches, peers);
criterion_main!(benches, peer_benches);
