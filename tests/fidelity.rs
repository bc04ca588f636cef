//! The walk against measured human gait (issue 12): a ratchet on `gaitlab compare`'s figures
//! for the shipped speeds, against the speed-matched references (data/normative/
//! joint_angles_by_speed.csv: young adults' treadmill trials at 0.80 / 1.00 / 1.30 / 1.59 /
//! 1.80 m/s, read at the walk's speed), and the shapes the calibration set out to give.
//!
//! The targets are r >= 0.95, RMS <= 5 deg (ankle <= 4) and >= 80 % of the cycle
//! inside +-2 SD. Measured 2026-11-28 against the speed-matched references, after session
//! 15's `ik.reach_margin` of 0.9996 and the swing forward, swing heel-height and heel-rise
//! curves drawn at 0.8, 1.3 and 1.6 m/s and blended by speed (`gait_curves::DESIGN_SPEEDS_MPS`),
//! every target holds at every speed tested:
//! - hip RMS 2.1-3.0 deg, r >= 0.985;
//! - knee RMS 3.2-4.3 deg, r >= 0.982, 92-100 % of the cycle inside +-2 SD;
//! - ankle RMS 2.0-3.6 deg, r >= 0.956.
//!
//! Session 16 took the fast walks' push-off into normal adults' 12-20 deg (the fast design
//! refitted with it as a bound, the swing's dip after toe-off limited): at 1.6 m/s and brisk
//! the hip RMS is 3.1 / 3.5, the knee's 4.3 / 4.8 (r 0.973-0.980, 88-92 % inside +-2 SD), the
//! ankle's 1.7 / 2.2.
//!
//! Against the single 1.245 m/s reference used before, the slow walks had read better than
//! they were (people at 0.8 m/s flex the knee 8 deg in loading response, not the comfortable
//! walk's 16). Each bound is the measured value with a small margin: a change that moves the
//! walk away from the norms fails here.

use gaitlab::normative::{self, Comparison, References};
use std::path::Path;

fn compare(config: &str, sets: &[&str]) -> Comparison {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(config);
    let sets: Vec<String> = sets.iter().map(|s| (*s).to_string()).collect();
    let params = gaitlab::config::load(&path, &sets).unwrap();
    normative::compare(&path, &params, References::built_in()).unwrap()
}

/// (rms_deg at most, r at least, % of the cycle outside +-2 SD at most) for hip, knee, ankle.
type Bounds = [(f64, f64, f64); 3];

