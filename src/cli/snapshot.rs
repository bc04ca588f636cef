//! `gaitlab snapshot`: each config's walk against its stored snapshot, as a status line a
//! config and a table of what moved (or JSON lines), with JUnit XML and overlay plots for CI.

use super::common::stdout_written;
use crate::error::{Error, Result};
use crate::output::{self, FileTarget, OutputError};
use crate::snapshot::format::number_text;
use crate::snapshot::junit::{change_text, junit_xml};
use crate::snapshot::{self, Options, Outcome, Tolerances};
use serde_json::json;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// `gaitlab snapshot`'s arguments.
pub(super) struct Args<'a> {
    pub(super) paths: &'a [PathBuf],
    pub(super) update: bool,
    pub(super) json: bool,
    pub(super) junit: Option<&'a Path>,
    pub(super) tolerance: Option<&'a Path>,
    pub(super) plot: Option<&'a Path>,
    pub(super) sets: &'a [String],
}

pub(super) fn run(args: &Args<'_>) -> Result<()> {
    let tolerances = match args.tolerance {
        Some(path) => Tolerances::load(path, &snapshot::known_keys())?,
        None => Tolerances::default(),
    };
    // Output places are checked before anything is walked (the output rule).
    let junit = args.junit.map(FileTarget::resolve).transpose()?;
    if let Some(dir) = args.plot
        && dir.exists()
        && !dir.is_dir()
    {
        return Err(Error::Output(OutputError::Refused(format!("--plot {}: not a folder", dir.display()))));
    }
    output::pending::remove_on_signal()
        .map_err(|e| Error::Output(OutputError::Failed(format!("cannot watch signals: {e}"))))?;
    let options = Options { update: args.update, tolerances, sets: args.sets.to_vec() };
    let outcomes = snapshot::run(args.paths, &options)?;
    let mut plots = vec![None; outcomes.len()];
    if let Some(dir) = args.plot {
        for (plot, outcome) in plots.iter_mut().zip(&outcomes).filter(|(_, o)| !o.moved.is_empty()) {
            *plot = snapshot::write_plot(dir, outcome)?;
        }
    }
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let written = if args.json { write_json(&mut out, &outcomes, &plots) } else { write_table(&mut out, &outcomes) };
    stdout_written(written.and_then(|()| out.flush()))?;
    if let Some(target) = &junit {
        let xml = junit_xml(&outcomes);
        output::write_file(target, |out| out.write_all(xml.as_bytes()))?;
    }
    let failed: Vec<String> = outcomes
        .iter()
        .filter(|o| o.failed())
        .map(|o| format!("{} ({})", o.config.display(), o.status.name()))
        .collect();
    if failed.is_empty() {
        return Ok(());
    }
    Err(Error::Snapshot(format!(
        "{} of {} configs failed: {}; `gaitlab snapshot --update` accepts the walks as they are now (review the diff)",
        failed.len(),
        outcomes.len(),
        failed.join(", ")
    )))
}

/// One JSON object a line, one a config.
fn write_json(out: &mut dyn Write, outcomes: &[Outcome], plots: &[Option<PathBuf>]) -> io::Result<()> {
    for (o, plot) in outcomes.iter().zip(plots) {
        let moved: Vec<serde_json::Value> = o
            .moved
            .iter()
            .map(|m| {
                let change = m.change();
                json!({
                    "metric": m.metric,
                    "old": m.old,
                    "new": m.new,
                    "change": change.is_finite().then(|| snapshot::measure::kind_of(&m.key).round(change)),
                    "allowed": m.allowed,
                })
            })
            .collect();
        let mut line = json!({
            "config": o.config.display().to_string(),
            "status": o.status.name(),
            "snapshot": o.snapshot.display().to_string(),
            "moved": moved,
        });
        if let Some(plot) = plot {
            line["plot"] = json!(plot.display().to_string());
        }
        writeln!(out, "{line}")?;
    }
    Ok(())
}

/// A status line a config, then a table of every figure that moved.
fn write_table(out: &mut dyn Write, outcomes: &[Outcome]) -> io::Result<()> {
    for o in outcomes {
        let note = match o.status {
            snapshot::Status::Ok => String::new(),
            snapshot::Status::Drift => format!("  {} moved", o.moved.len()),
            snapshot::Status::Missing => format!("  no {} (--update writes it)", o.snapshot.display()),
            snapshot::Status::Updated if o.old.is_none() => format!("  wrote {}", o.snapshot.display()),
            snapshot::Status::Updated => format!("  rewrote {} ({} moved)", o.snapshot.display(), o.moved.len()),
        };
        writeln!(out, "{:<8} {}{note}", o.status.name(), o.config.display())?;
    }
    let value = |key: &str, x: Option<f64>| x.map_or_else(|| "none".to_string(), |x| number_text(key, x));
    let mut rows = vec![["config", "metric", "old", "new", "change", "allowed"].map(String::from)];
    for o in outcomes {
        for m in &o.moved {
            rows.push([
                o.config.display().to_string(),
                m.metric.clone(),
                value(&m.key, m.old),
                value(&m.key, m.new),
                change_text(m),
                number_text(&m.key, m.allowed),
            ]);
        }
    }
    if rows.len() == 1 {
        return Ok(());
    }
    let widths: Vec<usize> = (0..6).map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0)).collect();
    writeln!(out)?;
    for row in &rows {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(c, (cell, w))| if c < 2 { format!("{cell:<w$}") } else { format!("{cell:>w$}") })
            .collect();
        writeln!(out, "{}", cells.join("  ").trim_end())?;
    }
    Ok(())
}
