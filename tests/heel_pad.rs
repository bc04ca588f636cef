//! The heel pad (`walk::heel_pad`, docs/gait-model.md §12 session 25): how far the stance
//! ankle sinks below the rigid foot's, read from the walk's frames as the flat foot's ankle
//! height over its drawn heel, with `body.ankle_height_m` set so that the rigid height is known.

use gaitlab::model::walk::leg::LegPhase;
use std::path::Path;

const ANKLE_HEIGHT_M: f64 = 0.07;

/// (least, most) sink (mm) of the flat stance foot's ankle over the leg-cycle phases `from..to`,
/// both legs, after the first two seconds; and the deepest a stance heel goes under the ground.
fn sink_mm(config: &str, sets: &[&str], from: f64, to: f64) -> ((f64, f64), f64) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(config);
    let mut sets: Vec<String> = sets.iter().map(|s| (*s).to_string()).collect();
    sets.push(format!("body.ankle_height_m={ANKLE_HEIGHT_M}"));
    let params = gaitlab::config::load(&path, &sets).unwrap();
    let run = gaitlab::analysis::run(&params, 8.0, 60.0).unwrap();
    let (mut least, mut most, mut under) = (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64);
    for f in run.frames.iter().filter(|f| f.time_s > 2.0) {
        for l in &f.legs {
            if l.leg_phase == LegPhase::Swing {
                continue;
            }
            under = under.max(l.ground_under_heel - l.heel.y);
            if l.phase >= from && l.phase < to {
                let sink = (ANKLE_HEIGHT_M - (l.ankle.y - l.heel.y)) * 1000.0;
                (least, most) = (least.min(sink), most.max(sink));
            }
        }
    }
    assert!(least.is_finite(), "{config} {sets:?}: no stance frame in {from}..{to}");
    ((least, most), under * 1000.0)
}

#[test]
fn the_loaded_heel_pad_lowers_the_ankle_6_mm_and_lets_it_rise_by_mid_stance() {
    // Foot flat (from 0.06) and the pad whole (0.06-0.10 of the cycle): 6 mm.
    let ((least, most), under) = sink_mm("configs/default.toml", &[], 0.065, 0.1);
    assert!(least > 5.9 && most < 6.0 + 1e-6, "loading: {least:.3}-{most:.3} mm");
    assert!(under < 1e-6, "a heel {under:.4} mm under the ground");
    // Let go by 30 %: at 28-30 % a fifth of a millimetre at most, and none after.
    let ((_, most), _) = sink_mm("configs/default.toml", &[], 0.28, 0.30);
    assert!(most < 0.2, "late mid-stance: {most:.3} mm");
}

#[test]
fn no_pad_where_it_is_off_or_set_to_none() {
    for (config, sets) in [
        ("configs/default.toml", &["legs.heel_pad_mm=0"][..]),
        ("configs/default.toml", &["walk.speed_mps=0.8"][..]),
        // Slopes and stairs keep the rigid foot (their flat foot is on the slope: the
        // landing's level treads are read on stairs).
        ("configs/stairs_up.toml", &[][..]),
    ] {
        let ((least, most), _) = sink_mm(config, sets, 0.065, 0.25);
        assert!(least.abs() < 1e-6 && most.abs() < 1e-6, "{config} {sets:?}: {least:.4}-{most:.4} mm");
    }
    // Half of it halfway through the blend (0.9 m/s: smoothstep 0.5), and a set size anywhere.
    let ((least, most), _) = sink_mm("configs/default.toml", &["walk.speed_mps=0.9"], 0.065, 0.1);
    assert!(least > 2.95 && most < 3.0 + 1e-6, "0.9 m/s: {least:.3}-{most:.3} mm");
    let ((least, most), _) = sink_mm("configs/default.toml", &["legs.heel_pad_mm=9"], 0.065, 0.1);
    assert!(least > 8.85 && most < 9.0 + 1e-6, "9 mm asked: {least:.3}-{most:.3} mm");
}

#[test]
fn a_heel_pad_of_none_walks_the_rigid_foot_s_loading_knee() {
    // The rigid foot's knee bends at once at heel strike and peaks early (18.1 deg at 9 % at
    // 1.3 m/s before session 25; people's 16.5 at 13 %); the pad's peaks on time.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
    let peak = |sets: &[String]| {
        let params = gaitlab::config::load(&path, sets).unwrap();
        let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
        let knee = &walk.curves.iter().find(|(n, _)| n == "knee_flex_r_deg").unwrap().1;
        (0..=12).map(|i| (2 * i, knee[i])).fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
    };
    let (rigid_pct, rigid_deg) = peak(&["legs.heel_pad_mm=0".to_string()]);
    let (padded_pct, padded_deg) = peak(&[]);
    assert!(rigid_pct <= 10 && rigid_deg > 17.5, "rigid: {rigid_deg:.1} at {rigid_pct} %");
    assert!((12..=14).contains(&padded_pct) && padded_deg < 17.0, "padded: {padded_deg:.1} at {padded_pct} %");
}
