//! The heel pad: the loaded heel's soft tissue lets the stance ankle sink a few millimetres
//! below where a rigid foot would hold it, while the foot's contact points stay on the ground.
//!
//! Why the walk needs it: through this leg chain people's hip closes on the ankle about 1 cm
//! per % of the cycle for the first 13 % of stance while the rigid heel rocker lowers the ankle
//! only 0.35 cm, so the rigid walk bent its knee all at once at heel strike and held it: its
//! loading-response knee peaked 3-4 % of the cycle early at every speed (18.1° at 9 % against
//! people's 16.5° at 13 % at 1.3 m/s; docs/gait-model.md §12, sessions 24-25). An unloaded
//! heel pad is about 16 mm thick (BMC Musculoskelet Disord 2022, doi:10.1186/
//! s12891-022-05197-w); Wearing et al. (Clin Biomech 2009, 24:397) measured its compression in
//! walking by fluoroscopy. [`PAD_M`] is the size measured to give people's loading knee (a
//! little over a third of that thickness).
//!
//! The compression follows the heel's share of the load: in with the body weight's transfer
//! onto the landing leg, held to the loading response's force peak, and let go through
//! mid-stance as the centre of pressure leaves the heel for the forefoot (sooner in fast
//! walks, [`FAST_RELEASE`]). Held until heel rise instead (session 24's prototype), the padded
//! leg stood 6 mm lower at mid-stance and the walked pelvis range fell 0.45-0.73 cm at every
//! speed; let go by mid-stance, the range is the rigid walk's.

use super::leg::{LegPhase, LegState};
use crate::model::params::Resolved;

/// The whole heel pad (m), reached in the loading response (`legs.heel_pad_mm` sets a walk's;
/// left out, `speed_laws::heel_pad_mm`).
pub(crate) const PAD_M: f64 = crate::model::speed_laws::HEEL_PAD_MM / 1000.0;

/// The share of the gait cycle over which the pad takes the landing's load (an ease-out, so
/// the ankle's descent at heel strike carries on into the pad).
const LOADING_END: f64 = 0.06;

/// The cycle phases between which the pad is let go as the load leaves the heel, up to
/// 1.3 m/s; from 1.6 m/s [`FAST_RELEASE`], between them the blend. Faster walks shorten their
/// stance and load the forefoot sooner: let go at (0.10, 0.30) the 1.6 / 1.75 m/s loading knee
/// peaked at 11 % (19.1 / 20.8 deg; people's 20.0 / 21.5 at 13 %), at (0.08, 0.25) at 13 / 12 %
/// (19.7 / 21.3 deg), the hip RMS 0.1 deg nearer people's; at 1.3 m/s (0.08, 0.25) peaked at 15 %
/// (17.2 deg; people's 16.5 at 13) and 1.0 m/s on a plateau at 17 %.
const RELEASE: (f64, f64) = (0.10, 0.30);

/// [`RELEASE`] from 1.6 m/s.
const FAST_RELEASE: (f64, f64) = (0.08, 0.25);

/// A stance's heel pad, frozen when its step is planned.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct HeelPad {
    /// The largest compression (m); 0 for a rigid foot.
    pub(crate) depth: f64,
    /// The cycle phases between which it is let go.
    pub(crate) release: (f64, f64),
}

/// The heel pad of a stance planned now at `speed_mps` in a walk resolved to `r`, if it is
/// one a pad is for (`padded`): on flat ground only (its walks alone take the slow rise out of
/// double support that goes with the pad, `gait_curves::Ground`; on stairs, slopes and rough
/// ground the rigid foot's walk is the one reviewed against the terrain checks), and not in a
/// stop's braking or closing step: the settle brings the pelvis to rest as high as the rigid
/// legs reach, and the closing stance stands there with its phase held in loading.
#[must_use]
pub(crate) fn for_stance(padded: bool, r: &Resolved, speed_mps: f64) -> HeelPad {
    if !padded {
        return HeelPad::default();
    }
    let t = ((speed_mps - 1.3) / 0.3).clamp(0.0, 1.0);
    let lerp = |a: f64, b: f64| a + t * (b - a);
    HeelPad { depth: r.heel_pad, release: (lerp(RELEASE.0, FAST_RELEASE.0), lerp(RELEASE.1, FAST_RELEASE.1)) }
}

/// The share of the slow rise out of double support (`gait_curves::PELVIS_RISE_KEYS`) that
/// comes with a walk's pad on flat ground: the pad's share of [`PAD_M`].
#[must_use]
pub(crate) fn rise_share(r: &Resolved) -> f64 {
    (r.heel_pad / PAD_M).clamp(0.0, 1.0)
}

/// How far (m) the pad `pad` is compressed `q` (cycle phase) into a stance whose heel rises at
/// `heel_rise` and whose toes leave at `toe_off`: 0 before heel strike, in swing and from the
/// end of its release on. A heel that rises before then takes the rest of the pad off with it
/// (the fast walks' heel rises at 0.27 of the cycle).
#[must_use]
pub(crate) fn compression_at(pad: HeelPad, q: f64, heel_rise: f64, toe_off: f64) -> f64 {
    let (from, to) = pad.release;
    if pad.depth <= 0.0 || q <= 0.0 || q >= to.min(toe_off) {
        return 0.0;
    }
    let x = (q / LOADING_END).min(1.0);
    let loading = 1.0 - (1.0 - x) * (1.0 - x);
    let held = 1.0 - smoothstep((q - from) / (to - from));
    let rising = 1.0 - smoothstep((q - heel_rise) / (toe_off - heel_rise));
    pad.depth * loading * held * rising
}

/// [`compression_at`] for a leg in its own state, `q` into its cycle.
#[must_use]
pub(crate) fn compression_of(leg: &LegState, q: f64) -> f64 {
    match leg.phase {
        LegPhase::Swing => 0.0,
        _ => compression_at(leg.pad, q, leg.heel_rise, leg.toe_off),
    }
}

fn smoothstep(u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pad_takes_the_load_holds_it_and_lets_it_go_by_mid_stance() {
        let pad = HeelPad { depth: PAD_M, release: RELEASE };
        let at = |q| compression_at(pad, q, 0.32, 0.62);
        assert_eq!(at(0.0), 0.0);
        assert!((at(0.03) - 0.75 * PAD_M).abs() < 1e-12, "{}", at(0.03));
        assert_eq!(at(LOADING_END), PAD_M);
        assert_eq!(at(0.10), PAD_M);
        assert!((at(0.20) - 0.5 * PAD_M).abs() < 1e-12, "{}", at(0.20));
        assert_eq!(at(0.30), 0.0);
        assert_eq!(at(0.5), 0.0);
        // Smooth: no step larger than a 60 fps frame's worth of a 1 s cycle allows.
        let most_step =
            (0..600).map(|i| (at(f64::from(i + 1) / 1000.0) - at(f64::from(i) / 1000.0)).abs()).fold(0.0, f64::max);
        assert!(most_step < 0.00025, "{most_step}");
        // No pad, none; an early heel rise lets it go sooner.
        assert_eq!(compression_at(HeelPad::default(), 0.08, 0.32, 0.62), 0.0);
        assert!(compression_at(pad, 0.15, 0.08, 0.2) < 0.5 * PAD_M);
    }
}
