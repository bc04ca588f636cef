//! The pelvis trajectory [6.3.3]: forward and vertical position between key instants, and
//! the three rotations and the lateral sway from cycle curves.
//!
//! Key instants alternate: mid double support (DS, the vertical minimum, fastest forward)
//! and mid-stance (MS, the vertical maximum, slowest forward). Between two keys the forward
//! position follows the DS→MS or MS→DS curve scaled to the distance between the keys, and
//! the height follows the vertical shape between the keys' heights. Keys are placed in
//! *cycle phase* (master phase, in cycles), not seconds, so a cadence change mid-walk
//! stretches time without moving any planned key.

use crate::model::curve::Curve;
use glam::{DQuat, DVec3};
use std::collections::VecDeque;

/// Which instant a key marks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyKind {
    /// Mid double support: the choice the optimisation makes.
    DoubleSupport,
    /// Mid-stance: fixed relative to the stance foot.
    MidStance,
}

/// A planned pelvis position at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PelvisKey {
    /// Master cycle phase of the instant (cycles since the walk began).
    pub phase: f64,
    /// Forward position of the pelvis (hip-joint centre), m.
    pub x: f64,
    /// Height of the pelvis, m.
    pub y: f64,
    /// DS or MS.
    pub kind: KeyKind,
    /// Forward pace the pelvis passes the key with, times the design curve's slope there
    /// (m per cycle): its step's average, mid-stance to mid-stance; the walk's nominal stride
    /// for the first key.
    pub pace: f64,
}

/// The planned keys, oldest first.
#[derive(Clone, Debug, Default)]
pub struct PelvisPlan {
    keys: VecDeque<PelvisKey>,
    /// The walk's end, once planned: from its start the pelvis leaves the keys and comes to
    /// rest over the feet.
    settle: Option<Settle>,
    /// A start from standing, once asked: until its end the pelvis sets off on it instead of
    /// the keys.
    launch: Option<Launch>,
}

/// How the pelvis sets off from standing (see `docs/gait-model.md`, §13).
///
/// Forward, a quintic Hermite from rest at `from_phase` (no speed, no acceleration) to the
/// first double-support key, which it meets with the keyed path's own position, speed and
/// acceleration, so that the start has no jump in velocity nor in acceleration (a cubic, as the
/// settle uses, would leave the latter: a joint jerk at the hand-over). Its span is chosen
/// so the end speed times the span is twice the distance: the quintic's speed then rises
/// without ever turning back (up to 2.5 times it does not; beyond, the pelvis would first move
/// backward; the end acceleration's term, small beside these, is not counted). The height
/// follows the keys, the first of which is the standing height at the moment the start was
/// asked; the sway, the rotations and the arm swing fade in by a smoothstep over the span,
/// and a weight shift over the stance foot comes and goes on its own ramps
/// ([`Launch::with_weight_shift`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launch {
    /// When the pelvis moves on it: from the phase it starts to move at, to the first double
    /// support.
    pub window: PhaseWindow,
    /// Forward position at rest (m).
    pub x0: f64,
    /// Forward position at its end: the double-support key's (m).
    pub x1: f64,
    /// Forward speed at its end times the span (m).
    pub m1: f64,
    /// Forward acceleration at its end times the span squared (m).
    pub a1: f64,
    /// The weight shift onto the stance foot before the first step: sideways by `z` (m),
    /// from the first phase to the peak one (the initiating foot's toe-off), back to the
    /// walk's own sway by the last (see [`Launch::with_weight_shift`]).
    pub shift: (f64, [f64; 3]),
}

impl Launch {
    /// Ratio of the end speed times the span to the distance the launch covers.
    pub const SPEED_TO_DISTANCE: f64 = 2.0;

    /// A launch from rest at `x0` to `x1`, reached at `end_phase` with speed `v1` (m per
    /// cycle) and acceleration `a1` (m per cycle²).
    #[must_use]
    pub fn new(end_phase: f64, x0: f64, (x1, v1, a1): (f64, f64, f64)) -> Self {
        let distance = (x1 - x0).max(0.02);
        let span = Self::span_for(distance, v1);
        Launch {
            window: PhaseWindow { from_phase: end_phase - span, span },
            x0,
            x1: x0 + distance,
            m1: v1 * span,
            a1: a1 * span * span,
            shift: (0.0, [end_phase; 3]),
        }
    }

