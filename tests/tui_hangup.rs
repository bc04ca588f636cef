//! The lab (and a long run) in a real terminal: the binary in a pty made here with `openpty`, so that
//! the test owns every descriptor of the master side and can close it the way sshd or tmux
//! does when the link goes. The lab must be gone within 1 s, spend under 0.2 s of CPU after
//! the close, and keep unsaved edits in a recovery file that the next start offers back.

use std::fs;
use std::io::{Read, Write};
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_gaitlab");

struct Lab {
    master: Option<fs::File>,
    child: Child,
    output: Vec<u8>,
}

/// Starts `program args` as a session leader whose controlling terminal is a new pty.
fn start(program: &str, args: &[&str], dir: &Path) -> Lab {
    // openpty's descriptors are inherited across exec: a child spawned meanwhile by another
    // test thread would hold this master open, and the link would never drop. Spawns are
    // serialized and both ends made close-on-exec before any other fork can see them.
    static SPAWN: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _one_at_a_time = SPAWN.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let (mut master, mut slave) = (-1, -1);
    let size = libc::winsize { ws_row: 30, ws_col: 100, ws_xpixel: 0, ws_ypixel: 0 };
    // SAFETY: out-pointers to two ints; no name buffer; a valid winsize.
    let r = unsafe { libc::openpty(&mut master, &mut slave, std::ptr::null_mut(), std::ptr::null(), &size) };
    assert_eq!(r, 0, "openpty");
    // SAFETY: openpty returned two fresh descriptors that nothing else owns.
    let (master, slave) = unsafe { (OwnedFd::from_raw_fd(master), OwnedFd::from_raw_fd(slave)) };
    for fd in [&master, &slave] {
        // SAFETY: fcntl on a descriptor we own.
        unsafe { libc::fcntl(fd.as_raw_fd(), libc::F_SETFD, libc::FD_CLOEXEC) };
    }
    let mut command = Command::new(program);
    command
        .args(args)
        .current_dir(dir)
        .env("TERM", "xterm-256color")
        .stdin(Stdio::from(slave.try_clone().unwrap()))
        .stdout(Stdio::from(slave.try_clone().unwrap()))
        .stderr(Stdio::from(slave.try_clone().unwrap()));
    // SAFETY: setsid and ioctl are async-signal-safe.
    unsafe {
        command.pre_exec(|| {
            if libc::setsid() < 0 || libc::ioctl(0, libc::TIOCSCTTY, 0) < 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let child = command.spawn().unwrap();
    drop(slave);
    // Non-blocking reads, so the test never waits on the lab's output.
    // SAFETY: fcntl on a descriptor we own.
    unsafe {
        let flags = libc::fcntl(master.as_raw_fd(), libc::F_GETFL);
        libc::fcntl(master.as_raw_fd(), libc::F_SETFL, flags | libc::O_NONBLOCK);
    }
    Lab { master: Some(fs::File::from(master)), child, output: Vec::new() }
}

impl Lab {
    fn pump(&mut self) {
        let Some(master) = self.master.as_mut() else { return };
        let mut buf = [0u8; 65536];
        while let Ok(n) = master.read(&mut buf) {
            if n == 0 {
                break;
            }
            self.output.extend_from_slice(&buf[..n]);
        }
    }

    fn screen(&mut self) -> String {
        self.pump();
        let mut parser =
            vt100::Parser::new(std::num::NonZero::new(30).unwrap(), std::num::NonZero::new(100).unwrap(), 0);
        parser.process(&self.output);
        parser.screen().contents()
    }

    fn wait_for(&mut self, text: &str) -> String {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let screen = self.screen();
            if screen.contains(text) {
                return screen;
            }
            assert!(Instant::now() < deadline, "`{text}` never appeared; screen:\n{screen}");
            std::thread::sleep(Duration::from_millis(30));
        }
    }

    fn send(&mut self, bytes: &[u8]) {
        let master = self.master.as_mut().unwrap();
        master.write_all(bytes).unwrap();
        master.flush().unwrap();
    }

    /// Closes the master side (the link drops), then waits for the lab to end. Returns the
    /// time it took and the CPU time the lab spent after the close.
    fn drop_link(&mut self, then_signal: Option<i32>) -> (Duration, Duration) {
        let pid = self.child.id();
        let cpu_before = cpu_time(pid).unwrap();
        self.master = None;
        let closed = Instant::now();
        if let Some(signal) = then_signal {
            std::thread::sleep(Duration::from_millis(20));
            // SAFETY: signalling our own child (a zombie at worst, never reaped before wait).
            unsafe { libc::kill(pid as libc::pid_t, signal) };
        }
        let mut cpu_after = cpu_before;
        loop {
            // The zombie keeps its final CPU times until it is reaped below.
            if let Some(t) = cpu_time(pid) {
                cpu_after = t;
            }
            if zombie(pid) {
                break;
            }
            assert!(closed.elapsed() < Duration::from_secs(5), "the lab is still running 5 s after the link dropped");
            std::thread::sleep(Duration::from_millis(5));
        }
        let took = closed.elapsed();
        self.child.wait().unwrap();
        eprintln!("the lab ended {took:?} after the link dropped, using {cpu_after:?} - {cpu_before:?} of CPU");
        (took, cpu_after.saturating_sub(cpu_before))
    }
}

fn stat_fields(pid: u32) -> Option<Vec<String>> {
    let stat = fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The command name is in parentheses and may hold spaces: fields start after it.
    let rest = &stat[stat.rfind(')')? + 2..];
    Some(rest.split_whitespace().map(str::to_string).collect())
}

fn zombie(pid: u32) -> bool {
    stat_fields(pid).is_none_or(|f| f[0] == "Z" || f[0] == "X")
}

/// User + system CPU time of a process, from /proc (clock ticks).
fn cpu_time(pid: u32) -> Option<Duration> {
    let f = stat_fields(pid)?;
    // SAFETY: sysconf has no preconditions.
    let hz = unsafe { libc::sysconf(libc::_SC_CLK_TCK) } as f64;
    let ticks: f64 = f[11].parse::<f64>().ok()? + f[12].parse::<f64>().ok()?;
    Some(Duration::from_secs_f64(ticks / hz))
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gaitlab-hangup-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    fs::copy(concat!(env!("CARGO_MANIFEST_DIR"), "/configs/default.toml"), d.join("mine.toml")).unwrap();
    d
}

#[test]
fn a_closed_terminal_with_no_signal_ends_the_lab_within_a_second_and_keeps_the_edits() {
    let d = scratch("nosignal");
    // SIGHUP ignored, as under nohup: the hang-up itself must be noticed.
    let mut lab = start("/bin/sh", &["-c", &format!("trap '' HUP; exec {BIN} mine.toml")], &d);
    lab.wait_for("Parameters");
    lab.send(b"l");
    lab.wait_for("modified (1)");
    let (took, cpu) = lab.drop_link(None);
    assert!(took < Duration::from_secs(1), "the lab took {took:?} to end");
    assert!(cpu < Duration::from_millis(200), "{cpu:?} of CPU after the close");
    let recovered = fs::read_to_string(d.join("mine.toml.recovery")).expect("a recovery file");
    assert!(recovered.contains("speed_mps = 1.31"), "the edit is kept");
    let saved = fs::read_to_string(d.join("mine.toml")).unwrap();
    assert!(saved.contains("speed_mps = 1.3\n"), "the saved config is never touched");
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn sighup_then_sigterm_after_the_terminal_is_gone_ends_the_lab_within_a_second() {
    let d = scratch("sighup");
    let mut lab = start(BIN, &["mine.toml"], &d);
    lab.wait_for("Parameters");
    // Closing the master hangs up the session (the kernel sends SIGHUP); SIGTERM follows.
    let (took, cpu) = lab.drop_link(Some(libc::SIGTERM));
    assert!(took < Duration::from_secs(1), "the lab took {took:?} to end");
    assert!(cpu < Duration::from_millis(200), "{cpu:?} of CPU after the close");
    assert!(!d.join("mine.toml.recovery").exists(), "nothing unsaved, no recovery file");
    fs::remove_dir_all(&d).unwrap();
}

#[test]
fn recovered_edits_are_offered_on_the_next_start_and_load_to_the_same_parameters() {
    let d = scratch("roundtrip");
    let mut lab = start(BIN, &["mine.toml"], &d);
    lab.wait_for("Parameters");
    // Two edits: speed up twice (1.32), and a key in another group typed in.
    lab.send(b"ll");
    lab.wait_for("walk.speed_mps = 1.32");
    lab.drop_link(None);
    let recovery = d.join("mine.toml.recovery");
    let text = fs::read_to_string(&recovery).unwrap();
    let edited = gaitlab::config::load_text(&text, "recovery", &[]).unwrap();
    assert!((edited.walk.speed_mps - 1.32).abs() < 1e-9);

    // Next start: the lab offers them; `l` loads them as unsaved edits, the file is removed.
    let mut lab = start(BIN, &["mine.toml"], &d);
    // The dialog's title can reach the screen a write before its text (seen under load).
    lab.wait_for("Unsaved edits found");
    let screen = lab.wait_for("mine.toml.recovery");
    assert!(screen.contains("Unsaved edits found"), "{screen}");
    lab.send(b"l");
    lab.wait_for("recovered the unsaved edits");
    lab.wait_for("modified (1)");
    assert!(!recovery.exists());
    // Saved now, the config holds exactly the recovered parameters.
    lab.send(b"s");
    lab.wait_for("saved mine.toml (1 key)");
    lab.send(b"q");
    assert!(lab.child.wait().unwrap().success());
    let saved = gaitlab::config::load(&d.join("mine.toml"), &[]).unwrap();
    assert_eq!(saved, edited);

    // Discarding: `d` removes the file and the config stays as saved.
    fs::write(&recovery, text.replace("speed_mps = 1.32", "speed_mps = 1.5")).unwrap();
    let mut lab = start(BIN, &["mine.toml"], &d);
    lab.wait_for("Unsaved edits found");
    lab.send(b"d");
    lab.wait_for("discarded");
    assert!(!recovery.exists());
    lab.send(b"q");
    assert!(lab.child.wait().unwrap().success());
    assert_eq!(gaitlab::config::load(&d.join("mine.toml"), &[]).unwrap(), edited);
    fs::remove_dir_all(&d).unwrap();
}

/// A long `simulate` shows its progress on a terminal (and only there: the CSV file gets
/// none of it), and clears the line when done.
#[test]
fn a_long_simulate_shows_its_progress_on_a_terminal() {
    let d = scratch("progress");
    let mut run = start(BIN, &["simulate", "mine.toml", "--cycles", "3000", "--out", "big.csv"], &d);
    let deadline = Instant::now() + Duration::from_secs(120);
    while run.child.try_wait().unwrap().is_none() {
        run.pump();
        assert!(Instant::now() < deadline, "simulate did not finish");
        std::thread::sleep(Duration::from_millis(50));
    }
    run.pump();
    assert!(run.child.wait().unwrap().success());
    let shown = String::from_utf8_lossy(&run.output).into_owned();
    assert!(shown.contains("gaitlab simulate: frame "), "no progress line on the terminal: {shown:?}");
    assert!(shown.contains(" %)"), "{shown:?}");
    assert!(shown.ends_with("\r\x1b[K"), "the progress line is cleared at the end: {shown:?}");
    let csv = fs::read_to_string(d.join("big.csv")).unwrap();
    assert!(!csv.contains("gaitlab") && csv.starts_with("frame,time_s"));
    // Without a terminal (a pipe for stderr) there is no progress at all.
    let o = Command::new(BIN)
        .args(["simulate", "mine.toml", "--cycles", "300", "--out", "/dev/null"])
        .current_dir(&d)
        .output()
        .unwrap();
    assert!(o.status.success() && o.stderr.is_empty(), "{}", String::from_utf8_lossy(&o.stderr));
    fs::remove_dir_all(&d).unwrap();
}
