//! FABRIK (Aristidou & Lasenby 2011) on the two-bone leg: a backward pass pins the ankle on the
//! target and drags the knee after it, a forward pass pins the hip and drags the rest back.
//!
//! The passes run on positions alone, as FABRIK is meant to: the knee's swivel about the
//! hip→ankle axis never moves the ankle, so the pole (the reference vector) is applied once,
//! after the reaching, and the joint angles are read once, at the end. Where that answer
//! breaks a limit, the knee is turned about the hip→ankle axis to the nearest swivel within
//! the limits (`into_limits`); only where no swivel is within them (a target the leg cannot
//! quite reach within its ranges) does FABRIK fall back to passes projected into the ranges
//! through the angles after every pair, finished by a damped least-squares polish from the
//! best pose those passes found.

use crate::model::ik::chain::{ChainPose, LegAngles, LegChain, swivel_to_reference};
use crate::model::ik::iterate::{Iterated, Stall, better, iterate, unlock_knee};
use crate::model::ik::jacobian;
use crate::model::ik::settings::IkSettings;
use crate::model::ik::swivel::{into_limits, pole, reach};
use glam::DVec3;

/// Solves for the ankle at `target` (leg frame) from `start`.
#[must_use]
pub fn solve(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    let (pose, distance, iterations) = reach(chain, target, side, start, s);
    let out_of_reach = Stall::new(chain, target).out_of_reach();
    if distance <= s.tolerance || out_of_reach {
        let pose = pole(pose);
        let angles = chain.angles_from_positions(pose, side, start.hip_rot);
        if !chain.limits.enabled || chain.limits.violation(angles) == 0.0 {
            return Iterated { angles, iterations, pose: Some(pose) };
        }
        if let Some((pose, angles)) = into_limits(chain, pose, side, start.hip_rot) {
            return Iterated { angles, iterations, pose: Some(pose) };
        }
    }
    let mut result = limited(chain, target, side, start, s);
    let residual = |a: LegAngles| chain.residual(chain.forward(a, side), target);
    if residual(result.angles).0 > s.tolerance {
        let polished = jacobian::solve(chain, target, side, result.angles, s);
        if better(s.tolerance, residual(polished.angles), residual(result.angles)) {
            result.angles = polished.angles;
        }
        result.iterations += polished.iterations;
    }
    result.iterations += iterations;
    result
}

/// FABRIK with the hinge and the ranges enforced through the angles after every pair of
/// passes, and the knee turned toward the reference: slower, and kept for targets the leg
/// cannot quite reach within its ranges.
fn limited(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    let limits = chain.limits;
    let start = unlock_knee(chain, start, target);
    iterate(chain, target, side, start, s, |angles, pose| {
        let (pose, _) = swivel_to_reference(pose);
        let knee = target + (pose.knee - target).normalize_or(DVec3::Y) * chain.shank;
        let knee = knee.normalize_or(DVec3::NEG_Y) * chain.thigh;
        let ankle = knee + (target - knee).normalize_or(DVec3::NEG_Y) * chain.shank;
        let reached = ChainPose { knee, ankle };
        let angles = limits.clamp(chain.angles_from_positions(reached, side, angles.hip_rot));
        let pose = chain.forward(angles, side);
        let (_, turn) = swivel_to_reference(pose);
        let hip = turn * LegChain::hip_rotation(angles, side);
        unlock_knee(chain, limits.clamp(LegChain::hip_angles(hip, side, angles.knee_flex)), target)
    })
}
