//! The angles a stance foot rolls to so that its leg reaches the hip: the heel rocker kept
//! toes-up a little longer, the heel raised about the toe joint. Closed forms and a short
//! bisection, called on every stance target ([`super::gait::Gait::target_of`]) and by the
//! reach guard's trailing-leg samples.

use crate::model::walk::leg::{Footfall, foot_rotation};
use glam::{DQuat, DVec3};

/// Steepest heel rise the stance leg may take to reach (rad).
pub const MAX_HEEL_RISE: f64 = 1.45;
/// How far inside full reach (m) a stance leg past it is brought by rolling its foot: the
/// IK's own tolerance is 1e-9 m.
pub(crate) const REACH_RESCUE_GAP: f64 = 1e-7;

/// Steepest extra toe-up pitch (rad) the heel rocker may keep to let a leg reach.
const MAX_HEEL_ROCKER_RESCUE: f64 = 0.1;

/// The heel rocker's foot pitch, kept toes-up just enough that a leg whose hip has run past
/// full reach between the guard's samples (a live change; the steady 1.6 m/s walk's heel
/// strike in 4 frames of 20 cycles) reaches its heel, which stays
/// planted: the ankle swings back and up about the heel toward the hip. Unchanged within reach
/// or if [`MAX_HEEL_ROCKER_RESCUE`] would not do.
pub(crate) fn heel_rocker_to_reach(
    heel: DVec3,
    yaw: f64,
    pitch: f64,
    heel_local: DVec3,
    hip: DVec3,
    reach: f64,
) -> f64 {
    let limit = reach - REACH_RESCUE_GAP;
    let distance = |extra: f64| hip.distance(heel - foot_rotation(yaw, pitch + extra) * heel_local);
    if distance(0.0) <= limit || distance(MAX_HEEL_ROCKER_RESCUE) > limit {
        return pitch;
    }
    let (mut lo, mut hi) = (0.0, MAX_HEEL_ROCKER_RESCUE);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if distance(mid) > limit { lo = mid } else { hi = mid }
    }
    pitch + hi
}

/// The least heel-rise angle ≥ `from` (rad) at which the ankle, swinging about the toe joint
/// `ball`, comes within `limit` of `hip`; `None` if no angle up to [`MAX_HEEL_RISE`] does.
///
/// In the foot's yaw frame the ankle is ball − Rz(g − β)·b, so the squared distance to the hip
/// is |d|² + |b|² + 2 d·Rz(θ)·b with d = hip − ball, θ = g − β: a sinusoid in θ, solved in
/// closed form (A cos θ + B sin θ = K) instead of by bisection on every frame.
#[must_use]
pub fn heel_rise_to_reach(
    ball: DVec3,
    footfall: &Footfall,
    ball_local: DVec3,
    hip: DVec3,
    limit: f64,
    from: f64,
) -> Option<f64> {
    let d = DQuat::from_rotation_y(-footfall.yaw) * (hip - ball);
    let b = ball_local;
    let a_coef = d.x * b.x + d.y * b.y;
    let b_coef = d.y * b.x - d.x * b.y;
    let k = 0.5 * (limit * limit - d.length_squared() - b.length_squared()) - d.z * b.z;
    let amplitude = a_coef.hypot(b_coef);
    if amplitude < 1e-12 || (k / amplitude).abs() > 1.0 {
        return None;
    }
    let phi = b_coef.atan2(a_coef);
    let spread = (k / amplitude).acos();
    // Both roots in θ, mapped to β = g − θ and brought into (from − π, from + π].
    let g = footfall.ground_angle;
    let wrap = |beta: f64| {
        let mut x = beta;
        while x <= from - std::f64::consts::PI {
            x += std::f64::consts::TAU;
        }
        while x > from + std::f64::consts::PI {
            x -= std::f64::consts::TAU;
        }
        x
    };
    [wrap(g - (phi + spread)), wrap(g - (phi - spread))]
        .into_iter()
        .filter(|beta| *beta >= from - 1e-12 && *beta <= MAX_HEEL_RISE)
        .min_by(f64::total_cmp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::{BodyDims, Sex};

    #[test]
    fn a_leg_past_reach_keeps_its_heel_down_and_its_toes_up_just_enough() {
        let d = BodyDims::from_height(1.75, Sex::Male);
        let heel = DVec3::new(0.3, 0.0, 0.1);
        let (yaw, pitch) = (0.05, 0.08);
        let ankle_at = |p: f64| heel - foot_rotation(yaw, p) * d.heel_local();
        let reach = d.leg_reach();
        // The hip behind and above the landing ankle, `past` beyond full reach of it.
        let along = DVec3::new(-0.35, 1.0, 0.0).normalize();
        for past in [0.0001, 0.0005, 0.002] {
            let hip = ankle_at(pitch) + along * (reach + past);
            let rolled = heel_rocker_to_reach(heel, yaw, pitch, d.heel_local(), hip, reach);
            assert!(rolled > pitch, "{past}");
            let gap = reach - hip.distance(ankle_at(rolled));
            assert!((0.0..2e-7).contains(&gap), "{past}: {gap}");
            // The least roll that reaches: a hundredth of a degree less does not.
            assert!(hip.distance(ankle_at(rolled - 1e-4)) > reach - REACH_RESCUE_GAP, "{past}");
        }
        // Within reach nothing moves; too far for the steepest rescue, nothing moves either
        // (the IK then reports the failure).
        let near = ankle_at(pitch) + along * (reach - 0.001);
        assert_eq!(heel_rocker_to_reach(heel, yaw, pitch, d.heel_local(), near, reach), pitch);
        let far = ankle_at(pitch) + along * (reach + 0.05);
        assert_eq!(heel_rocker_to_reach(heel, yaw, pitch, d.heel_local(), far, reach), pitch);
    }
}
