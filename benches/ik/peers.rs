//! The peers the IK bench measures gaitlab's solvers against, on the same leg and targets:
//! `rebirth-ik`'s allocation-free FABRIK on a point chain (f32, no pole, no limits) and `k`'s
//! Jacobian solver on a joint chain built like gaitlab's leg (hip Z·X·Y, knee Z; limits on).

use gaitlab::model::ik::{IkQuestion, JointLimits, LegAngles, LegChain};
use glam::DVec3;
use k::nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use k::prelude::*;

/// Where cold solves start: the rest pose every gaitlab solver starts from.
fn rest(thigh: f64, shank: f64) -> (DVec3, DVec3) {
    let chain = LegChain { thigh, shank, limits: JointLimits::default() };
    let pose = chain.forward(LegAngles::rest(), 1.0);
    (pose.knee, pose.ankle)
}

fn v32(v: DVec3) -> rebirth_ik::Vec3 {
    rebirth_ik::Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

/// One leg for `rebirth_ik::solve_chain`: hip, knee, ankle relative to the hip.
pub struct Rebirth {
    points: [rebirth_ik::Vec3; 3],
    rest: [rebirth_ik::Vec3; 3],
    lengths: [f32; 2],
}

impl Rebirth {
    pub fn new(thigh: f64, shank: f64) -> Self {
        let (knee, ankle) = rest(thigh, shank);
        let rest = [rebirth_ik::Vec3::ZERO, v32(knee), v32(ankle)];
        Rebirth { points: rest, rest, lengths: [thigh as f32, shank as f32] }
    }

    /// Solves `q` (warm from the previous answer unless `cold`); iterations and error (m).
    pub fn solve(&mut self, q: &IkQuestion, cold: bool, tolerance: f64) -> (u32, f64) {
        if cold {
            self.points = self.rest;
        }
        let target = v32(q.target - q.hip);
        let r = rebirth_ik::solve_chain(&mut self.points, &self.lengths, target, 5000, tolerance as f32);
        (r.iterations, f64::from(r.error))
    }
}

/// One leg for `k`'s Jacobian solver, position only, joint limits as gaitlab's (right leg).
pub struct KLeg {
    chain: k::SerialChain<f64>,
    end: k::Node<f64>,
    solver: k::JacobianIkSolver<f64>,
    constraints: k::Constraints,
    rest: Vec<f64>,
}

fn joint(name: &str, axis: Vector3<f64>, offset: f64, range: Option<(f64, f64)>) -> k::Node<f64> {
    let axis = k::nalgebra::Unit::new_normalize(axis);
    k::NodeBuilder::new()
        .name(name)
        .joint_type(k::JointType::Rotational { axis })
        .translation(Translation3::new(0.0, -offset, 0.0))
        .limits(range.map(|(lo, hi)| k::joint::Range::new(lo, hi)))
        .finalize()
        .into()
}

impl KLeg {
    pub fn new(thigh: f64, shank: f64, limits: &JointLimits, tolerance: f64) -> Self {
        let on = |r: (f64, f64)| limits.enabled.then_some(r);
        // The right leg: abduction is −x, knee flexion −z (see gaitlab's LegChain).
        let flex = joint("hip_flex", Vector3::z(), 0.0, on(limits.hip_flex));
        let abd = joint("hip_abd", Vector3::x(), 0.0, on((-limits.hip_abd.1, -limits.hip_abd.0)));
        let rot = joint("hip_rot", Vector3::y(), 0.0, on(limits.hip_rot));
        let knee = joint("knee", Vector3::z(), thigh, on((-limits.knee_flex.1, -limits.knee_flex.0)));
        let end: k::Node<f64> = k::NodeBuilder::new()
            .name("ankle")
            .joint_type(k::JointType::Fixed)
            .translation(Translation3::new(0.0, -shank, 0.0))
            .finalize()
            .into();
        k::connect![flex => abd => rot => knee => end];
        let chain = k::SerialChain::from_end(&end);
        let r = LegAngles::rest().to_array();
        let rest = vec![r[0], -r[1], r[2], -r[3]];
        chain.set_joint_positions_clamped(&rest);
        let solver = k::JacobianIkSolver::new(tolerance, 1.0, 0.5, 5000);
        let constraints =
            k::Constraints { rotation_x: false, rotation_y: false, rotation_z: false, ..k::Constraints::default() };
        KLeg { chain, end, solver, constraints, rest }
    }

    fn target(q: &IkQuestion) -> Isometry3<f64> {
        let t = q.target - q.hip;
        Isometry3::from_parts(Translation3::new(t.x, t.y, t.z), UnitQuaternion::identity())
    }

    fn error(&self, q: &IkQuestion) -> f64 {
        self.chain.update_transforms();
        let p = self.end.world_transform().unwrap().translation.vector;
        DVec3::new(p.x, p.y, p.z).distance(q.target - q.hip)
    }

    /// Solves `q` (warm unless `cold`); the final error (m).
    pub fn solve(&mut self, q: &IkQuestion, cold: bool) -> f64 {
        if cold {
            self.chain.set_joint_positions_clamped(&self.rest);
        }
        let _ = self.solver.solve_with_constraints(&self.chain, &Self::target(q), &self.constraints);
        self.error(q)
    }

    /// The same solve, counting its iterations (not timed): `k` reports none and restores the
    /// start on a miss, so this looks for the fewest tries that converge.
    pub fn count(&mut self, q: &IkQuestion, cold: bool, tolerance: f64) -> (u32, f64) {
        if cold {
            self.chain.set_joint_positions_clamped(&self.rest);
        }
        let start = self.chain.joint_positions();
        let target = Self::target(q);
        let tries = |n: usize| {
            self.chain.set_joint_positions_clamped(&start);
            let solver = k::JacobianIkSolver::new(tolerance, 1.0, 0.5, n);
            solver.solve_with_constraints(&self.chain, &target, &self.constraints).is_ok()
        };
        if !tries(5000) {
            return (5000, self.error(q));
        }
        let (mut lo, mut hi) = (0, 5000);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if tries(mid) { hi = mid } else { lo = mid }
        }
        tries(hi);
        (hi as u32, self.error(q))
    }
}
