//! Bytes the lab writes to a real terminal: while walking at 100x30 and the default frame
//! rate, and while paused with no input. Runs the release binary in a pseudo-terminal:
//! `cargo build --release && cargo run --release --example tui_bytes`.
use portable_pty::{CommandBuilder, PtySize, native_pty_system};
use std::io::{Read, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

fn main() {
    let pty = native_pty_system();
    let pair = pty.openpty(PtySize { rows: 30, cols: 100, pixel_width: 0, pixel_height: 0 }).unwrap();
    let mut cmd = CommandBuilder::new(concat!(env!("CARGO_MANIFEST_DIR"), "/target/release/gaitlab"));
    cmd.env("TERM", "xterm-256color");
    let mut child = pair.slave.spawn_command(cmd).unwrap();
    drop(pair.slave);
    let mut reader = pair.master.try_clone_reader().unwrap();
    let count = Arc::new(AtomicUsize::new(0));
    let c = Arc::clone(&count);
    std::thread::spawn(move || {
        let mut buf = [0u8; 65536];
        while let Ok(n) = reader.read(&mut buf) {
            if n == 0 {
                break;
            }
            c.fetch_add(n, Ordering::Relaxed);
        }
    });
    let mut writer = pair.master.take_writer().unwrap();
    std::thread::sleep(Duration::from_secs(2));
    let measure = |secs: u64| {
        let before = count.load(Ordering::Relaxed);
        std::thread::sleep(Duration::from_secs(secs));
        (count.load(Ordering::Relaxed) - before) as f64 / secs as f64
    };
    let walking = measure(10);
    writer.write_all(b" ").unwrap();
    writer.flush().unwrap();
    std::thread::sleep(Duration::from_millis(500));
    let idle = measure(5);
    writer.write_all(b"q").unwrap();
    writer.flush().unwrap();
    let status = child.wait().unwrap();
    println!("walking at 100x30, default fps: {:.1} KB/s", walking / 1000.0);
    println!("paused, no input: {idle:.0} bytes/s");
    println!("exit: {}", status.exit_code());
}
