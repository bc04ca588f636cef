//! FABRIK (Aristidou & Lasenby 2011) on the two-bone leg: a backward pass pins the ankle on the
//! target and drags the knee after it, a forward pass pins the hip and drags the rest back.
//! After each pair the positions are read as joint angles, which enforces the hinge (the knee
//! only folds about its axis, never backward) and the limits; the knee is then turned about the
//! hip→ankle axis toward the reference vector, FABRIK's usual pole target.

use crate::model::ik::chain::{ChainPose, LegAngles, LegChain, swivel_to_reference};
use crate::model::ik::iterate::{Iterated, iterate, unlock_knee};
use crate::model::ik::settings::IkSettings;
use glam::DVec3;

/// Solves for the ankle at `target` (leg frame) from `start`.
#[must_use]
pub fn solve(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    let limits = chain.limits;
    let start = unlock_knee(chain, start, target);
    iterate(chain, target, side, start, s, |angles, pose| {
        let (pose, _) = swivel_to_reference(pose);
        // Backward: ankle on the target.
        let knee = target + (pose.knee - target).normalize_or(DVec3::Y) * chain.shank;
        // Forward: hip at the origin.
        let knee = knee.normalize_or(DVec3::NEG_Y) * chain.thigh;
        let ankle = knee + (target - knee).normalize_or(DVec3::NEG_Y) * chain.shank;
        let reached = ChainPose { knee, ankle };

        // Constraints: the hinge and the ranges, through the angles.
        let angles = limits.clamp(chain.angles_from_positions(reached, side, angles.hip_rot));
        let pose = chain.forward(angles, side);
        let (_, turn) = swivel_to_reference(pose);
        let hip = turn * LegChain::hip_rotation(angles, side);
        unlock_knee(chain, limits.clamp(LegChain::hip_angles(hip, side, angles.knee_flex)), target)
    })
}
