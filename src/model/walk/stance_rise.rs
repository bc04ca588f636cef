//! The pelvis rising over the stance leg through single support.
//!
//! The keyed height curve peaks at the forward mid-stance key, 12-16 cm ahead of the stance
//! heel (where the late-stance knee wants it, `speed_laws::midstance_offset_cm`), but a
//! person's hip is highest as it passes over the ankle, about 4 cm ahead of the heel: a slow
//! walker vaults over a nearly straight leg there. Under the keyed curve the 0.8 m/s walk's
//! hip passed over the ankle 1 cm lower than the leg reaches and its knee stayed flexed
//! 13-15° from 12 to 24 % of the cycle, where the speed-matched norms fall from 8.3° to 5.7°
//! (data/normative/joint_angles_by_speed.csv). So the drawn pelvis is lifted toward the
//! height at which the stance leg stands with the knee the norms have there
//! ([`MIDSTANCE_KNEE_DEG`]), in a window from just after heel strike to the heel rise, by the
//! share `pelvis.stance_rise` (derived from speed: [`crate::model::speed_laws::stance_rise`]),
//! on level ground. Around the heel rise the lift fades out ([`RISE_OUT_AROUND_HEEL_RISE`]).
//!
//! The planning (reach guard, optimiser, swing planner) keeps to the keyed curve, which the
//! lift only ever raises toward a reach the stance leg has by construction; the other leg,
//! swinging or still on its toes, caps it at `REACH_EASE` of its reach from where its target
//! is under the keyed pelvis (the cap's corner rounded over half a millimetre), so the lift
//! never rolls that foot further or takes it out of reach. A walk's first stances (set up,
//! not planned) are not lifted.

use crate::model::params::Resolved;
use crate::model::walk::Walker;
use crate::model::walk::gait::REACH_EASE;
use crate::model::walk::leg::{Footfall, LegState};
use crate::model::walk::pelvis::{PelvisPose, PhaseWindow};
use glam::DVec3;

/// How far apart in height (m) the footfalls around a stance may be for it to be lifted.
const LEVEL_TOLERANCE_M: f64 = 0.01;

/// How steep (rad) a footfall's ground may be for its stance to be lifted.
const LEVEL_TOLERANCE_RAD: f64 = 0.0175;

/// Whether a stance on these footfalls (the one the leg leaves, the one it lands on, the
/// other leg's) is on level ground, the only ground the lift is made on: on stairs a lifted
/// hip tipped the swinging foot's toe into a nosing (86 mm under it at 0.5 m/s on 22 cm
/// rises) and took a rolling foot out of reach (37 reach failures); on stairs, slopes, and rough
/// ground whose footfalls differ by more than 1 cm, the keyed curve's terrain rules [fig 6.14]
/// keep the height.
pub(crate) fn on_level_ground(footfalls: &[Footfall]) -> bool {
    let (low, high) =
        footfalls.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), f| (lo.min(f.heel.y), hi.max(f.heel.y)));
    high - low <= LEVEL_TOLERANCE_M && footfalls.iter().all(|f| f.ground_angle.abs() <= LEVEL_TOLERANCE_RAD)
}

/// How much of `pelvis.stance_rise` a stance whose heel rises at `heel_rise` (cycle phase)
/// takes: all of it for a heel rise from 0.26 to 0.33 of the cycle (the speed law's 0.265 to
/// 0.31), none before 0.20 or after 0.40, eased between. A late heel rise keeps the trailing
/// foot flat into the next loading response and then rolls it fast: the lift, held down by
/// that foot's reach, caught up within a frame as it rolled (the pelvis's largest vertical
/// acceleration at 0.8 m/s 3.0 / 5.3 / 7.5 / 12 / 22 m/s² for a heel rise at 0.33 / 0.35 /
/// 0.37 / 0.40 / 0.45, against 0.5-1.5 with no lift); an early one leaves the lift a bump
/// between its ramps (6.7 m/s² at 0.15, 3.1 at 0.20).
#[must_use]
pub(crate) fn share_for_heel_rise(heel_rise: f64) -> f64 {
    ease(heel_rise, 0.20, 0.26) * (1.0 - ease(heel_rise, 0.33, 0.40))
}

/// The lift's ramp in, in the stance leg's cycle phase after its heel strike: none before
/// 0.04, all of it from 0.16. At 0.8 m/s (knee RMS against the speed-matched norms, the
/// loading knee's peak; measured on a prototype whose lift could also lower the pelvis, 3.55°
/// became 3.40° when it could not): from 0.10 to 0.24 3.80°, 12.4° at 12 %; from 0.04 to 0.16
/// 3.55°, 8.6° at 10 % (the norms' 8.3° at 11 %); from heel strike to 0.12 3.81°, 6.5° at 3 %.
const RISE_IN: (f64, f64) = (0.04, 0.16);