    /// The launch with a weight shift: before the first foot leaves the ground the body moves
    /// over the other (measured initiation: the centre of mass moves toward the stance foot
    /// during the anticipatory postural adjustment, pushed there by the centre of pressure
    /// moving toward the swing foot). Sideways by `z` (m) on a smootherstep from `from` to
    /// `peak`, back on one by `end`, added to the sway that fades in with the launch.
    #[must_use]
    pub fn with_weight_shift(self, z: f64, [from, peak, end]: [f64; 3]) -> Self {
        Launch { shift: (z, [from, peak.max(from + 1e-6), end.max(peak + 1e-6)]), ..self }
    }

    /// The weight shift's sideways offset at `phase` (m).
    #[must_use]
    pub fn weight_shift(&self, phase: f64) -> f64 {
        let (z, [from, peak, end]) = self.shift;
        // Smootherstep: no step in acceleration where the shift starts, turns or ends.
        let smooth = |s: f64| {
            let s = s.clamp(0.0, 1.0);
            s * s * s * (10.0 + s * (6.0 * s - 15.0))
        };
        if phase <= peak {
            z * smooth((phase - from) / (peak - from))
        } else {
            z * (1.0 - smooth((phase - peak) / (end - peak)))
        }
    }

    /// Longest launch (cycles): a walk whose keyed path is nearly still at its first double
    /// support (a pelvis-forward curve edited flat there) sets off over this instead of
    /// waiting ever longer; shorter, the end speed times the span is under twice the
    /// distance and the speed still never turns back.
    pub const MAX_SPAN: f64 = 1.5;

    /// The span (cycles) of a launch over `distance` (m) ending at speed `v1` (m per cycle).
    #[must_use]
    pub fn span_for(distance: f64, v1: f64) -> f64 {
        (Self::SPEED_TO_DISTANCE * distance.max(0.02) / v1.max(1e-3)).min(Self::MAX_SPAN)
    }

    /// Forward position at `phase` (before the end).
    fn x(&self, phase: f64) -> f64 {
        let s = self.window.progress(phase);
        let (s3, s4, s5) = (s * s * s, s * s * s * s, s * s * s * s * s);
        let h_distance = 10.0 * s3 - 15.0 * s4 + 6.0 * s5;
        let h_speed = -4.0 * s3 + 7.0 * s4 - 3.0 * s5;
        let h_acceleration = 0.5 * s3 - s4 + 0.5 * s5;
        self.x0 + h_distance * (self.x1 - self.x0) + h_speed * self.m1 + h_acceleration * self.a1
    }
}

/// How the pelvis comes to rest at the end of a walk (see `docs/gait-model.md`, §13).
///
/// Forward, a cubic Hermite from where and how fast the pelvis was going at `from_phase` to
/// standing still at `x1`: its start slope is the walk's, its end slope zero, and the span is
/// chosen so the start slope lies between 1.5 and 2.5 times the distance — never past 3, where
/// a cubic with a zero end slope would overshoot `x1` and come back. Height, the sway and
/// the three rotations are blended from the walk's values into standing ones by a smoothstep
/// over the same span, so none of them starts or stops with a jump in speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settle {
    /// When the pelvis settles: from the phase it leaves the keys at, to rest.
    pub window: PhaseWindow,
    /// Forward position at the start (m).
    pub x0: f64,
    /// Forward speed at the start times the span (m): the Hermite's start tangent.
    pub m0: f64,
    /// Forward position at rest (m).
    pub x1: f64,
    /// Height at rest (m).
    pub y1: f64,
    /// Phases after `from_phase` the height keeps to the keys before it too blends: until
    /// the closing step's toe-off, the trailing leg still stands where the walk put it (on
    /// stairs a tread lower), and raising the pelvis to the leading foot's standing height
    /// would pull it off the ground.
    pub y_delay: f64,
}

impl Settle {
    /// A body already at rest at (`x`, `y`) by `phase`: a walk that begins standing.
    #[must_use]
    pub fn at_rest(phase: f64, (x, y): (f64, f64)) -> Self {
        let window = PhaseWindow { from_phase: phase - 1.0, span: 1.0 };
        Settle { window, x0: x, m0: 0.0, x1: x, y1: y, y_delay: 0.0 }
    }