#[test]
fn joint_curves_stay_as_close_to_the_norms_as_calibrated() {
    // Measured (RMS deg / r / % outside +-2 SD) for hip; knee; ankle. Session 20's pelvic tilt
    // after the norms (its shape's r 0.85-0.96, the range 3 -> 1.8 deg) moved the hip alone
    // (measured against the pelvis): default 1.88 -> 1.64, stroll 2.54 -> 2.16, brisk 2.89 ->
    // 2.84, 0.8 m/s 2.50 -> 2.25, 1.0 2.68 -> 2.19, 1.6 2.30 -> 2.24 deg, r up 0.001-0.004; the
    // hip bounds below are tightened to it, the figures in the comments are from before it.
    // Session 21, the heel rise's reach softening brought in over 0.3 of its phase (0.1, the
    // knee's notch at the heel rise): within 0.1 deg of these but the 1.6 m/s hip, 2.24 -> 2.38,
    // and brisk's, 2.84 -> 2.97.
    let cases: [(&str, &[&str], Bounds); 9] = [
        // 1.88 / 0.996 / 0; 3.94 / 0.987 / 10; 2.08 / 0.977 / 0 (session 19, the norms' pelvic
        // obliquity, its RMS 2.25 -> 0.35 deg, the designs refitted to it, and the norms' rotation
        // shape (before it 1.75 / 0.996 / 0, 3.89 / 0.988 / 10, 2.08 / 0.976 / 0); session 18, the
        // pelvis placed for people's vertical range, 3.0 cm against 1.9: 2.43 / 0.995 / 0, 3.78 /
        // 0.988 / 10, 1.73 / 0.975 / 0; session 17: 2.05 / 0.994 / 0, 3.21 /
        // 0.991 / 8, 2.03 / 0.962 / 0; session 14: 2.08 / 0.994 / 0; 4.91 / 0.986 / 14; 2.13 /
        // 0.967 / 0; session 13: 3.28 / 0.994 / 0; 7.25 / 0.983 / 27; 2.69 / 0.991 / 0).
        // Session 25, the heel pad and the slow rise out of double support: 1.43 / 0.996 / 0;
        // 2.91 / 0.993 / 6; 2.03 / 0.976 / 0 (before: 1.62 / 0.997 / 0; 3.90 / 0.986 / 10; 1.97 /
        // 0.981 / 0).
        // Session 26, the swing knee's peak sooner and the swing ankle's cap lower (issue 12's
        // table): 1.51 / 0.996 / 0; 3.07 / 0.992 / 6; 2.03 / 0.973 / 0.
        ("configs/default.toml", &[], [(1.6, 0.995, 0.0), (3.1, 0.99, 8.0), (2.2, 0.97, 4.0)]),
        // 0.9 m/s, between the 0.80 and 1.00 m/s blocks: 2.54 / 0.992 / 0; 3.44 / 0.987 / 2;
        // 1.79 / 0.972 / 0 (session 20, the slow walk's pelvis falling late into double support
        // for people's vertical range, 1.36 -> 2.14 cm; session 19: 2.28 / 0.990 / 0, 3.07 /
        // 0.994 / 0, 1.45 / 0.983 / 0; session 18: 2.63 / 0.990 / 0, 2.65 / 0.994 / 0, 1.25 /
        // 0.982 / 0; session 17: 2.69 / 0.989 / 0, 2.52 / 0.996 / 0, 1.39 /
        // 0.978 / 0; session 17 with the pelvis rising over a straight stance leg, before
        // the slow designs' refit and the mid-stance knee of 7 -> 4 deg: 2.79 / 0.986 / 0, 3.18 / 0.992 / 2, 1.42 / 0.976 / 0; session 16:
        // 2.83 / 0.991 / 0, 4.34 / 0.991 / 2, 2.04 / 0.965 / 0; session 14: 3.73 / 0.991, 6.65 /
        // 0.989 / 14, 2.14 / 0.965).
        // Session 25, half the heel pad at 0.9 m/s: 2.02 / 0.995 / 0; 2.77 / 0.991 / 0; 1.78 /
        // 0.970 / 0 (before: 2.14 / 0.995 / 0; 3.36 / 0.987 / 2; 1.72 / 0.973 / 0).
        ("configs/stroll.toml", &[], [(2.2, 0.99, 0.0), (3.0, 0.988, 2.0), (1.9, 0.965, 4.0)]),
        // 1.75 m/s, between the 1.59 and 1.80 m/s blocks: 2.89 / 0.992 / 0; 4.28 / 0.980 / 10;
        // 2.73 / 0.975 / 0 (session 19; session 18: 2.08 / 0.994 / 0, 4.41 / 0.981 / 10, 2.30 /
        // 0.971 / 0; session 17: 3.54 / 0.988 / 0, 4.83 / 0.973 / 12, 2.22 /
        // 0.972 / 0; session 15: 3.04 / 0.992 / 0, 4.01 / 0.982 / 8, 3.58 / 0.969 / 6,
        // its push-off at -25.6 deg; session 14: 2.68 / 0.992, 5.91 / 0.974 / 12, 3.60).
        // Session 25, the heel pad let go sooner in fast walks: 2.88 / 0.992 / 0; 3.39 / 0.987 /
        // 8; 2.75 / 0.977 / 0 (before: 2.97 / 0.992 / 0; 4.31 / 0.979 / 10; 2.80 / 0.977 / 0).
        ("configs/brisk.toml", &[], [(3.0, 0.99, 0.0), (3.6, 0.983, 10.0), (3.0, 0.965, 4.0)]),
        // 2.50 / 0.991 / 0; 3.51 / 0.987 / 0; 1.86 / 0.969 / 0 (session 20: the pelvis falls late
        // into double support and its walked range is 1.99 cm, 0.81 before, people's 2.54 ±
        // 0.31; session 19: 2.88 / 0.982 / 0, 2.70 / 0.994 / 2, 1.99 / 0.955 / 0; session 18: 3.06 /
        // 0.981 / 0, 2.45 / 0.994 / 2, 1.51 / 0.970 / 0; before the slow designs' refit
        // 3.19 / 0.975 / 0, 3.38 / 0.987 / 2, 1.63 / 0.962 / 0; session 16: 3.01 / 0.985 / 0,
        // 4.30 / 0.990 / 2, 2.02 / 0.957 / 0: the rise over the stance leg costs the hip 0.01 of
        // r; session 14: 4.12 / 0.984, 6.84 / 0.989 / 12, 2.00 / 0.962).
        // Session 22, the pelvis nearer the heel at 0.7 and 0.8 m/s for people's vertical range
        // (1.99 -> 2.06 cm here) and the swing heel's lead capped (0.15 -> 0.09): 2.33 / 0.991 / 0;
        // 3.60 / 0.987 / 0; 2.02 / 0.963 / 0. Session 26, the swing ankle's cap lower (the walk's
        // peak 7.8 -> 7.2°, people's 6.7) lifts the late-swing heel instead, and the hip flexes
        // more there: 2.30 -> 2.41 / 0.992 / 0; 3.54 -> 3.63 / 0.987 / 0; 1.93 -> 1.85 / 0.967 / 0
        // (the hip's bound 2.4 -> 2.5).
        ("configs/default.toml", &["walk.speed_mps=0.8"], [(2.5, 0.99, 0.0), (3.7, 0.985, 4.0), (2.1, 0.96, 4.0)]),
        // 2.68 / 0.990 / 0; 3.75 / 0.983 / 6; 1.51 / 0.980 / 0 (session 20, the walked range
        // 1.85 -> 2.20 cm; session 19: 2.48 / 0.991 / 0, 3.39 / 0.991 / 4, 1.28 / 0.985 / 0;
        // session 18: 2.40 /
        // 0.993 / 0, 3.12 / 0.992 / 2, 1.15 / 0.985 / 0; session 17: 2.51 /
        // 0.993 / 0, 2.81 / 0.995 / 0, 1.53 / 0.978 / 0; before the slow designs' refit
        // 2.54 / 0.991 / 0, 3.22 / 0.995 / 0, 1.62 / 0.976 / 0; session 16: 2.64 / 0.994 / 0,
        // 4.30 / 0.992 / 0, 2.20 / 0.964 / 0; session 14: 3.44 / 0.994, 6.40 / 0.989 / 16, 2.33
        // / 0.966).
        // Session 25, the heel pad whole from 1.0 m/s: 1.98 / 0.994 / 0; 2.69 / 0.991 / 0; 1.64 /
        // 0.974 / 0 (before: 2.10 / 0.995 / 0; 3.64 / 0.984 / 6; 1.31 / 0.984 / 0 — the ankle's
        // price, its loading plantarflexion 2° deeper than people's).
        ("configs/default.toml", &["walk.speed_mps=1.0"], [(2.1, 0.99, 0.0), (2.9, 0.988, 2.0), (1.8, 0.97, 4.0)]),
        // Slower than the 0.80 m/s block (until session 26 the slowest, compared with it): session 22's pelvis
        // nearer the heel for people's vertical range (1.54 -> 1.97 cm at 0.7 m/s) costs the shape
        // of the ankle, r 0.942 -> 0.906 at 0.7 and 0.953 -> 0.932 at 0.75 m/s, under issue 12's
        // 0.95 (asked at 0.8 m/s and up): 3.03 / 0.991 / 0; 3.67 / 0.989 / 0; 3.15 / 0.906 / 0 and
        // 2.56 / 0.991 / 0; 3.56 / 0.989 / 0; 2.62 / 0.932 / 0. Session 26, the norms' 0.583 m/s
        // block (24 adults at 0.51-0.69 m/s; before it 0.7 and 0.75 m/s read the 0.796 block):
        // 0.7 m/s 3.01 -> 2.90 / 0.991 / 0; 3.62 -> 4.16 / 0.990 -> 0.988 / 0; 2.99 -> 2.65 / 0.917
        // -> 0.935 / 0, the knee further from people who flex it 7.4° in loading at 0.7 m/s (the
        // walk 12.6°); 0.75 m/s 2.53 / 0.992 / 0; 3.50 -> 3.73 / 0.989 / 0; 2.48 -> 2.34 / 0.941 ->
        // 0.947 / 0 (the knee's bound at 0.7 m/s 3.9 -> 4.3).
        ("configs/default.toml", &["walk.speed_mps=0.7"], [(3.2, 0.985, 0.0), (4.3, 0.985, 4.0), (3.3, 0.9, 4.0)]),
        ("configs/default.toml", &["walk.speed_mps=0.75"], [(2.7, 0.985, 0.0), (3.9, 0.985, 4.0), (2.8, 0.925, 4.0)]),
        // As the default.
        ("configs/default.toml", &["walk.speed_mps=1.3"], [(1.6, 0.995, 0.0), (3.1, 0.99, 8.0), (2.2, 0.97, 4.0)]),
        // 2.30 / 0.994 / 0; 3.99 / 0.984 / 10; 2.32 / 0.974 / 0 (session 19; session 18: 1.91 /
        // 0.995 / 0, 3.92 / 0.986 / 8, 1.67 / 0.979 / 0; session 17: 3.08 /
        // 0.990 / 0, 4.29 / 0.980 / 8, 1.74 / 0.976 / 0; session 15: 2.48 / 0.993 / 0,
        // 3.44 / 0.988 / 6, 2.75 / 0.974 / 0, its push-off at -23.6 deg; session 14: 2.21 /
        // 0.993, 5.70 / 0.979 / 18, 2.80 / 0.981 / 2).
        // Session 25: 2.26 / 0.994 / 0; 3.09 / 0.990 / 8; 2.23 / 0.977 / 0 (before: 2.38 / 0.994
        // / 0; 4.05 / 0.982 / 10; 2.29 / 0.976 / 0).
        ("configs/default.toml", &["walk.speed_mps=1.6"], [(2.4, 0.99, 0.0), (3.3, 0.985, 10.0), (2.6, 0.97, 4.0)]),
    ];

    for (config, sets, bounds) in cases {
        let c = compare(config, sets);
        for (curve, (max_rms, min_r, max_out2)) in ["hip_flex", "knee_flex", "ankle_dorsi"].iter().zip(bounds) {
            let k = c.curves.iter().find(|k| k.curve == *curve).unwrap();
            assert!(
                k.rms_deg <= max_rms && k.pearson_r >= min_r && k.outside_2sd_pct <= max_out2,
                "{config} {sets:?} {curve}: rms {:.2} (<= {max_rms}), r {:.3} (>= {min_r}), outside 2 SD {:.0} % (<= {max_out2})",
                k.rms_deg,
                k.pearson_r,
                k.outside_2sd_pct
            );
        }
    }
}

