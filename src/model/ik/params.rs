//! `[ik]`: the leg IK's parameters in the config's units, and the solver settings they
//! describe. Beside the solvers, whose defaults ([`IkSettings::default`]) they start from.

use crate::model::ik::settings::GradientSettings;
use crate::model::ik::{IkSettings, IkSolverKind, JacobianVariant, JointLimits};

/// `[ik]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct IkParams {
    /// Fraction of full leg reach the planner keeps the stance leg within: the knee never locks.
    /// 0.9996 (knee ≥ 3.2°, the norms' 1-3° at heel strike): knee RMS 0.4-0.7° under 0.999's
    /// (≥ 5.1°); 0.9998 jerked the hip 1.22x at a pace change (docs/gait-model.md §12).
    pub(crate) reach_margin: f64,
    pub solver: IkSolverKind,
    pub tolerance_mm: f64,
    pub(crate) max_iterations: u32,
    pub limits: bool,
    pub hip_flex_max_deg: f64,
    pub hip_ext_max_deg: f64,
    pub(crate) hip_abd_max_deg: f64,
    pub(crate) hip_add_max_deg: f64,
    pub hip_int_rot_max_deg: f64,
    pub hip_ext_rot_max_deg: f64,
    pub knee_flex_max_deg: f64,
    pub soften: f64,
    pub twist_deg: f64,
    pub(crate) ccd_stiffness_hip: f64,
    pub(crate) ccd_stiffness_knee: f64,
    pub(crate) dls_damping_m: f64,
    pub jacobian: JacobianVariant,
    pub(crate) gradient_delta0: f64,
    pub(crate) gradient_epsilon: f64,
    pub gradient_restarts: u32,
    pub gradient_perturbations: u32,
    pub(crate) gradient_perturbation_deg: f64,
    pub(crate) gradient_seed: u64,
    pub(crate) gradient_weight_swivel: f64,
    pub(crate) gradient_max_steps: u32,
}

impl Default for IkParams {
    fn default() -> Self {
        let s = IkSettings::default();
        let l = s.limits;
        let deg = f64::to_degrees;
        IkParams {
            reach_margin: 0.9996,
            solver: s.solver,
            tolerance_mm: s.tolerance * 1e3,
            max_iterations: s.max_iterations,
            limits: l.enabled,
            hip_flex_max_deg: deg(l.hip_flex.1).round(),
            hip_ext_max_deg: deg(-l.hip_flex.0).round(),
            hip_abd_max_deg: deg(l.hip_abd.1).round(),
            hip_add_max_deg: deg(-l.hip_abd.0).round(),
            hip_int_rot_max_deg: deg(l.hip_rot.1).round(),
            hip_ext_rot_max_deg: deg(-l.hip_rot.0).round(),
            knee_flex_max_deg: deg(l.knee_flex.1).round(),
            soften: s.soften,
            twist_deg: deg(s.twist),
            ccd_stiffness_hip: s.ccd_stiffness_hip,
            ccd_stiffness_knee: s.ccd_stiffness_knee,
            dls_damping_m: s.dls_damping,
            jacobian: s.jacobian_variant,
            gradient_delta0: s.gradient.delta0,
            gradient_epsilon: s.gradient.epsilon,
            gradient_restarts: s.gradient.restarts,
            gradient_perturbations: s.gradient.perturbations,
            gradient_perturbation_deg: deg(s.gradient.perturbation).round(),
            gradient_seed: s.gradient.seed,
            gradient_weight_swivel: s.gradient.weight_swivel,
            gradient_max_steps: s.gradient.max_steps,
        }
    }
}

impl IkParams {
    /// The solver settings these parameters describe, in SI units.
    #[must_use]
    pub fn settings(&self) -> IkSettings {
        let r = f64::to_radians;
        IkSettings {
            solver: self.solver,
            tolerance: self.tolerance_mm / 1e3,
            max_iterations: self.max_iterations,
            limits: JointLimits {
                enabled: self.limits,
                hip_flex: (-r(self.hip_ext_max_deg), r(self.hip_flex_max_deg)),
                hip_abd: (-r(self.hip_add_max_deg), r(self.hip_abd_max_deg)),
                hip_rot: (-r(self.hip_ext_rot_max_deg), r(self.hip_int_rot_max_deg)),
                knee_flex: (0.0, r(self.knee_flex_max_deg)),
            },
            soften: self.soften,
            twist: r(self.twist_deg),
            ccd_stiffness_hip: self.ccd_stiffness_hip,
            ccd_stiffness_knee: self.ccd_stiffness_knee,
            dls_damping: self.dls_damping_m,
            jacobian_variant: self.jacobian,
            gradient: GradientSettings {
                delta0: self.gradient_delta0,
                epsilon: self.gradient_epsilon,
                restarts: self.gradient_restarts,
                perturbations: self.gradient_perturbations,
                perturbation: r(self.gradient_perturbation_deg),
                seed: self.gradient_seed,
                weight_swivel: self.gradient_weight_swivel,
                max_steps: self.gradient_max_steps,
            },
        }
    }
}
