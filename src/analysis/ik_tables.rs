//! Seed 002's error tables for the leg solvers (issue 15, point 2): per solver and side, the
//! figures of the seed's tables 5.1–5.3, judged against the thresholds of its §5.2.
//!
//! The seed animates an arm from two trackers (forearm, upper arm) and tabulates, per motion
//! and arm, how far each virtual tracker stays from the object leading it, how far its axes
//! turn from that object's, and how far it moves between frames. A leg has one target (the
//! ankle) and four angles, so:
//! - **tables 5.1 and 5.2** (forearm and upper-arm tracker: max and mean distance, and the
//!   per-axis angle difference as vectors of max and mean) become one table: the ankle's
//!   distance from its target, and each leg angle's difference from the analytic answer's —
//!   the analytic solver is exact, so it is the leading object;
//! - **table 5.3** (forearm and upper-arm tracker travel between consecutive frames, max and
//!   mean) becomes the knee's and the ankle's jump, beside their jitter (the jump the solver
//!   adds to the walk's, see [`crate::analysis::ik`]).
//!
//! The jump threshold is judged on the jitter, not on the raw jump: the seed's arm exercises
//! were slow, so its raw travel was its jitter, whereas a walking swing ankle moves ~70 mm a
//! frame at 60 fps with an exact solver.

use crate::analysis::ik::{IkTarget, SolverRun};
use crate::model::body::Side;
use crate::model::ik::IkSolverKind;

/// Largest per-axis angle error that passes (deg). Seed 002 §5.2: "it was verified
/// experimentally that with deviations under five degrees the results can be declared
/// matching" (its tables 5.1–5.2 stay under 2.3°).
pub const ANGLE_ERROR_MAX_DEG: f64 = 5.0;

/// Largest jitter between consecutive frames that passes (mm/frame). Seed 002 §5.2: jumps
/// "under one centimetre will correspond to the motion within the animation" (table 5.3).
pub const JUMP_MAX_MM: f64 = 10.0;

/// Largest mean position error that passes (mm). Issue 15 reads seed 002's "5 mm mean" this
/// way; the seed itself (§5.2, table 5.3) states it for the mean jump — "as all mean jumps are
/// under five millimetres, the motion stays smooth" — and sets no bound on tracker distance.
pub const POSITION_ERROR_MEAN_MAX_MM: f64 = 5.0;

/// The leg angles, in [`crate::model::ik::LegAngles::to_array`] order.
pub const ANGLE_NAMES: [&str; 4] = ["hip flexion", "hip abduction", "hip rotation", "knee flexion"];

/// One solver's tables, a leg each.
pub type SolverSides = (IkSolverKind, Vec<SideTable>);

/// A max and a mean.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MaxMean {
    /// Largest value.
    pub max: f64,
    /// Mean value.
    pub mean: f64,
}

/// Accumulates a [`MaxMean`].
#[derive(Clone, Copy, Debug, Default)]
struct Acc {
    max: f64,
    sum: f64,
    n: usize,
}

impl Acc {
    fn add(&mut self, x: f64) {
        self.max = self.max.max(x);
        self.sum += x;
        self.n += 1;
    }

    fn done(self) -> MaxMean {
        MaxMean { max: self.max, mean: self.sum / self.n.max(1) as f64 }
    }
}

/// One solver's figures on one leg, in seed 002's form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideTable {
    /// The leg.
    pub side: Side,
    /// Solves of this leg.
    pub solves: usize,
    /// Ankle to target (mm).
    pub position_error_mm: MaxMean,
    /// Difference from the analytic answer per angle (deg), in [`ANGLE_NAMES`] order.
    pub angle_error_deg: [MaxMean; 4],
    /// Knee travel between consecutive frames of this leg (mm/frame).
    pub knee_jump_mm: MaxMean,
    /// Ankle travel between consecutive frames of this leg (mm/frame).
    pub ankle_jump_mm: MaxMean,
    /// The knee's jitter (mm/frame).
    pub knee_jitter_mm: MaxMean,
    /// The ankle's jitter (mm/frame).
    pub ankle_jitter_mm: MaxMean,
}

impl SideTable {
    /// The largest error of any angle (deg).
    #[must_use]
    pub fn angle_error_max_deg(&self) -> f64 {
        self.angle_error_deg.iter().map(|a| a.max).fold(0.0, f64::max)
    }

    /// The larger of the knee's and the ankle's largest jitter (mm/frame).
    #[must_use]
    pub fn jitter_max_mm(&self) -> f64 {
        self.knee_jitter_mm.max.max(self.ankle_jitter_mm.max)
    }

    /// Within [`ANGLE_ERROR_MAX_DEG`].
    #[must_use]
    pub fn angle_pass(&self) -> bool {
        self.angle_error_max_deg() <= ANGLE_ERROR_MAX_DEG
    }

    /// Within [`JUMP_MAX_MM`].
    #[must_use]
    pub fn jump_pass(&self) -> bool {
        self.jitter_max_mm() <= JUMP_MAX_MM
    }

    /// Within [`POSITION_ERROR_MEAN_MAX_MM`].
    #[must_use]
    pub fn position_pass(&self) -> bool {
        self.position_error_mm.mean <= POSITION_ERROR_MEAN_MAX_MM
    }

    /// Within all three.
    #[must_use]
    pub fn pass(&self) -> bool {
        self.angle_pass() && self.jump_pass() && self.position_pass()
    }
}

