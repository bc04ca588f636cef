//! The model's curves and their default designs (spec §4's table).
//!
//! Each default is built from a few keys `(x, y, slope)` (see [`Curve::hermite`]) placed where
//! published normal-adult gait data puts the curve's extrema. Cycle curves run over the right
//! leg's cycle phase x ∈ [0, 1) starting at right heel strike; the left side reads them half a
//! cycle later. Amplitude curves are unit-peak (±1) shapes scaled by the matching range
//! parameter, so a curve override changes the shape and the parameter still sets the size.

use crate::model::curve::{Curve, CurveError};
use std::fmt;

/// A curve of the model, by name (`[curves.<name>]` in the config).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CurveName {
    /// Pelvic obliquity (list), unit shape over the cycle; +1 = right hip highest.
    PelvisObliquity,
    /// Pelvic rotation, unit shape over the cycle; +1 = right hip furthest forward.
    PelvisRotation,
    /// Pelvic tilt, unit shape over the cycle; +1 = most anterior.
    PelvisTilt,
    /// Vertical pelvis shape 0→1 from a mid-stance maximum down to the double-support minimum
    /// (before `pelvis_vertical_ds_ms` it shaped the rise too).
    PelvisVertical,
    /// Vertical pelvis shape 0→1 from the double-support minimum up to the mid-stance maximum.
    PelvisVerticalDsMs,
    /// Lateral pelvis displacement, unit shape over the cycle; +1 = furthest right.
    PelvisLateral,
    /// Forward pelvis progress 0→1 from mid double support to mid-stance.
    PelvisForwardDsMs,
    /// Forward pelvis progress 0→1 from mid-stance to mid double support.
    PelvisForwardMsDs,
    /// Foot-vs-ground angle (deg) over the heel-rise phase, for a 1.8 m stride.
    HeelRise,
    /// Swing heel progress 0→1 toward the footfall over the swing.
    SwingForward,
    /// Weight 0→1→0 pulling the swing heel from the step-width line to the hip line.
    SwingLateral,
    /// The ankle against the shank over the swing (deg, dorsiflexion +); each step moves its
    /// start to the ankle's toe-off angle.
    SwingAnkle,
    /// Heel height above the toe-off ground (m) over the swing, for a heel 0.20 m up at toe-off.
    SwingHeelHeight,
    /// Shoulder flexion, unit shape over the arm's side cycle; +1 = arm furthest forward.
    Shoulder,
    /// Elbow flexion, unit shape over the arm's side cycle; +1 = most flexed.
    Elbow,
}

impl CurveName {
    /// Every curve.
    pub const ALL: [CurveName; 15] = [
        CurveName::PelvisObliquity,
        CurveName::PelvisRotation,
        CurveName::PelvisTilt,
        CurveName::PelvisVertical,
        CurveName::PelvisVerticalDsMs,
        CurveName::PelvisLateral,
        CurveName::PelvisForwardDsMs,
        CurveName::PelvisForwardMsDs,
        CurveName::HeelRise,
        CurveName::SwingForward,
        CurveName::SwingLateral,
        CurveName::SwingAnkle,
        CurveName::SwingHeelHeight,
        CurveName::Shoulder,
        CurveName::Elbow,
    ];

