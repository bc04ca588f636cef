//! Recovery files: the lab's unsaved edits, kept when it is cut off (a dropped SSH link, a
//! signal) so that the next start of the same config can offer them back.
//!
//! The file sits beside the config as `NAME.toml.recovery` — not `*.toml`, so that globs over
//! a folder of configs (the snapshot corpus, `gaitlab check configs/*.toml`) never take it
//! for a config. Its content is exactly what `s` would have saved (the config's text with the
//! edited keys written in, comments kept), so it is also a valid config by itself. The
//! embedded default has no file beside it; its recovery goes to
//! `$XDG_STATE_HOME/gaitlab/embedded-default.toml.recovery` (or `~/.local/state/gaitlab/…`).
//! The saved config itself is never touched.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::SystemTime;

/// The state folder [`use_state_folder`] set for this process, if any.
static STATE_FOLDER: OnceLock<PathBuf> = OnceLock::new();

/// Keeps the embedded default's recovery under `folder` instead of the user's state folder,
/// for the rest of the process (the first call wins). The lab's tests open the embedded
/// default in-process: a recovery file the developer's own lab left behind (a hang-up with
/// unsaved edits) opened its overlay in front of every one of them and failed a dozen.
#[doc(hidden)]
pub fn use_state_folder(folder: PathBuf) {
    let _ = STATE_FOLDER.set(folder);
}

/// The suffix added to the config's file name.
pub(crate) const SUFFIX: &str = ".recovery";

/// Where the recovery of `config` goes (`None` config: the embedded default; `None` result:
/// no place is known, as without `$HOME`).
#[must_use]
pub(crate) fn path_for(config: Option<&Path>) -> Option<PathBuf> {
    match config {
        Some(path) => {
            let name = path.file_name()?.to_string_lossy().into_owned();
            Some(path.with_file_name(format!("{name}{SUFFIX}")))
        }
        None => {
            let state = STATE_FOLDER.get().cloned().or_else(|| {
                std::env::var_os("XDG_STATE_HOME").filter(|v| !v.is_empty()).map(PathBuf::from).or_else(|| {
                    std::env::var_os("HOME").filter(|v| !v.is_empty()).map(|h| Path::new(&h).join(".local/state"))
                })
            })?;
            Some(state.join("gaitlab").join(format!("embedded-default.toml{SUFFIX}")))
        }
    }
}

/// A recovery file found at start.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// Where it is.
    pub path: PathBuf,
    /// Its text (a whole config).
    pub text: String,
    /// How long ago it was written, in words ("4 min ago").
    pub(crate) age: String,
}

/// The recovery file of `config`, if there is one to offer.
#[must_use]
pub fn find(config: Option<&Path>) -> Option<Found> {
    let path = path_for(config)?;
    let meta = std::fs::metadata(&path).ok()?;
    if !meta.is_file() || meta.len() > crate::config::MAX_CONFIG_BYTES {
        return None;
    }
    let text = std::fs::read_to_string(&path).ok()?;
    let age = meta
        .modified()
        .ok()
        .and_then(|t| SystemTime::now().duration_since(t).ok())
        .map_or_else(|| "at an unknown time".into(), |d| age_words(d.as_secs()));
    Some(Found { path, text, age })
}

fn age_words(secs: u64) -> String {
    match secs {
        0..60 => "less than a minute ago".into(),
        60..7200 => format!("{} min ago", secs / 60),
        7200..172_800 => format!("{} hours ago", secs / 3600),
        _ => format!("{} days ago", secs / 86_400),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_recovery_sits_beside_the_config_and_is_not_a_toml_file() {
        assert_eq!(path_for(Some(Path::new("configs/mine.toml"))), Some(PathBuf::from("configs/mine.toml.recovery")));
        assert_eq!(path_for(Some(Path::new("walk"))), Some(PathBuf::from("walk.recovery")));
    }

    #[test]
    fn ages_read_as_words() {
        assert_eq!(age_words(5), "less than a minute ago");
        assert_eq!(age_words(250), "4 min ago");
        assert_eq!(age_words(4 * 3600), "4 hours ago");
        assert_eq!(age_words(3 * 86_400), "3 days ago");
    }
}
