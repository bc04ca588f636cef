//! Jacobian iterations on the four leg angles. The task has four rows — the ankle's position
//! error (3, m) and the knee's swivel arc (1, m) — so the Jacobian is square and the swivel
//! preference is a task like the position, not an afterthought. Columns are forward
//! differences of the chain's own forward kinematics.

use crate::model::ik::chain::{LegAngles, LegChain};
use crate::model::ik::iterate::{Iterated, iterate};
use crate::model::ik::settings::{IkSettings, JacobianVariant};
use crate::model::ik::swivel::limited_else_turned;
use glam::{DMat4, DVec3, DVec4};

/// Largest joint update per iteration (rad): keeps a near-singular step from flinging the leg.
const MAX_STEP: f64 = 0.35;
/// Forward-difference step (rad).
const H: f64 = 1e-7;

fn task(chain: &LegChain, angles: LegAngles, side: f64, target: DVec3) -> DVec4 {
    let pose = chain.forward(angles, side);
    let (angle, radius) = LegChain::swivel(pose);
    let error = target - pose.ankle;
    DVec4::new(error.x, error.y, error.z, -angle * radius)
}

/// Solves for the ankle at `target` (leg frame) from `start`.
#[must_use]
pub fn solve(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    limited_else_turned(chain, target, side, start, s, |c| solve_within(c, target, side, start, s))
}

/// The iteration itself, with `chain`'s limits clamped after every step.
fn solve_within(chain: &LegChain, target: DVec3, side: f64, start: LegAngles, s: &IkSettings) -> Iterated {
    let limits = chain.limits;
    iterate(chain, target, side, start, s, |angles, _| {
        let e = task(chain, angles, side, target);
        // J = ∂(ankle, arc)/∂θ = −∂e/∂θ.
        let base = angles.to_array();
        let mut columns = [DVec4::ZERO; 4];
        for (j, column) in columns.iter_mut().enumerate() {
            let mut nudged = base;
            nudged[j] += H;
            *column = (e - task(chain, LegAngles::from_array(nudged), side, target)) / H;
        }
        let jac = DMat4::from_cols(columns[0], columns[1], columns[2], columns[3]);
        let jjt = jac * jac.transpose();
        let damped =
            |lambda: f64| jac.transpose() * (jjt + DMat4::from_diagonal(DVec4::splat(lambda * lambda))).inverse() * e;
        let step = match s.jacobian_variant {
            JacobianVariant::Dls => damped(s.dls_damping),
            JacobianVariant::Transpose => {
                let jjt_e = jjt * e;
                let alpha = e.dot(jjt_e) / jjt_e.length_squared().max(1e-300);
                jac.transpose() * e * alpha
            }
            JacobianVariant::PseudoInverse => {
                if jac.determinant().abs() > 1e-12 {
                    jac.inverse() * e
                } else {
                    damped(1e-3)
                }
            }
        };
        let step = if step.is_finite() { step } else { DVec4::ZERO };
        let scale = (MAX_STEP / step.abs().max_element().max(1e-300)).min(1.0);
        let mut next = base;
        for (x, d) in next.iter_mut().zip(step.to_array()) {
            *x += d * scale;
        }
        limits.clamp(LegAngles::from_array(next))
    })
}