    /// The config name.
    #[must_use]
    pub fn key(self) -> &'static str {
        use CurveName::*;
        match self {
            PelvisObliquity => "pelvis_obliquity",
            PelvisRotation => "pelvis_rotation",
            PelvisTilt => "pelvis_tilt",
            PelvisVertical => "pelvis_vertical",
            PelvisVerticalDsMs => "pelvis_vertical_ds_ms",
            PelvisLateral => "pelvis_lateral",
            PelvisForwardDsMs => "pelvis_forward_ds_ms",
            PelvisForwardMsDs => "pelvis_forward_ms_ds",
            HeelRise => "heel_rise",
            SwingForward => "swing_forward",
            SwingLateral => "swing_lateral",
            SwingAnkle => "swing_ankle",
            SwingHeelHeight => "swing_heel_height",
            Shoulder => "shoulder",
            Elbow => "elbow",
        }
    }

    /// The curve of a config name.
    #[must_use]
    pub(crate) fn from_key(key: &str) -> Option<CurveName> {
        CurveName::ALL.into_iter().find(|c| c.key() == key)
    }

    /// Whether the curve is a forward progress that may never go back: the pelvis and the
    /// swing heel move toward their next key or footfall, never away from it (a user's curve
    /// that dipped walked the heel backward in mid-swing, and `check` passed it).
    #[must_use]
    pub fn is_forward_progress(self) -> bool {
        matches!(self, CurveName::SwingForward | CurveName::PelvisForwardDsMs | CurveName::PelvisForwardMsDs)
    }

    /// Whether the curve repeats over the gait cycle (its ends must meet).
    #[must_use]
    pub fn is_cyclic(self) -> bool {
        use CurveName::*;
        matches!(self, PelvisObliquity | PelvisRotation | PelvisTilt | PelvisLateral | Shoulder | Elbow)
    }

    /// The default design; for the curves drawn at several speeds ([`DESIGN_SPEEDS_MPS`]),
    /// the comfortable walk's (1.3 m/s).
    #[must_use]
    pub fn default_curve(self) -> Curve {
        let keys: &[(f64, f64, f64)] = match self {
            CurveName::PelvisObliquity => &PELVIS_OBLIQUITY_KEYS,
            CurveName::PelvisRotation => &PELVIS_ROTATION_KEYS,
            // Two small waves a cycle, placed after the speed-matched norms
            // (data/normative/joint_angles_by_speed.csv): most posterior in mid-stance (0.24 /
            // 0.72), most anterior around the other leg's heel strike (0.47 / 0.97). Whittle's
            // notes [1], the thesis's, put them at 0.12 / 0.62 and 0.40 / 0.90: against the norms
            // the shape's r was 0.06 / 0.33 / 0.63 / 0.86 / 0.90 at 0.8 / 1.0 / 1.3 / 1.6 / 1.75
            // m/s, now 0.85 / 0.95 / 0.96 / 0.87 / 0.83 (people's troughs move from 28 % at 0.8
            // m/s to 18 % at 1.3: one shape between them). The hip, measured against the pelvis
            // as gait labs measure it, follows: RMS 2.50 / 2.68 / 1.88 / 2.30 / 2.89 -> 2.25 /
            // 2.19 / 1.64 / 2.24 / 2.84 deg, with `pelvis.tilt_range_deg` 3 -> 1.8 (session 20).
            CurveName::PelvisTilt => &[
                (0.0, 0.9397, -3.9796),
                (0.24, -1.0, 0.0),
                (0.47, 1.0, 0.0),
                (0.72, -1.0, 0.0),
                (0.97, 1.0, 0.0),
                (1.0, 0.9397, -3.9796),
            ],
            // Saunders, Inman & Eberhart 1953: a smooth sinusoid-like fall from the mid-stance
            // maximum to the double-support minimum, level at both ends; drawn at three speeds
            // ([`PELVIS_VERTICAL_KEYS`]).
            CurveName::PelvisVertical => &PELVIS_VERTICAL_KEYS[1],
            CurveName::PelvisVerticalDsMs => &PELVIS_RISE_KEYS,
            // Orendurff et al. 2004: one sway a cycle over the stance foot, furthest right at
            // right mid-stance (0.31), crossing the midline at mid double support (0.06 / 0.56).
            // Keys sample sin(2π(x − 0.06)) with its slopes.
            CurveName::PelvisLateral => &[
                (0.0, -0.368, 5.86),
                (0.06, 0.0, std::f64::consts::TAU),
                (0.31, 1.0, 0.0),
                (0.56, 0.0, -std::f64::consts::TAU),
                (0.81, -1.0, 0.0),
                (1.0, -0.368, 5.86),
            ],
            // Forward speed of the centre of mass is ±10–12 % about its mean, fastest in double
            // support and slowest at mid-stance (Orendurff 2004; Chung & Hahn's velocity curves):
            // the half-step curves start and end with slopes 1.12 and 0.88 of the mean.
            CurveName::PelvisForwardDsMs => &[(0.0, 0.0, 1.12), (1.0, 1.0, 0.88)],
            CurveName::PelvisForwardMsDs => &[(0.0, 0.0, 0.88), (1.0, 1.0, 1.12)],
            // Thesis fig 6.5's shape (slow lift first, faster later), first drawn from the
            // foot–floor angle of the normative walk (data/normative/, through this leg chain: 4°
            // at 40 %, 14° at opposite heel strike, 58° at toe-off, for a 1.25 m stride), for a
            // 1.8 m stride, scaled by stride/1.8; its keys are now fitted at three speeds
            // ([`HEEL_RISE_KEYS`], [`DESIGN_SPEEDS_MPS`]).
            CurveName::HeelRise => &HEEL_RISE_KEYS[1],
            // Thesis fig 6.6's shape, first drawn from the heel's forward progress in the
            // normative walk (data/normative/ through this leg chain): a quarter of the way at a
            // third of the swing, fastest at 0.6, easing onto the footfall; its keys are now
            // fitted at three speeds ([`SWING_FORWARD_KEYS`]).
            CurveName::SwingForward => &SWING_FORWARD_KEYS[1],
            // Thesis fig 6.7: step-width line at both ends, hip line at mid-swing.
            CurveName::SwingLateral => &[(0.0, 0.0, 0.0), (0.5, 1.0, 0.0), (1.0, 0.0, 0.0)],
            // Thesis fig 6.8: the ankle against the shank (dorsiflexion +), after the normative
            // walk (data/normative/): push-off plantarflexion peaks after toe-off (−13.6° at 65 %),
            // neutral by mid-swing, a few degrees up for the landing. Each step moves the start
            // to the ankle's actual toe-off angle.
            CurveName::SwingAnkle => {
                &[(0.0, -9.0, -60.0), (0.08, -13.6, 0.0), (0.34, -1.2, 45.0), (0.6, 5.7, 0.0), (1.0, 1.5, 0.0)]
            }
            CurveName::SwingHeelHeight => &SWING_HEEL_HEIGHT_KEYS[1],
            // Ceccato et al. 2009: the arm swings opposite to its leg, furthest back at its own
            // heel strike and furthest forward at the opposite one (widest at double support).
            CurveName::Shoulder => &[(0.0, -1.0, 0.0), (0.5, 1.0, 0.0), (1.0, -1.0, 0.0)],
            // Ceccato et al. 2009: the elbow flexes most shortly after the arm is furthest
            // forward (x ≈ 0.55) and is straightest as the arm swings back (x ≈ 0.05).
            CurveName::Elbow => &[(0.0, -0.95, -0.6), (0.05, -1.0, 0.0), (0.55, 1.0, 0.0), (1.0, -0.95, -0.6)],
        };
        Curve::hermite(self.key(), keys).expect("default curves are valid by construction")
    }
}