    /// A settling from `x0`, moving at `v0` m per cycle at `from_phase`, to rest at `x1`,
    /// taking as near `wanted_span` cycles as the no-overshoot bounds allow.
    #[must_use]
    pub fn new(from_phase: f64, x0: f64, v0: f64, (x1, y1): (f64, f64), wanted_span: f64, y_delay: f64) -> Self {
        let distance = (x1 - x0).max(0.02);
        let v0 = v0.max(1e-3);
        let span = wanted_span.clamp(1.5 * distance / v0, 2.5 * distance / v0);
        let window = PhaseWindow { from_phase, span };
        Settle { window, x0, m0: v0 * span, x1: x0 + distance, y1, y_delay: y_delay.min(0.5 * span) }
    }

    /// The blend weight of the standing height at `phase`: a smoothstep over the span after
    /// the delay.
    #[must_use]
    pub fn height_weight(&self, phase: f64) -> f64 {
        let from = self.window.from_phase + self.y_delay;
        smoothstep(((phase - from) / (self.window.end_phase() - from)).clamp(0.0, 1.0))
    }

    /// Forward position at `phase` (after the window's start).
    fn x(&self, phase: f64) -> f64 {
        let s = self.window.progress(phase);
        let h10 = s * (1.0 - s) * (1.0 - s);
        let h01 = smoothstep(s);
        self.x0 + h10 * self.m0 + h01 * (self.x1 - self.x0)
    }
}

/// A stretch of master phase over which the pelvis leaves or joins its keys (a start's
/// launch, a stop's settle), and the smoothstep weight the sway, rotations and arm swing
/// blend by over it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhaseWindow {
    /// Master phase it starts at.
    pub from_phase: f64,
    /// Phases it lasts.
    pub span: f64,
}

impl PhaseWindow {
    /// Progress through the window at `phase`: 0 before, 1 after.
    #[must_use]
    pub fn progress(&self, phase: f64) -> f64 {
        ((phase - self.from_phase) / self.span).clamp(0.0, 1.0)
    }

    /// The smoothstep of the progress at `phase`.
    #[must_use]
    pub fn weight(&self, phase: f64) -> f64 {
        smoothstep(self.progress(phase))
    }

    /// Master phase at which it ends.
    #[must_use]
    pub fn end_phase(&self) -> f64 {
        self.from_phase + self.span
    }
}

/// 3s² − 2s³: from 0 to 1 over `s` in 0..1 with zero slope at both ends.
fn smoothstep(s: f64) -> f64 {
    s * s * (3.0 - 2.0 * s)
}

/// Keys kept behind the current phase (for the optimiser's look-back and plots).
const KEYS_KEPT_BEHIND: usize = 4;

impl PelvisPlan {
    /// Starts the walk's end: from `settle.window.from_phase` on, the pelvis comes to rest.
    pub fn settle(&mut self, settle: Settle) {
        self.settle = Some(settle);
    }

    /// The walk's end, if planned.
    #[must_use]
    pub fn settling(&self) -> Option<&Settle> {
        self.settle.as_ref()
    }

    /// A start from standing, if one was made.
    #[must_use]
    pub fn launching(&self) -> Option<&Launch> {
        self.launch.as_ref()
    }

    /// Sets off from standing: the keys are dropped for `keys` (the standing key and those
    /// after it), the settle ends, and the pelvis leaves rest on `launch`.
    pub fn launch(&mut self, keys: &[PelvisKey], launch: Launch) {
        self.keys.clear();
        self.keys.extend(keys.iter().copied());
        self.settle = None;
        self.launch = Some(launch);
    }

    /// The start's weight shift at `phase` (m sideways), if a start was made.
    #[must_use]
    pub fn weight_shift(&self, phase: f64) -> Option<f64> {
        self.launch.as_ref().map(|l| l.weight_shift(phase))
    }

    /// Drops a launch that has ended: the pelvis is on its keys.
    pub fn end_launch(&mut self) {
        self.launch = None;
    }

