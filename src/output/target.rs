//! Where a single output file goes, decided before any work is done.

use super::error::OutputError;
use super::pending::{self, Pending};
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::os::unix::fs::{FileTypeExt, MetadataExt, OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};

/// A resolved place for one output file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FileTarget {
    /// Standard output (`-`, `/dev/stdout`, `/dev/fd/1`, `/proc/self/fd/1`): written to
    /// the descriptor the shell gave, so `>>` and pipes behave as they do for any tool.
    Stdout,
    /// A character device or FIFO: opened and written through, never replaced.
    Stream(PathBuf),
    /// A regular file, or nothing yet: replaced atomically.
    Replace {
        /// The file's real path (links resolved), where the temp is made beside it.
        path: PathBuf,
        /// Mode and owner of the file being replaced, kept on the new one.
        keep: Option<Keep>,
    },
}

/// What a replaced file keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Keep {
    /// Permission bits.
    pub mode: u32,
    /// Owner.
    pub(crate) uid: u32,
    /// Group.
    pub(crate) gid: u32,
}

/// Whether a look-up failed because the path is not there (or a file stands where a
/// folder of the path should be): the place is then checked through its parents.
pub(crate) fn missing(e: &io::Error) -> bool {
    e.kind() == io::ErrorKind::NotFound || e.raw_os_error() == Some(libc::ENOTDIR)
}

/// Paths that name this process's standard output.
fn is_stdout_alias(path: &Path) -> bool {
    ["-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"].iter().any(|a| path == Path::new(a))
}

/// What kind of thing a path names (links followed), for messages.
pub(crate) fn kind_of(meta: &fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_dir() {
        "a folder"
    } else if t.is_file() {
        "a regular file"
    } else if t.is_block_device() {
        "a block device"
    } else if t.is_char_device() {
        "a character device"
    } else if t.is_fifo() {
        "a FIFO"
    } else if t.is_socket() {
        "a socket"
    } else {
        "not a file"
    }
}

/// Checks that the nearest existing ancestor of `path`'s folder is a folder (the missing
/// ones will be created).
pub(crate) fn check_parents(path: &Path) -> Result<(), OutputError> {
    let mut dir = pending::parent_dir(path);
    loop {
        match fs::metadata(&dir) {
            Ok(m) if m.is_dir() => return Ok(()),
            Ok(m) => {
                return Err(OutputError::Refused(format!(
                    "{}: {} is {}, not a folder",
                    path.display(),
                    dir.display(),
                    kind_of(&m)
                )));
            }
            Err(e) if missing(&e) => {
                if fs::symlink_metadata(&dir).is_ok() {
                    return Err(OutputError::Refused(format!(
                        "{}: {} is a link to nothing",
                        path.display(),
                        dir.display()
                    )));
                }
                match dir.parent() {
                    Some(p) if !p.as_os_str().is_empty() => dir = p.to_path_buf(),
                    _ => return Ok(()),
                }
            }
            Err(e) => {
                return Err(OutputError::Refused(format!("{}: cannot look at {}: {e}", path.display(), dir.display())));
            }
        }
    }
}

/// Creates the missing folders above `path`, returning those it created (outermost first),
/// so that a failed write can remove them again.
pub(crate) fn create_parents(path: &Path) -> Result<Vec<PathBuf>, OutputError> {
    let mut missing = Vec::new();
    let mut dir = pending::parent_dir(path);
    while fs::symlink_metadata(&dir).is_err() {
        missing.push(dir.clone());
        match dir.parent() {
            Some(p) if !p.as_os_str().is_empty() => dir = p.to_path_buf(),
            _ => break,
        }
    }
    missing.reverse();
    for (i, d) in missing.iter().enumerate() {
        if let Err(e) = fs::create_dir(d)
            && e.kind() != io::ErrorKind::AlreadyExists
        {
            remove_created(&missing[..i]);
            return Err(OutputError::io(d, "create the folder", &e));
        }
    }
    Ok(missing)
}

/// Removes folders [`create_parents`] made, innermost first, if they are still empty.
pub(crate) fn remove_created(created: &[PathBuf]) {
    for d in created.iter().rev() {
        let _ = fs::remove_dir(d);
    }
}

