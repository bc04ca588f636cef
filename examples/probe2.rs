use gaitlab::analysis;
use gaitlab::config::presets;
fn main() {
    let name = std::env::args().nth(1).unwrap();
    let p = presets::params(&name).unwrap().unwrap();
    let run = analysis::run(&p, 20.0, 60.0).unwrap();
    for f in &run.frames {
        for (i, l) in f.legs.iter().enumerate() {
            if !l.reached { println!("{} leg{} {:.3} {} hip {:.3} ankle {:.3} dist {:.4}", f.frame, i, l.phase, l.leg_phase.name(), l.hip, l.ankle, l.hip.distance(l.ankle)); }
        }
    }
    for ff in run.footfalls.iter().take(14) { println!("{} {:?} {:.3} nominal {:.3}", ff.step, ff.side, ff.heel, ff.nominal_x); }
    for sp in run.step_plans.iter().take(12) { println!("{sp:?}"); }
}
