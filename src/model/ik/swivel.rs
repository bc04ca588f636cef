//! The knee's swivel about the hip→ankle axis, in positions: turning it moves the knee and
//! never the ankle, so position solvers can reach first and place the knee afterwards.

use crate::model::ik::analytic::orthogonal_part;
use crate::model::ik::chain::{ChainPose, LegAngles, LegChain};
use crate::model::ik::iterate::{Iterated, Stall, unlock_knee};
use crate::model::ik::settings::IkSettings;
use glam::{DQuat, DVec3};
use std::f64::consts::PI;

/// The knee turned about the hip→ankle axis into the reference plane (the leg frame's x),
/// keeping its distance from the axis: FABRIK's pole, applied once.
#[must_use]
pub(crate) fn pole(pose: ChainPose) -> ChainPose {
    let a = pose.ankle.normalize_or(DVec3::NEG_Y);
    let along = a * a.dot(pose.knee);
    let radius = (pose.knee - along).length();
    ChainPose { knee: along + orthogonal_part(a, DVec3::X) * radius, ankle: pose.ankle }
}

/// Coarse step of the search for a swivel within the limits (rad), and how far it looks.
const STEP: f64 = 5.0 * PI / 180.0;
const STEPS: u32 = 36;

/// How far the worst angle lies outside its range (rad), negative inside: how deep inside
/// the nearest range end is. Signed, so the edge of the limits is a root to home in on.
fn margin(chain: &LegChain, angles: LegAngles) -> f64 {
    angles
        .to_array()
        .iter()
        .zip(chain.limits.ranges())
        .map(|(x, (lo, hi))| (lo - x).max(x - hi))
        .fold(f64::MIN, f64::max)
}

/// The pose nearest the reference swivel whose angles lie within `chain`'s limits, turning
/// the knee about the hip→ankle axis of `pose` (the ankle stays where it is), with its
/// angles; `None` when no turn is within them. Used when a solver's answer with the knee
/// toward the reference breaks a limit: with the ankle on its target these turns are every
/// pose there is, so the search finds a pose within the limits wherever one reaches.
#[must_use]
pub(crate) fn into_limits(
    chain: &LegChain,
    pose: ChainPose,
    side: f64,
    previous_rot: f64,
) -> Option<(ChainPose, LegAngles)> {
    let a = pose.ankle.normalize_or(DVec3::NEG_Y);
    let along = a * a.dot(pose.knee);
    let radius = (pose.knee - along).length();
    let p = orthogonal_part(a, DVec3::X);
    let q = a.cross(p);
    let eval = |psi: f64| {
        let (s, c) = psi.sin_cos();
        let turned = ChainPose { knee: along + (p * c + q * s) * radius, ankle: pose.ankle };
        let angles = chain.angles_from_positions(turned, side, previous_rot);
        (margin(chain, angles), turned, angles)
    };
    let mut least = (f64::INFINITY, 0.0);
    for k in 0..=STEPS {
        for psi in [f64::from(k) * STEP, -f64::from(k) * STEP] {
            let (m, turned, angles) = eval(psi);
            if m <= 0.0 {
                if k == 0 {
                    return Some((turned, angles));
                }
                // Back toward the reference as far as the limits allow: regula falsi
                // (Illinois) on the margin between this turn and the previous one.
                let outside = psi - psi.signum() * STEP;
                return Some(edge(eval, (psi, m, turned, angles), (outside, eval(outside).0)));
            }
            if m < least.0 {
                least = (m, psi);
            }
        }
    }
    // A window within the limits narrower than the step: descend on the margin.
    let (mut lo, mut hi) = (least.1 - STEP, least.1 + STEP);
    for _ in 0..60 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        let (v1, p1, a1) = eval(m1);
        if v1 <= 0.0 {
            return Some((p1, a1));
        }
        if v1 < eval(m2).0 { hi = m2 } else { lo = m1 }
    }
    let (m, turned, angles) = eval(0.5 * (lo + hi));
    (m <= 0.0).then_some((turned, angles))
}

/// The turn on the edge of the limits between `inside` (margin ≤ 0, with its pose) and
/// `outside` (margin > 0), to within a millionth of a radian, kept on the inside.
fn edge(
    eval: impl Fn(f64) -> (f64, ChainPose, LegAngles),
    inside: (f64, f64, ChainPose, LegAngles),
    outside: (f64, f64),
) -> (ChainPose, LegAngles) {
    let (mut x_in, mut m_in, mut pose, mut angles) = inside;
    let (mut x_out, mut m_out) = outside;
    for _ in 0..40 {
        if (x_out - x_in).abs() < 1e-6 {
            break;
        }
        let x = (x_in * m_out - x_out * m_in) / (m_out - m_in);
        let x = if x.is_finite() && (x - x_in) * (x - x_out) < 0.0 { x } else { 0.5 * (x_in + x_out) };
        let (m, p, a) = eval(x);
        if m <= 0.0 {
            (x_in, m_in, pose, angles) = (x, m, p, a);
            m_out *= 0.5;
        } else {
            (x_out, m_out) = (x, m);
            m_in *= 0.5;
        }
    }
    (pose, angles)
}

