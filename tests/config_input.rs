//! Reading a config from anywhere a path can point (a folder, a huge or endless file, a FIFO
//! with or without a writer, bash's `<(...)`), in any encoding a file can arrive in (a BOM,
//! CRLF, invalid UTF-8), and the error lines that user text can reach: short, on one line,
//! never an empty list, nan and inf called what they are.

use gaitlab::config::{self, MAX_CONFIG_BYTES, READ_DEADLINE, read_source};
use gaitlab::model::params::WalkParams;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-config-input-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The one error line of a refusal.
fn only_error(result: Result<impl std::fmt::Debug, config::ConfigErrors>) -> String {
    let errors = result.expect_err("refused");
    assert_eq!(errors.0.len(), 1, "{errors}");
    errors.to_string()
}

fn errors_of(text: &str, sets: &[&str]) -> Vec<String> {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    let e = config::load_text(text, "a.toml", &sets).expect_err("refused");
    e.to_string().lines().map(str::to_string).collect()
}

fn error_of(text: &str, sets: &[&str]) -> String {
    let lines = errors_of(text, sets);
    assert_eq!(lines.len(), 1, "{lines:?}");
    lines[0].clone()
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().expect("mkfifo runs");
    assert!(status.success());
}

// ---- read_source: what a path can point to ----

#[cfg(target_os = "linux")]
#[test]
fn dev_zero_is_refused_within_two_seconds() {
    let start = Instant::now();
    let line = only_error(read_source(Path::new("/dev/zero")));
    let took = start.elapsed();
    eprintln!("/dev/zero refused in {took:.1?}");
    assert!(took < Duration::from_secs(2), "{took:?}");
    assert_eq!(
        line,
        "/dev/zero:1:1: more than the 1 MiB (1048576-byte) limit for a config file came from this character device"
    );
    // The same through the whole load.
    assert!(config::load(Path::new("/dev/zero"), &[]).is_err());
}

