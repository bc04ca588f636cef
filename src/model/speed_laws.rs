//! The laws by which the walk's speed sets the derived parameters that are measured against
//! normal adults rather than taken from the thesis: the step (walk ratio) and where the
//! pelvis passes at mid-stance. [`crate::model::params::WalkParams::resolve`] applies them
//! where a config leaves the key out.

/// Walk ratio (step length over cadence) of normal adults, m/(steps/min) for a 1.75 m body,
/// scaled with height. Sekiya & Nagasaki 1998 found it nearly constant across speeds; the
/// value is the normative walk's own (data/normative/spatiotemporal_by_speed.csv: 0.0054 to
/// 0.0056 at all six treadmill speeds), taken as it is for the 1.75 m body, so that cadence
/// and stride sit on the norms at every speed and the joint curves are compared with a walk
/// of the norms' step. Sekiya's 0.0064 (men, overground) took 1.3 m/s to 110.5 steps/min and
/// a 1.41 m stride, 1.2 SD below the norms' cadence: the longer step held the pelvis low at
/// double support and flexed the loading knee 14 deg past the norm.
pub(crate) const WALK_RATIO_PER_175: f64 = 0.0055;

/// How far below standing hip height the pelvis passes at mid-stance (cm) at `speed_mps`, when
/// the config does not say: about as high as the stance leg reaches on to its heel rise.
/// Against the speed-matched norms (data/normative/joint_angles_by_speed.csv) people keep the
/// hip 0.858-0.859 m from the ankle (99.9 % of reach) from heel strike to 48 % of the cycle,
/// and every millimetre the walk's pelvis sits lower bends its knee: at 1.0 m/s a drop of 0,
/// 0.4 and 0.9 cm gives a knee RMS of 7.5, 8.2 and 10.0 deg. The reach guard's bound (below
/// which a smaller drop changes nothing) is 0 at 0.8 m/s, 0.1 at 1.0, 1.15 at 1.3 and 1.6 at
/// 1.6 with the pelvis 15 cm ahead of the heel; up to 1.3 m/s the law follows it. Above, the
/// mid-stance moves ahead with speed ([`midstance_offset_cm`]) and the bound falls: the drop
/// falls 2 cm per m/s, under the bound, and the guard sets the height (at 1.6 m/s, 16 cm
/// ahead, knee RMS 7.3 deg with a drop of 0 to 1.1 cm, 7.9 with 1.5; the earlier law's 1.85
/// cm rose with speed for a pelvis 15 cm ahead).
pub(crate) fn midstance_drop_cm(speed_mps: f64) -> f64 {
    let fast = speed_mps - 1.3;
    let drop = if fast < 0.0 { 1.1 + 3.5 * fast } else { 1.1 - 2.0 * fast };
    drop.max(0.0)
}

/// How far ahead of the stance heel the pelvis passes at mid-stance (cm) at `speed_mps`, when
/// the config does not say. A longer, faster step carries the pelvis further over the foot
/// before heel rise: held at 15 cm, the 1.6 m/s walk stood behind its foot in late stance,
/// hip, knee and ankle all flexed (knee 13-19 deg at 40-48 % of the cycle against the norms'
/// 3-6). At 1.6 m/s 15 / 16 / 17 / 18 / 19 cm give a knee RMS against the speed-matched
/// norms of 8.9 / 7.3 / 6.5 / 6.3 / 7.6 deg and an ankle r of 0.974 / 0.986 / 0.986 / 0.973 /
/// 0.955, but a walked pelvis vertical range of 3.82 / 3.21 / 2.63 cm for 15 / 16 / 17 (2.52
/// at 1.3 m/s; Orendurff et al. 2004's rises with speed): the law takes 16 cm at 1.6 m/s,
/// 3.3 cm per m/s above 1.3, where both the knee and the rising pelvis hold. At 0.8 m/s 13 /
/// 14 / 15 cm give knee 8.5 / 8.3 / 8.8 deg and ankle r 0.985 / 0.968 / 0.941: 5 cm nearer
/// per m/s below 1.0.
pub(crate) fn midstance_offset_cm(speed_mps: f64) -> f64 {
    15.0 + 3.3 * (speed_mps - 1.3).max(0.0) - 5.0 * (1.0 - speed_mps).max(0.0)
}

/// Where the pelvis passes its lowest point, as a share of the double support after heel
/// strike, at `speed_mps`: mid double support (the thesis's key) up to 1.3 m/s, 0.25 sooner
/// per m/s faster, down to 0.4 from 1.7 m/s. The norms' hip is lowest near heel strike and
/// already rising after it; in a fast walk the landing knee, held down by a pelvis still
/// falling to mid double support, flexed 10 deg more than theirs in loading response. Knee
/// RMS against the norms at 1.6 m/s for a share of 0.5 / 0.45 / 0.4 / 0.35: 7.3 / 6.3 / 5.7 /
/// 5.9 deg (brisk, 1.75 m/s: 7.3 / 6.3 / 5.7 / 5.5, its ankle RMS 4.1 at 0.35); at 1.3 m/s
/// 0.45 and 0.4 gain nothing (7.2, 7.4), and at 1.0 m/s and slower an earlier lowest point
/// bends the ankle's shape (r 0.967 -> 0.934 at 0.4). The pelvis then rises less above its
/// lowest point ([`heel_rise_phase`] gives that back): 0.33 sooner per m/s (0.4 at 1.6 m/s)
/// left 1.6 m/s's vertical range at 1.3 m/s's, 2.49 cm.
pub(crate) fn double_support_key_share(speed_mps: f64) -> f64 {
    (0.5 - 0.25 * (speed_mps - 1.3)).clamp(0.4, 0.5)
}

/// The cycle phase at which the stance heel rises at `speed_mps`: 0.31 up to 1.3 m/s, 0.1
/// sooner per m/s faster. With the lowest point of the pelvis nearer heel strike
/// ([`double_support_key_share`]) the fast walks' pelvis no longer fell below its heel-strike
/// height, and its vertical range stopped rising with speed (2.52 / 2.69 / 2.79 cm at 1.3 /
/// 1.6 / 1.75 m/s; Orendurff et al. 2004's rises 2.33 cm per m/s). A sooner heel rise lets the
/// stance leg carry the mid-stance pelvis higher: 3.32 cm at 1.6 m/s and 3.81 at 1.75, the
/// knee's RMS against the norms 6.4 deg at both (5.9 and 5.7 with the heel rising at 0.31,
/// 7.3 and 7.3 with neither law). At 1.3 m/s a sooner heel rise flexes the knee (0.28: RMS
/// 7.25 -> 8.26 deg).
pub(crate) fn heel_rise_phase(speed_mps: f64) -> f64 {
    0.31 - 0.1 * (speed_mps - 1.3).max(0.0)
}
