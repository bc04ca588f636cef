//! The iteration driver the iterative solvers (CCD, FABRIK, Jacobian) share: stop at the
//! tolerance, at the cap, or when a target out of reach stops improving.

use crate::model::ik::chain::{ChainPose, LegAngles, LegChain};
use crate::model::ik::settings::IkSettings;
use glam::DVec3;

/// What an iterative solver hands back.
#[derive(Clone, Copy, Debug)]
pub struct Iterated {
    /// Final angles.
    pub angles: LegAngles,
    /// Iterations used.
    pub iterations: u32,
    /// The pose the angles were read from, when the solver read them off positions (then
    /// they are the shared decomposition and need no second read).
    pub pose: Option<ChainPose>,
}

/// Which of two poses a solver keeps: any on the target (within `tolerance`) beats any off
/// it; on it, the smaller swivel arc wins; off it, the smaller distance. Solvers keep the
/// best pose seen, so none ends worse than it started.
#[must_use]
pub(crate) fn better(tolerance: f64, (d1, arc1): (f64, f64), (d2, arc2): (f64, f64)) -> bool {
    match (d1 <= tolerance, d2 <= tolerance) {
        (true, true) => arc1.abs() < arc2.abs(),
        (true, false) => true,
        (false, true) => false,
        (false, false) => d1 < d2,
    }
}

/// Notices when an iteration on a target out of reach has stopped improving, so solvers end
/// with the leg stretched toward it instead of spinning to their cap. Reachable targets never
/// stall: slow convergence there is the solver's own figure to report.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stall {
    out_of_reach: bool,
    best: f64,
    since: u32,
}

impl Stall {
    /// Iterations without a gain of at least 0.1 µm before giving up.
    const PATIENCE: u32 = 4;

    /// A watcher for one solve toward `target` (leg frame).
    #[must_use]
    pub fn new(chain: &LegChain, target: DVec3) -> Self {
        let d = target.length();
        let out_of_reach = d > chain.reach() - 1e-9 || d < (chain.thigh - chain.shank).abs() + 1e-9;
        Stall { out_of_reach, best: f64::INFINITY, since: 0 }
    }

    /// Whether the target lies beyond full reach or inside the least.
    #[must_use]
    pub(crate) fn out_of_reach(&self) -> bool {
        self.out_of_reach
    }

    /// Records this iteration's error (m); true once it has not improved for a while.
    pub(crate) fn stalled(&mut self, error: f64) -> bool {
        if !self.out_of_reach {
            return false;
        }
        if error < self.best - 1e-7 {
            self.best = error;
            self.since = 0;
            false
        } else {
            self.since += 1;
            self.since >= Self::PATIENCE
        }
    }
}

/// The least knee flexion iterative solvers keep while the target is within reach (rad).
///
/// A straight chain pointed at a nearer target is a fixed point of CCD and FABRIK (every
/// joint already points at it), so they could never bend the knee out of it. 0.5° shortens
/// the leg by under 0.01 mm, far inside any tolerance.
pub(crate) const MIN_BEND: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// `angles` with the knee bent at least [`MIN_BEND`] when `target` is within reach.
#[must_use]
pub(crate) fn unlock_knee(chain: &LegChain, angles: LegAngles, target: DVec3) -> LegAngles {
    if angles.knee_flex < MIN_BEND && target.length() < chain.reach() - 1e-6 {
        LegAngles { knee_flex: MIN_BEND, ..angles }
    } else {
        angles
    }
}

/// Iterations without a new best pose after which a limited iteration is taken to circle.
const CIRCLING: u32 = 64;

/// Runs an iterative solver's `step` from `start` until the pose is within the tolerance,
/// the iterations run out, or it stops improving: out of reach, or on the target with the
/// knee's swivel held off the reference by a limit. `step` gets the current angles and their
/// pose and returns the next angles. Returns the best pose seen (see [`better`]).
pub(crate) fn iterate(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    mut step: impl FnMut(LegAngles, ChainPose) -> LegAngles,
) -> Iterated {
    let mut angles = start;
    let mut stall = Stall::new(chain, target);
    let mut settle = Stall { out_of_reach: true, best: f64::INFINITY, since: 0 };
    let mut best = (start, (f64::INFINITY, f64::INFINITY));
    let mut since_best = 0;
    for iteration in 0..=s.max_iterations {
        let pose = chain.forward(angles, side);
        let (distance, arc) = chain.residual(pose, target);
        since_best += 1;
        if better(s.tolerance, (distance, arc), best.1) {
            // Progress below a nanometre is a clamped iteration circling, not converging.
            if best.1.0 - distance > 1e-9 || (distance <= s.tolerance && best.1.1.abs() - arc.abs() > 1e-9) {
                since_best = 0;
            }
            best = (angles, (distance, arc));
        }
        // Limits clamped after every step can hold an iteration in a cycle off the target.
        let circling = chain.limits.enabled && since_best > CIRCLING;
        if distance <= s.tolerance && arc.abs() <= s.tolerance {
            return Iterated { angles, iterations: iteration, pose: None };
        }
        let settled = distance <= s.tolerance && settle.stalled(arc.abs());
        if iteration == s.max_iterations || settled || circling || stall.stalled(distance.hypot(arc)) {
            return Iterated { angles: best.0, iterations: iteration, pose: None };
        }
        angles = step(angles, pose);
    }
    Iterated { angles: best.0, iterations: s.max_iterations, pose: None }
}
