//! The procedural walk (spec §3, §5, §7, §9): time and phases, footfalls, swing planning,
//! the pelvis trajectory, the legs by IK, the upper body.
//!
//! Time runs as a *master phase* φ in gait cycles: the right leg's phase is frac(φ), the
//! left leg's frac(φ − ½). One update advances φ by at most [`MAX_UPDATE_CYCLES`]; a longer
//! frame is split. When an update crosses a leg's phase boundary, the leg is first evaluated
//! exactly at the boundary (finishing the old phase), then enters the new one: no phase end
//! is skipped, however long the frame.
//!
//! [`Walker`] here keeps the clock and the phases. The rest has its own file: the rules at
//! one moment and the one footfall builder (`gait`), the pose builder (`pose`), the start
//! (`start`), the step planner (`planner`), parameter changes during the walk (`live`), pace
//! changes and the stop (`pace`, its state in `pace_state`); the planner, `live` and `pace`
//! add `impl Walker` blocks, called here as methods only, so no file imports back.

mod ankle_pitch;
pub mod frame;
pub mod gait;
mod heel_pad;
mod initiation;
pub mod leg;
mod live;
pub mod pace;
mod pace_state;
pub mod pelvis;
mod planner;
pub mod pose;
mod reach_angles;
mod reach_guard;
mod stance_rise;
mod start;
pub mod step_problem;
mod swing_sim;
pub mod timing;
pub mod upper;

pub use gait::{Gait, HEEL_RISE_DESIGN_STRIDE_M, MIN_STRIKE_ANGLE, enter_stance_phase, swing_target};
pub use pose::{bone_frame, ik_question, leg_pose, solve_leg};
pub use reach_angles::{MAX_HEEL_RISE, heel_rise_to_reach};

use crate::model::body::{Pose, Side};
use crate::model::curve::Curve;
use crate::model::gait_curves::{CurveSet, Ground};
use crate::model::ik::{IkAnswer, LegSolver, TwoBoneSolution};
use crate::model::params::{Resolved, TerrainChoice, WalkParams};
use crate::model::schedule::PaceAction;
use crate::model::terrain::Terrain;
use gait::{LiveCurves, cycle_targets, trajectory_curves};
use glam::DVec3;
use leg::{Footfall, LegPhase, LegPose, LegState, LegTarget, PhaseBounds};
use pace_state::Pace;
use pelvis::{PelvisPlan, PelvisPose, TrajectoryCurves};
use pose::build_pose;
use start::standing_start;
use std::fmt;
use step_problem::{StepProblem, StepRecord};
use timing::{FramePart, FrameTimer};
use upper::{ArmHang, UpperBody};

/// Largest phase advance of one update (cycles) [6.3.3].
pub const MAX_UPDATE_CYCLES: f64 = 0.04;
/// Samples of the swing simulation at toe-off [6.3.2].
pub const SWING_SAMPLES: usize = 50;
/// Heel height at toe-off the swing heel-height curve is designed for (m) [fig 6.10].
pub const SWING_HEEL_DESIGN_M: f64 = 0.20;
/// Slope of the heel-height curve at landing (m per swing), at most: the heel descends onto
/// the footfall.
pub const LANDING_SLOPE_M: f64 = -0.08;
/// A walk that cannot be built.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelError(pub String);

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ModelError {}

/// The decision made for one step at toe-off, kept for the optimiser panel and reports.
#[derive(Clone, Debug, PartialEq)]
pub struct StepPlan {
    /// Step number of the footfall being swung to.
    pub step: i64,
    /// The swinging side.
    pub side: Side,
    /// Master phase of the toe-off.
    pub phase: f64,
    /// The pelvis-position choice for the coming double support.
    pub optimisation: StepRecord,
    /// Pelvis height at that double support after the terrain rule and reach guard.
    pub(crate) double_support_y: f64,
    /// How much the reach guard lowered the pelvis (m).
    pub(crate) reach_guard_drop: f64,
    /// Heel-height raises made by the swing simulation.
    pub(crate) swing_raises: u32,
    /// The step's heel-height curve (m above the toe-off ground) as adapted to the terrain.
    pub(crate) swing_heel_height: Curve,
    /// The step's foot-pitch curve (deg) as adapted.
    pub(crate) swing_ankle_deg: Curve,
}

