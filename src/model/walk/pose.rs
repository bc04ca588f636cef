//! The pose builder: a leg solved toward its target by the analytic IK, the foot and toes set
//! to the target's angles, bone frames, the skeleton's pose from the solved parts, and the
//! joint angles read back from a leg's pose.

use crate::model::body::{BodyDims, Bone, Pose, Side};
use crate::model::ik::{IkQuestion, TwoBoneOptions, TwoBoneSolution, solve_two_bone_with};
use crate::model::params::Resolved;
use crate::model::walk::leg::{LegPose, LegTarget, foot_rotation};
use crate::model::walk::pelvis::PelvisPose;
use crate::model::walk::upper::UpperBody;
use glam::{DQuat, DVec3};

/// IK for one leg toward `target`, with the knee toward the walking direction turned by the
/// foot's yaw (the reference vector), then the foot and toes set to the target's angles.
#[must_use]
pub fn solve_leg(r: &Resolved, hip: DVec3, target: LegTarget) -> LegPose {
    let dims = &r.dims;
    // The walking direction turned by the foot's yaw: Ry(yaw)·x.
    let (sin_yaw, cos_yaw) = target.yaw.sin_cos();
    let reference = DVec3::new(cos_yaw, 0.0, -sin_yaw);
    // The analytic solver's soften and twist apply to the walk too (both off by default, when
    // this is exactly the plain law-of-cosines solve).
    let options = TwoBoneOptions { soften: r.ik.soften, twist: r.ik.twist };
    let ik = solve_two_bone_with(hip, target.ankle, dims.thigh, dims.shank, reference, options);
    leg_pose(r, hip, target, &ik)
}

/// The IK question the walk asks for a leg: hip, ankle target, and the knee toward the walking
/// direction turned by the foot's yaw.
#[must_use]
pub fn ik_question(hip: DVec3, target: LegTarget, side: Side) -> IkQuestion {
    let (sin_yaw, cos_yaw) = target.yaw.sin_cos();
    IkQuestion { hip, target: target.ankle, reference: DVec3::new(cos_yaw, 0.0, -sin_yaw), side_sign: side.sign() }
}

/// The whole leg from a solved hip–knee–ankle chain: foot and toes set to the target's angles.
#[must_use]
pub fn leg_pose(r: &Resolved, hip: DVec3, target: LegTarget, ik: &TwoBoneSolution) -> LegPose {
    let dims = &r.dims;
    let foot = foot_rotation(target.yaw, target.pitch);
    // Flat-footed stance has no toe bend; skipping the rotation saves a sin/cos per solve.
    let toe = if target.toe_bend == 0.0 { foot } else { foot * DQuat::from_rotation_z(target.toe_bend) };
    let up = DVec3::new(0.0, target.pad, 0.0);
    let heel = ik.end + foot * dims.heel_local() + up;
    let ball = ik.end + foot * dims.ball_local() + up;
    let toe_tip = ball + toe * DVec3::new(dims.toe_length(), 0.0, 0.0);
    LegPose {
        hip,
        knee: ik.middle,
        ankle: ik.end,
        swivel: ik.swivel,
        foot,
        toe,
        heel,
        ball,
        toe_tip,
        reached: ik.reached,
        target,
    }
}

/// World rotation of a bone pointing along `along` (its rest direction is −y) with its local
/// z on `hinge`.
#[must_use]
pub fn bone_frame(along: DVec3, hinge: DVec3) -> DQuat {
    let y = (-along).normalize();
    let z = (hinge - y * y.dot(hinge)).normalize();
    let x = y.cross(z);
    DQuat::from_mat3(&glam::DMat3::from_cols(x, y, z))
}