/// The lift's ramp out, in cycle phase either side of the leg's heel rise: all of it up to
/// 0.06 before, none from 0.06 after. At 0.8 m/s, knee RMS against the norms and the pelvis's
/// largest vertical acceleration: this 2.45°, about 2.4 m/s² (the keyed walk's own largest at 1.3
/// m/s is 2.64); out over the 0.10 before the heel rise 2.55°, the pelvis falling 5 mm back to
/// the keyed curve with the foot still flat and the knee flexing and straightening again by
/// 5.6° between 22 and 32 % of the cycle; out over the 0.02 before it 2.46°, 4.47 m/s²; over the
/// 0.12 after it 2.44°, 3.53 m/s², the pelvis checked as the heel starts to rise.
const RISE_OUT_AROUND_HEEL_RISE: (f64, f64) = (0.06, 0.06);

/// The stance knee (deg) the lift stands the leg with: 7° where the lift is all in (0.16 of
/// the cycle), easing to 4° at the heel rise, as people's knee straightens through mid-stance
/// (the norms at 0.8 m/s: 7.3° at 16 %, 4.2° at 34 %). Lifted to the leg's reach margin (3°
/// throughout) the knee stood flat at 3.2° from 16 to 28 % of the cycle; with this, at 0.8 /
/// 1.0 m/s the knee RMS is 2.46 / 2.81° (3.2° flat: 2.70 / 2.81), hip 3.06 / 2.51, ankle 1.51 /
/// 1.52, and the knee is within 0.6° of the norms' mean from 14 to 28 %.
const MIDSTANCE_KNEE_DEG: (f64, f64) = (7.0, 4.0);

/// The smoothstep from 0 at `from` to 1 at `to` of `x` (the pelvis's blend windows' weight).
fn ease(x: f64, from: f64, to: f64) -> f64 {
    PhaseWindow { from_phase: from, span: to - from }.weight(x)
}

/// How much of the lift is in force at the stance leg's cycle phase `q`, 0 to 1, for a leg
/// whose heel rises at `heel_rise`.
fn window(q: f64, heel_rise: f64) -> f64 {
    let (out_from, out_to) = (heel_rise - RISE_OUT_AROUND_HEEL_RISE.0, heel_rise + RISE_OUT_AROUND_HEEL_RISE.1);
    ease(q, RISE_IN.0, RISE_IN.1).min(1.0 - ease(q, out_from, out_to))
}

/// The hip-to-ankle distance (m) of a stance leg standing with the knee [`MIDSTANCE_KNEE_DEG`]
/// gives at its cycle phase `q`, for a leg whose heel rises at `heel_rise`.
fn standing_distance(r: &Resolved, q: f64, heel_rise: f64) -> f64 {
    // A heel rise at or before the lift's full start (`legs.heel_rise` may be 0.15) straightens
    // the knee at once.
    let u = if heel_rise > RISE_IN.1 { ease(q, RISE_IN.1, heel_rise) } else { 1.0 };
    let (from, to) = MIDSTANCE_KNEE_DEG;
    let knee = (from + (to - from) * u).to_radians();
    let (thigh, shank) = (r.dims.thigh, r.dims.shank);
    (thigh * thigh + shank * shank + 2.0 * thigh * shank * knee.cos()).sqrt()
}

/// How wide (m) the lift's bends are where a cap takes over: with a hard `min` and `max` the
/// pelvis turned a corner as a trailing foot's cap rose through the keyed height (the largest
/// vertical acceleration at 0.8 m/s for a heel rise at 0.35 / 0.37 of the cycle 5.5 / 3.6
/// m/s², rounded over 0.5 mm 4.3 / 2.8). Session 20's slow walk falls later and more steeply
/// into double support and rises out of it as the other leg's lift ramps in: over 0.5 mm a
/// heel rise at 0.33 / 0.35 / 0.37 turned 5.6 / 9.0 / 6.3 m/s², over 2 mm 3.2 / 4.4 / 3.0, over
/// 3 mm 3.3 / 2.8 / 1.9 (the 0.8 m/s default's then, 0.322, its own 3.4, its joint curves
/// unchanged; the default since session 22 is 0.33).
const CAP_BEND_M: f64 = 0.003;

/// `max(x, 0)` with its corner rounded over [`CAP_BEND_M`]: ln(1 + eˣ) scaled (2.1 mm at 0).
fn soft_positive(x: f64) -> f64 {
    let u = x / CAP_BEND_M;
    if u > 30.0 { x } else { CAP_BEND_M * u.exp().ln_1p() }
}

/// The smaller of two lifts (≥ 0) with the corner rounded: (a⁻⁴ + b⁻⁴)^(−1/4), which is the
/// smaller within 1 % once the other is twice it, 0.84 of either where they are equal, and 0
/// where either is.
fn soft_min(a: f64, b: f64) -> f64 {
    if a <= 0.0 || b <= 0.0 {
        return 0.0;
    }
    (a.powi(-4) + b.powi(-4)).powf(-0.25)
}

/// The pelvis height at which the hip on `side_sign` is `distance` from `ankle`, the
/// pelvis's forward and side position and its rotations kept; `None` if the ankle is further
/// than `distance` across.
fn height_for_reach(pose: &PelvisPose, side_sign: f64, ankle: DVec3, distance: f64) -> Option<f64> {
    let hip = pose.hip(side_sign);
    let across2 = (hip.x - ankle.x).powi(2) + (hip.z - ankle.z).powi(2);
    let up2 = distance * distance - across2;
    (up2 > 0.0).then(|| pose.position.y + (ankle.y + up2.sqrt() - hip.y))
}

