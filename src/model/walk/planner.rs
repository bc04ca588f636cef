//! The step planner (spec §6.3.2, §8): at each toe-off, where the swinging foot will land,
//! the pelvis keys up to its mid-stance (their double-support position chosen by the
//! optimiser), and the swing that gets the foot there; plus the keys the walk starts from.
//!
//! Its own file because it is the walk's one decision per step, run once a step, while the
//! rest of [`Walker`] runs every frame. It writes the walker's plan, legs and records, so it
//! is an `impl Walker` block; the clock in `mod.rs` reaches it only by method calls
//! (`self.plan_start()`, `self.plan_step(..)`), never by path, so no import runs back here.

use crate::model::body::Side;
use crate::model::curve::Curve;
use crate::model::gait_curves::{CurveName, Ground};
use crate::model::search::Candidate;
use crate::model::walk::ankle_pitch::foot_pitch_for_ankle;
use crate::model::walk::gait::{MIN_STRIKE_ANGLE, shank_angle};
use crate::model::walk::leg::{Footfall, LegPhase, LegPose, LegState, SwingPlan};
use crate::model::walk::pace::LEVEL_M;
use crate::model::walk::pace_state::StepKind;
use crate::model::walk::pelvis::{KeyKind, PelvisKey};
use crate::model::walk::step_problem::{StepProblem, StepRecord};
use crate::model::walk::timing::FramePart;
use crate::model::walk::{LANDING_SLOPE_M, SWING_HEEL_DESIGN_M, StepPlan, Walker};
use glam::DVec3;

/// How much lower (a share of the fixed rule's cost) a searched double support must be to
/// replace the fixed rule. The cost is sampled: the two legs' steps of one steady walk differ
/// by 0.007-0.07 % (0.95-1.3 m/s), and `tests/optimiser.rs` allows a slope's steady steps 2 % for a
/// toe-off noticed a frame late; a candidate that wins by less is a tie. Taken on a tie, the choice flipped with the fourth
/// decimal of a key: at 1.0 m/s a mid-stance offset of 13.7014 cm kept the fixed rule and
/// 13.701 cm moved the double support 1.7 cm ahead (ratio 0.53) for a cost 0.01 % lower,
/// and the walk's knee RMS against the norms went from 3.43 to 4.83 deg. `gaitlab optimise`
/// notes the steps where a tie kept the fixed rule.
const CLEARLY_LOWER: f64 = 0.005;

/// The cheapest of the searched `candidates` that can reach, or the fixed rule where it is not
/// [`CLEARLY_LOWER`] than that; `None` if none can reach.
fn searched_choice(candidates: &[Candidate], fixed_rule: Candidate) -> Option<Candidate> {
    let found = candidates
        .iter()
        .filter(|c| c.cost.is_some())
        .min_by(|a, b| a.cost.unwrap().total_cmp(&b.cost.unwrap()))
        .copied()?;
    match (found.cost, fixed_rule.cost) {
        (Some(cost), Some(fixed)) if cost > fixed * (1.0 - CLEARLY_LOWER) => Some(fixed_rule),
        _ => Some(found),
    }
}

impl Walker {
    /// The pelvis keys the walk starts from, around the standing start: the left mid-stance
    /// behind, this double support, the right mid-stance ahead — lowered where the right leg
    /// could not reach its stance.
    pub(super) fn plan_start(&mut self) {
        let [right, left] = [self.legs[0].footfall, self.legs[1].footfall];
        let ms_left = self.midstance_key(&left, -0.5);
        self.plan.push(ms_left);
        self.push_step_keys(&left, &right, 0.0);
        self.guard_stance_reach(Side::Right, 0.0, None, f64::NEG_INFINITY);
    }

