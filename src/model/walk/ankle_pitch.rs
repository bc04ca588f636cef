//! The swing foot's pitch for an asked ankle angle: the swing's ankle curve is the ankle's own
//! angle, as the thesis draws it (fig 6.8) and the clinic measures it, but the IK is given a
//! foot pitch, and the ankle moves with the pitch (the heel is what the swing places). Its own
//! file because it is solved for each of the hundreds of swing targets a step plans — the
//! largest part of a step's planning — and is worked in sines and cosines to keep it cheap.

use crate::model::params::Resolved;
use glam::DVec3;

/// The foot pitch (rad, toe up +) that gives an ankle dorsiflexion of `dorsi` (rad) on a leg
/// from `hip` whose heel is at `heel`, the foot turned by `yaw` (rad) about the vertical. A
/// foot pitched against the horizontal instead flaps with the knee — it showed 20°
/// dorsiflexion in mid-swing where people hold 0–5°.
///
/// The pitch p solves p = shank(ankle(p)) + dorsi, the shank angle being the two-bone IK's
/// ([`shank_angle`](super::gait::shank_angle)). Started from the closed form of
/// `PitchSolve::closed_form` (below), one Newton step lands within 1e-9 rad on the walks measured;
/// from the dorsiflexion itself, where the leg is nearly straight and the residual curves hard,
/// Newton takes five or six (the plain fixed-point iteration crawled: three passes left
/// 0.1–0.6° with the knee bent and up to 7° near full reach).
#[must_use]
pub fn foot_pitch_for_ankle(hip: DVec3, heel: DVec3, yaw: f64, dorsi: f64, r: &Resolved) -> f64 {
    let leg = PitchSolve::new(hip, heel, yaw, dorsi, r);
    let guess = leg.closed_form();
    let mut turn = guess.unwrap_or((leg.cos_dorsi, leg.sin_dorsi));
    let mut pitch = guess.map_or(dorsi, |(cos, sin)| sin.atan2(cos));
    let mut from_guess = guess.is_some();
    // The pitches seen with the residual positive and negative: the root lies between. Where
    // the asked angle needs the leg at full reach, the residual turns a corner there (its slope
    // infinite on the reachable side) and Newton's steps alone jump across it back and forth
    // (3.6° off after ten); a step that would leave the bracket halves it instead.
    let (mut above, mut below) = (None::<f64>, None::<f64>);
    for _ in 0..64 {
        let (g, slope) = leg.residual(turn);
        // A start whose residual is not small (the yaw's correction missed, or the closed
        // form's branch is not the IK's) falls back to the dorsiflexion.
        if from_guess && g.abs() > 1e-3 {
            (pitch, turn, from_guess) = (dorsi, (leg.cos_dorsi, leg.sin_dorsi), false);
            continue;
        }
        from_guess = false;
        if g.abs() < 1e-9 {
            break;
        }
        if g > 0.0 {
            above = Some(pitch);
        } else {
            below = Some(pitch);
        }
        // A flat slope (the shank turning with the foot one for one) has no Newton step; the
        // fixed-point step still moves toward the root there.
        let mut next = pitch + if slope.abs() > 1e-6 { (-g / slope).clamp(-0.5, 0.5) } else { g };
        let mut newton = true;
        if let (Some(a), Some(b)) = (above, below) {
            if (a - b).abs() < 1e-12 {
                break;
            }
            if next <= a.min(b) || next >= a.max(b) {
                (next, newton) = (0.5 * (a + b), false);
            }
        }
        pitch = next;
        // The residual falls with the square of its size (to about 7 g² on the walks
        // measured): a Newton step from below 1e-5 lands within 1e-9, with no evaluation to
        // confirm.
        if newton && g.abs() < 1e-5 {
            break;
        }
        let (sin, cos) = pitch.sin_cos();
        turn = (cos, sin);
    }
    pitch
}

/// One pitch problem: the leg, the heel and the asked ankle angle, with the sines and cosines
/// every evaluation shares.
struct PitchSolve {
    /// Heel relative to the hip, in the walking plane (m).
    heel_x: f64,
    heel_y: f64,
    cos_yaw: f64,
    sin_yaw: f64,
    cos_dorsi: f64,
    sin_dorsi: f64,
    /// The heel in the foot's frame (the ankle is the heel minus this, turned by the foot).
    heel_local: DVec3,
    thigh: f64,
    shank: f64,
}

impl PitchSolve {
    fn new(hip: DVec3, heel: DVec3, yaw: f64, dorsi: f64, r: &Resolved) -> Self {
        let (sin_yaw, cos_yaw) = yaw.sin_cos();
        let (sin_dorsi, cos_dorsi) = dorsi.sin_cos();
        Self {
            heel_x: heel.x - hip.x,
            heel_y: heel.y - hip.y,
            cos_yaw,
            sin_yaw,
            cos_dorsi,
            sin_dorsi,
            heel_local: r.dims.heel_local(),
            thigh: r.dims.thigh,
            shank: r.dims.shank,
        }
    }