/// Steps of plans and footfalls a long-running walk keeps when it trims its history (the lab,
/// `simulate`): far more than the lab's optimiser table and walk view ever show.
pub const RECENT_STEPS: usize = 256;

/// A walking body.
#[derive(Clone, Debug)]
pub struct Walker {
    params: WalkParams,
    gait: Gait,
    terrain: Terrain,
    pending_traj: Option<TrajectoryCurves>,
    /// The foot-flat, heel-rise and toe-off phases a change asked for and a leg inside its
    /// phase held back ([`Walker::restore_phase_bounds`] sets them at the next heel strike).
    held_phases: Option<PhaseBounds>,
    plan: PelvisPlan,
    legs: [LegState; 2],
    phase: f64,
    time_s: f64,
    footfalls: Vec<Footfall>,
    step_plans: Vec<StepPlan>,
    last_problem: Option<StepProblem>,
    last_ds_ratio: f64,
    infeasible_steps: u64,
    cost_fixed_rule: bool,
    reach_failures: u64,
    leg_solvers: [LegSolver; 2],
    last_ik: [IkAnswer; 2],
    clock: Option<fn() -> std::time::Instant>,
    timer: Option<Box<FrameTimer>>,
    pelvis: PelvisPose,
    arm_hang: ArmHang,
    upper: UpperBody,
    pose: Pose,
    pace: Pace,
}

/// The design curves' kind of ground for a terrain: the one mapping both the curves (the slow
/// rise that goes with the heel pad) and the planner (which stances get a pad) read.
pub(crate) fn ground_of(kind: TerrainChoice) -> Ground {
    match kind {
        TerrainChoice::Flat => Ground::Flat,
        TerrainChoice::Stairs => Ground::Stairs,
        TerrainChoice::Slope | TerrainChoice::Random => Ground::Uneven,
    }
}

/// Checks that `params` make a walk — the curve overrides build, the leg phases come in
/// order — without building one (config validation asks this of every file), and returns
/// what a walker starts from.
pub fn check(params: &WalkParams) -> Result<(Resolved, CurveSet), ModelError> {
    let r = params.resolve();
    let ground = ground_of(params.terrain.kind);
    let design = CurveSet::with_overrides(&params.curves, params.walk.speed_mps, ground, heel_pad::rise_share(&r))
        .map_err(|e| ModelError(e.to_string()))?;
    if r.toe_off.is_nan() || r.toe_off <= 0.5 {
        return Err(ModelError(format!(
            "toe-off at {:.3} of the cycle leaves no double support: that is a run, which gaitlab does not model",
            r.toe_off
        )));
    }
    if !(0.0 < r.foot_flat && r.foot_flat < r.heel_rise && r.heel_rise < r.toe_off && r.toe_off < 1.0) {
        return Err(ModelError(format!(
            "leg phases must come in order: 0 < foot flat ({:.3}) < heel rise ({:.3}) < toe-off ({:.3}) < 1",
            r.foot_flat, r.heel_rise, r.toe_off
        )));
    }
    Ok((r, design))
}

/// Walkers built by this process (see [`walkers_built`]).
static WALKERS_BUILT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// How many walkers this process has built: lets a test show that a command walks its config
/// once (a walk is the costly part of every command).
#[must_use]
pub fn walkers_built() -> u64 {
    WALKERS_BUILT.load(std::sync::atomic::Ordering::Relaxed)
}

