use gaitlab::analysis;
use gaitlab::model::params::WalkParams;
fn main() {
    let p = WalkParams::default();
    let run = analysis::run(&p, 3.0, 60.0).unwrap();
    for f in run.frames.iter().skip(65).step_by(3).take(24) {
        let l = &f.legs[0];
        println!("{:5.3} {:9} pel=({:6.3},{:5.3}) hip={:6.1} knee={:5.1} ank={:6.1} | hipP=({:5.3},{:5.3}) knee=({:5.3},{:5.3}) ankle=({:5.3},{:5.3}) heel=({:5.3},{:5.3}) toe=({:5.3},{:5.3}) {}",
          l.phase, l.leg_phase.name(), f.pelvis.x, f.pelvis.y, l.hip_flex_deg, l.knee_flex_deg, l.ankle_dorsi_deg,
          l.hip.x, l.hip.y, l.knee.x, l.knee.y, l.ankle.x, l.ankle.y, l.heel.x, l.heel.y, l.toe.x, l.toe.y, l.reached);
    }
}