/// The run's table for each leg that has targets, right first. Jumps and jitter count from
/// each leg's second solve, as its first has nothing to move from.
#[must_use]
pub fn side_tables(run: &SolverRun, targets: &[IkTarget]) -> Vec<SideTable> {
    Side::BOTH
        .iter()
        .filter_map(|&side| {
            let mut solves = 0;
            let mut position = Acc::default();
            let mut angles = [Acc::default(); 4];
            let [mut knee, mut ankle, mut knee_jitter, mut ankle_jitter] = [Acc::default(); 4];
            for (x, _) in run.samples.iter().zip(targets).filter(|(_, t)| t.side == side) {
                position.add(x.answer.position_error * 1e3);
                for (acc, error) in angles.iter_mut().zip(x.angle_error_deg) {
                    if let Some(e) = error {
                        acc.add(e);
                    }
                }
                if solves > 0 {
                    knee.add(x.knee_jump_mm);
                    ankle.add(x.ankle_jump_mm);
                    knee_jitter.add(x.knee_jitter_mm);
                    ankle_jitter.add(x.ankle_jitter_mm);
                }
                solves += 1;
            }
            (solves > 0).then(|| SideTable {
                side,
                solves,
                position_error_mm: position.done(),
                angle_error_deg: angles.map(Acc::done),
                knee_jump_mm: knee.done(),
                ankle_jump_mm: ankle.done(),
                knee_jitter_mm: knee_jitter.done(),
                ankle_jitter_mm: ankle_jitter.done(),
            })
        })
        .collect()
}

/// A table as text cells, for the terminal and for Markdown alike.
#[derive(Clone, Debug, PartialEq)]
pub struct TextTable {
    /// What the table shows and which of the seed's tables it reproduces.
    pub title: String,
    /// Column heads.
    pub head: Vec<String>,
    /// Rows of cells, as many as `head`.
    pub rows: Vec<Vec<String>>,
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::Right => "right",
        Side::Left => "left",
    }
}

/// `[a b c d]`, seed 002's way of writing a vector of per-axis figures.
fn vector(values: [f64; 4]) -> String {
    let cells: Vec<String> = values.iter().map(|v| format!("{v:.3}")).collect();
    format!("[{}]", cells.join(" "))
}

fn verdict(value: f64, digits: usize, pass: bool) -> String {
    format!("{value:.digits$} {}", pass_fail(pass))
}

fn pass_fail(pass: bool) -> &'static str {
    if pass { "pass" } else { "fail" }
}

/// One row per solver and side: the two naming cells, then `cells`.
fn rows_of(rows: &[SolverSides], cells: impl Fn(&SideTable) -> Vec<String>) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for (solver, sides) in rows {
        for s in sides {
            let mut row = vec![solver.name().to_string(), side_name(s.side).to_string()];
            row.extend(cells(s));
            out.push(row);
        }
    }
    out
}

fn head(rest: &[&str]) -> Vec<String> {
    ["solver", "side"].iter().chain(rest).map(ToString::to_string).collect()
}

/// Seed 002's three tables for these solvers' sides: errors (its tables 5.1–5.2), jumps
/// (5.3), and the thresholds of its §5.2 marked pass or fail.
#[must_use]
pub fn seed_tables(rows: &[SolverSides]) -> [TextTable; 3] {
    [errors_table(rows), jumps_table(rows), verdicts_table(rows)]
}

fn errors_table(rows: &[SolverSides]) -> TextTable {
    TextTable {
        title: format!(
            "Seed 002 tables 5.1-5.2 (tracker distance, per-axis angle difference): ankle to target, \
             angles against the analytic answer [{}]",
            ANGLE_NAMES.join(", ")
        ),
        head: head(&["error max (mm)", "error mean (mm)", "angle error max (deg)", "angle error mean (deg)"]),
        rows: rows_of(rows, |s| {
            vec![
                format!("{:.4}", s.position_error_mm.max),
                format!("{:.4}", s.position_error_mm.mean),
                vector(s.angle_error_deg.map(|a| a.max)),
                vector(s.angle_error_deg.map(|a| a.mean)),
            ]
        }),
    }
}

fn jumps_table(rows: &[SolverSides]) -> TextTable {
    let mm = |m: MaxMean, digits: usize| [format!("{:.digits$}", m.max), format!("{:.digits$}", m.mean)];
    TextTable {
        title: "Seed 002 table 5.3 (travel between two frames): knee and ankle jump, and the jitter the \
                solver adds to the walk's own motion (mm/frame)"
            .to_string(),
        head: head(&[
            "knee max",
            "knee mean",
            "ankle max",
            "ankle mean",
            "knee jitter max",
            "knee jitter mean",
            "ankle jitter max",
            "ankle jitter mean",
        ]),
        rows: rows_of(rows, |s| {
            [mm(s.knee_jump_mm, 2), mm(s.ankle_jump_mm, 2), mm(s.knee_jitter_mm, 4), mm(s.ankle_jitter_mm, 4)].concat()
        }),
    }
}

fn verdicts_table(rows: &[SolverSides]) -> TextTable {
    TextTable {
        title: format!(
            "Seed 002's thresholds (its section 5.2): angle error max <= {ANGLE_ERROR_MAX_DEG} deg, jitter max <= \
             {JUMP_MAX_MM} mm/frame, position error mean <= {POSITION_ERROR_MEAN_MAX_MM} mm"
        ),
        head: head(&["angle error max (deg)", "jitter max (mm/frame)", "error mean (mm)", "overall"]),
        rows: rows_of(rows, |s| {
            vec![
                verdict(s.angle_error_max_deg(), 3, s.angle_pass()),
                verdict(s.jitter_max_mm(), 4, s.jump_pass()),
                verdict(s.position_error_mm.mean, 4, s.position_pass()),
                pass_fail(s.pass()).to_string(),
            ]
        }),
    }
}
