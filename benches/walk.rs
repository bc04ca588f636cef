//! Speed of the walk model: one full-body frame update, the update that plans a swing at
//! toe-off, writing the joint table, and one step's pelvis optimisation by each method; and of
//! the report: the default config's whole (issue 15: ≤ 1.5 s with its GIF and glTF), its
//! glTF file alone, and its walk for slides (`walk.gif`, `walk.svg`) alone. Figures and machine in
//! `benches/README.md`.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use gaitlab::config::presets;
use gaitlab::model::body::Side;
use gaitlab::model::params::SearchMethod;
use gaitlab::model::walk::Walker;
use gaitlab::model::walk::leg::LegPhase;
use gaitlab::output::joint_table;
use std::hint::black_box;
use std::time::{Duration, Instant};

fn default_walker() -> Walker {
    let params = presets::params("default").unwrap().unwrap();
    let mut w = Walker::new(&params).unwrap();
    // Past start-up.
    for _ in 0..200 {
        w.advance(1.0 / 60.0);
    }
    w
}

fn frame_update(c: &mut Criterion) {
    // A plain frame: no leg phase boundary inside it. The frames that cross one carry the
    // per-step planning (benchmarked below) and are walked through but not timed here.
    let dt = 1.0 / 60.0;
    let mut w = default_walker();
    c.bench_function("frame update (pelvis, legs IK, trunk, arms, pose) at 60 fps", |b| {
        b.iter_custom(|iters| {
            let mut timed = Duration::ZERO;
            let mut counted = 0;
            while counted < iters {
                let before = [w.leg(Side::Right).phase_serial, w.leg(Side::Left).phase_serial];
                let start = Instant::now();
                w.advance(black_box(dt));
                let took = start.elapsed();
                if before == [w.leg(Side::Right).phase_serial, w.leg(Side::Left).phase_serial] {
                    timed += took;
                    counted += 1;
                }
            }
            timed
        });
    });
    let mut w = default_walker();
    c.bench_function("walking on: mean frame incl. per-step planning at 60 fps", |b| {
        b.iter(|| {
            w.advance(black_box(dt));
            black_box(w.pose().position[0]);
        });
    });
}

fn toe_off_planning(c: &mut Criterion) {
    // (config, optimiser on, fixed rule costed for the comparison)
    let cases = [
        ("default", false, false),
        ("stairs_up", false, false),
        ("default", false, true),
        ("stairs_up", false, true),
        ("default", true, true),
        ("stairs_up", true, true),
    ];
    for (name, optimiser, costed) in cases {
        let mut params = presets::params(name).unwrap().unwrap();
        params.optimiser.enabled = optimiser;
        let label = match (optimiser, costed) {
            (true, _) => "with the thesis optimiser",
            (false, true) => "optimiser off, fixed rule costed",
            (false, false) => "swing planning alone",
        };
        let mut w = Walker::new(&params).unwrap();
        w.set_cost_fixed_rule(costed);
        let step = 0.001 * w.resolved().cycle_s;
        // Walk until one small step short of a right toe-off, on the stairs if there are any.
        let mut seen_toe_offs = 0;
        loop {
            let mut probe = w.clone();
            probe.advance(step);
            if w.leg(Side::Right).phase == LegPhase::HeelRise && probe.leg(Side::Right).phase == LegPhase::Swing {
                seen_toe_offs += 1;
                if seen_toe_offs == 3 {
                    break;
                }
            }
            w = probe;
        }
        c.bench_function(&format!("update with toe-off swing planning ({name}, {label})"), |b| {
            b.iter_batched(
                || w.clone(),
                |mut walker| {
                    walker.advance(step);
                    walker
                },
                BatchSize::SmallInput,
            );
        });
    }
}

/// Walks `w` on in steps of `step` until one step short of `side`'s next toe-off.
fn short_of_toe_off(mut w: Walker, side: Side, step: f64) -> Walker {
    loop {
        let mut probe = w.clone();
        probe.advance(step);
        if w.leg(side).phase == LegPhase::HeelRise && probe.leg(side).phase == LegPhase::Swing {
            return w;
        }
        w = probe;
    }
}

/// The two steps of a stop against a steady one, swing planning alone (the ≤ 100 µs budget's
/// case) and with the thesis optimiser: the braking step (shortened, the settling set up) and
/// the closing step (beside the other foot, no double support to choose).
fn stop_planning(c: &mut Criterion) {
    for optimiser in [false, true] {
        let mut params = presets::params("default").unwrap().unwrap();
        params.optimiser.enabled = optimiser;
        let label = if optimiser { "with the thesis optimiser" } else { "swing planning alone" };
        let mut w = Walker::new(&params).unwrap();
        w.set_cost_fixed_rule(optimiser);
        let step = 0.001 * w.resolved().cycle_s;
        for _ in 0..3 {
            w = short_of_toe_off(w, Side::Right, step);
            w.advance(step);
        }
        let mut braking = short_of_toe_off(w, Side::Right, step);
        braking.request_stop();
        let mut after = braking.clone();
        after.advance(step);
        let closing = short_of_toe_off(after, Side::Left, step);
        for (kind, walker) in [("braking", braking), ("closing", closing)] {
            c.bench_function(&format!("update with toe-off planning of the {kind} step (default, {label})"), |b| {
                b.iter_batched(
                    || walker.clone(),
                    |mut walker| {
                        walker.advance(step);
                        walker
                    },
                    BatchSize::SmallInput,
                );
            });
        }
    }
}

