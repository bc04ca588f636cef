//! Choosing a leg IK solver and keeping its state between frames.

use crate::model::ik::chain::{ChainPose, IkQuestion, JointLimits, LegAngles, LegChain};
use crate::model::ik::{TwoBoneOptions, ccd, fabrik, gradient, jacobian, solve_two_bone_with};
use crate::model::terrain::SplitMix64;
use glam::DVec3;

/// Which solver places the legs (`[ik] solver`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IkSolverKind {
    /// Law of cosines plus the reference-vector swivel: exact, the reference.
    Analytic,
    /// Cyclic coordinate descent, knee then hip, with per-joint stiffness (seed 001).
    Ccd,
    /// Forward and backward reaching on joint positions, hinge and limits enforced.
    Fabrik,
    /// Jacobian iterations: damped least squares, transpose or pseudo-inverse.
    JacobianDls,
    /// Seed 002's gradient descent with random restarts and perturbations.
    Gradient,
}

impl IkSolverKind {
    /// Every solver, in the order the config documents them.
    pub const ALL: [IkSolverKind; 5] = [
        IkSolverKind::Analytic,
        IkSolverKind::Ccd,
        IkSolverKind::Fabrik,
        IkSolverKind::JacobianDls,
        IkSolverKind::Gradient,
    ];

    /// The config's name for it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            IkSolverKind::Analytic => "analytic",
            IkSolverKind::Ccd => "ccd",
            IkSolverKind::Fabrik => "fabrik",
            IkSolverKind::JacobianDls => "jacobian_dls",
            IkSolverKind::Gradient => "gradient",
        }
    }

    /// The solver called `name` in a config.
    #[must_use]
    pub fn from_name(name: &str) -> Option<IkSolverKind> {
        IkSolverKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// Whether it iterates (and so warm-starts and counts iterations).
    #[must_use]
    pub fn is_iterative(self) -> bool {
        self != IkSolverKind::Analytic
    }
}

/// How the Jacobian solver turns the error into a joint update.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JacobianVariant {
    /// Δθ = Jᵀ(JJᵀ + λ²I)⁻¹e: stable through the straight-knee singularity.
    Dls,
    /// Δθ = αJᵀe with Buss's step α = ⟨e, JJᵀe⟩ / |JJᵀe|²: cheap, slow to converge.
    Transpose,
    /// Δθ = J⁻¹e (λ = 0), falling back to a small damping where J is singular.
    PseudoInverse,
}

impl JacobianVariant {
    /// Every variant, in config order.
    pub const ALL: [JacobianVariant; 3] =
        [JacobianVariant::Dls, JacobianVariant::Transpose, JacobianVariant::PseudoInverse];

    /// The config's name for it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            JacobianVariant::Dls => "dls",
            JacobianVariant::Transpose => "transpose",
            JacobianVariant::PseudoInverse => "pseudo_inverse",
        }
    }

    /// The variant called `name` in a config.
    #[must_use]
    pub fn from_name(name: &str) -> Option<JacobianVariant> {
        JacobianVariant::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// The gradient solver's settings (seed 002's defaults: δ0 = 5, ε = 1e-4, 100 restarts on
/// the first frame, 100 perturbations of ±15° a frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GradientSettings {
    /// Starting step: multiple of the gradient subtracted per step (deg² / mm²).
    pub delta0: f64,
    /// The step halves on every failed try; descent ends below this.
    pub epsilon: f64,
    /// Random starting poses tried on the first frame (0: the rest pose only).
    pub restarts: u32,
    /// Random perturbations tried after every descent, each kept only if it lowers the cost.
    pub perturbations: u32,
    /// Perturbation range, ± on every angle (rad).
    pub perturbation: f64,
    /// Seed of the portable generator; the same seed gives the same poses on every run.
    pub seed: u64,
    /// Weight of the knee's squared swivel arc against the squared position error.
    pub weight_swivel: f64,
    /// Most descent steps (accepted or halved) in one descent.
    pub max_steps: u32,
}

