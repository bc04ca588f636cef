//! The lab's watch over its terminal and signals, on a thread of its own.
//!
//! Why a thread: on a dead terminal (a dropped SSH link, a closed pty) the tty stays
//! readable while `read` returns 0 or `EIO`, and crossterm 0.29's event loop spins on it
//! without returning (crossterm-rs/crossterm#793), so a lab that only checks a signal flag
//! between events never sees it — it spun at 50 % CPU until SIGKILL. The watch does not
//! depend on the main thread getting back to its loop:
//!
//! - It polls the tty for `POLLHUP` / `POLLERR` / `POLLNVAL` (events 0: it never consumes
//!   input, which stays crossterm's) every `POLL_MS` ms — this catches a lost terminal with
//!   no signal at all (`nohup`, a closed pty master).
//! - It takes SIGTERM, SIGINT and SIGHUP (SIGHUP only when it was not ignored at start: a lab
//!   under `nohup` honours that, and ends on the hang-up itself).
//!
//! On either, it first writes the unsaved edits to the recovery file (published by the loop
//! through `publish`), then asks the loop to stop. A loop on a live terminal
//! restores it and returns within a frame; if it has not within `GRACE_MS` ms, or the
//! terminal is gone, the watch restores what it can (raw mode off, the restoring bytes
//! written straight to the descriptor, never through the stdout lock the stuck thread may
//! hold), removes pending temps and ends the process itself.

use crate::output;
use std::io;
use std::os::fd::{AsRawFd, RawFd};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How often the tty is checked for a hang-up (ms).
pub(crate) const POLL_MS: i32 = 100;
/// How long a live loop is given to stop by itself after a signal (ms).
pub(crate) const GRACE_MS: u64 = 500;

/// The bytes that put the terminal back: synchronized update off, main screen, cursor shown.
const RESTORE: &[u8] = b"\x1b[?2026l\x1b[?1049l\x1b[?25h";
/// Mouse capture off, as crossterm's `DisableMouseCapture` writes it (every mode its
/// `EnableMouseCapture` turns on), for a lab started with the mouse.
const MOUSE_OFF: &[u8] = b"\x1b[?1006l\x1b[?1015l\x1b[?1003l\x1b[?1002l\x1b[?1000l";

struct Shared {
    /// The recovery file and the text to put in it; `None` text: nothing unsaved.
    unsaved: Mutex<(Option<PathBuf>, Option<String>)>,
    stop: AtomicBool,
    /// The signal that ended the lab, or -1 for a lost terminal; 0 while running.
    ended_by: AtomicI32,
    /// The loop has finished and restored the terminal itself.
    loop_done: AtomicBool,
}

/// The handle the event loop keeps.
pub(crate) struct Watch {
    shared: Arc<Shared>,
}

/// Whether SIGHUP is ignored now (as `nohup` leaves it).
fn sighup_ignored() -> bool {
    // SAFETY: reading the current action with a null new action changes nothing.
    unsafe {
        let mut old: libc::sigaction = std::mem::zeroed();
        libc::sigaction(libc::SIGHUP, std::ptr::null(), &raw mut old) == 0 && old.sa_sigaction == libc::SIG_IGN
    }
}

/// The descriptor the lab's input comes from: stdin when it is a terminal, else the
/// controlling terminal (which crossterm then reads).
fn tty_fd() -> io::Result<(RawFd, Option<std::fs::File>)> {
    use std::io::IsTerminal;
    if io::stdin().is_terminal() {
        return Ok((io::stdin().as_raw_fd(), None));
    }
    let tty = std::fs::OpenOptions::new().read(true).open("/dev/tty")?;
    Ok((tty.as_raw_fd(), Some(tty)))
}

/// Whether the lab has a terminal to run in (checked before any escape code is written).
pub(crate) fn terminal_error() -> Option<&'static str> {
    use std::io::IsTerminal;
    if !io::stdout().is_terminal() {
        return Some("standard output is not a terminal");
    }
    if tty_fd().is_err() {
        return Some("there is no terminal to read keys from");
    }
    None
}

