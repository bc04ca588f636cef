//! `gaitlab fit`: a config calibrated to the normative reference, through the real binary.

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_gaitlab");

fn gaitlab(args: &[&str]) -> std::process::Output {
    Command::new(BIN).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

fn json(out: &std::process::Output) -> serde_json::Value {
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_str(String::from_utf8_lossy(&out.stdout).trim()).unwrap()
}

/// A deliberately bad start: the pelvis nearly flat and far ahead of the foot, a slow foot
/// flat and a high knee lift (hip / knee / ankle RMS 8.37 / 15.11 / 15.60 deg). Measured
/// 2026-11-25, with cadence and obliquity fitted too, to end at 3.00 / 7.37 / 2.79, cost
/// 13.03 -> 4.39 (2026-11-23, six keys: 4.3 / 8.2 / 4.5, cost 5.66); session 11, with the
/// swing ankle lifting the toe: 2.79 / 6.21 / 2.99 (ankle r 0.919), cost 11.09 -> 4.00.
/// Against the speed-matched references (2026-11-25, the reference at 1.30 m/s instead of
/// 1.245): from 6.81 / 12.47 / 10.43 to 2.36 / 5.41 / 2.21 (ankle r 0.954), cost 9.90 -> 3.33;
/// with the mid-stance drop law of session 12: 6.74 / 11.78 / 11.11 to 2.06 / 5.70 / 2.50 (ankle
/// r 0.949), cost 9.88 -> 3.42; with session 13's speed laws and quicker pelvis rise: 6.58 /
/// 11.42 / 11.02 to 1.98 / 5.31 / 2.18 (ankle r 0.964), cost 9.67 -> 3.16; with session 14's
/// double support at the legs' reach (the vertical range's fit range now from 0, its derived
/// value): 6.88 / 10.21 / 14.28 to 2.52 / 4.58 / 1.93 (knee r 0.984, ankle r 0.965), cost
/// 10.46 -> 3.01, inside the targets; with session 15's reach margin of 0.9996:
/// 10.75 -> 2.84 (2.49 / 4.06 / 1.97) with 600 walks (200 stuck at foot flat 0.19: 3.98); with
/// the swing and heel-rise curves drawn at three speeds: 10.55 -> 2.59 (1.73 / 3.84 / 2.21,
/// knee r 0.988, ankle r 0.970). Session 16, with the swing's push-off after toe-off limited,
/// the mean RMS alone settled at 3.38 with the ankle's r at 0.898 (3.13 deg); with a shape
/// below r 0.96 costing too (the start then costs 48.1): 2.75 (2.82 / 3.42 / 2.01, every
/// r at least 0.977). With the search started twice, from the config's keys and from the
/// middle of every range (from one start the same bad start had ended at 52.8 at 0.8 m/s and
/// 29.5 at 1.6): 48.1 -> 2.51 (2.29 / 2.93 / 2.31, every r at least 0.969).
const BAD: [&str; 8] = [
    "--set",
    "pelvis.vertical_range_cm=0.6",
    "--set",
    "pelvis.midstance_offset_cm=24",
    "--set",
    "legs.foot_flat=0.2",
    "--set",
    "legs.knee_lift_cm=7",
];

#[test]
fn a_bad_start_is_brought_back_to_the_calibrated_walk_deterministically() {
    let mut args = vec!["fit", "configs/default.toml", "--json"];
    args.extend(BAD);
    let (a, b) = (json(&gaitlab(&args)), json(&gaitlab(&args)));
    let (before, after) = (a["cost_before"].as_f64().unwrap(), a["cost_after"].as_f64().unwrap());
    // (The bad start costs 48.3 with its shapes' r under 0.96 and its pelvis range priced in;
    // the shipped default 2.63, fitted 2.14; this start's fit 2.15. Session 18: 53.0, 2.65,
    // 2.20 and 2.31.)
    assert!(before > 9.5 && after < 3.2, "{before} -> {after}");
    // Every walk inside the budget, the start's and the written answer's included (it read
    // "601 walks" for the default 600).
    let walks = a["evaluations"].as_u64().unwrap();
    assert!((590..=600).contains(&walks), "{walks} walks");
    for (curve, most, least_r) in [("hip_flex", 3.0, 0.98), ("knee_flex", 5.0, 0.975), ("ankle_dorsi", 2.5, 0.95)] {
        let k = a["curves_after"].as_array().unwrap().iter().find(|k| k["curve"] == curve).unwrap();
        assert!(k["rms_deg"].as_f64().unwrap() <= most, "{curve}: {k}");
        assert!(k["pearson_r"].as_f64().unwrap() >= least_r, "{curve}: {k}");
    }
    // The cadence is bought only inside the speed norms' mean +- 1 SD at 1.3 m/s (118.5 +- 6.5
    // steps/min, data/normative/spatiotemporal_by_speed.csv), not wherever the knee likes it.
    let cadence = a["keys"].as_array().unwrap().iter().find(|k| k["key"] == "walk.cadence_spm").unwrap();
    let (fitted, min, max) =
        (cadence["fitted"].as_f64().unwrap(), cadence["min"].as_f64().unwrap(), cadence["max"].as_f64().unwrap());
    assert!((min - 111.97).abs() < 0.01 && (max - 124.99).abs() < 0.01, "{cadence}");
    assert!((min..=max).contains(&fitted), "{cadence}");
    // The same walks in the same order: everything but the clock is the same.
    let strip = |mut v: serde_json::Value| {
        v.as_object_mut().unwrap().remove("seconds");
        v
    };
    assert_eq!(strip(a), strip(b));
}

/// The same bad start at 0.8 m/s, where from the config's keys alone the search settled at
/// 52.8 (hip / knee / ankle 5.98 / 8.11 / 5.45 deg, ankle r 0.54), and from those and the
/// middle of the ranges at 8.99 once the pelvis rose over the stance leg: with the third start
/// from the shipped calibration, 77.3 -> 2.54 (2.80 / 3.43 / 1.39, every r >= 0.972), below
/// the default config's own 2.73 at this speed (the search improves on the calibration); with
/// session 17's slow designs and mid-stance knee 79.1 -> 2.11 (2.49 / 2.51 / 1.33), below the
/// default config's own 2.34 (its own fit: 2.10).
#[test]
fn a_bad_start_is_brought_back_at_a_slow_speed_too() {
    let mut args = vec!["fit", "configs/default.toml", "--json", "--set", "walk.speed_mps=0.8"];
    args.extend(BAD);
    let a = json(&gaitlab(&args));
    let (before, after) = (a["cost_before"].as_f64().unwrap(), a["cost_after"].as_f64().unwrap());
    let calibrated = json(&gaitlab(&[
        "fit",
        "configs/default.toml",
        "--json",
        "--evaluations",
        "10",
        "--set",
        "walk.speed_mps=0.8",
    ]));
    let calibrated = calibrated["cost_before"].as_f64().unwrap();
    assert!(before > 50.0 && after < calibrated - 0.05, "{before} -> {after} (the calibration's {calibrated})");
    for k in a["curves_after"].as_array().unwrap().iter().take(3) {
        assert!(k["rms_deg"].as_f64().unwrap() <= 4.0 && k["pearson_r"].as_f64().unwrap() >= 0.95, "{k}");
    }
    // The pelvis's vertical range is part of the reference: a walk short of people's mean less
    // one SD (2.54 - 0.31 cm here) pays for each centimetre. Measured session 19: 1.55 cm from
    // this start (the calibration's walk 0.81 cm; 1.29 before the norms' rotation); session
    // 18, before the norms' pelvic obliquity, 1.80 (the calibration's 0.93; fitted on the joint
    // curves alone, 0.93).
    let range = |k: &str| a[k].as_f64().unwrap();
    assert!(range("pelvis_vertical_range_cm_after") >= 1.2, "{a}");
    assert!((range("pelvis_vertical_range_norm_cm") - 2.54).abs() < 0.01, "{a}");
    assert!((range("pelvis_vertical_range_norm_sd_cm") - 0.31).abs() < 0.01, "{a}");
}

#[test]
fn the_fitted_config_keeps_the_comments_walks_cleanly_and_compares_as_reported() {
    let dir = std::env::temp_dir().join(format!("gaitlab-fit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("fitted.toml");
    let mut args = vec!["fit", "configs/default.toml", "--evaluations", "150", "--out", file.to_str().unwrap()];
    args.extend(BAD);
    let out = gaitlab(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains("wrote ") && table.contains("legs.foot_flat"), "{table}");
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.starts_with("# Fitted by `gaitlab fit` against Fukuchi"), "{text}");
    assert!(text.contains("# preset: normal adult walk at 1.3 m/s"), "the input's comments are kept");
    // Each fitted key is written at its resolution (3 decimals in cm, 4 in a cycle), as a
    // person would write it, and the figures reported are that written config's (below).
    for key in gaitlab::fit::FIT_KEYS {
        let name = key.key.split('.').nth(1).unwrap();
        let line =
            text.lines().find(|l| l.starts_with(&format!("{name} = "))).unwrap_or_else(|| panic!("{name}: {text}"));
        let decimals = line.split('.').nth(1).map_or(0, str::len);
        assert!(decimals <= key.decimals, "{line}: more than {} decimals", key.decimals);
    }
    // The --set values and the fitted keys are in the file: it walks as fitted, and cleanly.
    let snapshot = gaitlab(&["snapshot", "--update", file.to_str().unwrap()]);
    assert!(snapshot.status.success(), "{}", String::from_utf8_lossy(&snapshot.stderr));
    let stored: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("fitted.snap.json")).unwrap()).unwrap();
    let figure = |k: &str| stored["summary"][k].as_f64().unwrap();
    assert!(figure("foot_skate_mm") < 1.0 && figure("terrain_penetration_mm") < 0.1, "{stored}");
    assert_eq!(figure("reach_failures"), 0.0, "{stored}");
    let compared = gaitlab(&["compare", file.to_str().unwrap(), "--json"]);
    let knee: serde_json::Value = String::from_utf8_lossy(&compared.stdout)
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .find(|l| l["curve"] == "knee_flex")
        .unwrap();
    let fitted_knee = table.lines().find(|l| l.starts_with("knee_flex")).unwrap();
    let reported: f64 = fitted_knee.split_whitespace().nth(2).unwrap().parse().unwrap();
    assert!((knee["rms_deg"].as_f64().unwrap() - reported).abs() < 0.01, "{knee} vs {fitted_knee}");
    // The pelvis line of the table and of the file's header is the written config's range too.
    let pelvis = table.lines().find(|l| l.starts_with("Pelvis vertical range: ")).unwrap();
    assert!(text.contains(&format!("# {pelvis}.\n")), "{pelvis}\n{text}");
    let after: f64 = pelvis.split(", ").nth(1).unwrap().split_whitespace().next().unwrap().parse().unwrap();
    assert!((knee["pelvis_vertical_range_cm"].as_f64().unwrap() - after).abs() < 0.01, "{knee} vs {pelvis}");
    let checks = gaitlab(&["simulate", file.to_str().unwrap(), "--cycles", "1"]);
    assert!(checks.status.success());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_options_are_refused_before_any_walking() {
    let out = gaitlab(&["fit", "configs/default.toml", "--evaluations", "5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--evaluations"), "{}", String::from_utf8_lossy(&out.stderr));
    // A folder as --out: refused before the search (src/cli/fit.rs resolves it first).
    let out = gaitlab(&["fit", "configs/default.toml", "--out", "configs"]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stdout.is_empty(), "no table: nothing was fitted");
}

#[test]
fn with_the_config_on_stdout_the_table_goes_to_stderr() {
    let out = gaitlab(&["fit", "configs/stroll.toml", "--evaluations", "10", "--out", "-"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let config = String::from_utf8_lossy(&out.stdout);
    assert!(config.starts_with("# Fitted by `gaitlab fit`"), "{config}");
    gaitlab::config::load_text(&config, "stdout", &[]).unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("cost (mean RMS"), "the table is on stderr");
}

#[test]
fn a_config_that_sets_its_stride_keeps_its_cadence_and_speed() {
    // Stride and cadence set together fix the speed too: the fit leaves the cadence alone
    // (its range is the one cadence the stride gives) and does not write it.
    let dir = std::env::temp_dir().join(format!("gaitlab-fit-stride-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("fitted.toml");
    let args = [
        "fit",
        "configs/default.toml",
        "--set",
        "walk.stride_m=1.3",
        "--evaluations",
        "60",
        "--out",
        file.to_str().unwrap(),
    ];
    let out = gaitlab(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = String::from_utf8_lossy(&out.stdout);
    let cadence = table.lines().find(|l| l.starts_with("walk.cadence_spm")).unwrap();
    assert_eq!(
        cadence.split_whitespace().collect::<Vec<_>>(),
        ["walk.cadence_spm", "120.000", "120.000", "120", "to", "120"]
    );
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.contains("\nstride_m = 1.3\n") && !text.contains("\ncadence_spm ="), "{text}");
    assert!(!text.lines().nth(2).unwrap().contains("walk.cadence_spm"), "{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}
