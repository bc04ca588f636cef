//! The cost over the feasible band of one default step, at two sample counts (a probe for
//! the sawtooth the report's zoomed landscape shows).
use gaitlab::config::presets;
use gaitlab::model::walk::Walker;

fn main() {
    let p = presets::params("default").unwrap().unwrap();
    let mut w = Walker::new(&p).unwrap();
    while w.step_plans().len() < 11 {
        w.advance(1.0 / 60.0);
    }
    let problem = w.last_step_problem().unwrap().clone();
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
        let row: Vec<String> = (0..60)
            .map(|i| lo + 0.205 + 0.0005 * f64::from(i))
            .map(|x| q.cost(&w, x, q.ds.y).map_or("  inf".into(), |c| format!("{c:5.0}")))
            .collect();
        println!("samples {samples} w {w3:?}: {}", row[14..40].join(" "));
    }
}
