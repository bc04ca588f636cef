//! One leg through its four phases [6.3.2] and the swing plan made at toe-off.

use crate::model::body::{BodyDims, Side};
use crate::model::curve::Curve;
use glam::{DQuat, DVec3};

/// The four leg phases (spec §3), each holding a different contact point fixed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LegPhase {
    /// Heel on the ground where it struck; the foot rolls down flat.
    LoadingResponse,
    /// Foot flat; the ankle is held.
    Midstance,
    /// Terminal stance and pre-swing: the heel lifts, the toe tip is held.
    HeelRise,
    /// The foot flies to the next footfall.
    Swing,
}

impl LegPhase {
    /// Short lower-case name, as printed in tables.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LegPhase::LoadingResponse => "loading",
            LegPhase::Midstance => "midstance",
            LegPhase::HeelRise => "heel_rise",
            LegPhase::Swing => "swing",
        }
    }

    /// Whether the foot carries weight.
    #[must_use]
    pub fn is_stance(self) -> bool {
        self != LegPhase::Swing
    }

    /// The phase that follows.
    #[must_use]
    pub fn next(self) -> LegPhase {
        match self {
            LegPhase::LoadingResponse => LegPhase::Midstance,
            LegPhase::Midstance => LegPhase::HeelRise,
            LegPhase::HeelRise => LegPhase::Swing,
            LegPhase::Swing => LegPhase::LoadingResponse,
        }
    }
}

/// Where a foot is set down.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Footfall {
    /// Step number: 0 is the first right footfall, odd numbers are left.
    pub step: i64,
    /// Which foot.
    pub side: Side,
    /// Heel contact point on the ground (m, world).
    pub heel: DVec3,
    /// Slope of the ground under the foot, heel to toe (rad, + uphill).
    pub(crate) ground_angle: f64,
    /// Foot direction about the vertical (rad); turnout turns the toes outward.
    pub(crate) yaw: f64,
    /// Where the step would have landed on unbroken ground (x, m); stairs move the footfall
    /// to one tread, and the next step is planned from here so the error does not add up.
    pub(crate) nominal_x: f64,
}

impl Footfall {
    /// Where the ankle is with the foot flat on this footfall.
    #[must_use]
    pub(crate) fn flat_ankle(&self, dims: &BodyDims) -> DVec3 {
        self.heel - foot_rotation(self.yaw, self.ground_angle) * dims.heel_local()
    }
}

/// The swing, planned once at toe-off: the curves the heel and foot will follow.
#[derive(Clone, Debug)]
pub struct SwingPlan {
    /// Heel at toe-off.
    pub(crate) heel_from: DVec3,
    /// Ground height under the toe-off foot: the heel-height curve's zero.
    pub(crate) ground_from: f64,
    /// The footfall the swing lands on.
    pub to: Footfall,
    /// Toe bend at toe-off (rad); returns to neutral over the first fifth of the swing.
    pub(crate) toe_bend_from: f64,
    /// Foot pitch at toe-off (rad): carried on at its toe-off rate at first, handed to the
    /// ankle curve over the first 15 % of the swing.
    pub(crate) pitch_from: f64,
    /// How fast the foot's pitch was changing at toe-off (rad per unit of swing fraction).
    pub(crate) pitch_rate_from: f64,
    /// Heel progress 0→1 toward the footfall.
    pub forward: Curve,
    /// How far ahead of the design curve the heel moves forward, frozen when the step is
    /// planned ([`SwingPlan::progress`]; the speed law `swing_lead`); below 0 (a lag) with a
    /// riser just ahead of the toe, when the foot's pitch is handed over on the same clock.
    pub(crate) lead: f64,
    /// Weight toward the hip line.
    pub lateral: Curve,
    /// The ankle against the shank (deg, dorsiflexion +): the design curve with its start moved
    /// to the toe-off ankle angle, its end turned up for an uphill landing.
    pub ankle_deg: Curve,
    /// Heel height above `ground_from` (m): scaled, end-shifted and raised where needed.
    pub(crate) heel_height: Curve,
    /// Heel-height raises the 50-sample simulation made (count).
    pub raises: u32,
    /// The stair riser just ahead of the toe at toe-off, which the toe is held behind until it
    /// has risen past the nosing.
    pub(crate) riser: Option<RiserAhead>,
    /// The ground the toe leaves, which the front of the foot stays on or above.
    pub(crate) toe_floor: ToeFloor,
}

