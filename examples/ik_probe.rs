//! Runs every IK solver over a preset's walk targets (4 cycles, 60 fps) and prints the raw
//! summaries and the first unreached or misdirected solves.
//! `cargo run --release --example ik_probe -- [PRESET] [MAX_ITERATIONS]`
use gaitlab::analysis::ik::{collect_targets, run_solver};
use gaitlab::config::presets;
use gaitlab::model::ik::IkSolverKind;

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "default".into());
    let params = presets::params(&name).unwrap().unwrap();
    let targets = collect_targets(&params, 4.0, 60.0).unwrap();
    let mut r = params.resolve();
    if let Some(n) = std::env::args().nth(2) {
        r.ik.max_iterations = n.parse().unwrap();
    }
    for solver in IkSolverKind::ALL {
        let run = run_solver(&targets, solver, &r.ik, r.dims.thigh, r.dims.shank);
        println!("{:>13} {:?}", solver.name(), run.summary(&targets));
        for (x, t) in run
            .samples
            .iter()
            .zip(&targets)
            .filter(|(x, _)| !x.answer.reached || x.knee_direction_error_deg.unwrap_or(0.0) > 1.0)
            .take(4)
        {
            let d = t.question.local_target().length();
            println!(
                "    frame {} {:?} err {:.3} mm arc {:.3} mm it {} dir {:?} reach-d {:.4} angles {:?}",
                t.frame,
                t.side,
                x.answer.position_error * 1e3,
                x.answer.swivel_arc * 1e3,
                x.answer.iterations,
                x.knee_direction_error_deg,
                r.dims.thigh + r.dims.shank - d,
                x.answer.angles.to_array().map(f64::to_degrees)
            );
        }
    }
}
