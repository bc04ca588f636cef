//! Solves one leg's inverse kinematics with the library's solvers: the analytic two-bone
//! solve the walk calls every frame, then one of the iterative solvers the IK lab compares
//! with it, through a `LegSolver`, on the same question.
//!
//! ```text
//! cargo run --release --example ik_one_leg                 # CCD
//! cargo run --release --example ik_one_leg -- fabrik       # or jacobian_dls, gradient, analytic
//! ```
//!
//! An unknown solver name prints the valid ones and exits 2.

use gaitlab::model::ik::{IkQuestion, IkSettings, IkSolverKind, LegSolver, solve_two_bone};
use glam::DVec3;
use std::process::ExitCode;

// A 1.75 m adult's leg (Drillis & Contini: thigh 0.245 H, shank 0.246 H).
const THIGH: f64 = 0.429;
const SHANK: f64 = 0.430;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let names: Vec<&str> = IkSolverKind::ALL.iter().map(|k| k.name()).collect();
    let kind = match args.as_slice() {
        [] => IkSolverKind::Ccd,
        [name] => match IkSolverKind::from_name(name) {
            Some(kind) => kind,
            None => {
                eprintln!("no solver {name:?}\nusage: ik_one_leg [SOLVER]  (SOLVER: {})", names.join(", "));
                return ExitCode::from(2);
            }
        },
        _ => {
            eprintln!("usage: ik_one_leg [SOLVER]  (SOLVER: {})", names.join(", "));
            return ExitCode::from(2);
        }
    };

    // World frame: x forward, y up, z to the right. A right hip at walking height, and the
    // ankle a little ahead of it and below: a leg just before heel strike.
    let hip = DVec3::new(0.0, 0.93, 0.09);
    let ankle_target = DVec3::new(0.25, 0.12, 0.10);
    // The knee goes toward this: forward, so it cannot flip backward. The walk turns it
    // by the foot's turnout but never ties it to the pelvis, whose rotation would twist
    // the leg.
    let forward = DVec3::X;

    let exact = solve_two_bone(hip, ankle_target, THIGH, SHANK, forward);
    println!("analytic two-bone: knee {:.4}, ankle {:.4}, reached {}", exact.middle, exact.end, exact.reached);

    // Out of reach, the analytic solve stretches the leg toward the target and says so
    // instead of giving NaN: the walk counts these as reach failures.
    let far_target = DVec3::new(0.6, 0.0, 0.1);
    let far = solve_two_bone(hip, far_target, THIGH, SHANK, forward);
    println!(
        "  a target {:.3} m away: ankle placed {:.3} m from the hip, reached {}",
        far_target.distance(hip),
        far.end.distance(hip),
        far.reached
    );

    // A LegSolver keeps the previous answer (and the gradient solver's random stream), so
    // it belongs to one leg for a whole walk: the second, nearby question starts warm.
    let settings = IkSettings { solver: kind, ..IkSettings::default() };
    let mut leg = LegSolver::new(settings, THIGH, SHANK, 1.0);
    for (when, target) in [("cold", ankle_target), ("warm, 1 cm further", ankle_target + DVec3::new(0.01, 0.0, 0.0))] {
        let question = IkQuestion { hip, target, reference: forward, side_sign: 1.0 };
        let a = leg.solve(&question);
        let [flex, abd, rot, knee] = a.angles.to_array().map(f64::to_degrees);
        println!(
            "{} ({when}): {} iterations, ankle off by {:.3} mm, knee {:.2} mm from the analytic one, reached {}",
            kind.name(),
            a.iterations,
            a.position_error * 1e3,
            a.knee.distance(solve_two_bone(hip, target, THIGH, SHANK, forward).middle) * 1e3,
            a.reached
        );
        println!("  hip flexion {flex:.1}°, abduction {abd:.1}°, rotation {rot:.1}°, knee flexion {knee:.1}°");
    }
    ExitCode::SUCCESS
}