    /// At `side`'s toe-off: plan its footfall, the pelvis keys up to its mid-stance, and the
    /// swing [6.3.2] (called by [`Walker::plan_step`], with the walk's toe-off set to the
    /// stepping leg's).
    pub(super) fn plan_swing_step(&mut self, side: Side, at: f64, toe_off_pose: &LegPose) {
        self.lap(FramePart::Bookkeeping);
        let i = side.index();
        let other = self.legs[side.other().index()].footfall;
        // Footfall: a step on from the previous footfall's nominal place, settled on the ground
        // (at the walk's end a shorter braking step, then the closing step beside it).
        let (kind, to) = self.next_footfall(side, &other);
        let strike_phase = self.legs[i].cycle_start + 1.0;
        let flat = super::ground_of(self.params.terrain.kind) == Ground::Flat;
        let walking = matches!(kind, StepKind::Starting | StepKind::Steady);
        self.legs[i].pad = super::heel_pad::for_stance(flat && walking, &self.gait.r, self.params.walk.speed_mps);
        // Pelvis keys: the coming double support (position chosen below), this leg's mid-stance.
        let ms_before = self.step_keys(kind, &other, &to, strike_phase);
        if kind == StepKind::Braking {
            self.begin_settle(at, &to);
        }
        // Swing planning step 1: the ankle curve, the foot angle it strikes at under the pelvis.
        let strike_hip = self.pelvis_at(strike_phase).hip(side.sign());
        let (ankle_deg, strike_angle) = self.adapt_swing_ankle(toe_off_pose, &to, strike_hip);
        let landing = self.landing_state(side, to, strike_phase, strike_angle, toe_off_pose);
        // Step 2: the heel-height curve (the closing step's lowered: `swing_lift`).
        let ground_from = self.legs[i].footfall.heel.y;
        let lift = self.swing_lift(kind, &self.legs[i].footfall, &to, toe_off_pose.heel.x);
        let riser = self.riser_ahead(toe_off_pose, ground_from, &to);
        let mut plan = SwingPlan {
            heel_from: toe_off_pose.heel,
            ground_from,
            to,
            toe_bend_from: toe_off_pose.target.toe_bend,
            pitch_from: toe_off_pose.target.pitch,
            pitch_rate_from: self.toe_off_pitch_rate(side, kind, toe_off_pose, &to),
            forward: self.gait.design.get(CurveName::SwingForward).clone(),
            lead: self.swing_lead(ground_from, &to, riser.is_some()),
            lateral: self.gait.design.get(CurveName::SwingLateral).clone(),
            ankle_deg,
            heel_height: self.adapt_swing_heel(toe_off_pose.heel.y, ground_from, &to, lift),
            raises: 0,
            riser,
            toe_floor: self.toe_floor(toe_off_pose),
        };
        // The end of the swing and the stance phases this plan sets up must reach: lower the
        // pelvis where they would not. Twice: first with the double support at the fixed rule,
        // so that the optimiser searches around keys the legs can follow (the mid-stance key in
        // particular, which no candidate moves), then for the chosen position.
        let mut guard_drop = self.guard_landing_reach(side, to, strike_angle, strike_phase, &plan, f64::NEG_INFINITY);
        let ds = *self.plan.last_of(KeyKind::DoubleSupport).expect("pushed above");
        let ms_after = *self.plan.last_of(KeyKind::MidStance).expect("pushed above");
        self.lap(FramePart::SwingPlanning);
        let record = self.decide_double_support(kind, side, at, landing, [ms_before, ds, ms_after]);
        self.lap(FramePart::PelvisChoice);
        if (record.chosen.x, record.chosen.y) != (ds.x, ds.y) {
            // The chosen pelvis sets the shank at heel strike and with it the angle the foot
            // lands at, which the guard's loading response starts from.
            let strike_hip = self.pelvis_at(strike_phase).hip(side.sign());
            let (ankle_deg, strike_angle) = self.adapt_swing_ankle(toe_off_pose, &to, strike_hip);
            plan.ankle_deg = ankle_deg;
            guard_drop += self.guard_landing_reach(side, to, strike_angle, strike_phase, &plan, f64::NEG_INFINITY);
        }
        // Step 3: simulate the swing; raise the heel where the leg cannot reach or the foot touches.
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
        self.step_planned(kind, &to);
        self.lap(FramePart::SwingPlanning);
    }

