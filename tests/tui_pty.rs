//! The real binary in a real pseudo-terminal: it draws, answers keys, quits on `q` or
//! SIGTERM, and leaves the terminal as it found it (main screen, cursor shown).

use portable_pty::{CommandBuilder, PtySize, native_pty_system};
use std::io::{Read, Write};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

struct Session {
    output: Arc<Mutex<Vec<u8>>>,
    writer: Box<dyn Write + Send>,
    child: Box<dyn portable_pty::Child + Send + Sync>,
    _master: Box<dyn portable_pty::MasterPty + Send>,
}

fn start(args: &[&str]) -> Session {
    start_with_env(args, &[])
}

fn start_with_env(args: &[&str], env: &[(&str, &str)]) -> Session {
    let pty = native_pty_system();
    let pair = pty.openpty(PtySize { rows: 24, cols: 80, pixel_width: 0, pixel_height: 0 }).expect("a pty");
    let mut cmd = CommandBuilder::new(env!("CARGO_BIN_EXE_gaitlab"));
    cmd.args(args);
    cmd.cwd(env!("CARGO_MANIFEST_DIR"));
    cmd.env("TERM", "xterm-256color");
    for (key, value) in env {
        cmd.env(key, value);
    }
    let child = pair.slave.spawn_command(cmd).expect("the binary starts");
    drop(pair.slave);
    let mut reader = pair.master.try_clone_reader().unwrap();
    let output = Arc::new(Mutex::new(Vec::new()));
    let sink = Arc::clone(&output);
    std::thread::spawn(move || {
        let mut buf = [0u8; 8192];
        while let Ok(n) = reader.read(&mut buf) {
            if n == 0 {
                break;
            }
            sink.lock().unwrap().extend_from_slice(&buf[..n]);
        }
    });
    let writer = pair.master.take_writer().unwrap();
    Session { output, writer, child, _master: pair.master }
}

impl Session {
    fn screen(&self) -> vt100::Parser {
        let mut parser =
            vt100::Parser::new(std::num::NonZero::new(24).unwrap(), std::num::NonZero::new(80).unwrap(), 0);
        parser.process(&self.output.lock().unwrap());
        parser
    }

