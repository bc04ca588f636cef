//! One frame of the walk as numbers: the joint table's row (interface "Joint table") and the
//! extra state the checks need.

use crate::model::body::{Bone, Side};
use crate::model::walk::Walker;
use crate::model::walk::leg::LegPhase;
use glam::DVec3;

/// Which feet carry the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// Both feet on the ground.
    Double,
    /// Only the right foot.
    Right,
    /// Only the left foot.
    Left,
    /// Neither (never happens in a walk; kept so a bad state is visible, not hidden).
    Flight,
}

impl Support {
    /// As written in the joint table.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Support::Double => "double",
            Support::Right => "right",
            Support::Left => "left",
            Support::Flight => "flight",
        }
    }
}

/// Per-leg numbers of a frame (index 0 right, 1 left in [`Frame::legs`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegFrame {
    /// The leg's own cycle phase, 0 at its heel strike.
    pub phase: f64,
    /// Its phase of the four.
    pub leg_phase: LegPhase,
    /// Changes whenever the leg changes phase.
    pub phase_serial: u64,
    /// Hip flexion (deg, flexion +), thigh against the pelvis.
    pub hip_flex_deg: f64,
    /// Hip abduction (deg, away from the midline +).
    pub(crate) hip_abd_deg: f64,
    /// Knee flexion (deg).
    pub knee_flex_deg: f64,
    /// Ankle dorsiflexion (deg, plantarflexion −), foot against the shank.
    pub ankle_dorsi_deg: f64,
    /// Hip, knee, ankle joint positions (m).
    pub hip: DVec3,
    /// Knee joint.
    pub knee: DVec3,
    /// Ankle joint.
    pub ankle: DVec3,
    /// Heel contact point.
    pub heel: DVec3,
    /// Toe tip contact point.
    pub toe: DVec3,
    /// Unit knee swivel direction about the hip→ankle axis.
    pub knee_swivel: DVec3,
    /// Ground height under the heel and under the toe tip (m).
    pub ground_under_heel: f64,
    /// Ground under the toe tip.
    pub(crate) ground_under_toe: f64,
    /// Shoulder flexion (deg), upper arm against the chest.
    pub shoulder_flex_deg: f64,
    /// Elbow flexion (deg).
    pub(crate) elbow_flex_deg: f64,
    /// Whether this frame's leg IK reached its target.
    pub reached: bool,
}

/// One frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Frame number.
    pub frame: u64,
    /// Time (s).
    pub time_s: f64,
    /// Which feet carry the body.
    pub support: Support,
    /// Pelvis (hip-joint centre), m.
    pub pelvis: DVec3,
    /// Pelvic tilt (deg, anterior +).
    pub pelvis_tilt_deg: f64,
    /// Pelvic obliquity (deg, right hip up +).
    pub pelvis_obliquity_deg: f64,
    /// Pelvic rotation (deg, right hip forward +).
    pub pelvis_rotation_deg: f64,
    /// Right, left.
    pub legs: [LegFrame; 2],
}

pub use crate::model::walk::pose::LegAngles;
use crate::model::walk::pose::{leg_angles, sagittal_and_frontal};

impl Walker {
    /// The current frame's numbers; `frame` is the caller's frame counter.
    #[must_use]
    pub fn frame(&self, frame: u64) -> Frame {
        let pose = self.pose();
        let pelvis = self.pelvis();
        // Clinical hip flexion and pelvic tilt are taken against the pelvis's anatomical frame,
        // tipped forward of the bone by the rest tilt: in the sagittal plane, a constant added
        // to both (a 3-D rotation of the frame would also mix obliquity into hip flexion). The
        // bone itself (the pose, BVH) does not move.
        let rest_tilt = self.resolved().rest_tilt;
        let legs = Side::BOTH.map(|side| {
            let leg = self.leg(side);
            let p = leg.pose;
            let mut angles = leg_angles(pelvis.rotation, &p, side.sign());
            angles.hip_flex_deg += rest_tilt.to_degrees();
            let chest = pose.rot(Bone::Chest);
            let upper_dir = pose.pos(Bone::forearm(side)) - pose.pos(Bone::upper_arm(side));
            let fore_dir = pose.pos(Bone::hand(side)) - pose.pos(Bone::forearm(side));
            let (shoulder, _) = sagittal_and_frontal(chest, upper_dir.normalize(), side.sign());
            let elbow = upper_dir.normalize().dot(fore_dir.normalize()).clamp(-1.0, 1.0).acos();
            let terrain = self.terrain();
            LegFrame {
                phase: (self.phase() - leg.cycle_start).rem_euclid(1.0),
                leg_phase: leg.phase,
                phase_serial: leg.phase_serial,
                hip_flex_deg: angles.hip_flex_deg,
                hip_abd_deg: angles.hip_abd_deg,
                knee_flex_deg: angles.knee_flex_deg,
                ankle_dorsi_deg: angles.ankle_dorsi_deg,
                hip: p.hip,
                knee: p.knee,
                ankle: p.ankle,
                heel: p.heel,
                toe: p.toe_tip,
                knee_swivel: p.swivel,
                ground_under_heel: terrain.height(p.heel.x),
                ground_under_toe: terrain.height(p.toe_tip.x),
                shoulder_flex_deg: shoulder.to_degrees(),
                elbow_flex_deg: elbow.to_degrees(),
                reached: p.reached,
            }
        });
        let support = match (legs[0].leg_phase.is_stance(), legs[1].leg_phase.is_stance()) {
            (true, true) => Support::Double,
            (true, false) => Support::Right,
            (false, true) => Support::Left,
            (false, false) => Support::Flight,
        };
        Frame {
            frame,
            time_s: self.time_s(),
            support,
            pelvis: pelvis.position,
            pelvis_tilt_deg: (pelvis.tilt + rest_tilt).to_degrees(),
            pelvis_obliquity_deg: pelvis.obliquity.to_degrees(),
            pelvis_rotation_deg: pelvis.rotation_angle.to_degrees(),
            legs,
        }
    }
}