#[cfg(unix)]
#[test]
fn a_fifo_with_no_writer_is_refused_at_the_deadline() {
    let dir = temp_dir("fifo-alone");
    let fifo = dir.join("nobody.toml");
    mkfifo(&fifo);
    let start = Instant::now();
    let line = only_error(read_source(&fifo));
    let took = start.elapsed();
    eprintln!("FIFO with no writer refused in {took:.2?}");
    assert!(took >= READ_DEADLINE && took < READ_DEADLINE + Duration::from_secs(2), "{took:?}");
    assert_eq!(
        line,
        format!(
            "{}:1:1: this pipe did not come to an end within 5 s (nothing writing to it?); a config must be readable at once",
            fifo.display()
        )
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_with_a_writer_is_read() {
    let dir = temp_dir("fifo-writer");
    let fifo = dir.join("fed.toml");
    mkfifo(&fifo);
    let writer_path = fifo.clone();
    // Opening the write end blocks until the reader opens the other: a thread of its own.
    let writer = std::thread::spawn(move || {
        std::fs::write(&writer_path, "[walk]\r\nspeed_mps = 1.1\r\n").unwrap();
    });
    let start = Instant::now();
    let (text, params) = config::load_with_text(&fifo, &[]).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("FIFO with a writer read in {:.1?}", start.elapsed());
    writer.join().unwrap();
    assert_eq!(params.walk.speed_mps, 1.1);
    assert_eq!(text, "[walk]\r\nspeed_mps = 1.1\r\n");
    assert!(start.elapsed() < Duration::from_secs(2));
}

#[cfg(unix)]
#[test]
fn bash_process_substitution_works_and_dev_null_is_an_empty_config() {
    let bin = env!("CARGO_BIN_EXE_gaitlab");
    let script = format!("'{bin}' check <(cat configs/brisk.toml) --set walk.speed_mps=1.6");
    let out = Command::new("bash")
        .arg("-c")
        .arg(&script)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("bash runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout} {}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.starts_with("ok: /dev/fd/"), "{stdout}");
    // A bad config through `<(...)` is placed at its line.
    let out = Command::new("bash")
        .arg("-c")
        .arg(format!("'{bin}' check <(printf '[walk]\\nspeed_mps = nan\\n')"))
        .output()
        .expect("bash runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr.contains(":2:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not nan"), "{stderr}");
    assert_eq!(config::load(Path::new("/dev/null"), &[]).unwrap(), WalkParams::default());
}

#[test]
fn a_sparse_200_mb_file_is_refused_at_once_from_its_size() {
    let dir = temp_dir("sparse");
    let path = dir.join("huge.toml");
    std::fs::File::create(&path).unwrap().set_len(200 * 1024 * 1024).unwrap();
    let start = Instant::now();
    let line = only_error(read_source(&path));
    let took = start.elapsed();
    eprintln!("200 MB sparse file refused in {took:.1?}");
    assert!(took < Duration::from_millis(500), "{took:?}");
    assert_eq!(
        line,
        format!(
            "{}:1:1: the file is 200.0 MiB (209715200 bytes), over the 1 MiB (1048576-byte) limit for a config file",
            path.display()
        )
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_size_limit_is_exact() {
    let dir = temp_dir("limit");
    let path = dir.join("big.toml");
    // A valid config of exactly the limit: comments after one key.
    let mut text = String::from("[walk]\nspeed_mps = 1.2\n");
    let line = format!("# {}\n", "x".repeat(97));
    while text.len() + line.len() <= MAX_CONFIG_BYTES as usize {
        text.push_str(&line);
    }
    text.push_str(&"#".repeat(MAX_CONFIG_BYTES as usize - text.len()));
    assert_eq!(text.len() as u64, MAX_CONFIG_BYTES);
    std::fs::write(&path, &text).unwrap();
    assert_eq!(config::load(&path, &[]).unwrap().walk.speed_mps, 1.2);
    text.push('#');
    std::fs::write(&path, &text).unwrap();
    assert_eq!(
        only_error(read_source(&path)),
        format!(
            "{}:1:1: the file is 1.0 MiB (1048577 bytes), over the 1 MiB (1048576-byte) limit for a config file",
            path.display()
        )
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_folder_and_a_missing_file_are_refused() {
    let dir = temp_dir("folder");
    assert_eq!(only_error(read_source(&dir)), format!("{}:1:1: is a folder, not a config file", dir.display()));
    let missing = dir.join("missing.toml");
    let line = only_error(read_source(&missing));
    assert!(line.starts_with(&format!("{}:1:1: cannot read the config: ", missing.display())), "{line}");
    let _ = std::fs::remove_dir_all(&dir);
}

// ---- encodings ----

#[test]
fn a_bom_is_skipped() {
    let dir = temp_dir("bom");
    let path = dir.join("bom.toml");
    std::fs::write(&path, b"\xEF\xBB\xBF[walk]\nspeed_mps = 1.1\n").unwrap();
    assert_eq!(read_source(&path).unwrap(), "[walk]\nspeed_mps = 1.1\n");
    assert_eq!(config::load(&path, &[]).unwrap().walk.speed_mps, 1.1);
    // Places count from after it, in a file and in text handed over with it.
    std::fs::write(&path, b"\xEF\xBB\xBF[wlk]\n").unwrap();
    let line = only_error(config::load(&path, &[]));
    assert!(line.starts_with(&format!("{}:1:2: wlk: unknown group; did you mean [walk]?", path.display())), "{line}");
    assert!(error_of("\u{feff}[wlk]\n", &[]).starts_with("a.toml:1:2: wlk: unknown group"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn crlf_line_endings_read_like_lf() {
    let dir = temp_dir("crlf");
    for name in ["elderly", "stairs_up", "default"] {
        let lf = std::fs::read_to_string(format!("configs/{name}.toml")).unwrap();
        let crlf = lf.replace('\n', "\r\n");
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, &crlf).unwrap();
        assert_eq!(config::load(&path, &[]).unwrap(), config::load_text(&lf, "lf", &[]).unwrap(), "{name}");
    }
    // A problem in a CRLF file is at the same place as in the LF one.
    let lf = "[body]\nheight_m = 1.7\n\n[walk]\nspeed_mps = 9.0\n";
    let at_lf = error_of(lf, &[]);
    let at_crlf = error_of(&lf.replace('\n', "\r\n"), &[]);
    assert_eq!(at_lf, at_crlf);
    assert!(at_lf.starts_with("a.toml:5:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not 9.0"), "{at_lf}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn invalid_utf8_is_placed_at_its_line_and_column() {
    let dir = temp_dir("utf8");
    let path = dir.join("a.toml");
    std::fs::write(&path, b"[walk]\n# pace\nsway = \xFF\n").unwrap();
    assert_eq!(only_error(read_source(&path)), format!("{}:3:8: not UTF-8 text (byte 0xff)", path.display()));
    // Columns count characters: two of two bytes each before the bad byte.
    std::fs::write(&path, b"[walk]\n\n# \xC3\xA9\xC3\xA9 \xC0\n").unwrap();
    assert_eq!(only_error(config::load(&path, &[])), format!("{}:3:6: not UTF-8 text (byte 0xc0)", path.display()));
    // Latin-1 text, a common way to get here.
    std::fs::write(&path, b"\xEF\xBB\xBF[body]\nsex = \"f\xE9male\"\n").unwrap();
    assert_eq!(only_error(config::load(&path, &[])), format!("{}:2:9: not UTF-8 text (byte 0xe9)", path.display()));
    let _ = std::fs::remove_dir_all(&dir);
}

// ---- error lines: short, one line each, no empty lists ----

#[test]
fn a_megabyte_string_value_gives_a_short_line() {
    let text = format!("[walk]\nspeed_mps = \"{}\"\n", "x".repeat(1_000_000));
    assert_eq!(
        error_of(&text, &[]),
        format!("a.toml:2:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not \"{}…\"", "x".repeat(79))
    );
    let text = format!("[terrain]\nkind = \"{}\"\n", "st".repeat(500_000));
    let line = error_of(&text, &[]);
    assert!(line.chars().count() < 200, "{line}");
    assert!(
        line.starts_with(&format!(
            "a.toml:2:8: terrain.kind needs one of \"flat\", \"stairs\", \"slope\", \"random\", not \"{}…\"",
            "st".repeat(39) + "s"
        )),
        "{line}"
    );
    // A number literal a megabyte long.
    let text = format!("[walk]\nspeed_mps = {}\n", "1".repeat(1_000_000));
    assert_eq!(
        error_of(&text, &[]),
        format!("a.toml:2:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not {}…", "1".repeat(79))
    );
}

#[test]
fn a_megabyte_key_gives_a_short_line_quickly() {
    let long = "k".repeat(1_000_000);
    let start = Instant::now();
    for (text, place, what) in [
        (format!("[walk]\n{long} = 1\n"), "2:1", "unknown key (keys of [walk]: "),
        (format!("[{long}]\n"), "1:2", "unknown group (groups: body, walk,"),
        (format!("[curves.{long}]\npoints = []\n"), "1:9", "unknown curve (15 curves; `gaitlab init` lists them all)"),
    ] {
        let line = error_of(&text, &[]);
        assert!(line.chars().count() <= 300, "{} chars: {line}", line.chars().count());
        assert!(line.starts_with(&format!("a.toml:{place}: ")), "{line}");
        assert!(line.contains(&format!("{}…: {what}", "k".repeat(20))), "{line}");
    }
    let line = error_of("", &[&format!("{long}=1")]);
    assert!(line.chars().count() <= 300 && line.starts_with("--set #1:1:1: kkkk"), "{line}");
    let line = error_of("", &[&format!("walk.speed_mps={long}")]);
    assert!(line.chars().count() <= 300 && line.contains("not \"kkkk"), "{line}");
    // The "did you mean" search does not measure a megabyte against every key.
    assert!(start.elapsed() < Duration::from_secs(5), "{:?}", start.elapsed());
}

#[test]
fn control_characters_in_keys_and_values_are_escaped() {
    assert_eq!(
        error_of("[walk]\n\"a\\nb\" = 1\n", &[]),
        "a.toml:2:1: walk.a\\nb: unknown key (keys of [walk]: speed_mps, sway, stride_m, cadence_spm, step_width_m)"
    );
    assert_eq!(
        error_of("[terrain]\nkind = \"\\u001b[2J\\\"\"\n", &[]),
        "a.toml:2:8: terrain.kind needs one of \"flat\", \"stairs\", \"slope\", \"random\", not \"\\u001B[2J\\\"\""
    );
}

#[test]
fn set_with_an_empty_key_says_so() {
    let wanted = "--set #1:1:1: empty key; expected KEY=VALUE with a dotted key, like walk.speed_mps=1.4 or terrain.kind=\"stairs\"";
    assert_eq!(error_of("", &["=1"]), wanted);
    assert_eq!(error_of("", &[" =1"]), wanted.replace("#1:1:1", "#1:1:2"));
    assert_eq!(error_of("", &["="]), wanted);
}

#[test]
fn set_never_prints_an_empty_list() {
    for (set, wanted) in [
        (
            "foo.bar=1",
            "--set #1:1:1: foo.bar: unknown group (groups: body, walk, pelvis, legs, arms, ik, optimiser, terrain, sim, curves)",
        ),
        (
            "speed_mps=1",
            "--set #1:1:1: speed_mps: unknown key; did you mean `walk.speed_mps`? (a key is GROUP.NAME, like walk.speed_mps; groups: body, walk, pelvis, legs, arms, ik, optimiser, terrain, sim, curves)",
        ),
        (
            "keys.quit=\"x\"",
            "--set #1:1:1: keys.quit: the lab's key bindings are set in the config file's [keys] table, not with --set",
        ),
        ("walk=1", "--set #1:1:1: walk: `walk` is a group; name a key in it, like walk.speed_mps=..."),
        (
            "walk.=1",
            "--set #1:1:1: walk.: unknown key (keys of [walk]: speed_mps, sway, stride_m, cadence_spm, step_width_m)",
        ),
        (
            "wlak.speed_mps=1",
            "--set #1:1:1: wlak.speed_mps: unknown group; did you mean [walk]? (groups: body, walk, pelvis, legs, arms, ik, optimiser, terrain, sim, curves)",
        ),
        ("ik.nope=1", "--set #1:1:1: ik.nope: unknown key (26 keys of [ik]; `gaitlab init` lists them all)"),
    ] {
        assert_eq!(error_of("", &[set]), wanted);
    }
    for set in ["=1", "x=1", ".=1", "a.b.c=1", "curves=1", "curves.x=1", "keys.quit=1", " = ", "."] {
        for line in errors_of("", &[set]) {
            assert!(!line.contains("[]") && !line.contains(": )") && !line.ends_with(": "), "{set}: {line}");
        }
    }
}

#[test]
fn nan_and_inf_need_a_finite_number_in_a_set_and_in_a_file() {
    let needs = "needs a number from 0.4 to 2 m/s";
    for (word, col) in [("nan", 16), ("inf", 16), ("-inf", 16), ("+inf", 16), ("-nan", 16), (" nan", 17)] {
        let shown = word.trim();
        assert_eq!(
            error_of("", &[&format!("walk.speed_mps={word}")]),
            format!("--set #1:1:{col}: walk.speed_mps {needs}, not {shown}")
        );
        assert_eq!(
            error_of(&format!("[walk]\nspeed_mps = {shown}\n"), &[]),
            format!("a.toml:2:13: walk.speed_mps {needs}, not {shown}")
        );
    }
    // Still a word for a key that takes words; still auto for an auto key.
    assert_eq!(
        error_of("", &["terrain.kind=nan"]),
        "--set #1:1:14: terrain.kind needs one of \"flat\", \"stairs\", \"slope\", \"random\", not \"nan\""
    );
    assert_eq!(
        error_of("", &["sim.cycles=inf"]),
        "--set #1:1:12: sim.cycles needs a whole number from 1 to 100000, not inf"
    );
    let p = config::load_text("[walk]\nstride_m = 1.3\n", "a.toml", &["walk.stride_m=auto".into()]).unwrap();
    assert_eq!(p.walk.stride_m, None);
}

#[test]
fn too_large_numbers_are_out_of_range_not_the_wrong_type() {
    assert_eq!(
        error_of("[walk]\nspeed_mps = 1e999\n", &[]),
        "a.toml:2:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not 1e999"
    );
    assert_eq!(
        error_of("[sim]\ncycles = 99999999999999999999\n", &[]),
        "a.toml:2:10: sim.cycles needs a whole number from 1 to 100000, not 99999999999999999999"
    );
    assert_eq!(
        error_of("[sim]\ncycles = 0xffffffffffffffffff\n", &[]),
        "a.toml:2:10: sim.cycles needs a whole number from 1 to 100000, not 0xffffffffffffffffff"
    );
    assert_eq!(
        error_of("[walk]\nspeed_mps = [1]\n", &[]),
        "a.toml:2:13: walk.speed_mps needs a number from 0.4 to 2 m/s, not an array"
    );
}

#[test]
fn a_megabyte_of_problems_lists_the_first_hundred_quickly() {
    let mut text = String::from("[walk]\n");
    for i in 0..50_000 {
        text.push_str(&format!("key_{i} = 1\n"));
    }
    let start = Instant::now();
    let lines = errors_of(&text, &[]);
    assert_eq!(lines.len(), config::MAX_PROBLEMS + 1);
    assert_eq!(lines[100], "a.toml:102:1: more problems from here on are not listed (the first 100 are)");
    // All on one line: the columns are counted once, not once a problem.
    let mut text = String::from("walk = {");
    for i in 0..60_000 {
        text.push_str(&format!("k{i} = 1, "));
    }
    text.push_str("z = 1 }\n");
    let lines = errors_of(&text, &[]);
    assert_eq!(lines.len(), config::MAX_PROBLEMS + 1);
    assert!(lines[1].starts_with("a.toml:1:17: walk.k1: unknown key"), "{}", lines[1]);
    assert!(start.elapsed() < Duration::from_secs(5), "{:?}", start.elapsed());
}

#[test]
fn curve_overrides_stay_within_their_limits() {
    let set = |name: &str, points: &str| format!("curves.{name}.points={points}");
    assert_eq!(
        error_of("", &[&set("heel_rise", "[[0, 0], [0.3, 10], [0.6, 800], [1, 80]]")]),
        "--set #1:1:25: curves.heel_rise.points: curve `heel_rise`: control point 2 has y = 800; valid: 0 to 90 (the foot-ground angle, 0 to 90 deg)"
    );
    assert_eq!(
        error_of("", &[&set("pelvis_vertical", "[[0, 0], [0.3, 0], [0.6, 1], [1, 0.5]]")]),
        "--set #1:1:31: curves.pelvis_vertical.points: curve `pelvis_vertical` must end at y = 1 (progress from one pelvis key to the next, 0 to 1); it ends at 0.5"
    );
    assert_eq!(
        error_of("", &[&set("pelvis_tilt", "[[0, 0], [0.3, 1e308], [0.6, 0], [1, 0]]")]),
        "--set #1:1:27: curves.pelvis_tilt.points: curve `pelvis_tilt`: control point 1 has y = 1e308; valid: -1 to 1 (a unit shape, -1 to 1)"
    );
    // A forward progress that dips: the swing heel would walk backward in mid-swing (it was
    // accepted, and walked). Where it falls, and to what, is named.
    assert_eq!(
        error_of(
            "",
            &[&set("swing_forward", "[[0, 0], [0.2, 0.5], [0.3, 0.9], [0.5, 0.6], [0.7, 0.3], [0.8, 0.9], [1, 1]]")]
        ),
        "--set #1:1:29: curves.swing_forward.points: curve `swing_forward` must never go back (progress from toe-off to the footfall, 0 to 1): it falls from 0.703 at x = 0.37 to 0.517 at x = 0.608"
    );
    let in_file = "[curves.pelvis_forward_ds_ms]\npoints = [[0, 0], [0.1, 0.6], [0.3, 0.1], [0.5, 0.5], [0.6, 0.6], [0.8, 0.8], [1, 1]]\n";
    let error = error_of(in_file, &[]);
    assert!(
        error.starts_with("a.toml:2:")
            && error.contains("curves.pelvis_forward_ds_ms.points: curve `pelvis_forward_ds_ms` must never go back"),
        "{error}"
    );
    // A progress that pauses (flat) is not going back.
    config::load_text(
        "",
        "a.toml",
        &[set("swing_forward", "[[0, 0], [0.2, 0.5], [0.3, 0.5], [0.5, 0.5], [0.7, 0.5], [0.8, 1], [1, 1]]")],
    )
    .unwrap();
    // At the limits, accepted.
    let p = config::load_text("", "a.toml", &[set("swing_lateral", "[[0, 0], [0.2, 1], [0.8, 1], [1, 0]]")]).unwrap();
    assert_eq!(p.curves["swing_lateral"], vec![(0.0, 0.0), (0.2, 1.0), (0.8, 1.0), (1.0, 0.0)]);
}