    /// `side`'s leg as it will be at heel strike on `to` (cycle phase `strike_phase`), its
    /// foot at `strike_angle`: what the double-support choice plans the loading response from.
    fn landing_state(
        &self,
        side: Side,
        to: Footfall,
        strike_phase: f64,
        strike_angle: f64,
        toe_off_pose: &LegPose,
    ) -> LegState {
        LegState {
            cycle_start: strike_phase,
            footfall: to,
            anchor: to.heel,
            strike_angle,
            phase: LegPhase::LoadingResponse,
            swing: None,
            phase_serial: 0,
            pose: *toe_off_pose,
            ..self.legs[side.index()].clone()
        }
    }

    /// How fast `side`'s stance foot pitches into its toe-off (rad per unit of the coming
    /// swing's fraction): the heel-rise target a hundredth of the cycle before toe-off and at it.
    /// None on a step that is not level (as [`Self::swing_lead`]: carried on up a flight, the
    /// foot steepened while the leg was still stretched from the push-off and stairs_up at 1.5
    /// and 1.6 m/s lost reach for a frame, `tests/stairs.rs`), nor into a step that is not a
    /// steady one, nor where the foot did not leave the ground in the pose its heel-rise target
    /// gives (`toe_off_pose`, 0.5° or more apart): a start's first two swings and a stop's
    /// closing step leave from stances of their own, and carried on the swing toe dipped 1.6-7.3
    /// mm into the ground it left (a reviewer's find).
    fn toe_off_pitch_rate(&self, side: Side, kind: StepKind, toe_off_pose: &LegPose, to: &Footfall) -> f64 {
        let leg = &self.legs[side.index()];
        let toe_off = leg.cycle_start + leg.toe_off;
        let pitch_at = |phase: f64| self.gait.target_of(leg, phase, self.pelvis_at(phase).hip(side.sign())).pitch;
        let at_toe_off = pitch_at(toe_off);
        let as_designed = (at_toe_off - toe_off_pose.target.pitch).abs() < 0.5_f64.to_radians();
        if !(level_step(leg.footfall.heel.y, to) && kind == StepKind::Steady && as_designed) {
            return 0.0;
        }
        let step = 0.01;
        (at_toe_off - pitch_at(toe_off - step)) / step * (1.0 - leg.toe_off)
    }

    /// The swing heel's lead ahead of the forward design curve (the speed law `swing_lead`),
    /// on level steps only: onto a stair or down a slope a heel brought forward sooner met a
    /// nosing before the swing simulation saw it (stairs_down at 0.5 m/s); a lag
    /// ([`RISER_LEAD`]) with a riser just ahead of the toe.
    fn swing_lead(&self, ground_from: f64, to: &Footfall, riser_ahead: bool) -> f64 {
        if riser_ahead {
            RISER_LEAD
        } else if level_step(ground_from, to) {
            self.gait.r.swing_lead
        } else {
            0.0
        }
    }

    /// The step's ankle curve and the foot–ground angle it strikes `to` at with the hip at
    /// `strike_hip`: the design curve (the ankle against the shank) with its start moved to
    /// the ankle's angle at toe-off, so the swing picks up the push-off where it ends [6.3.2,
    /// fig 6.8]; its end turned up where the foot would land toe first (uphill), so the heel,
    /// not the toe, lands first.
    fn adapt_swing_ankle(&self, toe_off_pose: &LegPose, to: &Footfall, strike_hip: DVec3) -> (Curve, f64) {
        let r = &self.gait.r;
        let mut ankle_deg = self.gait.design.get(CurveName::SwingAnkle).clone();
        // In the walking plane, as the swing's targets are set: the solved knee's swivel (an
        // IK twist) must not move the feet.
        let t = &toe_off_pose.target;
        let toe_off_dorsi_deg =
            (t.pitch - shank_angle(toe_off_pose.hip, t.ankle, r.dims.thigh, r.dims.shank)).to_degrees();
        ankle_deg.shift_start(toe_off_dorsi_deg - ankle_deg.eval(0.0));
        limit_push_off_after_toe_off(&mut ankle_deg, toe_off_dorsi_deg);
        let strike_pitch = |curve: &Curve| {
            foot_pitch_for_ankle(strike_hip, to.heel, to.yaw, curve.eval(1.0).to_radians(), r) - to.ground_angle
        };
        let strike = strike_pitch(&ankle_deg);
        if strike < MIN_STRIKE_ANGLE {
            ankle_deg.shift_last_two((MIN_STRIKE_ANGLE - strike).to_degrees());
        }
        let strike_angle = strike_pitch(&ankle_deg);
        (ankle_deg, strike_angle)
    }

