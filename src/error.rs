//! The library's one error type, and how each kind maps onto the interface's exit codes:
//! 2 for bad input (usage, a config, a walk its parameters cannot make, an output place
//! gaitlab may not write), 1 for a failure while running.

use crate::config::ConfigErrors;
use crate::model::walk::ModelError;
use crate::output::OutputError;
use crate::report::metrics::TooShort;
use std::io;
use std::path::PathBuf;

/// Everything that can stop a gaitlab command.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A config (file or `--set`) has problems: every one, located (`PATH:LINE:COL: key: …`).
    #[error("{0}")]
    Config(#[from] ConfigErrors),
    /// A config's parameters do not make a walk.
    #[error("{}: {source}", config.display())]
    Walk {
        /// The config.
        config: PathBuf,
        /// Why.
        #[source]
        source: ModelError,
    },
    /// Parameters that do not make a walk, with no file to name.
    #[error("{0}")]
    Model(#[from] ModelError),
    /// A run too short to measure.
    #[error("{0}")]
    TooShort(#[from] TooShort),
    /// An output that may not be written (exit 2) or that failed (exit 1).
    #[error("{0}")]
    Output(#[from] OutputError),
    /// Writing to a stream failed (a closed pipe is not an error: see `cli`).
    #[error("cannot write to {target}: {source}")]
    Write {
        /// Where (`stdout`).
        target: &'static str,
        /// Why.
        #[source]
        source: io::Error,
    },
    /// A command-line value clap cannot check: a range, a name.
    #[error("{0}")]
    Usage(String),
    /// Snapshots that drifted or are missing (`gaitlab snapshot`): a failed test, exit 1.
    #[error("{0}")]
    Snapshot(String),
}

impl Error {
    /// The exit code the interface gives this error.
    #[must_use]
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::Config(_) | Error::Walk { .. } | Error::Model(_) | Error::Usage(_) => 2,
            Error::Output(e) => u8::try_from(e.exit_code()).unwrap_or(1),
            Error::TooShort(_) | Error::Write { .. } | Error::Snapshot(_) => 1,
        }
    }
}

/// Results of the library's fallible operations.
pub type Result<T, E = Error> = std::result::Result<T, E>;