/// Push-off: the ankle's deepest plantarflexion around toe-off (56-76 % of the cycle) inside
/// normal adults' 12-20° from the comfortable speed up (issue 12's table), and near the
/// speed-matched norms' own, shallower one below it, and when theirs is. Measured session 16
/// on the right leg's mean cycle: −17.2 / −17.7 / −19.5° at 66-67 % for 1.3 / 1.6 / 1.75 m/s
/// (norms −14.2 / −15.8 / −15.4 at 63-65 %), −9.8 / −6.5° at 67-69 % for 1.0 / 0.8 m/s
/// (norms −10.7 / −7.8 at 66-67 %); before, −18.4 / −23.6 / −25.6 and −11.5 / −8.5 (the
/// swing's ankle curve carried its dip below a deep toe-off angle, and the fast heel-rise
/// design ended 5° steeper than people's foot at toe-off).
#[test]
fn push_off_plantarflexion_is_inside_normal_adults_range() {
    for (config, sets) in [
        ("configs/default.toml", &[][..]),
        ("configs/default.toml", &["walk.speed_mps=1.6"][..]),
        ("configs/brisk.toml", &[][..]),
        ("configs/default.toml", &["walk.speed_mps=1.0"][..]),
        ("configs/default.toml", &["walk.speed_mps=0.8"][..]),
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(config);
        let sets_owned: Vec<String> = sets.iter().map(|s| (*s).to_string()).collect();
        let params = gaitlab::config::load(&path, &sets_owned).unwrap();
        let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
        let ankle = &walk.curves.iter().find(|(n, _)| n == "ankle_dorsi_r_deg").unwrap().1;
        // Every 2 % of the cycle.
        let (pct, deg) =
            (28..=38).map(|i| (2 * i, ankle[i])).fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        let speed = compare(config, sets).speed_mps;
        let norms = References::built_in().at(speed);
        let mean = &norms.curves.iter().find(|c| c.0 == "ankle_dorsi").unwrap().1;
        let (norm_pct, norm_deg) =
            (56..=76).map(|p| (p, mean[p])).fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        if speed >= 1.25 {
            assert!((-20.0..=-12.0).contains(&deg), "{config} {sets:?}: push-off {deg:.1} deg");
        } else {
            assert!((deg - norm_deg).abs() <= 2.5, "{config} {sets:?}: push-off {deg:.1}, norms {norm_deg:.1} deg");
        }
        assert!(pct.abs_diff(norm_pct) <= 4, "{config} {sets:?}: push-off at {pct} %, norms at {norm_pct} %");
    }
}