/// Pelvic rotation's unit shape: the speed-matched norms' own at 1.3 m/s
/// (data/normative/joint_angles_by_speed.csv, the 1.30 m/s block's mean curve made
/// antisymmetric and scaled to a unit peak), five keys a half cycle with their Bézier handles
/// held inside the unit range the curve editor allows: RMS 0.012 of the peak, the curve
/// peaking at 0.96. The right hip is furthest forward at 3 % of the cycle, just after heel
/// strike, and turns forward a second, smaller time at 20-25 %. The thesis's design (Perry &
/// Burnfield: furthest forward at heel strike, one cosine) read r 0.68 against the norms at
/// 1.3 m/s; this one 0.997 there, 0.94 at 1.0 and 0.65 at 0.8 m/s, where people's hip is
/// furthest forward at mid-stance (one design for every speed: the norms' slow and fast shapes
/// drawn as speed designs made the 0.8 -> 1.6 -> 1.0 m/s schedule turn the hip 1.37x as sharply
/// as the steady walks, docs/gait-model.md §12, session 19).
const PELVIS_ROTATION_KEYS: [(f64, f64, f64); 11] = [
    (0.0, 0.8894, 4.1962),
    (0.079, 0.8216, -6.7707),
    (0.156, 0.5882, 3.9489),
    (0.257, 0.7669, -4.2774),
    (0.389, -0.0549, -5.6022),
    (0.5, -0.8894, -4.1962),
    (0.579, -0.8216, 6.7707),
    (0.656, -0.5882, -3.9489),
    (0.757, -0.7669, 4.2774),
    (0.889, 0.0549, 5.6022),
    (1.0, 0.8894, 4.1962),
];

/// Pelvic obliquity's unit shape: the speed-matched norms' own (data/normative/
/// joint_angles_by_speed.csv, the 0.80-1.80 m/s blocks' mean curves each scaled to a unit peak,
/// averaged and made antisymmetric). The stance-side hip is highest at 15 % (loading response,
/// as the opposite side drops after its toe-off), back to level by 35-40 % and slightly low by
/// the opposite heel strike; the keys' RMS from that shape is 0.017 of the peak (0.1° at
/// 1.3 m/s). The earlier design (after Lin et al. 2014) held the stance hip up through single
/// support and dropped it inside the opposite double support: r 0.73 against the norms, 63 % of
/// the cycle outside their 1 SD band. The range by speed is `speed_laws::obliquity_range_deg`.
const PELVIS_OBLIQUITY_KEYS: [(f64, f64, f64); 7] = [
    (0.0, 0.22, 0.0),
    (0.15, 1.0, 0.0),
    (0.40, -0.06, 0.0),
    (0.5, -0.22, 0.0),
    (0.65, -1.0, 0.0),
    (0.90, 0.06, 0.0),
    (1.0, 0.22, 0.0),
];

/// The rise out of double support is quicker than the fall into it: level at both ends, but
/// 0.4 of the way up at 0.35 of the segment (the symmetric shape is at 0.28). The landing
/// leg's knee flexes in loading response as the hip passes over the ankle lower than the leg
/// reaches; rising sooner keeps it nearer the norms' 16 deg peak (knee RMS against the norms
/// at 1.3 m/s 7.57 -> 7.25 deg, ankle 2.87 -> 2.69). The price is the pelvis's upward
/// acceleration out of double support: 3.6 m/s² at the default against 2.25 m/s² with the
/// symmetric shape; 0.4 of the way by 0.3 (knee 7.05 deg) asked 4.8 m/s². Its slope there
/// refitted with the swing designs at 1.3 m/s (1.45 -> 1.336, see [`SWING_FORWARD_KEYS`]).
/// Drawn at each speed too (0.50 of the way at 0.8 m/s, 0.32 at 1.6), it gained 0.1 deg of
/// knee at 0.8 m/s and took the scheduled 0.8 -> 1.6 -> 1.0 m/s walk's pelvis velocity
/// change to 1.23x the steady walks' (the issue-14 bound is 1.2x): one design.
/// The fall from mid-stance into double support at each of [`DESIGN_SPEEDS_MPS`]. The
/// comfortable and fast walks keep the thesis's smooth fall (the keys are the smoothstep's own:
/// halfway at half the segment, slope 1.5). The slow walk holds its height longer and falls
/// late and steeply, as people's pelvis does at 0.8 m/s (data/normative/pelvis_vertical_by_
/// speed.csv's adults: highest at 28-36 % of the cycle, lowest at 4 %, 2.5 cm apart); fitted in
/// session 20 with the slow swing and heel-rise designs and the 0.8 m/s knots, the walked
/// range held at 2.0 cm (docs/gait-model.md §12). With the smooth fall the slow walk's pelvis
/// passed its highest point at 20 % and fell through late stance, and no placement of it
/// moved its range past 1.2 cm without flexing the knee 5-8° off the norms (knee RMS 3.5 at
/// 1.21 cm, 6.1 at 2.08).
/// The slow heel rise of sessions 17-19, kept for stairs with `speed_laws::STAIRS` (see there).
const HEEL_RISE_SLOW_ON_STAIRS: [(f64, f64, f64); 5] =
    [(0.0, 0.0, 10.0), (0.42, 7.21, 38.12), (0.68, 30.55, 112.97), (0.87, 50.8, 168.11), (1.0, 82.19, 235.78)];

