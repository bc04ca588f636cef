//! What goes into the lab's state ([`Msg`]) and what it asks of the world ([`Effect`]).

use super::export::Export;
use super::text_input::TextInput;
use crate::model::params::WalkParams;
use ratatui::crossterm::event::{KeyEvent, MouseEvent};
use std::path::PathBuf;

/// What happens to the lab: a key, or the outcome of an effect it asked for.
#[derive(Debug)]
pub enum Msg {
    /// A key press.
    Key(KeyEvent),
    /// A mouse press, drag, release or wheel turn (read against the last frame drawn).
    Mouse(MouseEvent),
    /// A save asked for by [`Effect::Save`] ended.
    Saved {
        /// Where.
        path: PathBuf,
        /// The text written.
        text: String,
        /// How many keys it changed.
        keys: usize,
        /// What the save was for.
        after: AfterSave,
        /// How it went.
        result: Result<(), String>,
    },
    /// A report asked for by [`Effect::Export`] started, or could not.
    ExportStarted(Result<Export, String>),
}

/// What the lab's state asks of the world outside it; the event loop runs these
/// (`tui::effects`) and answers with a [`Msg`]. The state itself writes no file and starts
/// no thread.
#[derive(Debug)]
pub enum Effect {
    /// Write a config.
    Save {
        /// Where.
        path: PathBuf,
        /// The whole text (comments kept, edited keys written in).
        text: String,
        /// How many keys it changes.
        keys: usize,
        /// What to do once it is written.
        after: AfterSave,
    },
    /// Write a report of these parameters on a worker thread.
    Export {
        /// The report folder.
        out: PathBuf,
        /// The name in its summary.
        name: String,
        /// The parameters.
        params: Box<WalkParams>,
        /// The config text written into its config.toml.
        source_text: String,
    },
    /// Remove a file the lab is done with (a loaded or discarded recovery file).
    RemoveFile(PathBuf),
}

/// What a save is for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AfterSave {
    /// `s`: stay.
    Stay,
    /// `s` in the quit dialog: quit once saved.
    Quit,
    /// Save-as: on failure, the old path comes back and the typed path stays in its box.
    SaveAs {
        /// The field as typed.
        typed: TextInput,
        /// The path before.
        old_path: Option<PathBuf>,
    },
}
