//! Pace changes and the walk's end (docs/gait-model.md §13): the schedule (or a caller, with
//! [`Walker::request_speed`] and [`Walker::request_stop`]) asks for a speed or a stop; the walker takes a new speed step by step at heel strikes (stride and
//! cadence from the usual speed relations, the cadence blended over the step so the pelvis
//! never changes speed with a jump), and a stop as a braking step, a closing step that sets
//! the trailing foot beside the leading one, and the pelvis settling over the feet.
//!
//! Why at heel strike: it is the one instant no leg is in swing, so the toe-off share of the
//! cycle (which shrinks with speed) can change without moving a swing under way, and no
//! stance leg's held contact point depends on the speed. The footfalls, pelvis keys and swing
//! take the new stride from the next toe-off, about an eighth of a cycle later.

use crate::model::body::Side;
use crate::model::schedule::PaceAction;
use crate::model::search::Candidate;
use crate::model::walk::Walker;
use crate::model::walk::gait::place_footfall;
use crate::model::walk::leg::LegPose;
use crate::model::walk::leg::{Footfall, LegPhase, LegState};
pub use crate::model::walk::pace_state::{PaceEvent, PaceEventKind, WalkState};
use crate::model::walk::pace_state::{StartStage, StepKind, StopStage};
use crate::model::walk::pelvis::PelvisKey;
use crate::model::walk::pelvis::Settle;
use crate::model::walk::step_problem::StepRecord;

/// Steps a speed change is spread over: half of it at the first heel strike after it is
/// asked, the rest at the next.
pub const RAMP_STEPS: u32 = 2;
/// The braking step's length as a share of a steady step. Termination shortens the last
/// step: the leading foot is set down nearer, so that its stance can take the body's
/// momentum (Jaeger & Vanitchatchavan 1992 measured the stopping step's braking impulse;
/// the share is a model choice, see docs/gait-model.md §13).
pub const BRAKING_STEP: f64 = 0.8;
/// The closing leg's heel rise as a share of a steady step's, on level ground.
pub const CLOSING_HEEL_RISE: f64 = 0.5;
/// Height difference between two footfalls, beyond what the slope under the second
/// explains, below which the ground between them counts as even (m).
pub const LEVEL_M: f64 = 0.01;

/// Whether the ground from footfall `from` to `to` is even: no stair between them, only the
/// slope the foot at `to` stands on.
#[must_use]
pub(crate) fn even_between(from: &Footfall, to: &Footfall) -> bool {
    let sloped = to.ground_angle.tan() * (to.heel.x - from.heel.x);
    (to.heel.y - from.heel.y - sloped).abs() < LEVEL_M
}
/// Slowest and fastest speed the schedule and the lab may ask for (m/s), as `walk.speed_mps`.
pub const SPEED_RANGE_MPS: (f64, f64) = (0.4, 2.0);

impl Walker {
    /// At `side`'s toe-off: plan its footfall, the pelvis keys up to its mid-stance, and the
    /// swing [6.3.2].
    pub(super) fn plan_step(&mut self, side: Side, at: f64, toe_off_pose: &LegPose) {
        let i = side.index();
        self.pace.ramp_planned |= self.pace.ramp.is_some();
        // The step is planned with the toe-off its leg froze at heel rise (a pace change at
        // the heel strike between may have moved the walk's).
        let walk_toe_off = self.gait.r.toe_off;
        self.gait.r.toe_off = self.legs[i].toe_off;
        self.legs[i].heel_rise = self.gait.r.heel_rise;
        let leaving = self.legs[i].footfall;
        self.plan_swing_step(side, at, toe_off_pose);
        let other = &self.legs[side.other().index()].footfall;
        let level = self.legs[i]
            .swing
            .as_ref()
            .is_some_and(|plan| super::stance_rise::on_level_ground(&[leaving, plan.to, *other]));
        let share = super::stance_rise::share_for_heel_rise(self.legs[i].heel_rise);
        self.legs[i].stance_rise = if level { share * self.gait.r.stance_rise } else { 0.0 };
        self.legs[i].stance_reach = self.gait.r.reach_margin * self.gait.r.dims.leg_reach();
        self.gait.r.toe_off = walk_toe_off;
    }

