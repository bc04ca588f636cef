//! Cyclic coordinate descent (seed 001): from the leaf to the root, each joint turns so the
//! chain's end points at the target — the knee about its hinge, the hip freely — by the share
//! of the turn its stiffness allows; limits are clamped after every joint update. A swivel
//! turn about the hip→ankle axis then puts the knee back toward the reference vector; it
//! leaves the ankle where it is.
//!
//! At full stiffness the sweeps run on joint positions and the hinge's axis, and the angles
//! are read once at the end; an answer that breaks a limit is turned about the hip→ankle axis
//! into the limits. Only where that fails (or at partial stiffness) do the sweeps run on the
//! angles, clamped after every joint update, and where even those end off the target the
//! unlimited solve is turned into the limits (see `reach_then_turn`).

use crate::model::ik::analytic::orthogonal_part;
use crate::model::ik::chain::{ChainPose, LegAngles, LegChain, swivel_to_reference};
use crate::model::ik::iterate::{Iterated, MIN_BEND, Stall, iterate, unlock_knee};
use crate::model::ik::settings::IkSettings;
use crate::model::ik::swivel::{into_limits, limited_else_turned, to_reference};
use glam::{DQuat, DVec3};

/// Solves for the ankle at `target` (leg frame) from `start`.
#[must_use]
pub fn solve(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    if s.ccd_stiffness_hip == 1.0
        && s.ccd_stiffness_knee == 1.0
        && let Some(done) = in_positions(chain, target, side, start, s)
    {
        return done;
    }
    limited_else_turned(chain, target, side, start, s, |c| solve_within(c, target, side, start, s))
}

/// The same sweeps on positions, the limits left out, the angles read once at the end. After
/// the first sweep the knee lies in the reference plane through the hip→target line, and every
/// later sweep keeps it there (the knee turns in it, the hip turns about its normal, the
/// swivel at most flips the knee back across the line), so they run in that plane's two
/// coordinates without a trigonometric function. `None` where the answer misses or no swivel
/// of it is within the limits (or at partial stiffness, where a share of each turn needs
/// the angles).
fn in_positions(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Option<Iterated> {
    let first = chain.forward(start, side);
    let d0 = first.ankle.distance(target);
    if d0 <= s.tolerance || target.length() < 1e-9 {
        return finish(chain, first, d0, side, start, s, 0);
    }
    // The first sweep in three dimensions, about the hinge's own axis.
    let unlocked = unlock_knee(chain, start, target);
    let mut pose = chain.forward(unlocked, side);
    let axis = LegChain::knee_axis(unlocked, side);
    let t = target - pose.knee;
    let t_p = t - axis * axis.dot(t);
    if t_p.length_squared() > 1e-18 {
        pose.ankle = pose.knee + t_p.normalize() * chain.shank;
    }
    let a = target.normalize();
    let turn = DQuat::from_rotation_arc(pose.ankle.normalize_or(DVec3::NEG_Y), a);
    let (pose, _) = to_reference(ChainPose { knee: turn * pose.knee, ankle: turn * pose.ankle });
    // The plane's coordinates: x along the hip→target line, y toward the reference.
    let p = orthogonal_part(a, DVec3::X);
    let (knee, ankle, iterations) =
        in_plane(chain, target.length(), (pose.knee.dot(a), pose.knee.dot(p).abs()), pose.ankle.dot(a), s);
    let pose = ChainPose { knee: a * knee.0 + p * knee.1, ankle: a * ankle };
    let distance = (ankle - target.length()).abs();
    let (pose, distance) = if distance < d0 { (pose, distance) } else { (first, d0) };
    finish(chain, pose, distance, side, start, s, iterations + 1)
}

/// CCD sweeps in the reference plane: the target at (`reach`, 0), the knee at `knee`, the
/// ankle on the x axis at `ankle`. Returns the knee, the ankle and the sweeps run.
fn in_plane(
    chain: &LegChain,
    reach: f64,
    mut knee: (f64, f64),
    mut ankle: f64,
    s: &IkSettings,
) -> ((f64, f64), f64, u32) {
    let (thigh, shank) = (chain.thigh, chain.shank);
    let within_reach = reach < chain.reach() - 1e-6;
    let (bend_sin, bend_cos) = MIN_BEND.sin_cos();
    let mut stall = Stall::new(chain, DVec3::new(reach, 0.0, 0.0));
    let mut iterations = 1;
    loop {
        let distance = (ankle - reach).abs();
        if distance <= s.tolerance || iterations >= s.max_iterations || stall.stalled(distance) {
            return (knee, ankle, iterations - 1);
        }
        iterations += 1;
        // Knee: the shank toward the target.
        let (dx, dy) = (reach - knee.0, -knee.1);
        let d = (dx * dx + dy * dy).sqrt();
        let (mut wx, mut wy) = if d > 1e-12 { (dx / d, dy / d) } else { (1.0, 0.0) };
        let (ux, uy) = (knee.0 / thigh, knee.1 / thigh);
        if within_reach && ux * wx + uy * wy > bend_cos {
            // Re-bent, folding back toward the line (see `unlock_knee`).
            (wx, wy) = (ux * bend_cos + uy * bend_sin, uy * bend_cos - ux * bend_sin);
        }
        let (ax, ay) = (knee.0 + wx * shank, knee.1 + wy * shank);
        // Hip: the hip→ankle line onto the hip→target line; swivel: the knee back to its side.
        let l = (ax * ax + ay * ay).sqrt();
        let (c, sn) = (ax / l, ay / l);
        knee = (knee.0 * c + knee.1 * sn, (knee.1 * c - knee.0 * sn).abs());
        ankle = l;
    }
}

/// The angles of a pose reached on positions, turned into the limits where it breaks them.
fn finish(
    chain: &LegChain,
    pose: ChainPose,
    distance: f64,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    iterations: u32,
) -> Option<Iterated> {
    if distance > s.tolerance {
        return None;
    }
    let angles = chain.angles_from_positions(pose, side, start.hip_rot);
    if !chain.limits.enabled || chain.limits.violation(angles) == 0.0 {
        return Some(Iterated { angles, iterations, pose: Some(pose) });
    }
    let (pose, angles) = into_limits(chain, pose, side, start.hip_rot)?;
    Some(Iterated { angles, iterations, pose: Some(pose) })
}

/// The iteration itself, with `chain`'s limits clamped after every step.
fn solve_within(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
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