    /// The step's heel-height curve (m above `ground_from`, the toe-off ground): the design
    /// curve scaled to the heel's height at toe-off (`heel_from_y`), its end moved by the
    /// terrain step to `to`, its middle raised by the knee-lift parameter, and for the closing
    /// step lowered toward its ends by `lift` (1 for every other step). The swing
    /// simulation raises it further where it must.
    fn adapt_swing_heel(&self, heel_from_y: f64, ground_from: f64, to: &Footfall, lift: f64) -> Curve {
        let mut heel_height = self.gait.design.get(CurveName::SwingHeelHeight).clone();
        heel_height.scale(1.0, ((heel_from_y - ground_from) / SWING_HEEL_DESIGN_M).max(0.05));
        heel_height.shift_end(to.heel.y - ground_from - heel_height.eval(1.0));
        if self.gait.r.knee_lift > 0.0 {
            heel_height.raise_at(0.5, self.gait.r.knee_lift);
        }
        if lift < 1.0 {
            // Lower the middle, keep both ends: scale, then put the ends back (both shifts
            // are linear in x, so the joins stay smooth).
            let (start, end) = (heel_height.eval(0.0), heel_height.eval(1.0));
            heel_height.scale(1.0, lift);
            heel_height.shift_start(start * (1.0 - lift));
            heel_height.shift_end(end * (1.0 - lift));
        }
        // The heel must come down onto the footfall, never up into it: a big step up tilts
        // the shifted curve's end upward, so the last handle is set back to a descent.
        heel_height.limit_end_slope(LANDING_SLOPE_M);
        heel_height
    }

    /// The keys of a step of `kind` onto `leading`, pushed (see [`Self::push_step_keys`]);
    /// the first step from standing keeps the keys its start planned, as the pelvis's launch
    /// aims at their double support. Returns the mid-stance key before them.
    fn step_keys(&mut self, kind: StepKind, trailing: &Footfall, leading: &Footfall, strike_phase: f64) -> PelvisKey {
        match kind {
            StepKind::Starting => {
                *self.plan.keys().find(|k| k.kind == KeyKind::MidStance).expect("planned at the start")
            }
            StepKind::Steady => self.push_step_keys(trailing, leading, strike_phase),
            StepKind::Braking | StepKind::Closing => {
                let ms_before = self.push_step_keys(trailing, leading, strike_phase);
                // A stop's pelvis comes to rest at quiet-standing height over these feet
                // (`begin_settle`): a mid-stance key above it, at the walk's full reach, had
                // the settle's blend carry the hip past the stance leg's reach on stairs.
                let rest_y = self.rest_over(&leading.flat_ankle(&self.gait.r.dims)).1;
                if let Some(key) = self.plan.last_of_mut(KeyKind::MidStance) {
                    key.y = key.y.min(rest_y);
                }
                ms_before
            }
        }
    }

    /// Pushes the keys of the step onto `leading` (striking at `strike_phase`, `trailing`
    /// behind): its double support, at the fixed rule until the optimiser moves it, and its
    /// mid-stance, at that double support's pace. Returns the mid-stance key before them.
    fn push_step_keys(&mut self, trailing: &Footfall, leading: &Footfall, strike_phase: f64) -> PelvisKey {
        let ms_before = *self.plan.last_of(KeyKind::MidStance).expect("a mid-stance key is planned");
        let ms_after = self.midstance_key(leading, strike_phase);
        let ds = self.double_support_key(trailing, leading, strike_phase, &ms_before, &ms_after);
        self.plan.push(ds);
        // During a speed change the mid-stance key is passed at the coming ramp step's pace,
        // so that the speed-up (or slow-down) spreads over the segments either side of it
        // instead of falling into the one after it. The scheduled 0.8 -> 1.6 -> 1.0 m/s walk's
        // largest pelvis velocity change per frame: 0.081 m/s passed halfway there, 0.075 at
        // three quarters, 0.073 the whole way, 0.077 at 1.25 (the steady walks' largest,
        // 0.064); with the longer 0.0064 walk ratio halfway had been the best, 0.104.
        let pace = match self.coming_ramp() {
            Some(next) => next.stride_m,
            None => ds.pace,
        };
        self.plan.push(PelvisKey { pace, ..ms_after });
        ms_before
    }

