//! `gaitlab figures`: the seed thesis's figures and table 6.1 regenerated. Every file is
//! written and readable (PNGs decode at 1600x1000, SVGs parse, with axis labels in units and
//! the thesis figure named), the figures show what the thesis's show (measured from their
//! CSVs), table 6.1's parts add up to the frame, bad input exits 2, and everything but the
//! timing table is the same on a second run.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

const FIGURES: [&str; 5] =
    ["fig_6_2_terrain", "fig_6_6_swing_foot", "fig_6_8_ankle", "fig_6_15_pelvis_progress", "fig_6_17_arms"];

fn gaitlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab")).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-figures-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// A folder's files by name.
type Files = BTreeMap<String, Vec<u8>>;

/// Every file of a folder by name.
fn files(dir: &Path) -> Files {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read(&p).unwrap()))
        .collect()
}

/// The embedded default's figures, made twice into the same folder (the second run replaces
/// the first's): both runs' files.
fn made() -> &'static (Files, Files) {
    static MADE: OnceLock<(Files, Files)> = OnceLock::new();
    MADE.get_or_init(|| {
        let dir = temp("default");
        let run = || {
            let o = gaitlab(&["figures", "--out", dir.to_str().unwrap()]);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), dir.to_str().unwrap());
            assert!(o.stderr.is_empty(), "no progress without a terminal: {}", String::from_utf8_lossy(&o.stderr));
            files(&dir)
        };
        let first = run();
        let second = run();
        std::fs::remove_dir_all(&dir).unwrap();
        (first, second)
    })
}

fn text(name: &str) -> String {
    String::from_utf8(made().0[name].clone()).unwrap()
}

/// A CSV's column `name` as numbers (rows where it is empty left out), keeping rows whose
/// first column is `walk` when given.
fn column(csv: &str, name: &str, walk: Option<&str>) -> Vec<f64> {
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = head.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name} in {head:?}"));
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|row| walk.is_none_or(|w| row[0] == w))
        .filter_map(|row| row[k].parse().ok())
        .collect()
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
}

fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

#[test]
fn every_file_is_written_and_readable() {
    let (first, _) = made();
    let mut expected: Vec<String> = vec!["figures.md".into(), "table_6_1.md".into()];
    for f in FIGURES {
        expected.extend(["png", "svg", "csv"].map(|e| format!("{f}.{e}")));
    }
    expected.sort();
    assert_eq!(first.keys().cloned().collect::<Vec<_>>(), expected);
    let units: [(&str, &[&str]); 5] = [
        ("fig_6_2_terrain", &["distance along the walk (m)", "height (cm)"]),
        ("fig_6_6_swing_foot", &["% of swing", "heel forward of toe-off (m)", "heel above toe-off ground (cm)"]),
        ("fig_6_8_ankle", &["% of gait cycle", "dorsiflexion + (deg)", "Fukuchi 2018"]),
        ("fig_6_15_pelvis_progress", &["time from a right heel strike (s)", "pelvis forward (m)", "(cm)"]),
        ("fig_6_17_arms", &["% of gait cycle", "(deg, upper arm forward)", "flexion (deg)"]),
    ];
    let index = text("figures.md");
    for (stem, labels) in units {
        let png = image::load_from_memory(&first[&format!("{stem}.png")]).unwrap();
        assert_eq!((png.width(), png.height()), (1600, 1000), "{stem}.png");
        let svg = text(&format!("{stem}.svg"));
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let texts: Vec<&str> = doc.descendants().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
        let number = stem.split('_').skip(1).take(2).collect::<Vec<_>>().join(".");
        let name = format!("Thesis fig. {number}");
        assert!(texts.iter().any(|t| t.contains(&name)), "{stem}.svg does not name {name}: {texts:?}");
        for label in labels {
            assert!(texts.iter().any(|t| t.contains(label)), "{stem}.svg has no `{label}`");
        }
        assert!(index.contains(&format!("[{stem}.png]({stem}.png)")) && index.contains(&name), "figures.md: {stem}");
    }
}

#[test]
fn the_rougher_terrain_is_the_smaller_h() {
    let csv = text("fig_6_2_terrain.csv");
    let rms = |col: &str| {
        let h = column(&csv, col, None);
        let steps: Vec<f64> = h.windows(2).map(|w| w[1] - w[0]).collect();
        (steps.iter().map(|d| d * d).sum::<f64>() / steps.len() as f64).sqrt()
    };
    let (smooth, rough) = (rms("height_h03_cm"), rms("height_h01_cm"));
    assert!(column(&csv, "x_m", None).len() > 100);
    // Same seed, each level's displacement 2^-H of the last: at H 0.1 the fine levels keep
    // far more of the amplitude.
    assert!(rough > 2.0 * smooth && smooth > 0.1, "RMS step H 0.1 {rough:.3} cm, H 0.3 {smooth:.3} cm");
}

#[test]
fn the_swing_foot_rises_over_a_step_up_and_drops_over_a_step_down() {
    let csv = text("fig_6_6_swing_foot.csv");
    let heel = |walk: &str| column(&csv, &format!("{walk}_heel_cm"), None);
    let (flat, up, down) = (heel("flat"), heel("up"), heel("down"));
    assert_eq!(flat.len(), 101);
    // The default step is 15 cm: the step-up curve clears the flat one by half that or more
    // and lands on the step (the ankle lifts the toe over the nosing by up to 7° of
    // dorsiflexion before the heel is raised: 8.1 cm higher, 31.4 against 23.3; heel-first it
    // was more than 10); the step-down one lands 15 cm below where it left.
    assert!(max(&up) > max(&flat) + 7.5, "up {:.1} flat {:.1}", max(&up), max(&flat));
    assert!((up[100] - flat[100] - 15.0).abs() < 1.0, "lands {:.1} cm up", up[100] - flat[100]);
    assert!((down[100] - flat[100] + 15.0).abs() < 1.0, "lands {:.1} cm down", flat[100] - down[100]);
    assert!(flat[100].abs() < 1.0 && min(&flat) > -0.5, "the flat swing lands where it left: {:.2}", flat[100]);
    for walk in ["flat", "up", "down"] {
        let forward = column(&csv, &format!("{walk}_forward_m"), None);
        assert!(forward.windows(2).all(|w| w[1] >= w[0] - 1e-4), "{walk}: the heel goes forward only");
    }
}

