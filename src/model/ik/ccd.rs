//! Cyclic coordinate descent (seed 001): from the leaf to the root, each joint turns so the
//! chain's end points at the target — the knee about its hinge, the hip freely — by the share
//! of the turn its stiffness allows; limits are clamped after every joint update. A swivel
//! turn about the hip→ankle axis then puts the knee back toward the reference vector; it
//! leaves the ankle where it is.

use crate::model::ik::chain::{LegAngles, LegChain, swivel_to_reference};
use crate::model::ik::iterate::{Iterated, iterate, unlock_knee};
use crate::model::ik::settings::IkSettings;
use glam::{DQuat, DVec3};

/// Solves for the ankle at `target` (leg frame) from `start`.
#[must_use]
pub fn solve(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    let limits = chain.limits;
    iterate(chain, target, side, start, s, |mut angles, pose| {
        // Knee: turn the shank about the hinge toward the target.
        let axis = LegChain::knee_axis(angles, side);
        let e = pose.ankle - pose.knee;
        let t = target - pose.knee;
        let e_p = e - axis * axis.dot(e);
        let t_p = t - axis * axis.dot(t);
        if e_p.length_squared() > 1e-18 && t_p.length_squared() > 1e-18 {
            let turn = axis.dot(e_p.cross(t_p)).atan2(e_p.dot(t_p));
            // A turn of the shank by +δ about the hinge is a knee flexion of −δ.
            angles.knee_flex -= s.ccd_stiffness_knee * turn;
            angles = limits.clamp(angles);
        }

        angles = hip_step(chain, angles, side, target, s.ccd_stiffness_hip);

        // Swivel: the knee back toward the reference, the ankle unmoved.
        let pose = chain.forward(angles, side);
        let (_, turn) = swivel_to_reference(pose);
        let hip = turn * LegChain::hip_rotation(angles, side);
        angles = limits.clamp(LegChain::hip_angles(hip, side, angles.knee_flex));
        // A knee driven straight is re-bent and the hip re-aimed before the next knee step,
        // which then sees the ankle past the target and bends further.
        let unlocked = unlock_knee(chain, angles, target);
        if unlocked == angles { angles } else { hip_step(chain, unlocked, side, target, 1.0) }
    })
}

/// The hip's CCD step: the shortest rotation taking the hip→ankle line onto the hip→target
/// line, by the share `stiffness`.
fn hip_step(chain: &LegChain, angles: LegAngles, side: f64, target: DVec3, stiffness: f64) -> LegAngles {
    let pose = chain.forward(angles, side);
    let cross = pose.ankle.cross(target);
    if cross.length_squared() <= 1e-24 {
        return angles;
    }
    let turn = cross.length().atan2(pose.ankle.dot(target));
    let rotation = DQuat::from_axis_angle(cross.normalize(), stiffness * turn);
    let hip = rotation * LegChain::hip_rotation(angles, side);
    chain.limits.clamp(LegChain::hip_angles(hip, side, angles.knee_flex))
}