/// A stair riser just ahead of a swing foot's toe at toe-off (stairs up). The swing's heel
/// path and the foot's pitch hand-over are planned for open ground; on the treads, left to
/// them, the toe moved 3 cm forward and 5 cm up in the first swing frame, 9.5 cm into the
/// riser a finger's width ahead. A foot lifts clear of a step before it moves over it: such a
/// swing lags (its [`SwingPlan::lead`] below 0, the planner's `RISER_LEAD`), and the swing
/// target holds what is left of the front of the foot behind the riser.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RiserAhead {
    /// Furthest forward the front of the foot may be while it is below the nosing (m).
    pub(crate) hold_x: f64,
    /// The nosing's height (m).
    pub(crate) nosing_y: f64,
}

impl RiserAhead {
    /// Furthest forward the front of the foot may be at height `y` and swing fraction `s` (m):
    /// `hold_x` below the nosing, twice as far again as it is above it, and let go over the
    /// swing from [`RISER_HOLD_SWING_SHARE`] on (a foot landing on the tread at the nosing's
    /// height). The swing simulation raises the heel where the hold binds from 8 % of the
    /// swing on. A steep let-go (20 times) paid a held toe's debt back in one frame.
    #[must_use]
    pub(crate) fn front_limit_x(&self, y: f64, s: f64) -> f64 {
        self.hold_x + 2.0 * (y - self.nosing_y).max(0.0) + (s - RISER_HOLD_SWING_SHARE).max(0.0) * 4.0
    }
}

/// The ground a swing's toe leaves, up to its next corner (flat ground, a tread, a slope, a
/// piece of rough ground). As the heel, rising at toe-off, is taken over by the swing's
/// heel-height curve, the front of the foot dipped 0.6-1.2 mm back into it in the first swing
/// frames (stairs down at 0.9-1.1 m/s; a start's first swing 0.4 mm; rough ground 1.1 mm at
/// 240 frames a second): a toe drags along the ground it leaves, never through it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ToeFloor {
    /// The toe tip's x at toe-off (m).
    pub(crate) x: f64,
    /// The ground's height there (m).
    pub(crate) y: f64,
    /// The ground's slope up to `until_x` (rise over run).
    pub(crate) slope: f64,
    /// Where that piece of ground ends ahead of the toe: a nosing, a slope's start, a vertex
    /// of rough ground (m).
    pub(crate) until_x: f64,
}

impl ToeFloor {
    /// The lowest the front of the foot may be at `x` and swing fraction `s` (m): the
    /// ground's line up to `until_x`, falling away at 45° past it, never above the toe's
    /// ground behind the toe (carried back up a downhill line, past a slope's start or a
    /// rough vertex behind, it lifted the ball 13-18 mm in the first swing frame; a
    /// reviewer's find), and let go over the swing from [`RISER_HOLD_SWING_SHARE`] on, as
    /// the riser hold is.
    #[must_use]
    pub(crate) fn lowest_y(&self, x: f64, s: f64) -> f64 {
        let along = self.slope * (x.min(self.until_x) - self.x);
        let along = if x < self.x { along.min(0.0) } else { along };
        self.y + along - (x - self.until_x).max(0.0) - (s - RISER_HOLD_SWING_SHARE).max(0.0) * 4.0
    }

