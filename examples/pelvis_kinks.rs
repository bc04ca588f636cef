//! `cargo run --release --example pelvis_kinks`: largest step change of the pelvis's forward velocity between frames at 600 fps, per
//! config: a velocity jump at a pelvis key shows up as a spike (a development probe).
use gaitlab::analysis::run;
use gaitlab::config::presets;

fn main() {
    for (name, _) in presets::PRESETS {
        let p = presets::params(name).unwrap().unwrap();
        let fps = 600.0;
        let walk = run(&p, 6.0, fps).unwrap();
        let x: Vec<f64> = walk.frames.iter().map(|f| f.pelvis.x).collect();
        let v: Vec<f64> = x.windows(2).map(|w| (w[1] - w[0]) * fps).collect();
        let start = v.len() / 3;
        let jumps: Vec<f64> = v[start..].windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        let max = jumps.iter().copied().fold(0.0, f64::max);
        let mut sorted = jumps.clone();
        sorted.sort_by(f64::total_cmp);
        let median = sorted[sorted.len() / 2];
        println!(
            "{name:<12} max dv/frame {:.4} m/s  median {:.5} m/s  ratio {:.0}",
            max,
            median,
            max / median.max(1e-12)
        );
    }
}
