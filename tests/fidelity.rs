//! The walk against measured human gait (issue 12): a ratchet on `gaitlab compare`'s figures
//! for the shipped speeds, and the shapes the calibration set out to give.
//!
//! Measured 2026-11-23 after the calibration (before it, on the default walk: hip r 0.961 /
//! RMS 11.4°, knee 0.880 / 12.3°, ankle 0.821 / 10.3°, the ankle never below −0.4°). The
//! issue's targets are r ≥ 0.95 and RMS ≤ 5° (ankle ≤ 4°). As of session 11: shapes (r) meet
//! them for hip and knee at every speed and for the ankle from 1.0 m/s up (0.913 at 0.8);
//! RMS for the hip from 0.8 to 1.3 m/s, for the ankle at 1.0 and 1.3 m/s, and never yet for
//! the knee (9.6° at 1.3 m/s): its loading response is too flexed (the pelvis still falls
//! after heel strike) and the reference is one speed (1.245 m/s), so slower and brisker walks
//! are compared with another speed's curves. Each bound is the measured value with a small
//! margin: a change that moves the walk away from the norms fails here.

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
        // Measured in session 11 with the norms' walk ratio (0.0055; cadence and stride within
        // 0.1 SD of the speed norms at 0.8-1.3 m/s, against -1.2 / +1.0 SD before) and the toe
        // lifted by the ankle in swing. Default 1.3 m/s: hip 4.76 / 0.992, knee 9.64 / 0.975,
        // ankle 3.39 / 0.983 (before both: 5.89 / 0.992, 10.70 / 0.975, 4.18 / 0.959).
        ("configs/default.toml", &[], [(5.1, 0.985), (10.0, 0.965), (3.7, 0.975)]),
        // Slower walks take the norms' shorter step and, as people do, a smaller hip range;
        // against the one-speed (1.245 m/s) reference that reads as a larger RMS. Stroll:
        // 4.49 / 0.984, 8.31 / 0.971, 4.03 / 0.932 (before: 3.41 / 0.989, 7.01 / 0.975,
        // 2.65 / 0.955).
        ("configs/stroll.toml", &[], [(4.9, 0.98), (8.7, 0.965), (4.4, 0.925)]),
        // 7.16 / 0.996, 14.15 / 0.973, 6.41 / 0.928 (1.75 m/s against 1.245 m/s norms; before:
        // 9.22 / 0.996, 15.87 / 0.971, 8.11 / 0.900).
        ("configs/brisk.toml", &[], [(7.6, 0.99), (14.6, 0.965), (6.8, 0.92)]),
        // 4.40 / 0.981, 8.06 / 0.968, 4.37 / 0.913 (before: 3.25 / 0.987, 7.13 / 0.967,
        // 3.09 / 0.939).
        ("configs/default.toml", &["walk.speed_mps=0.8"], [(4.8, 0.975), (8.5, 0.96), (4.8, 0.905)]),
        // 3.84 / 0.990, 8.51 / 0.971, 3.59 / 0.962 (before: 3.91 / 0.991, 7.67 / 0.979,
        // 2.72 / 0.962).
        ("configs/default.toml", &["walk.speed_mps=1.0"], [(4.2, 0.985), (8.9, 0.965), (4.0, 0.955)]),
        // 4.76 / 0.992, 9.64 / 0.975, 3.39 / 0.983.
        ("configs/default.toml", &["walk.speed_mps=1.3"], [(5.1, 0.985), (10.0, 0.965), (3.7, 0.975)]),
        // 6.66 / 0.993, 12.81 / 0.978, 5.14 / 0.972 (before: 8.14 / 0.996, 14.26 / 0.971,
        // 6.88 / 0.914).
        ("configs/default.toml", &["walk.speed_mps=1.6"], [(7.1, 0.99), (13.2, 0.97), (5.5, 0.965)]),
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
    // reach guard lowers the mid-stance key of their short steps). Session 11, with the
    // norms' shorter step the guard no longer lowers the fast walks' keys either: vertical
    // 1.07 / 1.88 / 2.80 / 3.50 cm, as set (2.33 cm per m/s above 1.3 m/s).
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
