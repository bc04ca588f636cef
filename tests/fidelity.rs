//! The walk against measured human gait (issue 12): a ratchet on `gaitlab compare`'s figures
//! for the shipped speeds, and the shapes the calibration set out to give.
//!
//! Measured 2026-11-23 after the calibration (before it, on the default walk: hip r 0.961 /
//! RMS 11.4°, knee 0.880 / 12.3°, ankle 0.821 / 10.3°, the ankle never below −0.4°). The
//! issue's targets are r ≥ 0.95 and RMS ≤ 5° (ankle ≤ 4°); shapes (r) meet them for hip and
//! knee at every speed and for the ankle at 1.0 and 1.3 m/s; RMS for the hip at 0.8 and
//! 1.0 m/s, for the ankle from 0.8 to 1.0 m/s, and never yet for the knee: its loading
//! response is too flexed (the
//! pelvis is held low at double support) and the reference is one speed (1.245 m/s), so
//! brisk walks are compared with a slower walk's curves. Each bound is the measured value
//! with a small margin: a change that moves the walk away from the norms fails here.

use gaitlab::normative::{self, Comparison, Reference};
use std::path::Path;

fn compare(config: &str, sets: &[&str]) -> Comparison {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(config);
    let sets: Vec<String> = sets.iter().map(|s| (*s).to_string()).collect();
    let params = gaitlab::config::load(&path, &sets).unwrap();
    let reference = Reference::parse(normative::BUILT_IN, "built-in").unwrap();
    normative::compare(&path, &params, &reference).unwrap()
}

/// (rms_deg at most, r at least) for hip, knee, ankle.
type Bounds = [(f64, f64); 3];

#[test]
fn joint_curves_stay_as_close_to_the_norms_as_calibrated() {
    let cases: [(&str, &[&str], Bounds); 7] = [
        // Measured in session 11, once the swing ankle lifts the toe (before it, the heel was
        // raised instead: hip 5.89 / 0.992, knee 10.70 / 0.975, ankle 4.18 / 0.959): hip
        // 5.34 / 0.991, knee 10.23 / 0.971, ankle 3.88 / 0.984.
        ("configs/default.toml", &[], [(5.7, 0.985), (10.6, 0.965), (4.2, 0.975)]),
        // 3.07 / 0.991, 6.60 / 0.978, 2.79 / 0.971 (before: 3.41 / 0.989, 7.01 / 0.975,
        // 2.65 / 0.955).
        ("configs/stroll.toml", &[], [(3.5, 0.985), (7.0, 0.97), (3.2, 0.96)]),
        // 8.30 / 0.994, 15.15 / 0.961, 7.41 / 0.921 (1.75 m/s against 1.245 m/s norms; before:
        // 9.22 / 0.996, 15.87 / 0.971, 8.11 / 0.900: the swing knee nearer the norm, its
        // over-flexed loading response now the larger share of the shape's misfit).
        ("configs/brisk.toml", &[], [(8.7, 0.99), (15.6, 0.955), (7.8, 0.91)]),
        // 3.01 / 0.988, 6.80 / 0.970, 3.25 / 0.951.
        ("configs/default.toml", &["walk.speed_mps=0.8"], [(3.4, 0.98), (7.2, 0.965), (3.7, 0.94)]),
        // 3.50 / 0.992, 7.25 / 0.981, 2.76 / 0.980.
        ("configs/default.toml", &["walk.speed_mps=1.0"], [(3.9, 0.985), (7.7, 0.975), (3.2, 0.97)]),
        // 5.34 / 0.991, 10.23 / 0.971, 3.88 / 0.984.
        ("configs/default.toml", &["walk.speed_mps=1.3"], [(5.7, 0.985), (10.6, 0.965), (4.2, 0.975)]),
        // 7.30 / 0.994, 13.60 / 0.963, 6.31 / 0.940.
        ("configs/default.toml", &["walk.speed_mps=1.6"], [(7.7, 0.99), (14.0, 0.955), (6.7, 0.93)]),
    ];
    for (config, sets, bounds) in cases {
        let c = compare(config, sets);
        for (curve, (max_rms, min_r)) in ["hip_flex", "knee_flex", "ankle_dorsi"].iter().zip(bounds) {
            let k = c.curves.iter().find(|k| k.curve == *curve).unwrap();
            assert!(
                k.rms_deg <= max_rms && k.pearson_r >= min_r,
                "{config} {sets:?} {curve}: rms {:.2} (<= {max_rms}), r {:.3} (>= {min_r})",
                k.rms_deg,
                k.pearson_r
            );
        }
    }
}

