//! Outputs never destroy what they do not own: device nodes and FIFOs are written through,
//! modes and hard links survive, users' folders are refused, temps vanish on every failure
//! and signal, and stale temps of killed runs are swept. Each test runs the real binary and
//! asserts the target's type, mode, link count and content afterwards, and that no
//! `.tmp` / `.partial` / `.old` entry is left.

use std::fs;
use std::io::Read;
use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
use std::os::unix::process::{CommandExt, ExitStatusExt};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_gaitlab");
const CONFIG: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/configs/default.toml");

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gaitlab-outputs-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

fn gaitlab(args: &[&str], dir: &Path) -> Output {
    Command::new(BIN).args(args).current_dir(dir).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Entries of `dir` that are gaitlab temps of any kind.
fn leftovers(dir: &Path) -> Vec<String> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in fs::read_dir(&d).unwrap().flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.contains(".tmp-") || name.contains(".partial-") || name.contains(".old-") {
                found.push(e.path().display().to_string());
            }
            if e.file_type().unwrap().is_dir() {
                stack.push(e.path());
            }
        }
    }
    found
}

fn mkfifo(path: &Path) {
    let c = std::ffi::CString::new(path.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0, "mkfifo {}", path.display());
}

fn simulate_one_cycle_stdout() -> Vec<u8> {
    let o = Command::new(BIN).args(["simulate", CONFIG, "--cycles", "1"]).output().unwrap();
    assert!(o.status.success());
    o.stdout
}

#[test]
fn a_fifo_or_device_as_output_is_written_through_and_stays_what_it_was() {
    let d = scratch("fifo");
    let fifo = d.join("pipe");
    mkfifo(&fifo);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            fs::File::open(&fifo).unwrap().read_to_end(&mut bytes).unwrap();
            bytes
        })
    };
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "pipe"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    let read = reader.join().unwrap();
    assert_eq!(read, simulate_one_cycle_stdout(), "the FIFO's reader gets the whole CSV");
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "still a FIFO");
    assert_eq!(fs::read_dir(&d).unwrap().count(), 1, "{:?}", leftovers(&d));

    // A private character device where the system lets us make one (root in most CI
    // containers); the same null device as /dev/null, never the real one.
    let dev = d.join("null");
    let c = std::ffi::CString::new(dev.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid path; makedev(1, 3) is the null device.
    let made = unsafe { libc::mknod(c.as_ptr(), libc::S_IFCHR | 0o666, libc::makedev(1, 3)) } == 0;
    if made {
        let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "null"], &d);
        assert!(o.status.success(), "{}", stderr(&o));
        let meta = fs::symlink_metadata(&dev).unwrap();
        assert!(meta.file_type().is_char_device(), "still a character device");
        assert_eq!(meta.rdev(), libc::makedev(1, 3));
        assert!(leftovers(&d).is_empty());
    }
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn out_dash_and_dev_stdout_are_standard_output() {
    let d = scratch("dash");
    let expected = simulate_one_cycle_stdout();
    for out in ["-", "/dev/stdout"] {
        let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", out], &d);
        assert!(o.status.success(), "{out}: {}", stderr(&o));
        assert_eq!(o.stdout, expected, "{out}");
    }
    assert_eq!(fs::read_dir(&d).unwrap().count(), 0);
    // A report is a folder: `-` is refused as bad input.
    let o = gaitlab(&["report", CONFIG, "--out", "-"], &d);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("a report is a folder"), "{}", stderr(&o));
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_file_as_the_report_folder_is_refused_and_kept() {
    let d = scratch("file-as-folder");
    fs::write(d.join("existing_file"), "my notes").unwrap();
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "existing_file"], &d);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("existing_file: is a regular file, not a folder"), "{}", stderr(&o));
    assert_eq!(fs::read_to_string(d.join("existing_file")).unwrap(), "my notes");
    assert_eq!(fs::read_dir(&d).unwrap().count(), 1, "{:?}", leftovers(&d));
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_users_folder_is_never_replaced_but_a_previous_report_is() {
    let d = scratch("users-folder");
    let thesis = d.join("thesis");
    fs::create_dir_all(thesis.join("figures")).unwrap();
    fs::write(thesis.join("main.tex"), "\\chapter{Walk}").unwrap();
    for extra in [&[][..], &["--force"][..]] {
        let mut args = vec!["report", CONFIG, "--cycles", "4", "--out", "thesis"];
        args.extend_from_slice(extra);
        let o = gaitlab(&args, &d);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains("not a gaitlab report"), "{}", stderr(&o));
        assert_eq!(fs::read_to_string(thesis.join("main.tex")).unwrap(), "\\chapter{Walk}");
        assert!(thesis.join("figures").is_dir());
    }
    // A report written there before is replaced by the next run, whole.
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "r"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    let first = fs::read_to_string(d.join("r/summary.json")).unwrap();
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "r", "--set", "walk.speed_mps=1.1"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    let second = fs::read_to_string(d.join("r/summary.json")).unwrap();
    assert_ne!(first, second);
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    // The user's notes inside a report make it theirs too: --force is asked for.
    fs::write(d.join("r/notes.md"), "keep").unwrap();
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "r"], &d);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("also holds notes.md") && stderr(&o).contains("--force"), "{}", stderr(&o));
    assert_eq!(fs::read_to_string(d.join("r/notes.md")).unwrap(), "keep");
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn mode_is_kept_and_hard_links_are_not_split() {
    let d = scratch("modes");
    let lonely = d.join("private.csv");
    fs::write(&lonely, "old").unwrap();
    fs::set_permissions(&lonely, fs::Permissions::from_mode(0o640)).unwrap();
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "private.csv"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    let meta = fs::metadata(&lonely).unwrap();
    assert_eq!(meta.permissions().mode() & 0o7777, 0o640);
    assert_eq!(fs::read(&lonely).unwrap(), simulate_one_cycle_stdout());

    let linked = d.join("linked.csv");
    fs::write(&linked, "shared").unwrap();
    fs::set_permissions(&linked, fs::Permissions::from_mode(0o600)).unwrap();
    fs::hard_link(&linked, d.join("other-name.csv")).unwrap();
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "linked.csv"], &d);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("has 2 hard links"), "{}", stderr(&o));
    let meta = fs::metadata(&linked).unwrap();
    assert_eq!((meta.nlink(), meta.permissions().mode() & 0o7777), (2, 0o600));
    assert_eq!(fs::read_to_string(&linked).unwrap(), "shared");
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));

    // A link to a file: the file it names gets the new content, the link stays a link.
    fs::create_dir(d.join("runs")).unwrap();
    fs::write(d.join("runs/today.csv"), "old").unwrap();
    std::os::unix::fs::symlink("runs/today.csv", d.join("latest.csv")).unwrap();
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "latest.csv"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(fs::symlink_metadata(d.join("latest.csv")).unwrap().file_type().is_symlink());
    assert_eq!(fs::read(d.join("runs/today.csv")).unwrap(), simulate_one_cycle_stdout());
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn the_labs_save_keeps_the_configs_mode() {
    let d = scratch("save-mode");
    let path = d.join("mine.toml");
    let source = "[walk]\nspeed_mps = 1.3\n";
    fs::write(&path, source).unwrap();
    fs::set_permissions(&path, fs::Permissions::from_mode(0o640)).unwrap();
    let mut params = gaitlab::config::load_text(source, "mine.toml", &[]).unwrap();
    params.walk.speed_mps = 1.4;
    gaitlab::tui::save::save(&path, source, &params, &["walk.speed_mps"]).unwrap();
    assert_eq!(fs::metadata(&path).unwrap().permissions().mode() & 0o7777, 0o640);
    assert!(fs::read_to_string(&path).unwrap().contains("speed_mps = 1.4"));
    assert!(leftovers(&d).is_empty());
    fs::remove_dir_all(&d).unwrap();
}