    /// The pitch, as (cos, sin), in closed form. Without yaw the knee is the heel plus a
    /// vector w fixed in the foot's frame (back up the heel offset, then up the shank at the
    /// asked ankle angle) turned by the pitch, and it must lie a thigh's length from the hip:
    /// a cos p + b sin p = k. A yawed foot's heel offset is foreshortened in the walking plane
    /// by cos(yaw) (under a millimetre at the walk's toe-out): that difference, taken at the
    /// unyawed answer, moves the heel and the closed form is solved once more. `None` where
    /// the leg cannot reach.
    fn closed_form(&self) -> Option<(f64, f64)> {
        let (wx, wy) =
            (self.shank * self.sin_dorsi - self.heel_local.x, self.shank * self.cos_dorsi - self.heel_local.y);
        let solve = |dx: f64, dy: f64| {
            let a = dx * wx + dy * wy;
            let b = dy * wx - dx * wy;
            let k = 0.5 * (self.thigh * self.thigh - dx * dx - dy * dy - wx * wx - wy * wy);
            let amplitude_sq = a * a + b * b;
            if amplitude_sq < 1e-24 || k * k > amplitude_sq {
                return None;
            }
            // p = atan2(b, a) + acos(k / amplitude), by the angle sum.
            let (cos_spread, sin_spread) = (k, (amplitude_sq - k * k).sqrt());
            Some(((a * cos_spread - b * sin_spread) / amplitude_sq, (b * cos_spread + a * sin_spread) / amplitude_sq))
        };
        let (cos, sin) = solve(self.heel_x, self.heel_y)?;
        if self.cos_yaw == 1.0 {
            return Some((cos, sin));
        }
        let pitched_x = self.heel_local.x * cos - self.heel_local.y * sin;
        solve(self.heel_x + (1.0 - self.cos_yaw) * pitched_x, self.heel_y)
    }

