use gaitlab::analysis;
use gaitlab::config::presets;
use gaitlab::model::walk::Walker;
fn main() {
    let name = std::env::args().nth(1).unwrap();
    let p = presets::params(&name).unwrap().unwrap();
    let w = Walker::new(&p).unwrap();
    let t = w.terrain().clone();
    let run = analysis::run(&p, 16.0, 120.0).unwrap();
    for f in &run.frames[480..500] {
        for (i, l) in f.legs.iter().enumerate() {
            if l.leg_phase.name() == "swing" {
                println!(
                    "{} leg{} {:.3} heel {:.4} ground {:.4} toe {:.4} ground {:.4}",
                    f.frame,
                    i,
                    l.phase,
                    l.heel,
                    t.height(l.heel.x),
                    l.toe,
                    t.height(l.toe.x)
                );
            }
        }
    }
}
