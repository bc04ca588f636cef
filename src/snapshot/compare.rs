//! A walk against its snapshot: which figures moved further than their tolerance.

use super::measure::{POINTS, Snapshot, kind_of};
use super::tolerance::{Kind, Tolerances};
use std::path::PathBuf;

/// A figure that moved further than allowed (or is only on one side).
#[derive(Clone, Debug, PartialEq)]
pub struct Moved {
    /// The figure's key; a curve's as `knee_flex_r_deg at 62 %` (its point that moved most).
    pub metric: String,
    /// The key its tolerance and rounding go by (the curve's name for a curve point).
    pub key: String,
    /// The snapshot's value (`None`: the snapshot has no such figure).
    pub old: Option<f64>,
    /// This walk's value (`None`: the walk no longer has the figure).
    pub new: Option<f64>,
    /// How far it may move.
    pub allowed: f64,
}

impl Moved {
    /// `new − old` (NaN when either is missing).
    #[must_use]
    pub fn change(&self) -> f64 {
        match (self.old, self.new) {
            (Some(old), Some(new)) => new - old,
            _ => f64::NAN,
        }
    }
}

/// What became of one config.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Within tolerance of its snapshot.
    Ok,
    /// Moved further than allowed (not rewritten: no `--update`).
    Drift,
    /// No snapshot yet (not written: no `--update`).
    Missing,
    /// Written with `--update`: it was missing, unreadable or drifted.
    Updated,
}

impl Status {
    /// The name `--json` and the table print.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Drift => "drift",
            Status::Missing => "missing",
            Status::Updated => "updated",
        }
    }
}

/// One config's result.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The config, as given or found.
    pub config: PathBuf,
    /// Its snapshot file.
    pub snapshot: PathBuf,
    /// What became of it.
    pub status: Status,
    /// What moved (also for an updated snapshot: what the update accepted).
    pub moved: Vec<Moved>,
    /// The snapshot before this run, when there was a readable one.
    pub old: Option<Snapshot>,
    /// This walk.
    pub new: Snapshot,
    /// Seconds spent walking and measuring the config.
    pub seconds: f64,
}

impl Outcome {
    /// Whether this config fails the run (drifted or missing, without `--update`).
    #[must_use]
    pub fn failed(&self) -> bool {
        matches!(self.status, Status::Drift | Status::Missing)
    }
}

/// Whether `new` is further from `old` than `allowed` (rounding noise of the stored
/// decimals aside); NaN matches only NaN.
fn exceeds(old: f64, new: f64, allowed: f64) -> bool {
    if old.is_nan() || new.is_nan() {
        return old.is_nan() != new.is_nan();
    }
    let slack = 1e-9 * (allowed + old.abs().max(new.abs()));
    (new - old).abs() > allowed + slack
}

/// The figures of `new` that moved from `old` further than `tolerances` allow, in the
/// snapshot's order: the walk's cycles and frame rate, the summary, then each curve's worst
/// point.
#[must_use]
pub fn compare(old: &Snapshot, new: &Snapshot, tolerances: &Tolerances) -> Vec<Moved> {
    let mut moved = Vec::new();
    // Which cycles were measured (a schedule's plateau, the cycles on stairs or a slope): the
    // figures after it mean something else when it moves, however little they change.
    if old.steady_part != new.steady_part {
        let say =
            |part: &Option<String>| part.as_deref().map_or_else(|| "every cycle".to_string(), |p| format!("\"{p}\""));
        moved.push(Moved {
            metric: format!("steady part: {} (was {})", say(&new.steady_part), say(&old.steady_part)),
            key: "steady_part".into(),
            old: None,
            new: None,
            allowed: 0.0,
        });
    }
    let mut check = |metric: String, key: &str, old: Option<f64>, new: Option<f64>| {
        let allowed = tolerances.allowed(key, kind_of(key), old.or(new).unwrap_or(0.0));
        let drifted = match (old, new) {
            (Some(a), Some(b)) => exceeds(a, b, allowed),
            _ => true,
        };
        if drifted {
            moved.push(Moved { metric, key: key.to_string(), old, new, allowed });
        }
    };
    check("sim.cycles".into(), "sim_cycles", Some(f64::from(old.cycles)), Some(f64::from(new.cycles)));
    check("sim.fps".into(), "sim_fps", Some(old.fps), Some(new.fps));
    let find = |list: &[(String, f64)], key: &str| list.iter().find(|(k, _)| k == key).map(|(_, x)| *x);
    for (key, x) in &new.summary {
        check(key.clone(), key, find(&old.summary, key), Some(*x));
    }
    for (key, x) in old.summary.iter().filter(|(k, _)| find(&new.summary, k).is_none()) {
        check(key.clone(), key, Some(*x), None);
    }
    for (name, points) in &new.curves {
        match old.curves.iter().find(|(k, _)| k == name) {
            Some((_, before)) if before.len() == points.len() => {
                let allowed = tolerances.allowed(name, Kind::Angle, 0.0);
                let worst = (0..points.len())
                    .filter(|&i| exceeds(before[i], points[i], allowed))
                    .max_by(|&i, &j| (points[i] - before[i]).abs().total_cmp(&(points[j] - before[j]).abs()));
                if let Some(i) = worst {
                    let pct = 100.0 * i as f64 / (POINTS - 1) as f64;
                    check(format!("{name} at {pct:.0} %"), name, Some(before[i]), Some(points[i]));
                }
            }
            _ => check(format!("{name} (curve)"), name, None, points.first().copied()),
        }
    }
    moved
}

#[cfg(test)]
mod tests {
    use super::*;

    fn snapshot(speed: f64, knee: f64) -> Snapshot {
        Snapshot {
            config: "a.toml".into(),
            cycles: 10,
            fps: 60.0,
            summary: vec![("speed_mps".into(), speed), ("reach_failures".into(), 0.0)],
            curves: vec![("knee_flex_r_deg".into(), vec![0.0, knee, 1.0])],
            steady_part: None,
        }
    }

    #[test]
    fn only_what_moved_past_its_tolerance_is_listed() {
        let t = Tolerances::default();
        assert!(compare(&snapshot(1.3, 5.0), &snapshot(1.3001, 5.05), &t).is_empty());
        let moved = compare(&snapshot(1.3, 5.0), &snapshot(1.3002, 5.1), &t);
        let names: Vec<&str> = moved.iter().map(|m| m.metric.as_str()).collect();
        assert_eq!(names, ["speed_mps", "knee_flex_r_deg at 2 %"]);
        assert!((moved[1].change() - 0.1).abs() < 1e-12 && moved[1].allowed == 0.05);
    }

    #[test]
    fn a_different_part_measured_is_a_drift_even_with_the_same_figures() {
        let t = Tolerances::default();
        let stairs = |cycles: u32| Snapshot {
            steady_part: Some(format!("4.08–8.17 s, {cycles} cycles on the stairs (level walking left out)")),
            ..snapshot(0.5, 60.0)
        };
        assert!(compare(&stairs(3), &stairs(3), &t).is_empty());
        let moved = compare(&stairs(2), &stairs(3), &t);
        assert_eq!(moved.len(), 1);
        assert_eq!(moved[0].key, "steady_part");
        assert!(moved[0].metric.contains("3 cycles") && moved[0].metric.contains("(was \"4.08–8.17 s, 2 cycles"));
        let level = compare(&snapshot(0.5, 60.0), &stairs(3), &t);
        assert!(level[0].metric.ends_with("(was every cycle)"), "{}", level[0].metric);
    }
}
