//! Measuring the leg IK solvers on the walk's own targets (`gaitlab ik`, the report's `ik.csv`).
//!
//! The walk is run once with the analytic solver and every leg's IK question (hip, ankle
//! target, reference vector) is kept. Each solver then answers the whole sequence, one leg at a
//! time in frame order, warm-starting from its previous answer as it would in the walk. (A
//! report keeps the questions of the walk it reports, whatever its solver, while running it.)
//!
//! Metrics, after seed 002's three (tracker distance, angle difference, inter-frame jump):
//! - **position error**: ankle to target (mm), max and mean over all solves;
//! - **knee direction error**: angle about the hip→ankle axis between the solver's knee and
//!   the analytic one (deg), over solves where the analytic knee stands ≥ 5 mm off that axis
//!   (a straighter knee has no meaningful direction);
//! - **iterations**: per solve, mean and max (analytic: 1);
//! - **time per solve** (µs): wall clock, mean; the only figure that differs between runs;
//! - **joint-limit violations**: solves whose angles leave the `[ik]` ranges by > 0.01°;
//! - **inter-frame jump**: distance the knee and the ankle move between consecutive frames of
//!   the same leg (mm), max (with the frame) and mean — the analytic row is the walk's own
//!   motion, so a solver's excess over it is its jitter;
//! - **angle error** (per sample): each leg angle's difference from the analytic answer's
//!   (deg); hip rotation only where the knee direction error is defined, as a straight knee
//!   leaves the hip's axial turn to whatever the previous frame had;
//! - **jitter** (per sample): how far the knee's and the ankle's offset from the analytic
//!   answer changes since this leg's previous frame (mm) — the part of the jump the solver
//!   adds to the walk's own motion.
//!
//! Per side, with seed 002's thresholds applied: [`crate::analysis::ik_tables`].

pub use crate::analysis::recording::IkTarget;
use crate::analysis::recording::{Keep, record};
use crate::model::body::Side;
use crate::model::ik::{IkAnswer, IkQuestion, IkSettings, IkSolverKind, JointLimits, LegAngles, LegChain, LegSolver};
use crate::model::params::WalkParams;
use crate::model::terrain::SplitMix64;
use crate::model::walk::ModelError;
use glam::DVec3;
use std::time::Instant;

/// Runs the walk (analytic IK) and keeps both legs' IK questions of every frame.
pub fn collect_targets(params: &WalkParams, cycles: f64, fps: f64) -> Result<Vec<IkTarget>, ModelError> {
    let mut reference = params.clone();
    reference.ik.solver = IkSolverKind::Analytic;
    let keep = Keep { ik_targets: true, ..Keep::default() };
    Ok(record(&reference, cycles, fps, keep)?.ik_targets)
}

/// A standing right hip (m): what `random_targets` places its targets around.
pub const STANDING_HIP: DVec3 = DVec3::new(0.0, 0.9, 0.09);

/// `n` targets for the right leg of a standing hip ([`STANDING_HIP`], knee reference
/// forward), each the ankle of a pose drawn uniformly within `limits`' ranges (whether or not
/// they are enabled), so every one is reachable within them. The same `seed` gives the same
/// targets; frames count the targets, all at time 0.
#[must_use]
pub fn random_targets(n: usize, seed: u64, thigh: f64, shank: f64, limits: &JointLimits) -> Vec<IkTarget> {
    let chain = LegChain { thigh, shank, limits: *limits };
    let mut rng = SplitMix64::new(seed);
    (0..n as u64)
        .map(|frame| {
            let angles = limits.ranges().map(|(lo, hi)| lo + (hi - lo) * 0.5 * (rng.next_signed_unit() + 1.0));
            // The reference is the leg frame's x, so leg-frame offsets are world offsets.
            let ankle = chain.forward(LegAngles::from_array(angles), 1.0).ankle;
            let question =
                IkQuestion { hip: STANDING_HIP, target: STANDING_HIP + ankle, reference: DVec3::X, side_sign: 1.0 };
            IkTarget { frame, time_s: 0.0, side: Side::Right, question }
        })
        .collect()
}

/// One solve of one target.
#[derive(Clone, Copy, Debug)]
pub struct IkSample {
    /// The answer.
    pub answer: IkAnswer,
    /// Knee direction error against the analytic knee (deg); `None` where the knee is too
    /// straight to have a direction.
    pub knee_direction_error_deg: Option<f64>,
    /// Worst joint-limit excess (deg).
    pub limit_excess_deg: f64,
    /// Knee and ankle travel since this leg's previous frame (mm); 0 on its first.
    pub knee_jump_mm: f64,
    /// See `knee_jump_mm`.
    pub ankle_jump_mm: f64,
    /// Difference from the analytic answer's angles (deg), in [`LegAngles::to_array`] order;
    /// hip rotation `None` where `knee_direction_error_deg` is.
    pub angle_error_deg: [Option<f64>; 4],
    /// Change of the knee's offset from the analytic knee since this leg's previous frame
    /// (mm); 0 on its first.
    pub knee_jitter_mm: f64,
    /// See `knee_jitter_mm`, for the ankle.
    pub ankle_jitter_mm: f64,
    /// Wall-clock time of the solve (µs).
    pub time_us: f64,
}

