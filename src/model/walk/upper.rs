//! The upper body [6.3.4]: trunk counter-rotation, the frontal-plane trunk compensation,
//! an upright head, and arms swinging opposite to the legs.

use crate::model::body::{BodyDims, Bone, Pose, Side};
use crate::model::ik::solve_two_bone;
use crate::model::params::Resolved;
use crate::model::walk::pelvis::PelvisPose;
use glam::{DQuat, DVec3};

/// The arms' hanging pose, solved once by IK: the wrist straight under the shoulder with the
/// elbow at its least flexion, pointing back. Its upper-arm angle is the neutral the swing
/// curve adds to.
#[derive(Clone, Debug, PartialEq)]
pub struct ArmHang {
    /// Shoulder flexion of the hanging arm (rad; negative: the upper arm slants back).
    pub(crate) shoulder_flex: f64,
    /// Abduction of the hanging arm (rad).
    pub spread: f64,
}

impl ArmHang {
    /// Solves the hang for the body and settings.
    #[must_use]
    pub fn new(dims: &BodyDims, spread: f64, elbow_min_flex: f64) -> Self {
        let (u, f) = (dims.upper_arm, dims.forearm);
        // Shoulder-to-wrist distance for an elbow flexed by `elbow_min_flex`.
        let d = (u * u + f * f + 2.0 * u * f * elbow_min_flex.cos()).sqrt();
        let ik = solve_two_bone(DVec3::ZERO, DVec3::new(0.0, -d, 0.0), u, f, DVec3::NEG_X);
        let dir = ik.middle / u;
        ArmHang { shoulder_flex: dir.x.atan2(-dir.y), spread }
    }
}

/// Solves the frontal-plane trunk compensation [6.3.4]: the bend α of spine and chest that
/// puts the neck straight above the pelvis for a pelvic obliquity θ,
/// l1·sin θ + l2·sin(θ + α) + l3·sin(θ + 2α) = 0, by the Illinois variant of Regula Falsi.
#[must_use]
pub fn trunk_bend(lengths: [f64; 3], obliquity: f64) -> f64 {
    let [l1, l2, l3] = lengths;
    let f = |a: f64| l1 * obliquity.sin() + l2 * (obliquity + a).sin() + l3 * (obliquity + 2.0 * a).sin();
    if obliquity.abs() < 1e-12 {
        return 0.0;
    }
    // The small-angle solution, α ≈ −θ(l1 + l2 + l3)/(l2 + 2 l3), brackets the root tightly, so
    // Regula Falsi needs three or four steps; f(0) has θ's sign and f(−2θ) the opposite one
    // for any trunk whose top segment is not longer than the other two, the fallback bracket.
    let guess = -obliquity * (l1 + l2 + l3) / (l2 + 2.0 * l3);
    let (mut a, mut b) = (guess * 0.98, guess * 1.02);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa * fb > 0.0 {
        (a, b) = (0.0, -2.0 * obliquity);
        (fa, fb) = (f(a), f(b));
    }
    if fa * fb > 0.0 {
        return -obliquity; // degenerate trunk: lean the upper segments back by θ
    }
    let mut side = 0;
    for _ in 0..40 {
        let c = (a * fb - b * fa) / (fb - fa);
        let fc = f(c);
        if fc.abs() < 1e-13 {
            return c;
        }
        if fc * fb < 0.0 {
            a = b;
            fa = fb;
            side = 0;
        } else {
            fa *= if side == 1 { 0.5 } else { 1.0 };
            side = 1;
        }
        b = c;
        fb = fc;
        if (b - a).abs() < 1e-12 {
            break;
        }
    }
    b
}

/// World rotations of the upper body's bones for one frame.
#[derive(Clone, Debug, PartialEq)]
pub struct UpperBody {
    /// Spine, chest, neck, head.
    pub trunk: [DQuat; 4],
    /// Shoulder girdle (clavicle), right then left.
    pub(crate) girdle: [DQuat; 2],
    /// Upper arms.
    pub(crate) upper_arm: [DQuat; 2],
    /// Forearms (hands follow them).
    pub(crate) forearm: [DQuat; 2],
    /// Trunk bend α of the frontal compensation (rad).
    pub(crate) trunk_bend: f64,
    /// Thorax rotation about the vertical (rad).
    pub(crate) thorax_rotation: f64,
    /// Shoulder flexion asked of each arm (rad).
    pub(crate) shoulder_flex: [f64; 2],
    /// Elbow flexion asked of each arm (rad).
    pub(crate) elbow_flex: [f64; 2],
}

impl Default for UpperBody {
    fn default() -> Self {
        UpperBody {
            trunk: [DQuat::IDENTITY; 4],
            girdle: [DQuat::IDENTITY; 2],
            upper_arm: [DQuat::IDENTITY; 2],
            forearm: [DQuat::IDENTITY; 2],
            trunk_bend: 0.0,
            thorax_rotation: 0.0,
            shoulder_flex: [0.0; 2],
            elbow_flex: [0.0; 2],
        }
    }
}

