//! `gaitlab report`: the folder's files, their headers and keys, determinism, `--set` in
//! config.toml, failures that leave nothing behind. (Every config's summary figures are
//! checked against `configs/NAME.snap.json` by `tests/snapshot.rs`, through `gaitlab
//! snapshot`'s code.)

use std::path::{Path, PathBuf};
use std::process::Command;

fn gaitlab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab")).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-report-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

const SUMMARY_KEYS: &[&str] = &[
    "speed_mps",
    "cadence_spm",
    "stride_length_m",
    "step_width_m",
    "cycle_s",
    "stance_pct",
    "double_support_pct",
    "pelvis_vertical_range_cm",
    "pelvis_lateral_range_cm",
    "pelvis_tilt_range_deg",
    "pelvis_obliquity_range_deg",
    "pelvis_rotation_range_deg",
    "hip_flex_max_deg",
    "hip_ext_max_deg",
    "knee_flex_max_stance_deg",
    "knee_flex_max_swing_deg",
    "ankle_dorsi_max_deg",
    "ankle_plantar_max_deg",
    "shoulder_flex_range_deg",
    "elbow_flex_range_deg",
    "min_toe_clearance_cm",
    "max_heel_clearance_cm",
    "foot_skate_mm",
    "terrain_penetration_mm",
    "reach_failures",
    "non_finite_values",
    "optimiser_steps",
    "optimiser_mean_cost",
    "optimiser_infeasible_steps",
];

