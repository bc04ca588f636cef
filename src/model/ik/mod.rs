//! Analytic two-bone inverse kinematics with a reference-vector swivel (spec §6, [6.3.2]).
//!
//! Given the root joint (hip or shoulder), the end target (ankle or wrist) and the two bone
//! lengths, the law of cosines fixes the middle joint's distance along the root→target axis
//! **a**; the remaining freedom, the swivel about **a**, puts the middle joint (knee, elbow)
//! toward a reference vector **k**. For the leg, **k** is horizontal along the walking
//! direction turned by the foot turnout — not attached to the pelvis, so pelvic rotation does
//! not twist the legs, and never parallel to a walking leg's axis, so the knee cannot flip.

pub mod analytic;
pub mod ccd;
pub mod chain;
pub mod fabrik;
pub mod gradient;
pub mod iterate;
pub mod jacobian;
pub mod params;
pub mod settings;
pub mod solver;
pub(crate) mod swivel;

pub use analytic::{TwoBoneOptions, TwoBoneSolution, solve_two_bone, solve_two_bone_with};
pub(crate) use analytic::{orthogonal_part, softened_distance};
pub use chain::{IkQuestion, JointLimits, LegAngles, LegChain};
pub use settings::{GradientSettings, IkAnswer, IkSettings, IkSolverKind, JacobianVariant};
pub use solver::LegSolver;
