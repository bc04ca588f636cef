//! The leg as a joint chain: a ball-jointed hip, a hinged knee, an ankle target.
//!
//! Every iterative solver works on this one model so that all of them answer the question the
//! analytic solver answers: put the ankle on the target with the knee toward the reference
//! vector. Angles are measured in the **leg frame** of the question — x along the reference
//! vector (the walking direction turned by the foot's turnout), y up, z to the right — not in
//! the pelvis's frame: the walk's reference vector is deliberately not attached to the pelvis
//! (spec §6), and pelvic rotation stays within a few degrees.
//!
//! The hip's rotation is `Rz(flexion)·Rx(∓abduction)·Ry(±internal rotation)` (sign by side, so
//! that abduction moves either foot away from the midline and internal rotation turns the knee
//! inward); the knee flexes about the thigh's local z, folding the shank backward.

use glam::{DQuat, DVec3, EulerRot};

/// The joint angles of one leg in its leg frame (rad).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LegAngles {
    /// Hip flexion, + thigh forward.
    pub(crate) hip_flex: f64,
    /// Hip abduction, + foot away from the midline.
    pub(crate) hip_abd: f64,
    /// Hip internal rotation, + knee turned toward the midline.
    pub(crate) hip_rot: f64,
    /// Knee flexion, + shank folded back; 0 is straight.
    pub(crate) knee_flex: f64,
}

impl LegAngles {
    /// As `[hip_flex, hip_abd, hip_rot, knee_flex]`.
    #[must_use]
    pub fn to_array(self) -> [f64; 4] {
        [self.hip_flex, self.hip_abd, self.hip_rot, self.knee_flex]
    }

    /// From `[hip_flex, hip_abd, hip_rot, knee_flex]`.
    #[must_use]
    pub(crate) fn from_array(a: [f64; 4]) -> Self {
        LegAngles { hip_flex: a[0], hip_abd: a[1], hip_rot: a[2], knee_flex: a[3] }
    }

    /// A slightly bent standing leg: where iterative solvers start when nothing better is known.
    #[must_use]
    pub fn rest() -> Self {
        LegAngles { hip_flex: 5f64.to_radians(), hip_abd: 0.0, hip_rot: 0.0, knee_flex: 10f64.to_radians() }
    }

    /// Whether every angle is finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.to_array().iter().all(|a| a.is_finite())
    }
}

/// Joint ranges (rad), `(least, greatest)` for each angle of [`LegAngles`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointLimits {
    /// Whether solvers enforce them.
    pub enabled: bool,
    /// Hip flexion range; the least is minus the extension limit.
    pub hip_flex: (f64, f64),
    /// Hip abduction range; the least is minus the adduction limit.
    pub hip_abd: (f64, f64),
    /// Hip internal rotation range; the least is minus the external rotation limit.
    pub hip_rot: (f64, f64),
    /// Knee flexion range; the least is 0 (straight).
    pub knee_flex: (f64, f64),
}

impl Default for JointLimits {
    /// Active ranges of healthy adults (AAOS): hip 120° flexion, 30° extension, 45° abduction,
    /// 30° adduction, 45° internal and external rotation; knee 0–140°. The leg frame does not
    /// tilt with the pelvis, so extension is counted from the vertical: with the walk's ~10°
    /// of anterior pelvic tilt, 40° from the vertical is the anatomical 30°.
    fn default() -> Self {
        let r = f64::to_radians;
        JointLimits {
            enabled: true,
            hip_flex: (r(-40.0), r(120.0)),
            hip_abd: (r(-30.0), r(45.0)),
            hip_rot: (r(-45.0), r(45.0)),
            knee_flex: (0.0, r(140.0)),
        }
    }
}

impl JointLimits {
    /// The ranges as an array in [`LegAngles::to_array`] order.
    #[must_use]
    pub fn ranges(&self) -> [(f64, f64); 4] {
        [self.hip_flex, self.hip_abd, self.hip_rot, self.knee_flex]
    }

    /// `angles` clamped into the ranges when limits are on; unchanged otherwise.
    #[must_use]
    pub(crate) fn clamp(&self, angles: LegAngles) -> LegAngles {
        if !self.enabled {
            return angles;
        }
        let mut a = angles.to_array();
        for (x, (lo, hi)) in a.iter_mut().zip(self.ranges()) {
            *x = x.clamp(lo, hi);
        }
        LegAngles::from_array(a)
    }