/// The loading-response knee: its peak (0-25 % of the cycle, right leg's mean cycle) near the
/// speed-matched norms' in size and timing, at slow speeds as at the comfortable one. Session
/// 25, the heel pad (`walk::heel_pad`) and the slow rise out of double support, whole from 1.0
/// m/s: 10.6° at 10 % at 1.0 m/s (norms 11.3 at 12), 16.0 at 13 % at 1.3 (16.5 at 13), 19.7 at
/// 13 % at 1.6 (20.0 at 13), read every 1 %; before, 13.7 at 8 %, 18.1 at 9 %, 21.5 at 9 %: the
/// timing is held to 2 % from 1.0 m/s up (4 % before), the size to 1° over. 0.8 m/s, without
/// the pad, as before: 13.5 at 8 % (8.3 at 11). Measured
/// session 20: 13.4 deg at 8 % at 0.8 m/s, 13.7 at 8 % at 1.0 (the pelvis falls late and deeper
/// into double support, for people's vertical range, and the landing knee takes it: the
/// bound at 0.8 m/s 2.5 -> 5.5°, inside the norms' SD there, 6.8°). Session 19: 10.4 deg at 8 % at 0.8 m/s (norms 8.3 at 11), 13.3 at 8 % at 1.0 (11.3 at 12;
/// a second, equal peak at 4 %, 0.03° higher in a short average), 18.1 at 8 % at 1.3 (16.5 at
/// 13): with the norms' pelvic obliquity the landing hip is no
/// longer dropped at heel strike, the double support sits lower and the slow walk's loading
/// knee flexes 1° further (the bound at 0.8 m/s 1.5 -> 2.5°). Session 18: 9.6 at 10 %, 14.1 at
/// 9 %, 18.4 at 10 %. Session 17, with the pelvis rising over the stance leg in
/// slow walks (`pelvis.stance_rise`): 9.3 at 10 %, 14.1 at 10 %, 18.2 at 12 %; before, the
/// slow walks' knee stayed flexed past the hip's passage over the ankle: 14.8 at 19 % and 18.2
/// at 16 %.
#[test]
fn the_loading_knee_peaks_as_people_s_does_at_each_speed() {
    // (speed, most degrees over the norms' peak, most % of the cycle from its timing).
    for (speed, most_deg_over, most_pct_off) in [(0.8, 5.5, 4), (1.0, 1.0, 2), (1.3, 1.0, 2), (1.6, 1.0, 2)] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
        let params = gaitlab::config::load(&path, &[format!("walk.speed_mps={speed}")]).unwrap();
        let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
        let knee = &walk.curves.iter().find(|(n, _)| n == "knee_flex_r_deg").unwrap().1;
        // Every 2 % of the cycle.
        let (pct, deg) =
            (0..=12).map(|i| (2 * i, knee[i])).fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        let norms = References::built_in().at(speed);
        let mean = &norms.curves.iter().find(|c| c.0 == "knee_flex").unwrap().1;
        let (norm_pct, norm_deg) =
            (0..=25).map(|p| (p, mean[p])).fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        assert!(
            deg - norm_deg <= most_deg_over && deg > norm_deg - 1.5,
            "{speed} m/s: loading knee {deg:.1}, norms {norm_deg:.1} deg"
        );
        assert!(pct.abs_diff(norm_pct) <= most_pct_off, "{speed} m/s: loading knee at {pct} %, norms at {norm_pct} %");
    }
}

/// The swing, against the speed-matched norms (right leg's mean cycle, every 2 %): the ankle's
/// peak after mid-swing (76-100 % of the cycle) within 1° of people's, and the knee's peak
/// within 2 % of the cycle of theirs (3 % at 0.8 m/s, whose slow design session 17 fitted with
/// its peak at 76-77 %, people's at 75 %). Session 26 lowered the swing simulation's dorsiflexion
/// cap (7 -> 5°) and refitted the comfortable swing design: the ankle 7.8 / 6.5 / 6.0 / 7.2 /
/// 7.4° -> 7.2 / 6.2 / 4.7 / 6.1 / 6.0° at 0.8 / 1.0 / 1.3 / 1.6 / 1.75 m/s (people's 6.7 / 6.0 /
/// 5.4 / 5.9 / 6.1), read every 1 %; the knee at 77 / 74 / 74 / 74 / 73 % (people's 75 / 74 / 74
/// / 73 / 73).
#[test]
fn the_swing_ankle_and_knee_peak_as_people_s_do_at_each_speed() {
    for (speed, most_pct_off) in [(0.8, 3), (1.0, 2), (1.3, 2), (1.6, 2), (1.75, 2)] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
        let params = gaitlab::config::load(&path, &[format!("walk.speed_mps={speed}")]).unwrap();
        let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
        let curve = |name: &str| walk.curves.iter().find(|(n, _)| n == name).unwrap().1.clone();
        let norms = References::built_in().at(speed);
        let mean = |name: &str| norms.curves.iter().find(|c| c.0 == name).unwrap().1.clone();
        let peak = |c: &[f64], from: usize, to: usize, step: usize| {
            (from..=to).map(|i| (i * step, c[i])).fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
        };
        let (_, ankle) = peak(&curve("ankle_dorsi_r_deg"), 38, 50, 2);
        let (_, people_ankle) = peak(&mean("ankle_dorsi"), 76, 100, 1);
        assert!(
            (ankle - people_ankle).abs() <= 1.0,
            "{speed} m/s: swing ankle {ankle:.1}, people {people_ankle:.1} deg"
        );
        let (knee_pct, _) = peak(&curve("knee_flex_r_deg"), 30, 45, 2);
        let (people_pct, _) = peak(&mean("knee_flex"), 60, 90, 1);
        assert!(
            knee_pct.abs_diff(people_pct) <= most_pct_off,
            "{speed} m/s: swing knee at {knee_pct} %, people at {people_pct} %"
        );
    }
}

