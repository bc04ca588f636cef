//! Gait initiation (docs/gait-model.md §13): a walk that begins standing, and a start from
//! standing — at the beginning or after a stop.
//!
//! A start is the stop played forward, with the same parts: the legs keep the walk's phase
//! rules (heel rise, toe-off, swing, heel strike, each at its usual share of the cycle), so
//! a start is a matter of *when* each leg's cycle begins and *where* the first foot lands.
//! Asked at master phase `p`, the start picks the first half-cycle boundary `c` (the
//! initiating leg's cycle start; which leg follows from its parity) at which both the
//! initiating leg's heel rise and the pelvis's launch still lie ahead; the other leg's
//! cycle starts half a cycle later, so that from its heel rise on it walks exactly as in the
//! steady walk. The first step is [`FIRST_STEP`] of a steady one (published initiation:
//! 60–80 %), the second a full step on from it, so the walk is steady from the second step.
//!
//! The pelvis stands still until its launch (see [`Launch`]) carries it from rest onto the
//! keyed path at the first double support. That key is planned with the start, at the fixed
//! rule, and the first step's toe-off plans nothing of the pelvis but keeps it: the launch
//! aims at it from the moment the body first moves.

use crate::model::body::Side;
use crate::model::walk::Walker;
use crate::model::walk::gait::place_footfall;
use crate::model::walk::leg::{Footfall, LegPhase, LegState};
use crate::model::walk::pace::{PaceEvent, PaceEventKind, STANDING_REACH};
use crate::model::walk::pace_state::{StartStage, StopStage};
use crate::model::walk::pelvis::{KeyKind, Launch, PelvisKey, PelvisPlan, PelvisPose, Settle};
use glam::DVec3;

/// The first step's length as a share of a steady step: published gait initiation sets the
/// first foot down at 60–80 % of a steady step (e.g. Jian et al. 1993; Brunt et al. 1999),
/// the second near steady.
pub const FIRST_STEP: f64 = 0.7;
/// The initiating leg's heel rise as a share of a steady step's, on even ground: its push-off
/// starts beside the other foot, under a body still at rest (as the closing step's, which
/// ends there).
pub const START_HEEL_RISE: f64 = 0.5;

/// How far from the first step's average pace toward the steady walk's the pelvis passes the
/// first step's mid-stance key.
///
/// With [`DOUBLE_SUPPORT_PACE_SHARE`], chosen on the default walk (1.3 m/s) for the smallest
/// change of pelvis velocity per frame: 1.10x the steady walk's largest; halfway (0.5, 0)
/// gave 1.49x, the steady pace at once (1.0, 1.0) 1.22x.
pub const MIDSTANCE_PACE_SHARE: f64 = 0.9;
/// How far below the first step's average pace the pelvis passes its double support, as a
/// share of the mid-stance key's rise above it: the step's average must still come out, so a
/// faster mid-stance asks a slower double support.
pub const DOUBLE_SUPPORT_PACE_SHARE: f64 = 0.75;

/// The weight shift onto the stance foot before the first toe-off, as a share of the walk's
/// peak-to-peak sideways sway (0.5: the body over the stance foot as far as at mid-stance).
pub const WEIGHT_SHIFT: f64 = 0.5;

/// A start worked out for one candidate moment.
struct StartPlan {
    initiator: Side,
    cycle_start: f64,
    first: Footfall,
    keys: [PelvisKey; 4],
    launch: Launch,
}

