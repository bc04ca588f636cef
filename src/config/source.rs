//! Reading a config file's text without ever hanging or eating memory.
//!
//! A config path can name anything: a folder, a 200 MB file, `/dev/zero`, a FIFO nobody
//! writes to (whose `open` blocks), or `/dev/fd/63` from bash's `<(...)`, which must work. So:
//!
//! - a regular file larger than [`MAX_CONFIG_BYTES`] is refused from its metadata, unread;
//! - a folder is refused;
//! - everything is opened and read on a helper thread, through `Read::take(limit + 1)`,
//!   waited for at most [`READ_DEADLINE`]; more than the limit, or no end within the
//!   deadline, is refused. A thread still blocked when the deadline passes is left behind
//!   (nothing can cancel a blocking `open`); it ends when its source does, and holds at
//!   most the limit;
//! - the bytes must be UTF-8, a leading byte-order mark skipped; invalid UTF-8 is reported
//!   at its line and column.

use super::errors::{ConfigError, ConfigErrors, line_col};
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

/// The largest config accepted, in bytes (1 MiB; the longest shipped config is ~10 KiB).
pub const MAX_CONFIG_BYTES: u64 = 1024 * 1024;

/// How long reading a config may take before it is refused.
pub const READ_DEADLINE: Duration = Duration::from_secs(5);

/// The UTF-8 byte-order mark, skipped when a file starts with it.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// One error at the start of the source.
fn refuse(label: &str, message: String) -> ConfigErrors {
    ConfigErrors(vec![ConfigError { path: label.to_string(), line: 1, col: 1, key: String::new(), message }])
}

/// What kind of file `meta` describes, for messages.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "pipe";
        }
        if t.is_char_device() {
            return "character device";
        }
        if t.is_block_device() {
            return "block device";
        }
        if t.is_socket() {
            return "socket";
        }
    }
    if meta.is_file() { "file" } else { "special file" }
}

/// "1 MiB (1048576 bytes)"-style size.
fn size_text(bytes: u64) -> String {
    let mib = bytes as f64 / (1024.0 * 1024.0);
    if mib >= 1.0 { format!("{mib:.1} MiB ({bytes} bytes)") } else { format!("{bytes} bytes") }
}

/// Reads the config at `path` as text: at most [`MAX_CONFIG_BYTES`], within
/// [`READ_DEADLINE`], UTF-8 (a leading byte-order mark skipped). Every refusal is one
/// [`ConfigError`] at `PATH:1:1` (invalid UTF-8: at its own line and column).
pub fn read_source(path: &Path) -> Result<String, ConfigErrors> {
    read_source_within(path, MAX_CONFIG_BYTES, READ_DEADLINE)
}

/// [`read_source`] for another text input (`what`, e.g. "reference"), whose refusals name it.
pub fn read_text(path: &Path, what: &str) -> Result<String, ConfigErrors> {
    read_text_within(path, MAX_CONFIG_BYTES, READ_DEADLINE, what)
}

/// [`read_source`] with another size limit and deadline.
pub(crate) fn read_source_within(path: &Path, limit: u64, deadline: Duration) -> Result<String, ConfigErrors> {
    read_text_within(path, limit, deadline, "config")
}

fn read_text_within(path: &Path, limit: u64, deadline: Duration, what: &str) -> Result<String, ConfigErrors> {
    let label = path.display().to_string();
    let meta = std::fs::metadata(path).map_err(|e| refuse(&label, format!("cannot read the {what}: {e}")))?;
    if meta.is_dir() {
        return Err(refuse(&label, format!("is a folder, not a {what} file")));
    }
    let kind = kind_of(&meta);
    if meta.is_file() && meta.len() > limit {
        return Err(refuse(
            &label,
            format!("the file is {}, over the {} limit for a {what} file", size_text(meta.len()), limit_text(limit)),
        ));
    }
    let bytes = read_on_helper(path.to_path_buf(), limit, deadline).map_err(|failure| {
        refuse(
            &label,
            match failure {
                Failure::Io(e) => format!("cannot read the {what}: {e}"),
                Failure::TooLong => {
                    format!("more than the {} limit for a {what} file came from this {kind}", limit_text(limit))
                }
                Failure::Deadline => format!(
                    "this {kind} did not come to an end within {} s (nothing writing to it?); a {what} must be readable at once",
                    deadline.as_secs_f64()
                ),
                Failure::NoThread(e) => format!("cannot read the {what}: no thread to read it on: {e}"),
            },
        )
    })?;
    decode_source(bytes, &label)
}

