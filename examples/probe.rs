use gaitlab::analysis;
use gaitlab::config::presets;
fn main() {
    for (name, _) in presets::PRESETS {
        let p = presets::params(name).unwrap().unwrap();
        let run = analysis::run(&p, 20.0, 60.0).unwrap();
        let c = analysis::checks(&run.frames);
        let cs = analysis::cycle_summaries(&run.frames);
        let s = &cs[cs.len() / 2];
        let drop: f64 = run.step_plans.iter().map(|s| s.reach_guard_drop).fold(0.0, f64::max);
        println!(
            "{name:12} skate {:.3}mm {:?} pen {:.3}mm {:?} reach {} nf {} | stance {:.1} ds {:.1} vert {:.1} lat {:.1} knee st {:.0} sw {:.0} hip {:.0}/{:.0} ank {:.0}/{:.0} clear {:.1} guard {:.3} raises {}",
            c.foot_skate_mm,
            c.worst_skate,
            c.terrain_penetration_mm,
            c.worst_penetration,
            c.reach_failures,
            c.non_finite_values,
            s.stance_pct[0],
            s.double_support_pct,
            s.pelvis_vertical_cm,
            s.pelvis_lateral_cm,
            s.knee_max_stance_deg[0],
            s.knee_max_swing_deg[0],
            s.hip_flex_deg[0].0,
            s.hip_flex_deg[0].1,
            s.ankle_deg[0].0,
            s.ankle_deg[0].1,
            s.min_toe_clearance_cm[0],
            drop,
            run.step_plans.iter().map(|s| s.swing_raises).max().unwrap_or(0)
        );
    }
}