impl Walker {
    /// The pelvis the walk is drawn with at `phase`: the keyed pelvis, lifted toward the
    /// standing stance leg through single support (module docs).
    pub(crate) fn pelvis_walked(&self, phase: f64) -> PelvisPose {
        let mut pose = self.pelvis_at(phase);
        // Setting off and settling blend the sway and rotations in and out; the lift too, so
        // a stop or a start never makes the pelvis jump.
        let walking = self.plan.walking_weight(phase);
        if walking <= 0.0 {
            return pose;
        }
        let r = &self.gait.r;
        let keyed = pose.position.y;
        let mut lifted: Option<f64> = None;
        let weights = self.legs.each_ref().map(|leg: &LegState| {
            if leg.phase.is_stance() {
                walking * leg.stance_rise * window(phase - leg.cycle_start, leg.heel_rise)
            } else {
                0.0
            }
        });
        for (leg, &weight) in self.legs.iter().zip(&weights) {
            if weight <= 0.0 {
                continue;
            }
            let ankle = self.gait.target_of(leg, phase, pose.hip(leg.side.sign())).ankle;
            let distance = standing_distance(r, phase - leg.cycle_start, leg.heel_rise).min(leg.stance_reach);
            let Some(reached) = height_for_reach(&pose, leg.side.sign(), ankle, distance) else { continue };
            // Never below the keyed curve: the lift is only ever a rise.
            let y = keyed + weight * (reached - keyed).max(0.0);
            lifted = Some(lifted.map_or(y, |other: f64| other.min(y)));
        }
        let Some(y) = lifted else { return pose };
        let mut lift = y - keyed;
        // Every other leg, swinging or still on its toes in double support, keeps to the reach
        // it has under the keyed pelvis: the lift never takes it further (a trailing foot in
        // double support was pulled off the ground on a stair).
        for (leg, _) in self.legs.iter().zip(&weights).filter(|(_, w)| **w <= 0.0) {
            let target = self.gait.target_of(leg, phase, pose.hip(leg.side.sign()));
            // A foot on its toes rolls further from REACH_EASE of the reach on: kept inside it,
            // and so is the same leg once it swings, or the cap would jump at its toe-off.
            // A foot already further across than that (a late heel rise) allows no lift at all.
            let room = height_for_reach(&pose, leg.side.sign(), target.ankle, REACH_EASE * leg.stance_reach)
                .map_or(0.0, |cap| soft_positive(cap - keyed));
            lift = soft_min(lift, room);
        }
        pose.position.y = keyed + lift;
        pose
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lift_ramps_in_after_heel_strike_and_out_around_the_heel_rise() {
        let heel_rise = 0.31;
        assert_eq!(window(0.0, heel_rise), 0.0);
        assert_eq!(window(RISE_IN.0, heel_rise), 0.0);
        assert!((window(0.10, heel_rise) - 0.5).abs() < 1e-12);
        assert_eq!(window(0.2, heel_rise), 1.0);
        assert_eq!(window(heel_rise - 0.06, heel_rise), 1.0);
        assert!((window(heel_rise, heel_rise) - 0.5).abs() < 1e-12);
        assert_eq!(window(heel_rise + 0.06, heel_rise), 0.0);
        assert_eq!(window(0.6, heel_rise), 0.0);
    }

    #[test]
    fn the_standing_leg_straightens_from_7_to_4_degrees_through_mid_stance() {
        let r = crate::model::params::WalkParams::default().resolve();
        let knee_at = |q: f64| {
            let d = standing_distance(&r, q, 0.31);
            let (t, s) = (r.dims.thigh, r.dims.shank);
            ((d * d - t * t - s * s) / (2.0 * t * s)).acos().to_degrees()
        };
        assert!((knee_at(0.10) - 7.0).abs() < 1e-9);
        assert!((knee_at(0.16) - 7.0).abs() < 1e-9);
        assert!((knee_at(0.235) - 5.5).abs() < 1e-9);
        assert!((knee_at(0.31) - 4.0).abs() < 1e-9);
    }

    #[test]
    fn the_height_for_reach_puts_the_hip_that_far_from_the_ankle() {
        let pose = PelvisPose::new(DVec3::new(0.0, 0.9, 0.0), 0.1, 0.05, 0.02, 0.09);
        let ankle = DVec3::new(0.1, 0.05, 0.08);
        let y = height_for_reach(&pose, 1.0, ankle, 0.85).expect("in reach");
        let lifted = PelvisPose { position: DVec3::new(pose.position.x, y, pose.position.z), ..pose };
        assert!((lifted.hip(1.0).distance(ankle) - 0.85).abs() < 1e-12);
        assert_eq!(height_for_reach(&pose, 1.0, DVec3::new(2.0, 0.0, 0.0), 0.85), None);
    }
}