    /// The pelvis key at mid-stance over `footfall`, whose heel strike is at master phase
    /// `strike_phase`: ahead of the heel by the offset parameter, at the mid-stance height
    /// above the ground under the foot (so the stance knee's extension is the same on any
    /// terrain, [6.3.3, fig 6.14]).
    pub(super) fn midstance_key(&self, footfall: &Footfall, strike_phase: f64) -> PelvisKey {
        let r = &self.gait.r;
        // During a speed-up the mid-stance key takes the coming ramp step's drop when it is the
        // larger (the drop grows with speed): planned at the slower speed's height, the first
        // full-speed step had to reach its long double support from a pelvis 0.8 cm higher,
        // and the reach guard lowered that key further (configs/pace.toml's speed-up cycles:
        // vertical range 6.5 -> 6.1 cm against 4.8 steady; with a lower heel-rise curve tried
        // in session 8 the key's drop went 4.3 -> 2.9 cm, 1.5 in a steady walk).
        let drop = self.coming_ramp().map_or(r.midstance_drop, |next| next.midstance_drop.max(r.midstance_drop));
        // And its offset ahead of the heel, which grows with speed: at the old speed's offset
        // the first full-speed step's pelvis caught up 2 cm within one segment (the scheduled
        // 0.8 -> 1.6 m/s walk's pelvis changed velocity 1.21x as sharply as a steady walk's;
        // 1.06x this way).
        let offset = self.coming_ramp().map_or(r.midstance_offset, |next| next.midstance_offset);
        PelvisKey {
            phase: strike_phase + 0.5 * r.toe_off,
            x: footfall.heel.x + offset,
            y: footfall.heel.y + r.dims.standing_hip_height() - drop,
            kind: KeyKind::MidStance,
            pace: r.stride_m,
        }
    }

