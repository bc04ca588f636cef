//! Probe: the pelvis optimiser's cost across the feasible band of one step (the default
//! walk's step 11), as a row of 26 costs 0.5 mm apart, at 50 samples and at 200, with all
//! three joints weighted and with hip, knee or ankle alone. A sawtooth along the row means
//! the cost depends on where a corner in a joint angle falls between two samples rather than
//! on the pelvis position; a smooth row means it does not. What it showed before and after
//! the heel-rise easing is in benches/README.md, "Pelvis optimisation" (the report's
//! optimisation plot zooms to the same band).
//!
//! ```text
//! cargo bench --bench landscape_probe
//! ```
//!
//! Not run by a plain `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use gaitlab::model::walk::Walker;

const USAGE: &str = "cargo bench --bench landscape_probe";

fn main() {
    common::args(USAGE, 0);
    let p = common::preset(USAGE, "default");
    let mut w = Walker::new(&p).expect("the default preset walks");
    while w.step_plans().len() < 11 {
        w.advance(1.0 / 60.0);
    }
    let problem = w.last_step_problem().expect("a step was just planned").clone();
    for (samples, w3) in [
        (50u32, [1.0, 1.0, 1.0]),
        (200, [1.0, 1.0, 1.0]),
        (200, [1.0, 0.0, 0.0]),
        (200, [0.0, 1.0, 0.0]),
        (200, [0.0, 0.0, 1.0]),
    ] {
        let mut q = problem.clone();
        q.settings.samples = samples;
        (q.settings.weight_hip, q.settings.weight_knee, q.settings.weight_ankle) = (w3[0], w3[1], w3[2]);
        let q = q.with_allowance(&w);
        let (lo, _) = q.range;
        // The same stretch of the band as the figures in benches/README.md were read from.
        let row: Vec<String> = (0..60)
            .map(|i| lo + 0.205 + 0.0005 * f64::from(i))
            .map(|x| q.cost(&w, x, q.ds.y).map_or("  inf".into(), |c| format!("{c:5.0}")))
            .collect();
        println!("samples {samples} w {w3:?}: {}", row[14..40].join(" "));
    }
}