/// Another body is compared with the same adults: the calibrated laws are for a 1.75 m body,
/// and the mid-stance offset (cm) is scaled with the height, as the step is. Measured session 22
/// (hip / knee / ankle RMS, the offset scaled -> left at the 1.75 m body's): 1.95 m at 1.3 m/s
/// 2.93 / 4.57 / 1.91 against 4.21 / 6.56 / 2.85, at 1.6 m/s 3.74 / 5.13 / 2.42 against 4.38 /
/// 7.34 / 3.27; 1.55 m at 1.3 m/s 3.30 / 5.54 / 2.90 against 4.52 / 6.62 / 1.81, at 1.6 m/s 4.06 /
/// 6.26 / 2.78 against 5.67 / 7.40 / 2.79. The short body's ankle is the price (at 1.3 m/s).
#[test]
fn a_taller_or_shorter_body_walks_its_own_offset_nearer_the_norms() {
    for (height, speed, unscaled_offset_cm) in
        [(1.95, 1.3, 12.36), (1.95, 1.6, 14.3), (1.55, 1.3, 12.36), (1.55, 1.6, 14.3)]
    {
        let (h, v) = (format!("body.height_m={height}"), format!("walk.speed_mps={speed}"));
        let unscaled = format!("pelvis.midstance_offset_cm={unscaled_offset_cm}");
        let scaled = compare("configs/default.toml", &[&h, &v]);
        let kept = compare("configs/default.toml", &[&h, &v, &unscaled]);
        let rms = |c: &Comparison, curve: &str| c.curves.iter().find(|k| k.curve == curve).unwrap().rms_deg;
        let (hip, knee) = (rms(&scaled, "hip_flex"), rms(&scaled, "knee_flex"));
        assert!(
            knee < rms(&kept, "knee_flex") - 1.0 && hip < rms(&kept, "hip_flex") - 0.5,
            "{height} m at {speed} m/s: hip {hip:.2}, knee {knee:.2} against {:.2}, {:.2} unscaled",
            rms(&kept, "hip_flex"),
            rms(&kept, "knee_flex")
        );
        assert!(knee < 6.5 && hip < 4.2, "{height} m at {speed} m/s: hip {hip:.2}, knee {knee:.2}");
    }
}

/// Terminal swing: the knee straightens on to heel strike, as people's does (0.8 m/s: 12.9 /
/// 6.4 / 2.0 / 0.4° at 92 / 94 / 96 / 98 %), without bending again first. Session 22's slow
/// mid-stance pelvis nearer the heel had the swing heel, arriving sooner (`speed_laws::
/// swing_lead`), land ahead of the hip's reach: the knee straightened at the limit at 93 % and
/// bent again by up to 3.5° (0.70-0.75 m/s, every cycle, both legs; the fidelity figures did not
/// see it, 8.0° at 96 % is inside people's ± 2 SD). Measured with the lead capped at 0.09: the
/// knee's increments after 88 % of each leg's cycle sum to 0.0-0.13° from 0.5 to 0.95 m/s (0.87
/// at 1.0 and 1.3, 1.42 at 1.6 m/s, older and not fixed).
#[test]
fn the_swing_knee_straightens_on_to_heel_strike_at_slow_speeds() {
    for speed in [0.5, 0.6, 0.64, 0.7, 0.72, 0.74, 0.76, 0.8, 0.84, 0.9] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
        let params = gaitlab::config::load(&path, &[format!("walk.speed_mps={speed}")]).unwrap();
        let run = gaitlab::analysis::run(&params, 8.0, 60.0).unwrap();
        for side in 0..2 {
            // Each leg's terminal swing: from 88 % of its cycle to the heel strike that wraps it.
            let mut re_flexion = 0.0_f64;
            let mut worst = 0.0_f64;
            for w in run.frames.windows(2).filter(|w| w[0].time_s >= 2.0) {
                let (a, b) = (&w[0].legs[side], &w[1].legs[side]);
                if b.phase < a.phase {
                    worst = worst.max(re_flexion);
                    re_flexion = 0.0;
                } else if a.phase >= 0.88 {
                    re_flexion += (b.knee_flex_deg - a.knee_flex_deg).max(0.0);
                }
            }
            assert!(worst < 0.5, "{speed} m/s, leg {side}: the knee bends again {worst:.2} deg before heel strike");
        }
    }
}

