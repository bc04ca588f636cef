//! Where a report folder goes: built whole under a temp name, then swapped into place.
//!
//! gaitlab replaces only what it wrote. An existing folder is replaced when it is empty or
//! is a gaitlab report (it holds `summary.json`, or a figures folder `figures.md`, and
//! nothing but the files it writes);
//! a report that also holds files of the user's is replaced only with `--force`; any other
//! folder, and anything that is not a folder, is refused before the walk is run.

use super::error::OutputError;
use super::pending::{self, Pending};
use super::target::{check_parents, create_parents, kind_of, missing, remove_created};
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// A resolved place for a report folder.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FolderTarget {
    /// The folder's real path (a link to a folder is followed).
    pub path: PathBuf,
    /// Whether a previous report (or an empty folder) is there to be replaced.
    pub replaces: bool,
    /// Replace a report that holds files of the user's too.
    pub force: bool,
}

/// What sits at a report folder's place.
#[derive(Debug, PartialEq, Eq)]
enum Found {
    Empty,
    Report,
    /// A report with other files in it: their names (a few).
    ReportWith(Vec<String>),
    /// A folder that is not a gaitlab report: a few of its names.
    Foreign(Vec<String>),
}

/// Whether `rel` (a path inside a report folder) is one a report writes.
fn written_by_report(rel: &Path, files: &[&str]) -> bool {
    let s = rel.to_string_lossy();
    if files.contains(&s.as_ref()) || s == "plots" {
        return true;
    }
    rel.parent() == Some(Path::new("plots"))
        && rel.extension().is_some_and(|e| e == "png" || e == "svg")
        && rel.components().count() == 2
}

/// The file that marks a folder as one gaitlab wrote: a report's `summary.json`, or
/// `figures.md` for `gaitlab figures`' folder (whose `files` list it and no summary).
fn marker<'a>(files: &[&'a str]) -> &'a str {
    if files.contains(&"figures.md") && !files.contains(&"summary.json") { "figures.md" } else { "summary.json" }
}

fn survey(dir: &Path, files: &[&str]) -> io::Result<Found> {
    let mut others = Vec::new();
    let mut any = false;
    let mut has_summary = false;
    let mut stack = vec![PathBuf::new()];
    while let Some(rel) = stack.pop() {
        for entry in fs::read_dir(dir.join(&rel))? {
            let entry = entry?;
            any = true;
            let child = rel.join(entry.file_name());
            if child == Path::new(marker(files)) {
                has_summary = true;
            }
            if !written_by_report(&child, files) {
                others.push(child.display().to_string());
            } else if entry.file_type()?.is_dir() {
                stack.push(child);
            }
        }
    }
    others.sort();
    Ok(if !any {
        Found::Empty
    } else if !has_summary {
        Found::Foreign(others)
    } else if others.is_empty() {
        Found::Report
    } else {
        Found::ReportWith(others)
    })
}

fn some_names(names: &[String]) -> String {
    let shown: Vec<&str> = names.iter().take(3).map(String::as_str).collect();
    let more = if names.len() > 3 { format!(" and {} more", names.len() - 3) } else { String::new() };
    format!("{}{more}", shown.join(", "))
}

impl FolderTarget {
    /// Decides whether a report may be written at `path`, or refuses it. `files` are the
    /// top-level files a report writes (besides `plots/*.png|svg`). Nothing is changed.
    pub fn resolve(path: &Path, files: &[&str], force: bool) -> Result<FolderTarget, OutputError> {
        if path.as_os_str().is_empty() || path == Path::new("-") {
            return Err(OutputError::Refused(format!("--out {}: a report is a folder; give its path", path.display())));
        }
        let link = fs::symlink_metadata(path);
        let (real, meta) = match fs::metadata(path) {
            Ok(m) => (fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()), Some(m)),
            Err(e) if missing(&e) => {
                if link.is_ok() {
                    let to = fs::read_link(path).map_or_else(|_| "?".into(), |p| p.display().to_string());
                    return Err(OutputError::Refused(format!(
                        "{}: a link to {to}, which does not exist; give the folder's path itself",
                        path.display()
                    )));
                }
                (path.to_path_buf(), None)
            }
            Err(e) => return Err(OutputError::Refused(format!("{}: cannot look at it: {e}", path.display()))),
        };
        let Some(meta) = meta else {
            check_parents(path)?;
            return Ok(FolderTarget { path: real, replaces: false, force });
        };
        if !meta.is_dir() {
            return Err(OutputError::Refused(format!(
                "{}: is {}, not a folder; a report is a folder of files (choose another --out)",
                path.display(),
                kind_of(&meta)
            )));
        }
        let found = survey(&real, files)
            .map_err(|e| OutputError::Refused(format!("{}: cannot read the folder: {e}", path.display())))?;
        check_found(path, &found, force)?;
        Ok(FolderTarget { path: real, replaces: true, force })
    }
}