    /// The highest [`Self::lowest_y`] between `x0` and `x1` (`x0 <= x1`): at an end, at the
    /// toe's x or at `until_x`, as it is a line between those.
    #[must_use]
    pub(crate) fn highest_between(&self, x0: f64, x1: f64, s: f64) -> f64 {
        let mut y = self.lowest_y(x0, s).max(self.lowest_y(x1, s));
        for x in [self.x, self.until_x] {
            if (x0..=x1).contains(&x) {
                y = y.max(self.lowest_y(x, s));
            }
        }
        y
    }
}

/// From what share of the swing on a toe held behind the riser ahead ([`RiserAhead`]) is let
/// go, and the floor under a toe leaving the ground ([`ToeFloor`]) falls away.
pub(crate) const RISER_HOLD_SWING_SHARE: f64 = 0.35;

impl SwingPlan {
    /// The heel's forward progress at swing fraction `s`: the forward curve at `s` moved
    /// ahead by `lead · s · (1 − s)`, so that both ends stay where they are.
    #[must_use]
    pub fn progress(&self, s: f64) -> f64 {
        self.forward.eval(led_fraction(s, self.lead))
    }

    /// Where the heel's way puts it along x at `progress` (m), before the swing target holds
    /// it behind a riser.
    #[must_use]
    pub(crate) fn planned_heel_x(&self, progress: f64) -> f64 {
        self.heel_from.x + (self.to.heel.x - self.heel_from.x) * progress
    }
}

/// Swing fraction `s` moved ahead by `lead · s · (1 − s)`: the ends stay, and for a lead up
/// to 1 the result still rises with `s` (its slope is 1 + lead at toe-off, 1 − lead at heel
/// strike), so the heel never steps back.
#[must_use]
pub(crate) fn led_fraction(s: f64, lead: f64) -> f64 {
    s + lead * s * (1.0 - s)
}

/// What a leg does at one instant: the IK input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegTarget {
    /// Ankle joint target (m, world).
    pub ankle: DVec3,
    /// Foot pitch vs horizontal (rad, toe up +).
    pub(crate) pitch: f64,
    /// Toe bend relative to the foot (rad, toes up +).
    pub(crate) toe_bend: f64,
    /// Foot yaw (rad).
    pub(crate) yaw: f64,
    /// Extra heel rise the stance leg needed to reach the hip (rad), 0 mostly.
    pub(crate) extra_heel_rise: f64,
    /// How far (m) the loaded heel pad is compressed: the ankle sits this much lower than the
    /// rigid foot would put it, the contact points on the ground.
    pub(crate) pad: f64,
}

/// The solved leg.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegPose {
    /// Hip joint (m, world).
    pub hip: DVec3,
    /// Knee joint.
    pub knee: DVec3,
    /// Ankle joint, as the IK placed it.
    pub ankle: DVec3,
    /// Unit swivel direction of the knee about the hip→ankle axis.
    pub swivel: DVec3,
    /// Foot world rotation.
    pub foot: DQuat,
    /// Toe world rotation.
    pub toe: DQuat,
    /// Heel contact point.
    pub heel: DVec3,
    /// Toe joint (ball of the foot).
    pub(crate) ball: DVec3,
    /// Toe tip contact point.
    pub(crate) toe_tip: DVec3,
    /// Whether the IK reached its target.
    pub reached: bool,
    /// The target it was solved for.
    pub target: LegTarget,
}