/// The limit as messages say it.
fn limit_text(limit: u64) -> String {
    if limit == MAX_CONFIG_BYTES { format!("1 MiB ({limit}-byte)") } else { format!("{limit}-byte") }
}

/// Why a read on the helper thread failed.
enum Failure {
    Io(std::io::Error),
    TooLong,
    Deadline,
    NoThread(std::io::Error),
}

/// Opens and reads `path` on a helper thread (the `open` of a FIFO without a writer blocks),
/// at most `limit + 1` bytes, waiting at most `deadline`.
fn read_on_helper(path: PathBuf, limit: u64, deadline: Duration) -> Result<Vec<u8>, Failure> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("config-read".into())
        .spawn(move || {
            let read = File::open(&path).and_then(|file| {
                let mut bytes = Vec::new();
                file.take(limit + 1).read_to_end(&mut bytes).map(|_| bytes)
            });
            // The receiver is gone when the deadline passed: nobody to tell.
            let _ = tx.send(read);
        })
        .map_err(Failure::NoThread)?;
    match rx.recv_timeout(deadline) {
        Ok(Ok(bytes)) if bytes.len() as u64 > limit => Err(Failure::TooLong),
        Ok(Ok(bytes)) => Ok(bytes),
        Ok(Err(e)) => Err(Failure::Io(e)),
        Err(_) => Err(Failure::Deadline),
    }
}

/// A config's bytes as text: a leading byte-order mark skipped, invalid UTF-8 reported at
/// its line and column (characters, as `line_col` counts them) with the offending byte.
pub fn decode_source(mut bytes: Vec<u8>, label: &str) -> Result<String, ConfigErrors> {
    if bytes.starts_with(BOM) {
        bytes.drain(..BOM.len());
    }
    String::from_utf8(bytes).map_err(|e| {
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let valid = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
        let (line, col) = line_col(valid, at);
        let cut = if e.utf8_error().error_len().is_none() { ", a character cut off at the end" } else { "" };
        ConfigErrors(vec![ConfigError {
            path: label.to_string(),
            line,
            col,
            key: String::new(),
            message: format!("not UTF-8 text (byte {:#04x}{cut})", bytes[at]),
        }])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_utf8_is_placed_in_characters() {
        let e = decode_source(b"[walk]\n# \xC3\xA9t\xC3\xA9\nspeed = \xFF\n".to_vec(), "a.toml").unwrap_err();
        assert_eq!(e.to_string(), "a.toml:3:9: not UTF-8 text (byte 0xff)");
        let e = decode_source(b"ab\xE2\x82".to_vec(), "b.toml").unwrap_err();
        assert_eq!(e.to_string(), "b.toml:1:3: not UTF-8 text (byte 0xe2, a character cut off at the end)");
    }

    #[test]
    fn a_bom_is_skipped_and_only_at_the_start() {
        assert_eq!(decode_source(b"\xEF\xBB\xBF[walk]\n".to_vec(), "a").unwrap(), "[walk]\n");
        assert_eq!(decode_source(b"[walk]\n".to_vec(), "a").unwrap(), "[walk]\n");
        assert_eq!(decode_source(b"a\xEF\xBB\xBF".to_vec(), "a").unwrap(), "a\u{feff}");
    }

    #[test]
    fn sizes_read_well() {
        assert_eq!(size_text(200 * 1024 * 1024), "200.0 MiB (209715200 bytes)");
        assert_eq!(size_text(1000), "1000 bytes");
        assert_eq!(limit_text(MAX_CONFIG_BYTES), "1 MiB (1048576-byte)");
    }
}
