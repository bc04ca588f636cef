//! The body: a skeleton tree with anthropometric segment lengths (spec §2).
//!
//! Lengths are proportions of standing height H after Drillis & Contini as tabulated in
//! Winter, *Biomechanics and Motor Control of Human Movement* (4th ed., fig. 4.1). The rest
//! pose stands upright facing +x with every bone frame aligned with the world (x forward,
//! y up, z right), so a bone's local rotation is identity at rest.

use glam::{DQuat, DVec3};

/// Body sex, which sets the pelvis and shoulder widths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sex {
    /// Wider pelvis, narrower shoulders.
    Female,
    /// Narrower pelvis, wider shoulders.
    Male,
}

/// Which side of the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// Right (+z).
    Right,
    /// Left (−z).
    Left,
}

impl Side {
    /// Both sides, right first (the order of every per-side array).
    pub const BOTH: [Side; 2] = [Side::Right, Side::Left];

    /// +1 for right (+z), −1 for left.
    #[must_use]
    pub(crate) fn sign(self) -> f64 {
        match self {
            Side::Right => 1.0,
            Side::Left => -1.0,
        }
    }

    /// 0 for right, 1 for left.
    #[must_use]
    pub fn index(self) -> usize {
        match self {
            Side::Right => 0,
            Side::Left => 1,
        }
    }

    /// The other side.
    #[must_use]
    pub fn other(self) -> Side {
        match self {
            Side::Right => Side::Left,
            Side::Left => Side::Right,
        }
    }

    /// `"r"` or `"l"`, as in the joint table's column names.
    #[must_use]
    pub(crate) fn suffix(self) -> &'static str {
        match self {
            Side::Right => "r",
            Side::Left => "l",
        }
    }
}

/// Every bone of the skeleton, parents before children.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Bone {
    Pelvis,
    Spine,
    Chest,
    Neck,
    Head,
    ShoulderR,
    UpperArmR,
    ForearmR,
    HandR,
    ShoulderL,
    UpperArmL,
    ForearmL,
    HandL,
    ThighR,
    ShinR,
    FootR,
    ToeR,
    ThighL,
    ShinL,
    FootL,
    ToeL,
}

/// Number of bones.
pub(crate) const BONE_COUNT: usize = 21;

impl Bone {
    /// All bones, parents before children.
    pub const ALL: [Bone; BONE_COUNT] = [
        Bone::Pelvis,
        Bone::Spine,
        Bone::Chest,
        Bone::Neck,
        Bone::Head,
        Bone::ShoulderR,
        Bone::UpperArmR,
        Bone::ForearmR,
        Bone::HandR,
        Bone::ShoulderL,
        Bone::UpperArmL,
        Bone::ForearmL,
        Bone::HandL,
        Bone::ThighR,
        Bone::ShinR,
        Bone::FootR,
        Bone::ToeR,
        Bone::ThighL,
        Bone::ShinL,
        Bone::FootL,
        Bone::ToeL,
    ];

    /// Position in [`Bone::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The parent bone (`None` for the root).
    #[must_use]
    pub fn parent(self) -> Option<Bone> {
        use Bone::*;
        Some(match self {
            Pelvis => return None,
            Spine => Pelvis,
            Chest => Spine,
            Neck => Chest,
            Head => Neck,
            ShoulderR | ShoulderL => Chest,
            UpperArmR => ShoulderR,
            UpperArmL => ShoulderL,
            ForearmR => UpperArmR,
            ForearmL => UpperArmL,
            HandR => ForearmR,
            HandL => ForearmL,
            ThighR | ThighL => Pelvis,
            ShinR => ThighR,
            ShinL => ThighL,
            FootR => ShinR,
            FootL => ShinL,
            ToeR => FootR,
            ToeL => FootL,
        })
    }