/// Everything a leg solver needs from the `[ik]` group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkSettings {
    /// The solver.
    pub solver: IkSolverKind,
    /// Iterative solvers stop once the ankle is this close to the target and the knee's swivel
    /// arc this small (m).
    pub tolerance: f64,
    /// Most iterations of CCD, FABRIK and the Jacobian solver.
    pub max_iterations: u32,
    /// Joint ranges.
    pub limits: JointLimits,
    /// Analytic: softening ratio (1: off).
    pub soften: f64,
    /// Analytic: extra knee twist about the hip→ankle axis (rad).
    pub twist: f64,
    /// CCD: share of each hip rotation applied per iteration, (0, 1].
    pub ccd_stiffness_hip: f64,
    /// CCD: share of each knee rotation applied per iteration, (0, 1].
    pub ccd_stiffness_knee: f64,
    /// Jacobian: damping λ (m).
    pub dls_damping: f64,
    /// Jacobian: update rule.
    pub jacobian_variant: JacobianVariant,
    /// Gradient descent.
    pub gradient: GradientSettings,
}

impl Default for IkSettings {
    fn default() -> Self {
        IkSettings {
            solver: IkSolverKind::Analytic,
            tolerance: 1e-4,
            max_iterations: 5000,
            limits: JointLimits::default(),
            soften: 1.0,
            twist: 0.0,
            ccd_stiffness_hip: 1.0,
            ccd_stiffness_knee: 1.0,
            dls_damping: 0.02,
            jacobian_variant: JacobianVariant::Dls,
            gradient: GradientSettings {
                delta0: 5.0,
                epsilon: 1e-4,
                restarts: 100,
                perturbations: 5,
                perturbation: 15f64.to_radians(),
                seed: 2,
                weight_swivel: 10.0,
                max_steps: 20_000,
            },
        }
    }
}

/// One solve's result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkAnswer {
    /// Knee joint (m, world).
    pub knee: DVec3,
    /// Ankle joint as placed (m, world).
    pub ankle: DVec3,
    /// The joint angles in the leg frame.
    pub angles: LegAngles,
    /// Ankle to target (m).
    pub position_error: f64,
    /// The knee's arc off the reference plane (m, signed).
    pub swivel_arc: f64,
    /// Iterations used (analytic: 1; gradient: descent steps over all starts).
    pub iterations: u32,
    /// Whether the ankle is on the target within the tolerance (analytic: exactly, unsoftened).
    pub reached: bool,
}

impl Default for IkAnswer {
    fn default() -> Self {
        IkAnswer {
            knee: DVec3::ZERO,
            ankle: DVec3::ZERO,
            angles: LegAngles::default(),
            position_error: 0.0,
            swivel_arc: 0.0,
            iterations: 0,
            reached: true,
        }
    }
}

impl IkAnswer {
    /// The analytic solver's answer as the walk records it: one iteration, no swivel error.
    #[must_use]
    pub fn exact(knee: DVec3, ankle: DVec3, reached: bool, target: DVec3) -> Self {
        IkAnswer { knee, ankle, position_error: ankle.distance(target), iterations: 1, reached, ..IkAnswer::default() }
    }
}

/// What an iterative solver hands back.
#[derive(Clone, Copy, Debug)]
pub struct Iterated {
    /// Final angles.
    pub angles: LegAngles,
    /// Iterations used.
    pub iterations: u32,
}

/// Notices when an iteration on a target out of reach has stopped improving, so solvers end
/// with the leg stretched toward it instead of spinning to their cap. Reachable targets never
/// stall: slow convergence there is the solver's own figure to report.
#[derive(Clone, Copy, Debug)]
pub struct Stall {
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