#[test]
fn the_ankle_figure_draws_the_walk_against_the_norms() {
    let csv = text("fig_6_8_ankle.csv");
    let (walk, norms, sd) = (
        column(&csv, "walk_ankle_deg", None),
        column(&csv, "adults_mean_deg", None),
        column(&csv, "adults_sd_deg", None),
    );
    assert_eq!((walk.len(), norms.len(), sd.len()), (101, 101, 101));
    // Push-off plantarflexion and the swing's return to neutral, in both.
    assert!(min(&walk[55..75]) < -10.0 && min(&norms[55..75]) < -10.0);
    assert!(walk[100].abs() < 5.0 && sd.iter().all(|s| *s > 0.0));
}

#[test]
fn downhill_the_pelvis_progresses_differently() {
    let csv = text("fig_6_15_pelvis_progress.csv");
    let swing = |walk: &str| {
        let ahead = column(&csv, "ahead_of_uniform_cm", Some(walk));
        max(&ahead) - min(&ahead)
    };
    let (flat, down) = (swing("flat"), swing("downhill"));
    // Two cycles of progress, varying about uniform by centimetres; the slope moves the keys.
    assert!(max(&column(&csv, "pelvis_forward_m", Some("flat"))) > 2.0);
    assert!(flat > 0.5 && (down - flat).abs() > 0.5, "unevenness flat {flat:.2} cm, downhill {down:.2} cm");
}

#[test]
fn the_arms_swing_opposite() {
    let csv = text("fig_6_17_arms.csv");
    let (r, l) = (column(&csv, "shoulder_r_deg", None), column(&csv, "shoulder_l_deg", None));
    let correlation = {
        let (mr, ml) = (r.iter().sum::<f64>() / r.len() as f64, l.iter().sum::<f64>() / l.len() as f64);
        let cov: f64 = r.iter().zip(&l).map(|(a, b)| (a - mr) * (b - ml)).sum();
        let var = |v: &[f64], m: f64| v.iter().map(|a| (a - m).powi(2)).sum::<f64>();
        cov / (var(&r, mr) * var(&l, ml)).sqrt()
    };
    assert!(correlation < -0.9 && max(&r) - min(&r) > 10.0, "r {correlation:.2}");
}

/// A table row's figure in column `k` (markdown bold removed).
fn cell(row: &str, k: usize) -> f64 {
    row.split('|').nth(k + 1).unwrap().trim().trim_matches('*').parse().unwrap()
}

#[test]
fn table_6_1_parts_sum_to_the_frame() {
    let md = text("table_6_1.md");
    let rows: Vec<&str> = md.lines().filter(|l| l.starts_with("| ")).collect();
    let sum = cell(rows.iter().find(|r| r.contains("sum of the parts")).unwrap(), 3);
    let whole = cell(rows.iter().find(|r| r.contains("the walk's frame, timed whole")).unwrap(), 3);
    let parts: Vec<f64> = rows[1..=10].iter().map(|r| cell(r, 3)).collect();
    assert!(parts.iter().all(|p| *p > 0.0), "{parts:?}");
    assert!((parts.iter().sum::<f64>() - sum).abs() < 0.01, "{parts:?} vs {sum}");
    assert!((sum / whole - 1.0).abs() <= 0.10, "parts {sum:.3} µs, whole {whole:.3} µs");
    let draw = rows.iter().find(|r| r.contains("the lab's draw")).unwrap();
    assert!(cell(draw, 3) > 0.0, "{draw}");
    assert!(md.contains("~5 ms a frame") && md.contains("3.75 steps a second"));
}

#[test]
fn everything_but_the_timing_table_is_the_same_on_a_second_run() {
    let (first, second) = made();
    assert_eq!(first.keys().collect::<Vec<_>>(), second.keys().collect::<Vec<_>>());
    for (name, bytes) in first {
        if name != "table_6_1.md" {
            assert!(bytes == &second[name], "{name} differs between runs");
        }
    }
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = temp("bad");
    let out = dir.join("figs");
    let out_s = out.to_str().unwrap();
    let cases: [(&[&str], &str); 4] = [
        (&["figures", "--set", "walk.speed_mps=99", "--out", out_s], "walk.speed_mps"),
        (&["figures", "no/such/config.toml", "--out", out_s], "no/such/config.toml"),
        (&["figures", "--bogus"], "--bogus"),
        (&["figures", "--out", "Cargo.toml"], "not a folder"),
    ];
    for (args, says) in cases {
        let o = gaitlab(args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    // A folder of someone else's is never replaced.
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let o = gaitlab(&["figures", "--out", out_s]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("not a gaitlab report"));
    assert_eq!(std::fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn report_compare_overlays_the_swing_foot() {
    let dir = temp("compare");
    let o = gaitlab(&[
        "report",
        "configs/default.toml",
        "--cycles",
        "4",
        "--compare",
        "configs/stairs_up.toml",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(dir.join("plots/swing_foot.svg")).unwrap();
    assert!(svg.contains("default, each step") && svg.contains("stairs_up, each step"));
    std::fs::remove_dir_all(dir).unwrap();
}