    /// How much of the walk's sway, rotations and arm swing is in force at `phase`: 0
    /// standing, 1 walking, in between while setting off or settling.
    #[must_use]
    pub fn walking_weight(&self, phase: f64) -> f64 {
        let settling = self.settle.as_ref().map_or(0.0, |s| s.window.weight(phase));
        let launched = self.launch.as_ref().map_or(1.0, |l| l.window.weight(phase));
        (1.0 - settling) * launched
    }

    /// Appends a key; keys must come in phase order.
    pub fn push(&mut self, key: PelvisKey) {
        debug_assert!(self.keys.back().is_none_or(|k| k.phase < key.phase));
        self.keys.push_back(key);
    }

    /// Drops keys long past `phase`.
    pub fn forget_before(&mut self, phase: f64) {
        while self.keys.len() > KEYS_KEPT_BEHIND + 2 && self.keys[KEYS_KEPT_BEHIND].phase < phase {
            self.keys.pop_front();
        }
    }

    /// All keys, oldest first.
    pub fn keys(&self) -> impl Iterator<Item = &PelvisKey> {
        self.keys.iter()
    }

    /// The last key.
    #[must_use]
    pub fn last(&self) -> Option<&PelvisKey> {
        self.keys.back()
    }

    /// The newest key of `kind`.
    #[must_use]
    pub fn last_of(&self, kind: KeyKind) -> Option<&PelvisKey> {
        self.keys.iter().rev().find(|k| k.kind == kind)
    }

    /// Mutable access to the newest key of `kind` (the reach guard lowers a DS key).
    pub fn last_of_mut(&mut self, kind: KeyKind) -> Option<&mut PelvisKey> {
        self.keys.iter_mut().rev().find(|k| k.kind == kind)
    }

    /// The pair of keys around `phase` and where `phase` lies between them (0..1). Before the
    /// first or after the last key the nearest pair is used, clamped.
    #[must_use]
    pub fn bracket(&self, phase: f64) -> (PelvisKey, PelvisKey, f64) {
        let n = self.keys.len();
        debug_assert!(n >= 2, "a pelvis plan needs two keys");
        let i = (1..n).find(|&i| phase < self.keys[i].phase).unwrap_or(n - 1);
        let (a, b) = (self.keys[i - 1], self.keys[i]);
        let u = ((phase - a.phase) / (b.phase - a.phase)).clamp(0.0, 1.0);
        (a, b, u)
    }

    /// Forward position and height at `phase`.
    ///
    /// The pelvis passes every key at the pace planned with it times the design curve's slope
    /// there, so its forward speed is continuous from segment to segment. Scaling the design
    /// curve to a segment's distance alone would not do that: the end slopes match only when
    /// neighbouring segments cover their distances at the same average speed, and a chosen
    /// double-support position or uneven ground makes them differ (the speed jumped by up to
    /// half the walking speed at a key on a steep slope). The difference is added as
    /// `d₀·u(1 − u)² − d₁·u²(1 − u)`, zero at both keys, which sets the end slopes and nothing
    /// else; it depends only on the segment's own two keys, so no segment changes shape once
    /// the pelvis is in it.
    #[must_use]
    pub fn position(&self, phase: f64, curves: &TrajectoryCurves) -> (f64, f64) {
        let (a, b, u) = self.bracket(phase);
        let forward = curves.forward(a.kind);
        let (dx, dp) = (b.x - a.x, b.phase - a.phase);
        let d0 = forward.slope(0.0) * (a.pace * dp - dx);
        let d1 = forward.slope(1.0) * (b.pace * dp - dx);
        let w = 1.0 - u;
        let x = a.x + dx * forward.eval(u) + d0 * u * w * w - d1 * u * u * w;
        let y = self.height_between(&a, &b, u, phase, curves);
        match (&self.settle, &self.launch) {
            (Some(settle), _) if phase > settle.window.from_phase => (settle.x(phase), y),
            (_, Some(launch)) if phase < launch.window.end_phase() => (launch.x(phase), y),
            _ => (x, y),
        }
    }

    /// The height of [`Self::position`] alone, the same number: the reach guard and a start's
    /// flat-feet check lower keys and ask again on each of their passes, and lowering moves
    /// no pelvis forward or back.
    #[must_use]
    pub fn height(&self, phase: f64, curves: &TrajectoryCurves) -> f64 {
        let (a, b, u) = self.bracket(phase);
        self.height_between(&a, &b, u, phase, curves)
    }

