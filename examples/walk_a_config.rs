//! Walks a config through the library API: load it, record a few gait cycles headless, and
//! print what each cycle measured and the steady-state figures `gaitlab report` puts in
//! `summary.json`.
//!
//! ```text
//! cargo run --release --example walk_a_config                          # the embedded default
//! cargo run --release --example walk_a_config -- configs/stairs_up.toml 8
//! ```
//!
//! Arguments: `[CONFIG.toml] [CYCLES]` (3 to 100, default 6). A config that does not load is
//! reported as `gaitlab check` reports it, with exit code 2.

use gaitlab::analysis::{self, Keep};
use gaitlab::config::{self, presets};
use gaitlab::report::metrics;
use std::path::Path;
use std::process::ExitCode;

const USAGE: &str = "usage: walk_a_config [CONFIG.toml] [CYCLES (3 to 100, default 6)]";

fn main() -> ExitCode {
    match walk(&std::env::args().skip(1).collect::<Vec<_>>()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{message}");
            ExitCode::from(2)
        }
    }
}

fn walk(args: &[String]) -> Result<(), String> {
    if args.len() > 2 {
        return Err(USAGE.into());
    }
    let (params, label) = match args.first() {
        // The same file `gaitlab init` prints, so the example runs from any directory.
        None => (
            presets::params("default").expect("the default preset exists").map_err(|e| e.to_string())?,
            "default".into(),
        ),
        // Reported as `gaitlab check` reports it: every problem with its line and column.
        Some(path) => (config::load(Path::new(path), &[]).map_err(|e| e.to_string())?, path.clone()),
    };
    let cycles = match args.get(1) {
        None => 6,
        Some(n) => {
            n.parse::<u32>().ok().filter(|n| (3..=100).contains(n)).ok_or_else(|| format!("CYCLES: {n:?}\n{USAGE}"))?
        }
    };
    // Frames, footfalls and step plans only: poses, IK questions and step problems are for
    // BVH, `gaitlab ik` and the landscape plot, and cost memory a frame.
    let run =
        analysis::record(&params, f64::from(cycles), params.sim.fps, Keep::default()).map_err(|e| e.to_string())?;
    println!("{label}: {} frames at {} fps, {} footfalls", run.frames.len(), run.fps, run.footfalls.len());

    println!(
        "\ncycle  time s  stride m  speed m/s  stance % R/L  double %  pelvis up-down cm  knee swing deg R/L  toe clearance cm R/L"
    );
    for c in analysis::cycle_summaries(&run.frames) {
        // Cycle 0 starts from standing: its figures are not the walk's. On stairs and slopes a
        // cycle's vertical range includes the climb; the summary below takes it out.
        let note = if c.cycle == 0 { "  (start-up)" } else { "" };
        let row = format!(
            "{:>5}  {:>6.3}  {:>8.3}  {:>9.2}  {:>5.1} / {:<5.1}  {:>8.1}  {:>17.1}  {:>8.1} / {:<8.1}  {:>6.1} / {:<6.1}{note}",
            c.cycle,
            c.duration_s,
            c.stride_m,
            c.speed_mps,
            c.stance_pct[0],
            c.stance_pct[1],
            c.double_support_pct,
            c.pelvis_vertical_cm,
            c.knee_max_swing_deg[0],
            c.knee_max_swing_deg[1],
            c.min_toe_clearance_cm[0],
            c.min_toe_clearance_cm[1],
        );
        println!("{}", row.trim_end());
    }

    // The report's definitions: steady cycles only, both legs pooled.
    let s = metrics::summarise(&run).map_err(|e| e.to_string())?;
    println!(
        "\nsteady state: {:.2} m/s, {:.1} steps/min, stride {:.3} m, step width {:.3} m",
        s.speed_mps, s.cadence_spm, s.stride_length_m, s.step_width_m
    );
    println!("pelvis bob {:.1} cm, lateral sway {:.1} cm", s.pelvis_vertical_range_cm, s.pelvis_lateral_range_cm);
    println!(
        "health: foot skate {:.3} mm, terrain penetration {:.3} mm, {} IK reach failures, {} non-finite values",
        s.foot_skate_mm, s.terrain_penetration_mm, s.reach_failures, s.non_finite_values
    );
    println!(
        "optimiser: {} steps, mean cost {:.1} against the fixed rule's {:.1}",
        s.optimiser_steps, s.optimiser_mean_cost, s.optimiser_fixed_rule_mean_cost
    );
    Ok(())
}