impl Walker {
    /// A walker standing in the double support right after a right heel strike, in the
    /// steady-state pose of the walk (the left foot already in heel rise behind), at x = 0.
    pub fn new(params: &WalkParams) -> Result<Self, ModelError> {
        WALKERS_BUILT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let (r, design) = check(params)?;
        let terrain = Terrain::new(params.terrain.kind());
        let traj = trajectory_curves(&design);
        let live = LiveCurves::new(cycle_targets(&design, &r));
        let legs = standing_start(&terrain, &r, &design);
        let footfalls = vec![legs[1].footfall, legs[0].footfall];
        let arm_hang = ArmHang::new(&r.dims, r.arm_spread, r.elbow_min_flex);
        let leg_solvers = Side::BOTH.map(|side| LegSolver::new(r.ik, r.dims.thigh, r.dims.shank, side.sign()));
        let mut walker = Walker {
            params: params.clone(),
            pose: Pose::rest(&r.dims),
            gait: Gait { r, design, traj, live },
            terrain,
            pending_traj: None,
            held_phases: None,
            plan: PelvisPlan::default(),
            legs,
            phase: 0.0,
            time_s: 0.0,
            footfalls,
            step_plans: Vec::new(),
            last_problem: None,
            last_ds_ratio: 0.5,
            infeasible_steps: 0,
            cost_fixed_rule: true,
            reach_failures: 0,
            leg_solvers,
            last_ik: [IkAnswer::default(); 2],
            clock: None,
            timer: None,
            pelvis: PelvisPose::new(DVec3::ZERO, 0.0, 0.0, 0.0, 0.0),
            arm_hang,
            upper: UpperBody::default(),
            pace: Pace::new(&[], 0.0, false),
        };
        let standing = params.schedule.first().is_some_and(|e| e.action == PaceAction::Start);
        if standing {
            walker.stand_still()
        } else {
            walker.plan_start()
        }
        walker.evaluate_now();
        walker.pace = Pace::new(&params.schedule, walker.pelvis.position.x, standing);
        Ok(walker)
    }

    /// Advances the walk by `dt_s` seconds, in updates of at most [`MAX_UPDATE_CYCLES`].
    pub fn advance(&mut self, dt_s: f64) {
        if dt_s.is_nan() || dt_s <= 0.0 || !dt_s.is_finite() {
            return;
        }
        self.poll_schedule();
        if let Some(from_cycle) = self.blending_from() {
            self.advance_blending(dt_s, from_cycle);
        } else {
            let total = dt_s / self.gait.r.cycle_s;
            let n = (total / MAX_UPDATE_CYCLES).ceil().max(1.0) as usize;
            let d = total / n as f64;
            for _ in 0..n {
                self.update_to(self.phase + d);
            }
        }
        self.time_s += dt_s;
    }

    /// Moves the walk to master phase `target` (≤ one update ahead), handling every phase
    /// boundary crossed on the way in time order.
    fn update_to(&mut self, target: f64) {
        loop {
            // The earliest boundary either leg crosses before `target`.
            let next = Side::BOTH
                .iter()
                .map(|&s| (self.boundary_phase(s), s))
                .filter(|(b, _)| *b <= target)
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let Some((at, side)) = next else { break };
            let at = at.max(self.phase);
            self.cross_key_boundaries(at);
            let pelvis = self.pelvis_walked(at);
            let finished = self.evaluate_leg(side, at, &pelvis);
            self.legs[side.index()].pose = finished;
            self.enter_next_phase(side, at);
        }
        self.cross_key_boundaries(target);
        if target.floor() > self.phase.floor() {
            self.gait.live.wrap(Side::Right);
        }
        if (target - 0.5).floor() > (self.phase - 0.5).floor() {
            self.gait.live.wrap(Side::Left);
        }
        self.reguard_after_pace_change(target);
        self.phase = target;
        self.plan.forget_before(target - 1.0);
        self.evaluate_now();
        self.check_standing();
        self.check_walking();
    }

    /// Master phase at which `side`'s current phase ends.
    fn boundary_phase(&self, side: Side) -> f64 {
        let leg = &self.legs[side.index()];
        let end = match leg.phase {
            LegPhase::LoadingResponse => self.gait.r.foot_flat,
            LegPhase::Midstance if self.holds_midstance(leg) => return f64::INFINITY,
            LegPhase::Midstance => leg.heel_rise,
            LegPhase::HeelRise => leg.toe_off,
            LegPhase::Swing => 1.0,
        };
        leg.cycle_start + end
    }