    fn height_between(&self, a: &PelvisKey, b: &PelvisKey, u: f64, phase: f64, curves: &TrajectoryCurves) -> f64 {
        let y = a.y + (b.y - a.y) * curves.height_progress(a.kind, b.y - a.y, u);
        match &self.settle {
            Some(settle) if phase > settle.window.from_phase => y + (settle.y1 - y) * settle.height_weight(phase),
            _ => y,
        }
    }
}

/// The largest rise out of double support (m) that takes the quick-start rise curve at full
/// weight. The level walks up to 1.3 m/s rise at most 2.5 cm and take it whole; the 1.6 and
/// 1.75 m/s walks, once their heel rose sooner, 3.3 and 3.8 cm (walked vertical range), and
/// take it at weights of about 0.66 and 0.50.
pub const QUICK_RISE_M: f64 = 0.027;

/// The design curves the trajectory is built from.
#[derive(Clone, Debug)]
pub struct TrajectoryCurves {
    /// Forward progress from mid double support to mid-stance.
    pub(crate) forward_ds_ms: Curve,
    /// Forward progress from mid-stance to mid double support.
    pub(crate) forward_ms_ds: Curve,
    /// Height progress from mid-stance down to mid double support.
    pub(crate) vertical_ms_ds: Curve,
    /// Height progress from mid double support up to mid-stance.
    pub(crate) vertical_ds_ms: Curve,
}

impl TrajectoryCurves {
    /// The forward curve of the segment that starts at a key of `kind`.
    #[must_use]
    pub fn forward(&self, kind: KeyKind) -> &Curve {
        match kind {
            KeyKind::DoubleSupport => &self.forward_ds_ms,
            KeyKind::MidStance => &self.forward_ms_ds,
        }
    }

    /// Height progress (0 at the key, 1 at the next) at `u` of the segment that starts at a
    /// key of `kind` and rises `rise` metres (negative for a fall).
    ///
    /// The rise out of double support starts quicker than the fall into it, for the level
    /// walk's own range; a rise more than [`QUICK_RISE_M`] (a speed-up's first long step,
    /// whose double support the reach guard sinks 2 cm further, or a stair) blends toward the
    /// fall retraced, so that the pelvis's upward acceleration out of double support stays
    /// that of a rise of that size: with the quick shape at full weight the scheduled
    /// 0.8 -> 1.6 m/s walk's pelvis changed velocity 1.43x as sharply as the steady walks'.
    #[must_use]
    pub fn height_progress(&self, kind: KeyKind, rise: f64, u: f64) -> f64 {
        match kind {
            KeyKind::MidStance => self.vertical_ms_ds.eval(u),
            KeyKind::DoubleSupport => {
                let quick = self.vertical_ds_ms.eval(u);
                let w = if rise > QUICK_RISE_M { (QUICK_RISE_M / rise).powi(2) } else { 1.0 };
                if w < 1.0 { w * quick + (1.0 - w) * (1.0 - self.vertical_ms_ds.eval(1.0 - u)) } else { quick }
            }
        }
    }
}

/// The pelvis at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PelvisPose {
    /// Hip-joint centre, world (m).
    pub position: DVec3,
    /// World rotation: rotation about y, then obliquity about x, then tilt about z.
    pub rotation: DQuat,
    /// Pelvic rotation, rad, positive when the right hip is forward.
    pub(crate) rotation_angle: f64,
    /// Pelvic obliquity, rad, positive when the right hip is higher.
    pub(crate) obliquity: f64,
    /// Pelvic tilt, rad, positive anterior.
    pub tilt: f64,
    /// Half the distance between the hip joints (m).
    pub(crate) half_hip_width: f64,
}

impl PelvisPose {
    /// Builds the pose from its three clinical angles.
    #[must_use]
    pub fn new(position: DVec3, rotation_angle: f64, obliquity: f64, tilt: f64, half_hip_width: f64) -> Self {
        // +y turns the right hip (+z) forward; −obliquity about x lifts +z; −tilt about z
        // tips the front (+x) down (anterior).
        let rotation =
            DQuat::from_rotation_y(rotation_angle) * DQuat::from_rotation_x(-obliquity) * DQuat::from_rotation_z(-tilt);
        PelvisPose { position, rotation, rotation_angle, obliquity, tilt, half_hip_width }
    }