/// One solver's run over the target set.
#[derive(Clone, Debug)]
pub struct SolverRun {
    /// The solver.
    pub solver: IkSolverKind,
    /// One sample per target, in target order.
    pub samples: Vec<IkSample>,
}

/// A solver's figures over its run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkSummary {
    /// Solves.
    pub solves: usize,
    /// Solves that ended on the target within the tolerance.
    pub reached: usize,
    /// Position error, max and mean (mm).
    pub position_error_max_mm: f64,
    /// See `position_error_max_mm`.
    pub(crate) position_error_mean_mm: f64,
    /// Knee direction error against the analytic swivel, max and mean (deg).
    pub knee_direction_error_max_deg: f64,
    /// See `knee_direction_error_max_deg`.
    pub(crate) knee_direction_error_mean_deg: f64,
    /// Iterations, mean and max.
    pub iterations_mean: f64,
    /// See `iterations_mean`.
    pub(crate) iterations_max: u32,
    /// Mean wall-clock time per solve (µs).
    pub(crate) time_per_solve_us: f64,
    /// Solves outside the joint ranges by more than 0.01°.
    pub limit_violations: usize,
    /// Knee jump between frames, max (mm), its frame, and mean.
    pub(crate) knee_jump_max_mm: f64,
    /// See `knee_jump_max_mm`.
    pub(crate) knee_jump_max_frame: u64,
    /// See `knee_jump_max_mm`.
    pub(crate) knee_jump_mean_mm: f64,
    /// Ankle jump between frames, max (mm), its frame, and mean.
    pub(crate) ankle_jump_max_mm: f64,
    /// See `ankle_jump_max_mm`.
    pub(crate) ankle_jump_max_frame: u64,
    /// See `ankle_jump_max_mm`.
    pub(crate) ankle_jump_mean_mm: f64,
}

/// Solves every target with `solver` under `settings` (its own solver field is replaced),
/// each leg warm-started from its previous answer.
#[must_use]
pub fn run_solver(
    targets: &[IkTarget],
    solver: IkSolverKind,
    settings: &IkSettings,
    thigh: f64,
    shank: f64,
) -> SolverRun {
    run_solver_from(targets, solver, settings, (thigh, shank), false)
}

/// [`run_solver`], every solve started cold (from the rest pose) when `cold`.
#[must_use]
pub fn run_solver_from(
    targets: &[IkTarget],
    solver: IkSolverKind,
    settings: &IkSettings,
    (thigh, shank): (f64, f64),
    cold: bool,
) -> SolverRun {
    let mut settings = *settings;
    settings.solver = solver;
    let mut analytic_settings = settings;
    analytic_settings.solver = IkSolverKind::Analytic;
    analytic_settings.soften = 1.0;
    analytic_settings.twist = 0.0;
    let mut legs = Side::BOTH.map(|side| LegSolver::new(settings, thigh, shank, side.sign()));
    let mut references = Side::BOTH.map(|side| LegSolver::new(analytic_settings, thigh, shank, side.sign()));
    // Each leg's previous answer and the analytic one beside it: jumps and jitter.
    let mut previous: [Option<(IkAnswer, IkAnswer)>; 2] = [None, None];
    let mut samples = Vec::with_capacity(targets.len());
    for t in targets {
        let i = t.side.index();
        if cold {
            legs[i].forget();
        }
        let started = Instant::now();
        let answer = legs[i].solve(&t.question);
        let time_us = started.elapsed().as_secs_f64() * 1e6;
        let reference = references[i].solve(&t.question);
        let ((knee_jump_mm, ankle_jump_mm), (knee_jitter_mm, ankle_jitter_mm)) =
            previous[i].map_or(((0.0, 0.0), (0.0, 0.0)), |(p, r)| {
                let jitter = |now: DVec3, was: DVec3, ref_now: DVec3, ref_was: DVec3| {
                    ((now - ref_now) - (was - ref_was)).length() * 1e3
                };
                (
                    (p.knee.distance(answer.knee) * 1e3, p.ankle.distance(answer.ankle) * 1e3),
                    (
                        jitter(answer.knee, p.knee, reference.knee, r.knee),
                        jitter(answer.ankle, p.ankle, reference.ankle, r.ankle),
                    ),
                )
            });
        previous[i] = Some((answer, reference));
        let knee_direction_error_deg = knee_direction_error_deg(t.question.hip, &answer, &reference);
        samples.push(IkSample {
            answer,
            knee_direction_error_deg,
            limit_excess_deg: settings.limits.violation(answer.angles).to_degrees(),
            knee_jump_mm,
            ankle_jump_mm,
            angle_error_deg: angle_error_deg(answer.angles, reference.angles, knee_direction_error_deg.is_some()),
            knee_jitter_mm,
            ankle_jitter_mm,
            time_us,
        });
    }
    SolverRun { solver, samples }
}