fn check_found(path: &Path, found: &Found, force: bool) -> Result<(), OutputError> {
    match found {
        Found::Empty | Found::Report => Ok(()),
        Found::ReportWith(_) if force => Ok(()),
        Found::ReportWith(others) => Err(OutputError::Refused(format!(
            "{}: a gaitlab report that also holds {}, which a report does not write; they would be deleted: move them out, or pass --force to replace the folder with them",
            path.display(),
            some_names(others)
        ))),
        Found::Foreign(names) => Err(OutputError::Refused(format!(
            "{}: a folder that is not a gaitlab report (it holds {}); gaitlab replaces only folders it wrote: choose another --out",
            path.display(),
            some_names(names)
        ))),
    }
}

/// Swaps two paths in one step where the system can (Linux `renameat2` with
/// `RENAME_EXCHANGE`), so that readers and a concurrent report see one whole report at
/// every moment; elsewhere the old one is moved aside first.
#[cfg(target_os = "linux")]
fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    let a = CString::new(a.as_os_str().as_bytes()).map_err(io::Error::other)?;
    let b = CString::new(b.as_os_str().as_bytes()).map_err(io::Error::other)?;
    // SAFETY: both are valid NUL-terminated paths; AT_FDCWD resolves them from the cwd.
    let r = unsafe {
        libc::syscall(
            libc::SYS_renameat2,
            libc::AT_FDCWD,
            a.as_ptr(),
            libc::AT_FDCWD,
            b.as_ptr(),
            libc::RENAME_EXCHANGE,
        )
    };
    if r == 0 { Ok(()) } else { Err(io::Error::last_os_error()) }
}

#[cfg(not(target_os = "linux"))]
fn exchange(_a: &Path, _b: &Path) -> io::Result<()> {
    Err(io::Error::from(io::ErrorKind::Unsupported))
}

