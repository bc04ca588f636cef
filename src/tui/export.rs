//! The lab's `e`: a report of the current parameters, written on a worker thread so the lab
//! keeps walking; the thread's stages come back over a channel and show in the status line.

use crate::model::params::WalkParams;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{self, Receiver, TryRecvError};

/// What the report thread tells the lab.
enum ExportMsg {
    Progress(String),
    Done(Result<PathBuf, String>),
}

/// A report being written.
pub struct Export {
    rx: Receiver<ExportMsg>,
}

impl std::fmt::Debug for Export {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Export { .. }")
    }
}

/// What the lab shows after a poll.
pub(crate) struct News {
    /// The status line.
    pub message: String,
    /// The report is finished (written or failed).
    pub done: bool,
}

impl Export {
    /// Starts writing a report into `out`. The place is checked before the walk is run: a
    /// folder that is not a previous report is never replaced, and the lab says why at once.
    pub fn start(out: &Path, name: String, params: &WalkParams, source_text: &str) -> Result<Export, String> {
        let target = crate::report::resolve_out(out, false).map_err(|e| e.to_string())?;
        let out = out.to_path_buf();
        let params = params.clone();
        let source = source_text.to_string();
        let cycles = params.sim.cycles.max(4);
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let input = crate::report::ReportInput {
                name,
                source_text: &source,
                params: &params,
                cycles,
                fps: params.sim.fps,
                compare: Vec::new(),
                ik_solvers: Vec::new(),
            };
            let progress_tx = tx.clone();
            let mut progress = |stage: &str| {
                let _ = progress_tx.send(ExportMsg::Progress(stage.to_string()));
            };
            let result =
                crate::report::write_report(&input, &target, &mut progress).map(|_| out).map_err(|e| e.to_string());
            let _ = tx.send(ExportMsg::Done(result));
        });
        Ok(Export { rx })
    }

    /// The latest news from the thread, if any (several progress lines coalesce into the last).
    #[must_use]
    pub(crate) fn poll(&self) -> Option<News> {
        let mut latest = None;
        loop {
            match self.rx.try_recv() {
                Ok(ExportMsg::Progress(stage)) => {
                    latest = Some(News { message: format!("report: {stage}…"), done: false })
                }
                Ok(ExportMsg::Done(result)) => {
                    let message = match result {
                        Ok(path) => format!("report written to {}", path.display()),
                        Err(e) => format!("report failed: {e}"),
                    };
                    return Some(News { message, done: true });
                }
                Err(TryRecvError::Empty) => return latest,
                Err(TryRecvError::Disconnected) => {
                    return Some(News { message: "report failed: the writer stopped".into(), done: true });
                }
            }
        }
    }
}