    /// Lower-case name, as used in BVH and plots (`thigh_r`).
    #[must_use]
    pub fn name(self) -> &'static str {
        use Bone::*;
        match self {
            Pelvis => "pelvis",
            Spine => "spine",
            Chest => "chest",
            Neck => "neck",
            Head => "head",
            ShoulderR => "shoulder_r",
            UpperArmR => "upper_arm_r",
            ForearmR => "forearm_r",
            HandR => "hand_r",
            ShoulderL => "shoulder_l",
            UpperArmL => "upper_arm_l",
            ForearmL => "forearm_l",
            HandL => "hand_l",
            ThighR => "thigh_r",
            ShinR => "shin_r",
            FootR => "foot_r",
            ToeR => "toe_r",
            ThighL => "thigh_l",
            ShinL => "shin_l",
            FootL => "foot_l",
            ToeL => "toe_l",
        }
    }

    /// The per-side bone of a limb.
    #[must_use]
    pub fn thigh(side: Side) -> Bone {
        if side == Side::Right { Bone::ThighR } else { Bone::ThighL }
    }
    /// The shin of `side`.
    #[must_use]
    pub(crate) fn shin(side: Side) -> Bone {
        if side == Side::Right { Bone::ShinR } else { Bone::ShinL }
    }
    /// The foot of `side`.
    #[must_use]
    pub fn foot(side: Side) -> Bone {
        if side == Side::Right { Bone::FootR } else { Bone::FootL }
    }
    /// The toes of `side`.
    #[must_use]
    pub fn toe(side: Side) -> Bone {
        if side == Side::Right { Bone::ToeR } else { Bone::ToeL }
    }
    /// The shoulder girdle (clavicle) of `side`.
    #[must_use]
    pub(crate) fn shoulder(side: Side) -> Bone {
        if side == Side::Right { Bone::ShoulderR } else { Bone::ShoulderL }
    }
    /// The upper arm of `side`.
    #[must_use]
    pub(crate) fn upper_arm(side: Side) -> Bone {
        if side == Side::Right { Bone::UpperArmR } else { Bone::UpperArmL }
    }
    /// The forearm of `side`.
    #[must_use]
    pub(crate) fn forearm(side: Side) -> Bone {
        if side == Side::Right { Bone::ForearmR } else { Bone::ForearmL }
    }
    /// The hand of `side`.
    #[must_use]
    pub fn hand(side: Side) -> Bone {
        if side == Side::Right { Bone::HandR } else { Bone::HandL }
    }
}

/// Segment lengths and widths (m). Every field can be overridden in the config's `[body]`.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyDims {
    /// Standing height H.
    pub height: f64,
    /// Hip joint centre to knee joint centre.
    pub thigh: f64,
    /// Knee joint centre to ankle joint centre.
    pub shank: f64,
    /// Ankle joint centre above the sole.
    pub(crate) ankle_height: f64,
    /// Heel to toe tip.
    pub foot_length: f64,
    /// Shoulder joint to elbow.
    pub(crate) upper_arm: f64,
    /// Elbow to wrist.
    pub(crate) forearm: f64,
    /// Wrist to finger tip.
    pub hand: f64,
    /// Between the two hip joint centres.
    pub(crate) hip_width: f64,
    /// Between the two shoulder joint centres.
    pub(crate) shoulder_width: f64,
    /// Hip-joint centre level to shoulder-joint level.
    pub trunk: f64,
    /// Shoulder level to the top of the head.
    pub(crate) head_neck: f64,
}

/// Where the toe joint sits along the foot, as a fraction of foot length from the heel (the
/// metatarsal heads; Winter's foot markers put them at about three quarters).
pub(crate) const BALL_FRACTION: f64 = 0.75;

/// How far the heel's contact point sits behind the ankle joint, as a fraction of foot
/// length. The ankle joint is not over the heel: anatomically the malleoli stand about a fifth
/// of the foot ahead of the heel's back. 0.15 is what the normative joint angles ask of this
/// leg chain: put through it (forward kinematics, a test in `src/normative.rs`), they set the leading
/// heel and the trailing ball on the ground at heel strike 1.03 cm apart in height, where
/// a heel under the ankle leaves them 3.4 cm apart.
pub(crate) const HEEL_FRACTION: f64 = 0.15;

