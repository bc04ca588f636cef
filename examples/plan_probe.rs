//! Walks 40 steps with the optimiser off and the fixed rule not costed: the swing planning
//! alone, for `valgrind --tool=callgrind` (instruction counts repeat exactly).
use gaitlab::config::presets;
use gaitlab::model::walk::Walker;
fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "default".into());
    let mut p = presets::params(&name).unwrap().unwrap();
    p.optimiser.enabled = false;
    let mut w = Walker::new(&p).unwrap();
    w.set_cost_fixed_rule(false);
    while w.step_plans().len() < 40 {
        w.advance(1.0 / 60.0);
    }
    println!("{}", w.phase());
}