/// Writes the skeleton's pose from the solved pelvis, legs (right, left) and upper body. Thigh
/// and shin share one hinge axis, across the hip–ankle line and the IK's swivel, so the knee
/// bends in the plane the solver chose.
// Once a frame from the walker's update, which it was part of before; inlined there as it
// was then (out of line, callgrind counts 0.5 % more instructions for `simulate`).
#[inline]
pub fn build_pose(dims: &BodyDims, pelvis: &PelvisPose, legs: [&LegPose; 2], upper: &UpperBody, pose: &mut Pose) {
    pose.position[Bone::Pelvis.index()] = pelvis.position;
    pose.rotation[Bone::Pelvis.index()] = pelvis.rotation;
    for side in Side::BOTH {
        let leg = legs[side.index()];
        let hinge = (leg.ankle - leg.hip).cross(leg.swivel).normalize_or(DVec3::Z);
        pose.place(dims, Bone::thigh(side), bone_frame(leg.knee - leg.hip, hinge));
        pose.position[Bone::thigh(side).index()] = leg.hip;
        pose.place(dims, Bone::shin(side), bone_frame(leg.ankle - leg.knee, hinge));
        pose.place(dims, Bone::foot(side), leg.foot);
        pose.place(dims, Bone::toe(side), leg.toe);
    }
    upper.apply(dims, pose);
}

/// The clinical angles of a solved leg under a pelvis with world rotation `pelvis`. Shared
/// by the joint table and the pelvis optimisation's cost, so both measure the same thing.
#[must_use]
pub fn leg_angles(pelvis: DQuat, leg: &LegPose, side_sign: f64) -> LegAngles {
    let [hip_flex, knee, ankle] = sagittal_leg_angles(pelvis, leg);
    let thigh = (leg.knee - leg.hip).normalize();
    let (_, hip_abd) = sagittal_and_frontal(pelvis, thigh, side_sign);
    LegAngles {
        hip_flex_deg: hip_flex.to_degrees(),
        hip_abd_deg: hip_abd.to_degrees(),
        knee_flex_deg: knee.to_degrees(),
        ankle_dorsi_deg: ankle.to_degrees(),
    }
}

/// Hip flexion, knee flexion and ankle dorsiflexion (rad) of a solved leg: the three angles
/// of [`leg_angles`] that the pelvis optimisation's cost differentiates.
#[must_use]
pub fn sagittal_leg_angles(pelvis: DQuat, leg: &LegPose) -> [f64; 3] {
    let thigh = (leg.knee - leg.hip).normalize();
    let shank = (leg.ankle - leg.knee).normalize();
    let d = pelvis.inverse() * thigh;
    let hip_flex = d.x.atan2(-d.y);
    let knee = thigh.dot(shank).clamp(-1.0, 1.0).acos();
    // The shank's frame: y up along the shank, z on the knee hinge, x forward.
    let hinge = (leg.ankle - leg.hip).cross(leg.swivel).normalize_or(DVec3::Z);
    let y = -shank;
    let z = (hinge - y * y.dot(hinge)).normalize_or(DVec3::Z);
    let x = y.cross(z);
    let foot_forward = leg.foot * DVec3::X;
    let ankle = foot_forward.dot(y).atan2(foot_forward.dot(x));
    [hip_flex, knee, ankle]
}

/// Flexion of a limb segment pointing along `dir` (world), measured in the sagittal plane of
/// the parent frame `parent` (forward of straight down +), and its abduction toward `side`.
pub(crate) fn sagittal_and_frontal(parent: DQuat, dir: DVec3, side_sign: f64) -> (f64, f64) {
    let d = parent.inverse() * dir;
    (d.x.atan2(-d.y), (side_sign * d.z).atan2(-d.y))
}

/// Clinical angles of one leg (deg).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegAngles {
    /// Hip flexion, thigh against the pelvis, flexion +.
    pub hip_flex_deg: f64,
    /// Hip abduction, away from the midline +.
    pub(crate) hip_abd_deg: f64,
    /// Knee flexion.
    pub knee_flex_deg: f64,
    /// Ankle dorsiflexion (plantarflexion −), foot against the shank.
    pub ankle_dorsi_deg: f64,
}
