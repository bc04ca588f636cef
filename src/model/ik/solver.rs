//! Choosing a leg IK solver and keeping its state between frames: [`LegSolver`] only
//! dispatches to the solver files, which import nothing back from here.

use crate::model::ik::analytic::{TwoBoneOptions, solve_two_bone_with};
use crate::model::ik::chain::{ChainPose, IkQuestion, LegAngles, LegChain};
use crate::model::ik::settings::{IkAnswer, IkSettings, IkSolverKind};
use crate::model::ik::{ccd, fabrik, gradient, jacobian};
use crate::model::terrain::SplitMix64;

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
    pub(crate) fn set_settings(&mut self, settings: IkSettings) {
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