/// Mid-stance at a slow walk: the knee straightens as people's does, from the loading peak to
/// the heel rise, without flexing again on the way. Measured session 17 at 0.8 m/s (every 2 %
/// from 14 to 30 % of the cycle): 7.3 7.0 6.7 6.3 5.7 5.2 5.2 5.4 4.3° against the norms' 7.8
/// 7.3 6.9 6.5 6.1 5.7 5.2 4.9 4.5 (the heel rise, at 31 %, then flexes it 0.6°; people's goes on
/// straightening to 3° at 42 %); lifted to the leg's reach margin it stood flat at 3.2°, and
/// with the lift fading out over the 0.10 before the heel rise it flexed to 8.8° at 26 % and
/// straightened again.
#[test]
fn a_slow_walk_s_stance_knee_straightens_through_mid_stance_as_people_s_does() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
    let params = gaitlab::config::load(&path, &["walk.speed_mps=0.8".to_string()]).unwrap();
    let walk = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
    let knee = &walk.curves.iter().find(|(n, _)| n == "knee_flex_r_deg").unwrap().1;
    let norms = References::built_in().at(0.8);
    let mean = &norms.curves.iter().find(|c| c.0 == "knee_flex").unwrap().1;
    for i in 7..=14 {
        let (walked, people) = (knee[i], mean[2 * i]);
        assert!((walked - people).abs() <= 1.0, "{} %: knee {walked:.1}, norms {people:.1} deg", 2 * i);
        assert!(knee[i + 1] - walked <= 0.5, "{} %: knee flexes again, {walked:.1} -> {:.1} deg", 2 * i, knee[i + 1]);
    }
}