    /// Evaluates everything at the current phase and builds the pose.
    fn evaluate_now(&mut self) {
        self.lap(FramePart::Bookkeeping);
        let pelvis = self.pelvis_walked(self.phase);
        self.lap(FramePart::Curves);
        for side in Side::BOTH {
            let hip = pelvis.hip(side.sign());
            let target = self.leg_target(side, self.phase, hip);
            self.lap(FramePart::LegTargets);
            let pose = if self.gait.r.ik.solver.is_iterative() {
                let answer = self.leg_solvers[side.index()].solve(&ik_question(hip, target, side));
                self.last_ik[side.index()] = answer;
                let axis = (answer.ankle - hip).normalize_or(DVec3::NEG_Y);
                let swivel = crate::model::ik::orthogonal_part(axis, answer.knee - hip);
                let solved =
                    TwoBoneSolution { middle: answer.knee, end: answer.ankle, swivel, reached: answer.reached };
                leg_pose(&self.gait.r, hip, target, &solved)
            } else {
                let pose = solve_leg(&self.gait.r, hip, target);
                self.last_ik[side.index()] = IkAnswer::exact(pose.knee, pose.ankle, pose.reached, pose.target.ankle);
                pose
            };
            if !pose.reached {
                self.reach_failures += 1;
            }
            self.legs[side.index()].pose = pose;
            self.lap(FramePart::LegIk);
        }
        self.pelvis = pelvis;
        let p_right = self.phase.rem_euclid(1.0);
        let arm_phase = [p_right, (self.phase - 0.5).rem_euclid(1.0)];
        let mut shoulder =
            [self.gait.live.shoulder[0].eval(arm_phase[0]), self.gait.live.shoulder[1].eval(arm_phase[1])];
        let mut elbow = [self.gait.live.elbow[0].eval(arm_phase[0]), self.gait.live.elbow[1].eval(arm_phase[1])];
        if self.plan.settling().is_some() || self.plan.launching().is_some() {
            // Setting off and at the walk's end the arms swing from and come to hanging: the
            // swing fades in and out about its middle.
            let keep = self.plan.walking_weight(self.phase);
            let elbow_mid = self.gait.r.elbow_min_flex + 0.5 * self.gait.r.elbow_range;
            for side in 0..2 {
                shoulder[side] *= keep;
                elbow[side] = elbow_mid + (elbow[side] - elbow_mid) * keep;
            }
        }
        self.lap(FramePart::Curves);
        let bend = upper::trunk_bend(self.gait.r.dims.trunk_segments(), pelvis.obliquity);
        self.lap(FramePart::Spine);
        self.upper = UpperBody::solve_bent(&self.gait.r, &self.arm_hang, &pelvis, bend, shoulder, elbow);
        self.lap(FramePart::Arms);
        let legs = [&self.legs[0].pose, &self.legs[1].pose];
        build_pose(&self.gait.r.dims, &self.pelvis, legs, &self.upper, &mut self.pose);
        self.lap(FramePart::Pose);
    }

    /// Gives the walk a frame timer (or takes it away): each part of every later update is
    /// charged to it (see [`timing`]).
    pub fn set_frame_timer(&mut self, timer: Option<FrameTimer>) {
        self.timer = timer.map(Box::new);
    }

    /// The frame timer, if one was given.
    #[must_use]
    pub fn frame_timer(&self) -> Option<&FrameTimer> {
        self.timer.as_deref()
    }

    /// Restarts the timer's chain without charging any part (see [`FrameTimer::restart`]).
    pub fn restart_timer(&mut self) {
        if let Some(timer) = self.timer.as_deref_mut() {
            timer.restart();
        }
    }

    /// Charges the time since the last lap to `part`, when the walk is timed.
    #[inline]
    pub fn lap(&mut self, part: FramePart) {
        if let Some(timer) = self.timer.as_deref_mut() {
            timer.lap(part);
        }
    }

    /// The pelvis at master phase `phase` under the current plan.
    #[must_use]
    pub fn pelvis_at(&self, phase: f64) -> PelvisPose {
        self.pelvis_with_plan(&self.plan, phase)
    }