/// A start from standing against a steady step: the update in which the start is asked
/// (its boundary chosen, the first step's footfall and keys planned, the launch built, the
/// stance key lowered for the flat feet) and the update that crosses the first step's
/// toe-off (its swing planned, its double support kept at the fixed rule).
fn start_planning(c: &mut Criterion) {
    let mut params = presets::params("start_stop").unwrap().unwrap();
    params.schedule.truncate(0);
    params.schedule.push(gaitlab::model::schedule::PaceEntry {
        trigger: gaitlab::model::schedule::PaceTrigger::TimeS(1e6),
        action: gaitlab::model::schedule::PaceAction::Start,
    });
    let mut standing = Walker::new(&params).unwrap();
    let step = 0.001 * standing.resolved().cycle_s;
    standing.advance(0.2);
    c.bench_function("start asked from standing (default speed, planning the start)", |b| {
        b.iter_batched(
            || standing.clone(),
            |mut walker| {
                walker.request_start();
                walker
            },
            BatchSize::SmallInput,
        );
    });
    let mut started = standing.clone();
    started.request_start();
    // The initiating leg is the one whose heel rises first.
    let side = if started.leg(Side::Right).footfall.step < started.leg(Side::Left).footfall.step {
        Side::Right
    } else {
        Side::Left
    };
    let first = short_of_toe_off(started, side, step);
    c.bench_function("update with toe-off planning of the first step (default speed, swing planning alone)", |b| {
        b.iter_batched(
            || first.clone(),
            |mut walker| {
                walker.advance(step);
                walker
            },
            BatchSize::SmallInput,
        );
    });
}

fn joint_table_rows(c: &mut Criterion) {
    let mut w = default_walker();
    let mut line = String::with_capacity(512);
    c.bench_function("frame update + joint table row", |b| {
        b.iter(|| {
            w.advance(1.0 / 60.0);
            joint_table::format_row(&w.frame(0), &mut line);
            black_box(line.len());
        });
    });
}

/// One step's pelvis choice, as the walk makes it at a toe-off: the fixed rule's cost (which
/// sets the heel-rise allowance) and the search. Each method on the same step problems.
fn optimiser(c: &mut Criterion) {
    let mut group = c.benchmark_group("pelvis optimisation, one step");
    for name in ["default", "stairs_down", "slope_down", "rough"] {
        let params = presets::params(name).unwrap().unwrap();
        let mut walker = Walker::new(&params).unwrap();
        // The fourth step: on the stairs, slope or rough ground in those configs.
        while walker.step_plans().len() < 6 {
            walker.advance(1.0 / 60.0);
        }
        let problem = walker.last_step_problem().unwrap().clone();
        for method in SearchMethod::ALL {
            let mut p = problem.clone();
            p.settings.method = method;
            group.bench_function(format!("{name}/{}", method.name()), |b| {
                b.iter(|| {
                    let p = black_box(&p).clone().with_allowance(&walker);
                    black_box(p.search(&walker).len())
                });
            });
        }
    }
    group.finish();
}

/// `gaitlab report configs/default.toml` as the command writes it (its 10 cycles at 60 fps,
/// every file and plot), and its `walk.glb` and its animation alone on the same recording.
fn report(c: &mut Criterion) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
    let (text, params) = gaitlab::config::load_with_text(&path, &[]).unwrap();
    let out = std::env::temp_dir().join(format!("gaitlab-bench-report-{}", std::process::id()));
    let input = gaitlab::report::ReportInput {
        name: "default".into(),
        source_text: &text,
        params: &params,
        cycles: params.sim.cycles,
        fps: params.sim.fps,
        compare: Vec::new(),
        ik_solvers: Vec::new(),
    };
    let mut group = c.benchmark_group("report, default config");
    group.sample_size(10);
    group.bench_function("whole report (10 cycles at 60 fps, walk.glb, walk.gif and walk.svg included)", |b| {
        b.iter(|| {
            let target = gaitlab::report::resolve_out(&out, false).unwrap();
            black_box(gaitlab::report::write_report(&input, &target, &mut |_| {}).unwrap());
        });
    });
    let run =
        gaitlab::analysis::record(&params, f64::from(params.sim.cycles), params.sim.fps, gaitlab::analysis::Keep::ALL)
            .unwrap();
    group.bench_function("walk.glb from the recording", |b| {
        b.iter(|| black_box(gaitlab::output::gltf::glb(&run.gait.resolved().dims, &run.poses, run.fps)).len());
    });
    group.bench_function("walk.gif and walk.svg from the recording", |b| {
        b.iter(|| black_box(gaitlab::report::plots::animation::animate("default", &run).unwrap().gif.len()));
    });
    group.finish();
    let _ = std::fs::remove_dir_all(&out);
}

criterion_group!(
    benches,
    frame_update,
    toe_off_planning,
    stop_planning,
    start_planning,
    joint_table_rows,
    optimiser,
    report
);
criterion_main!(benches);
