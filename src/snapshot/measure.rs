//! What a snapshot holds of a walk, measured: the report's summary figures and the mean joint
//! curves over the right gait cycle, each rounded as the snapshot file stores it.

use super::tolerance::Kind;
use crate::analysis::{self, Run};
use crate::error::{Error, Result};
use crate::model::params::WalkParams;
use crate::model::walk::frame::Frame;
use crate::report::metrics::{self, LABELS, Summary, TooShort};
use std::path::Path;

/// The joint curves a snapshot keeps, named as the joint table's columns.
pub const CURVES: [&str; 9] = [
    "hip_flex_r_deg",
    "knee_flex_r_deg",
    "ankle_dorsi_r_deg",
    "hip_flex_l_deg",
    "knee_flex_l_deg",
    "ankle_dorsi_l_deg",
    "pelvis_tilt_deg",
    "pelvis_obliquity_deg",
    "pelvis_rotation_deg",
];

/// Points of each curve: 0 to 100 % of the right gait cycle, every 2 %.
pub const POINTS: usize = 51;

/// Gait cycles a snapshot may walk (the config's `sim.cycles`): the first is start-up, and a
/// snapshot records every frame, as a report does.
pub const CYCLES: std::ops::RangeInclusive<u32> = 4..=1000;

/// One config's figures as a snapshot file holds them (every number rounded as stored).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// The config's file name (no folder: snapshots move with their configs).
    pub config: String,
    /// Gait cycles walked (the config's `sim.cycles`).
    pub cycles: u32,
    /// Frames per second (the config's `sim.fps`).
    pub fps: f64,
    /// The summary figures (`summary.json`'s keys), in the interface's order.
    pub summary: Vec<(String, f64)>,
    /// The mean joint curves ([`CURVES`], [`POINTS`] each).
    pub curves: Vec<(String, Vec<f64>)>,
    /// Which part of the walk the figures and curves were measured on, for a walk that was
    /// not steady throughout (its pace changed or it stopped): "6.42–8.37 s, the 1.60 m/s
    /// plateau, 2 cycles"; `None` (and not written) for a walk steady throughout.
    pub steady_part: Option<String>,
}

/// The kind of figure `key` (its tolerance and rounding); a key without a known unit is
/// treated as a cost (compared relatively).
#[must_use]
pub fn kind_of(key: &str) -> Kind {
    Kind::of(key).unwrap_or(Kind::Cost)
}

/// Walks the config at `path` (already loaded as `params`) for its `sim.cycles` at its
/// `sim.fps` and measures it.
pub fn measure(path: &Path, params: &WalkParams) -> Result<Snapshot> {
    let cycles = params.sim.cycles;
    if !CYCLES.contains(&cycles) {
        return Err(Error::Usage(format!(
            "{}: sim.cycles {cycles} is out of range for a snapshot; valid: {} to {} (e.g. --set sim.cycles=10)",
            path.display(),
            CYCLES.start(),
            CYCLES.end()
        )));
    }
    let run = analysis::run(params, f64::from(cycles), params.sim.fps)
        .map_err(|source| Error::Walk { config: path.to_path_buf(), source })?;
    let summary = metrics::summarise(&run).map_err(|e| TooShort(format!("{}: {e}", path.display())))?;
    recorded(path, cycles, &run, &summary)
}

/// A walk already recorded (`cycles` of the config at `path`) and summarised, measured as
/// [`measure`] measures it: the report compares its own recording with the norms through
/// this, so that its figures are `gaitlab compare`'s without a second walk.
pub fn recorded(path: &Path, cycles: u32, run: &Run, summary: &Summary) -> Result<Snapshot> {
    let too_short = |e: TooShort| TooShort(format!("{}: {e}", path.display()));
    let value = serde_json::to_value(summary).map_err(|e| Error::Usage(e.to_string()))?;
    let summary = LABELS
        .iter()
        .map(|(key, _, _)| {
            let x = value[*key].as_f64().unwrap_or(f64::NAN);
            ((*key).to_string(), kind_of(key).round(x))
        })
        .collect();
    let window = metrics::steady_window(run).map_err(too_short)?;
    let curves = mean_curves(&run.frames, &window.strikes);
    Ok(Snapshot {
        config: path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
        cycles,
        fps: run.fps,
        summary,
        curves: CURVES
            .iter()
            .zip(curves)
            .map(|(name, points)| ((*name).to_string(), points.iter().map(|&x| Kind::Angle.round(x)).collect()))
            .collect(),
        steady_part: window.describe(),
    })
}

/// Curve `c` of [`CURVES`] at frame `f`.
fn curve_value(f: &Frame, c: usize) -> f64 {
    let (r, l) = (&f.legs[0], &f.legs[1]);
    match c {
        0 => r.hip_flex_deg,
        1 => r.knee_flex_deg,
        2 => r.ankle_dorsi_deg,
        3 => l.hip_flex_deg,
        4 => l.knee_flex_deg,
        5 => l.ankle_dorsi_deg,
        6 => f.pelvis_tilt_deg,
        7 => f.pelvis_obliquity_deg,
        _ => f.pelvis_rotation_deg,
    }
}

/// Each of [`CURVES`] at [`POINTS`] points of the right gait cycle (linear between frames),
/// the mean over the steady cycles (those the summary measures: heel strikes `strikes`).
fn mean_curves(frames: &[Frame], strikes: &[usize]) -> Vec<Vec<f64>> {
    let mut sums = vec![vec![0.0; POINTS]; CURVES.len()];
    for w in strikes.windows(2) {
        let (t0, t1) = (frames[w[0]].time_s, frames[w[1]].time_s);
        let mut i = w[0];
        for p in 0..POINTS {
            let t = t0 + (t1 - t0) * p as f64 / (POINTS - 1) as f64;
            while i + 1 < w[1] && frames[i + 1].time_s <= t {
                i += 1;
            }
            let (a, b) = (&frames[i], &frames[i + 1]);
            let s = if b.time_s > a.time_s { ((t - a.time_s) / (b.time_s - a.time_s)).clamp(0.0, 1.0) } else { 0.0 };
            for (c, sum) in sums.iter_mut().enumerate() {
                sum[p] += curve_value(a, c) * (1.0 - s) + curve_value(b, c) * s;
            }
        }
    }
    let cycles = (strikes.len() - 1) as f64;
    sums.into_iter().map(|sum| sum.into_iter().map(|x| x / cycles).collect()).collect()
}