/// Angle about the hip→ankle axis between two knees (deg), or `None` when the reference knee
/// is within 5 mm of the axis.
fn knee_direction_error_deg(hip: glam::DVec3, answer: &IkAnswer, reference: &IkAnswer) -> Option<f64> {
    let axis = (reference.ankle - hip).normalize_or(glam::DVec3::NEG_Y);
    let off = |knee: glam::DVec3| {
        let v = knee - hip;
        v - axis * axis.dot(v)
    };
    let (a, b) = (off(answer.knee), off(reference.knee));
    if b.length() < 5e-3 || a.length() < 1e-12 {
        return None;
    }
    Some(a.angle_between(b).to_degrees())
}

/// Each angle's distance from the reference's (deg), taken the short way round: a solver's
/// own parametrisation may sit a full turn from the shared one. Hip rotation is `None` unless
/// `rotation_defined`.
fn angle_error_deg(answer: LegAngles, reference: LegAngles, rotation_defined: bool) -> [Option<f64>; 4] {
    let (a, r) = (answer.to_array(), reference.to_array());
    let [flex, abd, rot, knee] = std::array::from_fn(|k| {
        let d = (a[k] - r[k]).rem_euclid(std::f64::consts::TAU);
        Some(d.min(std::f64::consts::TAU - d).to_degrees())
    });
    [flex, abd, rot.filter(|_| rotation_defined), knee]
}

impl SolverRun {
    /// The run's figures.
    #[must_use]
    pub fn summary(&self, targets: &[IkTarget]) -> IkSummary {
        let n = self.samples.len().max(1) as f64;
        let mut s = IkSummary {
            solves: self.samples.len(),
            reached: self.samples.iter().filter(|x| x.answer.reached).count(),
            position_error_max_mm: 0.0,
            position_error_mean_mm: 0.0,
            knee_direction_error_max_deg: 0.0,
            knee_direction_error_mean_deg: 0.0,
            iterations_mean: 0.0,
            iterations_max: 0,
            time_per_solve_us: 0.0,
            limit_violations: self.samples.iter().filter(|x| x.limit_excess_deg > 0.01).count(),
            knee_jump_max_mm: 0.0,
            knee_jump_max_frame: 0,
            knee_jump_mean_mm: 0.0,
            ankle_jump_max_mm: 0.0,
            ankle_jump_max_frame: 0,
            ankle_jump_mean_mm: 0.0,
        };
        let mut directions = 0usize;
        let mut jumps = 0usize;
        for (x, t) in self.samples.iter().zip(targets) {
            let error_mm = x.answer.position_error * 1e3;
            s.position_error_max_mm = s.position_error_max_mm.max(error_mm);
            s.position_error_mean_mm += error_mm / n;
            if let Some(d) = x.knee_direction_error_deg {
                s.knee_direction_error_max_deg = s.knee_direction_error_max_deg.max(d);
                s.knee_direction_error_mean_deg += d;
                directions += 1;
            }
            s.iterations_mean += f64::from(x.answer.iterations) / n;
            s.iterations_max = s.iterations_max.max(x.answer.iterations);
            s.time_per_solve_us += x.time_us / n;
            if t.frame > 0 {
                jumps += 1;
                s.knee_jump_mean_mm += x.knee_jump_mm;
                s.ankle_jump_mean_mm += x.ankle_jump_mm;
                if x.knee_jump_mm > s.knee_jump_max_mm {
                    (s.knee_jump_max_mm, s.knee_jump_max_frame) = (x.knee_jump_mm, t.frame);
                }
                if x.ankle_jump_mm > s.ankle_jump_max_mm {
                    (s.ankle_jump_max_mm, s.ankle_jump_max_frame) = (x.ankle_jump_mm, t.frame);
                }
            }
        }
        s.knee_direction_error_mean_deg /= directions.max(1) as f64;
        s.knee_jump_mean_mm /= jumps.max(1) as f64;
        s.ankle_jump_mean_mm /= jumps.max(1) as f64;
        s
    }
}
