//! A config's problems, each at its place (file or `--set`, line, column, key), and the
//! line/column of a byte offset that places them.

use std::fmt;

/// One problem in a config, at a place.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigError {
    /// The file (or `--set`) the problem is in.
    pub path: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column (characters).
    pub col: usize,
    /// The dotted key, or empty for a syntax error.
    pub key: String,
    /// What is wrong and what would be valid.
    pub message: String,
}

/// How a message about a value begins: it goes on from the key as one sentence ("walk.speed_mps
/// needs a number from 0.4 to 2 m/s, not 9.5"), where others follow it after a colon.
pub(crate) const NEEDS: &str = "needs ";

impl ConfigError {
    /// The key and what is wrong, without the place: what the lab's editor shows.
    #[must_use]
    pub fn what(&self) -> String {
        if self.key.is_empty() {
            self.message.clone()
        } else if self.message.starts_with(NEEDS) {
            format!("{} {}", self.key, self.message)
        } else {
            format!("{}: {}", self.key, self.message)
        }
    }
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: {}", self.path, self.line, self.col, self.what())
    }
}

/// All problems found in one config.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigErrors(pub Vec<ConfigError>);

impl fmt::Display for ConfigErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ConfigErrors {}

/// `at` clamped into `text` and moved back onto a character boundary.
pub(crate) fn char_floor(text: &str, at: usize) -> usize {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// Line and column (1-based, in characters) of byte offset `at` in `text`.
#[must_use]
pub(crate) fn line_col(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..char_floor(text, at)];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}