    fn wait_for(&self, text: &str) -> String {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let contents = self.screen().screen().contents();
            if contents.contains(text) {
                return contents;
            }
            assert!(Instant::now() < deadline, "`{text}` never appeared; screen:\n{contents}");
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    fn send(&mut self, bytes: &[u8]) {
        self.writer.write_all(bytes).unwrap();
        self.writer.flush().unwrap();
    }

    fn wait_exit(&mut self) -> u32 {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                return status.exit_code();
            }
            assert!(Instant::now() < deadline, "the lab did not exit");
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// The terminal is back to normal: alternate screen left, cursor visible.
    fn assert_restored(&self) {
        // The child may exit before the reader thread has drained the pty: wait for the
        // restoring bytes to arrive (they are the last the lab writes).
        let deadline = Instant::now() + Duration::from_secs(10);
        while !String::from_utf8_lossy(&self.output.lock().unwrap()).contains("\x1b[?1049l")
            && Instant::now() < deadline
        {
            std::thread::sleep(Duration::from_millis(20));
        }
        std::thread::sleep(Duration::from_millis(100));
        let bytes = self.output.lock().unwrap().clone();
        let text = String::from_utf8_lossy(&bytes);
        let entered = text.rfind("\x1b[?1049h").expect("entered the alternate screen");
        let left = text.rfind("\x1b[?1049l").expect("left the alternate screen");
        assert!(left > entered);
        assert!(text.rfind("\x1b[?25h").expect("showed the cursor") > text.rfind("\x1b[?25l").unwrap());
        let parser = self.screen();
        assert!(!parser.screen().alternate_screen());
        assert!(!parser.screen().hide_cursor());
        // Mouse capture, if the lab turned it on, is off again.
        assert_eq!(parser.screen().mouse_protocol_mode(), vt100::MouseProtocolMode::None);
    }
}

#[test]
fn the_lab_runs_in_a_pty_answers_keys_and_quits_cleanly() {
    let mut s = start(&["configs/default.toml"]);
    // One frame can reach the screen in several writes: wait for each part.
    s.wait_for("Parameters");
    s.wait_for("Walk: side view");
    let screen = s.wait_for("configs/default.toml");
    assert!(screen.contains("Parameters") && screen.contains("Walk: side view"), "{screen}");
    s.send(b"?");
    s.wait_for("Keys (any key closes)");
    s.send(b"x");
    s.send(b"v");
    s.wait_for("front view");
    // An edit, then q: the lab asks, and esc keeps it running.
    s.send(b"l");
    s.wait_for("modified (1)");
    s.send(b"q");
    s.wait_for("Quit?");
    s.send(b"y");
    assert_eq!(s.wait_exit(), 0);
    s.assert_restored();
}

#[test]
fn the_mouse_is_captured_clicks_work_and_no_mouse_leaves_it_alone() {
    let mut s = start(&["configs/default.toml"]);
    let screen = s.wait_for("Parameters");
    assert_ne!(s.screen().screen().mouse_protocol_mode(), vt100::MouseProtocolMode::None);
    // A click (SGR press and release, 1-based cells) on the Joints tab shows that panel.
    let tabs = screen.lines().next().unwrap();
    let column = tabs[..tabs.find("Joints").unwrap()].chars().count() + 2;
    s.send(format!("\x1b[<0;{column};1M\x1b[<0;{column};1m").as_bytes());
    s.wait_for("Joint angles");
    s.send(b"q");
    assert_eq!(s.wait_exit(), 0);
    s.assert_restored();
    let mut s = start(&["--no-mouse", "configs/default.toml"]);
    s.wait_for("Parameters");
    assert_eq!(s.screen().screen().mouse_protocol_mode(), vt100::MouseProtocolMode::None);
    s.send(b"q");
    assert_eq!(s.wait_exit(), 0);
    s.assert_restored();
    assert!(!String::from_utf8_lossy(&s.output.lock().unwrap()).contains("\x1b[?1000"), "no mouse bytes at all");
}

#[test]
fn sigterm_ends_the_lab_and_restores_the_terminal() {
    let mut s = start(&[]);
    s.wait_for("(embedded default)");
    let pid = s.child.process_id().expect("a pid");
    let killed = std::process::Command::new("kill").args(["-TERM", &pid.to_string()]).status().unwrap();
    assert!(killed.success());
    assert_eq!(s.wait_exit(), 0);
    s.assert_restored();
}

#[test]
fn a_bad_config_exits_2_before_touching_the_terminal() {
    let mut s = start(&["tests/bad_configs/unknown_key.toml"]);
    let code = s.wait_exit();
    assert_eq!(code, 2);
    std::thread::sleep(Duration::from_millis(200));
    let bytes = s.output.lock().unwrap().clone();
    let text = String::from_utf8_lossy(&bytes);
    assert!(!text.contains("\x1b[?1049h"), "{text}");
    assert!(text.contains("unknown_key.toml:"), "{text}");
}

#[test]
fn paused_and_idle_the_lab_writes_nothing() {
    let mut s = start(&["configs/default.toml"]);
    s.wait_for("Parameters");
    s.send(b" ");
    s.wait_for("paused");
    // Let the last frame out, then listen.
    std::thread::sleep(Duration::from_millis(300));
    let before = s.output.lock().unwrap().len();
    std::thread::sleep(Duration::from_millis(1500));
    assert_eq!(s.output.lock().unwrap().len(), before, "bytes written while paused and idle");
    // A key still gets an answer.
    s.send(b"v");
    s.wait_for("front view");
    s.send(b"q");
    assert_eq!(s.wait_exit(), 0);
    s.assert_restored();
}

#[test]
fn a_panic_in_the_lab_still_restores_the_terminal_and_reports_it() {
    let mut s = start_with_env(&[], &[("GAITLAB_TEST_PANIC", "1")]);
    let code = s.wait_exit();
    assert_ne!(code, 0, "a panic is a failure");
    s.assert_restored();
    // The message comes after the restore, on the normal screen where the user sees it.
    let text = String::from_utf8_lossy(&s.output.lock().unwrap()).into_owned();
    let message = text.find("GAITLAB_TEST_PANIC is set").expect("the panic message is printed");
    let before = &text[..message];
    assert!(before.rfind("\x1b[?1049l") > before.rfind("\x1b[?1049h"), "printed after leaving the alternate screen");
    assert!(s.screen().screen().contents().contains("GAITLAB_TEST_PANIC is set"), "and visible");
}
