//! The reach guard: the pelvis keys a step plans are lowered where a leg could not reach its
//! foot — the landing leg from the end of its swing through loading response and mid-stance,
//! and the trailing leg through its heel rise to toe-off [6.3.3]. Run when a step is planned
//! and again when a live change moves the hips' heights. Its own file as the planner's other
//! half: what a step *asks* of the pelvis, beside `planner.rs`'s what a step *is*.

use crate::model::body::Side;
use crate::model::walk::Walker;
use crate::model::walk::ankle_pitch::foot_pitch_for_ankle;
use crate::model::walk::gait::{MIN_STRIKE_ANGLE, SwingCurvesAt, swing_target_at};
use crate::model::walk::leg::{Footfall, LegPhase, SwingPlan, foot_rotation};
use crate::model::walk::pelvis::{KeyKind, PelvisKey, PelvisPose};
use crate::model::walk::reach_angles::MAX_HEEL_RISE;
use glam::DVec3;

impl Walker {
    /// The reach guard for the stance `side` is about to land in on `to`: the leg still
    /// stands on its old footfall until heel strike, so its state is lent the new footfall
    /// and strike angle for the guard's questions, then given back. Returns the guard's drop.
    pub(super) fn guard_landing_reach(
        &mut self,
        side: Side,
        to: Footfall,
        strike_angle: f64,
        strike_phase: f64,
        plan: &SwingPlan,
        playing_at: f64,
    ) -> f64 {
        let i = side.index();
        let saved_footfall = self.legs[i].footfall;
        let saved_strike = self.legs[i].strike_angle;
        self.legs[i].footfall = to;
        self.legs[i].strike_angle = strike_angle;
        let drop = self.guard_stance_reach(side, strike_phase, Some(plan), playing_at);
        self.legs[i].footfall = saved_footfall;
        self.legs[i].strike_angle = saved_strike;
        drop
    }

    /// Lowers the newest pelvis keys where `side`'s leg, striking at `strike_phase`, could not
    /// reach its ground contact during loading response and midstance. The terrain rule
    /// keeps the knee's extension, but a long stride or a big drop can still put the heel out
    /// of reach; the planner drops the pelvis rather than let the heel slide. Returns the
    /// drop of the double-support key (m).
    ///
    /// Planning passes `playing_at` = −∞. A live change passes the walk's phase: a key whose
    /// segment is already playing there stays put too.
    pub(super) fn guard_stance_reach(
        &mut self,
        side: Side,
        strike_phase: f64,
        swing: Option<&SwingPlan>,
        playing_at: f64,
    ) -> f64 {
        let r = self.gait.r.clone();
        let limit = r.reach_margin * r.dims.leg_reach();
        // Only the two newest keys may move: the segment ending at any older key may be
        // playing already, and moving its key would make the pelvis jump.
        let ds_phase = self.movable_key_phase(KeyKind::DoubleSupport, playing_at);
        let ms_phase = self.movable_key_phase(KeyKind::MidStance, playing_at);
        let points = self.guard_points(side, strike_phase, swing, limit);
        let mut dropped = 0.0;
        for _ in 0..6 {
            let deficits = self.deficits(&points, side, swing, limit);
            let Some((need, kind)) = self.key_to_lower(&deficits, ds_phase, ms_phase) else { break };
            if let Some(key) = self.plan.last_of_mut(kind) {
                key.y -= need;
                if kind == KeyKind::DoubleSupport {
                    dropped += need;
                }
            }
        }
        let standing = matches!(self.legs[side.index()].phase, LegPhase::LoadingResponse | LegPhase::Midstance);
        if playing_at.is_finite() && swing.is_none() && standing {
            self.rise_heel_where_out_of_reach(side, strike_phase, &points, playing_at, limit);
        }
        dropped
    }