    /// Forward position and height of the pelvis at `phase` under a given plan.
    #[must_use]
    pub fn pelvis_position_with_plan(&self, plan: &PelvisPlan, phase: f64) -> (f64, f64) {
        self.gait.pelvis_position_with_plan(plan, phase)
    }

    /// The pelvis at `phase` under a given plan.
    #[must_use]
    pub fn pelvis_with_plan(&self, plan: &PelvisPlan, phase: f64) -> PelvisPose {
        self.gait.pelvis_with_plan(plan, phase)
    }

    /// The IK target of a leg in state `leg` at master phase `phase` (see [`Gait::target_of`]).
    #[must_use]
    pub fn target_of(&self, leg: &LegState, phase: f64, hip: DVec3) -> LegTarget {
        self.gait.target_of(leg, phase, hip)
    }

    /// A copy of a stance leg's state moved forward to `phase` (see [`Gait::project_stance`]).
    pub fn project_stance(&self, leg: &mut LegState, phase: f64) {
        self.gait.project_stance(leg, phase);
    }

    /// Gives the walk a clock to time each step's pelvis search with (the records'
    /// `elapsed_us`); without one (the default) nothing is timed and the records say 0.
    pub fn set_clock(&mut self, clock: Option<fn() -> std::time::Instant>) {
        self.clock = clock;
    }

    /// The walk's rules now, without its clock: what the optimiser's cost runs.
    #[must_use]
    pub fn gait(&self) -> &Gait {
        &self.gait
    }

    /// The leg's IK target at master phase `phase`, from its state and the hip position.
    #[must_use]
    pub fn leg_target(&self, side: Side, phase: f64, hip: DVec3) -> LegTarget {
        self.target_of(&self.legs[side.index()], phase, hip)
    }

    /// Solves `side`'s leg at `phase` with the given pelvis.
    #[must_use]
    pub fn evaluate_leg(&self, side: Side, phase: f64, pelvis: &PelvisPose) -> LegPose {
        let hip = pelvis.hip(side.sign());
        let target = self.leg_target(side, phase, hip);
        solve_leg(&self.gait.r, hip, target)
    }

    /// Enters the phase after the current one at master phase `at` (the boundary).
    fn enter_next_phase(&mut self, side: Side, at: f64) {
        let i = side.index();
        let pose = self.legs[i].pose;
        let next = self.legs[i].phase.next();
        match next {
            LegPhase::Midstance => enter_stance_phase(&mut self.legs[i], &self.gait.r, &self.gait.design),
            LegPhase::HeelRise => {
                enter_stance_phase(&mut self.legs[i], &self.gait.r, &self.gait.design);
                self.legs[i].heel_rise_scale *= self.closing_heel_rise_share(&self.legs[i]);
            }
            LegPhase::Swing => {
                self.plan_step(side, at, &pose);
                self.legs[i].phase = next;
            }
            LegPhase::LoadingResponse => {
                let leg = &mut self.legs[i];
                let plan = leg.swing.take().expect("a landing leg was swinging");
                leg.footfall = plan.to;
                leg.anchor = plan.to.heel;
                leg.strike_angle = pose.target.pitch - plan.to.ground_angle;
                leg.cycle_start += 1.0;
                leg.phase = next;
                self.pace_at_heel_strike(at);
                self.restore_phase_bounds(at);
            }
        }
        self.legs[i].phase_serial += 1;
    }

    /// The parameters in force.
    #[must_use]
    pub fn params(&self) -> &WalkParams {
        &self.params
    }

    /// Derived values in force.
    #[must_use]
    pub fn resolved(&self) -> &Resolved {
        &self.gait.r
    }

    /// The terrain walked on.
    #[must_use]
    pub fn terrain(&self) -> &Terrain {
        &self.terrain
    }

    /// The current skeleton pose.
    #[must_use]
    pub fn pose(&self) -> &Pose {
        &self.pose
    }

    /// Master phase (cycles since the start).
    #[must_use]
    pub fn phase(&self) -> f64 {
        self.phase
    }