    /// The residual g(p) = shank(ankle(p)) + dorsi − p (rad) at the pitch whose cosine and
    /// sine are `turn`, and its slope. The angle between the IK's shank and the one the pitch
    /// asks for is taken from their directions' cross and dot products: no arc functions on
    /// the Newton step that ends the solve (near the root the arc sine's series does).
    fn residual(&self, (cos_pitch, sin_pitch): (f64, f64)) -> (f64, f64) {
        let (hl, thigh, shank) = (self.heel_local, self.thigh, self.shank);
        let pitched_x = hl.x * cos_pitch - hl.y * sin_pitch;
        let pitched_y = hl.x * sin_pitch + hl.y * cos_pitch;
        // The ankle (heel − the turned offset) from the hip, in the walking plane.
        let dx = self.heel_x - (pitched_x * self.cos_yaw + hl.z * self.sin_yaw);
        let dy = self.heel_y - pitched_y;
        let (dx_dp, dy_dp) = (pitched_y * self.cos_yaw, -pitched_x);
        let length_sq = dx * dx + dy * dy;
        let raw_length = length_sq.sqrt();
        let length = raw_length.clamp((thigh - shank).abs() + 1e-9, thigh + shank - 1e-9);
        let cos_at_ankle =
            ((shank * shank + length * length - thigh * thigh) / (2.0 * shank * length)).clamp(-1.0, 1.0);
        let sin_at_ankle = (1.0 - cos_at_ankle * cos_at_ankle).max(0.0).sqrt();
        // The IK's shank angle is the hip–ankle direction turned back by the angle at the
        // ankle (the knee forward); the asked one is pitch − dorsi.
        let (sin_toward, cos_toward) = (dx / raw_length, -dy / raw_length);
        let sin_ik = sin_toward * cos_at_ankle - cos_toward * sin_at_ankle;
        let cos_ik = cos_toward * cos_at_ankle + sin_toward * sin_at_ankle;
        let sin_asked = sin_pitch * self.cos_dorsi - cos_pitch * self.sin_dorsi;
        let cos_asked = cos_pitch * self.cos_dorsi + sin_pitch * self.sin_dorsi;
        let sin_g = sin_ik * cos_asked - cos_ik * sin_asked;
        let cos_g = cos_ik * cos_asked + sin_ik * sin_asked;
        let g =
            if sin_g.abs() < 1e-3 && cos_g > 0.0 { sin_g + sin_g * sin_g * sin_g / 6.0 } else { sin_g.atan2(cos_g) };
        let toward_dp = (dx * dy_dp - dy * dx_dp) / length_sq;
        let at_ankle_dp = if length == raw_length && sin_at_ankle > 1e-12 {
            let length_dp = (dx * dx_dp + dy * dy_dp) / raw_length;
            let cos_dl = (length * length - shank * shank + thigh * thigh) / (2.0 * shank * length * length);
            -cos_dl * length_dp / sin_at_ankle
        } else {
            0.0
        };
        (g, toward_dp - at_ankle_dp - 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::params::WalkParams;
    use crate::model::walk::gait::shank_angle;
    use crate::model::walk::leg::foot_rotation;

    /// The ankle angle the IK gives a foot at `pitch` (rad).
    fn ankle_of(hip: DVec3, heel: DVec3, yaw: f64, pitch: f64, r: &Resolved) -> (f64, DVec3) {
        let ankle = heel - foot_rotation(yaw, pitch) * r.dims.heel_local();
        (pitch - shank_angle(hip, ankle, r.dims.thigh, r.dims.shank), ankle)
    }

    #[test]
    fn the_swing_foot_gets_the_ankle_angle_asked_for_within_a_nanoradian() {
        let r = WalkParams::default().resolve();
        let hip = DVec3::new(0.0, 0.9, 0.0);
        let (mut worst, mut solved) = (0.0_f64, 0);
        // Heels from behind the hip at toe-off to ahead of it at heel strike, low and high,
        // ankle angles from push-off plantarflexion to landing dorsiflexion, feet straight and
        // turned out as the walk's are (7°) and further.
        for heel_x in [-0.45, -0.25, 0.0, 0.2, 0.3] {
            for heel_y in [0.01, 0.1, 0.25] {
                for dorsi_deg in [-20.0_f64, -5.0, 0.0, 5.0] {
                    for yaw_deg in [0.0_f64, 7.0, -7.0, 20.0] {
                        let (heel, yaw) = (DVec3::new(heel_x, heel_y, 0.0), yaw_deg.to_radians());
                        let pitch = foot_pitch_for_ankle(hip, heel, yaw, dorsi_deg.to_radians(), &r);
                        let (got, ankle) = ankle_of(hip, heel, yaw, pitch, &r);
                        // Where the leg cannot reach the heel, no pitch gives the angle.
                        if hip.distance(ankle) < r.dims.leg_reach() * 0.999 {
                            worst = worst.max((got - dorsi_deg.to_radians()).abs());
                            solved += 1;
                        }
                    }
                }
            }
        }
        assert!(solved >= 180, "only {solved} reachable cases");
        assert!(worst < 1e-9, "worst ankle error {worst} rad");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(3000))]
        /// Any heel the leg can reach, any ankle angle and yaw the walk can ask: the pitch
        /// gives the angle within a nanoradian, whichever start the solve took (the closed
        /// form, or the dorsiflexion where the closed form has no answer).
        #[test]
        fn any_reachable_heel_gets_its_ankle_angle(
            heel_x in -0.5_f64..0.45,
            below_hip in 0.55_f64..0.95,
            dorsi_deg in -30.0_f64..25.0,
            yaw_deg in -10.0_f64..30.0,
        ) {
            let r = WalkParams::default().resolve();
            let hip = DVec3::new(0.0, 0.9, 0.0);
            let heel = DVec3::new(heel_x, 0.9 - below_hip, 0.0);
            let yaw = yaw_deg.to_radians();
            let pitch = foot_pitch_for_ankle(hip, heel, yaw, dorsi_deg.to_radians(), &r);
            proptest::prop_assert!(pitch.is_finite() && pitch.abs() <= std::f64::consts::PI + 0.5);
            let (got, ankle) = ankle_of(hip, heel, yaw, pitch, &r);
            let (dx, dy) = (ankle.x - hip.x, ankle.y - hip.y);
            let sagittal = (dx * dx + dy * dy).sqrt();
            if sagittal < r.dims.leg_reach() * 0.999 && sagittal > (r.dims.thigh - r.dims.shank).abs() + 0.05 {
                proptest::prop_assert!((got - dorsi_deg.to_radians()).abs() < 1e-9, "error {} rad", got - dorsi_deg.to_radians());
            }
        }
    }

    #[test]
    fn the_closed_form_start_is_the_knee_forward_answer() {
        // The closed form's other root bends the knee backward; the one taken must be within
        // the yaw correction's reach of the IK's answer, not merely some answer.
        let r = WalkParams::default().resolve();
        let hip = DVec3::new(0.0, 0.9, 0.0);
        for (heel_x, heel_y, dorsi_deg) in [(-0.3, 0.05, -15.0_f64), (0.0, 0.2, 0.0), (0.25, 0.03, 5.0)] {
            let heel = DVec3::new(heel_x, heel_y, 0.0);
            let leg = PitchSolve::new(hip, heel, 0.0, dorsi_deg.to_radians(), &r);
            let (cos, sin) = leg.closed_form().expect("reachable");
            let (got, _) = ankle_of(hip, heel, 0.0, sin.atan2(cos), &r);
            assert!((got - dorsi_deg.to_radians()).abs() < 1e-12, "{heel_x} {heel_y}: {got}");
        }
    }
}