    /// The guard points whose hip is above what its leg reaches: (phase, by how much, m).
    fn deficits(&self, points: &[GuardPoint], side: Side, swing: Option<&SwingPlan>, limit: f64) -> Vec<(f64, f64)> {
        let r = &self.gait.r;
        points
            .iter()
            .filter_map(|point| {
                let hip = self.rekeyed_hip(&point.pose, point.x, point.phase, point.side_sign);
                let allowed = match (&point.allowed, swing) {
                    (Allowed::Height(height), _) => *height,
                    (Allowed::Swing(at), Some(plan)) => {
                        allowed_height(hip, swing_target_at(plan, at, side, r, hip).ankle, limit)
                    }
                    (Allowed::Swing(_), None) => unreachable!("swing samples are made from a plan"),
                };
                (hip.y > allowed).then_some((point.phase, hip.y - allowed))
            })
            .collect()
    }

    /// After a live change, a deficit the guard could not lower away lies in a segment that is
    /// already playing (its key cannot move without a jump). At the end of mid-stance the leg
    /// then lifts its heel sooner, as a person whose hip runs ahead of a flat foot does: one
    /// guard sample (about two frames) before the first such deficit. With the double
    /// support at the legs' reach, 1.3 -> 1.45 m/s with the sway at 1.4 asked as the left leg
    /// passed its mid-stance took its hip 0.85 mm past reach for the frame before its heel
    /// rose (tests/gait_normal.rs, the change at frame 154).
    fn rise_heel_where_out_of_reach(
        &mut self,
        side: Side,
        strike_phase: f64,
        points: &[GuardPoint],
        playing_at: f64,
        limit: f64,
    ) {
        let i = side.index();
        let flat_from = strike_phase + self.gait.r.foot_flat;
        let first = self
            .deficits(points, side, None, limit)
            .into_iter()
            .map(|(phase, _)| phase)
            .filter(|&phase| phase > playing_at && phase > flat_from)
            .fold(f64::INFINITY, f64::min);
        if first.is_finite() {
            let heel_rise = self.legs[i].heel_rise;
            let sample = (heel_rise - self.gait.r.foot_flat) / 8.0;
            let sooner =
                (first - sample - strike_phase).max(playing_at - strike_phase + 1e-6).max(self.gait.r.foot_flat);
            self.legs[i].heel_rise = heel_rise.min(sooner);
        }
    }

    /// The instants the guard checks for `side` striking at `strike_phase`, the trailing
    /// leg's first. Lowering keys moves the hips straight down, so what a pass needs again is
    /// each hip's height: forward positions and, but for the swing's samples (whose ankle
    /// follows the hip), the allowed heights are worked out once here.
    fn guard_points(&self, side: Side, strike_phase: f64, swing: Option<&SwingPlan>, limit: f64) -> Vec<GuardPoint> {
        let r = &self.gait.r;
        let with_swing = swing.is_some();
        let footfall = self.legs[side.index()].footfall;
        let strike_angle = self.legs[side.index()].strike_angle;
        let mut points = Vec::with_capacity(28);
        // The other leg's heel rise up to its toe-off, which falls in the coming double
        // support: it must reach at some heel-rise angle the walk may take (a stair's upper
        // landing can lift the pelvis past the trailing foot's reach, tearing its toe off the
        // tread into the next riser). No lowering helps a foot too far behind: never short.
        if let Some(t) = self.trailing_reach(side, with_swing) {
            for &phase in &t.phases {
                let (pose, x, side_sign) = (self.pelvis_at(phase), self.rekeyed_x(phase), side.other().sign());
                // No heel pad here: the trailing leg let its own go by 30 % of its cycle.
                let allowed = t.allowed(self.rekeyed_hip(&pose, x, phase, side_sign), limit);
                let allowed = Allowed::Height(if allowed.is_finite() { allowed } else { f64::INFINITY });
                points.push(GuardPoint { phase, pose, x, side_sign, allowed });
            }
        }
        // From the end of the swing (when a plan is given: the knee is nearly straight there
        // too) through loading response and midstance, which lasts to heel rise: past the
        // mid-stance key when the toe-off is early (brisk walks), where the hip has moved on
        // and the leg is straightest. Samples are densest around heel strike.
        let mut samples: Vec<f64> = Vec::with_capacity(19);
        if with_swing {
            samples.extend([-0.03, -0.02, -0.01, -0.005].map(|d| strike_phase + d));
        }
        samples.extend((0..=6).map(|i| strike_phase + r.foot_flat * i as f64 / 6.0));
        let window_end = strike_phase + self.legs[side.index()].heel_rise;
        samples.extend(
            (1..=8).map(|i| strike_phase + r.foot_flat + (window_end - strike_phase - r.foot_flat) * i as f64 / 8.0),
        );
        for phase in samples {
            let (pose, x, side_sign) = (self.pelvis_at(phase), self.rekeyed_x(phase), side.sign());
            let allowed = match swing {
                Some(plan) if phase < strike_phase => {
                    Allowed::Swing(SwingCurvesAt::of(plan, 1.0 - (strike_phase - phase) / (1.0 - r.toe_off)))
                }
                _ => {
                    let s = ((phase - strike_phase) / r.foot_flat).clamp(0.0, 1.0);
                    let pitch = footfall.ground_angle + strike_angle * (1.0 - s);
                    let landing = &self.legs[side.index()];
                    let pad = super::heel_pad::compression_at(
                        landing.pad,
                        phase - strike_phase,
                        landing.heel_rise,
                        r.toe_off,
                    );
                    let ankle = footfall.heel
                        - foot_rotation(footfall.yaw, pitch) * r.dims.heel_local()
                        - DVec3::new(0.0, pad, 0.0);
                    Allowed::Height(allowed_height(self.rekeyed_hip(&pose, x, phase, side_sign), ankle, limit))
                }
            };
            points.push(GuardPoint { phase, pose, x, side_sign, allowed });
        }
        points
    }