    /// World position of the hip joint of the side with sign `side_sign` (+1 right, −1 left).
    #[must_use]
    pub fn hip(&self, side_sign: f64) -> DVec3 {
        self.position + self.rotation * DVec3::new(0.0, 0.0, side_sign * self.half_hip_width)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::gait_curves::CurveName;

    fn curves() -> TrajectoryCurves {
        TrajectoryCurves {
            forward_ds_ms: CurveName::PelvisForwardDsMs.default_curve(),
            forward_ms_ds: CurveName::PelvisForwardMsDs.default_curve(),
            vertical_ms_ds: CurveName::PelvisVertical.default_curve(),
            vertical_ds_ms: CurveName::PelvisVerticalDsMs.default_curve(),
        }
    }

    #[test]
    fn passes_through_keys_and_is_fastest_at_double_support() {
        let mut plan = PelvisPlan::default();
        plan.push(PelvisKey { phase: 0.0, x: 0.0, y: 0.90, kind: KeyKind::MidStance, pace: 1.4 });
        plan.push(PelvisKey { phase: 0.25, x: 0.35, y: 0.86, kind: KeyKind::DoubleSupport, pace: 1.4 });
        plan.push(PelvisKey { phase: 0.5, x: 0.70, y: 0.90, kind: KeyKind::MidStance, pace: 1.4 });
        let c = curves();
        assert_eq!(plan.position(0.25, &c), (0.35, 0.86));
        let speed = |p: f64| (plan.position(p + 1e-4, &c).0 - plan.position(p - 1e-4, &c).0) / 2e-4;
        assert!(speed(0.25) > speed(0.01) * 1.2, "{} {}", speed(0.25), speed(0.01));
        let (_, y_mid) = plan.position(0.125, &c);
        assert!(y_mid > 0.86 && y_mid < 0.90);
    }

    #[test]
    fn forward_speed_is_continuous_at_keys_whatever_the_distances() {
        // Uneven segments: 0.30 m then 0.40 m in equal times, as a chosen double support
        // off the midpoint makes them.
        let mut plan = PelvisPlan::default();
        plan.push(PelvisKey { phase: 0.0, x: 0.0, y: 0.90, kind: KeyKind::MidStance, pace: 1.4 });
        plan.push(PelvisKey { phase: 0.25, x: 0.30, y: 0.86, kind: KeyKind::DoubleSupport, pace: 1.4 });
        plan.push(PelvisKey { phase: 0.5, x: 0.70, y: 0.90, kind: KeyKind::MidStance, pace: 1.4 });
        plan.push(PelvisKey { phase: 0.75, x: 1.05, y: 0.86, kind: KeyKind::DoubleSupport, pace: 1.4 });
        let c = curves();
        let h = 1e-7;
        let left = |p: f64| (plan.position(p, &c).0 - plan.position(p - h, &c).0) / h;
        let right = |p: f64| (plan.position(p + h, &c).0 - plan.position(p, &c).0) / h;
        for key in [0.25, 0.5] {
            assert!((left(key) - right(key)).abs() < 1e-4, "at {key}: {} vs {}", left(key), right(key));
        }
        // At the pace times the design slope: 1.4 m/cycle x 1.12 at double support.
        assert!((right(0.25) - 1.4 * 1.12).abs() < 1e-4, "{}", right(0.25));
        // Keys are still passed through exactly, and the pelvis never goes backward.
        assert_eq!(plan.position(0.5, &c).0, 0.70);
        for i in 0..100 {
            assert!(right(0.75 * f64::from(i) / 100.0) > 0.5);
        }
    }

    #[test]
    fn obliquity_lifts_the_right_hip() {
        let p = PelvisPose::new(DVec3::new(0.0, 1.0, 0.0), 0.1, 0.05, 0.0, 0.1);
        assert!(p.hip(1.0).y > p.hip(-1.0).y);
        assert!(p.hip(1.0).x > p.hip(-1.0).x, "positive rotation brings the right hip forward");
        let tilted = PelvisPose::new(DVec3::ZERO, 0.0, 0.0, 0.2, 0.1);
        assert!((tilted.rotation * DVec3::X).y < 0.0, "anterior tilt tips the front down");
    }
}
