//! The pelvis's rise and fall that a cycle of joint angles gives through this body's legs.
//!
//! People's pelvis (the WBDS adults' markers, [`super::PelvisNorms`]) rises and falls more
//! than the walk's at slow speeds, and the question a user then has is whether the walk's
//! joint curves are what holds it down. Put through the walk's own leg chain, people's mean
//! angles answer it: if they give no more range than the walk's own angles do, matching the
//! angles better cannot raise the pelvis, and the rest of the gap lies in what the chain
//! leaves out (a foot that rolls over its toes, soft tissue, the markers' place on the pelvis)
//! or in the difference between the adults whose angles were averaged (22) and those whose
//! pelvis markers were (5). The chain is the sagittal one the walk's legs solve: thigh, shank
//! and a rigid foot standing on whichever of heel and ball is lower, the pelvic obliquity
//! lifting one hip over the other; the hips' ab/adduction and the turnout, which the norms do
//! not give, are left out of both.

use crate::model::body::BodyDims;
use glam::DVec3;

/// One gait cycle of clinical angles (deg), sampled evenly from a right heel strike to the
/// next, both included (the norms' 0..=100 %, the snapshot's every 2 %). Hip flexion and pelvic tilt as
/// gait labs measure them (both against the pelvis's anatomical frame, so that their
/// difference is the thigh's angle from the vertical); obliquity positive with the right hip up.
#[derive(Clone, Copy, Debug)]
pub struct LegAngles<'a> {
    /// Right hip flexion.
    pub hip_flex: &'a [f64],
    /// Right knee flexion.
    pub knee_flex: &'a [f64],
    /// Right ankle dorsiflexion.
    pub ankle_dorsi: &'a [f64],
    /// Anterior pelvic tilt.
    pub pelvis_tilt: &'a [f64],
    /// Pelvic obliquity, right hip up.
    pub pelvis_obliquity: &'a [f64],
}

/// Samples the range is measured at over the cycle.
const SAMPLES: usize = 200;

/// The pelvis's vertical range (cm) that `angles` give through the legs of `dims` on level
/// ground: from each heel strike to the other foot's, the pelvis centre as high as the leg that
/// struck holds it (the left half a cycle after the right, mirrored). The trailing leg of a
/// double support is left out: it stands on its toes, where a rigid foot cannot follow it (fed
/// people's angles with both legs and the lower kept, the range grew with the stance share
/// assumed, 2.65 -> 5.05 cm at 1.0 m/s for a stance of 62 -> 68 %; leading leg only, it is the
/// both-legs figure at people's own toe-off, 60 % from 1.0 to 1.6 m/s). NaN when a curve has
/// fewer than two samples.
#[must_use]
pub fn pelvis_range_through_legs(angles: &LegAngles<'_>, dims: &BodyDims) -> f64 {
    let a = angles;
    if [a.hip_flex, a.knee_flex, a.ankle_dorsi, a.pelvis_tilt, a.pelvis_obliquity].iter().any(|c| c.len() < 2) {
        return f64::NAN;
    }
    let hip_height = |phase: f64| {
        let at = |curve: &[f64]| sample(curve, phase).to_radians();
        let thigh = at(a.hip_flex) - at(a.pelvis_tilt);
        let shank = thigh - at(a.knee_flex);
        let pitch = shank + at(a.ankle_dorsi);
        // The ankle's height over a point of the sole (in the foot's frame) pitched toes-up by
        // `pitch`: it stands on whichever of heel and ball is lower.
        let over = |sole: DVec3| -(sole.x * pitch.sin() + sole.y * pitch.cos());
        let ankle = over(dims.heel_local()).max(over(dims.ball_local()));
        dims.thigh * thigh.cos() + dims.shank * shank.cos() + ankle
    };
    let half_width = 0.5 * dims.hip_width;
    let (lowest, highest) = (0..SAMPLES)
        .map(|i| {
            let phase = i as f64 / SAMPLES as f64;
            let lift = half_width * sample(a.pelvis_obliquity, phase).to_radians().sin();
            if phase < 0.5 { hip_height(phase) - lift } else { hip_height(phase - 0.5) + lift }
        })
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), h| (lo.min(h), hi.max(h)));
    100.0 * (highest - lowest)
}

/// `curve` (evenly over the cycle, 0 and 100 % both sampled) at `phase` (0-1, wrapping),
/// linearly between samples.
fn sample(curve: &[f64], phase: f64) -> f64 {
    let spans = curve.len() - 1;
    let x = phase.rem_euclid(1.0) * spans as f64;
    let i = (x.floor() as usize).min(spans - 1);
    curve[i] + (curve[i + 1] - curve[i]) * (x - i as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::Sex;

    fn flat(v: f64, n: usize) -> Vec<f64> {
        vec![v; n]
    }

    #[test]
    fn still_legs_hold_the_pelvis_still_and_a_bent_knee_lowers_it_by_the_chain() {
        let d = BodyDims::from_height(1.75, Sex::Male);
        let zero = flat(0.0, 101);
        let still = LegAngles {
            hip_flex: &zero,
            knee_flex: &zero,
            ankle_dorsi: &zero,
            pelvis_tilt: &zero,
            pelvis_obliquity: &zero,
        };
        assert!(pelvis_range_through_legs(&still, &d).abs() < 1e-12);
        // The right knee bent 20° through its mid-stance, the ankle dorsiflexed as far to keep
        // the foot flat (the left's the same half a cycle on): in single support the pelvis
        // drops by the shank's loss of height, shank (1 - cos 20°).
        let knee: Vec<f64> = (0..=100).map(|p| if (15..=35).contains(&p) { 20.0 } else { 0.0 }).collect();
        let bent = LegAngles { knee_flex: &knee, ankle_dorsi: &knee, ..still };
        let drop = 100.0 * (d.shank * (1.0 - 20f64.to_radians().cos()));
        assert!((pelvis_range_through_legs(&bent, &d) - drop).abs() < 1e-9, "{drop}");
        // Obliquity alone: the pelvis centre sits under the raised stance hip by half the hip
        // width's sine, and the double supports hold it on the lower leg.
        let obliquity: Vec<f64> =
            (0..=100).map(|p| 4.0 * (f64::from(p) * std::f64::consts::TAU / 100.0).sin()).collect();
        let tilted = LegAngles { pelvis_obliquity: &obliquity, ..still };
        let range = pelvis_range_through_legs(&tilted, &d);
        let most = 100.0 * 0.5 * d.hip_width * 4f64.to_radians().sin();
        assert!(range > 0.5 * most && range <= 2.0 * most + 1e-9, "{range} against {most}");
    }

    #[test]
    fn samples_are_read_between_points_and_around_the_cycle() {
        let c: Vec<f64> = (0..=50).map(f64::from).collect();
        assert!((sample(&c, 0.5) - 25.0).abs() < 1e-12);
        assert!((sample(&c, 0.51) - 25.5).abs() < 1e-12);
        assert!((sample(&c, 1.25) - 12.5).abs() < 1e-12);
        assert!(sample(&c, 1.0).abs() < 1e-12, "100 % is the next cycle's 0 %");
        let three = [0.0, 10.0, 4.0];
        assert!((sample(&three, 0.25) - 5.0).abs() < 1e-12 && (sample(&three, 0.75) - 7.0).abs() < 1e-12);
    }
}