    /// The phase of the newest key of `kind` if the segment ending at it starts after
    /// `playing_at` (so moving it moves no pelvis already played); NaN, matching no key, if not.
    fn movable_key_phase(&self, kind: KeyKind, playing_at: f64) -> f64 {
        let keys: Vec<&PelvisKey> = self.plan.keys().collect();
        let Some(at) = keys.iter().rposition(|k| k.kind == kind) else { return f64::NAN };
        let segment_start = if at == 0 { f64::NEG_INFINITY } else { keys[at - 1].phase };
        if segment_start > playing_at { keys[at].phase } else { f64::NAN }
    }

    /// After a live change of the pelvis's obliquity or tilt, which raise or lower a stance
    /// hip: the swinging leg's landing was guarded with the old shape when its step was
    /// planned, so its loading response and mid-stance are guarded again under the new one.
    /// Without this, a `walk.sway` edit in a few-frame window of the cycle left that leg out
    /// of reach at the end of its mid-stance (12 of 33 moments of a cycle, up to 0.5 mm of
    /// slide). Only keys not yet playing move.
    pub(super) fn guard_swing_landing_again(&mut self, playing_at: f64) {
        let Some(i) = self.legs.iter().position(|l| l.phase == LegPhase::Swing && l.swing.is_some()) else {
            return;
        };
        let (side, strike_phase) = (self.legs[i].side, self.legs[i].cycle_start + 1.0);
        let plan = self.legs[i].swing.clone().expect("checked above");
        let strike_hip = self.pelvis_at(strike_phase).hip(side.sign());
        let to = plan.to;
        let dorsi = plan.ankle_deg.eval(1.0).to_radians();
        let strike_angle = (foot_pitch_for_ankle(strike_hip, to.heel, to.yaw, dorsi, &self.gait.r) - to.ground_angle)
            .max(MIN_STRIKE_ANGLE);
        self.guard_landing_reach(side, to, strike_angle, strike_phase, &plan, playing_at);
    }