/// A leg's state between updates.
#[derive(Clone, Debug)]
pub struct LegState {
    /// Which leg.
    pub side: Side,
    /// Current phase.
    pub phase: LegPhase,
    /// Master phase of this leg's last heel strike; the leg's own phase is master − this.
    pub(crate) cycle_start: f64,
    /// The footfall it stands on (during swing: the one it left).
    pub footfall: Footfall,
    /// The contact point held in the current stance phase: heel (loading), ankle
    /// (midstance), toe joint (heel rise).
    pub(crate) anchor: DVec3,
    /// Foot–ground angle at heel strike (rad), rolled to zero through loading response.
    pub(crate) strike_angle: f64,
    /// Heel-rise curve scale frozen at the phase's start: stride / 1.8 m.
    pub(crate) heel_rise_scale: f64,
    /// The heel-rise curve, frozen at the phase's start: the design depends on the walk's
    /// speed, and a pace change at a heel strike (the other leg always in its heel rise) took
    /// a knee 7.4 -> 20.6 deg in a frame when the curve changed under it.
    pub(crate) heel_rise_curve: Curve,
    /// Cycle phase of this leg's toe-off, frozen when its heel rise starts: its heel rise
    /// and swing are timed by it, so a pace change (which moves the toe-off with speed) never
    /// moves a heel rise or a swing under way.
    pub(crate) toe_off: f64,
    /// Cycle phase of this leg's heel rise, frozen when its step is planned (at its toe-off):
    /// its stance was guarded for reach with it, so a change of pace or of `legs.heel_rise`
    /// (which moves the phase with speed) never moves the heel rise of a leg already landing.
    /// Held walk-wide instead, a heel strike always found the other leg inside its heel rise,
    /// and a 1.3 -> 1.6 m/s walk raised its heels at 0.31 of the cycle for good, not 0.28.
    pub(crate) heel_rise: f64,
    /// Share of the lift toward the straight stance leg (`pelvis.stance_rise`), frozen when
    /// its step is planned, as `heel_rise` is: a live change or a pace change lifts the next
    /// stance, never one already lifted.
    pub(crate) stance_rise: f64,
    /// The reach (m) the lift keeps this leg within (`ik.reach_margin` of its length), frozen
    /// with `stance_rise`: read live, a change of the margin mid-stance dropped a lifted pelvis
    /// 4.1 mm in a frame (1.1 mm with the lift off).
    pub(crate) stance_reach: f64,
    /// How far (m) the loaded heel pad lets the ankle sink in this leg's loading response
    /// (`legs.heel_pad_mm` on flat ground, none elsewhere), frozen when its step is planned so
    /// that the reach guard sees the stance that will be walked.
    pub(crate) pad: super::heel_pad::HeelPad,
    /// The current swing's plan.
    pub swing: Option<SwingPlan>,
    /// Counts phase changes, so one phase instance can be told from the next.
    pub phase_serial: u64,
    /// The last solved pose.
    pub pose: LegPose,
}

/// Foot world rotation from yaw (about y) and pitch (about the foot's z, toe up +).
#[must_use]
pub fn foot_rotation(yaw: f64, pitch: f64) -> DQuat {
    DQuat::from_rotation_y(yaw) * DQuat::from_rotation_z(pitch)
}

/// The three phase boundaries of a leg's stance (cycle phase): where the foot is flat, where
/// the heel rises, where the toe leaves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PhaseBounds {
    pub(crate) foot_flat: f64,
    pub(crate) heel_rise: f64,
    pub(crate) toe_off: f64,
}

#[cfg(test)]
mod tests {
    use super::led_fraction;

    #[test]
    fn a_lead_moves_the_swing_ahead_between_fixed_ends_and_never_back() {
        for lead in [0.0, 0.15, 0.3, 1.0] {
            assert_eq!(led_fraction(0.0, lead), 0.0);
            assert_eq!(led_fraction(1.0, lead), 1.0);
            let samples: Vec<f64> = (0..=100).map(|i| led_fraction(f64::from(i) / 100.0, lead)).collect();
            assert!(samples.windows(2).all(|w| w[1] >= w[0]), "lead {lead}");
        }
        // 0.8 m/s's lead: at three quarters of the swing the heel is where the design curve
        // has it at 0.778.
        assert!((led_fraction(0.75, 0.15) - 0.778_125).abs() < 1e-12);
    }
}
