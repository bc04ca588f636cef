//! The procedural walk (spec §3, §5, §7, §9): time and phases, footfalls, swing planning,
//! the pelvis trajectory, the legs by IK, the upper body.
//!
//! Time runs as a *master phase* φ in gait cycles: the right leg's phase is frac(φ), the
//! left leg's frac(φ − ½). One update advances φ by at most [`MAX_UPDATE_CYCLES`]; a longer
//! frame is split. When an update crosses a leg's phase boundary, the leg is first evaluated
//! exactly at the boundary (finishing the old phase), then enters the new one: no phase end
//! is skipped, however long the frame.

pub mod frame;
pub mod gait;
pub mod leg;
pub mod pelvis;
pub mod pose;
pub mod upper;

pub use gait::{Gait, HEEL_RISE_DESIGN_STRIDE_M, MAX_HEEL_RISE, enter_stance_phase, heel_rise_to_reach, swing_target};
pub use pose::{bone_frame, ik_question, leg_pose, solve_leg};

use crate::model::body::{Bone, Pose, Side};
use crate::model::curve::{Curve, LiveCurve};
use crate::model::gait_curves::{CurveName, CurveSet};
use crate::model::ik::{IkAnswer, LegSolver, TwoBoneSolution};
use crate::model::optimise::{Candidate, StepProblem, StepRecord};
use crate::model::params::{Resolved, WalkParams};
use crate::model::terrain::Terrain;
use gait::{LiveCurves, cycle_targets, trajectory_curves};
use glam::{DQuat, DVec3};
use leg::{Footfall, LegPhase, LegPose, LegState, LegTarget, SwingPlan, foot_rotation};
use pelvis::{KeyKind, PelvisKey, PelvisPlan, PelvisPose, TrajectoryCurves};
use std::fmt;
use upper::{ArmHang, UpperBody};

/// Largest phase advance of one update (cycles) [6.3.3].
pub const MAX_UPDATE_CYCLES: f64 = 0.04;
/// Samples of the swing simulation at toe-off [6.3.2].
pub const SWING_SAMPLES: usize = 50;
/// Toe-off plantarflexion the swing-ankle curve is designed for (deg) [fig 6.8].
pub const SWING_ANKLE_DESIGN_DEG: f64 = 15.0;
/// Heel height at toe-off the swing heel-height curve is designed for (m) [fig 6.10].
pub const SWING_HEEL_DESIGN_M: f64 = 0.20;
/// Least foot–ground angle at heel strike (rad): the heel, not the toe, lands first.
pub const MIN_STRIKE_ANGLE: f64 = 0.035;
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
    pub double_support_y: f64,
    /// How much the reach guard lowered the pelvis (m).
    pub reach_guard_drop: f64,
    /// Heel-height raises made by the swing simulation.
    pub swing_raises: u32,
    /// The step's heel-height curve (m above the toe-off ground) as adapted to the terrain.
    pub swing_heel_height: Curve,
    /// The step's foot-pitch curve (deg) as adapted.
    pub swing_ankle_deg: Curve,
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
    pelvis: PelvisPose,
    arm_hang: ArmHang,
    upper: UpperBody,
    pose: Pose,
}

