//! Files gaitlab writes, and the one way every writer puts them on disk.
//!
//! The rule every output follows (CSV, report folders, BVH, glTF, plots, saved configs,
//! recovery files), in [`target`] and [`folder`]:
//!
//! - A regular file, or nothing, at the target is replaced atomically (temp file beside it,
//!   flushed, renamed over it) and keeps its mode and, where permitted, its owner.
//! - A character device or a FIFO (`/dev/null`, `/dev/stdout`, a named pipe) is written
//!   through and never replaced; `-` means standard output.
//! - Anything else — a block device, a socket, a folder where a file is expected, a file
//!   where a folder is expected, a dangling link, a regular file with other hard links (a
//!   rename would split them) — is refused with [`OutputError::Refused`] (exit 2) before any
//!   work is done.
//! - Missing parent folders are created (one rule for every command), and removed again if
//!   the write fails.
//! - Temp files and partial folders are registered in [`pending`] and removed on every
//!   failure path and on SIGINT / SIGTERM / SIGHUP; stale ones left by a killed run (their
//!   PID is dead) are swept by the next write to the same place.

pub mod bvh;
pub mod error;
pub mod folder;
pub mod gltf;
pub mod joint_table;
pub mod pending;
pub mod target;

pub use error::OutputError;
pub use folder::{FolderTarget, write_folder};
pub use target::{FileTarget, write_file};

use std::io;
use std::path::Path;

/// Writes `path` so that it is either the old file or the whole new one, never half of it
/// (see the module's rule for what else may sit at `path`).
pub(crate) fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn io::Write) -> io::Result<()>,
) -> Result<(), OutputError> {
    let target = FileTarget::resolve(path)?;
    write_file(&target, write)
}