impl BodyDims {
    /// Lengths from height and sex with Drillis & Contini's proportions. The widths are
    /// joint-centre distances, not skin widths: hip joints 0.098 H apart for male and 0.108 H
    /// for female bodies (pelvic breadth 0.191 H less the femoral heads); shoulder joints
    /// 0.220 H (male) and 0.200 H (female) apart (biacromial 0.259 H / 0.236 H less the
    /// humeral heads).
    #[must_use]
    pub(crate) fn from_height(height: f64, sex: Sex) -> Self {
        let (hip_width, shoulder_width) = match sex {
            Sex::Male => (0.098, 0.220),
            Sex::Female => (0.108, 0.200),
        };
        BodyDims {
            height,
            thigh: 0.245 * height,
            shank: 0.246 * height,
            ankle_height: 0.039 * height,
            foot_length: 0.152 * height,
            upper_arm: 0.186 * height,
            forearm: 0.146 * height,
            hand: 0.108 * height,
            hip_width: hip_width * height,
            shoulder_width: shoulder_width * height,
            trunk: (0.818 - 0.530) * height,
            head_neck: (1.0 - 0.818) * height,
        }
    }

    /// Hip-joint height when standing: thigh + shank + ankle height.
    #[must_use]
    pub(crate) fn standing_hip_height(&self) -> f64 {
        self.thigh + self.shank + self.ankle_height
    }

    /// Full leg reach from hip to ankle.
    #[must_use]
    pub(crate) fn leg_reach(&self) -> f64 {
        self.thigh + self.shank
    }

    /// Heel contact point in the foot's frame (origin at the ankle joint): on the sole, behind
    /// the ankle by [`HEEL_FRACTION`] of the foot [6.3.2, fig 6.4].
    #[must_use]
    pub(crate) fn heel_local(&self) -> DVec3 {
        DVec3::new(-HEEL_FRACTION * self.foot_length, -self.ankle_height, 0.0)
    }

    /// Toe joint (ball of the foot) in the foot's frame, on the sole, [`BALL_FRACTION`] of the
    /// foot ahead of the heel.
    #[must_use]
    pub(crate) fn ball_local(&self) -> DVec3 {
        DVec3::new((BALL_FRACTION - HEEL_FRACTION) * self.foot_length, -self.ankle_height, 0.0)
    }

    /// Length of the toe segment, ball to toe tip.
    #[must_use]
    pub(crate) fn toe_length(&self) -> f64 {
        (1.0 - BALL_FRACTION) * self.foot_length
    }

    /// The three trunk segments pelvis→spine, spine→chest, chest→neck (l1, l2, l3 of the
    /// frontal-plane compensation [6.3.4]): 35 %, 35 % and 30 % of the trunk.
    #[must_use]
    pub(crate) fn trunk_segments(&self) -> [f64; 3] {
        [0.35 * self.trunk, 0.35 * self.trunk, 0.30 * self.trunk]
    }

    /// Offset of each bone's joint from its parent's joint in the rest pose (the skeleton's
    /// local translations; BVH OFFSETs).
    #[must_use]
    pub(crate) fn rest_offset(&self, bone: Bone) -> DVec3 {
        use Bone::*;
        let [l1, l2, l3] = self.trunk_segments();
        let hip = 0.5 * self.hip_width;
        let clavicle = 0.05 * self.height;
        let shoulder = 0.5 * self.shoulder_width;
        match bone {
            Pelvis => DVec3::new(0.0, self.standing_hip_height(), 0.0),
            Spine => DVec3::new(0.0, l1, 0.0),
            Chest => DVec3::new(0.0, l2, 0.0),
            Neck => DVec3::new(0.0, l3, 0.0),
            Head => DVec3::new(0.0, 0.35 * self.head_neck, 0.0),
            ShoulderR => DVec3::new(0.0, l3 - 0.01 * self.height, clavicle * 0.5),
            ShoulderL => DVec3::new(0.0, l3 - 0.01 * self.height, -clavicle * 0.5),
            UpperArmR => DVec3::new(0.0, 0.01 * self.height, shoulder - clavicle * 0.5),
            UpperArmL => DVec3::new(0.0, 0.01 * self.height, -(shoulder - clavicle * 0.5)),
            ForearmR | ForearmL => DVec3::new(0.0, -self.upper_arm, 0.0),
            HandR | HandL => DVec3::new(0.0, -self.forearm, 0.0),
            ThighR => DVec3::new(0.0, 0.0, hip),
            ThighL => DVec3::new(0.0, 0.0, -hip),
            ShinR | ShinL => DVec3::new(0.0, -self.thigh, 0.0),
            FootR | FootL => DVec3::new(0.0, -self.shank, 0.0),
            ToeR | ToeL => self.ball_local(),
        }
    }

