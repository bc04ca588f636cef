//! What the commands share: a stdout that may close early, a progress line, range checks.

use crate::error::{Error, Result};
use std::io;

/// A command's stdout output ended: a reader that went away (a closed pipe, `| head`) is not
/// a failure; any other write error is.
pub(super) fn stdout_written(written: io::Result<()>) -> Result<()> {
    match written {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => Err(Error::Write { target: "stdout", source: e }),
        _ => Ok(()),
    }
}

/// A progress line on stderr for long runs, only when stderr is a terminal (scripts and
/// pipes get nothing): rewritten in place at most twice a second, cleared at the end.
pub(super) struct Progress {
    command: &'static str,
    total: u64,
    tty: bool,
    started: std::time::Instant,
    last: Option<std::time::Instant>,
}

impl Progress {
    pub(super) fn new(command: &'static str, total: u64) -> Self {
        use std::io::IsTerminal;
        Progress { command, total, tty: io::stderr().is_terminal(), started: std::time::Instant::now(), last: None }
    }

    pub(super) fn at(&mut self, done: u64) {
        // Checked every 1024 frames: the clock is not read on every row.
        if !self.tty || !done.is_multiple_of(1024) || self.started.elapsed().as_secs_f64() < 1.0 {
            return;
        }
        if self.last.is_some_and(|t| t.elapsed().as_secs_f64() < 0.5) {
            return;
        }
        self.last = Some(std::time::Instant::now());
        let pct = 100.0 * done as f64 / self.total.max(1) as f64;
        eprint!("\rgaitlab {}: frame {done} of {} ({pct:.0} %)\x1b[K", self.command, self.total);
    }

    pub(super) fn done(&self) {
        if self.last.is_some() {
            eprint!("\r\x1b[K");
        }
    }
}

/// Refuses a value out of its range, naming the option and the range.
pub(super) fn in_range<T: PartialOrd + std::fmt::Display>(
    option: &str,
    value: T,
    range: std::ops::RangeInclusive<T>,
    valid: &str,
) -> Result<T> {
    if range.contains(&value) {
        Ok(value)
    } else {
        Err(Error::Usage(format!("{option} {value} is out of range; valid: {valid}")))
    }
}

/// The references `compare` and `fit` measure against, and how their output names them: the
/// file given (one speed block or several), else the built-in ones by speed.
pub(super) fn references(file: Option<&std::path::Path>) -> Result<(crate::normative::References, String)> {
    use crate::normative::{self, References};
    Ok(match file {
        Some(file) => {
            let text = crate::config::read_text(file, "reference")?;
            (References::parse(&text, &file.display().to_string())?, file.display().to_string())
        }
        None => (References::built_in().clone(), normative::BUILT_IN_SOURCE.to_string()),
    })
}