    /// The kind of step `side` takes now and its footfall: a step on from `other`'s nominal
    /// place (a steady step half a stride, the braking step [`BRAKING_STEP`] of that, the
    /// closing step none), settled on the ground.
    pub(super) fn next_footfall(&self, side: Side, other: &Footfall) -> (StepKind, Footfall) {
        let kind = self.next_step_kind();
        if let Some(first) = self.first_step_footfall() {
            return (kind, first);
        }
        let share = match kind {
            StepKind::Starting => super::initiation::FIRST_STEP,
            StepKind::Steady => 1.0,
            StepKind::Braking => BRAKING_STEP,
            StepKind::Closing => 0.0,
        };
        let nominal_x = other.nominal_x + share * 0.5 * self.gait.r.stride_m;
        (kind, place_footfall(&self.terrain, &self.gait.r, other.step + 1, side, nominal_x))
    }

    /// The step's double-support decision: the optimiser's (or the fixed rule's) choice, but
    /// for the closing step of a stop, whose pelvis is settling, the fixed rule's key
    /// uncosted. `keys`: the mid-stance before, the double support, the mid-stance after.
    pub(super) fn decide_double_support(
        &mut self,
        kind: StepKind,
        side: Side,
        at: f64,
        landing: LegState,
        [ms_before, ds, ms_after]: [PelvisKey; 3],
    ) -> StepRecord {
        let step = landing.footfall.step;
        // The first step from standing too: the pelvis's launch aims at its fixed-rule key.
        if matches!(kind, StepKind::Closing | StepKind::Starting) {
            return fixed_record(side, at, step, &ms_before, &ds, &ms_after);
        }
        self.choose_double_support(side, at, step, landing, ms_before, ds, ms_after)
    }

    /// The swing's heel-height scale on even ground (1 on stairs, where the nosing must be
    /// cleared): for the first and the closing step half the share of a stride the heel
    /// covers; for any other step the share of a stride from footfall to footfall, below a
    /// whole one. That is the second step of a start, whose foot swings from beside the other
    /// (0.85 of a stride at 1.0 m/s): lifted as high as a whole stride's, its knee flexed as
    /// far and straightened 8.5° a frame into the heel strike (6.5 in the steady walk), its
    /// largest acceleration 7.73°/frame² against the steady walk's 6.08 (6.82 at 0.85).
    pub(super) fn swing_lift(&self, kind: StepKind, from: &Footfall, to: &Footfall, toe_off_heel_x: f64) -> f64 {
        match kind {
            StepKind::Closing | StepKind::Starting if even_between(from, to) => {
                (0.5 * (to.heel.x - toe_off_heel_x) / self.gait.r.stride_m).clamp(0.15, 1.0)
            }
            StepKind::Steady if even_between(from, to) => {
                let share = (to.heel.x - from.heel.x) / self.gait.r.stride_m;
                // A steady step's share is 1 but for rounding, and keeps its curve's bytes.
                if share < 0.999 { share.max(0.15) } else { 1.0 }
            }
            _ => 1.0,
        }
    }

    /// What the walker is doing.
    #[must_use]
    pub fn walk_state(&self) -> WalkState {
        if self.pace.start != StartStage::None {
            return WalkState::Starting;
        }
        match self.pace.stop {
            StopStage::None => WalkState::Walking,
            StopStage::Standing { .. } => WalkState::Standing,
            _ => WalkState::Stopping,
        }
    }

    /// Every pace event so far, in order.
    #[must_use]
    pub fn pace_events(&self) -> &[PaceEvent] {
        &self.pace.events
    }

    /// Metres the pelvis has come forward since the start.
    #[must_use]
    pub fn distance_m(&self) -> f64 {
        self.pelvis.position.x - self.pace.start_x
    }