const PELVIS_VERTICAL_KEYS: [[(f64, f64, f64); 3]; 3] = [
    [(0.0, 0.0, 0.0), (0.5, 0.4704, 2.81), (1.0, 1.0, 0.0)],
    [(0.0, 0.0, 0.0), (0.5, 0.5, 1.5), (1.0, 1.0, 0.0)],
    [(0.0, 0.0, 0.0), (0.5, 0.5, 1.5), (1.0, 1.0, 0.0)],
];

/// Session 25, with the heel pad ([`crate::model::walk`]'s `heel_pad`): the rise starts
/// slowly instead, 0.443 of the way up at half the segment, so that the landing leg's hip
/// closes on its sinking ankle through the loading response as people's does, the knee
/// flexing to its peak at 13 % of the cycle rather than at once (1.3 m/s: knee RMS 3.90 ->
/// 2.91 deg with the pad, its loading peak 18.1 deg at 9 % -> 16.0 at 13 %; people 16.5 at
/// 13). With the quick rise the pad alone took the peak to 12.2 deg at 9 %; the slow rise
/// without the pad, to 21.3 deg at 12 % (docs/gait-model.md §12).
const PELVIS_RISE_KEYS: [(f64, f64, f64); 3] = [(0.0, 0.0, 0.0), (0.5, 0.443, 1.511), (1.0, 1.0, 0.0)];

/// The quick rise of sessions 14-24 (above), kept where the heel pad is off: on stairs, slopes
/// and rough ground (their walks were reviewed with it) and in slow walks
/// (`speed_laws::heel_pad_share`).
const PELVIS_QUICK_RISE_KEYS: [(f64, f64, f64); 3] = [(0.0, 0.0, 0.0), (0.35, 0.402, 1.336), (1.0, 1.0, 0.0)];

/// The rise out of double support for a heel pad's `share` of the whole: the quick rise where
/// the pad is off, the slow one where it is whole, and between them the blend. To blend, each
/// design gets the other's inner knot at its own value and slope there (a cubic split at a
/// knot is the same cubic), so the blend is the one curve with four keys.
fn pelvis_rise_for(share: f64) -> Curve {
    let (quick, slow) = (PELVIS_QUICK_RISE_KEYS, PELVIS_RISE_KEYS);
    let keys: Vec<(f64, f64, f64)> = if share <= 0.0 {
        quick.to_vec()
    } else if share >= 1.0 {
        slow.to_vec()
    } else {
        let quick = [quick[0], quick[1], hermite_key(quick[1], quick[2], slow[1].0), quick[2]];
        let slow = [slow[0], hermite_key(slow[0], slow[1], quick[1].0), slow[1], slow[2]];
        quick.iter().zip(slow).map(|(a, b)| (a.0, a.1 + share * (b.1 - a.1), a.2 + share * (b.2 - a.2))).collect()
    };
    Curve::hermite(CurveName::PelvisVerticalDsMs.key(), &keys)
        .expect("blends of valid designs with the same knots are valid")
}

