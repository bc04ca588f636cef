//! Temp files and partial folders that exist only while a write is under way.
//!
//! Each is registered while it exists, so that a signal (SIGINT, SIGTERM, SIGHUP) can remove
//! them before the process ends: the headless commands install `remove_on_signal`, the lab
//! calls `remove_all` on its way out. A run killed with SIGKILL cannot clean up, so the
//! next write to the same place calls `sweep_stale`: it removes entries of gaitlab's own
//! naming (`.NAME.tmp-PID-N`, `.NAME.partial-PID`, `.NAME.old-PID`) whose PID is dead.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};

static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// The suffixes gaitlab gives its temps: `.NAME.<kind>-PID[-N]`.
const KINDS: [&str; 3] = ["tmp", "partial", "old"];

/// A temp file or folder that is removed when dropped unless [`Pending::keep`] was called
/// (after it was renamed into place).
#[derive(Debug)]
pub(crate) struct Pending {
    path: PathBuf,
    kept: bool,
}

impl Pending {
    /// A fresh temp name beside `target` (`.NAME.<kind>-PID-N`), registered for removal.
    /// Nothing is created on disk.
    #[must_use]
    pub fn beside(target: &Path, kind: &str) -> Pending {
        let dir = parent_dir(target);
        let name = target.file_name().map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
        let path =
            dir.join(format!(".{name}.{kind}-{}-{}", std::process::id(), COUNTER.fetch_add(1, Ordering::Relaxed)));
        lock().push(path.clone());
        Pending { path, kept: false }
    }

    /// The temp's path.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// It has become the real output (renamed into place): forget it without removing.
    pub fn keep(mut self) {
        self.kept = true;
        unregister(&self.path);
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        if !self.kept {
            remove_path(&self.path);
            unregister(&self.path);
        }
    }
}

fn lock() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    // A panic while holding the lock leaves the list as it was: still the right list.
    PENDING.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn unregister(path: &Path) {
    lock().retain(|p| p != path);
}

/// The folder a target sits in (`.` for a bare name).
#[must_use]
pub(crate) fn parent_dir(target: &Path) -> PathBuf {
    target.parent().filter(|p| !p.as_os_str().is_empty()).map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// Removes a file or a folder tree. A writer on another thread may still be creating files
/// inside a folder being removed, so a folder that is not empty yet is tried again.
fn remove_path(path: &Path) {
    for _ in 0..5 {
        let result = match fs::symlink_metadata(path) {
            Ok(m) if m.is_dir() => fs::remove_dir_all(path),
            Ok(_) => fs::remove_file(path),
            Err(_) => return,
        };
        if result.is_ok() || matches!(&result, Err(e) if e.kind() == io::ErrorKind::NotFound) {
            return;
        }
    }
}

/// Removes every registered temp now (the process is about to end).
pub(crate) fn remove_all() {
    let paths: Vec<PathBuf> = lock().drain(..).collect();
    for p in &paths {
        remove_path(p);
    }
}

/// Starts a thread that, on SIGINT, SIGTERM or SIGHUP, removes every registered temp and
/// ends the process with 128 + the signal's number (the shell's convention). The previous
/// output stays as it was, since only temps are touched.
pub(crate) fn remove_on_signal() -> io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])?;
    std::thread::Builder::new().name("gaitlab-signals".into()).spawn(move || {
        if let Some(signal) = signals.forever().next() {
            remove_all();
            std::process::exit(128 + signal);
        }
    })?;
    Ok(())
}

/// Whether a process with this PID exists (a PID reused by another program counts as
/// alive: its temps are then left alone, which is the safe side).
fn alive(pid: u32) -> bool {
    let Ok(pid) = libc::pid_t::try_from(pid) else { return false };
    // SAFETY: kill with signal 0 only checks for the process; it sends nothing.
    let r = unsafe { libc::kill(pid, 0) };
    r == 0 || io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}

/// The PID in a temp name of `target`'s naming, if `file_name` is one.
fn temp_pid(file_name: &str, target_name: &str) -> Option<u32> {
    let rest = file_name.strip_prefix('.')?.strip_prefix(target_name)?.strip_prefix('.')?;
    let (kind, rest) = rest.split_once('-')?;
    if !KINDS.contains(&kind) {
        return None;
    }
    let pid = rest.split('-').next()?;
    pid.parse().ok()
}

/// Removes temps of `target`'s naming left by processes that no longer run. Returns how
/// many were removed.
pub(crate) fn sweep_stale(target: &Path) -> usize {
    let Some(name) = target.file_name().map(|n| n.to_string_lossy().into_owned()) else { return 0 };
    let Ok(entries) = fs::read_dir(parent_dir(target)) else { return 0 };
    let own = std::process::id();
    let mut removed = 0;
    for entry in entries.flatten() {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        if let Some(pid) = temp_pid(&file_name, &name)
            && pid != own
            && !alive(pid)
        {
            remove_path(&entry.path());
            removed += 1;
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn temp_names_parse_only_for_their_own_target() {
        assert_eq!(temp_pid(".big.csv.tmp-123-0", "big.csv"), Some(123));
        assert_eq!(temp_pid(".r.partial-77-3", "r"), Some(77));
        assert_eq!(temp_pid(".r.old-77", "r"), Some(77));
        assert_eq!(temp_pid(".r.partial-77-3", "r2"), None);
        assert_eq!(temp_pid(".r.backup-77", "r"), None);
        assert_eq!(temp_pid("r.tmp-77", "r"), None);
        assert_eq!(temp_pid(".r.tmp-x", "r"), None);
    }

    #[test]
    fn a_dropped_pending_removes_its_file_and_a_kept_one_stays() {
        let dir = std::env::temp_dir().join(format!("gaitlab-pending-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let target = dir.join("x.csv");
        let a = Pending::beside(&target, "tmp");
        fs::write(a.path(), "a").unwrap();
        let a_path = a.path().to_path_buf();
        drop(a);
        assert!(!a_path.exists());
        let b = Pending::beside(&target, "tmp");
        fs::write(b.path(), "b").unwrap();
        let b_path = b.path().to_path_buf();
        b.keep();
        assert!(b_path.exists());
        assert!(!lock().contains(&b_path));
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn stale_temps_of_dead_processes_are_swept_and_live_ones_kept() {
        let dir = std::env::temp_dir().join(format!("gaitlab-sweep-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let target = dir.join("big.csv");
        // PID 4194304 is above Linux's pid_max ceiling: never a live process.
        let dead = dir.join(".big.csv.tmp-4194304-0");
        let dead_folder = dir.join(".big.csv.partial-4194304-1");
        let live = dir.join(format!(".big.csv.tmp-{}-9", std::process::id()));
        let other = dir.join(".other.csv.tmp-4194304-0");
        fs::write(&dead, "x").unwrap();
        fs::create_dir_all(dead_folder.join("plots")).unwrap();
        fs::write(&live, "x").unwrap();
        fs::write(&other, "x").unwrap();
        assert_eq!(sweep_stale(&target), 2);
        assert!(!dead.exists() && !dead_folder.exists());
        assert!(live.exists() && other.exists());
        fs::remove_dir_all(&dir).unwrap();
    }
}