impl FileTarget {
    /// Decides how `path` is written, or refuses it. Nothing is created or changed.
    pub fn resolve(path: &Path) -> Result<FileTarget, OutputError> {
        if is_stdout_alias(path) {
            return Ok(FileTarget::Stdout);
        }
        if path.as_os_str().is_empty() {
            return Err(OutputError::Refused("--out: an empty path".into()));
        }
        let link = fs::symlink_metadata(path);
        let meta = match fs::metadata(path) {
            Ok(m) => Some(m),
            Err(e) if missing(&e) => {
                if link.is_ok() {
                    let to = fs::read_link(path).map_or_else(|_| "?".into(), |p| p.display().to_string());
                    return Err(OutputError::Refused(format!(
                        "{}: a link to {to}, which does not exist; give the path itself",
                        path.display()
                    )));
                }
                None
            }
            Err(e) => return Err(OutputError::Refused(format!("{}: cannot look at it: {e}", path.display()))),
        };
        let Some(meta) = meta else {
            check_parents(path)?;
            return Ok(FileTarget::Replace { path: path.to_path_buf(), keep: None });
        };
        let t = meta.file_type();
        if t.is_char_device() || t.is_fifo() {
            return Ok(FileTarget::Stream(path.to_path_buf()));
        }
        if !t.is_file() {
            return Err(OutputError::Refused(format!(
                "{}: is {}; gaitlab writes only to a regular file, a character device, a FIFO or - (stdout)",
                path.display(),
                kind_of(&meta)
            )));
        }
        if meta.nlink() > 1 {
            return Err(OutputError::Refused(format!(
                "{}: has {} hard links; replacing it would split them, so it is left alone (write elsewhere, or remove the other links)",
                path.display(),
                meta.nlink()
            )));
        }
        // A link to a regular file: the file it names is replaced, in its own folder, so
        // the link keeps pointing at the new content.
        let real = if link.is_ok_and(|l| l.file_type().is_symlink()) {
            fs::canonicalize(path)
                .map_err(|e| OutputError::Refused(format!("{}: cannot resolve the link: {e}", path.display())))?
        } else {
            path.to_path_buf()
        };
        let keep = Keep { mode: meta.permissions().mode() & 0o7777, uid: meta.uid(), gid: meta.gid() };
        Ok(FileTarget::Replace { path: real, keep: Some(keep) })
    }

    /// The path to name in messages (`-` for stdout).
    #[must_use]
    pub fn display(&self) -> String {
        match self {
            FileTarget::Stdout => "stdout".into(),
            FileTarget::Stream(p) | FileTarget::Replace { path: p, .. } => p.display().to_string(),
        }
    }
}

/// Writes one output to `target` by its rule (see [`FileTarget`]). A closed reader on a
/// stream (`| head`, a FIFO whose reader left) is not a failure.
pub fn write_file(
    target: &FileTarget,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), OutputError> {
    let finish = |result: io::Result<()>, what: &str| match result {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(OutputError::Failed(format!("cannot write {what}: {e}"))),
    };
    match target {
        FileTarget::Stdout => {
            let stdout = io::stdout();
            let mut out = io::BufWriter::new(stdout.lock());
            finish(write(&mut out).and_then(|()| out.flush()), "to stdout")
        }
        FileTarget::Stream(path) => {
            let file = OpenOptions::new().write(true).open(path).map_err(|e| OutputError::io(path, "open", &e))?;
            let mut out = io::BufWriter::new(file);
            finish(write(&mut out).and_then(|()| out.flush()), &path.display().to_string())
        }
        FileTarget::Replace { path, keep } => replace(path, *keep, write),
    }
}

fn replace(
    path: &Path,
    keep: Option<Keep>,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), OutputError> {
    pending::sweep_stale(path);
    let created = create_parents(path)?;
    let temp = Pending::beside(path, "tmp");
    let result = (|| -> io::Result<()> {
        let mut options = OpenOptions::new();
        options.write(true).create_new(true).mode(keep.map_or(0o666, |k| k.mode));
        let file = options.open(temp.path())?;
        if let Some(k) = keep {
            // The umask may have cleared bits the old file had; the owner is kept where the
            // user may give it (root, or the same owner), otherwise left as the writer's.
            file.set_permissions(fs::Permissions::from_mode(k.mode))?;
            let _ = std::os::unix::fs::fchown(&file, Some(k.uid), Some(k.gid));
        }
        let mut out = io::BufWriter::new(file);
        write(&mut out)?;
        let file: File = out.into_inner().map_err(io::IntoInnerError::into_error)?;
        file.sync_all()?;
        fs::rename(temp.path(), path)
    })();
    match result {
        Ok(()) => {
            temp.keep();
            Ok(())
        }
        Err(e) => {
            drop(temp);
            remove_created(&created);
            Err(OutputError::io(path, "write", &e))
        }
    }
}