/// Thesis fig 6.10's shape, first drawn from the normative walk's heel (data/normative/
/// through this leg chain): 20 cm up at toe-off, its peak of 26 cm at 0.16 of the swing, down
/// to 2 cm by three quarters and skimming the ground onto the footfall. The key at 0.88 was
/// placed on that curve (its value and slope there) because the swing simulation lifts a
/// heel by moving the knots around the sample that asks, and with the last knots at 0.75 and
/// 1.0 a toe clearance asked at 0.6-0.75 held the heel up to the footfall and the knee bent
/// into heel strike. With it,
/// knee RMS against the norms 9.07 / 7.50 / 7.82 / 10.16 -> 8.88 / 7.15 / 7.57 / 10.01 deg at
/// 0.8 / 1.0 / 1.3 / 1.6 m/s (docs/gait-model.md §12 has the denser variants that broke a stop
/// on slope_up). Fitted at each of [`DESIGN_SPEEDS_MPS`] (see [`SWING_FORWARD_KEYS`]): the
/// heel nearly level at 1.4-2.1 cm from 0.75 to 0.88 of the swing, then down onto the footfall.
///
/// The comfortable design's peak and mid-swing keys (and its forward partner's key at 0.316)
/// were refitted in session 26 for issue 12's swing knee, which peaked at 62.9° at 75 % of the
/// cycle (normal adults: 55-65° at 70-74 %; the norms' 63.0° at 74 %): the heel 2.3 cm higher
/// at 0.16 of the swing flexes the knee sooner (4 keys, Nelder-Mead, 200 walks at 1.3 m/s on the
/// mean hip / knee / ankle RMS with the peak's timing, read between the 1 % samples, held
/// under 73.6 %), together with the swing simulation's lower dorsiflexion cap (5°, `walk::
/// swing_sim`). The default walk's knee now peaks at 61.0° at 73.6 % and its swing ankle at
/// 4.7°, for knee RMS 2.91 -> 3.07 and hip 1.43 -> 1.51 deg (docs/gait-model.md §12).
const SWING_HEEL_HEIGHT_KEYS: [[(f64, f64, f64); 6]; 3] = [
    [
        (0.0, 0.20, 0.7),
        (0.16, 0.257, 0.0),
        (0.47, 0.1397, -0.6),
        (0.75, 0.0235, -0.1),
        (0.88, 0.0184, -0.082),
        (1.0, 0.0, -0.1),
    ],
    [
        (0.0, 0.20, 0.7),
        (0.16, 0.2797, 0.0),
        (0.47, 0.1824, -0.3239),
        (0.75, 0.0209, -0.1),
        (0.88, 0.0176, -0.082),
        (1.0, 0.0, -0.1),
    ],
    [
        (0.0, 0.20, 0.7),
        (0.16, 0.257, 0.0),
        (0.47, 0.1545, -0.6),
        (0.75, 0.016, -0.1),
        (0.88, 0.0174, -0.082),
        (1.0, 0.0, -0.1),
    ],
];

/// Thesis fig 6.5's shape at each of [`DESIGN_SPEEDS_MPS`] (see [`SWING_FORWARD_KEYS`]): the
/// slow walk's heel rises less late in the phase (44° against 54° at 0.87), the comfortable
/// one's less early (4.7° against 9.5° at 0.42, where the stance leg's reach lifts it anyway).
/// The fast one ends at 73° for a 1.8 m stride, not 83°: refitted (session 16) with the
/// push-off inside normal adults' 12-20° as a bound, since at 83° the foot left the ground 5°
/// steeper than the norms' and the ankle plantarflexed to −23.6° at 1.6 m/s (−25.6 at 1.75).
/// The slow one was refitted in session 17 (see [`SWING_FORWARD_KEYS`]); it now ends turning
/// faster (226° per unit of the phase against 197° at 0.87), as a foot still rolling at
/// toe-off does. The comfortable and fast ones were refitted in session 18 (see
/// [`SWING_FORWARD_KEYS`]): both now rise less by 0.68 of the phase (18.4° and 22.4° against
/// 28.7° and 26.7°), the trailing foot flatter at the double support, where people's ankle is
/// still dorsiflexed, and end 79° and 75°.
const HEEL_RISE_KEYS: [[(f64, f64, f64); 5]; 3] = [
    [
        (0.0, 0.0, 10.0),
        (0.42, 1.4135, 0.0947),
        (0.68, 15.0145, 110.5724),
        (0.87, 36.7207, 168.11),
        (1.0, 82.19, 235.78),
    ],
    [(0.0, 0.0, 10.0), (0.42, 4.58, 30.35), (0.68, 22.66, 126.32), (0.87, 47.32, 144.64), (1.0, 79.71, 346.51)],
    [(0.0, 0.0, 10.0), (0.42, 5.04, 35.86), (0.68, 21.84, 156.01), (0.87, 49.36, 257.43), (1.0, 77.65, 175.17)],
];