    /// How far the worst angle lies outside its range (rad); 0 inside. Measured whether or
    /// not limits are on, so unlimited solves can be judged against them too.
    #[must_use]
    pub(crate) fn violation(&self, angles: LegAngles) -> f64 {
        angles
            .to_array()
            .iter()
            .zip(self.ranges())
            .map(|(x, (lo, hi))| (lo - x).max(x - hi).max(0.0))
            .fold(0.0, f64::max)
    }
}

/// One IK question: where the hip is, where the ankle should go, where the knee should point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkQuestion {
    /// Hip joint (m, world).
    pub hip: DVec3,
    /// Ankle target (m, world).
    pub target: DVec3,
    /// Unit horizontal reference vector: the knee goes toward it.
    pub reference: DVec3,
    /// +1 for the right leg, −1 for the left.
    pub side_sign: f64,
}

impl IkQuestion {
    /// The leg frame's rotation: its x is the reference vector, y stays up.
    #[must_use]
    pub fn frame(&self) -> DQuat {
        DQuat::from_rotation_y((-self.reference.z).atan2(self.reference.x))
    }

    /// The leg frame's axes: the same rotation as [`Self::frame`], built without
    /// trigonometry. Every solve maps the target in and the joints out, and an atan2 and a
    /// sin-cos each time would cost more than the analytic solve itself.
    #[must_use]
    pub(crate) fn leg_frame(&self) -> LegFrame {
        let (x, z) = (self.reference.x, self.reference.z);
        let n = (x * x + z * z).sqrt();
        let (c, s) = if n > 0.0 { (x / n, z / n) } else { (1.0, 0.0) };
        LegFrame { hip: self.hip, ex: DVec3::new(c, 0.0, s), ez: DVec3::new(-s, 0.0, c) }
    }
}

/// The leg frame in the world: the hip, and the frame's x (the horizontal reference) and z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LegFrame {
    hip: DVec3,
    ex: DVec3,
    ez: DVec3,
}

impl LegFrame {
    /// A world point in the leg frame.
    #[must_use]
    pub(crate) fn to_local(self, world: DVec3) -> DVec3 {
        let d = world - self.hip;
        DVec3::new(d.dot(self.ex), d.y, d.dot(self.ez))
    }
}

/// `atan2(s, c)` for a point (s, c) on the unit circle, from an arcsine or an arccosine
/// (whichever is well conditioned there): each is a fraction of atan2's cost, and every
/// solve reads four angles.
#[must_use]
fn angle_of(s: f64, c: f64) -> f64 {
    if s.abs() < 0.7 {
        let a = s.clamp(-1.0, 1.0).asin();
        if c >= 0.0 { a } else { std::f64::consts::PI.copysign(s) - a }
    } else {
        c.clamp(-1.0, 1.0).acos().copysign(s)
    }
}

/// The leg chain: bone lengths and joint ranges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegChain {
    /// Hip to knee (m).
    pub thigh: f64,
    /// Knee to ankle (m).
    pub shank: f64,
    /// Joint ranges.
    pub limits: JointLimits,
}

/// Knee and ankle in the leg frame, hip at the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainPose {
    /// Knee joint (m).
    pub knee: DVec3,
    /// Ankle joint (m).
    pub ankle: DVec3,
}

impl LegChain {
    /// Full reach, hip to ankle with the knee straight (m).
    #[must_use]
    pub fn reach(&self) -> f64 {
        self.thigh + self.shank
    }

    /// The hip's rotation in the leg frame.
    #[must_use]
    pub(crate) fn hip_rotation(angles: LegAngles, side_sign: f64) -> DQuat {
        DQuat::from_euler(EulerRot::ZXY, angles.hip_flex, -side_sign * angles.hip_abd, side_sign * angles.hip_rot)
    }

    /// Hip angles from the hip's rotation in the leg frame; the inverse of [`Self::hip_rotation`].
    #[must_use]
    pub(crate) fn hip_angles(rotation: DQuat, side_sign: f64, knee_flex: f64) -> LegAngles {
        let (flex, x, y) = rotation.to_euler(EulerRot::ZXY);
        LegAngles { hip_flex: flex, hip_abd: -side_sign * x, hip_rot: side_sign * y, knee_flex }
    }