fn read(dir: &Path, file: &str) -> String {
    std::fs::read_to_string(dir.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

#[test]
fn default_report_has_every_file_header_and_key_and_repeats_byte_for_byte() {
    let (a, b) = (temp("a"), temp("b"));
    for dir in [&a, &b] {
        let out = gaitlab(&["report", "configs/default.toml", "--out", dir.to_str().unwrap(), "--cycles", "6"]);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), dir.display().to_string());
    }
    for file in gaitlab::report::FILES {
        // As bytes: walk.gif is not text.
        let bytes = |dir: &Path| std::fs::read(dir.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(bytes(&a) == bytes(&b), "{file} differs between runs");
    }
    for plot in gaitlab::report::plots::PLOTS {
        let svg = format!("plots/{plot}.svg");
        assert_eq!(read(&a, &svg), read(&b, &svg), "{svg} differs between runs");
        let png = a.join(format!("plots/{plot}.png"));
        let img = image::open(&png).unwrap_or_else(|e| panic!("{}: {e}", png.display()));
        assert_eq!((img.width(), img.height()), gaitlab::report::plots::SIZE, "{plot}.png size");
        // Not blank: a plot has many colours.
        let rgb = img.to_rgb8();
        let distinct: std::collections::BTreeSet<[u8; 3]> = rgb.pixels().step_by(97).map(|p| p.0).collect();
        assert!(distinct.len() > 20, "{plot}.png looks empty");
        let text = read(&a, &svg);
        let doc = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{svg} is not XML: {e}"));
        let words: String = doc.descendants().filter_map(|n| n.text()).collect::<Vec<_>>().join(" ");
        let axis = match *plot {
            "pelvis" | "joints" => "% of gait cycle",
            "swing_foot" | "ankle" => "% of swing",
            "stick_figure" => "forward x (m)",
            "ik" => "iterations (log scale)",
            _ => "step",
        };
        assert!(words.contains(axis), "{svg} lacks the axis label `{axis}`");
    }
    let md = read(&a, "summary.md");
    for plot in gaitlab::report::plots::PLOTS {
        assert!(md.contains(&format!("(plots/{plot}.png)")), "summary.md does not link {plot}");
    }
    let joints = read(&a, "joints.csv");
    assert!(joints.starts_with("frame,time_s,phase_r,phase_l,support,pelvis_x,pelvis_y,pelvis_z,"));
    assert!(joints.lines().next().unwrap().ends_with("terrain_y_under_heel_r,terrain_y_under_heel_l"));
    assert_eq!(read(&a, "footfalls.csv").lines().next().unwrap(), "step,side,x,y,z,terrain_y,stride_m");
    assert_eq!(read(&a, "optimisation.csv").lines().next().unwrap(), "step,candidate,pelvis_x,cost,feasible,chosen");
    // The walk's own solver (analytic) alone: two rows a frame, each exact.
    let ik = read(&a, "ik.csv");
    let frames = joints.lines().count() - 1;
    assert_eq!(ik.lines().count() - 1, 2 * frames);
    assert!(ik.lines().skip(1).all(|l| l.contains(",analytic,0.000000,") && l.contains(",1,true,")), "{}", &ik[..400]);
    // One chosen candidate a step.
    let opt = read(&a, "optimisation.csv");
    let steps: std::collections::BTreeSet<&str> = opt.lines().skip(1).map(|l| l.split(',').next().unwrap()).collect();
    assert_eq!(opt.lines().filter(|l| l.ends_with(",true")).count(), steps.len());
    let json: serde_json::Value = serde_json::from_str(&read(&a, "summary.json")).unwrap();
    for key in SUMMARY_KEYS {
        let v = json[key].as_f64().unwrap_or_else(|| panic!("{key} missing or not a number"));
        assert!(v.is_finite(), "{key} = {v}");
    }
    // The figures of a normal adult walk at 1.3 m/s, measured from the frames.
    let f = |k: &str| json[k].as_f64().unwrap();
    assert!((f("speed_mps") - 1.3).abs() < 0.01);
    assert!((f("stance_pct") - 62.0).abs() < 1.0);
    assert!((f("cadence_spm") - 120.0 / f("cycle_s")).abs() < 1e-9);
    assert!((f("stride_length_m") - f("speed_mps") * f("cycle_s")).abs() < 0.02);
    assert!((f("step_width_m") - 0.1).abs() < 1e-6);
    assert!(f("foot_skate_mm") < 0.5 && f("terrain_penetration_mm") < 1.0 && f("reach_failures") == 0.0);
    assert!(f("optimiser_mean_cost") > 0.0 && f("optimiser_steps") >= 6.0, "{}", f("optimiser_steps"));
    // Level ground at 1.3 m/s keeps the fixed rule since the calibration (issue 12): never above.
    assert!(f("optimiser_mean_cost") <= json["optimiser_fixed_rule_mean_cost"].as_f64().unwrap());
    let md = read(&a, "summary.md");
    for key in SUMMARY_KEYS {
        assert!(md.contains(&format!("(`{key}`)")), "{key} not in summary.md");
    }
    assert_eq!(read(&a, "config.toml"), read(Path::new(env!("CARGO_MANIFEST_DIR")), "configs/default.toml"));
    for dir in [a, b] {
        std::fs::remove_dir_all(dir).unwrap();
    }
}

#[test]
fn config_toml_holds_the_set_values_and_reloads_to_the_same_walk() {
    let dir = temp("set");
    let out = gaitlab(&[
        "report",
        "configs/stairs_up.toml",
        "--out",
        dir.to_str().unwrap(),
        "--cycles",
        "4",
        "--set",
        "walk.sway=1.7",
        "--set",
        "legs.knee_lift_cm=6.5",
        "--set",
        "walk.speed_mps=0.45",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    // The preset's words are quoted as its own; the speed walked is stated apart from them.
    let summary = read(&dir, "summary.md");
    assert!(
        summary.contains("\n\nPreset: \"walking up a flight of 8 shallow outdoor stairs")
            && summary.contains(", walked at 0.45 m/s (`walk.speed_mps`) on stairs terrain; 4 cycles at 60 fps"),
        "{summary}"
    );
    let text = read(&dir, "config.toml");
    assert!(text.contains("sway = 1.7") && text.contains("knee_lift_cm = 6.5"), "{text}");
    let from_report = gaitlab::config::load(&dir.join("config.toml"), &[]).unwrap();
    let direct = gaitlab::config::load(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/stairs_up.toml"),
        &["walk.sway=1.7".into(), "legs.knee_lift_cm=6.5".into(), "walk.speed_mps=0.45".into()],
    )
    .unwrap();
    assert_eq!(from_report, direct);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_failed_report_leaves_no_folder_and_bad_input_exits_2() {
    let blocker = temp("blocker");
    std::fs::write(&blocker, "a file, not a folder").unwrap();
    let out_dir = blocker.join("report");
    // A file where a folder of the path should be: refused before the walk, as bad input.
    let out = gaitlab(&["report", "configs/default.toml", "--out", out_dir.to_str().unwrap(), "--cycles", "4"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is a regular file, not a folder"));
    assert!(!out_dir.exists());
    std::fs::remove_file(&blocker).unwrap();

    let out = gaitlab(&["report", "configs/default.toml", "--cycles", "2"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("valid: 4 to 1000"));
    let out = gaitlab(&["report", "configs/default.toml", "--compare", "configs/no_such.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no_such.toml"));
    let out = gaitlab(&["report", "configs/default.toml", "--set", "walk.speed_mps=9"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("walk.speed_mps"));
}

/// walk.bvh read back by an independent parser (bvh_anim), its channels turned into joint
/// positions by forward kinematics: every joint within 1 mm of the model's own, every frame.
#[test]
fn walk_bvh_round_trips_through_an_independent_parser_to_within_a_millimetre() {
    use bvh_anim::ChannelType;
    use gaitlab::model::body::Bone;
    use glam::{DQuat, DVec3};
    let dir = temp("bvh");
    let out = gaitlab(&["report", "configs/stairs_up.toml", "--out", dir.to_str().unwrap(), "--cycles", "4"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let bvh = bvh_anim::from_bytes(std::fs::read(dir.join("walk.bvh")).unwrap()).expect("a valid BVH");
    let joints: Vec<_> = bvh.joints().collect();
    assert_eq!(joints.len(), Bone::ALL.len());
    let bones: Vec<Bone> = joints
        .iter()
        .map(|j| {
            let name = j.data().name().to_string();
            *Bone::ALL.iter().find(|b| b.name() == name).unwrap_or_else(|| panic!("unknown joint {name}"))
        })
        .collect();
    let params =
        gaitlab::config::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/stairs_up.toml"), &[]).unwrap();
    let mut walker = gaitlab::model::walk::Walker::new(&params).unwrap();
    let fps = params.sim.fps;
    let frames: Vec<_> = bvh.frames().collect();
    assert_eq!(frames.len(), (4.0 * walker.resolved().cycle_s * fps).round() as usize + 1);
    let mut worst = 0.0f64;
    for (i, frame) in frames.iter().enumerate() {
        if i > 0 {
            walker.advance(1.0 / fps);
        }
        let mut world: Vec<(DVec3, DQuat)> = Vec::with_capacity(joints.len());
        for (k, j) in joints.iter().enumerate() {
            let d = j.data();
            let o = d.offset();
            let mut position = DVec3::new(f64::from(o.x), f64::from(o.y), f64::from(o.z)) / 100.0;
            let mut rotation = DQuat::IDENTITY;
            for c in d.channels() {
                let v = f64::from(*frame.get(c).unwrap());
                match c.channel_type() {
                    ChannelType::PositionX => position.x += v / 100.0,
                    ChannelType::PositionY => position.y += v / 100.0,
                    ChannelType::PositionZ => position.z += v / 100.0,
                    ChannelType::RotationX => rotation *= DQuat::from_rotation_x(v.to_radians()),
                    ChannelType::RotationY => rotation *= DQuat::from_rotation_y(v.to_radians()),
                    ChannelType::RotationZ => rotation *= DQuat::from_rotation_z(v.to_radians()),
                }
            }
            let placed = match d.parent_index() {
                None => (position, rotation),
                Some(p) => {
                    let (pp, pr) = world[p];
                    (pp + pr * position, pr * rotation)
                }
            };
            world.push(placed);
            let model = walker.pose().pos(bones[k]);
            worst = worst.max(placed.0.distance(model));
        }
    }
    eprintln!("BVH round trip: worst joint distance {:.4} mm over {} frames", worst * 1000.0, frames.len());
    assert!(worst < 0.001, "worst joint distance {:.3} mm", worst * 1000.0);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_comparison_report_names_both_walks_in_legends_and_columns() {
    let dir = temp("compare");
    let out = gaitlab(&[
        "report",
        "configs/default.toml",
        "--compare",
        "configs/elderly.toml",
        "--out",
        dir.to_str().unwrap(),
        "--cycles",
        "4",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let md = read(&dir, "summary.md");
    assert!(md.contains("| figure | default | elderly | unit |"), "{md}");
    // Every figure row has a value for each walk, and the speeds differ as the presets do.
    let speed = md.lines().find(|l| l.contains("(`speed_mps`)")).unwrap();
    let cells: Vec<&str> = speed.split('|').map(str::trim).collect();
    assert_eq!(&cells[2..5], &["1.30", "0.95", "m/s"], "{speed}");
    for plot in ["pelvis", "joints"] {
        let svg = read(&dir, &format!("plots/{plot}.svg"));
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let words: Vec<&str> = doc.descendants().filter_map(|n| n.text()).map(str::trim).collect();
        assert!(words.contains(&"default") && words.contains(&"elderly"), "{plot} legend lacks a walk's name");
    }
    // summary.json stays the report's own walk, and so does the table against the norms.
    let json: serde_json::Value = serde_json::from_str(&read(&dir, "summary.json")).unwrap();
    assert!((json["speed_mps"].as_f64().unwrap() - 1.3).abs() < 0.01);
    assert!(md.contains("The table is for `default`, the report's own walk"), "{md}");
    // Seed 002's IK tables too: once, on the report's own walk's targets.
    assert_eq!(md.matches("**Seed 002's thresholds").count(), 1, "{md}");
    assert!(
        md.contains("in seed 002's form, on `default`'s targets") && md.contains("| analytic | left | 0.000 pass |")
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// `value @ pct` of an extremes cell.
fn at(cell: &str) -> (f64, f64) {
    let (v, p) = cell.split_once(" @ ").unwrap_or_else(|| panic!("not `value @ %`: {cell}"));
    (v.parse().unwrap(), p.parse().unwrap())
}

/// summary.md's "Against measured gait" reads as `gaitlab compare --json` for the same walk
/// (the same cycles: `--cycles` for the report, `sim.cycles` for compare), and summary.json's
/// `normative_*` keys, appended after the interface's, are its figures.
#[test]
fn the_summary_compares_the_walk_with_measured_gait_as_compare_does() {
    let dir = temp("normative");
    let out = gaitlab(&["report", "configs/brisk.toml", "--out", dir.to_str().unwrap(), "--cycles", "5"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let o = gaitlab(&["compare", "configs/brisk.toml", "--json", "--set", "sim.cycles=5"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let lines: Vec<serde_json::Value> =
        String::from_utf8_lossy(&o.stdout).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let md = read(&dir, "summary.md");
    let section = &md[md.find("\n## Against measured gait\n").expect("the section")..];
    let speed = lines[0]["speed_mps"].as_f64().unwrap();
    assert!(section.contains(&format!("`brisk` at {speed:.3} m/s against Fukuchi")), "{section}");
    // The joint-angle norms at the walk's own speed, between the two blocks around it.
    assert!(
        section.contains(&format!("at {speed:.3} m/s against Fukuchi, Fukuchi & Duarte 2018 (young adults, treadmill, by speed, CC BY 4.0), interpolated between the 1.593 and 1.799 m/s blocks,")),
        "the reference's speed: {section}"
    );
    assert!(!section.contains("The table is for"), "a lone walk needs no such note");
    // brisk (1.75 m/s) is faster than the fastest block of spatiotemporal norms: it says so.
    let norm = lines[0]["cadence_norm_spm"].as_f64().unwrap();
    assert!(section.contains(&format!("at the walk's {speed:.3} m/s (the 1.417 m/s block, the fastest")), "{section}");
    assert!(
        section.contains(&format!(
            "| cadence (steps/min) | {:.1} | {norm:.1} ± ",
            lines[0]["cadence_spm"].as_f64().unwrap()
        )),
        "{section}"
    );
    let num = |v: &serde_json::Value| v.as_f64().unwrap();
    let pair = |v: &serde_json::Value| (num(&v[0]), num(&v[1]));
    for l in &lines {
        let stem = l["curve"].as_str().unwrap();
        let row = section.lines().find(|r| r.contains(&format!("(`{stem}`)"))).unwrap_or_else(|| panic!("{stem}"));
        let cells: Vec<&str> = row.split('|').map(str::trim).filter(|c| !c.is_empty()).collect();
        assert_eq!(cells.len(), 10, "{row}");
        let figures = ["rms_deg", "pearson_r", "outside_1sd_pct", "outside_2sd_pct", "range_difference_deg"];
        for (cell, key) in cells[1..6].iter().zip(figures) {
            let ours: f64 = cell.parse().unwrap();
            assert!((ours - num(&l[key])).abs() <= 0.01, "{stem} {key}: {ours} against {}", l[key]);
        }
        let extremes = ["walk_max", "reference_max", "walk_min", "reference_min"];
        for (cell, key) in cells[6..].iter().zip(extremes) {
            let ((v, p), (cv, cp)) = (at(cell), pair(&l[key]));
            assert!((v - cv).abs() <= 0.01 && p == cp, "{stem} {key}: {cell} against {}", l[key]);
        }
    }
    // summary.json: the interface's keys first, in order, then the comparison's, the same
    // numbers as compare's (one measuring code, the same walk).
    let text = read(&dir, "summary.json");
    let position = |key: &str| text.find(&format!("\"{key}\":")).unwrap_or_else(|| panic!("{key} missing"));
    let keys: Vec<usize> = SUMMARY_KEYS.iter().map(|k| position(k)).collect();
    assert!(keys.windows(2).all(|w| w[0] < w[1]), "the interface's keys keep their order");
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    for (joint, stem) in [("hip", "hip_flex"), ("knee", "knee_flex"), ("ankle", "ankle_dorsi")] {
        let l = lines.iter().find(|l| l["curve"] == stem).unwrap();
        for (suffix, key) in [("rms_deg", "rms_deg"), ("r", "pearson_r")] {
            let name = format!("normative_{joint}_{suffix}");
            assert!(position(&name) > position("optimiser_fixed_rule_mean_cost"), "{name} is appended");
            assert!((num(&json[&name]) - num(&l[key])).abs() < 1e-9, "{name}: {} against {}", json[&name], l[key]);
        }
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn ik_solvers_are_measured_side_by_side_in_the_report() {
    let dir = temp("ik");
    let out = gaitlab(&[
        "report",
        "configs/stairs_up.toml",
        "--out",
        dir.to_str().unwrap(),
        "--cycles",
        "4",
        "--ik-solvers",
        "jacobian_dls,fabrik",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let ik = read(&dir, "ik.csv");
    assert_eq!(
        ik.lines().next().unwrap(),
        "frame,time_s,side,solver,position_error_mm,knee_direction_error_deg,iterations,reached,limit_excess_deg,knee_jump_mm,ankle_jump_mm"
    );
    let rows: Vec<Vec<&str>> = ik.lines().skip(1).map(|l| l.split(',').collect()).collect();
    let per_solver = |name: &str| rows.iter().filter(|r| r[3] == name).count();
    assert!(per_solver("jacobian_dls") > 300);
    assert_eq!(per_solver("jacobian_dls"), per_solver("fabrik"));
    assert_eq!(per_solver("jacobian_dls") + per_solver("fabrik"), rows.len());
    for r in &rows {
        let error_mm: f64 = r[4].parse().unwrap();
        assert!(error_mm <= 0.1 + 1e-9 && r[7] == "true", "{r:?}");
        assert!(r[6].parse::<u32>().unwrap() < 5000);
    }
    let md = read(&dir, "summary.md");
    assert!(md.contains("| jacobian_dls | ") && md.contains("| fabrik | "), "{md}");
    seed_002s_tables_match_ik_csv(&md, &rows);
    let svg = read(&dir, "plots/ik.svg");
    assert!(svg.contains("jacobian_dls") && svg.contains("fabrik") && svg.contains("error (mm)"));

    let out =
        gaitlab(&["report", "configs/default.toml", "--out", dir.to_str().unwrap(), "--ik-solvers", "ccd,newton"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("unknown solver `newton`") && err.contains("jacobian_dls"), "{err}");
}

/// Seed 002's tables in the IK section (issue 15, point 2): a row per solver and leg, whose
/// mean position error is the one of that solver's and leg's rows of ik.csv, judged against
/// 5 mm, every verdict a pass for these solvers at their 0.1 mm tolerance.
fn seed_002s_tables_match_ik_csv(md: &str, csv: &[Vec<&str>]) {
    let section = &md[md.find("## Leg IK").unwrap()..md.find("## Plots").unwrap()];
    for title in ["**Seed 002 tables 5.1-5.2", "**Seed 002 table 5.3", "**Seed 002's thresholds"] {
        assert!(section.contains(title), "{title} missing:\n{section}");
    }
    let verdicts = &section[section.find("**Seed 002's thresholds").unwrap()..];
    assert!(
        verdicts
            .contains("| solver | side | angle error max (deg) | jitter max (mm/frame) | error mean (mm) | overall |")
    );
    let rows: Vec<Vec<&str>> = verdicts
        .lines()
        .filter(|l| l.starts_with("| jacobian_dls |") || l.starts_with("| fabrik |"))
        .map(|l| l.trim_matches('|').split('|').map(str::trim).collect())
        .collect();
    assert_eq!(rows.len(), 4, "{verdicts}");
    for row in rows {
        let (solver, side) = (row[0], row[1]);
        let errors: Vec<f64> =
            csv.iter().filter(|r| r[3] == solver && r[2] == side).map(|r| r[4].parse().unwrap()).collect();
        let mean = errors.iter().sum::<f64>() / errors.len() as f64;
        let (shown, verdict) = row[4].split_once(' ').unwrap();
        assert!((shown.parse::<f64>().unwrap() - mean).abs() < 1e-4, "{row:?}: ik.csv says {mean}");
        assert_eq!(verdict, "pass", "{row:?}");
        let angle: f64 = row[2].split_once(' ').unwrap().0.parse().unwrap();
        assert!(angle > 0.0 && angle < 5.0 && row[2].ends_with("pass") && row[5] == "pass", "{row:?}");
    }
}

/// The least `--cycles` a report takes measures every shipped config (at 3, the third heel
/// strike fell past the last frame for 4 of them: long_stride, slope_down, slope_up, stroll).
#[test]
fn the_least_report_length_measures_every_shipped_config() {
    for entry in std::fs::read_dir("configs").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let params = gaitlab::config::load(&path, &[]).unwrap();
        let run = gaitlab::analysis::run(&params, 4.0, params.sim.fps).unwrap();
        let summary = gaitlab::report::metrics::summarise(&run);
        assert!(summary.is_ok(), "{}: {:?}", path.display(), summary.err());
    }
}

/// A scheduled walk's report plots its pace over time with the events marked and lists the
/// events in summary.md (issue 14, point 5); a walk without a schedule has neither.
#[test]
fn a_scheduled_walk_plots_its_pace_and_lists_its_events() {
    let dir = temp("pace");
    let out = gaitlab(&["report", "configs/pace.toml", "--out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let md = read(&dir, "summary.md");
    let pace = &md[md.find("## Pace").expect("a Pace section")..];
    // The events' table: the section's first, up to the blank line after it.
    let events: Vec<&str> = pace
        .lines()
        .skip_while(|l| !l.starts_with("| time"))
        .take_while(|l| l.starts_with('|'))
        .filter(|l| l.starts_with("| ") && !l.starts_with("| time"))
        .collect();
    let kinds: Vec<&str> = events.iter().map(|l| l.rsplit('|').nth(1).unwrap().trim()).collect();
    assert_eq!(
        kinds,
        [
            "1.60 m/s asked",
            "1.60 m/s reached",
            "1.00 m/s asked",
            "1.00 m/s reached",
            "stop asked",
            "braking",
            "closing",
            "standing"
        ],
        "{pace}"
    );
    let times: Vec<f64> = events.iter().map(|l| l.split('|').nth(1).unwrap().trim().parse().unwrap()).collect();
    assert!(times.windows(2).all(|w| w[0] <= w[1]), "{times:?}");
    assert!((times[0] - 4.0).abs() < 0.1 && (times[4] - 12.0).abs() < 0.1, "the schedule's times: {times:?}");
    let png = image::open(dir.join("plots/speed.png")).expect("plots/speed.png decodes");
    assert_eq!((png.width(), png.height()), (1600, 1000));
    let svg = read(&dir, "plots/speed.svg");
    let doc = roxmltree::Document::parse(&svg).expect("plots/speed.svg parses");
    let text: Vec<&str> = doc.descendants().filter_map(|n| n.text()).map(str::trim).collect();
    for wanted in ["time (s)", "speed (m/s)", "stop asked", "standing", "walked", "summary figures measured here"] {
        assert!(text.contains(&wanted), "{wanted} missing from speed.svg");
    }
    // Every event label sits above the walked line (they once printed across its ramps):
    // the label's bottom (its top plus a line of its font) over the line's highest point.
    let walked_top = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#C81E1E"))
        .filter_map(|n| n.attribute("points"))
        .max_by_key(|points| points.len())
        .expect("the walked line")
        .split_whitespace()
        .map(|xy| xy.split(',').nth(1).unwrap().parse::<f64>().unwrap())
        .fold(f64::INFINITY, f64::min);
    let events = ["asked", "reached", "braking", "closing", "standing"];
    let labels: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.text().is_some_and(|t| events.iter().any(|e| t.trim().ends_with(e))))
        .collect();
    assert!(labels.len() >= 7, "{} event labels", labels.len());
    for label in labels {
        let top: f64 = label.attribute("y").unwrap().parse().unwrap();
        let size: f64 = label.attribute("font-size").unwrap().parse().unwrap();
        assert!(
            top + 1.2 * size < walked_top,
            "{:?} at y {top} reaches the walked line's top {walked_top}",
            label.text()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);

    let plain = temp("no-pace");
    let out = gaitlab(&["report", "configs/default.toml", "--out", plain.to_str().unwrap()]);
    assert!(out.status.success());
    assert!(!plain.join("plots/speed.png").exists() && !read(&plain, "summary.md").contains("## Pace"));
    let _ = std::fs::remove_dir_all(&plain);
}

/// optimisation.svg says where the optimiser kept the fixed rule (the two cost lines are one
/// there), and a search that also moves the height marks its choice as lower than the
/// landscape, drawn on the landscape's axes rather than clipped onto the unreachable row.
#[test]
fn the_optimisation_plot_says_when_the_lines_coincide_and_when_the_choice_is_off_the_landscape() {
    let words = |config: &str, sets: &[&str], name: &str| {
        let dir = temp(name);
        let mut args = vec!["report", config, "--out", dir.to_str().unwrap(), "--cycles", "5"];
        for s in sets {
            args.extend(["--set", s]);
        }
        let out = gaitlab(&args);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        let svg = read(&dir, "plots/optimisation.svg");
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let words: Vec<String> = doc.descendants().filter_map(|n| n.text()).map(|t| t.trim().to_string()).collect();
        std::fs::remove_dir_all(dir).unwrap();
        words
    };
    // The shipped walk: the thesis search keeps the fixed rule on every costed step.
    let thesis = words("configs/default.toml", &[], "opt_thesis");
    assert!(thesis.iter().any(|w| w.starts_with("cost per step (fixed rule kept on all ")), "{thesis:?}");
    assert!(thesis.iter().any(|w| w == "chosen"), "{thesis:?}");
    // The joint search lowers the double support below the landscape's height: on stroll
    // with session 16's slow heel-rise design, 3.0 cm (with session 17's, which ends turning
    // faster, stroll's choice stays at the landscape's height, as the default's has since
    // session 15's swing designs, 6.3 % under the fixed rule at the feasible band's edge).
    let session16_heel_rise = "curves.heel_rise.points=[[0,0],[0.14,1.4],[0.28,3.59],[0.42,9.19],[0.506667,12.656667],[0.593333,16.716667],[0.68,26.25],[0.743333,33.216667],[0.806667,31.666667],[0.87,43.7],[0.913333,51.933333],[0.956667,76.033333],[1.0,83.4]]";
    let joint = words("configs/stroll.toml", &["optimiser.method=joint", session16_heel_rise], "opt_joint");
    assert!(joint.iter().any(|w| w == "cost per step"), "{joint:?}");
    let lower = joint.iter().find(|w| w.starts_with("chosen, ")).expect("the chosen point's label");
    let cm: f64 = lower.trim_start_matches("chosen, ").trim_end_matches(" cm lower").parse().unwrap();
    assert!(cm > 0.5, "{lower}");
}