/// Thesis fig 6.6's shape at each of [`DESIGN_SPEEDS_MPS`]. The values of this curve, the
/// heel-height and heel-rise curves (and the pelvis's rise out of double support) were fitted
/// together at each speed (Nelder-Mead over the 14 key values and slopes, 400 walks, on `gaitlab compare`'s knee RMS + half the hip's
/// and the ankle's, r held at 0.97 / 0.97 / 0.955) from the earlier single design; the knots'
/// phases were kept. Knee RMS against the speed-matched norms, earlier design -> these:
/// 6.14 -> 4.15 at 0.8 m/s, 4.42 -> 3.23 at 1.3, 5.26 -> 3.51 at 1.6 (docs/gait-model.md §12).
/// The heel reaches 0.95 of the way by 0.84 of the swing at every speed (0.91 before): the
/// leg straightens before heel strike, as people's does. The fast design (with its heel-height
/// and heel-rise partners) was refitted in session 16 at 1.6 and 1.75 m/s together, 0.6 / 0.4
/// of the cost, the push-off held at or above −19° (docs/gait-model.md §12): knee RMS 3.44 ->
/// 4.29 and 4.01 -> 4.83 deg, ankle 2.75 -> 1.74 and 3.58 -> 2.22, hip 2.48 -> 3.08 and 3.04 ->
/// 3.54 — the price of a push-off people make. The slow design (with its partners) was
/// refitted in session 17 once the slow walk's pelvis rose over the stance leg
/// (`walk::stance_rise`), at 0.8 and 1.0 m/s together (the 1.0 m/s walk blends it 0.6 / 0.4
/// with the comfortable one), 1 600 walks, the same cost plus the swing knee's and the
/// push-off's peak timing beyond 1 % of the norms': knee RMS 3.38 -> 2.70 at 0.8 m/s and 3.22
/// -> 2.81 at 1.0, hip 3.19 -> 3.24 and 2.54 -> 2.55, ankle 1.63 -> 1.68 and 1.62 -> 1.58; the
/// swing knee peaks at 76-77 % of the cycle either way (the norms' 74-75 %). The comfortable
/// and fast designs were refitted in session 18 with the speed laws that place the pelvis over
/// the foot (`speed_laws::midstance_offset_cm` and its partners), the walk's pelvis vertical
/// range held at people's measured one less about half an SD (3.0 cm at 1.3 m/s, 3.5 at 1.6;
/// 1.9 and 2.9 before), the loading knee's peak within 2° of the norms', and each
/// segment's Bézier polygon monotone (a heel rise that stalled and then spurted into toe-off
/// set a walk's first step from standing moving the hip 1.22x as fast as the steady walk's;
/// `tests/start.rs` holds 1.2x). Hip / knee / ankle RMS against the speed-matched norms,
/// before -> after: 2.05 / 3.21 / 2.03 -> 2.43 / 3.78 / 1.73 at 1.3 m/s, 3.08 / 4.29 / 1.74 ->
/// 1.91 / 3.92 / 1.67 at 1.6, 3.54 / 4.83 / 2.22 -> 2.08 / 4.41 / 2.30 at 1.75, with the fast
/// walk's heel rise at 0.275 of the cycle (`speed_laws::heel_rise_phase`; docs/gait-model.md
/// §12, session 18).
const SWING_FORWARD_KEYS: [[(f64, f64, f64); 5]; 3] = [
    [(0.0, 0.0, 0.5), (0.316, 0.1824, 0.98), (0.632, 0.5785, 1.2631), (0.842, 0.9606, 0.503), (1.0, 1.0, 0.0238)],
    [(0.0, 0.0, 0.5), (0.316, 0.2215, 0.98), (0.632, 0.5997, 1.8539), (0.842, 0.9344, 0.9745), (1.0, 1.0, 0.265)],
    [(0.0, 0.0, 0.5), (0.316, 0.2641, 0.98), (0.632, 0.6217, 1.909), (0.842, 0.9331, 0.9431), (1.0, 1.0, 0.304)],
];

/// The walking speeds (m/s) of the three designs of the swing's forward and heel-height curves, the
/// heel rise and the pelvis's fall into double support: slow, comfortable and fast. Between two the
/// keys are blended linearly by speed (a Hermite curve is linear in its keys' values and slopes, so
/// the curve is the same blend of the two); outside, the end design. Why three: each was fitted to
/// the speed-matched norms at its speed (docs/gait-model.md §12, session 15), and the slow walk's
/// and the fast walk's differ in opposite directions from the comfortable one's.
pub const DESIGN_SPEEDS_MPS: [f64; 3] = [0.8, 1.3, 1.6];

/// The key (x, y, dy/dx) at `x` of the cubic Hermite segment between keys `a` and `b`: the
/// segment as the curve the keys build (`Curve::hermite`, its handles at the thirds, so x is
/// linear in the Bézier parameter and read exactly), evaluated there.
fn hermite_key(a: (f64, f64, f64), b: (f64, f64, f64), x: f64) -> (f64, f64, f64) {
    let segment = Curve::hermite("segment", &[a, b]).expect("two keys with rising x are a valid curve");
    (x, segment.eval(x), segment.slope(x))
}

/// The ground a walk's designs are chosen for: some are drawn for stairs, and the slow rise
/// out of double support comes with the heel pad, which flat ground alone has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ground {
    /// `terrain.kind = "flat"`.
    Flat,
    /// `terrain.kind = "stairs"`.
    Stairs,
    /// Slopes and rough ground.
    Uneven,
}

impl CurveName {
    /// The default design at walking speed `speed_mps`: [`CurveName::default_curve`] blended
    /// between the designs at [`DESIGN_SPEEDS_MPS`] for the curves drawn at several speeds.
    #[must_use]
    pub fn default_curve_at(self, speed_mps: f64) -> Curve {
        self.default_curve_for(speed_mps, Ground::Flat)
    }

