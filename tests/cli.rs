//! The `gaitlab` binary as scripts use it: exit codes, messages, files.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn gaitlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab")).args(args).output().expect("the binary runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-test-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn every_bad_config_exits_2_and_names_the_place() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_configs");
    let mut seen = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let body = std::fs::read_to_string(&path).unwrap();
        let expect = body
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("# expect: "))
            .expect("first line states the expected message");
        // "PLACE: KEY: MESSAGE", "PLACE: KEY needs ..." (a value's problem), or, where no
        // key is to blame, "PLACE: : MESSAGE".
        let (place, rest) = expect.split_once(": ").unwrap();
        let rest = rest.strip_prefix(": ").unwrap_or(rest);
        let shown = path.display().to_string();
        let out = gaitlab(&["check", &shown]);
        let stderr = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{shown}: {stderr}");
        assert!(!stderr.contains("panicked"), "{shown}: {stderr}");
        let wanted = format!("{shown}:{place}: {rest}");
        assert!(stderr.contains(&wanted), "{shown}:\n  wanted {wanted}\n  got    {stderr}");
        assert!(text(&out.stdout).is_empty(), "{shown}: nothing on stdout for a bad config");
        seen += 1;
    }
    assert!(seen >= 15, "only {seen} bad configs");
}

#[test]
fn check_accepts_every_shipped_config() {
    let mut args = vec!["check".to_string()];
    // The configs, not their snapshots (`NAME.snap.json`, checked by tests/snapshot.rs).
    for entry in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("configs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|x| x == "toml") {
            args.push(path.display().to_string());
        }
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = gaitlab(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout).lines().filter(|l| l.starts_with("ok: ")).count(), args.len() - 1);
}

