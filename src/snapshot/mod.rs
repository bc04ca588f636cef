//! Snapshot tests for walks (`gaitlab snapshot`): each config's summary figures and mean joint
//! curves, stored beside it as `NAME.snap.json`, compared with the walk it makes today.
//!
//! - A config is a file, or every `*.toml` directly in a folder (sorted; `*.toml.recovery`
//!   and `*.snap.json` are not configs).
//! - The walk is the config's own (`sim.cycles`, 4 to 1000, at `sim.fps`, `--set` applied);
//!   the figures are the report's summary ([`crate::report::metrics::summarise`]) and the
//!   mean over the steady cycles of hip, knee and ankle angles of both legs and the pelvis's
//!   tilt, obliquity and rotation, at every 2 % of the right gait cycle ([`measure`]).
//! - Numbers are stored and compared as the report's tables round them, and a figure drifts
//!   when it moves further than its tolerance ([`tolerance`] has the defaults and the
//!   `--tolerance FILE` format). A missing snapshot fails (as `insta --ci` does); `update`
//!   writes missing and drifted ones (a snapshot within tolerance is left as it is).
//! - Configs are walked in parallel, at most one thread a core.
//!
//! This is also how the project checks its own `configs/` (`tests/snapshot.rs`).

pub mod compare;
pub mod format;
pub mod junit;
pub mod measure;
pub mod tolerance;

pub use compare::{Moved, Outcome, Status, compare};
pub use measure::{CURVES, POINTS, Snapshot};
pub use tolerance::{Kind, Tolerances};

use crate::config::{self, ConfigErrors};
use crate::error::{Error, Result};
use crate::model::params::WalkParams;
use crate::output::{self, OutputError};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// How a run goes.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Write missing and drifted snapshots instead of failing.
    pub update: bool,
    /// The tolerances (the defaults, or a file's).
    pub tolerances: Tolerances,
    /// `--set KEY=VALUE` overrides, applied to every config.
    pub sets: Vec<String>,
}

/// The snapshot file of `config`: `NAME.snap.json` beside `NAME.toml`.
#[must_use]
pub fn snapshot_path(config: &Path) -> PathBuf {
    let stem = config.file_stem().map_or_else(|| "config".into(), |s| s.to_string_lossy().into_owned());
    config.with_file_name(format!("{stem}.snap.json"))
}

/// Keys a tolerance file may name beside the kinds: every summary figure and curve.
#[must_use]
pub fn known_keys() -> Vec<&'static str> {
    let summary = crate::report::metrics::LABELS.iter().map(|(key, _, _)| *key);
    summary.chain(CURVES).chain(["sim_cycles", "sim_fps"]).collect()
}

/// The configs `paths` name: each file as given, each folder's `*.toml` files (sorted),
/// every config once. A path that is not there is bad input.
pub fn configs_in(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut configs: Vec<PathBuf> = Vec::new();
    for path in paths {
        let meta = std::fs::metadata(path).map_err(|e| Error::Usage(format!("{}: {e}", path.display())))?;
        if !meta.is_dir() {
            configs.push(path.clone());
            continue;
        }
        let entries = std::fs::read_dir(path).map_err(|e| Error::Usage(format!("{}: {e}", path.display())))?;
        let mut found: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml") && p.is_file())
            .collect();
        if found.is_empty() {
            return Err(Error::Usage(format!("{}: no *.toml configs in this folder", path.display())));
        }
        found.sort();
        configs.extend(found);
    }
    let mut seen = std::collections::BTreeSet::new();
    configs.retain(|c| seen.insert(c.clone()));
    Ok(configs)
}

/// Snapshots every config `paths` names ([`configs_in`]): loads them all (every problem of
/// every config reported at once, nothing walked or written then), walks them in parallel,
/// compares, and with [`Options::update`] writes what is missing or drifted.
pub fn run(paths: &[PathBuf], options: &Options) -> Result<Vec<Outcome>> {
    let configs = configs_in(paths)?;
    let mut loaded = Vec::with_capacity(configs.len());
    let mut problems = Vec::new();
    for path in configs {
        match config::load(&path, &options.sets) {
            Ok(params) => loaded.push((path, params)),
            // A `--set` problem shared by several configs is listed once.
            Err(e) => problems.extend(e.0.into_iter().filter(|p| !problems.contains(p)).collect::<Vec<_>>()),
        }
    }
    if !problems.is_empty() {
        return Err(Error::Config(ConfigErrors(problems)));
    }
    let mut stored = Vec::with_capacity(loaded.len());
    for (path, _) in &loaded {
        stored.push(read_snapshot(&snapshot_path(path), options.update)?);
    }
    let measured = measure_all(&loaded);
    let mut outcomes = Vec::with_capacity(loaded.len());
    for (((path, _), old), result) in loaded.into_iter().zip(stored).zip(measured) {
        let (new, seconds) = result?;
        outcomes.push(settle(path, old, new, seconds, options)?);
    }
    Ok(outcomes)
}

