//! `gaitlab snapshot`: the project's own configs against their committed snapshots (through
//! the library, the one mechanism that checks the config corpus), and the command as a
//! user's CI runs it, through the binary in a temp folder of copied configs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn gaitlab(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab")).args(args).current_dir(dir).output().expect("the binary runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn shipped() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("configs")
}

/// A temp folder holding `configs/` with copies of the shipped configs (no snapshots).
fn copied(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-snapshot-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("configs")).unwrap();
    for entry in std::fs::read_dir(shipped()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|x| x == "toml") {
            std::fs::copy(&path, dir.join("configs").join(path.file_name().unwrap())).unwrap();
        }
    }
    dir
}

fn snapshots(dir: &Path) -> Vec<(String, String)> {
    let mut found: Vec<(String, String)> = std::fs::read_dir(dir.join("configs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_string_lossy().ends_with(".snap.json"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    found.sort();
    found
}

fn edit(path: &Path, from: &str, to: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains(from), "{} lacks `{from}`", path.display());
    std::fs::write(path, text.replacen(from, to, 1)).unwrap();
}

/// The corpus check: every shipped config matches its committed `configs/NAME.snap.json`
/// (regenerate with `gaitlab snapshot configs --update`, review the diff).
#[test]
fn every_shipped_config_matches_its_snapshot() {
    let outcomes = gaitlab::snapshot::run(&[shipped()], &gaitlab::snapshot::Options::default()).unwrap();
    assert!(outcomes.len() >= 11, "{} configs", outcomes.len());
    let failed: Vec<String> = outcomes
        .iter()
        .filter(|o| o.status != gaitlab::snapshot::Status::Ok)
        .map(|o| {
            let moved: Vec<String> = o.moved.iter().map(gaitlab::snapshot::junit::moved_line).collect();
            format!("{} {}: {}", o.config.display(), o.status.name(), moved.join("; "))
        })
        .collect();
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

#[test]
fn update_writes_stable_snapshots_and_a_second_run_passes() {
    let (a, b) = (copied("update-a"), copied("update-b"));
    let out = gaitlab(&a, &["snapshot", "configs"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(text(&out.stdout).lines().all(|l| l.starts_with("missing ")), "{}", text(&out.stdout));
    assert!(snapshots(&a).is_empty(), "nothing is written without --update");
    for dir in [&a, &b] {
        let out = gaitlab(dir, &["snapshot", "configs/", "--update"]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    }
    let (first, second) = (snapshots(&a), snapshots(&b));
    assert_eq!(first.len(), 13);
    assert_eq!(first, second, "snapshots differ between runs");
    for (name, body) in &first {
        assert!(!body.contains(&*a.to_string_lossy()) && !body.contains("/tmp"), "{name} holds a path");
        let json: serde_json::Value = serde_json::from_str(body).unwrap();
        assert_eq!(json["config"], name.replace(".snap.json", ".toml"));
        assert_eq!(json["curves"]["knee_flex_r_deg"].as_array().unwrap().len(), 51);
        assert!(json["summary"]["knee_flex_max_swing_deg"].as_f64().unwrap() > 40.0, "{name}");
    }
    let out = gaitlab(&a, &["snapshot", "configs", "--json"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let lines: Vec<serde_json::Value> =
        text(&out.stdout).lines().map(|l| serde_json::from_str(l).expect("a JSON line")).collect();
    assert_eq!(lines.len(), 13);
    assert!(lines.iter().all(|l| l["status"] == "ok" && l["moved"].as_array().unwrap().is_empty()));
    // A snapshot within tolerance is left as it is by --update.
    let out = gaitlab(&a, &["snapshot", "configs", "--update"]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(snapshots(&a), first);
    for dir in [a, b] {
        std::fs::remove_dir_all(dir).unwrap();
    }
}

#[test]
fn a_changed_config_drifts_alone_with_its_moved_figures_in_table_junit_json_and_plot() {
    let dir = copied("drift");
    assert_eq!(gaitlab(&dir, &["snapshot", "configs", "--update"]).status.code(), Some(0));
    edit(&dir.join("configs/default.toml"), "# heel_rise = 0.3  # derived", "heel_rise = 0.33");
    let out = gaitlab(&dir, &["snapshot", "configs", "--junit", "out/report.xml", "--plot", "plots"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for line in stdout.lines().take(13) {
        let drifted = line.starts_with("drift    configs/default.toml");
        assert!(drifted || line.starts_with("ok "), "{line}");
    }
    let rows: Vec<&str> = stdout.lines().skip(14).collect();
    assert!(rows[0].starts_with("config") && rows[0].ends_with("allowed"), "{stdout}");
    assert!(rows[1..].iter().all(|r| r.starts_with("configs/default.toml ")), "{stdout}");
    assert!(stdout.contains(" hip_ext_max_deg ") && stdout.contains(" knee_flex_r_deg at "), "{stdout}");
    assert!(text(&out.stderr).contains("1 of 13 configs failed: configs/default.toml (drift)"));

    let xml = std::fs::read_to_string(dir.join("out/report.xml")).unwrap();
    let doc = roxmltree::Document::parse(&xml).expect("JUnit XML parses");
    let suite = doc.root_element();
    assert_eq!(
        (suite.tag_name().name(), suite.attribute("tests"), suite.attribute("failures")),
        ("testsuite", Some("13"), Some("1"))
    );
    let failures: Vec<_> = doc.descendants().filter(|n| n.has_tag_name("failure")).collect();
    assert_eq!(failures.len(), 1);
    let case = failures[0].parent().unwrap();
    assert_eq!(case.attribute("name"), Some("configs/default.toml"));
    assert!(failures[0].text().unwrap().contains("hip_ext_max_deg: "), "{xml}");

    let png = image::open(dir.join("plots/default.png")).expect("the plot decodes");
    assert_eq!((png.width(), png.height()), (1600, 1000));
    assert_eq!(std::fs::read_dir(dir.join("plots")).unwrap().count(), 1, "one plot, for the drifted config");

    let out = gaitlab(&dir, &["snapshot", "configs", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let lines: Vec<serde_json::Value> =
        text(&out.stdout).lines().map(|l| serde_json::from_str(l).expect("a JSON line")).collect();
    let drifted: Vec<&serde_json::Value> = lines.iter().filter(|l| l["status"] != "ok").collect();
    assert_eq!(drifted.len(), 1);
    assert_eq!((&drifted[0]["config"], &drifted[0]["status"]), (&"configs/default.toml".into(), &"drift".into()));
    let moved = drifted[0]["moved"].as_array().unwrap();
    assert!(moved.iter().any(|m| m["metric"] == "hip_ext_max_deg" && m["allowed"] == 0.05), "{moved:?}");

    // A looser tolerance for what moved lets it pass; --update accepts the rest. (The later
    // heel rise also lowers the mid-stance key 2.3 mm, the stance leg reaching until its heel
    // rises: before the reach guard saw that far, this walk lost reach 17 times and slid
    // 0.84 mm.)
    let lenient = "[tolerance]\nangles_deg = 12\nlengths_mm = 5\nlengths_cm = 1\ncounts = 30\ncosts_relative = 1.5\n";
    std::fs::write(dir.join("lenient.toml"), lenient).unwrap();
    let out = gaitlab(&dir, &["snapshot", "configs/default.toml", "--tolerance", "lenient.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}{}", text(&out.stdout), text(&out.stderr));
    let out = gaitlab(&dir, &["snapshot", "configs", "--update"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(text(&out.stdout).contains("updated  configs/default.toml  rewrote configs/default.snap.json"));
    assert_eq!(gaitlab(&dir, &["snapshot", "configs"]).status.code(), Some(0));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_change_below_tolerance_passes_and_a_missing_snapshot_fails() {
    let dir = copied("below");
    assert_eq!(gaitlab(&dir, &["snapshot", "configs", "--update"]).status.code(), Some(0));
    edit(&dir.join("configs/default.toml"), "speed_mps = 1.3\n", "speed_mps = 1.300000001\n");
    let out = gaitlab(&dir, &["snapshot", "configs"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));

    std::fs::copy(dir.join("configs/default.toml"), dir.join("configs/mine.toml")).unwrap();
    // Neither a recovery file nor a snapshot is a config.
    std::fs::write(dir.join("configs/mine.toml.recovery"), "not a config").unwrap();
    let out = gaitlab(&dir, &["snapshot", "configs"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("missing  configs/mine.toml  no configs/mine.snap.json"), "{stdout}");
    assert_eq!(stdout.lines().filter(|l| l.starts_with("ok ")).count(), 13, "{stdout}");
    let out = gaitlab(&dir, &["snapshot", "configs/mine.toml", "--json"]);
    let line: serde_json::Value = serde_json::from_str(text(&out.stdout).trim()).unwrap();
    assert_eq!(line["status"], "missing");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn bad_input_exits_2_and_names_the_place() {
    let dir = copied("bad");
    assert_eq!(gaitlab(&dir, &["snapshot", "configs", "--update"]).status.code(), Some(0));
    let before = snapshots(&dir);
    std::fs::write(dir.join("configs/zz_bad.toml"), "[walk]\nsped_mps = 1.2\n").unwrap();
    let out = gaitlab(&dir, &["snapshot", "configs", "--update"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).starts_with("configs/zz_bad.toml:2:1: walk.sped_mps: unknown key"),
        "{}",
        text(&out.stderr)
    );
    assert_eq!(snapshots(&dir), before, "nothing written when a config is bad");
    std::fs::remove_file(dir.join("configs/zz_bad.toml")).unwrap();

    let out = gaitlab(&dir, &["snapshot", "configs/nowhere.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("configs/nowhere.toml"), "{}", text(&out.stderr));

    std::fs::write(dir.join("tol.toml"), "[tolerance]\nangles_deg = 0.1\nkne_flex_max_swing_deg = 1\n").unwrap();
    let out = gaitlab(&dir, &["snapshot", "configs", "--tolerance", "tol.toml"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(stderr.starts_with("tol.toml:3:1: tolerance.kne_flex_max_swing_deg: unknown key"), "{stderr}");
    assert!(stderr.contains("did you mean `knee_flex_max_swing_deg`?"), "{stderr}");

    std::fs::write(dir.join("configs/default.snap.json"), "{ \"gaitlab_snapshot\": 1,\n  broken").unwrap();
    let out = gaitlab(&dir, &["snapshot", "configs"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("configs/default.snap.json:2:3: not JSON"), "{}", text(&out.stderr));
    std::fs::remove_dir_all(dir).unwrap();
}
