//! What the leg solvers are asked to do: which solver, its settings, and the answer it gives.

use crate::model::ik::chain::{JointLimits, LegAngles};
use glam::DVec3;

/// Which solver places the legs (`[ik] solver`).
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    Hash,
    strum::IntoStaticStr,
    strum::EnumString,
    strum::VariantArray,
    strum::EnumCount,
)]
#[strum(serialize_all = "snake_case")]
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

crate::model::variants::named_variants!(IkSolverKind);

impl IkSolverKind {
    /// Whether it iterates (and so warm-starts and counts iterations).
    #[must_use]
    pub fn is_iterative(self) -> bool {
        self != IkSolverKind::Analytic
    }
}

/// How the Jacobian solver turns the error into a joint update.
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    Hash,
    strum::IntoStaticStr,
    strum::EnumString,
    strum::VariantArray,
    strum::EnumCount,
)]
#[strum(serialize_all = "snake_case")]
pub enum JacobianVariant {
    /// Δθ = Jᵀ(JJᵀ + λ²I)⁻¹e: stable through the straight-knee singularity.
    Dls,
    /// Δθ = αJᵀe with Buss's step α = ⟨e, JJᵀe⟩ / |JJᵀe|²: cheap, slow to converge.
    Transpose,
    /// Δθ = J⁻¹e (λ = 0), falling back to a small damping where J is singular.
    PseudoInverse,
}

crate::model::variants::named_variants!(JacobianVariant);

/// The gradient solver's settings (seed 002's defaults: δ0 = 5, ε = 1e-4, 100 restarts on
/// the first frame, 100 perturbations of ±15° a frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GradientSettings {
    /// Starting step: multiple of the gradient subtracted per step (deg² / mm²).
    pub(crate) delta0: f64,
    /// The step halves on every failed try; descent ends below this.
    pub(crate) epsilon: f64,
    /// Random starting poses tried on the first frame (0: the rest pose only).
    pub restarts: u32,
    /// Random perturbations tried after every descent, each kept only if it lowers the cost.
    pub perturbations: u32,
    /// Perturbation range, ± on every angle (rad).
    pub(crate) perturbation: f64,
    /// Seed of the portable generator; the same seed gives the same poses on every run.
    pub seed: u64,
    /// Weight of the knee's squared swivel arc against the squared position error.
    pub(crate) weight_swivel: f64,
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
    pub(crate) swivel_arc: f64,
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