    /// Where a bone ends in its own frame (for drawing leaf bones: head top, hand tip, toe tip).
    #[must_use]
    pub(crate) fn end_offset(&self, bone: Bone) -> DVec3 {
        match bone {
            Bone::Head => DVec3::new(0.0, 0.65 * self.head_neck, 0.0),
            Bone::HandR | Bone::HandL => DVec3::new(0.0, -self.hand, 0.0),
            Bone::ToeR | Bone::ToeL => DVec3::new(self.toe_length(), 0.0, 0.0),
            other => {
                // The end of a non-leaf bone is its first child's joint.
                Bone::ALL
                    .iter()
                    .find(|b| b.parent() == Some(other))
                    .map(|&child| self.rest_offset(child))
                    .unwrap_or(DVec3::ZERO)
            }
        }
    }
}

/// A posed skeleton: every bone's world rotation and joint position.
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// World rotation of each bone, indexed by [`Bone::index`].
    pub rotation: [DQuat; BONE_COUNT],
    /// World position of each bone's joint (its origin), indexed by [`Bone::index`].
    pub position: [DVec3; BONE_COUNT],
}

impl Pose {
    /// The standing rest pose.
    #[must_use]
    pub fn rest(dims: &BodyDims) -> Self {
        let mut pose = Pose { rotation: [DQuat::IDENTITY; BONE_COUNT], position: [DVec3::ZERO; BONE_COUNT] };
        for bone in Bone::ALL {
            pose.position[bone.index()] = match bone.parent() {
                None => dims.rest_offset(bone),
                Some(p) => pose.position[p.index()] + dims.rest_offset(bone),
            };
        }
        pose
    }

    /// World rotation of `bone`.
    #[must_use]
    pub fn rot(&self, bone: Bone) -> DQuat {
        self.rotation[bone.index()]
    }

    /// World position of `bone`'s joint.
    #[must_use]
    pub fn pos(&self, bone: Bone) -> DVec3 {
        self.position[bone.index()]
    }

    /// Rotation of `bone` relative to its parent (BVH channels).
    #[must_use]
    pub(crate) fn local_rotation(&self, bone: Bone) -> DQuat {
        match bone.parent() {
            None => self.rot(bone),
            Some(p) => self.rot(p).inverse() * self.rot(bone),
        }
    }

    /// Sets `bone`'s world rotation and places its joint from its parent by forward
    /// kinematics: parent position + parent rotation × rest offset.
    pub fn place(&mut self, dims: &BodyDims, bone: Bone, world_rotation: DQuat) {
        let parent = bone.parent().expect("place() is for child bones");
        self.position[bone.index()] = self.pos(parent) + self.rot(parent) * dims.rest_offset(bone);
        self.rotation[bone.index()] = world_rotation;
    }

    /// World position of a point given in `bone`'s frame.
    #[must_use]
    pub fn point(&self, bone: Bone, local: DVec3) -> DVec3 {
        self.pos(bone) + self.rot(bone) * local
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn proportions_add_up() {
        let d = BodyDims::from_height(1.75, Sex::Male);
        assert!((d.standing_hip_height() - 0.530 * 1.75).abs() < 1e-12);
        let rest = Pose::rest(&d);
        let shoulder = rest.pos(Bone::UpperArmR);
        assert!((shoulder.y - 0.818 * 1.75).abs() < 1e-9, "{shoulder}");
        let head_top = rest.point(Bone::Head, d.end_offset(Bone::Head));
        assert!((head_top.y - 1.75).abs() < 1e-9, "{head_top}");
        let heel = rest.point(Bone::FootR, d.heel_local());
        assert!(heel.y.abs() < 1e-12);
        let f = BodyDims::from_height(1.75, Sex::Female);
        assert!(f.hip_width > d.hip_width && f.shoulder_width < d.shoulder_width);
    }

    #[test]
    fn local_rotation_round_trips() {
        let d = BodyDims::from_height(1.6, Sex::Female);
        let mut pose = Pose::rest(&d);
        pose.rotation[Bone::Pelvis.index()] = DQuat::from_rotation_y(0.2);
        pose.place(&d, Bone::ThighR, DQuat::from_rotation_z(0.4));
        let local = pose.local_rotation(Bone::ThighR);
        let back = pose.rot(Bone::Pelvis) * local;
        assert!(back.angle_between(pose.rot(Bone::ThighR)) < 1e-12);
    }
}
