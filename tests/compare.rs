//! `gaitlab compare`: the walk against a normative reference.

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_gaitlab");

fn gaitlab(args: &[&str]) -> std::process::Output {
    Command::new(BIN).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

#[test]
fn the_default_walk_against_the_built_in_norms() {
    let o = gaitlab(&["compare", "configs/default.toml"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table = String::from_utf8_lossy(&o.stdout);
    for curve in ["hip_flex", "knee_flex", "ankle_dorsi", "pelvis_tilt_ant*", "pelvis_obliq_up", "pelvis_rot_fwd"] {
        assert!(table.lines().any(|l| l.starts_with(curve)), "{curve} missing:\n{table}");
    }
    assert!(table.contains("Fukuchi"), "the reference is named");
    let o = gaitlab(&["compare", "configs/default.toml", "--json"]);
    let lines: Vec<serde_json::Value> =
        String::from_utf8_lossy(&o.stdout).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 6);
    for l in &lines {
        let rms = l["rms_deg"].as_f64().unwrap();
        assert!(rms.is_finite() && rms >= 0.0);
        assert!((0.0..=100.0).contains(&l["outside_1sd_pct"].as_f64().unwrap()));
    }
    // The knee's swing peak is where the norms put it, within a few percent of the cycle.
    let knee = lines.iter().find(|l| l["curve"] == "knee_flex").unwrap();
    let (walk_at, ref_at) = (knee["walk_max"][1].as_f64().unwrap(), knee["reference_max"][1].as_f64().unwrap());
    assert!((walk_at - ref_at).abs() <= 6.0, "knee peak at {walk_at} % against {ref_at} %");
}

/// A reference made of the walk's own curves gives no deviation: the comparison lines the
/// cycles up point for point.
#[test]
fn the_walk_against_itself_deviates_by_nothing() {
    let params = gaitlab::config::load(std::path::Path::new("configs/default.toml"), &[]).unwrap();
    let path = std::path::Path::new("configs/default.toml");
    let walk = gaitlab::snapshot::measure::measure(path, &params).unwrap();
    let curve = |name: &str| walk.curves.iter().find(|(n, _)| n == name).unwrap().1.clone();
    let stems = [
        ("hip_flex", "hip_flex_r_deg"),
        ("knee_flex", "knee_flex_r_deg"),
        ("ankle_dorsi", "ankle_dorsi_r_deg"),
        ("pelvis_tilt_ant", "pelvis_tilt_deg"),
        ("pelvis_obliq_up", "pelvis_obliquity_deg"),
        ("pelvis_rot_fwd", "pelvis_rotation_deg"),
    ];
    let mut csv = String::from("pct_cycle,speed_m_s");
    for (stem, _) in stems {
        csv.push_str(&format!(",{stem}_mean_deg,{stem}_sd_deg"));
    }
    csv.push('\n');
    for pct in 0..=100usize {
        csv.push_str(&format!("{pct},1.3"));
        for (_, name) in stems {
            let c = curve(name);
            // Every 2 % from the walk; the odd rows halfway (compare reads the even ones).
            let v = if pct % 2 == 0 { c[pct / 2] } else { 0.5 * (c[pct / 2] + c[pct / 2 + 1]) };
            csv.push_str(&format!(",{v},1.0"));
        }
        csv.push('\n');
    }
    let reference = gaitlab::normative::References::parse(&csv, "self.csv").unwrap();
    let c = gaitlab::normative::compare(path, &params, &reference).unwrap();
    for k in &c.curves {
        assert!(k.rms_deg < 1e-9, "{}: {}", k.curve, k.rms_deg);
        assert_eq!(k.outside_1sd_pct, 0.0);
    }
}

#[test]
fn a_bad_reference_is_refused_with_its_place() {
    let dir = std::env::temp_dir().join(format!("gaitlab-compare-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("ref.csv");
    std::fs::write(&bad, "pct_cycle,speed_m_s,hip_flex_mean_deg\n0,1.2,oops\n").unwrap();
    let o = gaitlab(&["compare", "configs/default.toml", "--reference", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("ref.csv:1:") && e.contains("no column `hip_flex_sd_deg`"), "{e}");
    // Every column there, a value not a number: its line.
    let header = "pct_cycle,speed_m_s,hip_flex_mean_deg,hip_flex_sd_deg,knee_flex_mean_deg,knee_flex_sd_deg,ankle_dorsi_mean_deg,ankle_dorsi_sd_deg,pelvis_tilt_ant_mean_deg,pelvis_tilt_ant_sd_deg,pelvis_obliq_up_mean_deg,pelvis_obliq_up_sd_deg,pelvis_rot_fwd_mean_deg,pelvis_rot_fwd_sd_deg";
    std::fs::write(&bad, format!("{header}\n0,1.2,oops,1,1,1,1,1,1,1,1,1,1,1\n")).unwrap();
    let o = gaitlab(&["compare", "configs/default.toml", "--reference", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("ref.csv:2:") && e.contains("`hip_flex_mean_deg` is `oops`, not a finite number"), "{e}");
    // A reference that is not there is named as a reference, not as a config.
    let o = gaitlab(&["compare", "configs/default.toml", "--reference", dir.join("none.csv").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("none.csv") && e.contains("cannot read the reference"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_walks_spatiotemporal_figures_come_with_the_comparison_and_agree_with_its_speed() {
    let o = gaitlab(&["compare", "configs/stroll.toml", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let first: serde_json::Value =
        serde_json::from_str(String::from_utf8_lossy(&o.stdout).lines().next().unwrap()).unwrap();
    let f = |k: &str| first[k].as_f64().unwrap();
    // Speed = stride x strides per second: the three are measured apart, from the frames.
    let from_steps = f("stride_length_m") * f("cadence_spm") / 120.0;
    assert!((from_steps - f("speed_mps")).abs() < 0.02 * f("speed_mps"), "{first}");
    assert!((55.0..=70.0).contains(&f("stance_pct")), "{first}");
    let table = String::from_utf8_lossy(&gaitlab(&["compare", "configs/stroll.toml"]).stdout).to_string();
    assert!(table.lines().nth(1).unwrap().starts_with("# the walk: cadence "), "{table}");
}

/// The cadence and stride norms are those of the walk's own speed, and the table and every
/// JSON line say which blocks they came from; the joint curves' reference speed stays named.
#[test]
fn the_spatiotemporal_norms_are_for_the_walks_speed_and_say_so() {
    let norms = gaitlab::normative::SpeedNorms::built_in();
    let pelvis = gaitlab::normative::PelvisNorms::built_in();
    for (config, blocks, curves) in [
        (
            "configs/stroll.toml",
            "interpolated between the 0.862 and 1.048 m/s blocks",
            "interpolated between the 0.796 and 0.997 m/s blocks",
        ),
        (
            "configs/default.toml",
            "interpolated between the 1.232 and 1.417 m/s blocks",
            "interpolated between the 0.997 and 1.303 m/s blocks",
        ),
        (
            "configs/brisk.toml",
            "the 1.417 m/s block, the fastest (the walk is faster; not extrapolated)",
            "interpolated between the 1.593 and 1.799 m/s blocks",
        ),
    ] {
        let o = gaitlab(&["compare", config, "--json"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let stdout = String::from_utf8_lossy(&o.stdout).to_string();
        for line in stdout.lines() {
            let l: serde_json::Value = serde_json::from_str(line).unwrap();
            let f = |k: &str| l[k].as_f64().unwrap();
            let at = norms.at(f("speed_mps"));
            // To the last bits JSON's decimal text allows.
            assert!((f("cadence_norm_spm") - at.cadence_spm.0).abs() < 1e-9, "{config}");
            assert!((f("stride_length_norm_sd_m") - at.stride_length_m.1).abs() < 1e-12, "{config}");
            assert_eq!((f("norm_from_block_mps"), f("norm_to_block_mps")), (at.from_block_mps, at.to_block_mps));
            // The pelvis beside the same adults' measured pelvis at this speed.
            let p = pelvis.at(f("speed_mps"));
            assert!((f("pelvis_vertical_range_norm_cm") - p.vertical_range_cm.0).abs() < 1e-9, "{config}");
            assert!((f("pelvis_vertical_range_norm_sd_cm") - p.vertical_range_cm.1).abs() < 1e-9, "{config}");
            assert!(f("pelvis_vertical_range_cm") > 0.5 && f("pelvis_vertical_range_cm") < 5.0, "{config}");
            // The curves' reference: the walk's speed inside the blocks' 0.583-1.799 m/s.
            assert!((f("reference_speed_mps") - f("speed_mps").clamp(0.583, 1.799)).abs() < 1e-9, "{config}");
        }
        let table = String::from_utf8_lossy(&gaitlab(&["compare", config]).stdout).to_string();
        let norms_line = table.lines().nth(2).unwrap();
        assert!(norms_line.starts_with("# norms at ") && norms_line.contains(blocks), "{config}: {table}");
        let pelvis_line = table.lines().nth(3).unwrap();
        assert!(
            pelvis_line.starts_with("# pelvis vertical range: walk ") && pelvis_line.contains(" cm (walk "),
            "{table}"
        );
        assert!(
            table.lines().next().unwrap().ends_with(&format!(", {curves}; right gait cycle, every 2 %")),
            "{table}"
        );
    }
}

/// A walk off level ground is compared with level treadmill norms: the table says so, and
/// the JSON lines carry it; a level walk's do not.
#[test]
fn a_walk_off_level_ground_says_the_norms_are_level_walking() {
    for (config, level) in [("configs/stairs_up.toml", false), ("configs/default.toml", true)] {
        let table = String::from_utf8_lossy(&gaitlab(&["compare", config]).stdout).to_string();
        assert_eq!(
            table.contains("# the walk is not on level ground and the norms are level treadmill walking"),
            !level,
            "{table}"
        );
        let o = gaitlab(&["compare", config, "--json"]);
        let first: serde_json::Value =
            serde_json::from_str(String::from_utf8_lossy(&o.stdout).lines().next().unwrap()).unwrap();
        assert_eq!(first["level_ground"], level, "{config}");
    }
}