    /// [`CurveName::default_curve_at`] for a walk on `ground`: on stairs the slow designs of the
    /// heel rise and the fall into double support are session 19's (`HEEL_RISE_SLOW_ON_STAIRS`,
    /// the smoothstep), with `speed_laws::STAIRS`; off flat ground the rise out of double
    /// support is the quick one of sessions 14-24 (`PELVIS_QUICK_RISE_KEYS`): the heel pad is
    /// off there.
    #[must_use]
    pub fn default_curve_for(self, speed_mps: f64, ground: Ground) -> Curve {
        let mut designs: [&[(f64, f64, f64)]; 3] = match self {
            CurveName::SwingForward => SWING_FORWARD_KEYS.each_ref().map(|k| k.as_slice()),
            CurveName::SwingHeelHeight => SWING_HEEL_HEIGHT_KEYS.each_ref().map(|k| k.as_slice()),
            CurveName::HeelRise => HEEL_RISE_KEYS.each_ref().map(|k| k.as_slice()),
            CurveName::PelvisVertical => PELVIS_VERTICAL_KEYS.each_ref().map(|k| k.as_slice()),
            CurveName::PelvisVerticalDsMs => {
                let pad_share =
                    if ground == Ground::Flat { crate::model::speed_laws::heel_pad_share(speed_mps) } else { 0.0 };
                return pelvis_rise_for(pad_share);
            }
            _ => return self.default_curve(),
        };
        if ground == Ground::Stairs {
            match self {
                CurveName::HeelRise => designs[0] = &HEEL_RISE_SLOW_ON_STAIRS,
                CurveName::PelvisVertical => designs[0] = &PELVIS_VERTICAL_KEYS[1],
                _ => {}
            }
        }
        let [slow, comfortable, fast] = DESIGN_SPEEDS_MPS;
        // NaN (never from a valid config) walks the comfortable design.
        let speed_mps = if speed_mps.is_nan() { comfortable } else { speed_mps };
        let (from, to, t) = if speed_mps < comfortable {
            (designs[0], designs[1], (speed_mps - slow) / (comfortable - slow))
        } else {
            (designs[1], designs[2], (speed_mps - comfortable) / (fast - comfortable))
        };
        let t = t.clamp(0.0, 1.0);
        let keys: Vec<(f64, f64, f64)> =
            from.iter().zip(to).map(|(a, b)| (a.0, a.1 + t * (b.1 - a.1), a.2 + t * (b.2 - a.2))).collect();
        Curve::hermite(self.key(), &keys).expect("blends of valid designs with the same knots are valid")
    }
}

impl fmt::Display for CurveName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// The design curves of one walk, defaults or overrides.
#[derive(Clone, Debug)]
pub struct CurveSet {
    curves: Vec<Curve>,
}