    /// Asks for a new speed (m/s, clamped to [`SPEED_RANGE_MPS`]), reached over the next
    /// [`RAMP_STEPS`] steps; standing, it is the speed the walk sets off at. Ignored while a
    /// stop is under way.
    pub fn request_speed(&mut self, speed_mps: f64) {
        if !speed_mps.is_finite() {
            return;
        }
        let to = speed_mps.clamp(SPEED_RANGE_MPS.0, SPEED_RANGE_MPS.1);
        if matches!(self.pace.stop, StopStage::Standing { .. }) {
            // Nothing moves: the speed is the walk's at once (its sway and swing are faded out
            // while standing), and the next start plans its steps with it.
            let mut params = self.params.clone();
            params.walk.speed_mps = to;
            if self.set_params(&params).unwrap_or(false) {
                for kind in [PaceEventKind::SpeedAsked(to), PaceEventKind::SpeedReached(to)] {
                    self.pace.events.push(PaceEvent { time_s: self.time_s, kind });
                }
            }
            return;
        }
        if self.pace.stop != StopStage::None {
            return;
        }
        let from = self.params.walk.speed_mps;
        self.pace.ramp = Some((from, to, 0));
        self.pace.ramp_planned = false;
        self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::SpeedAsked(to) });
    }

    /// Asks the walk to stop: the next step brakes, the one after closes beside it.
    pub fn request_stop(&mut self) {
        if self.pace.stop == StopStage::None {
            self.pace.stop = StopStage::Asked;
            self.pace.ramp = None;
            self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::StopAsked });
        }
    }

    /// Fires the schedule's entries whose time or distance has come, in file order.
    pub(super) fn poll_schedule(&mut self) {
        while let Some(entry) = self.pace.entries.get(self.pace.next).copied() {
            if !entry.trigger.reached(self.time_s, self.distance_m()) {
                break;
            }
            self.pace.next += 1;
            match entry.action {
                PaceAction::Speed(v) => self.request_speed(v),
                PaceAction::Stop => self.request_stop(),
                PaceAction::Start => self.request_start(),
            }
        }
    }

    /// Cycle duration in force at master phase `phase`: the walk's, or on the way to it
    /// during a cadence blend — a cubic Hermite over [`CADENCE_BLEND_CYCLES`] from the duration
    /// and slope the blend began with to the walk's, flat at its end.
    #[must_use]
    pub(super) fn cycle_s_at(&self, phase: f64) -> f64 {
        self.cadence_blend_at(phase).0
    }

    /// The cycle duration (s) at `phase` and its slope (s per cycle of phase).
    fn cadence_blend_at(&self, phase: f64) -> (f64, f64) {
        let target = self.gait.r.cycle_s;
        let Some((from_phase, from_cycle, from_slope)) = self.pace.rate_from else { return (target, 0.0) };
        let span = CADENCE_BLEND_CYCLES;
        let u = ((phase - from_phase) / span).clamp(0.0, 1.0);
        let (u2, u3) = (u * u, u * u * u);
        let value = (2.0 * u3 - 3.0 * u2 + 1.0) * from_cycle
            + (u3 - 2.0 * u2 + u) * span * from_slope
            + (3.0 * u2 - 2.0 * u3) * target;
        let slope = if u >= 1.0 {
            0.0
        } else {
            ((6.0 * u2 - 6.0 * u) * from_cycle
                + (3.0 * u2 - 4.0 * u + 1.0) * span * from_slope
                + (6.0 * u - 6.0 * u2) * target)
                / span
        };
        (value, slope)
    }

    /// Advances by `dt_s` during a cadence blend: updates of at most [`super::MAX_UPDATE_CYCLES`]
    /// at the fastest rate of the blend, each at the rate where it starts.
    pub(super) fn advance_blending(&mut self, dt_s: f64, from_cycle: f64) {
        // A blend handed a slope may pass beyond both ends for a while: the rate now counts.
        let fastest = from_cycle.min(self.gait.r.cycle_s).min(self.cycle_s_at(self.phase));
        let n = (dt_s / fastest / super::MAX_UPDATE_CYCLES).ceil().max(1.0) as usize;
        let sub = dt_s / n as f64;
        for _ in 0..n {
            let cycle = self.cycle_s_at(self.phase);
            self.update_to(self.phase + sub / cycle);
        }
        if let Some((from_phase, ..)) = self.pace.rate_from
            && self.phase >= from_phase + CADENCE_BLEND_CYCLES
        {
            self.pace.rate_from = None;
        }
    }

    /// The cadence blend under way, if any: the cycle duration it began from.
    pub(super) fn blending_from(&self) -> Option<f64> {
        self.pace.rate_from.map(|(_, c, _)| c)
    }

    /// At a heel strike (master phase `at`): takes the next step of a speed change.
    pub(super) fn pace_at_heel_strike(&mut self, at: f64) {
        let Some((from, to, done)) = self.pace.ramp else { return };
        if !self.pace.ramp_planned {
            return;
        }
        let done = done + 1;
        let speed = from + (to - from) * f64::from(done) / f64::from(RAMP_STEPS);
        self.apply_speed(speed, at);
        if done >= RAMP_STEPS {
            self.pace.ramp = None;
            self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::SpeedReached(to) });
        } else {
            self.pace.ramp = Some((from, to, done));
        }
    }

    /// Walks at `speed_mps` from master phase `at` (a heel strike): the parameters change as
    /// a live edit would change them, and the cadence blends over the coming cycle.
    fn apply_speed(&mut self, speed_mps: f64, at: f64) {
        // A blend under way hands on its duration and its slope: restarting flat at this
        // heel strike was a 1.24x joint jerk at a ramp's second step.
        let (old_cycle, old_slope) = self.cadence_blend_at(at);
        let mut params = self.params.clone();
        params.walk.speed_mps = speed_mps;
        // The same body, terrain and curves: the change cannot be refused. As at a hair before
        // the heel strike: the striking side's cycle curves (its arm's; the pelvis's with the
        // right leg) are at their cycle's end, about to wrap within this update, and must
        // take the change at the wrap, which pins the new cycle's start to the old one's end;
        // asked at the new cycle's start they would bend the old cycle's last segment, whose
        // end is that very instant, and jump.
        let applied = self.set_params_at(&params, at - 1e-9).unwrap_or(false);
        if applied {
            self.pace.reguard_landing = Some(at);
        }
        if applied && old_cycle != self.gait.r.cycle_s {
            self.pace.rate_from = Some((at, old_cycle, old_slope));
        }
    }

    /// The walk's derived values after the coming heel strike, when that strike takes a step
    /// of a speed change.
    pub(super) fn coming_ramp(&self) -> Option<crate::model::params::Resolved> {
        let (from, to, done) = self.pace.ramp?;
        let mut params = self.params.clone();
        params.walk.speed_mps = from + (to - from) * f64::from(done + 1) / f64::from(RAMP_STEPS);
        Some(params.resolve())
    }

    /// The kind of step to plan at the coming toe-off.
    pub(super) fn next_step_kind(&self) -> StepKind {
        if self.first_step_footfall().is_some() {
            return StepKind::Starting;
        }
        match self.pace.stop {
            StopStage::Asked => StepKind::Braking,
            StopStage::Braking { .. } => StepKind::Closing,
            _ => StepKind::Steady,
        }
    }

    /// After a step onto `to` of `kind` is planned.
    pub(super) fn step_planned(&mut self, kind: StepKind, to: &Footfall) {
        if kind == StepKind::Starting {
            self.first_step_planned();
            return;
        }
        let (stage, event) = match (kind, self.pace.stop) {
            (StepKind::Braking, _) => (StopStage::Braking { final_step: to.step }, PaceEventKind::Braking),
            (StepKind::Closing, StopStage::Braking { final_step }) => {
                (StopStage::Closing { final_step }, PaceEventKind::Closing)
            }
            _ => return,
        };
        self.pace.stop = stage;
        self.pace.events.push(PaceEvent { time_s: self.time_s, kind: event });
    }

    /// The share of the usual heel rise a leg entering heel rise takes: during a stop it is
    /// the closing leg, whose push-off only has to bring the foot up beside the other while
    /// the body slows down (a full push-off lifts the heel 19 cm, and a swing that starts so
    /// high lands under the body with the hip swinging back fast); otherwise 1.
    /// A closing step that climbs or descends (stairs) keeps the full push-off: its foot has
    /// a tread's nosing to clear.
    pub(super) fn closing_heel_rise_share(&self, leg: &LegState) -> f64 {
        let level = self.footfalls.last().is_some_and(|braking| even_between(&leg.footfall, braking));
        let closing =
            if matches!(self.pace.stop, StopStage::Braking { .. }) && level { CLOSING_HEEL_RISE } else { 1.0 };
        closing * self.start_heel_rise_share(leg)
    }

    /// Whether `leg` stays in midstance for good: it stands on the braking or the closing
    /// footfall.
    pub(super) fn holds_midstance(&self, leg: &LegState) -> bool {
        match self.pace.stop {
            StopStage::Braking { final_step }
            | StopStage::Closing { final_step }
            | StopStage::Standing { final_step } => leg.footfall.step >= final_step,
            _ => false,
        }
    }

    /// After an update: the walk is at rest once the pelvis has settled with both feet flat.
    pub(super) fn check_standing(&mut self) {
        let StopStage::Closing { final_step } = self.pace.stop else { return };
        let settled = self.plan.settling().is_some_and(|s| self.phase >= s.window.end_phase());
        if settled && self.legs.iter().all(|l| l.phase == LegPhase::Midstance) {
            self.pace.stop = StopStage::Standing { final_step };
            self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::Standing });
        }
    }

    /// At the braking step's toe-off (master phase `at`), with `braking` the footfall it goes
    /// to: the pelvis leaves its keys and comes to rest with the hip joints above the ankles
    /// there, as high as the legs reach with the knees a little bent, by the time the closing
    /// step has landed and rolled flat.
    pub(super) fn begin_settle(&mut self, at: f64, braking: &Footfall) {
        let r = &self.gait.r;
        let rest = self.rest_over(&braking.flat_ankle(&r.dims));
        let h = 1e-4;
        let x0 = self.pelvis_at(at).position.x;
        let v0 = (self.pelvis_at(at + h).position.x - self.pelvis_at(at - h).position.x) / (2.0 * h);
        // Swing of this step, the closing step's toe-off, swing and loading response.
        let closing_toe_off = (1.0 - r.toe_off) + (r.toe_off - 0.5);
        let wanted = closing_toe_off + (1.0 - r.toe_off) + r.foot_flat + 0.05;
        let settle = Settle::new(at, x0, v0, rest, wanted, closing_toe_off);
        self.plan.settle(settle);
    }
}

