use gaitlab::config::presets;
use gaitlab::model::walk::Walker;
fn main() {
    let name = std::env::args().nth(1).unwrap();
    let p = presets::params(&name).unwrap().unwrap();
    let mut w = Walker::new(&p).unwrap();
    while w.step_plans().len() < 4 {
        w.advance(1.0 / 60.0);
    }
    let pr = w.last_step_problem().unwrap().clone();
    for wts in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
        let mut q = pr.clone();
        q.settings.weight_hip = wts[0];
        q.settings.weight_knee = wts[1];
        q.settings.weight_ankle = wts[2];
        let l = q.landscape(&w, 13);
        println!("{:?}", wts);
        for c in l {
            println!(
                "  ratio {:.3} cost {:?}",
                (c.x - pr.ms_before.x) / (pr.ms_after.x - pr.ms_before.x),
                c.cost.map(|c| c.round())
            );
        }
    }
}
