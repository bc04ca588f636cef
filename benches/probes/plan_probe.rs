//! Probe: 40 steps of a walk with the optimiser off and the fixed rule not costed — the swing
//! planning alone (footfall, reach guard, the 50-sample swing simulation), for
//! `valgrind --tool=callgrind`, whose instruction counts repeat exactly where this VM's wall
//! clock drifts. It prints only the final phase. The counts compared in benches/README.md,
//! "Pelvis optimisation", come from this walk.
//!
//! ```text
//! cargo bench --bench plan_probe --no-run     # prints: Executable ... (target/release/deps/plan_probe-HASH)
//! valgrind --tool=callgrind target/release/deps/plan_probe-HASH stairs_up
//! callgrind_annotate callgrind.out.PID | head -40
//! ```
//!
//! `cargo bench --bench plan_probe -- PRESET` runs it without valgrind. Not run by a plain
//! `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use gaitlab::model::walk::Walker;

const USAGE: &str = "cargo bench --bench plan_probe -- [PRESET] (default: default)";

fn main() {
    let args = common::args(USAGE, 1);
    let name = args.first().map_or("default", String::as_str);
    let mut p = common::preset(USAGE, name);
    p.optimiser.enabled = false;
    let mut w = Walker::new(&p).expect("a preset walks");
    w.set_cost_fixed_rule(false);
    while w.step_plans().len() < 40 {
        w.advance(1.0 / 60.0);
    }
    println!("{}", w.phase());
}
