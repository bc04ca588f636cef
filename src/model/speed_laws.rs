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
/// cm rose with speed for a pelvis 15 cm ahead). Session 14's sooner heel rise from 1.0 m/s
/// ([`heel_rise_phase`]) moved the 1.3 m/s bound to between 0.8 and 1.1 cm: the law takes 0.8
/// there (drops of 0 to 0.8 walk the same; 1.1 took the walked vertical range 2.07 -> 2.00 cm).
pub(crate) fn midstance_drop_cm(speed_mps: f64) -> f64 {
    let fast = speed_mps - 1.3;
    let drop = if fast < 0.0 { 0.8 + 3.5 * fast } else { 0.8 - 2.0 * fast };
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
/// strike, at `speed_mps`: mid double support (the thesis's key) up to 1.0 m/s, 0.5 sooner
/// per m/s faster to 0.35 at 1.3 m/s, then back up to 0.375 from 1.4 m/s. The norms' hip is
/// lowest at heel strike and already rising after it (put through this leg chain,
/// data/normative/joint_angles_by_speed.csv's stance hip is 2.9 cm below standing at 4 % of
/// the cycle at 1.3 m/s, the walk's was 3.9): a pelvis still falling to mid double support
/// holds the landing knee down through loading response. The sooner lowest point pays only
/// with the double support as high as the legs reach ([`DERIVED_VERTICAL_RANGE_CM`]); below
/// it the asked range sets the height and the sooner key only moves the same low point.
/// Knee RMS against the speed-matched norms, double support at the reach guard, for a share
/// of 0.5 / 0.45 / 0.4 / 0.35 / 0.3: 1.3 m/s (heel rise at 0.31) 7.26 / 6.17 / 5.39 / 4.96 / 4.84 deg (ankle r
/// 0.991 / 0.988 / 0.978 / 0.960 / 0.934); 1.6 m/s (heel rise at 0.28) 8.21 / 6.96 / 5.87 /
/// 5.28 / 5.27; 1.0 m/s
/// 6.96 / 6.39 / 6.04 / 5.88 / 5.88 but the ankle's shape bends (r 0.967 / 0.949 / 0.922 /
/// 0.888 / 0.847): in a slow walk the trailing ankle plantarflexes from 40 % instead of at
/// 52 %. Above 1.3 m/s the scheduled 0.8 -> 1.6 -> 1.0 m/s walk's first full-speed steps
/// change the pelvis's velocity more sharply per frame than a steady walk the sooner the
/// fall from the mid-stance key ends (tests/pace.rs holds 1.2x): 0.35 / 0.375 / 0.4 give
/// 1.21x / 1.18x / 1.13x, the 1.6 m/s knee 5.40 / 5.70 / 6.15 deg with 82 / 82 / 78 % of its
/// cycle inside +-2 SD, brisk's 5.59 / 5.91 / 6.38.
pub(crate) fn double_support_key_share(speed_mps: f64) -> f64 {
    if speed_mps <= 1.3 {
        (0.5 - 0.5 * (speed_mps - 1.0)).clamp(0.35, 0.5)
    } else {
        (0.35 + 0.25 * (speed_mps - 1.3)).min(0.375)
    }
}

/// The vertical range a config that leaves `pelvis.vertical_range_cm` out asks for: none, so
/// the double support is asked at the mid-stance height and the reach guard lowers it until
/// both legs reach; the walked range is then what the legs' reach gives. The thesis's law
/// (1.9 + 1.5 (v − 0.7) cm, 2.8 at 1.3 m/s) asked the pelvis below where the legs reach at
/// every speed up to 1.3 m/s, and each centimetre it sat lower bent both knees at heel
/// strike: knee RMS against the speed-matched norms 8.33 -> 7.72 deg at 0.8 m/s and, with
/// [`double_support_key_share`]'s sooner lowest point, 7.25 -> 4.96 at 1.3 m/s. The price is
/// the walked range (summary's pelvis_vertical_range_cm: 0.83 -> 0.66 cm at 0.8 m/s, 2.52 ->
/// 2.07 at 1.3 with the heel rising sooner, 3.32 -> 3.17 at 1.6), below Orendurff et al.
/// 2004's 2.7-4.8 cm; the norms' own stance hip, put through this leg chain, rises 2.5 / 2.9
/// / 3.5 / 4.1 cm at 0.8 / 1.0 / 1.3 / 1.6 m/s, and the walk's mid-stance sits 0.5 cm under
/// theirs (docs/gait-model.md §12).
pub(crate) const DERIVED_VERTICAL_RANGE_CM: f64 = 0.0;

/// The cycle phase at which the stance heel rises at `speed_mps`: 0.31 up to 1.0 m/s, 0.1
/// sooner per m/s to 0.28 at 1.3 m/s, then 1/30 sooner per m/s (0.27 at 1.6, 0.265 at 1.75).
/// A sooner heel rise lets the stance leg carry the mid-stance pelvis higher, so the vertical
/// range rises with speed: with the double support at the legs' reach
/// ([`DERIVED_VERTICAL_RANGE_CM`]) the 1.3 m/s walk's range is 1.62 cm with the heel rising at
/// 0.31 and 2.07 at 0.28, its knee RMS against the norms 4.97 and 4.91 deg, its ankle RMS 2.52
/// and 2.13. At 1.0 m/s a sooner heel rise costs the knee its share inside +-2 SD (0.29: 78 %
/// against 84 %). (Before the double support rose to the legs' reach, 0.28 at 1.3 m/s had
/// flexed the knee: RMS 7.25 -> 8.26 deg.)
pub(crate) fn heel_rise_phase(speed_mps: f64) -> f64 {
    0.31 - 0.1 * (speed_mps - 1.0).clamp(0.0, 0.3) - (speed_mps - 1.3).max(0.0) / 30.0
}

/// How far ahead of the swing-forward design curve the swing heel moves at `speed_mps`
/// ([`crate::model::walk::leg::SwingPlan::progress`]): none from 1.3 m/s, 0.3 more per m/s
/// slower (0.15 at 0.8 m/s). The design curve is the normative walk's heel at about 1.3 m/s;
/// slower walkers reach the landing place sooner in the swing and straighten the knee before
/// heel strike (the norms' knee at 92 % of the cycle is 13° at 0.8 m/s, the walk's was 29°).
/// Knee / hip RMS against the speed-matched norms at 0.8 m/s for 0 / 0.15 / 0.23 / 0.3:
/// 7.71 / 6.84 / 6.68 / 6.67 and 3.71 / 4.12 / 4.58 / 5.15 deg (the hip flexes further as the
/// leg reaches ahead; 0.15 keeps their sum lowest); at 1.0 m/s 0.09 gives 6.40 / 3.44 (6.97 /
/// 3.27 without). At 1.3 m/s a sooner heel made the knee worse: the forward curve's keys 0.03
/// to 0.04 sooner (as a lead of 0.13 to 0.26 moves them) took it 4.91 -> 5.36 deg.
pub(crate) fn swing_lead(speed_mps: f64) -> f64 {
    (0.3 * (1.3 - speed_mps)).clamp(0.0, 0.3)
}

/// How far the pelvis rises toward the standing stance leg through single support at
/// `speed_mps` when `pelvis.stance_rise` is left out (`walk::stance_rise`): all the way up to
/// 0.8 m/s, none from 1.3 m/s, linear between. The norms' loading knee peaks at 8.3 / 11.3 /
/// 16.5 / 19.9° at 0.8 / 1.0 / 1.3 / 1.6 m/s: a slow walker passes over a nearly straight leg,
/// a fast one flexes it as a spring, which the keyed curve already gives. Against the
/// speed-matched norms with none / this law (session 17's designs): knee RMS 3.85 -> 2.45° at
/// 0.8 m/s (the loading peak 14.8° at 19 % -> 9.3° at 10 %), 4.04 -> 2.81° at 1.0 (18.2° at
/// 16 % -> 14.1° at 10 %), ankle 2.08 -> 1.51 and 2.19 -> 1.53°, hip 3.14 -> 3.06 and 2.68 ->
/// 2.51°; the walked pelvis vertical range 0.52 -> 0.92 cm and 1.05 -> 1.27 cm. The whole lift
/// at 1.3 and 1.6 m/s (`--set pelvis.stance_rise=1`) straightens the loading knee (15.2° at 7 %
/// and 18.5° at 8 % against the norms' 16.5 and 19.9° at 13 %) and takes the knee RMS 3.21 ->
/// 4.36 and 4.29 -> 6.31°.
pub(crate) fn stance_rise(speed_mps: f64) -> f64 {
    ((1.3 - speed_mps) / 0.5).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_laws_take_their_documented_values_and_meet_where_their_pieces_do() {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
        // Lowest point of the pelvis: mid double support when slow, soonest at 1.3 m/s.
        for (v, share) in [(0.8, 0.5), (1.0, 0.5), (1.15, 0.425), (1.3, 0.35), (1.6, 0.375), (2.0, 0.375)] {
            assert!(close(double_support_key_share(v), share), "{v}: {}", double_support_key_share(v));
        }
        assert!(close(double_support_key_share(1.3 - 1e-12), double_support_key_share(1.3 + 1e-12)));
        for (v, phase) in [(0.8, 0.31), (1.0, 0.31), (1.3, 0.28), (1.6, 0.27), (1.75, 0.265)] {
            assert!(close(heel_rise_phase(v), phase), "{v}: {}", heel_rise_phase(v));
        }
        for (v, drop) in [(0.9, 0.0), (1.3, 0.8), (1.6, 0.2), (1.75, 0.0)] {
            assert!(close(midstance_drop_cm(v), drop), "{v}: {}", midstance_drop_cm(v));
        }
        for (v, lead) in [(0.5, 0.24), (0.8, 0.15), (1.0, 0.09), (1.3, 0.0), (1.6, 0.0)] {
            assert!(close(swing_lead(v), lead), "{v}: {}", swing_lead(v));
        }
    }
}