/// The snapshot stored at `path`: `None` when there is none, or (with `update`, which will
/// replace it) when it cannot be read.
fn read_snapshot(path: &Path, update: bool) -> Result<Option<Snapshot>> {
    if std::fs::symlink_metadata(path).is_err() {
        return Ok(None);
    }
    let read = config::read_source(path).and_then(|text| format::parse(&text, &path.display().to_string()));
    match read {
        Ok(snapshot) => Ok(Some(snapshot)),
        Err(_) if update => Ok(None),
        Err(e) => Err(Error::Config(e)),
    }
}

/// Walks and measures every config, in parallel (at most one thread a core); each result
/// with the seconds it took, in the configs' order.
fn measure_all(loaded: &[(PathBuf, WalkParams)]) -> Vec<Result<(Snapshot, f64)>> {
    let threads = std::thread::available_parallelism().map_or(1, std::num::NonZero::get).min(loaded.len()).max(1);
    let next = AtomicUsize::new(0);
    let mut results: Vec<Option<Result<(Snapshot, f64)>>> = (0..loaded.len()).map(|_| None).collect();
    std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        let Some((path, params)) = loaded.get(i) else { break };
                        let started = std::time::Instant::now();
                        let result = measure::measure(path, params);
                        mine.push((i, result.map(|s| (s, started.elapsed().as_secs_f64()))));
                    }
                    mine
                })
            })
            .collect();
        for worker in workers {
            let done = worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            for (i, result) in done {
                results[i] = Some(result);
            }
        }
    });
    results.into_iter().map(|r| r.expect("every config is taken by a worker")).collect()
}

/// Compares one config's walk with its snapshot and, with `update`, writes the snapshot
/// when it is missing or drifted.
fn settle(config: PathBuf, old: Option<Snapshot>, new: Snapshot, seconds: f64, options: &Options) -> Result<Outcome> {
    let snapshot = snapshot_path(&config);
    let moved = old.as_ref().map(|old| compare(old, &new, &options.tolerances)).unwrap_or_default();
    let status = match (&old, moved.is_empty(), options.update) {
        (Some(_), true, _) => Status::Ok,
        (None, _, false) => Status::Missing,
        (Some(_), false, false) => Status::Drift,
        (_, _, true) => {
            let text = format::render(&new);
            output::write_atomic(&snapshot, |out| out.write_all(text.as_bytes()))?;
            Status::Updated
        }
    };
    Ok(Outcome { config, snapshot, status, moved, old, new, seconds })
}

/// Writes `outcome`'s overlay plot (the stored curves against this walk's, the moved figures
/// listed) as `DIR/<config stem>.png`, 1600x1000; returns its path. Only for an outcome with
/// a stored snapshot.
pub fn write_plot(dir: &Path, outcome: &Outcome) -> Result<Option<PathBuf>> {
    let Some(old) = &outcome.old else { return Ok(None) };
    let curves: Vec<crate::report::plots::Overlay<'_>> = outcome
        .new
        .curves
        .iter()
        .filter_map(|(name, new)| {
            let (_, stored) = old.curves.iter().find(|(k, _)| k == name)?;
            Some((name.as_str(), stored.as_slice(), new.as_slice()))
        })
        .collect();
    let notes: Vec<String> = outcome
        .moved
        .iter()
        .flat_map(|m| {
            let value = |x: Option<f64>| x.map_or_else(|| "none".to_string(), |x| format::number_text(&m.key, x));
            let allowed = format::number_text(&m.key, m.allowed);
            let change = junit::change_text(m);
            [m.metric.clone(), format!("    {} -> {}  ({change}; allowed {allowed})", value(m.old), value(m.new))]
        })
        .collect();
    let title = format!("{}: snapshot vs this walk (mean of the steady cycles)", outcome.config.display());
    let png = crate::report::plots::overlay_png(&title, &curves, &notes)
        .map_err(|e| Error::Output(OutputError::Failed(format!("{}: {e}", outcome.config.display()))))?;
    let stem = outcome.config.file_stem().map_or_else(|| "config".into(), |s| s.to_string_lossy().into_owned());
    let path = dir.join(format!("{stem}.png"));
    output::write_atomic(&path, |out| out.write_all(&png))?;
    Ok(Some(path))
}