/// Writes the restoring bytes straight to stdout's descriptor (no lock), on a thread that is
/// not waited for longer than 200 ms: a stalled link must not keep the process alive.
fn restore_raw() {
    let done = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&done);
    let _ = std::thread::Builder::new().name("gaitlab-restore".into()).spawn(move || {
        let _ = ratatui::crossterm::terminal::disable_raw_mode();
        // SAFETY: writing a static buffer to fd 1; a failure (dead tty) is ignored.
        if super::MOUSE_CAPTURED.load(Ordering::SeqCst) {
            // SAFETY: as below.
            unsafe { libc::write(1, MOUSE_OFF.as_ptr().cast(), MOUSE_OFF.len()) };
        }
        unsafe { libc::write(1, RESTORE.as_ptr().cast(), RESTORE.len()) };
        flag.store(true, Ordering::SeqCst);
    });
    let deadline = Instant::now() + Duration::from_millis(200);
    while !done.load(Ordering::SeqCst) && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(5));
    }
}

impl Shared {
    fn write_recovery(&self) {
        let guard = self.unsaved.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let (Some(path), Some(text)) = &*guard {
            let _ = output::write_atomic(path, |out| out.write_all(text.as_bytes()));
        }
    }
}

impl Watch {
    /// Starts the watch. `recovery` is where unsaved edits go if the lab is cut off.
    pub fn start(recovery: Option<PathBuf>) -> io::Result<Watch> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let shared = Arc::new(Shared {
            unsaved: Mutex::new((recovery, None)),
            stop: AtomicBool::new(false),
            ended_by: AtomicI32::new(0),
            loop_done: AtomicBool::new(false),
        });
        let mut wanted = vec![SIGTERM, SIGINT];
        if !sighup_ignored() {
            wanted.push(SIGHUP);
        }
        let mut signals = signal_hook::iterator::Signals::new(&wanted)?;
        let (fd, tty) = tty_fd()?;
        let watched = Arc::clone(&shared);
        std::thread::Builder::new().name("gaitlab-watch".into()).spawn(move || {
            let _tty = tty;
            loop {
                let mut pfd = libc::pollfd { fd, events: 0, revents: 0 };
                // SAFETY: one valid pollfd; the descriptor lives as long as this thread.
                let ready = unsafe { libc::poll(&raw mut pfd, 1, POLL_MS) };
                let hung = ready > 0 && pfd.revents & (libc::POLLHUP | libc::POLLERR | libc::POLLNVAL) != 0;
                let signal = signals.pending().next();
                if !hung && signal.is_none() {
                    continue;
                }
                watched.write_recovery();
                watched.ended_by.store(signal.unwrap_or(-1), Ordering::SeqCst);
                watched.stop.store(true, Ordering::SeqCst);
                if !hung {
                    let deadline = Instant::now() + Duration::from_millis(GRACE_MS);
                    while Instant::now() < deadline {
                        if watched.loop_done.load(Ordering::SeqCst) {
                            // The loop is ending the process in order; nothing more to do.
                            return;
                        }
                        std::thread::sleep(Duration::from_millis(10));
                    }
                }
                restore_raw();
                output::pending::remove_all();
                let code = signal.map_or(129, |s| 128 + s);
                // SAFETY: ends the process at once, without running exit handlers that
                // could wait on locks the stuck main thread holds.
                unsafe { libc::_exit(code) };
            }
        })?;
        Ok(Watch { shared })
    }

    /// The loop's current unsaved text (`None`: nothing unsaved), for the recovery file.
    pub(crate) fn publish(&self, text: Option<String>) {
        let mut guard = self.shared.unsaved.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        guard.1 = text;
    }

    /// Writes the unsaved edits to the recovery file now: the loop itself found the terminal
    /// gone (crossterm returned an error rather than spinning) before the watch did.
    pub(crate) fn keep_unsaved(&self) {
        self.shared.write_recovery();
    }

    /// Whether the loop should stop (a signal or a lost terminal).
    #[must_use]
    pub(crate) fn stop_requested(&self) -> bool {
        self.shared.stop.load(Ordering::SeqCst)
    }

    /// The loop has stopped and restores the terminal itself: the watch stands down.
    pub(crate) fn loop_done(&self) {
        self.shared.loop_done.store(true, Ordering::SeqCst);
    }
}