/// How the angle-space solvers (CCD, Jacobian) finish: `solve` on the chain as it is (limits
/// clamped after every step); where that ends off the target — clamping can pin the iteration
/// against a limit — [`reach_then_turn`] with the same `solve` on the unlimited chain.
pub(crate) fn limited_else_turned(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    solve: impl Fn(&LegChain) -> Iterated,
) -> Iterated {
    let limited = solve(chain);
    let end = chain.forward(limited.angles, side).ankle.distance(target);
    if !chain.limits.enabled || end <= s.tolerance {
        return limited;
    }
    match reach_then_turn(chain, target, side, start, s, solve) {
        Some(mut turned) => {
            turned.iterations += limited.iterations;
            turned
        }
        None => limited,
    }
}

/// The fallback of the angle-space solvers (CCD, Jacobian) where their limited iteration
/// ends off the target: `free` (the same solver on the same chain with the limits off, or
/// where that misses, FABRIK's passes) reaches with the knee toward the reference, and the
/// knee is then turned about the hip→ankle axis into the limits. `None` when both miss or no
/// swivel is within the limits.
#[must_use]
pub(crate) fn reach_then_turn(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    free: impl FnOnce(&LegChain) -> Iterated,
) -> Option<Iterated> {
    let mut unlimited = *chain;
    unlimited.limits.enabled = false;
    let own = free(&unlimited);
    let mut iterations = own.iterations;
    let mut pose = chain.forward(own.angles, side);
    if pose.ankle.distance(target) > s.tolerance {
        // Near full reach CCD creeps (and the Jacobian can meet a singularity from a cold
        // start): FABRIK's passes on positions reach there.
        let (reached, distance, n) = reach(chain, target, side, start, s);
        iterations += n;
        if distance > s.tolerance {
            return None;
        }
        pose = reached;
    }
    let pose = pole(pose);
    let angles = chain.angles_from_positions(pose, side, start.hip_rot);
    let (pose, angles) = if chain.limits.violation(angles) == 0.0 {
        (pose, angles)
    } else {
        into_limits(chain, pose, side, start.hip_rot)?
    };
    Some(Iterated { angles, iterations, pose: Some(pose) })
}

/// FABRIK's reaching passes on positions from `start`: the best pose seen (by ankle distance), its
/// distance, and the iterations run.
pub(crate) fn reach(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
) -> (ChainPose, f64, u32) {
    let first = chain.forward(start, side);
    // A straight leg pointed at a nearer target is a fixed point of the passes.
    let unlocked = unlock_knee(chain, start, target);
    let mut pose = if unlocked == start { first } else { chain.forward(unlocked, side) };
    let mut best = (first, first.ankle.distance_squared(target));
    let mut stall = Stall::new(chain, target);
    let (thigh, shank, tolerance2) = (chain.thigh, chain.shank, s.tolerance * s.tolerance);
    let mut iterations = 0;
    loop {
        // Squared: a square root an iteration saved (the out-of-reach watch takes its own).
        let d2 = pose.ankle.distance_squared(target);
        if d2 < best.1 {
            best = (pose, d2);
        }
        if d2 <= tolerance2 || iterations == s.max_iterations || (stall.out_of_reach() && stall.stalled(d2.sqrt())) {
            return (best.0, best.1.sqrt(), iterations);
        }
        // Backward: ankle on the target. Forward: hip at the origin.
        let knee = target + (pose.knee - target).normalize_or(DVec3::Y) * shank;
        let knee = knee.normalize_or(DVec3::NEG_Y) * thigh;
        let ankle = knee + (target - knee).normalize_or(DVec3::NEG_Y) * shank;
        pose = ChainPose { knee, ankle };
        iterations += 1;
    }
}

/// The turn about the hip→ankle axis that puts the knee in the reference plane, without
/// trigonometry (the rotation between two unit vectors), and the turned pose.
#[must_use]
pub(crate) fn to_reference(pose: ChainPose) -> (ChainPose, DQuat) {
    let a = pose.ankle.normalize_or(DVec3::NEG_Y);
    let u = pose.knee - a * a.dot(pose.knee);
    let radius = u.length();
    if radius < 1e-12 {
        return (pose, DQuat::IDENTITY);
    }
    let (u, p) = (u / radius, orthogonal_part(a, DVec3::X));
    // Half a turn has no unique shortest arc; about the axis is the one wanted.
    let turn = if u.dot(p) > -1.0 + 1e-12 { DQuat::from_rotation_arc(u, p) } else { DQuat::from_axis_angle(a, PI) };
    (ChainPose { knee: turn * pose.knee, ankle: pose.ankle }, turn)
}