    /// Forward kinematics in the leg frame.
    #[must_use]
    pub fn forward(&self, angles: LegAngles, side_sign: f64) -> ChainPose {
        let hip = Self::hip_rotation(angles, side_sign);
        let knee = hip * DVec3::new(0.0, -self.thigh, 0.0);
        let (s, c) = angles.knee_flex.sin_cos();
        let ankle = knee + hip * DVec3::new(-s * self.shank, -c * self.shank, 0.0);
        ChainPose { knee, ankle }
    }

    /// The knee's hinge axis in the leg frame for these hip angles.
    #[must_use]
    pub(crate) fn knee_axis(angles: LegAngles, side_sign: f64) -> DVec3 {
        Self::hip_rotation(angles, side_sign) * DVec3::Z
    }

    /// Joint angles that put the knee and ankle where given (leg frame); the inverse of
    /// [`Self::forward`] for positions with the right bone lengths. Hip rotation is undefined
    /// with the knee straight; `previous_rot` is kept then.
    ///
    /// Four arcsines or arccosines and no other transcendental function: the swing's sines
    /// and cosines are read off the thigh direction instead of being rebuilt from its angles
    /// (this runs once per solve of every solver, the analytic one included).
    #[must_use]
    pub(crate) fn angles_from_positions(&self, pose: ChainPose, side_sign: f64, previous_rot: f64) -> LegAngles {
        let u = pose.knee.normalize_or(DVec3::NEG_Y);
        let hip_abd = (side_sign * u.z).clamp(-1.0, 1.0).asin();
        let w = (pose.ankle - pose.knee).normalize_or(u);
        let sin_knee = u.cross(w).length();
        let knee_flex = angle_of(sin_knee, u.dot(w));
        // The swing Rz(flexion)·Rx(x), x = −side·abduction, has the columns (cf, sf, 0),
        // (−sf·cx, cf·cx, sx), (sf·sx, −cf·sx, cx), and the thigh is minus the second:
        // sx = −u.z, and (sf, cf) = (u.x, −u.y) / cx.
        let cx = (1.0 - u.z * u.z).max(0.0).sqrt();
        let (hip_flex, sf, cf) = if cx > 1e-12 {
            let (sf, cf) = (u.x / cx, -u.y / cx);
            (angle_of(sf, cf), sf, cf)
        } else {
            let flex = u.x.atan2(-u.y);
            let (sf, cf) = flex.sin_cos();
            (flex, sf, cf)
        };
        let sx = -u.z;
        // The shank in the thigh's frame before the hip's axial rotation:
        // (−sin k·cos φ, −cos k, sin k·sin φ) with φ = side·rotation.
        let w_x = cf * w.x + sf * w.y;
        let w_z = sf * sx * w.x - cf * sx * w.y + cx * w.z;
        let hip_rot =
            if sin_knee > 1e-9 { side_sign * angle_of(w_z / sin_knee, -w_x / sin_knee) } else { previous_rot };
        LegAngles { hip_flex, hip_abd, hip_rot, knee_flex }
    }

    /// The knee's signed turn about the hip→ankle axis away from the plane of the reference
    /// vector (rad), and its distance from that axis (m); the reference is the leg frame's x.
    #[must_use]
    pub fn swivel(pose: ChainPose) -> (f64, f64) {
        let a = pose.ankle.normalize_or(DVec3::NEG_Y);
        let u = pose.knee - a * a.dot(pose.knee);
        let radius = u.length();
        let p = DVec3::X - a * a.x;
        if radius < 1e-12 || p.length_squared() < 1e-18 {
            return (0.0, radius);
        }
        let angle = p.cross(u).dot(a).atan2(p.dot(u));
        (angle, radius)
    }

    /// What every solver drives to zero: the ankle's distance from the target, and the knee's
    /// arc off the reference plane (both m). The arc, `swivel angle × knee radius`, vanishes
    /// smoothly as the knee straightens, where the swivel means nothing.
    #[must_use]
    pub(crate) fn residual(&self, pose: ChainPose, local_target: DVec3) -> (f64, f64) {
        let (angle, radius) = Self::swivel(pose);
        (pose.ankle.distance(local_target), angle * radius)
    }
}