    /// Records this iteration's error (m); true once it has not improved for a while.
    pub fn stalled(&mut self, error: f64) -> bool {
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
pub const MIN_BEND: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// `angles` with the knee bent at least [`MIN_BEND`] when `target` is within reach.
#[must_use]
pub fn unlock_knee(chain: &LegChain, angles: LegAngles, target: DVec3) -> LegAngles {
    if angles.knee_flex < MIN_BEND && target.length() < chain.reach() - 1e-6 {
        LegAngles { knee_flex: MIN_BEND, ..angles }
    } else {
        angles
    }
}

/// Runs an iterative solver's `step` from `start` until the pose is within the tolerance,
/// the iterations run out, or (out of reach) it stops improving. `step` gets the current
/// angles and their pose and returns the next angles.
pub fn iterate(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    mut step: impl FnMut(LegAngles, ChainPose) -> LegAngles,
) -> Iterated {
    let mut angles = start;
    let mut stall = Stall::new(chain, target);
    for iteration in 0..=s.max_iterations {
        let pose = chain.forward(angles, side);
        let (distance, arc) = chain.residual(pose, target);
        if distance <= s.tolerance && arc.abs() <= s.tolerance {
            return Iterated { angles, iterations: iteration };
        }
        if iteration == s.max_iterations || stall.stalled(distance.hypot(arc)) {
            return Iterated { angles, iterations: iteration };
        }
        angles = step(angles, pose);
    }
    Iterated { angles, iterations: s.max_iterations }
}

/// A leg's solver with its memory: the previous frame's angles (warm start) and, for the
/// gradient solver, its random generator.
#[derive(Clone, Debug)]
pub struct LegSolver {
    settings: IkSettings,
    chain: LegChain,
    side_sign: f64,
    warm: Option<LegAngles>,
    rng: SplitMix64,
}

impl LegSolver {
    /// A solver for one leg (`side_sign` +1 right, −1 left) with bones `thigh`, `shank` (m).
    #[must_use]
    pub fn new(settings: IkSettings, thigh: f64, shank: f64, side_sign: f64) -> Self {
        let chain = LegChain { thigh, shank, limits: settings.limits };
        // Each leg draws its own stream, so solving one leg more often never shifts the other's.
        let stream = if side_sign > 0.0 { 0x5249_4748_5400_0000 } else { 0x4c45_4654_0000_0000 };
        LegSolver { settings, chain, side_sign, warm: None, rng: SplitMix64::new(settings.gradient.seed ^ stream) }
    }

    /// Changes the settings, keeping the previous frame's answer to start from.
    pub fn set_settings(&mut self, settings: IkSettings) {
        let warm = self.warm;
        *self = LegSolver::new(settings, self.chain.thigh, self.chain.shank, self.side_sign);
        self.warm = warm;
    }

    /// Solves one question, warm-starting from the previous answer.
    pub fn solve(&mut self, question: &IkQuestion) -> IkAnswer {
        let chain = self.chain;
        let side = question.side_sign;
        let target = question.local_target();
        let s = &self.settings;
        let (angles, iterations) = match s.solver {
            IkSolverKind::Analytic => {
                let options = TwoBoneOptions { soften: s.soften, twist: s.twist };
                let solved = solve_two_bone_with(
                    question.hip,
                    question.target,
                    chain.thigh,
                    chain.shank,
                    question.reference,
                    options,
                );
                let frame_inv = question.frame().inverse();
                let pose = ChainPose {
                    knee: frame_inv * (solved.middle - question.hip),
                    ankle: frame_inv * (solved.end - question.hip),
                };
                let previous = self.warm.map_or(0.0, |w| w.hip_rot);
                (chain.angles_from_positions(pose, side, previous), 1)
            }
            _ if target.length() >= chain.reach() => {
                // Beyond reach every solver would only creep up on the straight-knee
                // singularity; like the analytic solver (and FABRIK's own first test), answer
                // with the leg stretched straight toward the target.
                let dir = target.normalize();
                let straight = ChainPose { knee: dir * chain.thigh, ankle: dir * chain.reach() };
                let previous = self.warm.map_or(0.0, |w| w.hip_rot);
                (chain.limits.clamp(chain.angles_from_positions(straight, side, previous)), 0)
            }
            kind => {
                let start = self.warm.unwrap_or_else(LegAngles::rest);
                let start = chain.limits.clamp(start);
                let result = match kind {
                    IkSolverKind::Ccd => ccd::solve(&chain, target, side, start, s),
                    IkSolverKind::Fabrik => fabrik::solve(&chain, target, side, start, s),
                    IkSolverKind::JacobianDls => jacobian::solve(&chain, target, side, start, s),
                    _ => {
                        let first = self.warm.is_none();
                        gradient::solve(&chain, target, side, start, s, first, &mut self.rng)
                    }
                };
                (result.angles, result.iterations)
            }
        };
        let angles = if angles.is_finite() { angles } else { LegAngles::rest() };
        self.warm = Some(angles);
        let pose = chain.forward(angles, side);
        // Random restarts can land on another Euler branch of the same pose (flexion past
        // ±180°, say); report the one decomposition every solver shares, so limit checks
        // compare poses, not parametrisations.
        let angles = chain.angles_from_positions(pose, side, angles.hip_rot);
        let (position_error, swivel_arc) = chain.residual(pose, target);
        let reached = if s.solver.is_iterative() { position_error <= s.tolerance } else { position_error <= 1e-9 };
        IkAnswer {
            knee: question.to_world(pose.knee),
            ankle: question.to_world(pose.ankle),
            angles,
            position_error,
            swivel_arc,
            iterations,
            reached,
        }
    }
}
