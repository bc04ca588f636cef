//! Choosing a leg IK solver and keeping its state between frames: [`LegSolver`] only
//! dispatches to the solver files, which import nothing back from here.

use crate::model::ik::analytic::{TwoBoneOptions, solve_two_bone_with};
use crate::model::ik::chain::{ChainPose, IkQuestion, LegAngles, LegChain};
use crate::model::ik::iterate::Iterated;
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

    /// Forgets the previous answer: the next solve starts cold, from the rest pose (and the
    /// gradient solver runs its first-frame restarts again).
    pub fn forget(&mut self) {
        self.warm = None;
    }

    /// Solves one question, warm-starting from the previous answer.
    pub fn solve(&mut self, question: &IkQuestion) -> IkAnswer {
        if self.settings.solver == IkSolverKind::Analytic {
            return self.analytic(question);
        }
        let chain = self.chain;
        let side = question.side_sign;
        // The quaternion frame, not the trigonometry-free one the analytic answer uses: the
        // Jacobian's forward differences magnify its last-bit differences into the
        // nanometres the report prints.
        let frame = question.frame();
        let target = frame.inverse() * (question.target - question.hip);
        let s = &self.settings;
        let previous = self.warm.map_or(0.0, |w| w.hip_rot);
        let result = if target.length() >= chain.reach() {
            // Beyond reach every solver would only creep up on the straight-knee
            // singularity; like the analytic solver (and FABRIK's own first test), answer
            // with the leg stretched straight toward the target.
            let dir = target.normalize();
            let straight = ChainPose { knee: dir * chain.thigh, ankle: dir * chain.reach() };
            let angles = chain.limits.clamp(chain.angles_from_positions(straight, side, previous));
            Iterated { angles, iterations: 0, pose: None }
        } else {
            let start = chain.limits.clamp(self.warm.unwrap_or_else(LegAngles::rest));
            match s.solver {
                IkSolverKind::Ccd => ccd::solve(&chain, target, side, start, s),
                IkSolverKind::Fabrik => fabrik::solve(&chain, target, side, start, s),
                IkSolverKind::JacobianDls => jacobian::solve(&chain, target, side, start, s),
                _ => {
                    let first = self.warm.is_none();
                    gradient::solve(&chain, target, side, start, s, first, &mut self.rng)
                }
            }
        };
        let (angles, pose, warm) = match result.pose {
            Some(pose) if result.angles.is_finite() => (result.angles, pose, result.angles),
            _ => {
                let angles = if result.angles.is_finite() { result.angles } else { LegAngles::rest() };
                let pose = chain.forward(angles, side);
                // Random restarts can land on another Euler branch of the same pose (flexion
                // past ±180°, say); report the one decomposition every solver shares, so limit
                // checks compare poses, not parametrisations.
                // The solver's own angles stay its warm start.
                (chain.angles_from_positions(pose, side, angles.hip_rot), pose, angles)
            }
        };
        self.warm = Some(warm);
        let (position_error, swivel_arc) = chain.residual(pose, target);
        IkAnswer {
            knee: question.hip + frame * pose.knee,
            ankle: question.hip + frame * pose.ankle,
            angles,
            position_error,
            swivel_arc,
            iterations: result.iterations,
            reached: position_error <= s.tolerance,
        }
    }

    /// The analytic solve with its joint angles read off once, straight from the solved
    /// positions: no forward kinematics after it, no second read.
    fn analytic(&mut self, question: &IkQuestion) -> IkAnswer {
        let (chain, s) = (self.chain, &self.settings);
        let options = TwoBoneOptions { soften: s.soften, twist: s.twist };
        let hip = question.hip;
        let solved = solve_two_bone_with(hip, question.target, chain.thigh, chain.shank, question.reference, options);
        let frame = question.leg_frame();
        let pose = ChainPose { knee: frame.to_local(solved.middle), ankle: frame.to_local(solved.end) };
        let previous = self.warm.map_or(0.0, |w| w.hip_rot);
        let angles = chain.angles_from_positions(pose, question.side_sign, previous);
        let angles = if angles.is_finite() { angles } else { LegAngles::rest() };
        self.warm = Some(angles);
        let position_error = solved.end.distance(question.target);
        // Untwisted, the knee lies in the reference plane by construction.
        let swivel_arc = if s.twist == 0.0 { 0.0 } else { chain.residual(pose, frame.to_local(question.target)).1 };
        IkAnswer {
            knee: solved.middle,
            ankle: solved.end,
            angles,
            position_error,
            swivel_arc,
            iterations: 1,
            reached: position_error <= 1e-9,
        }
    }
}
