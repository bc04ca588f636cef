//! Why an output could not be written, and which exit code that is.

use std::fmt;
use std::io;
use std::path::Path;

/// Why an output could not be written.
#[derive(Debug)]
pub enum OutputError {
    /// The target is not something gaitlab may write (exit 2): nothing was touched.
    Refused(String),
    /// Writing failed part-way (exit 1): temps were removed, the target is as it was.
    Failed(String),
}

impl OutputError {
    /// The exit code for this error: 2 for a refused target (bad input), 1 for a failure.
    #[must_use]
    pub fn exit_code(&self) -> i32 {
        match self {
            OutputError::Refused(_) => 2,
            OutputError::Failed(_) => 1,
        }
    }

    pub(crate) fn io(path: &Path, what: &str, e: &io::Error) -> Self {
        OutputError::Failed(format!("cannot {what} {}: {e}", path.display()))
    }
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OutputError::Refused(m) | OutputError::Failed(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for OutputError {}