/// Builds a report folder: `fill` writes every file into the folder it is given (a temp
/// beside the target); when it succeeds, the folder is moved into place — swapped with a
/// previous report, which is then removed. On any failure, or a signal, the temp is removed
/// and the target is as it was.
pub fn write_folder(
    target: &FolderTarget,
    files: &[&str],
    fill: impl FnOnce(&Path) -> Result<(), String>,
) -> Result<(), OutputError> {
    let path = &target.path;
    pending::sweep_stale(path);
    let created = create_parents(path)?;
    let temp = Pending::beside(path, "partial");
    let fail = |e: OutputError, temp: Pending| {
        drop(temp);
        remove_created(&created);
        Err(e)
    };
    if let Err(e) = fs::create_dir(temp.path()) {
        return fail(OutputError::io(temp.path(), "create the folder", &e), temp);
    }
    if let Err(e) = fill(temp.path()) {
        return fail(OutputError::Failed(e), temp);
    }
    // Into place. A folder can be renamed over a missing or empty one; a previous report is
    // swapped with the new one and then checked again before it is removed, in case the
    // folder changed while the report was being made.
    match fs::rename(temp.path(), path) {
        Ok(()) => {
            temp.keep();
            return Ok(());
        }
        Err(e) if e.kind() != io::ErrorKind::DirectoryNotEmpty && e.raw_os_error() != Some(libc::EEXIST) => {
            return fail(OutputError::io(path, "move the report to", &e), temp);
        }
        Err(_) => {}
    }
    let aside = Pending::beside(path, "old");
    let swapped = match exchange(temp.path(), path) {
        Ok(()) => fs::rename(temp.path(), aside.path()),
        Err(_) => fs::rename(path, aside.path()).and_then(|()| {
            fs::rename(temp.path(), path).inspect_err(|_| {
                let _ = fs::rename(aside.path(), path);
            })
        }),
    };
    if let Err(e) = swapped {
        drop(aside);
        return fail(OutputError::io(path, "replace", &e), temp);
    }
    let found = survey(aside.path(), files).unwrap_or(Found::Foreign(vec!["(unreadable)".into()]));
    if let Err(e) = check_found(path, &found, target.force) {
        // Someone put other things there meanwhile: give them back and keep the new report
        // under the temp name, named in the message.
        let _ = fs::rename(path, temp.path());
        let _ = fs::rename(aside.path(), path);
        aside.keep();
        return fail(e, temp);
    }
    drop(aside);
    temp.keep();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILES: &[&str] = &["summary.json", "summary.md", "joints.csv"];

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("gaitlab-folder-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    fn fill_report(dir: &Path, tag: &str) -> Result<(), String> {
        for f in FILES {
            fs::write(dir.join(f), tag).map_err(|e| e.to_string())?;
        }
        fs::create_dir(dir.join("plots")).map_err(|e| e.to_string())?;
        fs::write(dir.join("plots/joints.png"), tag).map_err(|e| e.to_string())
    }

    #[test]
    fn a_previous_report_is_replaced_whole() {
        let d = scratch("replace");
        let out = d.join("r");
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        write_folder(&t, FILES, |dir| fill_report(dir, "one")).unwrap();
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        assert!(t.replaces);
        write_folder(&t, FILES, |dir| fill_report(dir, "two")).unwrap();
        assert_eq!(fs::read_to_string(out.join("summary.md")).unwrap(), "two");
        assert_eq!(fs::read_dir(&d).unwrap().count(), 1, "no temp or old folder left");
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_users_folder_is_refused_and_left_untouched() {
        let d = scratch("foreign");
        let out = d.join("thesis");
        fs::create_dir_all(&out).unwrap();
        fs::write(out.join("chapter1.tex"), "precious").unwrap();
        for force in [false, true] {
            let e = FolderTarget::resolve(&out, FILES, force).unwrap_err();
            assert_eq!(e.exit_code(), 2);
            assert!(e.to_string().contains("not a gaitlab report (it holds chapter1.tex)"), "{e}");
        }
        assert_eq!(fs::read_to_string(out.join("chapter1.tex")).unwrap(), "precious");
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_report_with_the_users_notes_needs_force() {
        let d = scratch("notes");
        let out = d.join("r");
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        write_folder(&t, FILES, |dir| fill_report(dir, "one")).unwrap();
        fs::write(out.join("notes.md"), "mine").unwrap();
        let e = FolderTarget::resolve(&out, FILES, false).unwrap_err();
        assert!(e.to_string().contains("also holds notes.md"), "{e}");
        let t = FolderTarget::resolve(&out, FILES, true).unwrap();
        write_folder(&t, FILES, |dir| fill_report(dir, "two")).unwrap();
        assert!(!out.join("notes.md").exists());
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_failed_fill_leaves_the_previous_report_and_no_temp() {
        let d = scratch("fail");
        let out = d.join("new/deeper/r");
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        let e = write_folder(&t, FILES, |dir| {
            fill_report(dir, "half")?;
            Err("No space left on device (os error 28)".into())
        })
        .unwrap_err();
        assert_eq!(e.exit_code(), 1);
        assert_eq!(fs::read_dir(&d).unwrap().count(), 0, "the parents it made are gone too");
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_folder_changed_during_the_run_is_given_back() {
        let d = scratch("race");
        let out = d.join("r");
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        write_folder(&t, FILES, |dir| fill_report(dir, "one")).unwrap();
        let t = FolderTarget::resolve(&out, FILES, false).unwrap();
        let e = write_folder(&t, FILES, |dir| {
            // While this report is made, the user drops a file into the old one.
            fs::write(out.join("late.txt"), "mine").map_err(|e| e.to_string())?;
            fill_report(dir, "two")
        })
        .unwrap_err();
        assert!(e.to_string().contains("late.txt"), "{e}");
        assert_eq!(fs::read_to_string(out.join("late.txt")).unwrap(), "mine");
        assert_eq!(fs::read_to_string(out.join("summary.md")).unwrap(), "one");
        assert_eq!(fs::read_dir(&d).unwrap().count(), 1);
        fs::remove_dir_all(&d).unwrap();
    }
}