    /// Seconds since the start.
    #[must_use]
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// A leg's state.
    #[must_use]
    pub fn leg(&self, side: Side) -> &LegState {
        &self.legs[side.index()]
    }

    /// The current pelvis.
    #[must_use]
    pub fn pelvis(&self) -> &PelvisPose {
        &self.pelvis
    }

    /// The pelvis plan.
    #[must_use]
    pub fn pelvis_plan(&self) -> &PelvisPlan {
        &self.plan
    }

    /// Every footfall so far, in order (the first is the left one behind the start).
    #[must_use]
    pub fn footfalls(&self) -> &[Footfall] {
        &self.footfalls
    }

    /// Every step's planning decision so far.
    #[must_use]
    pub fn step_plans(&self) -> &[StepPlan] {
        &self.step_plans
    }

    /// The last step's optimisation problem (for the cost landscape).
    #[must_use]
    pub fn last_step_problem(&self) -> Option<&StepProblem> {
        self.last_problem.as_ref()
    }

    /// Whether, with the optimiser off, each step still costs the fixed rule's position (for
    /// the "with and without" comparison of `gaitlab optimise` and the report). On by
    /// default; off leaves those records' costs empty and the walk unchanged.
    pub fn set_cost_fixed_rule(&mut self, on: bool) {
        self.cost_fixed_rule = on;
    }

    /// Steps at which no candidate pelvis position was feasible.
    #[must_use]
    pub fn infeasible_steps(&self) -> u64 {
        self.infeasible_steps
    }

    /// Drops all but about the last `steps` step plans and footfalls (between `steps` and
    /// `2·steps` stay, so the trimming is amortised). The walk itself never looks back at
    /// them; a long-running lab calls this so its memory stays flat, while a headless run
    /// keeps everything for its report.
    pub fn keep_recent_history(&mut self, steps: usize) {
        let steps = steps.max(2);
        if self.step_plans.len() > 2 * steps {
            self.step_plans.drain(..self.step_plans.len() - steps);
        }
        if self.footfalls.len() > 2 * steps {
            self.footfalls.drain(..self.footfalls.len() - steps);
        }
    }

    /// The legs' last IK answers, right then left: error, iterations, whether reached.
    #[must_use]
    pub fn last_ik(&self) -> &[IkAnswer; 2] {
        &self.last_ik
    }

    /// IK solves that had to clamp an unreachable target (or, with an iterative solver, ended
    /// outside its tolerance), counted over every evaluated frame.
    #[must_use]
    pub fn reach_failures(&self) -> u64 {
        self.reach_failures
    }

    /// The design curves in force.
    #[must_use]
    pub fn design_curves(&self) -> &CurveSet {
        &self.gait.design
    }

    /// The upper body as solved this frame.
    #[must_use]
    pub fn upper_body(&self) -> &UpperBody {
        &self.upper
    }
}

impl AsRef<Gait> for Walker {
    fn as_ref(&self) -> &Gait {
        &self.gait
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::presets;

    #[test]
    fn trimming_the_history_keeps_memory_flat_and_the_walk_unchanged() {
        let params = presets::params("rough").unwrap().unwrap();
        let mut full = Walker::new(&params).unwrap();
        let mut trimmed = full.clone();
        for frame in 0..3000u64 {
            full.advance(1.0 / 60.0);
            trimmed.advance(1.0 / 60.0);
            trimmed.keep_recent_history(8);
            assert!(trimmed.step_plans().len() <= 16 && trimmed.footfalls().len() <= 16);
            if frame % 97 == 0 {
                assert_eq!(format!("{:?}", full.frame(frame)), format!("{:?}", trimmed.frame(frame)), "frame {frame}");
            }
        }
        assert!(full.step_plans().len() > 80, "the untrimmed walk kept {}", full.step_plans().len());
        assert_eq!(full.step_plans().last().unwrap().step, trimmed.step_plans().last().unwrap().step);
        assert_eq!(full.footfalls().last(), trimmed.footfalls().last());
    }
}