    /// After a pace change at a heel strike, once the cycle curves are playing that the leg
    /// which has just landed will stand under: its loading response and mid-stance are
    /// guarded again, as its step was planned at the old speed. The new speed's sway,
    /// rotation and obliquity move its hip by millimetres, and the walk kept only 0.1 % of
    /// reach in hand: a slowdown from 2.0 to 0.5 m/s left that leg out of reach at the end of
    /// its mid-stance (1-2 mm of slide). With 0.04 % in hand since session 15, what is still
    /// past reach (up to 0.30 deg of heel, 2.0 -> 0.5 m/s) is taken by the foot's roll in
    /// `Gait::target_of`. Only keys not yet playing at `playing_at` move.
    pub(super) fn reguard_after_pace_change(&mut self, playing_at: f64) {
        let Some(strike) = self.pace.reguard_landing.take() else { return };
        let landed =
            self.legs.iter().find(|l| l.phase == LegPhase::LoadingResponse && (l.cycle_start - strike).abs() < 1e-9);
        if let Some(side) = landed.map(|l| l.side) {
            self.guard_stance_reach(side, strike, None, playing_at);
        }
    }

    /// The hip of side `side_sign` at `phase`, `pose` being the pelvis there before the
    /// guard moved keys and `x` its forward position ([`Self::rekeyed_x`]). The guard only
    /// lowers keys, which changes the pelvis's height and nothing else, so only the height
    /// is evaluated again: the same numbers as a whole [`Walker::pelvis_at`], without its
    /// four angle curves, three rotations and forward curve on each of the guard's up to
    /// six passes.
    ///
    /// Past the last key (a fast walk's mid-stance key comes before the heel rises, and the
    /// segment after it is planned only at the other leg's toe-off) the pelvis goes on at the
    /// pace it passes that key with instead of stopping there: stopped, it hid up to 1.4 cm
    /// of forward travel over a flat foot from the guard.
    fn rekeyed_hip(&self, pose: &PelvisPose, x: f64, phase: f64, side_sign: f64) -> DVec3 {
        let traj = &self.gait.traj;
        let y = match self.plan.last() {
            Some(last) if phase > last.phase && self.plan.settling().is_none() => self.plan.height(last.phase, traj),
            _ => self.plan.height(phase, traj),
        };
        PelvisPose { position: DVec3::new(x, y, pose.position.z), ..*pose }.hip(side_sign)
    }

    /// The forward position [`Self::rekeyed_hip`] puts the pelvis at, which no lowering moves.
    fn rekeyed_x(&self, phase: f64) -> f64 {
        match self.plan.last() {
            Some(last) if phase > last.phase && self.plan.settling().is_none() => {
                let (x, _) = self.pelvis_position_with_plan(&self.plan, last.phase);
                x + last.pace * self.gait.traj.forward(last.kind).slope(0.0) * (phase - last.phase)
            }
            _ => self.pelvis_position_with_plan(&self.plan, phase).0,
        }
    }

    /// Of the movable keys (the newest double support and mid-stance: an older one may be
    /// playing already), the one to lower and by how much, so that the worst reach deficit
    /// goes: at each instant, the key that moves the pelvis most then.
    fn key_to_lower(&self, deficits: &[(f64, f64)], ds_phase: f64, ms_phase: f64) -> Option<(f64, KeyKind)> {
        let mut worst: Option<(f64, KeyKind)> = None;
        for &(phase, deficit) in deficits {
            let (a, b, u) = self.plan.bracket(phase);
            let v = self.gait.traj.height_progress(a.kind, b.y - a.y, u);
            let mut choice: Option<(KeyKind, f64)> = None;
            for (key, weight) in [(a, 1.0 - v), (b, v)] {
                let movable = key.phase == ds_phase || key.phase == ms_phase;
                if movable && choice.is_none_or(|(_, w)| weight > w) {
                    choice = Some((key.kind, weight));
                }
            }
            // A key that hardly moves the pelvis at the deficit's instant cannot take it away:
            // lowered by four times the deficit on each of the guard's passes it sank the
            // coming double support 9.4 cm for a 3.4 mm deficit just past the mid-stance key (a
            // live `ik.reach_margin` change at 0.8 m/s, the stance's last sample past the key
            // once its heel rise, then 0.322 of the cycle, passed the key's 0.32). Such a deficit is
            // the standing heel's to take (`rise_heel_where_out_of_reach`).
            let Some((kind, weight)) = choice.filter(|&(_, w)| w >= MOVING_WEIGHT) else { continue };
            let need = deficit / weight + 1e-4;
            if worst.is_none_or(|(w, _)| need > w) {
                worst = Some((need, kind));
            }
        }
        worst
    }