/// Checks that `params` make a walk — the curve overrides build, the leg phases come in
/// order — without building one (config validation asks this of every file), and returns
/// what a walker starts from.
pub fn check(params: &WalkParams) -> Result<(Resolved, CurveSet), ModelError> {
    let r = params.resolve();
    let design = CurveSet::with_overrides(&params.curves).map_err(|e| ModelError(e.to_string()))?;
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
        let targets = cycle_targets(&design, &r);
        let [obl, rot, tilt, lat, sh, el] = targets;
        let live = LiveCurves {
            obliquity: LiveCurve::new(obl),
            rotation: LiveCurve::new(rot),
            tilt: LiveCurve::new(tilt),
            lateral: LiveCurve::new(lat),
            shoulder: [LiveCurve::new(sh.clone()), LiveCurve::new(sh)],
            elbow: [LiveCurve::new(el.clone()), LiveCurve::new(el)],
        };
        let dims = r.dims.clone();
        let step = 0.5 * r.stride_m;
        let make_footfall = |step_no: i64, side: Side, nominal_x: f64| {
            let yaw = -side.sign() * r.turnout;
            let foot_x = dims.foot_length * yaw.cos();
            let x = terrain.settle_footfall(nominal_x, foot_x, r.clearance);
            Footfall {
                step: step_no,
                side,
                heel: DVec3::new(x, terrain.height(x), side.sign() * 0.5 * r.step_width_m),
                ground_angle: terrain.angle_between(x, x + foot_x),
                yaw,
                nominal_x,
            }
        };
        let right = make_footfall(0, Side::Right, 0.0);
        let left = make_footfall(-1, Side::Left, -step);
        let heel_rise_scale = (r.stride_m / HEEL_RISE_DESIGN_STRIDE_M).powi(2);
        let toe_off_angle = design.get(CurveName::HeelRise).eval(1.0) * heel_rise_scale;
        let strike_angle = (design.get(CurveName::SwingAnkle).eval(1.0) * toe_off_angle / SWING_ANKLE_DESIGN_DEG)
            .to_radians()
            .max(MIN_STRIKE_ANGLE);
        let placeholder = LegPose {
            hip: DVec3::ZERO,
            knee: DVec3::ZERO,
            ankle: DVec3::ZERO,
            swivel: DVec3::X,
            foot: DQuat::IDENTITY,
            toe: DQuat::IDENTITY,
            heel: DVec3::ZERO,
            ball: DVec3::ZERO,
            toe_tip: DVec3::ZERO,
            reached: true,
            target: LegTarget { ankle: DVec3::ZERO, pitch: 0.0, toe_bend: 0.0, yaw: 0.0, extra_heel_rise: 0.0 },
        };
        let left_ball =
            left.heel + foot_rotation(left.yaw, left.ground_angle) * (dims.ball_local() - dims.heel_local());
        let legs = [
            LegState {
                side: Side::Right,
                phase: LegPhase::LoadingResponse,
                cycle_start: 0.0,
                footfall: right,
                anchor: right.heel,
                strike_angle,
                heel_rise_scale,
                swing: None,
                phase_serial: 0,
                pose: placeholder,
            },
            LegState {
                side: Side::Left,
                phase: LegPhase::HeelRise,
                cycle_start: -0.5,
                footfall: left,
                anchor: left_ball,
                strike_angle,
                heel_rise_scale,
                swing: None,
                phase_serial: 0,
                pose: placeholder,
            },
        ];
        let arm_hang = ArmHang::new(&dims, r.arm_spread, r.elbow_min_flex);
        let (r_ik, r_thigh, r_shank) = (r.ik, dims.thigh, dims.shank);
        let mut walker = Walker {
            params: params.clone(),
            pose: Pose::rest(&dims),
            gait: Gait { r, design, traj, live },
            terrain,
            pending_traj: None,
            plan: PelvisPlan::default(),
            legs,
            phase: 0.0,
            time_s: 0.0,
            footfalls: vec![left, right],
            step_plans: Vec::new(),
            last_problem: None,
            last_ds_ratio: 0.5,
            infeasible_steps: 0,
            cost_fixed_rule: true,
            reach_failures: 0,
            leg_solvers: Side::BOTH.map(|side| LegSolver::new(r_ik, r_thigh, r_shank, side.sign())),
            last_ik: [IkAnswer::default(); 2],
            clock: None,
            pelvis: PelvisPose::new(DVec3::ZERO, 0.0, 0.0, 0.0, 0.0),
            arm_hang,
            upper: UpperBody::default(),
        };
        // Keys around the start: the left mid-stance behind, this double support, the right
        // mid-stance ahead.
        let ms_left = walker.midstance_key(&left, -0.5);
        let ms_right = walker.midstance_key(&right, 0.0);
        walker.plan.push(ms_left);
        let ds = walker.double_support_key(&left, &right, 0.0, &ms_left, &ms_right);
        walker.plan.push(ds);
        walker.plan.push(PelvisKey { pace: ds.pace, ..ms_right });
        walker.guard_stance_reach(Side::Right, 0.0, None);
        walker.evaluate_now();
        Ok(walker)
    }

    /// Advances the walk by `dt_s` seconds, in updates of at most [`MAX_UPDATE_CYCLES`].
    pub fn advance(&mut self, dt_s: f64) {
        if dt_s.is_nan() || dt_s <= 0.0 || !dt_s.is_finite() {
            return;
        }
        let total = dt_s / self.gait.r.cycle_s;
        let n = (total / MAX_UPDATE_CYCLES).ceil().max(1.0) as usize;
        let d = total / n as f64;
        for _ in 0..n {
            self.update_to(self.phase + d);
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
            let pelvis = self.pelvis_at(at);
            let finished = self.evaluate_leg(side, at, &pelvis);
            self.legs[side.index()].pose = finished;
            self.enter_next_phase(side, at);
        }
        self.cross_key_boundaries(target);
        if target.floor() > self.phase.floor() {
            self.wrap_cycle_curves(Side::Right);
        }
        if (target - 0.5).floor() > (self.phase - 0.5).floor() {
            self.wrap_cycle_curves(Side::Left);
        }
        self.phase = target;
        self.plan.forget_before(target - 1.0);
        self.evaluate_now();
    }

    /// Swaps in edited trajectory curves when the pelvis passes a key, so the segment being
    /// played never changes shape under it.
    fn cross_key_boundaries(&mut self, to: f64) {
        if self.pending_traj.is_some() && self.plan.keys().any(|k| k.phase > self.phase && k.phase <= to) {
            self.gait.traj = self.pending_traj.take().expect("checked");
        }
    }

    fn wrap_cycle_curves(&mut self, side: Side) {
        let i = side.index();
        self.gait.live.shoulder[i].wrap();
        self.gait.live.elbow[i].wrap();
        if side == Side::Right {
            for c in [
                &mut self.gait.live.obliquity,
                &mut self.gait.live.rotation,
                &mut self.gait.live.tilt,
                &mut self.gait.live.lateral,
            ] {
                c.wrap();
            }
        }
    }

    /// Master phase at which `side`'s current phase ends.
    fn boundary_phase(&self, side: Side) -> f64 {
        let leg = &self.legs[side.index()];
        let end = match leg.phase {
            LegPhase::LoadingResponse => self.gait.r.foot_flat,
            LegPhase::Midstance => self.gait.r.heel_rise,
            LegPhase::HeelRise => self.gait.r.toe_off,
            LegPhase::Swing => 1.0,
        };
        leg.cycle_start + end
    }

    /// Evaluates everything at the current phase and builds the pose.
    fn evaluate_now(&mut self) {
        let pelvis = self.pelvis_at(self.phase);
        for side in Side::BOTH {
            let pose = if self.gait.r.ik.solver.is_iterative() {
                let hip = pelvis.hip(side.sign());
                let target = self.leg_target(side, self.phase, hip);
                let answer = self.leg_solvers[side.index()].solve(&ik_question(hip, target, side));
                self.last_ik[side.index()] = answer;
                let axis = (answer.ankle - hip).normalize_or(DVec3::NEG_Y);
                let swivel = crate::model::ik::orthogonal_part(axis, answer.knee - hip);
                let solved =
                    TwoBoneSolution { middle: answer.knee, end: answer.ankle, swivel, reached: answer.reached };
                leg_pose(&self.gait.r, hip, target, &solved)
            } else {
                let pose = self.evaluate_leg(side, self.phase, &pelvis);
                self.last_ik[side.index()] = IkAnswer::exact(pose.knee, pose.ankle, pose.reached, pose.target.ankle);
                pose
            };
            if !pose.reached {
                self.reach_failures += 1;
            }
            self.legs[side.index()].pose = pose;
        }
        self.pelvis = pelvis;
        let p_right = self.phase.rem_euclid(1.0);
        let arm_phase = [p_right, (self.phase - 0.5).rem_euclid(1.0)];
        let shoulder = [self.gait.live.shoulder[0].eval(arm_phase[0]), self.gait.live.shoulder[1].eval(arm_phase[1])];
        let elbow = [self.gait.live.elbow[0].eval(arm_phase[0]), self.gait.live.elbow[1].eval(arm_phase[1])];
        self.upper = UpperBody::solve(&self.gait.r, &self.arm_hang, &pelvis, shoulder, elbow);
        self.build_pose();
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
    pub fn project_stance(&self, plan: &PelvisPlan, leg: &mut LegState, phase: f64) {
        self.gait.project_stance(plan, leg, phase);
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
            LegPhase::Midstance | LegPhase::HeelRise => enter_stance_phase(&mut self.legs[i], &pose, &self.gait.r),
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
            }
        }
        self.legs[i].phase_serial += 1;
    }

    /// The pelvis key at mid-stance over `footfall`, whose heel strike is at master phase
    /// `strike_phase`: ahead of the heel by the offset parameter, at the mid-stance height
    /// above the ground under the foot (so the stance knee's extension is the same on any
    /// terrain, [6.3.3, fig 6.14]).
    fn midstance_key(&self, footfall: &Footfall, strike_phase: f64) -> PelvisKey {
        let r = &self.gait.r;
        PelvisKey {
            phase: strike_phase + 0.5 * r.toe_off,
            x: footfall.heel.x + r.midstance_offset,
            y: footfall.heel.y + r.dims.standing_hip_height() - r.midstance_drop,
            kind: KeyKind::MidStance,
            pace: r.stride_m,
        }
    }

    /// The pelvis key at mid double support after `leading` strikes at `strike_phase`, with
    /// `trailing` behind. Height: the vertical range below the mid-stance height over the
    /// *lower* of the two footfalls — stepping down lowers the minimum so the leading leg
    /// reaches, stepping up keeps it and the knee bends [fig 6.14].
    fn double_support_key(
        &self,
        trailing: &Footfall,
        leading: &Footfall,
        strike_phase: f64,
        ms_before: &PelvisKey,
        ms_after: &PelvisKey,
    ) -> PelvisKey {
        let r = &self.gait.r;
        let ground = trailing.heel.y.min(leading.heel.y);
        PelvisKey {
            phase: strike_phase + 0.5 * (r.toe_off - 0.5),
            x: 0.5 * (ms_before.x + ms_after.x),
            y: ground + r.dims.standing_hip_height() - r.midstance_drop - r.vertical_range,
            kind: KeyKind::DoubleSupport,
            // This step's own average pace, so a change of speed or a stair spreads over the
            // steps it happens in instead of being caught up within one segment.
            pace: (ms_after.x - ms_before.x) / (ms_after.phase - ms_before.phase),
        }
    }

    /// Where the pelvis is at the coming mid double support: the one choice per step that
    /// the pelvis-acceleration optimisation (spec §8) makes, written into the plan's newest
    /// double-support key. With the optimiser off, the fixed rule: halfway between the
    /// mid-stance positions around it. When no candidate is feasible the previous step's
    /// choice (as a share of the distance between the mid-stances) is kept and counted; the
    /// reach guard that runs next lowers the pelvis until the legs reach.
    #[allow(clippy::too_many_arguments)]
    fn choose_double_support(
        &mut self,
        side: Side,
        at: f64,
        step: i64,
        landing: LegState,
        ms_before: PelvisKey,
        ds: PelvisKey,
        ms_after: PelvisKey,
    ) -> StepRecord {
        let started = self.clock.map(|now| now());
        let settings = self.params.optimiser.clone();
        let half_range = 0.5 * settings.range_pct / 100.0 * (ms_after.x - ms_before.x);
        let centre = 0.5 * (ms_before.x + ms_after.x);
        let problem = StepProblem {
            plan: self.plan.clone(),
            stance: self.legs[side.other().index()].clone(),
            landing,
            ms_before,
            ds,
            ms_after,
            range: (centre - half_range, centre + half_range),
            height_range: (ds.y - 0.03, ds.y + 0.01),
            settings,
            heel_rise_allowance: f64::INFINITY,
            hip_extension_allowance: f64::INFINITY,
            fixed_rule_cost: None,
            orientations: Vec::new(),
        };
        // With the optimiser off nothing needs a cost but the comparison, which callers that
        // only want the walk (or want to time the swing planning alone) can switch off.
        let problem =
            if problem.settings.enabled || self.cost_fixed_rule { problem.with_allowance(self) } else { problem };
        let fixed_x = problem.fixed_rule_x();
        let fixed_rule = Candidate { x: fixed_x, y: ds.y, cost: problem.fixed_rule_cost };
        let (method, candidates) = if problem.settings.enabled {
            (Some(problem.settings.method), problem.search(self))
        } else {
            (None, vec![fixed_rule])
        };
        // Off, the fixed rule is the choice whatever its cost (or whether it was costed at
        // all); the reach guard after the choice keeps the legs able to reach.
        let best = if method.is_none() {
            Some(fixed_rule)
        } else {
            candidates
                .iter()
                .filter(|c| c.cost.is_some())
                .min_by(|a, b| a.cost.unwrap().total_cmp(&b.cost.unwrap()))
                .copied()
        };
        let fallback = best.is_none();
        let chosen = best.unwrap_or_else(|| {
            self.infeasible_steps += 1;
            let x = ms_before.x + self.last_ds_ratio * (ms_after.x - ms_before.x);
            Candidate { x, y: ds.y, cost: problem.cost(self, x, ds.y) }
        });
        let elapsed_us = started.map_or(0.0, |t| t.elapsed().as_secs_f64() * 1e6);
        if let Some(key) = self.plan.last_of_mut(KeyKind::DoubleSupport) {
            key.x = chosen.x;
            key.y = chosen.y;
        }
        self.last_ds_ratio = (chosen.x - ms_before.x) / (ms_after.x - ms_before.x);
        let record = StepRecord {
            step,
            side,
            phase: at,
            method,
            evaluations: if method.is_some() { candidates.len() as u32 } else { 0 },
            feasible: candidates.iter().filter(|c| c.cost.is_some()).count() as u32,
            candidates,
            chosen,
            window_x: (ms_before.x, ms_after.x),
            fixed_rule,
            fallback,
            elapsed_us,
        };
        self.last_problem = Some(problem);
        record
    }

    /// Lowers the newest pelvis keys where `side`'s leg, striking at `strike_phase`, could not
    /// reach its ground contact during loading response and midstance. The terrain rule
    /// keeps the knee's extension, but a long stride or a big drop can still put the heel out
    /// of reach; the planner drops the pelvis rather than let the heel slide. Returns the
    /// drop of the double-support key (m).
    fn guard_stance_reach(&mut self, side: Side, strike_phase: f64, swing: Option<&SwingPlan>) -> f64 {
        let r = self.gait.r.clone();
        let limit = r.reach_margin * r.dims.leg_reach();
        let footfall = self.legs[side.index()].footfall;
        let strike_angle = self.legs[side.index()].strike_angle;
        // Only the two newest keys may move: the segment ending at any older key may be
        // playing already, and moving its key would make the pelvis jump.
        let ds_phase = self.plan.last_of(KeyKind::DoubleSupport).map_or(f64::NAN, |k| k.phase);
        let ms_phase = self.plan.last_of(KeyKind::MidStance).map_or(f64::NAN, |k| k.phase);
        // From the end of the swing (when a plan is given: the knee is nearly straight there
        // too) through loading response and midstance.
        // Samples are densest around heel strike, where the leg is straightest.
        let mut samples: Vec<f64> = Vec::with_capacity(24);
        if swing.is_some() {
            samples.extend([-0.03, -0.02, -0.01, -0.005].map(|d| strike_phase + d));
        }
        samples.extend((0..=6).map(|i| strike_phase + r.foot_flat * i as f64 / 6.0));
        let window_end = strike_phase + r.heel_rise.min(0.5 * r.toe_off);
        samples.extend(
            (1..=8).map(|i| strike_phase + r.foot_flat + (window_end - strike_phase - r.foot_flat) * i as f64 / 8.0),
        );
        let mut dropped = 0.0;
        for _ in 0..6 {
            let mut worst: Option<(f64, KeyKind)> = None;
            for &phase in &samples {
                let ankle = match swing {
                    Some(plan) if phase < strike_phase => {
                        let s = 1.0 - (strike_phase - phase) / (1.0 - r.toe_off);
                        swing_target(plan, s, side, &r).ankle
                    }
                    _ => {
                        let s = ((phase - strike_phase) / r.foot_flat).clamp(0.0, 1.0);
                        let pitch = footfall.ground_angle + strike_angle * (1.0 - s);
                        footfall.heel - foot_rotation(footfall.yaw, pitch) * r.dims.heel_local()
                    }
                };
                let hip = self.pelvis_at(phase).hip(side.sign());
                let d = hip - ankle;
                let horizontal = (d.x * d.x + d.z * d.z).sqrt();
                let allowed = if horizontal < limit {
                    ankle.y + (limit * limit - horizontal * horizontal).sqrt()
                } else {
                    ankle.y
                };
                let deficit = hip.y - allowed;
                if deficit <= 0.0 {
                    continue;
                }
                // Lower whichever movable key moves the pelvis most at this instant.
                let (a, b, u) = self.plan.bracket(phase);
                let v = self.gait.traj.vertical.eval(u);
                let mut choice: Option<(KeyKind, f64)> = None;
                for (key, weight) in [(a, 1.0 - v), (b, v)] {
                    let movable = key.phase == ds_phase || key.phase == ms_phase;
                    if movable && choice.is_none_or(|(_, w)| weight > w) {
                        choice = Some((key.kind, weight));
                    }
                }
                let Some((kind, weight)) = choice else { continue };
                let need = deficit / weight.max(0.25) + 1e-4;
                if worst.is_none_or(|(w, _)| need > w) {
                    worst = Some((need, kind));
                }
            }
            let Some((need, kind)) = worst else { break };
            if let Some(key) = self.plan.last_of_mut(kind) {
                key.y -= need;
                if kind == KeyKind::DoubleSupport {
                    dropped += need;
                }
            }
        }
        dropped
    }

    /// At `side`'s toe-off: plan its footfall, the pelvis keys up to its mid-stance, and the
    /// swing [6.3.2].
    fn plan_step(&mut self, side: Side, at: f64, toe_off_pose: &LegPose) {
        let r = self.gait.r.clone();
        let dims = &r.dims;
        let i = side.index();
        let other = self.legs[side.other().index()].footfall;
        // Footfall: a step on from the previous footfall's nominal place, settled on the ground.
        let nominal_x = other.nominal_x + 0.5 * r.stride_m;
        let yaw = -side.sign() * r.turnout;
        let foot_x = dims.foot_length * yaw.cos();
        let x = self.terrain.settle_footfall(nominal_x, foot_x, r.clearance);
        let to = Footfall {
            step: other.step + 1,
            side,
            heel: DVec3::new(x, self.terrain.height(x), side.sign() * 0.5 * r.step_width_m),
            ground_angle: self.terrain.angle_between(x, x + foot_x),
            yaw,
            nominal_x,
        };
        let strike_phase = self.legs[i].cycle_start + 1.0;

        // Swing planning step 1: the foot pitch curve, scaled to the toe-off angle and turned
        // up at its end where the footfall slopes up so the toe does not land first.
        let pitch_from = toe_off_pose.target.pitch;
        let mut ankle_deg = self.gait.design.get(CurveName::SwingAnkle).clone();
        let toe_off_plantar_deg = (-pitch_from).to_degrees().max(0.0);
        ankle_deg.scale(1.0, (toe_off_plantar_deg / SWING_ANKLE_DESIGN_DEG).min(6.0));
        let strike = ankle_deg.eval(1.0).to_radians() - to.ground_angle;
        if strike < MIN_STRIKE_ANGLE {
            ankle_deg.shift_last_two((MIN_STRIKE_ANGLE - strike).to_degrees());
        }
        let strike_angle = ankle_deg.eval(1.0).to_radians() - to.ground_angle;

        // Pelvis keys: the coming double support (its position chosen below), then this leg's
        // mid-stance.
        let ms_before = *self.plan.last_of(KeyKind::MidStance).expect("a mid-stance key is planned");
        let ms_after = self.midstance_key(&to, strike_phase);
        let ds = self.double_support_key(&other, &to, strike_phase, &ms_before, &ms_after);
        self.plan.push(ds);
        self.plan.push(PelvisKey { pace: ds.pace, ..ms_after });
        let landing = LegState {
            side,
            phase: LegPhase::LoadingResponse,
            cycle_start: strike_phase,
            footfall: to,
            anchor: to.heel,
            strike_angle,
            heel_rise_scale: self.legs[i].heel_rise_scale,
            swing: None,
            phase_serial: 0,
            pose: *toe_off_pose,
        };

        // Step 2: the heel-height curve, scaled to the heel's height at toe-off, its end
        // moved by the terrain step, its middle raised by the knee-lift parameter.
        let ground_from = self.legs[i].footfall.heel.y;
        let heel_from = toe_off_pose.heel;
        let mut heel_height = self.gait.design.get(CurveName::SwingHeelHeight).clone();
        heel_height.scale(1.0, ((heel_from.y - ground_from) / SWING_HEEL_DESIGN_M).max(0.05));
        heel_height.shift_end(to.heel.y - ground_from - heel_height.eval(1.0));
        if r.knee_lift > 0.0 {
            heel_height.raise_at(0.5, r.knee_lift);
        }
        // The heel must come down onto the footfall, never up into it: a big step up tilts
        // the shifted curve's end upward, so the last handle is set back to a descent.
        heel_height.limit_end_slope(LANDING_SLOPE_M);
        let mut plan = SwingPlan {
            heel_from,
            ground_from,
            to,
            pitch_from,
            toe_bend_from: toe_off_pose.target.toe_bend,
            forward: self.gait.design.get(CurveName::SwingForward).clone(),
            lateral: self.gait.design.get(CurveName::SwingLateral).clone(),
            ankle_deg,
            heel_height,
            raises: 0,
        };
        // The end of the swing and the stance phases this plan sets up must reach: lower the
        // pelvis where they would not.
        // The guard runs twice: first with the double support at the fixed rule, so that the
        // optimiser searches around keys the legs can follow (the mid-stance key in
        // particular, which no candidate moves), then for the chosen position.
        let saved_footfall = self.legs[i].footfall;
        let saved_strike = self.legs[i].strike_angle;
        self.legs[i].footfall = to;
        self.legs[i].strike_angle = strike_angle;
        let mut guard_drop = self.guard_stance_reach(side, strike_phase, Some(&plan));
        self.legs[i].footfall = saved_footfall;
        self.legs[i].strike_angle = saved_strike;
        let ds = *self.plan.last_of(KeyKind::DoubleSupport).expect("pushed above");
        let ms_after = *self.plan.last_of(KeyKind::MidStance).expect("pushed above");
        let record = self.choose_double_support(side, at, to.step, landing, ms_before, ds, ms_after);
        if (record.chosen.x, record.chosen.y) != (ds.x, ds.y) {
            self.legs[i].footfall = to;
            self.legs[i].strike_angle = strike_angle;
            guard_drop += self.guard_stance_reach(side, strike_phase, Some(&plan));
            self.legs[i].footfall = saved_footfall;
            self.legs[i].strike_angle = saved_strike;
        }
        // Step 3: simulate the swing and raise the heel where the leg cannot reach or the
        // foot would touch the ground.
        self.simulate_swing(side, at, &mut plan);
        self.step_plans.push(StepPlan {
            step: to.step,
            side,
            phase: at,
            optimisation: record,
            double_support_y: self.plan.last_of(KeyKind::DoubleSupport).map_or(ds.y, |k| k.y),
            reach_guard_drop: guard_drop,
            swing_raises: plan.raises,
            swing_heel_height: plan.heel_height.clone(),
            swing_ankle_deg: plan.ankle_deg.clone(),
        });
        self.footfalls.push(to);
        self.legs[i].swing = Some(plan);
    }

    /// The 50-sample swing simulation [6.3.2]: at each sample, the pelvis pose, the heel from
    /// the plan, IK; raise the heel-height curve where the ankle is beyond reach, then where
    /// heel, toe tip or sole would come within the clearance of the ground. Up to eight passes;
    /// the foot's first 8 % are left alone, as its toe is on the ground at toe-off by design.
    fn simulate_swing(&self, side: Side, toe_off_phase: f64, plan: &mut SwingPlan) {
        let r = &self.gait.r;
        let dims = &r.dims;
        let limit = r.reach_margin * dims.leg_reach();
        let span = 1.0 - r.toe_off;
        for _pass in 0..8 {
            let mut raised = false;
            let mut prev_toe_x = plan.heel_from.x + dims.foot_length;
            for i in 0..SWING_SAMPLES {
                let s = (i as f64 + 0.5) / SWING_SAMPLES as f64;
                let pelvis = self.pelvis_at(toe_off_phase + s * span);
                let hip = pelvis.hip(side.sign());
                let target = swing_target(plan, s, side, r);
                // Out of reach: lift the heel until the ankle is back inside the sphere.
                let d = hip - target.ankle;
                let horizontal = (d.x * d.x + d.z * d.z).sqrt();
                if horizontal < limit {
                    let lowest_ok = hip.y - (limit * limit - horizontal * horizontal).sqrt();
                    if target.ankle.y < lowest_ok - 1e-6 && s < 0.97 {
                        plan.heel_height.raise_at(s, lowest_ok - target.ankle.y + 1e-4);
                        plan.raises += 1;
                        raised = true;
                        continue;
                    }
                }
                // Too close to the ground: clearance ramps in over the first and out over the
                // last 15 % of the swing, where the foot leaves and meets the ground.
                let pose = solve_leg(r, hip, target);
                let needed = r.clearance * (s / 0.15).min((1.0 - s) / 0.15).min(1.0);
                let ground_heel = self.terrain.height(pose.heel.x);
                let ground_toe = self.terrain.max_height_between(prev_toe_x, pose.toe_tip.x);
                prev_toe_x = pose.toe_tip.x;
                let mut deficit = (ground_heel + needed - pose.heel.y).max(ground_toe + needed - pose.toe_tip.y);
                for corner in self.terrain.corners_between(pose.heel.x, pose.toe_tip.x) {
                    let top = self.terrain.height(corner).max(self.terrain.height(corner - 1e-9));
                    let f = (corner - pose.heel.x) / (pose.toe_tip.x - pose.heel.x).max(1e-9);
                    let sole_y = pose.heel.y + (pose.toe_tip.y - pose.heel.y) * f;
                    deficit = deficit.max(top + needed - sole_y);
                }
                if deficit > 1e-5 && s > 0.08 && s < 0.985 {
                    plan.heel_height.raise_at(s, deficit + 1e-4);
                    plan.raises += 1;
                    raised = true;
                }
            }
            if !raised {
                break;
            }
        }
    }

    /// Builds the skeleton pose from the pelvis, legs and upper body.
    fn build_pose(&mut self) {
        let dims = &self.gait.r.dims;
        let pose = &mut self.pose;
        pose.position[Bone::Pelvis.index()] = self.pelvis.position;
        pose.rotation[Bone::Pelvis.index()] = self.pelvis.rotation;
        for side in Side::BOTH {
            let leg = &self.legs[side.index()].pose;
            let hinge = (leg.ankle - leg.hip).cross(leg.swivel).normalize_or(DVec3::Z);
            pose.place(dims, Bone::thigh(side), bone_frame(leg.knee - leg.hip, hinge));
            pose.position[Bone::thigh(side).index()] = leg.hip;
            pose.place(dims, Bone::shin(side), bone_frame(leg.ankle - leg.knee, hinge));
            pose.place(dims, Bone::foot(side), leg.foot);
            pose.place(dims, Bone::toe(side), leg.toe);
        }
        self.upper.apply(dims, pose);
    }

    /// Applies new parameters during the walk without a jump: cycle curves change from the
    /// segment after the one playing, trajectory curves at the next pelvis key, everything
    /// planned per step (footfalls, swing, pelvis keys) from the next toe-off. Body and
    /// terrain cannot change under a walking body: returns false, and the caller restarts.
    pub fn set_params(&mut self, params: &WalkParams) -> Result<bool, ModelError> {
        if params.body != self.params.body || params.terrain != self.params.terrain {
            return Ok(false);
        }
        let r = params.resolve();
        let design = CurveSet::with_overrides(&params.curves).map_err(|e| ModelError(e.to_string()))?;
        let [obl, rot, tilt, lat, sh, el] = cycle_targets(&design, &r);
        let p_right = self.phase.rem_euclid(1.0);
        let p_left = (self.phase - 0.5).rem_euclid(1.0);
        self.gait.live.obliquity.change_to(obl, p_right);
        self.gait.live.rotation.change_to(rot, p_right);
        self.gait.live.tilt.change_to(tilt, p_right);
        self.gait.live.lateral.change_to(lat, p_right);
        self.gait.live.shoulder[0].change_to(sh.clone(), p_right);
        self.gait.live.shoulder[1].change_to(sh, p_left);
        self.gait.live.elbow[0].change_to(el.clone(), p_right);
        self.gait.live.elbow[1].change_to(el, p_left);
        let traj = trajectory_curves(&design);
        if traj.forward_ds_ms != self.gait.traj.forward_ds_ms
            || traj.forward_ms_ds != self.gait.traj.forward_ms_ds
            || traj.vertical != self.gait.traj.vertical
        {
            self.pending_traj = Some(traj);
        }
        // Phase boundaries must not jump behind a leg that is inside the phase they end.
        let mut r = r;
        for leg in &self.legs {
            let q = self.phase - leg.cycle_start;
            match leg.phase {
                LegPhase::LoadingResponse => r.foot_flat = r.foot_flat.max(q),
                LegPhase::Midstance => r.heel_rise = r.heel_rise.max(q),
                LegPhase::HeelRise => {
                    r.toe_off = r.toe_off.max(q);
                    r.heel_rise = self.gait.r.heel_rise;
                }
                LegPhase::Swing => r.toe_off = self.gait.r.toe_off,
            }
        }
        self.arm_hang = ArmHang::new(&r.dims, r.arm_spread, r.elbow_min_flex);
        if r.ik != self.gait.r.ik {
            for solver in &mut self.leg_solvers {
                solver.set_settings(r.ik);
            }
        }
        self.gait.design = design;
        self.gait.r = r;
        self.params = params.clone();
        Ok(true)
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

    /// A cycle curve being played, in real units (for plots): pelvis obliquity, rotation,
    /// tilt (rad) and lateral (m); shoulder and elbow of the right arm (rad).
    #[must_use]
    pub fn live_curve(&self, name: CurveName) -> Option<&Curve> {
        let live = &self.gait.live;
        Some(match name {
            CurveName::PelvisObliquity => live.obliquity.playing(),
            CurveName::PelvisRotation => live.rotation.playing(),
            CurveName::PelvisTilt => live.tilt.playing(),
            CurveName::PelvisLateral => live.lateral.playing(),
            CurveName::Shoulder => live.shoulder[0].playing(),
            CurveName::Elbow => live.elbow[0].playing(),
            _ => return None,
        })
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

    #[test]
    fn a_step_with_no_feasible_candidate_keeps_the_previous_ratio_and_is_counted() {
        let params = presets::params("default").unwrap().unwrap();
        let mut walker = Walker::new(&params).unwrap();
        while walker.step_plans().len() < 4 {
            walker.advance(1.0 / 60.0);
        }
        let problem = walker.last_step_problem().unwrap().clone();
        let previous_ratio = walker.last_ds_ratio;
        // The same question, but the landing foot a metre further on: out of every
        // candidate's reach at heel strike.
        let mut landing = problem.landing.clone();
        landing.footfall.heel.x += 1.0;
        landing.anchor.x += 1.0;
        let before = walker.infeasible_steps();
        let record = walker.choose_double_support(
            landing.side,
            problem.ds.phase,
            99,
            landing,
            problem.ms_before,
            problem.ds,
            problem.ms_after,
        );
        assert!(record.fallback);
        assert_eq!(record.feasible, 0);
        assert!(record.evaluations >= 5);
        assert_eq!(walker.infeasible_steps(), before + 1);
        assert!((record.chosen_ratio() - previous_ratio).abs() < 1e-12);
        assert!(record.chosen.x.is_finite() && record.chosen.y.is_finite());
        assert!(record.chosen.cost.is_none_or(f64::is_finite));
        let key = walker.plan.last_of(KeyKind::DoubleSupport).unwrap();
        assert_eq!((key.x, key.y), (record.chosen.x, record.chosen.y));
    }
}
