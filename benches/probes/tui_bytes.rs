//! Probe: the bytes the lab writes to a real terminal — walking at 100x30 and the default
//! frame rate (10 s), then paused with no input (5 s). It runs the release `gaitlab` binary
//! in a pseudo-terminal; cargo builds that binary with the probe. Figures in
//! benches/README.md, "Terminal lab" (the paused case is also asserted by `tests/tui_pty.rs`).
//!
//! ```text
//! cargo bench --bench tui_bytes
//! ```
//!
//! Not run by a plain `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use portable_pty::{CommandBuilder, PtySize, native_pty_system};
use std::error::Error;
use std::io::{Read, Write};
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

const USAGE: &str = "cargo bench --bench tui_bytes";

fn main() -> ExitCode {
    common::args(USAGE, 0);
    match measure() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("tui_bytes: {e}");
            ExitCode::FAILURE
        }
    }
}

fn measure() -> Result<(), Box<dyn Error>> {
    let pty = native_pty_system();
    let pair = pty.openpty(PtySize { rows: 30, cols: 100, pixel_width: 0, pixel_height: 0 })?;
    // Set for bench targets, and the binary is built with the same (release) profile.
    let mut cmd = CommandBuilder::new(env!("CARGO_BIN_EXE_gaitlab"));
    cmd.env("TERM", "xterm-256color");
    let mut child = pair.slave.spawn_command(cmd)?;
    drop(pair.slave);
    let mut reader = pair.master.try_clone_reader()?;
    let count = Arc::new(AtomicUsize::new(0));
    let c = Arc::clone(&count);
    // The pty must be drained all the time, or the lab would block on a full buffer and
    // write less than it would to a real terminal.
    std::thread::spawn(move || {
        let mut buf = [0u8; 65536];
        while let Ok(n) = reader.read(&mut buf) {
            if n == 0 {
                break;
            }
            c.fetch_add(n, Ordering::Relaxed);
        }
    });
    let mut writer = pair.master.take_writer()?;
    // Past the first full screen, which is not the steady rate.
    std::thread::sleep(Duration::from_secs(2));
    let measure = |secs: u64| {
        let before = count.load(Ordering::Relaxed);
        std::thread::sleep(Duration::from_secs(secs));
        (count.load(Ordering::Relaxed) - before) as f64 / secs as f64
    };
    let walking = measure(10);
    writer.write_all(b" ")?;
    writer.flush()?;
    std::thread::sleep(Duration::from_millis(500));
    let idle = measure(5);
    writer.write_all(b"q")?;
    writer.flush()?;
    let status = child.wait()?;
    println!("walking at 100x30, default fps: {:.1} KB/s", walking / 1000.0);
    println!("paused, no input: {idle:.0} bytes/s");
    println!("exit: {}", status.exit_code());
    Ok(())
}