/// Hip-to-ankle distance of the standing legs as a share of full reach: knees 7° short of
/// straight, as in quiet standing (the walk's own reach margin, kept for moving legs, would
/// leave them bent 18°).
pub const STANDING_REACH: f64 = 0.998;

/// The record of a step whose double support is not chosen (the closing step: the pelvis is
/// settling): the fixed rule's key, uncosted.
pub(super) fn fixed_record(
    side: Side,
    at: f64,
    step: i64,
    ms_before: &PelvisKey,
    ds: &PelvisKey,
    ms_after: &PelvisKey,
) -> StepRecord {
    let fixed = Candidate { x: ds.x, y: ds.y, cost: None };
    StepRecord {
        step,
        side,
        phase: at,
        method: None,
        evaluations: 0,
        feasible: 0,
        candidates: vec![fixed],
        chosen: fixed,
        window_x: (ms_before.x, ms_after.x),
        fixed_rule: fixed,
        fallback: false,
        elapsed_us: 0.0,
    }
}

/// Gait cycles over which the cadence of a speed change's step fades in (a step interrupting
/// the blend starts its own from the duration and slope reached). Over half a cycle (one
/// step) and linearly, as first built, the swing under way sped up so fast that the knee
/// extended toward heel strike at 1.32x the steady walks' fastest, and the rate's corners were
/// 1.30x jerks (tests/pace.rs).
pub const CADENCE_BLEND_CYCLES: f64 = 1.0;