    /// The other leg's remaining heel rise, when a step is being planned (`planning`) and
    /// that leg stands.
    fn trailing_reach(&self, side: Side, planning: bool) -> Option<TrailingReach> {
        let leg = &self.legs[side.other().index()];
        if !planning || leg.phase == LegPhase::Swing {
            return None;
        }
        let r = &self.gait.r;
        let ff = leg.footfall;
        // The toe joint the heel rise turns about: where it is, or where it will be.
        let ball = if leg.phase == LegPhase::HeelRise {
            leg.anchor
        } else {
            ff.heel + foot_rotation(ff.yaw, ff.ground_angle) * (r.dims.ball_local() - r.dims.heel_local())
        };
        let (from, to) = (leg.cycle_start + leg.heel_rise, leg.cycle_start + r.toe_off);
        let phases = (0..=8).map(|i| from + (to - from) * f64::from(i) / 8.0).collect();
        // The ankle at each heel-rise angle depends on the foot alone, not on the hip the
        // guard tries: worked out once here, not for every phase of every pass (those
        // quaternions were a quarter of a step's planning instructions).
        let ankles = std::array::from_fn(|i| {
            let angle = MAX_HEEL_RISE * i as f64 / (TRAILING_ANGLES - 1) as f64;
            ball - foot_rotation(ff.yaw, ff.ground_angle - angle) * r.dims.ball_local()
        });
        Some(TrailingReach { phases, ankles })
    }
}

/// One instant the reach guard checks: a hip, and how high it may be for its leg to reach.
struct GuardPoint {
    phase: f64,
    /// The pelvis there before the guard moved keys.
    pose: PelvisPose,
    /// Its forward position, which no lowering moves.
    x: f64,
    side_sign: f64,
    /// How high the hip may be.
    allowed: Allowed,
}

/// How high a guard point's hip may be.
enum Allowed {
    /// At most this (m).
    Height(f64),
    /// As high as the swing's ankle there allows: it moves with the hip (the foot's pitch is
    /// set against the shank), so it is asked again on each pass, from the curves' values.
    Swing(SwingCurvesAt),
}

/// The highest `hip` may be, at its horizontal place, for a leg reaching `limit` to reach
/// `ankle`; `None` where the ankle is beyond reach sideways (no height reaches it).
fn reach_top(hip: DVec3, ankle: DVec3, limit: f64) -> Option<f64> {
    let d = hip - ankle;
    let horizontal = (d.x * d.x + d.z * d.z).sqrt();
    (horizontal < limit).then(|| ankle.y + (limit * limit - horizontal * horizontal).sqrt())
}

/// The least share of a key's move the pelvis makes at an instant for the guard to lower that
/// key for a deficit there ([`Walker::key_to_lower`]).
const MOVING_WEIGHT: f64 = 0.25;

/// [`reach_top`], or the ankle's own height where it is beyond reach sideways.
fn allowed_height(hip: DVec3, ankle: DVec3, limit: f64) -> f64 {
    reach_top(hip, ankle, limit).unwrap_or(ankle.y)
}

/// Heel-rise angles the trailing foot is tried at, from flat to [`MAX_HEEL_RISE`].
const TRAILING_ANGLES: usize = 30;

/// A trailing leg in (or coming to) heel rise: the toe joint it turns about and the instants
/// to check.
struct TrailingReach {
    phases: Vec<f64>,
    /// The ankle at each of the [`TRAILING_ANGLES`] heel-rise angles, the foot turning about
    /// its toe joint.
    ankles: [DVec3; TRAILING_ANGLES],
}

impl TrailingReach {
    /// The highest the hip at `hip`'s horizontal place may be for the leg to still reach its
    /// foot at some heel-rise angle up to [`MAX_HEEL_RISE`] (m); −∞ if no lowering would help
    /// (the foot is too far behind).
    fn allowed(&self, hip: DVec3, limit: f64) -> f64 {
        self.ankles.iter().filter_map(|&ankle| reach_top(hip, ankle, limit)).fold(f64::NEG_INFINITY, f64::max)
    }
}