impl UpperBody {
    /// Solves the upper body for the pelvis and the arm curves' values (shoulder and elbow
    /// flexion, rad, per side).
    ///
    /// Horizontal plane: the thorax counter-rotates by `counter_rotation` × the pelvic
    /// rotation, the twist spread evenly over spine, chest and shoulder girdle; neck and head
    /// turn back so the head faces forward. Frontal plane: spine and chest bend by
    /// [`trunk_bend`]; neck and head stay upright. Sagittal: the lean is split over spine and
    /// chest, and neck and head look level. Arms swing in the walking direction about the
    /// hanging pose, abducted by the spread.
    #[must_use]
    pub fn solve(r: &Resolved, hang: &ArmHang, pelvis: &PelvisPose, shoulder: [f64; 2], elbow: [f64; 2]) -> Self {
        let alpha = trunk_bend(r.dims.trunk_segments(), pelvis.obliquity);
        Self::solve_bent(r, hang, pelvis, alpha, shoulder, elbow)
    }

    /// [`UpperBody::solve`] with the trunk bend `alpha` (rad, from [`trunk_bend`]) already
    /// solved: the walk times the spine's solve apart from the rest (thesis table 6.1).
    #[must_use]
    pub fn solve_bent(
        r: &Resolved,
        hang: &ArmHang,
        pelvis: &PelvisPose,
        alpha: f64,
        shoulder: [f64; 2],
        elbow: [f64; 2],
    ) -> Self {
        let theta = pelvis.obliquity;
        let yaw = pelvis.rotation_angle;
        let thorax = -r.counter_rotation * yaw;
        let twist = thorax - yaw;
        let lean = r.trunk_lean;
        let half_lean = DQuat::from_rotation_z(-0.5 * lean);
        let spine = DQuat::from_rotation_y(yaw + twist / 3.0) * DQuat::from_rotation_x(-(theta + alpha)) * half_lean;
        // Chest and shoulder girdle share their bend and lean; only their turn differs.
        let chest_tilt = DQuat::from_rotation_x(-(theta + 2.0 * alpha)) * DQuat::from_rotation_z(-lean);
        let chest = DQuat::from_rotation_y(yaw + 2.0 * twist / 3.0) * chest_tilt;
        let neck = DQuat::from_rotation_y(0.5 * thorax) * half_lean;
        let head = DQuat::IDENTITY;
        let girdle_rot = DQuat::from_rotation_y(thorax) * chest_tilt;
        let mut upper_arm = [DQuat::IDENTITY; 2];
        let mut forearm = [DQuat::IDENTITY; 2];
        for side in Side::BOTH {
            let i = side.index();
            let u = DQuat::from_rotation_x(-side.sign() * hang.spread)
                * DQuat::from_rotation_z(hang.shoulder_flex + shoulder[i]);
            upper_arm[i] = u;
            forearm[i] = u * DQuat::from_rotation_z(elbow[i]);
        }
        UpperBody {
            trunk: [spine, chest, neck, head],
            girdle: [girdle_rot; 2],
            upper_arm,
            forearm,
            trunk_bend: alpha,
            thorax_rotation: thorax,
            shoulder_flex: shoulder,
            elbow_flex: elbow,
        }
    }

    /// Writes the rotations into `pose` and places the joints by forward kinematics.
    pub fn apply(&self, dims: &BodyDims, pose: &mut Pose) {
        pose.place(dims, Bone::Spine, self.trunk[0]);
        pose.place(dims, Bone::Chest, self.trunk[1]);
        pose.place(dims, Bone::Neck, self.trunk[2]);
        pose.place(dims, Bone::Head, self.trunk[3]);
        for side in Side::BOTH {
            let i = side.index();
            pose.place(dims, Bone::shoulder(side), self.girdle[i]);
            pose.place(dims, Bone::upper_arm(side), self.upper_arm[i]);
            pose.place(dims, Bone::forearm(side), self.forearm[i]);
            pose.place(dims, Bone::hand(side), self.forearm[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trunk_bend_puts_the_neck_over_the_pelvis() {
        let l = [0.35, 0.35, 0.30];
        for theta in [-0.08, -0.02, 0.0, 0.03, 0.07] {
            let a = trunk_bend(l, theta);
            let offset = l[0] * theta.sin() + l[1] * (theta + a).sin() + l[2] * (theta + 2.0 * a).sin();
            assert!(offset.abs() < 1e-12, "θ={theta}: {offset}");
            if theta != 0.0 {
                assert!(a * theta < 0.0, "the trunk bends back against the pelvis");
            }
        }
    }

    #[test]
    fn hanging_arm_puts_the_wrist_under_the_shoulder() {
        let dims = BodyDims::from_height(1.75, crate::model::body::Sex::Male);
        let hang = ArmHang::new(&dims, 0.0, 0.3);
        assert!(hang.shoulder_flex < 0.0, "elbow behind: upper arm slants back");
        let elbow_dir = DVec3::new(hang.shoulder_flex.sin(), -hang.shoulder_flex.cos(), 0.0);
        let fore = DQuat::from_rotation_z(hang.shoulder_flex + 0.3) * DVec3::NEG_Y;
        let wrist = elbow_dir * dims.upper_arm + fore * dims.forearm;
        assert!(wrist.x.abs() < 1e-9, "{wrist}");
    }
}