    /// The pelvis key at mid double support after `leading` strikes at `strike_phase`, with
    /// `trailing` behind. Height: the vertical range below the mid-stance height over the
    /// *lower* of the two footfalls — stepping down lowers the minimum so the leading leg
    /// reaches, stepping up keeps it and the knee bends [fig 6.14].
    pub(super) fn double_support_key(
        &self,
        trailing: &Footfall,
        leading: &Footfall,
        strike_phase: f64,
        ms_before: &PelvisKey,
        ms_after: &PelvisKey,
    ) -> PelvisKey {
        let r = &self.gait.r;
        let ground = trailing.heel.y.min(leading.heel.y);
        // During a speed-up the double support sinks by the coming ramp step's vertical range
        // and drop when they are the larger (both grow with speed), as the mid-stance key
        // takes the drop: the double support stays the vertical range below the mid-stance
        // around it. (The drop's share changes configs/pace.toml's walk, not the scheduled
        // 0.8 -> 1.6 m/s walk's largest pelvis velocity change, 1.13x steady either way.)
        let (vertical_range, drop) = self.coming_ramp().map_or((r.vertical_range, r.midstance_drop), |next| {
            (next.vertical_range.max(r.vertical_range), next.midstance_drop.max(r.midstance_drop))
        });
        PelvisKey {
            phase: strike_phase + r.double_support_key * (r.toe_off - 0.5),
            x: 0.5 * (ms_before.x + ms_after.x),
            y: ground + r.dims.standing_hip_height() - drop - vertical_range,
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
    pub(super) fn choose_double_support(
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
        let best = if method.is_none() { Some(fixed_rule) } else { searched_choice(&candidates, fixed_rule) };
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
}

/// The swing heel's lead on a step with a riser just ahead of its toe (a lag): its progress
/// toward the footfall at swing fraction `s` is the design curve's at `s − 0.7 · s · (1 − s)`
/// (0.03 at 8 % of the swing, 0.15 at 30 %), and the foot's pitch is handed over on the same
/// clock, so the foot goes up before it goes forward. Held behind the riser by the swing target
/// alone, the toe built up a debt of up to 5 cm, paid back in one frame as it passed the nosing
/// (the heel 10-18 cm in a frame, the knee straight for a frame at 2.0 m/s; a reviewer's find).
/// At 0.6 a 20 cm riser at 1.5 m/s still paid 3 cm back in a frame; at 0.8 the heel's late
/// catch-up lengthened single frames' steps more than the hold had (docs/gait-model.md §12).
const RISER_LEAD: f64 = -0.7;

/// Whether a step from ground at height `ground_from` lands on `to` at the same height (within
/// [`LEVEL_M`]): the swing's early heel and its carried toe-off pitch are for such steps only.
/// Unlike [`super::pace::even_between`] a slope's rise over the step counts as not level.
fn level_step(ground_from: f64, to: &Footfall) -> bool {
    (to.heel.y - ground_from).abs() < LEVEL_M
}

/// How much further than its toe-off angle the ankle may plantarflex after toe-off (deg).
/// The normative walk's ankle goes on plantarflexing for 2-4 % of the cycle after toe-off,
/// by 0.5-2.7° (data/normative/joint_angles_by_speed.csv: about 0.5 at 0.8 m/s, 2.7 at 1.3,
/// 2.5 at 1.6). The design curve dips 4.6° below its own start, and moving the start to a
/// deeper toe-off angle carried the whole dip down with it: at 1.6 m/s the ankle reached
/// −23.6° at 66 % of the cycle (norms −15.8° at 64 %; normal adults 12-20°).
pub(crate) const PUSH_OFF_AFTER_TOE_OFF_DEG: f64 = 2.5;

/// Raises the swing ankle curve where, in the first third of the swing, it dips more than
/// [`PUSH_OFF_AFTER_TOE_OFF_DEG`] below the toe-off angle `toe_off_deg` (the curve's start).
/// The lowest point is searched on a grid, since a user's curve may dip between its keys.
fn limit_push_off_after_toe_off(ankle_deg: &mut Curve, toe_off_deg: f64) {
    let floor = toe_off_deg - PUSH_OFF_AFTER_TOE_OFF_DEG;
    let (x, lowest) = (1..=40)
        .map(|i| f64::from(i) / 120.0)
        .map(|x| (x, ankle_deg.eval(x)))
        .fold((0.0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    if lowest < floor {
        ankle_deg.raise_at(x, floor - lowest);
    }
}

#[cfg(test)]
mod tests {
    use crate::config::presets;
    use crate::model::walk::Walker;
    use crate::model::walk::pelvis::KeyKind;

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

    #[test]
    fn a_search_s_best_replaces_the_fixed_rule_only_when_clearly_cheaper() {
        use super::{CLEARLY_LOWER, searched_choice};
        use crate::model::search::Candidate;
        let at = |x: f64, cost: Option<f64>| Candidate { x, y: 0.9, cost };
        let fixed = at(1.0, Some(1000.0));
        let tie = 1000.0 * (1.0 - 0.5 * CLEARLY_LOWER);
        let clear = 1000.0 * (1.0 - 2.0 * CLEARLY_LOWER);
        let near = [at(1.0, Some(1000.0)), at(1.02, Some(tie)), at(1.04, None)];
        assert_eq!(searched_choice(&near, fixed).unwrap().x, 1.0, "a tie keeps the fixed rule");
        let far = [at(1.0, Some(1000.0)), at(1.02, Some(tie)), at(1.04, Some(clear))];
        assert_eq!(searched_choice(&far, fixed).unwrap().x, 1.04);
        // A fixed rule out of reach is no choice; no candidate in reach is none.
        let unreachable = at(1.0, None);
        assert_eq!(searched_choice(&near, unreachable).unwrap().x, 1.02);
        assert!(searched_choice(&[at(1.0, None), at(1.02, None)], fixed).is_none());
    }
}