/// A bad value is told in the key's terms, at its place: the key, the kind of value it needs
/// with its range and unit, and what it got (the lab's editor says the same: tests/tui.rs).
/// It used to read "expected a number, found ...; valid: ..." or, for a typo, the TOML
/// parser's "value is not TOML: invalid float, expected nothing".
#[test]
fn a_bad_value_says_what_its_key_needs() {
    let speed = "walk.speed_mps needs a number from 0.4 to 2 m/s";
    for (value, wanted) in [
        ("abc", format!("--set #1:1:16: {speed}, not \"abc\"")),
        ("1.39abc", format!("--set #1:1:16: {speed}, not 1.39abc")),
        ("", format!("--set #1:1:16: {speed}")),
        ("nan", format!("--set #1:1:16: {speed}, not nan")),
    ] {
        let out = gaitlab(&["check", "configs/default.toml", "--set", &format!("walk.speed_mps={value}")]);
        assert_eq!(out.status.code(), Some(2));
        assert_eq!(text(&out.stderr).trim_end(), wanted);
    }
    let out = gaitlab(&["check", "configs/default.toml", "--set", "terrain.kind=stair"]);
    assert_eq!(
        text(&out.stderr).trim_end(),
        "--set #1:1:14: terrain.kind needs one of \"flat\", \"stairs\", \"slope\", \"random\", not \"stair\" (did you mean \"stairs\"?)"
    );
    let dir = temp_dir("needs");
    let path = dir.join("a.toml");
    std::fs::write(&path, "[walk]\nspeed_mps = \"fast\"\n\n[sim]\ncycles = 2.5\n").unwrap();
    let out = gaitlab(&["check", path.to_str().unwrap()]);
    let shown = path.display();
    assert_eq!(
        text(&out.stderr).trim_end(),
        format!(
            "{shown}:2:13: {speed}, not \"fast\"\n{shown}:5:10: sim.cycles needs a whole number from 1 to 100000, not 2.5"
        )
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn check_reports_bad_set_and_missing_file() {
    let out = gaitlab(&["check", "configs/default.toml", "--set", "walk.speed_mps=3"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("--set #1:1:16: walk.speed_mps needs a number from 0.4 to 2 m/s, not 3"),
        "{}",
        text(&out.stderr)
    );
    let out = gaitlab(&["check", "no/such/file.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("no/such/file.toml:1:1: cannot read the config"), "{}", text(&out.stderr));
    let out = gaitlab(&["simulate", "configs/default.toml", "--fps", "nine"]);
    assert_eq!(out.status.code(), Some(2), "usage errors exit 2");
}

#[test]
fn simulate_writes_the_interface_columns_identically_every_run() {
    let dir = temp_dir("simulate");
    let a = dir.join("a.csv");
    let b = dir.join("b.csv");
    for out in [&a, &b] {
        let o = gaitlab(&[
            "simulate",
            "configs/rough.toml",
            "--cycles",
            "3",
            "--fps",
            "50",
            "--out",
            &out.display().to_string(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    }
    let (x, y) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    assert_eq!(x, y, "same config, same bytes");
    let csv = text(&x);
    let mut lines = csv.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with(
        "frame,time_s,phase_r,phase_l,support,pelvis_x,pelvis_y,pelvis_z,pelvis_tilt_deg,pelvis_obliquity_deg,pelvis_rotation_deg,hip_flex_r_deg,hip_abd_r_deg,knee_flex_r_deg,ankle_dorsi_r_deg,hip_flex_l_deg,hip_abd_l_deg,knee_flex_l_deg,ankle_dorsi_l_deg,heel_r_x,heel_r_y,heel_r_z,toe_r_x,toe_r_y,toe_r_z,heel_l_x,heel_l_y,heel_l_z,toe_l_x,toe_l_y,toe_l_z,shoulder_flex_r_deg,elbow_flex_r_deg,shoulder_flex_l_deg,elbow_flex_l_deg,terrain_y_under_heel_r,terrain_y_under_heel_l"
    ));
    let rows: Vec<&str> = lines.collect();
    // 3 cycles at 50 fps plus the start frame (the default's derived cadence, 119.0874).
    let cycle_s: f64 = 120.0 / 119.0874;
    assert_eq!(rows.len(), (3.0 * cycle_s * 50.0_f64).round() as usize + 1);
    for row in &rows {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells.len(), 37);
        assert!(["double", "right", "left"].contains(&cells[4]), "{row}");
        for c in cells.iter().enumerate().filter(|(i, _)| *i != 4).map(|(_, c)| c) {
            let v: f64 = c.parse().unwrap_or_else(|_| panic!("{c} in {row}"));
            assert!(v.is_finite());
        }
    }
    // Stdout gives the same bytes.
    let o = gaitlab(&["simulate", "configs/rough.toml", "--cycles", "3", "--fps", "50"]);
    assert_eq!(o.stdout, x);
    // No temporary files are left beside the output.
    let names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn simulate_into_an_unwritable_place_fails_with_1_and_leaves_nothing() {
    // Missing parents are created (tests/outputs.rs); a folder nobody may create, root
    // included, is a failure while running.
    let target = std::path::Path::new("/proc/gaitlab-no-such-folder/walk.csv");
    let o = gaitlab(&["simulate", "configs/default.toml", "--cycles", "1", "--out", &target.display().to_string()]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    assert!(text(&o.stderr).contains("cannot create the folder /proc/gaitlab-no-such-folder"), "{}", text(&o.stderr));
    assert!(!target.exists());
}

#[test]
fn init_prints_the_default_config_and_presets_match_the_configs_folder() {
    let out = gaitlab(&["init"]);
    assert_eq!(out.status.code(), Some(0));
    let default = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml")).unwrap();
    let printed = text(&out.stdout);
    if let Some((n, (a, b))) = printed.lines().zip(default.lines()).enumerate().find(|(_, (a, b))| a != b) {
        panic!(
            "configs/default.toml differs from `gaitlab init` at line {}:\n  init: {a}\n  file: {b}\nregenerate it",
            n + 1
        );
    }
    assert_eq!(printed, default, "configs/default.toml is `gaitlab init`'s output; regenerate it");
    // Every preset's init output is itself a valid config giving the same walk parameters.
    let listed = text(&gaitlab(&["presets"]).stdout);
    let names: Vec<&str> = listed.lines().map(|l| l.split_whitespace().next().unwrap()).collect();
    let mut files: Vec<String> = std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("configs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    files.sort();
    let mut sorted = names.clone();
    sorted.sort();
    assert_eq!(sorted, files, "every config in configs/ is a preset and every preset a config");
    for name in names {
        let out = gaitlab(&["init", "--preset", name]);
        assert_eq!(out.status.code(), Some(0));
        let rendered = gaitlab::config::parse_str(&text(&out.stdout), "init").unwrap();
        let original = gaitlab::config::presets::params(name).unwrap().unwrap();
        assert_eq!(rendered.resolve(), original.resolve(), "{name}");
    }
    let out = gaitlab(&["init", "--preset", "eldery"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("did you mean `elderly`?"));
}

fn config_path(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("configs").join(format!("{name}.toml")).display().to_string()
}

#[test]
fn optimise_prints_a_line_per_step_and_the_summed_costs() {
    // Downhill, where the choice beats the fixed rule by 7 %; on level ground, with the
    // double support as high as the legs reach, only the fixed rule is inside reach and the
    // push-off allowances, and it is kept (see issue 12's notes).
    let out = gaitlab(&["optimise", &config_path("slope_down"), "--steps", "6"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let lines: Vec<&str> = stdout.lines().filter(|l| !l.starts_with('#')).collect();
    assert!(lines[0].split_whitespace().eq([
        "step",
        "side",
        "phase",
        "evals",
        "feas",
        "x_m",
        "ratio",
        "y_m",
        "cost",
        "fixed_cost",
        "time_us",
        "note"
    ]));
    assert_eq!(lines.len(), 1 + 6 + 1, "{stdout}");
    for (i, row) in lines[1..7].iter().enumerate() {
        let cols: Vec<&str> = row.split_whitespace().collect();
        assert_eq!(cols[0], (i + 1).to_string());
        assert!(cols[1] == "l" || cols[1] == "r");
        let cost: f64 = cols[8].parse().unwrap();
        let fixed: f64 = cols[9].parse().unwrap();
        assert!(cost > 0.0 && cost <= fixed, "{row}");
        assert!(cols[4].parse::<u32>().unwrap() >= 1);
    }
    let total = lines[7];
    assert!(total.starts_with("total 6 steps: cost ") && total.contains("fixed rule (-"), "{total}");
    assert!(total.contains("0 steps without a feasible candidate"), "{total}");
}

#[test]
fn optimise_json_lines_carry_every_candidate_and_a_summary() {
    let out = gaitlab(&[
        "optimise",
        &config_path("stairs_down"),
        "--steps",
        "4",
        "--json",
        "--set",
        "optimiser.method=\"brent\"",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let values: Vec<serde_json::Value> =
        text(&out.stdout).lines().map(|l| serde_json::from_str(l).expect("each line is JSON")).collect();
    assert_eq!(values.len(), 5);
    for (i, v) in values[..4].iter().enumerate() {
        assert_eq!(v["step"], i as i64 + 1);
        assert_eq!(v["method"], "brent");
        let candidates = v["candidates"].as_array().unwrap();
        assert_eq!(candidates.len() as u64, v["evaluations"].as_u64().unwrap());
        let best = candidates.iter().filter_map(|c| c["cost"].as_f64()).fold(f64::INFINITY, f64::min);
        assert_eq!(v["chosen"]["cost"].as_f64().unwrap(), best);
        assert!(v["fixed_rule"]["cost"].as_f64().unwrap() >= best);
    }
    let summary = &values[4]["summary"];
    assert_eq!(summary["steps"], 4);
    assert_eq!(summary["infeasible_steps"], 0);
    assert!(summary["cost_chosen"].as_f64().unwrap() <= summary["cost_fixed_rule"].as_f64().unwrap());
}

#[test]
fn optimise_with_the_optimiser_off_and_with_bad_input() {
    let out = gaitlab(&["optimise", &config_path("default"), "--steps", "3", "--set", "optimiser.enabled=false"]);
    assert_eq!(out.status.code(), Some(0));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("method off (fixed rule)"));
    assert_eq!(stdout.matches("optimiser off").count(), 3, "{stdout}");
    assert!(stdout.contains("(+0.0%)"), "{stdout}");

    let out = gaitlab(&["optimise", &config_path("default"), "--set", "optimiser.method=\"newton\""]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("optimiser.method") && stderr.contains("thesis"), "{stderr}");
    assert!(out.stdout.is_empty());

    let out = gaitlab(&["optimise", &config_path("default"), "--steps", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("valid: 1 to 100000"));

    let out = gaitlab(&["optimise", "no/such/config.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("no/such/config.toml"));
}

#[test]
fn ik_prints_a_table_per_solver_and_json_lines_and_names_bad_solvers() {
    let out = gaitlab(&["ik", &config_path("default"), "--cycles", "1", "--solvers", "analytic,jacobian_dls,fabrik"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let table = text(&out.stdout);
    for part in [
        "analytic: exact",
        "jacobian_dls: dls (damping 0.02 m)",
        "fabrik: tolerance 0.100 mm",
        "position error (mm)",
        "knee direction error (deg)",
        "iterations",
        "time per solve (us)",
        "joint-limit violations",
        "knee jump (mm)",
        "ankle jump (mm)",
        "worst at frame",
    ] {
        assert!(table.contains(part), "{part} missing:\n{table}");
    }
    assert!(!table.contains("ccd:") && !table.contains("gradient:"), "only the solvers asked for:\n{table}");
    // The side-by-side lines: every target reached by each solver.
    let solves: Vec<&str> =
        table.lines().filter(|l| l.starts_with("jacobian_dls ") || l.starts_with("fabrik ")).collect();
    assert_eq!(solves.len(), 2, "{table}");
    for line in solves {
        let reached = line.split_whitespace().nth(1).unwrap();
        let (a, b) = reached.split_once('/').unwrap();
        assert_eq!(a, b, "{line}");
    }

    let out = gaitlab(&[
        "ik",
        &config_path("stairs_down"),
        "--cycles",
        "1",
        "--json",
        "--solvers",
        "ccd",
        "--set",
        "ik.limits=false",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let lines: Vec<serde_json::Value> = text(&out.stdout).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 1);
    assert_eq!(lines[0]["solver"], "ccd");
    assert_eq!(lines[0]["reached"], lines[0]["solves"]);
    assert!(lines[0]["position_error_max_mm"].as_f64().unwrap() <= 0.1 + 1e-9);
    assert!(lines[0]["knee_direction_error_max_deg"].as_f64().unwrap() < 1.0);

    let out = gaitlab(&["ik", &config_path("default"), "--solvers", "ccd,newton"]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(
        err.contains("unknown solver `newton`") && err.contains("analytic, ccd, fabrik, jacobian_dls, gradient"),
        "{err}"
    );
    let out = gaitlab(&["ik", &config_path("default"), "--cycles", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("valid: 1 to 10000"));
    let out = gaitlab(&["ik", &config_path("default"), "--set", "ik.solver=\"newton\""]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("ik.solver"), "{}", text(&out.stderr));
}

/// Seed 002's tables (issue 15, point 2) after the side-by-side lines, and in the JSON after
/// every field scripts already read.
#[test]
fn ik_adds_seed_002s_tables_per_side_with_a_starved_solver_failing() {
    let args =
        ["ik", &config_path("default"), "--cycles", "1", "--solvers", "analytic,ccd", "--set", "ik.tolerance_mm=10"];
    let out = gaitlab(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let table = text(&out.stdout);
    let side_by_side = table.find("solver            reached").expect("the side-by-side table");
    let verdicts = table.find("Seed 002's thresholds").expect("the verdict table");
    assert!(side_by_side < table.find("Seed 002 tables 5.1-5.2").unwrap(), "{table}");
    assert!(table.find("Seed 002 table 5.3").unwrap() < verdicts, "{table}");
    // solver, side, angle error, jitter, position error mean (value and verdict each), overall.
    let rows: Vec<Vec<&str>> = table[verdicts..].lines().skip(2).map(|l| l.split_whitespace().collect()).collect();
    // Indented, so that a script's `^ccd ` still finds only the side-by-side line.
    assert_eq!(table.lines().filter(|l| l.starts_with("ccd ")).count(), 1, "{table}");
    assert_eq!(rows.len(), 4, "{table}");
    for (row, (solver, side)) in
        rows.iter().zip([("analytic", "right"), ("analytic", "left"), ("ccd", "right"), ("ccd", "left")])
    {
        assert_eq!((row[0], row[1], row.len()), (solver, side, 9), "{table}");
        let mean_mm: f64 = row[6].parse().unwrap();
        if solver == "analytic" {
            assert_eq!((row[2], row[4], row[6]), ("0.000", "0.0000", "0.0000"), "{table}");
            assert_eq!([row[3], row[5], row[7], row[8]], ["pass"; 4], "{table}");
        } else {
            // A 10 mm tolerance lets CCD stop as soon as it is within it: > 5 mm on average.
            assert!(mean_mm > 5.0 && mean_mm <= 10.0, "{table}");
            assert_eq!((row[7], row[8]), ("fail", "fail"), "{table}");
        }
    }

    let json_args = [&args[..], &["--json"]].concat();
    let out = gaitlab(&json_args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for line in stdout.lines() {
        // The old fields first, in their old order; the new one last.
        assert!(line.starts_with("{\"ankle_jump_max_frame\":"), "{line}");
        let time = line.find("\"time_per_solve_us\":").unwrap();
        assert!(line[time..].contains(",\"seed002\":{\"right\":{\"solves\":"), "{line}");
    }
    let lines: Vec<serde_json::Value> = stdout.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let (analytic, ccd) = (&lines[0]["seed002"], &lines[1]["seed002"]);
    for side in ["right", "left"] {
        let a = &analytic[side];
        for axis in ["hip_flexion", "hip_abduction", "hip_rotation", "knee_flexion"] {
            assert_eq!(a["angle_error_max_deg"][axis].as_f64(), Some(0.0), "{a}");
            assert_eq!(a["angle_error_mean_deg"][axis].as_f64(), Some(0.0), "{a}");
        }
        assert_eq!((a["knee_jitter_max_mm"].as_f64(), a["ankle_jitter_max_mm"].as_f64()), (Some(0.0), Some(0.0)));
        assert!(a["ankle_jump_max_mm"].as_f64().unwrap() > 10.0, "{a}");
        assert_eq!(a["pass"], true, "{a}");
        let c = &ccd[side];
        assert!(c["position_error_mean_mm"].as_f64().unwrap() > 5.0, "{c}");
        assert_eq!((c["position_pass"].as_bool(), c["pass"].as_bool()), (Some(false), Some(false)), "{c}");
    }
    let solves = |v: &serde_json::Value| v["right"]["solves"].as_u64().unwrap() + v["left"]["solves"].as_u64().unwrap();
    assert_eq!(Some(solves(ccd)), lines[1]["solves"].as_u64());
}

/// Run lengths at the extremes are refused with the valid range, before any work.
#[test]
fn run_lengths_at_the_extremes_are_refused_with_the_range() {
    let cases: &[(&[&str], &str)] = &[
        (&["simulate", "--cycles", "0"], "valid: 1 to 100000"),
        (&["simulate", "--cycles", "1000000000"], "valid: 1 to 100000"),
        (&["simulate", "--cycles=-1"], "invalid value '-1'"),
        (&["simulate", "--fps", "0"], "valid: 10 to 1000"),
        (&["simulate", "--fps", "nan"], "valid: 10 to 1000"),
        (&["optimise", "--steps", "0"], "valid: 1 to 100000"),
        (&["optimise", "--steps", "1000000000"], "valid: 1 to 100000"),
        (&["optimise", "--steps=-5"], "invalid value '-5'"),
        (&["report", "--cycles", "3"], "valid: 4 to 1000"),
        (&["report", "--cycles", "1000000000"], "valid: 4 to 1000"),
        (&["ik", "--cycles", "0"], "valid: 1 to 10000"),
        (&["ik", "--cycles", "4294967296"], "invalid value '4294967296'"),
    ];
    for (args, expected) in cases {
        let mut full = vec![args[0], "configs/default.toml"];
        full.extend_from_slice(&args[1..]);
        let started = std::time::Instant::now();
        let o = gaitlab(&full);
        assert_eq!(o.status.code(), Some(2), "{full:?}: {}", text(&o.stderr));
        assert!(text(&o.stderr).contains(expected), "{full:?}: {}", text(&o.stderr));
        assert!(started.elapsed().as_secs() < 5, "{full:?} was not refused at once");
    }
}

/// A long simulate streams its rows and trims the walk's history: its peak memory does not
/// grow with the run's length (before the trimming it grew ~2.6 KB a cycle).
#[test]
#[expect(clippy::zombie_processes, reason = "wait4 reaps the child, which Child::wait cannot do with its rusage")]
fn a_long_simulate_keeps_its_memory_flat() {
    let peak_kb = |cycles: &str| -> i64 {
        let child = std::process::Command::new(env!("CARGO_BIN_EXE_gaitlab"))
            .args(["simulate", "configs/default.toml", "--cycles", cycles, "--out", "/dev/null"])
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .spawn()
            .unwrap();
        let mut status = 0;
        // SAFETY: a zeroed rusage is valid; wait4 fills it for this child only.
        let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
        let pid = unsafe { libc::wait4(child.id() as libc::pid_t, &mut status, 0, &mut usage) };
        assert_eq!(pid, child.id() as libc::pid_t);
        assert_eq!(status, 0, "simulate --cycles {cycles} failed");
        usage.ru_maxrss
    };
    let short = peak_kb("60");
    let long = peak_kb("1500");
    assert!(long < short + 1500, "peak {short} KB at 60 cycles, {long} KB at 1500");
}

/// A config from a pipe is read once: `gaitlab report <(cat CONFIG)` writes that config's
/// text into config.toml (it used to read the pipe twice and write an empty one).
#[test]
fn a_config_from_a_pipe_is_read_once() {
    let dir = temp_dir("pipe-config");
    let out = dir.join("r");
    let script = format!(
        "exec {} report <(cat configs/default.toml) --cycles 4 --out {}",
        env!("CARGO_BIN_EXE_gaitlab"),
        out.display()
    );
    let o = std::process::Command::new("bash")
        .args(["-c", &script])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o.stderr));
    let written = std::fs::read_to_string(out.join("config.toml")).unwrap();
    assert_eq!(written, std::fs::read_to_string("configs/default.toml").unwrap());
}

/// Inputs that never end are refused quickly with the size limit, by every command.
#[test]
fn endless_inputs_as_a_config_are_refused_at_once() {
    for command in ["check", "simulate", "report", "optimise", "ik"] {
        let started = std::time::Instant::now();
        let o = gaitlab(&[command, "/dev/zero"]);
        assert_eq!(o.status.code(), Some(2), "{command}: {}", text(&o.stderr));
        assert!(
            text(&o.stderr).contains("/dev/zero") && text(&o.stderr).contains("1 MiB"),
            "{command}: {}",
            text(&o.stderr)
        );
        assert!(started.elapsed().as_secs_f64() < 2.0, "{command} took {:?}", started.elapsed());
    }
}

/// `check` validates `[keys]` exactly as the lab does: the same refusals, the same lines.
#[test]
fn check_and_the_lab_agree_on_key_bindings() {
    let dir = temp_dir("check-keys");
    let cases = [
        ("[keys]\nquit = \"Q\"\npause = [\"p\", \"ctrl+space\"]\n", true),
        ("[keys]\npuase = \"p\"\n", false),
        ("[keys]\nquit = \"ctrl+\"\n", false),
        ("[keys]\nquit = 5\n", false),
        ("keys = 3\n", false),
        ("[keys]\ntoggle_norms = [\"N\", \"ctrl+n\"]\n", true),
        ("[keys]\ntoggle_norms = \"shift+\"\n", false),
        ("[keys]\ntoggle_norm = \"N\"\n", false),
    ];
    for (i, (text, valid)) in cases.iter().enumerate() {
        let path = dir.join(format!("k{i}.toml"));
        std::fs::write(&path, text).unwrap();
        let o = gaitlab(&["check", path.to_str().unwrap()]);
        let lab = gaitlab::tui::load_app(Some(&path), &[]);
        assert_eq!(o.status.success(), *valid, "{text}: {}", text_of(&o.stderr));
        assert_eq!(lab.is_ok(), *valid, "{text}");
        if let Err(e) = lab {
            assert_eq!(text_of(&o.stderr).trim_end(), e.to_string(), "{text}: the same message");
            if text.contains("toggle_norm") {
                let named =
                    if text.contains("toggle_norms") { "keys.toggle_norms" } else { "did you mean `toggle_norms`" };
                assert!(e.to_string().contains(named), "{text}: {e}");
            }
        }
    }
}

fn text_of(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn options_before_the_command_reach_it_or_are_refused_by_name() {
    let config = config_path("default");
    // A leading --set walks the command at that speed: the same bytes as the --set after it.
    let leading = gaitlab(&["--set", "walk.speed_mps=0.8", "simulate", &config, "--cycles", "4"]);
    let trailing = gaitlab(&["simulate", &config, "--cycles", "4", "--set", "walk.speed_mps=0.8"]);
    let plain = gaitlab(&["simulate", &config, "--cycles", "4"]);
    assert_eq!(leading.status.code(), Some(0), "{}", text(&leading.stderr));
    assert_eq!(leading.stdout, trailing.stdout);
    assert_ne!(leading.stdout, plain.stdout, "the leading --set was dropped");
    // Both given: the command's own comes later and wins.
    let both =
        gaitlab(&["--set", "walk.speed_mps=1.0", "simulate", &config, "--cycles", "4", "--set", "walk.speed_mps=0.8"]);
    assert_eq!(both.stdout, trailing.stdout);
    // A bad leading value is located like any --set.
    let bad = gaitlab(&["--set", "walk.speed_mps=9", "compare", &config]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(
        text(&bad.stderr).contains("walk.speed_mps needs a number from 0.4 to 2 m/s, not 9"),
        "{}",
        text(&bad.stderr)
    );
    // The lab's own options and config mean nothing to another command: refused, not dropped.
    for (args, says) in [
        (
            vec!["--fps", "10", "simulate", &config],
            "--fps before the command is the lab's option, not read by `simulate`",
        ),
        // The default's own value, written, is written: not dropped without a word.
        (vec!["--fps", "30", "ik", &config], "--fps before the command is the lab's option, not read by `ik`"),
        (vec!["--marker", "braille", "compare", &config], "--marker before the command is the lab's option"),
        (vec![&config, "tui", &config], "two configs for the lab"),
        (
            vec!["--no-mouse", "compare", &config],
            "--no-mouse before the command is the lab's option, not read by `compare`",
        ),
        (vec![&config, "simulate", &config], "before the command is the lab's config, not read by `simulate`"),
        (vec!["--set", "walk.sway=0", "init"], "`init` takes no --set"),
    ] {
        let out = gaitlab(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(text(&out.stderr).contains(says), "{args:?}: {}", text(&out.stderr));
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}