/// Rotates the whole chain about the hip→ankle axis so the knee lies in the reference plane:
/// the ankle stays put, so this fixes the swivel without undoing any reaching.
#[must_use]
pub(crate) fn swivel_to_reference(pose: ChainPose) -> (ChainPose, DQuat) {
    let (angle, radius) = LegChain::swivel(pose);
    if radius < 1e-12 || angle == 0.0 {
        return (pose, DQuat::IDENTITY);
    }
    let a = pose.ankle.normalize_or(DVec3::NEG_Y);
    let turn = DQuat::from_axis_angle(a, -angle);
    (ChainPose { knee: turn * pose.knee, ankle: pose.ankle }, turn)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chain() -> LegChain {
        LegChain { thigh: 0.43, shank: 0.44, limits: JointLimits::default() }
    }

    #[test]
    fn euler_order_is_flexion_then_abduction_then_rotation() {
        let q = DQuat::from_euler(EulerRot::ZXY, 0.3, -0.2, 0.1);
        let manual = DQuat::from_rotation_z(0.3) * DQuat::from_rotation_x(-0.2) * DQuat::from_rotation_y(0.1);
        assert!(q.abs_diff_eq(manual, 1e-12) || q.abs_diff_eq(-manual, 1e-12));
    }

    #[test]
    fn signs_follow_the_clinical_conventions() {
        let c = chain();
        for side in [1.0, -1.0] {
            let flexed = c.forward(LegAngles { hip_flex: 0.4, ..LegAngles::default() }, side);
            assert!(flexed.knee.x > 0.1, "hip flexion moves the thigh forward");
            let abducted = c.forward(LegAngles { hip_abd: 0.3, ..LegAngles::default() }, side);
            assert!(abducted.ankle.z * side > 0.1, "abduction moves the foot outward");
            let bent = c.forward(LegAngles { knee_flex: 0.6, ..LegAngles::default() }, side);
            assert!(bent.ankle.x < -0.1, "knee flexion folds the shank back");
            let turned =
                c.forward(LegAngles { hip_flex: 0.5, hip_rot: 0.4, knee_flex: 0.8, ..LegAngles::default() }, side);
            let plain = c.forward(LegAngles { hip_flex: 0.5, knee_flex: 0.8, ..LegAngles::default() }, side);
            assert!((turned.ankle.z - plain.ankle.z) * side > 0.05, "internal rotation swings the shank out");
        }
    }

    #[test]
    fn angles_from_positions_inverts_forward() {
        let c = chain();
        let mut seed = 7u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for _ in 0..300 {
            let side = if rnd() > 0.0 { 1.0 } else { -1.0 };
            let a = LegAngles {
                hip_flex: rnd() * 2.0,
                hip_abd: rnd() * 1.2,
                hip_rot: rnd() * 1.5,
                knee_flex: 0.05 + (rnd() + 0.5) * 2.0,
            };
            let pose = c.forward(a, side);
            let back = c.angles_from_positions(pose, side, 0.0);
            for (x, y) in a.to_array().iter().zip(back.to_array()) {
                assert!((x - y).abs() < 1e-9, "{a:?} vs {back:?}");
            }
            let q = LegChain::hip_rotation(a, side);
            let from_q = LegChain::hip_angles(q, side, a.knee_flex);
            assert!(c.forward(from_q, side).ankle.distance(pose.ankle) < 1e-12);
        }
    }

    #[test]
    fn swivel_is_zero_for_a_knee_toward_the_reference_and_fixable() {
        let c = chain();
        let forward_knee = c.forward(LegAngles { hip_flex: 0.3, knee_flex: 0.6, ..LegAngles::default() }, 1.0);
        assert!(LegChain::swivel(forward_knee).0.abs() < 1e-12);
        let turned = c.forward(LegAngles { hip_flex: 0.3, hip_rot: 0.5, knee_flex: 0.6, ..LegAngles::default() }, 1.0);
        let (angle, radius) = LegChain::swivel(turned);
        assert!(angle.abs() > 0.3 && radius > 0.05);
        let (fixed, _) = swivel_to_reference(turned);
        assert!(LegChain::swivel(fixed).0.abs() < 1e-9);
        assert!(fixed.ankle.distance(turned.ankle) < 1e-15);
        assert!((fixed.knee.length() - 0.43).abs() < 1e-12);
    }

    #[test]
    fn limits_clamp_and_measure() {
        let limits = JointLimits::default();
        let wild = LegAngles { hip_flex: 3.0, hip_abd: -1.0, hip_rot: 0.0, knee_flex: -0.2 };
        let clamped = limits.clamp(wild);
        assert_eq!(limits.violation(clamped), 0.0);
        assert!((limits.violation(wild) - (3.0 - 120f64.to_radians())).abs() < 1e-12);
        let off = JointLimits { enabled: false, ..limits };
        assert_eq!(off.clamp(wild), wild);
    }
}