#[test]
fn the_calibrated_shapes_are_there_on_the_default_walk() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
    let params = gaitlab::config::load(&path, &[]).unwrap();
    let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
    // Every 2 % of the right leg's cycle.
    let curve = |name: &str| walk.curves.iter().find(|(n, _)| n == name).unwrap().1.clone();
    let (knee, ankle) = (curve("knee_flex_r_deg"), curve("ankle_dorsi_r_deg"));
    let at = |c: &[f64], pct: usize| c[pct / 2];
    // Push-off: the ankle plantarflexes from heel rise to just after toe-off (norm: −13.6° at
    // 65 %, 12–20° in normal adults); before, it never went below −0.4°.
    let push_off = (30..35).map(|i| ankle[i]).fold(f64::INFINITY, f64::min);
    assert!((-25.0..=-12.0).contains(&push_off), "push-off {push_off}");
    // The knee flexes again from heel rise instead of being held at its reach limit: up 25°
    // from 46 % to toe-off (norm: 3.7° → 35°); before, held at 5–7° from 30 % to 45 %.
    assert!(at(&knee, 62) - at(&knee, 46) > 25.0, "{} -> {}", at(&knee, 46), at(&knee, 62));
    // The swing ankle near neutral after mid-swing (norm 0–6°); before, 20° dorsiflexion.
    for pct in [80, 84, 88, 92] {
        assert!((-5.0..=8.0).contains(&at(&ankle, pct)), "ankle at {pct} %: {}", at(&ankle, pct));
    }
    // The swing knee's peak in early-to-mid swing (norm 62° at 74 %).
    let (peak_i, peak) = knee.iter().enumerate().skip(31).fold((0, 0.0), |a, (i, &v)| if v > a.1 { (i, v) } else { a });
    assert!((70..=80).contains(&(2 * peak_i)) && (55.0..=70.0).contains(&peak), "{peak} at {} %", 2 * peak_i);
}

#[test]
fn the_pelvis_rises_more_and_sways_less_as_the_walk_speeds_up() {
    // Orendurff et al. 2004: vertical excursion 2.7 cm at 0.7 m/s rising to 4.8 cm at
    // 1.6 m/s, lateral 6.9 cm falling to 3.8 cm. Measured 2026-11-23: vertical 1.07 / 1.89 /
    // 3.46 / 4.46 cm, lateral 6.90 / 5.87 / 4.84 / 3.80 cm at 0.7 / 1.0 / 1.3 / 1.6 m/s — the
    // trends and the lateral values hold; vertically the slow walks sway too little (the
    // reach guard lowers the mid-stance key of their short steps).
    let mut previous: Option<(f64, f64)> = None;
    for speed in [0.7, 1.0, 1.3, 1.6] {
        let set = format!("walk.speed_mps={speed}");
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
        let params = gaitlab::config::load(&path, &[set]).unwrap();
        let run = gaitlab::analysis::run(&params, 8.0, 60.0).unwrap();
        let cycles = gaitlab::analysis::cycle_summaries(&run.frames);
        let c = &cycles[4];
        let (vertical, lateral) = (c.pelvis_vertical_cm, c.pelvis_lateral_cm);
        let orendurff_lateral = 6.9 - 3.44 * (speed - 0.7);
        assert!((lateral - orendurff_lateral).abs() < 0.5, "{speed} m/s: lateral {lateral}");
        assert!(vertical < 4.8 + 0.5, "{speed} m/s: vertical {vertical}");
        if let Some((v0, l0)) = previous {
            assert!(vertical > v0 + 0.5 && lateral < l0 - 0.5, "{speed} m/s: {vertical} {lateral} after {v0} {l0}");
        }
        previous = Some((vertical, lateral));
    }
}