impl CurveSet {
    /// Defaults at walking speed `speed_mps` on `ground` ([`CurveName::default_curve_for`]),
    /// the rise out of double support for a heel pad's `pad_share` of the whole (on flat
    /// ground; none elsewhere), with the given overrides (control points by curve name); an
    /// override holds at every speed and on any ground.
    pub(crate) fn with_overrides<'a>(
        overrides: impl IntoIterator<Item = (&'a String, &'a Vec<(f64, f64)>)>,
        speed_mps: f64,
        ground: Ground,
        pad_share: f64,
    ) -> Result<Self, CurveError> {
        let mut curves: Vec<Curve> = CurveName::ALL.iter().map(|c| c.default_curve_for(speed_mps, ground)).collect();
        if ground == Ground::Flat {
            curves[CurveName::PelvisVerticalDsMs as usize] = pelvis_rise_for(pad_share);
        }
        for (name, points) in overrides {
            if let Some(c) = CurveName::from_key(name) {
                curves[c as usize] = Curve::from_pairs(name.clone(), points)?;
            }
        }
        Ok(CurveSet { curves })
    }

    /// The design curve `name`.
    #[must_use]
    pub fn get(&self, name: CurveName) -> &Curve {
        &self.curves[name as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::curve::G1_TOLERANCE;

    #[test]
    fn defaults_are_valid_smooth_and_cyclic_where_they_should_be() {
        for c in CurveName::ALL {
            let curve = c.default_curve();
            assert!(curve.joins_are_g1(G1_TOLERANCE), "{c}");
            assert_eq!(curve.x_start(), 0.0, "{c}");
            assert_eq!(curve.x_end(), 1.0, "{c}");
            if c.is_cyclic() {
                assert!((curve.eval(0.0) - curve.eval(1.0)).abs() < 1e-9, "{c}");
                assert!((curve.slope(0.0) - curve.slope(1.0)).abs() < 1e-6, "{c}");
            }
        }
    }

    #[test]
    fn extrema_sit_where_the_docs_say() {
        let argmax = |c: CurveName| {
            let curve = c.default_curve();
            (0..=1000).map(|i| i as f64 / 1000.0).max_by(|a, b| curve.eval(*a).total_cmp(&curve.eval(*b))).unwrap()
        };
        assert!((argmax(CurveName::PelvisObliquity) - 0.15).abs() < 0.01);
        // People's pelvis at 1.3 m/s turns the right hip furthest forward at 3-4 % of the cycle.
        let rotation_peak = argmax(CurveName::PelvisRotation);
        assert!((0.02..=0.05).contains(&rotation_peak), "{rotation_peak}");
        assert!((argmax(CurveName::PelvisLateral) - 0.31).abs() < 0.01);
        assert!((argmax(CurveName::Shoulder) - 0.5).abs() < 0.01);
        assert!((argmax(CurveName::SwingHeelHeight) - 0.16).abs() < 0.02);
        let heel_rise = CurveName::HeelRise.default_curve();
        assert!((heel_rise.eval(1.0) - 79.71).abs() < 1e-9);
        // The ankle's push-off peaks just after toe-off, its dorsiflexion mid-swing.
        let ankle = CurveName::SwingAnkle.default_curve();
        let argmin = (0..=1000).map(|i| i as f64 / 1000.0).min_by(|a, b| ankle.eval(*a).total_cmp(&ankle.eval(*b)));
        assert!((argmin.unwrap() - 0.08).abs() < 0.01);
        assert!((argmax(CurveName::SwingAnkle) - 0.6).abs() < 0.02);
        // Monotone where progress is meant.
        for c in [
            CurveName::PelvisForwardDsMs,
            CurveName::PelvisForwardMsDs,
            CurveName::SwingForward,
            CurveName::PelvisVertical,
            CurveName::PelvisVerticalDsMs,
            CurveName::HeelRise,
        ] {
            let curve = c.default_curve();
            let ys: Vec<f64> = (0..=200).map(|i| curve.eval(i as f64 / 200.0)).collect();
            assert!(ys.windows(2).all(|w| w[1] >= w[0] - 1e-12), "{c}");
        }
    }
}

#[cfg(test)]
mod speed_design_tests {
    use super::*;

    #[test]
    fn the_rise_blend_is_each_design_at_its_ends_and_between_them_in_between() {
        // The four-key blend at a share a hair from 0 and from 1 is, within the share, the
        // quick and the slow designs themselves: the inserted knots keep each cubic exact.
        let (quick, slow) = (pelvis_rise_for(0.0), pelvis_rise_for(1.0));
        let (near_quick, near_slow, half) = (pelvis_rise_for(1e-9), pelvis_rise_for(1.0 - 1e-9), pelvis_rise_for(0.5));
        for i in 0..=100 {
            let x = f64::from(i) / 100.0;
            assert!((near_quick.eval(x) - quick.eval(x)).abs() < 1e-8, "{x}");
            assert!((near_slow.eval(x) - slow.eval(x)).abs() < 1e-8, "{x}");
            let mid = 0.5 * (quick.eval(x) + slow.eval(x));
            assert!((half.eval(x) - mid).abs() < 1e-9, "{x}: {} against {mid}", half.eval(x));
        }
        // The slow design starts slower: a fifth of the way in it has risen less.
        assert!(slow.eval(0.2) < quick.eval(0.2) - 0.05, "{} {}", slow.eval(0.2), quick.eval(0.2));
    }

    #[test]
    fn each_speeds_design_is_the_blend_of_its_neighbours_and_holds_its_shape() {
        let at = |c: CurveName, v: f64, x: f64| c.default_curve_at(v).eval(x);
        for c in [CurveName::SwingForward, CurveName::SwingHeelHeight, CurveName::HeelRise] {
            for x in [0.1, 0.42, 0.7, 0.9] {
                // The comfortable design is the default; beyond the ends, the end designs.
                assert_eq!(at(c, 1.3, x), c.default_curve().eval(x), "{c}");
                assert_eq!(at(c, 0.5, x), at(c, 0.8, x), "{c}");
                assert_eq!(at(c, 2.2, x), at(c, 1.6, x), "{c}");
                assert_eq!(at(c, f64::NAN, x), at(c, 1.3, x), "{c}");
                // Between two designs: the same blend of the curves as of their keys.
                let mid = 0.5 * (at(c, 0.8, x) + at(c, 1.3, x));
                assert!((at(c, 1.05, x) - mid).abs() < 1e-12, "{c} at {x}");
                let fast = (at(c, 1.3, x) + 2.0 * at(c, 1.6, x)) / 3.0;
                assert!((at(c, 1.5, x) - fast).abs() < 1e-12, "{c} at {x}");
            }
            for v in [0.8, 1.0, 1.3, 1.45, 1.6] {
                let curve = c.default_curve_at(v);
                assert!(curve.joins_are_g1(crate::model::curve::G1_TOLERANCE), "{c} at {v}");
                let ys: Vec<f64> = (0..=400).map(|i| curve.eval(f64::from(i) / 400.0)).collect();
                if c != CurveName::SwingHeelHeight {
                    // Progress curves never run back.
                    assert!(ys.windows(2).all(|w| w[1] >= w[0] - 1e-12), "{c} at {v}");
                } else {
                    // The swing heel stays off the ground until the footfall.
                    assert!(ys[..400].iter().all(|h| *h > 0.0) && ys[400] == 0.0, "{c} at {v}");
                }
            }
        }
        // An override holds at every speed; a curve drawn once is the same at every speed.
        let mine = vec![(0.0, 0.0), (0.3, 0.2), (0.7, 0.9), (1.0, 1.0)];
        let overrides = [("swing_forward".to_string(), mine)];
        for v in [0.8, 1.6] {
            let set = CurveSet::with_overrides(
                overrides.iter().map(|(k, p)| (k, p)),
                v,
                Ground::Flat,
                crate::model::speed_laws::heel_pad_share(v),
            )
            .unwrap();
            assert_eq!(
                set.get(CurveName::SwingForward).eval(0.5),
                CurveSet::with_overrides(overrides.iter().map(|(k, p)| (k, p)), 1.3, Ground::Flat, 1.0)
                    .unwrap()
                    .get(CurveName::SwingForward)
                    .eval(0.5)
            );
            assert_eq!(set.get(CurveName::SwingAnkle).eval(0.5), CurveName::SwingAnkle.default_curve().eval(0.5));
        }
    }
}