impl Walker {
    /// Makes a freshly built walker stand at x = 0: both feet flat side by side (right step
    /// 0, left step −1), the pelvis at rest over the ankles as a stop leaves it, arms hanging.
    pub(super) fn stand_still(&mut self) {
        let r = &self.gait.r;
        let right = place_footfall(&self.terrain, r, 0, Side::Right, 0.0);
        let left = place_footfall(&self.terrain, r, -1, Side::Left, 0.0);
        let rest = self.rest_over(&right.flat_ankle(&r.dims).max(left.flat_ankle(&r.dims)));
        for (leg, footfall, cycle_start) in [(0, right, 0.0), (1, left, -0.5)] {
            let leg = &mut self.legs[leg];
            leg.phase = LegPhase::Midstance;
            leg.cycle_start = cycle_start;
            leg.footfall = footfall;
            leg.anchor = footfall.flat_ankle(&self.gait.r.dims);
            leg.strike_angle = 0.0;
            leg.swing = None;
        }
        self.footfalls = vec![left, right];
        let mut plan = PelvisPlan::default();
        for (phase, kind) in [(-1.0, KeyKind::DoubleSupport), (-0.5, KeyKind::MidStance)] {
            plan.push(PelvisKey { phase, x: rest.0, y: rest.1, kind, pace: 0.0 });
        }
        plan.settle(Settle::at_rest(0.0, rest));
        self.plan = plan;
    }

    /// Where the pelvis stands at rest over an ankle at `ankle` (the higher of two on
    /// uneven ground): above it, as high as the legs reach with the knees a little bent.
    pub(super) fn rest_over(&self, ankle: &glam::DVec3) -> (f64, f64) {
        let r = &self.gait.r;
        let dz = 0.5 * (r.dims.hip_width - r.step_width_m);
        let reach = STANDING_REACH * r.dims.leg_reach();
        (ankle.x, ankle.y + (reach * reach - dz * dz).max(0.0).sqrt())
    }

