use gaitlab::config::presets;
use gaitlab::model::walk::frame::leg_angles;
use gaitlab::model::walk::pelvis::KeyKind;
use gaitlab::model::walk::{Walker, solve_leg};
fn main() {
    let name = std::env::args().nth(1).unwrap();
    let p = presets::params(&name).unwrap().unwrap();
    let mut w = Walker::new(&p).unwrap();
    while w.step_plans().len() < 4 {
        w.advance(1.0 / 60.0);
    }
    let pr = w.last_step_problem().unwrap().clone();
    let r = w.resolved();
    for ratio in [0.5, 0.8] {
        let x = pr.ms_before.x + ratio * (pr.ms_after.x - pr.ms_before.x);
        let mut plan = pr.plan.clone();
        plan.last_of_mut(KeyKind::DoubleSupport).unwrap().x = x;
        println!("ratio {ratio}");
        for (leg, from, to) in
            [(&pr.stance, pr.ms_before.phase, pr.ds.phase), (&pr.landing, pr.ds.phase, pr.ms_after.phase)]
        {
            let mut leg = leg.clone();
            for i in 0..25 {
                let ph = from + (to - from) * i as f64 / 24.0;
                w.project_stance(&plan, &mut leg, ph);
                let pel = w.pelvis_with_plan(&plan, ph);
                let hip = pel.hip(leg.side.sign());
                let t = w.target_of(&leg, ph, hip);
                let pose = solve_leg(r, hip, t);
                let a = leg_angles(pel.rotation, &pose, leg.side.sign());
                println!(
                    "{:?} {:.3} {:?} px {:.4} hip {:.1} knee {:.1} ankle {:.1} extra {:.1}",
                    leg.side,
                    ph,
                    leg.phase,
                    pel.position.x,
                    a.hip_flex_deg,
                    a.knee_flex_deg,
                    a.ankle_dorsi_deg,
                    t.extra_heel_rise.to_degrees()
                );
            }
        }
    }
}