/// Starts a long run, waits until its temp exists, sends `signal`, and returns the exit status.
fn interrupt(args: &[&str], dir: &Path, temp_marker: &str, signal: i32) -> std::process::ExitStatus {
    let mut child =
        Command::new(BIN).args(args).current_dir(dir).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap();
    let started = Instant::now();
    loop {
        let seen = fs::read_dir(dir).unwrap().flatten().any(|e| e.file_name().to_string_lossy().contains(temp_marker));
        if seen {
            break;
        }
        assert!(started.elapsed() < Duration::from_secs(60), "no {temp_marker} temp appeared");
        assert!(child.try_wait().unwrap().is_none(), "the run ended before it was interrupted");
        std::thread::sleep(Duration::from_millis(5));
    }
    // SAFETY: signalling our own child.
    unsafe { libc::kill(child.id() as libc::pid_t, signal) };
    child.wait().unwrap()
}

#[test]
fn a_signal_mid_write_keeps_the_old_output_and_leaves_nothing_else() {
    let d = scratch("signal");
    for (signal, code) in [(libc::SIGTERM, 143), (libc::SIGINT, 130), (libc::SIGHUP, 129)] {
        fs::write(d.join("big.csv"), "previous run").unwrap();
        let status =
            interrupt(&["simulate", CONFIG, "--cycles", "100000", "--out", "big.csv"], &d, ".big.csv.tmp-", signal);
        assert_eq!(status.code(), Some(code), "signal {signal}: {status:?}");
        assert_eq!(fs::read_to_string(d.join("big.csv")).unwrap(), "previous run");
        assert!(leftovers(&d).is_empty(), "signal {signal}: {:?}", leftovers(&d));
    }
    // A report: the previous report stays whole and no partial folder is left.
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "rep"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    let before = fs::read_to_string(d.join("rep/summary.json")).unwrap();
    for signal in [libc::SIGTERM, libc::SIGINT] {
        let status = interrupt(&["report", CONFIG, "--cycles", "200", "--out", "rep"], &d, ".rep.partial-", signal);
        assert_eq!(status.code(), Some(128 + signal));
        assert_eq!(fs::read_to_string(d.join("rep/summary.json")).unwrap(), before);
        assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    }
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn temps_of_a_killed_run_are_swept_by_the_next_run() {
    let d = scratch("sigkill");
    let status =
        interrupt(&["simulate", CONFIG, "--cycles", "100000", "--out", "big.csv"], &d, ".big.csv.tmp-", libc::SIGKILL);
    assert_eq!(status.signal(), Some(libc::SIGKILL));
    assert_eq!(leftovers(&d).len(), 1, "SIGKILL cannot clean up");
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "big.csv"], &d);
    assert!(o.status.success());
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn links_to_nothing_and_files_in_the_path_are_refused_before_the_walk() {
    let d = scratch("links");
    std::os::unix::fs::symlink("gone/away", d.join("dangling")).unwrap();
    for command in ["report", "simulate"] {
        let o = gaitlab(&[command, CONFIG, "--cycles", "4", "--out", "dangling"], &d);
        assert_eq!(o.status.code(), Some(2), "{command}: {}", stderr(&o));
        assert!(stderr(&o).contains("a link to gone/away, which does not exist"), "{}", stderr(&o));
    }
    fs::write(d.join("plain"), "x").unwrap();
    for command in ["report", "simulate"] {
        let o = gaitlab(&[command, CONFIG, "--cycles", "4", "--out", "plain/sub/out"], &d);
        assert_eq!(o.status.code(), Some(2), "{command}: {}", stderr(&o));
        assert!(stderr(&o).contains("plain is a regular file, not a folder"), "{}", stderr(&o));
    }
    let mut names: Vec<String> =
        fs::read_dir(&d).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(names, ["dangling", "plain"]);
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn missing_parents_are_created_by_every_command() {
    let d = scratch("parents");
    let o = gaitlab(&["simulate", CONFIG, "--cycles", "1", "--out", "no/such/dir/x.csv"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.join("no/such/dir/x.csv").is_file());
    let o = gaitlab(&["report", CONFIG, "--cycles", "4", "--out", "new/place/r"], &d);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(d.join("new/place/r/summary.json").is_file());
    fs::remove_dir_all(&d).unwrap();
}

/// Runs the binary with a file-size limit, the way a full disk looks to a writer: a write
/// past it fails (EFBIG) with the signal it would raise ignored.
fn gaitlab_with_file_limit(args: &[&str], dir: &Path, bytes: u64) -> Output {
    let mut command = Command::new(BIN);
    command.args(args).current_dir(dir);
    // SAFETY: only async-signal-safe calls between fork and exec.
    unsafe {
        command.pre_exec(move || {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            let limit = libc::rlimit { rlim_cur: bytes, rlim_max: bytes };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    command.output().unwrap()
}

#[test]
fn a_full_disk_gives_a_clear_error_and_nothing_partial() {
    let d = scratch("full");
    fs::write(d.join("x.csv"), "previous").unwrap();
    let o = gaitlab_with_file_limit(&["simulate", CONFIG, "--cycles", "20", "--out", "x.csv"], &d, 64 * 1024);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("cannot write") && stderr(&o).contains("x.csv"), "{}", stderr(&o));
    assert_eq!(fs::read_to_string(d.join("x.csv")).unwrap(), "previous");
    let o = gaitlab_with_file_limit(&["report", CONFIG, "--cycles", "4", "--out", "rep"], &d, 64 * 1024);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("File too large"), "{}", stderr(&o));
    assert!(!d.join("rep").exists());
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn two_reports_into_one_folder_at_once_end_as_one_whole_report() {
    let d = scratch("concurrent");
    let spawn = |speed: &str| {
        Command::new(BIN)
            .args(["report", CONFIG, "--cycles", "4", "--out", "r", "--set", &format!("walk.speed_mps={speed}")])
            .current_dir(&d)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    };
    let a = spawn("1.1");
    let b = spawn("1.5");
    let (a, b) = (a.wait_with_output().unwrap(), b.wait_with_output().unwrap());
    assert!(a.status.success(), "{}", stderr(&a));
    assert!(b.status.success(), "{}", stderr(&b));
    let summary: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(d.join("r/summary.json")).unwrap()).unwrap();
    let speed = summary["speed_mps"].as_f64().unwrap();
    // Whichever came last: its config.toml, summary and joint table are of the same walk.
    let config = fs::read_to_string(d.join("r/config.toml")).unwrap();
    let set = if (speed - 1.1).abs() < 0.05 { "1.1" } else { "1.5" };
    assert!((speed - set.parse::<f64>().unwrap()).abs() < 0.05, "speed {speed}");
    assert!(config.contains(&format!("speed_mps = {set}")), "config.toml of another walk than summary.json");
    for f in gaitlab::report::FILES {
        assert!(d.join("r").join(f).is_file(), "{f} missing");
    }
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn the_lab_without_a_terminal_writes_no_escape_codes() {
    let d = scratch("no-tty");
    let o = Command::new(BIN).arg(CONFIG).current_dir(&d).stdin(Stdio::null()).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty(), "stdout got {:?}", String::from_utf8_lossy(&o.stdout));
    assert!(stderr(&o).contains("needs a terminal"), "{}", stderr(&o));
    fs::remove_dir_all(&d).unwrap();
}