    /// Asks a standing walk to set off: the first step begins within half a cycle. Ignored
    /// unless standing.
    pub fn request_start(&mut self) {
        if !matches!(self.pace.stop, StopStage::Standing { .. }) {
            return;
        }
        self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::StartAsked });
        let p = self.phase;
        let first_boundary = (2.0 * p).ceil() / 2.0;
        // The launch lasts at most `Launch::MAX_SPAN` cycles, so one of the first eight
        // boundaries leaves it room; the last is taken whatever happens.
        let fits = |s: &StartPlan| s.launch.window.from_phase >= p && s.cycle_start + self.gait.r.heel_rise > p;
        let mut plan = self.start_plan(first_boundary);
        for k in 1..8 {
            if fits(&plan) {
                break;
            }
            plan = self.start_plan(first_boundary + 0.5 * f64::from(k));
        }
        let flat_until = [
            (plan.initiator, plan.cycle_start + self.gait.r.heel_rise),
            (plan.initiator.other(), plan.cycle_start + 0.5 + self.gait.r.heel_rise),
        ];
        self.lower_for_flat_feet(&mut plan.keys, plan.launch, flat_until);
        self.begin_start(plan);
    }

    /// The start whose initiating leg's cycle begins at `cycle_start` (a multiple of ½: the
    /// right leg's cycles start at whole phases, the left's at halves).
    fn start_plan(&self, cycle_start: f64) -> StartPlan {
        let r = &self.gait.r;
        let initiator = if (2.0 * cycle_start).rem_euclid(2.0) < 0.5 { Side::Right } else { Side::Left };
        let stance = &self.legs[initiator.other().index()].footfall;
        // After `begin_start`'s renumbering the stance foot is the later: the first step is
        // the one after it.
        let own = self.legs[initiator.index()].footfall.step;
        let step = if stance.step > own { stance.step + 1 } else { own + 2 };
        // On stairs the first step climbs (or descends) one tread like any other: a short
        // step there lands on the tread the feet stand on, or just past its edge.
        let place =
            |share: f64| place_footfall(&self.terrain, r, step, initiator, stance.nominal_x + share * 0.5 * r.stride_m);
        let full = place(1.0);
        let first = if super::pace::even_between(stance, &full) { place(FIRST_STEP) } else { full };
        let ms_stance = self.midstance_key(stance, cycle_start + 0.5);
        let ms_first = self.midstance_key(&first, cycle_start + 1.0);
        let ds = self.double_support_key(stance, &first, cycle_start + 1.0, &ms_stance, &ms_first);
        // The pelvis speeds up through the first step instead of at its mid-stance: keyed at
        // the first step's own pace (as a steady step's are), the whole speed-up to the
        // second step fell into the quarter cycle after its mid-stance, a change of pelvis
        // velocity per frame of 2.1x the steady walk's largest.
        let ms_first = PelvisKey { pace: ds.pace + MIDSTANCE_PACE_SHARE * (r.stride_m - ds.pace), ..ms_first };
        let ds = PelvisKey { pace: ds.pace - DOUBLE_SUPPORT_PACE_SHARE * (ms_first.pace - ds.pace), ..ds };
        // The keyed path's speed and acceleration where the launch hands over to it.
        let mut keyed = PelvisPlan::default();
        keyed.push(ds);
        keyed.push(ms_first);
        let h = 1e-3;
        let x = |k: f64| self.pelvis_position_with_plan(&keyed, ds.phase + k * h).0;
        let (x0, x1, x2) = (x(0.0), x(1.0), x(2.0));
        let (v1, a1) = ((-3.0 * x0 + 4.0 * x1 - x2) / (2.0 * h), (x0 - 2.0 * x1 + x2) / (h * h));
        let rest = self.pelvis_position_with_plan(&self.plan, self.phase);
        // The weight shift reaches half the walk's sideways sway toward the stance foot (as far
        // as the walk leans over a foot at mid-stance) by the first toe-off, from the ask on,
        // and gives way to the sway by the launch's end (by the stance leg's mid-stance, a
        // fifth of a cycle after the toe-off, it moved the pelvis sideways 2.4x as abruptly as
        // the walk ever does).
        let stance_side = initiator.other().sign();
        let launch = Launch::new(ds.phase, rest.0, (ds.x, v1, a1)).with_weight_shift(
            stance_side * WEIGHT_SHIFT * r.lateral_range,
            [self.phase, cycle_start + r.toe_off, ds.phase],
        );
        // The standing key, at the ask: from it the height goes to the stance leg's mid-stance
        // key, lowered where the shifting and launching pelvis asks it.
        let standing = PelvisKey { phase: self.phase, x: rest.0, y: rest.1, kind: KeyKind::DoubleSupport, pace: 0.0 };
        StartPlan { initiator, cycle_start, first, keys: [standing, ms_stance, ds, ms_first], launch }
    }

    /// Lowers the stance leg's mid-stance key (`keys[1]`) where a leg whose foot stays flat
    /// until a phase of `flat_until` could not reach it under the launching pelvis: from
    /// rest the legs are nearly straight, and the pelvis moves forward before either heel
    /// has risen (a flat foot has no heel rise to lengthen the leg with).
    fn lower_for_flat_feet(&self, keys: &mut [PelvisKey; 4], launch: Launch, flat_until: [(Side, f64); 2]) {
        let r = &self.gait.r;
        let limit = r.reach_margin * r.dims.leg_reach();
        let trial = |keys: &[PelvisKey; 4]| {
            let mut plan = self.plan.clone();
            plan.launch(keys, launch);
            plan
        };
        // Lowering the stance key moves the hips straight down and nothing else: the pelvis at
        // each sample is worked out once, and a pass asks only its height again (the same
        // numbers as a whole `pelvis_with_plan`, as in the reach guard).
        let mut plan = trial(keys);
        let mut samples: Vec<(Side, f64, PelvisPose)> = Vec::new();
        for (side, until) in flat_until {
            let from = keys[0].phase;
            let count = ((until - from) / 0.01).ceil().max(0.0) as usize;
            samples.extend((0..=count).map(|n| {
                let phase = (from + n as f64 * 0.01).min(until);
                (side, phase, self.pelvis_with_plan(&plan, phase))
            }));
        }
        let hip_under = |plan: &PelvisPlan, side: Side, phase: f64, pose: &PelvisPose| {
            let y = plan.height(phase, &self.gait.traj);
            PelvisPose { position: DVec3::new(pose.position.x, y, pose.position.z), ..*pose }.hip(side.sign())
        };
        for _pass in 0..4 {
            let mut probe = *keys;
            probe[1].y -= 0.01;
            let lowered = trial(&probe);
            let mut lower = 0.0f64;
            for (side, phase, pose) in &samples {
                let ankle = self.legs[side.index()].anchor;
                let hip = hip_under(&plan, *side, *phase, pose);
                let d = hip - ankle;
                let horizontal_sq = d.x * d.x + d.z * d.z;
                let deficit = d.y - (limit * limit - horizontal_sq).max(0.0).sqrt();
                let moves = (hip.y - hip_under(&lowered, *side, *phase, pose).y) / 0.01;
                if deficit > 0.0 && moves > 0.05 {
                    lower = lower.max(deficit / moves + 1e-4);
                }
            }
            if lower <= 0.0 {
                break;
            }
            keys[1].y -= lower;
            plan = trial(keys);
        }
    }

    /// Sets the start in motion: the legs' cycles, the numbering that keeps the stance foot's
    /// step ahead of the initiating foot's, the pelvis keys and launch.
    fn begin_start(&mut self, plan: StartPlan) {
        let (i, s) = (plan.initiator.index(), plan.initiator.other().index());
        // Step numbers keep their side's parity and grow along the walk: the foot the walk
        // sets off from must be numbered after the one that steps (the two stand side by side,
        // so which was "ahead" is a matter of naming).
        if self.legs[s].footfall.step < self.legs[i].footfall.step {
            let renumbered = self.legs[i].footfall.step + 1;
            let old = self.legs[s].footfall.step;
            self.legs[s].footfall.step = renumbered;
            if let Some(pos) = self.footfalls.iter().rposition(|f| f.step == old && f.side == plan.initiator.other()) {
                let mut moved = self.footfalls.remove(pos);
                moved.step = renumbered;
                self.footfalls.push(moved);
            }
        }
        self.legs[i].cycle_start = plan.cycle_start;
        self.legs[s].cycle_start = plan.cycle_start + 0.5;
        // Phases the standing legs held were kept out of a live edit's phase-boundary rule.
        self.gait.r.heel_rise = self.params.resolve().heel_rise;
        self.plan.launch(&plan.keys, plan.launch);
        self.pace.stop = StopStage::None;
        self.pace.start = StartStage::FirstStep { first: plan.first, initiator: plan.initiator };
    }

    /// The first step's footfall, while it is still to be planned.
    pub(super) fn first_step_footfall(&self) -> Option<Footfall> {
        match self.pace.start {
            StartStage::FirstStep { first, .. } => Some(first),
            _ => None,
        }
    }

    /// The share of the usual heel rise the initiating leg takes (1 for every other leg, and
    /// on uneven ground, where a tread's nosing may be in the way).
    pub(super) fn start_heel_rise_share(&self, leg: &LegState) -> f64 {
        match self.pace.start {
            StartStage::FirstStep { first, initiator }
                if initiator == leg.side && super::pace::even_between(&leg.footfall, &first) =>
            {
                START_HEEL_RISE
            }
            _ => 1.0,
        }
    }

    /// After the first step is planned: the launch runs to its end.
    pub(super) fn first_step_planned(&mut self) {
        self.pace.start = StartStage::Launching;
        self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::FirstStep });
    }

    /// After an update: the start is over once the pelvis is on the keyed path; the plan
    /// drops the spent launch, so nothing afterwards blends by it.
    pub(super) fn check_walking(&mut self) {
        let on_keys = self.plan.launching().is_none_or(|l| self.phase >= l.window.end_phase());
        if self.pace.start == StartStage::Launching && on_keys {
            self.plan.end_launch();
            self.pace.start = StartStage::None;
            self.pace.events.push(PaceEvent { time_s: self.time_s, kind: PaceEventKind::Walking });
        }
    }
}