/// The reference each comparison used is the walk's own speed's (inside the blocks).
#[test]
fn each_walk_is_compared_with_the_norms_of_its_own_speed() {
    for (config, sets, blocks) in [
        ("configs/default.toml", &["walk.speed_mps=0.8"][..], (0.796, 0.997)),
        ("configs/default.toml", &["walk.speed_mps=1.6"][..], (1.593, 1.799)),
        ("configs/brisk.toml", &[][..], (1.593, 1.799)),
        ("configs/stroll.toml", &[][..], (0.796, 0.997)),
    ] {
        let c = compare(config, sets);
        let expected = c.speed_mps.clamp(0.796, 1.799);
        assert!((c.reference_speed_mps - expected).abs() < 1e-9, "{config} {sets:?}: {}", c.reference_speed_mps);
        assert_eq!(c.reference_blocks_mps, blocks, "{config} {sets:?}");
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
    // The swing ankle near neutral after mid-swing (issue 12's table: 0-5°; the norms' own
    // 5.4° at 85 %): session 26, 4.7° at 84-86 %; before it 6.0°, and at first 20°.
    let swing_ankle = ankle[38..=50].iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!((0.0..=5.0).contains(&swing_ankle), "swing ankle peaks at {swing_ankle}");
    for pct in [80, 84, 88, 92] {
        assert!((-5.0..=8.0).contains(&at(&ankle, pct)), "ankle at {pct} %: {}", at(&ankle, pct));
    }
    // Issue 12's table: the loading-response knee peaks at 15-20° at 12-15 % of the cycle
    // (session 25: 16.0° at 13 %, read every 1 %; before the heel pad 18.1° at 9 %).
    let (load_i, load) = knee.iter().enumerate().take(13).fold((0, 0.0), |a, (i, &v)| if v > a.1 { (i, v) } else { a });
    assert!(
        (12..=15).contains(&(2 * load_i)) && (15.0..=20.0).contains(&load),
        "loading knee {load} at {} %",
        2 * load_i
    );
    // The swing knee's peak (issue 12's table: 55-65° at 70-74 %; the norms' 63.0° at 74 %):
    // session 26, 61.0° at 73.6 % read every 1 %; before it 62.9° at 75 %.
    let (peak_i, peak) = knee.iter().enumerate().skip(31).fold((0, 0.0), |a, (i, &v)| if v > a.1 { (i, v) } else { a });
    assert!((70..=74).contains(&(2 * peak_i)) && (55.0..=65.0).contains(&peak), "{peak} at {} %", 2 * peak_i);
    // Read between the 2 % samples (a parabola through the peak and its neighbours).
    let (a, b, c) = (knee[peak_i - 1], knee[peak_i], knee[peak_i + 1]);
    let peak_pct = 2.0 * (peak_i as f64 + 0.5 * (a - c) / (a - 2.0 * b + c));
    assert!((70.0..=74.0).contains(&peak_pct), "swing knee peaks at {peak_pct:.2} %");
}

#[test]
fn the_pelvis_rises_more_and_sways_less_as_the_walk_speeds_up() {
    // Orendurff et al. 2004: vertical excursion 2.7 cm at 0.7 m/s rising to 4.8 cm at
    // 1.6 m/s, lateral 6.9 cm falling to 3.8 cm. Measured 2026-11-23: vertical 1.07 / 1.89 /
    // 3.46 / 4.46 cm, lateral 6.90 / 5.87 / 4.84 / 3.80 cm at 0.7 / 1.0 / 1.3 / 1.6 m/s — the
    // trends and the lateral values hold; vertically the slow walks sway too little (the
    // reach guard lowers the mid-stance key of their short steps). Session 11, with the
    // norms' shorter step the guard no longer lowers the fast walks' keys either: vertical
    // 1.07 / 1.88 / 2.80 / 3.50 cm, as set (2.33 cm per m/s above 1.3 m/s). Session 12, with
    // the pelvis at mid-stance about as high as the stance leg reaches (the drop law, for
    // the joint curves): 0.56 / 1.17 / 2.49 / 3.50 cm. The trend holds; the slow walks are
    // further from Orendurff's values than before — the walk's stance leg reaches the
    // mid-stance pelvis only from 15 cm behind it, where the norms' hip passes over the ankle.
    // Session 13, with the mid-stance pelvis nearer the heel at slow speeds and further ahead
    // at fast ones, and the heel rising sooner above 1.3 m/s (the speed laws, for the joint
    // curves): 0.73 / 1.19 / 2.52 / 3.32 cm (the step from 0.7 to 1.0 m/s 0.46 cm, so the
    // bound between speeds is 0.4). Laws that bought the 1.6 m/s knee another 0.5-0.8 deg
    // left its pelvis rising 2.49-2.69 cm, no more than at 1.3 m/s: this test is what held
    // them back. Session 14, with the double support as high as the legs reach and its
    // lowest point sooner above 1.0 m/s (for the knee): 0.40 / 1.19 / 2.07 / 3.17 cm, the
    // norms' own stance hip through this leg chain 2.5 / 2.9 / 3.5 / 4.1 cm at 0.8 / 1.0 /
    // 1.3 / 1.6 m/s (docs/gait-model.md §12). Session 17, with the slow walks' pelvis rising
    // over the stance leg (`pelvis.stance_rise`): 0.72 / 1.27 / 1.92 / 2.91 cm
    // (session 16: 0.39 / 1.05 / 1.92 / 2.91).
    //
    // Against the same adults' measured pelvis (data/normative/pelvis_vertical_by_speed.csv:
    // the centre of their pelvis markers, 2.49 / 2.88 / 3.59 / 4.53 cm at 0.77 / 0.99 / 1.32 /
    // 1.57 m/s), measured session 17: the walk's range is 0.29 / 0.44 / 0.54 / 0.64 of people's
    // at 0.7 / 1.0 / 1.3 / 1.6 m/s. Session 18 placed the pelvis over the foot for people's
    // range from 1.0 m/s (`speed_laws::midstance_offset_cm`): 0.72 / 1.72 / 2.97 / 3.54 cm,
    // 0.29 / 0.60 / 0.83 / 0.78 of people's; at 1.3 and 1.6 m/s inside their mean ± 1 SD
    // (3.59 ± 1.58, 4.53 ± 1.63), held here. Session 19, with the norms' pelvic obliquity (the
    // landing hip up at heel strike, so the double support lower) and rotation: 0.68 / 1.85 /
    // 3.07 / 3.71 cm (compare's figure). Session 20, the slow walk's pelvis falling late into
    // double support (`gait_curves::PELVIS_VERTICAL_KEYS`): 1.51 / 1.97 / 2.18 / 3.04 / 3.67 cm
    // at 0.7 / 0.8 / 1.0 / 1.3 / 1.6 m/s (this test's cycle; compare's 1.54 / 1.99 / 2.20 / 3.07
    // / 3.71), from 0.8 m/s inside people's mean ± 2 SD (0.78 / 0.75 of their mean at 0.8 / 1.0),
    // held here; at 0.7 m/s (no norms that slow) 0.61 of the 0.77 m/s adults'. Session 22, the
    // mid-stance pelvis nearer the heel and the heel rise later at 0.7 and 0.8 m/s
    // (`speed_laws`' 0.7 m/s knots, the 0.8 m/s ones moved): compare's 1.97 / 2.06 / 2.20 /
    // 3.07 / 3.71 cm, from 0.7 m/s inside people's mean ± 2 SD (the slowest adults, 0.77 m/s,
    // 2.49 ± 0.28, read at 0.7 m/s too), held here. Session 26, the same adults measured at
    // 0.592 m/s (2.10 ± 0.61 cm, their T01 / T02 trials): at 0.7 m/s people's range reads 2.33 ±
    // 0.41 cm, between that block and the 0.774 one, and the walk's 1.97 is inside their mean ± 1
    // SD (-0.86 SD), held here; Orendurff's 2.7 cm at 0.7 m/s is other adults' centre of mass.
    let people = gaitlab::normative::PelvisNorms::built_in();
    let mut previous: Option<(f64, f64, f64)> = None;
    for (speed, least_share) in [(0.7, 0.75), (0.8, 0.75), (1.0, 0.7), (1.3, 0.75), (1.6, 0.70)] {
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
        let (measured, sd) = people.at(speed).vertical_range_cm;
        assert!(vertical >= least_share * measured, "{speed} m/s: vertical {vertical} against people's {measured}");
        if speed >= 1.3 || speed <= 0.7 {
            assert!(vertical >= measured - sd, "{speed} m/s: vertical {vertical} against people's {measured} +- {sd}");
        }
        assert!(
            vertical >= measured - 2.0 * sd,
            "{speed} m/s: vertical {vertical} against people's {measured} +- {sd}"
        );
        if let Some((v0, l0, s0)) = previous {
            // Rising with speed, falling sideways: each at least half a centimetre per m/s and
            // 1.6 cm per m/s (Orendurff's lateral falls 3.44).
            let dv = speed - s0;
            assert!(
                vertical > v0 + 0.5 * dv && lateral < l0 - 1.6 * dv,
                "{speed} m/s: {vertical} {lateral} after {v0} {l0}"
            );
        }
        previous = Some((vertical, lateral, speed));
    }
}

/// The pelvis range the joint curves alone account for (`normative::pelvis_range_through_legs`,
/// compare's "joint curves alone" line): put through the walk's legs, the walk's own mean
/// angles give within 0.25 cm of what it walks (the chain leaves out the hips' ab/adduction,
/// the trailing foot's roll and, from session 25, the heel pad's sinking: measured session 21,
/// +0.16 / +0.15 / +0.14 / +0.04 / -0.07 cm at 0.7 / 0.8 / 1.0 / 1.3 / 1.6 m/s; session 25
/// +0.16 / +0.15 / +0.07 / -0.04 / -0.22 cm, the bound 0.2 -> 0.25), and from 0.8 to 1.6 m/s at least 85 % of what people's mean
/// angles give (2.14 / 2.34 / 3.11 / 3.64 cm against 2.27 / 2.65 / 3.18 / 3.82): the walk's joint
/// curves are not what holds its pelvis under the adults' markers (2.54 / 2.91 / 3.56 / 4.53
/// cm), which people's own angles through this chain fall short of too, by 0.26-0.71 cm.
#[test]
fn the_walk_s_joint_curves_give_its_pelvis_nearly_the_range_people_s_give_through_its_legs() {
    for speed in [0.7, 0.8, 1.0, 1.3, 1.6] {
        let set = format!("walk.speed_mps={speed}");
        let c = compare("configs/default.toml", &[set.as_str()]);
        let (people, walk) = c.pelvis_range_through_legs_cm.expect("compare measures it on level ground");
        let walked = c.pelvis_vertical_range_cm;
        assert!((walk - walked).abs() < 0.25, "{speed} m/s: through the legs {walk:.2}, walked {walked:.2}");
        if speed >= 0.8 {
            assert!(walk >= 0.85 * people, "{speed} m/s: the walk's angles give {walk:.2} cm, people's {people:.2}");
            let markers = c.pelvis_norms.vertical_range_cm.0;
            assert!(people < markers - 0.2, "{speed} m/s: people's angles {people:.2} cm, their markers {markers:.2}");
        }
    }
    // Off level ground the chain does not stand: no figure.
    let c = compare("configs/slope_up.toml", &[]);
    assert_eq!(c.pelvis_range_through_legs_cm, None);
}

/// Pelvic obliquity: the norms' own shape and range at every speed (session 19,
/// `PELVIS_OBLIQUITY_KEYS` and `speed_laws::obliquity_range_deg`). Measured: RMS 0.36 / 0.22 /
/// 0.35 / 0.44 / 0.38 deg, r 0.996-0.999, range within 0.13 deg of the norms' at 0.8 / 1.0 / 1.3
/// / 1.6 / 1.75 m/s, no sample outside their 1 SD band. The design before (after Lin et al.
/// 2014, a fixed 7 deg) read RMS 2.0-2.7, r 0.70-0.74 and 63 % of the cycle outside 1 SD at
/// 1.3 m/s, its range 1.2 deg under the norms' at 0.8 m/s and 7.4 under at 1.6.
#[test]
fn pelvic_obliquity_follows_the_norms_shape_and_range_at_every_speed() {
    for (config, sets) in [
        ("configs/default.toml", &["walk.speed_mps=0.8"][..]),
        ("configs/default.toml", &["walk.speed_mps=1.0"]),
        ("configs/default.toml", &[]),
        ("configs/default.toml", &["walk.speed_mps=1.6"]),
        ("configs/brisk.toml", &[]),
    ] {
        let c = compare(config, sets);
        let k = c.curves.iter().find(|k| k.curve == "pelvis_obliq_up").unwrap();
        assert!(
            k.rms_deg <= 0.6 && k.pearson_r >= 0.99 && k.range_difference_deg.abs() <= 0.5 && k.outside_1sd_pct == 0.0,
            "{config} {sets:?}: rms {:.2}, r {:.3}, range {:+.2} deg, {:.0} % outside 1 SD",
            k.rms_deg,
            k.pearson_r,
            k.range_difference_deg,
            k.outside_1sd_pct
        );
    }
}

/// The sway knob plays at most 20 deg of pelvic obliquity (`params::MOST_OBLIQUITY_DEG`):
/// with the norms' 14.5 deg at 1.75 m/s, the knob's 3 asked 43 deg and bent the swing knee to
/// 84 deg and the ankle to 32 (the norms' 63 and 10). Measured capped: 19.85 deg walked, knee
/// peak 64.9, ankle 16.1.
#[test]
fn the_sway_knob_plays_no_more_obliquity_than_the_key_allows() {
    let c = compare("configs/default.toml", &["walk.sway=3", "walk.speed_mps=1.75"]);
    let curve = |name: &str| c.curves.iter().find(|k| k.curve == name).unwrap();
    let obliquity = curve("pelvis_obliq_up");
    let walked = obliquity.walk_max.0 - obliquity.walk_min.0;
    assert!((19.0..=20.0).contains(&walked), "obliquity {walked:.1} deg peak to peak");
    assert!(curve("knee_flex").walk_max.0 < 67.0, "knee {:?}", curve("knee_flex").walk_max);
    assert!(curve("ankle_dorsi").walk_max.0 < 18.0, "ankle {:?}", curve("ankle_dorsi").walk_max);
}

/// Pelvic rotation: the norms' own shape at 1.3 m/s (`gait_curves::PELVIS_ROTATION_KEYS`,
/// session 19), one design at every speed with the thesis-era range law. Measured: r 0.649 /
/// 0.936 / 0.997 / 0.993 / 0.989 and RMS 1.77 / 0.82 / 0.45 / 1.34 / 1.23 deg at 0.8 / 1.0 /
/// 1.3 / 1.6 / 1.75 m/s; the cosine before read r -0.05 / 0.44 / 0.68 / 0.75 / 0.74 and RMS
/// 2.3-3.1. Still off: at 0.8 m/s people's right hip is furthest forward at mid-stance, not
/// just after heel strike, and from 1.6 m/s the range is 4.5-4.8 deg under the norms'.
#[test]
fn pelvic_rotation_follows_the_norms_shape() {
    for (config, sets, least_r, most_rms) in [
        ("configs/default.toml", &["walk.speed_mps=0.8"][..], 0.6, 2.0),
        ("configs/default.toml", &["walk.speed_mps=1.0"], 0.92, 1.0),
        ("configs/default.toml", &[], 0.99, 0.6),
        ("configs/default.toml", &["walk.speed_mps=1.6"], 0.98, 1.5),
        ("configs/brisk.toml", &[], 0.98, 1.4),
    ] {
        let c = compare(config, sets);
        let k = c.curves.iter().find(|k| k.curve == "pelvis_rot_fwd").unwrap();
        assert!(
            k.pearson_r >= least_r && k.rms_deg <= most_rms,
            "{config} {sets:?}: rotation r {:.3} (>= {least_r}), rms {:.2} (<= {most_rms})",
            k.pearson_r,
            k.rms_deg
        );
    }
}
