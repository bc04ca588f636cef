//! Measuring walks: running a walk headless into frames, and the checks and per-cycle
//! figures computed from those frames (never from the parameters).
//!
//! Definitions:
//! - **foot skate**: for each stance phase instance, the largest distance of the contact
//!   point that phase holds fixed (heel in loading response, ankle in midstance, toe tip in
//!   heel rise) from where it was at the phase's first frame;
//! - **terrain penetration**: the deepest a heel or toe tip goes under the ground directly
//!   below it;
//! - **stance %**: frames in which a leg is in one of its three stance phases, over frames;
//! - **cycle**: heel strike to heel strike of the right leg; the first cycle is start-up.
//!   A standing walker takes no steps and so has no cycles ([`events`]); which cycles are
//!   steady, and which are a speed change, a stop or standing, is [`steady`]'s.

pub mod events;
pub mod frame_cost;
pub mod ik;
pub mod ik_tables;
pub mod recording;
pub mod steady;

pub use recording::{IkTarget, Keep, Recording, record};

use crate::model::body::Side;
use crate::model::params::WalkParams;
use crate::model::walk::ModelError;
use crate::model::walk::frame::{Frame, Support};
use crate::model::walk::leg::LegPhase;

/// A finished headless run: the name the measuring code has always used for a recording.
pub type Run = Recording;

/// Runs `cycles` gait cycles at `fps` frames per second, keeping frames, footfalls and plans.
pub fn run(params: &WalkParams, cycles: f64, fps: f64) -> Result<Run, ModelError> {
    record(params, cycles, fps, Keep::default())
}

/// The walk's health checks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Checks {
    /// Largest stance contact slide within one phase (mm).
    pub foot_skate_mm: f64,
    /// Where it happened: frame, side, phase.
    pub(crate) worst_skate: Option<(u64, Side, LegPhase)>,
    /// Deepest heel or toe tip under the ground (mm, 0 if never).
    pub terrain_penetration_mm: f64,
    /// Where it happened.
    pub worst_penetration: Option<(u64, Side)>,
    /// Frames whose leg IK did not reach.
    pub reach_failures: u64,
    /// Non-finite numbers in any frame.
    pub non_finite_values: u64,
}

/// Computes [`Checks`] over `frames`.
#[must_use]
pub fn checks(frames: &[Frame]) -> Checks {
    let mut c = Checks::default();
    for side in Side::BOTH {
        let i = side.index();
        let mut start: Option<(u64, glam::DVec3)> = None;
        for f in frames {
            let leg = &f.legs[i];
            // Swinging feet too: a toe that clips a stair's riser is as much under the ground
            // as a planted one.
            for (ground, y) in [(leg.ground_under_heel, leg.heel.y), (leg.ground_under_toe, leg.toe.y)] {
                let depth = (ground - y) * 1000.0;
                if depth > c.terrain_penetration_mm {
                    c.terrain_penetration_mm = depth;
                    c.worst_penetration = Some((f.frame, side));
                }
            }
            let contact = match leg.leg_phase {
                LegPhase::LoadingResponse => leg.heel,
                // The toe, not the ankle: a leg past reach after a live change lifts its heel
                // about the planted ball (`Gait::target_of`), which is no slide.
                LegPhase::Midstance => leg.toe,
                LegPhase::HeelRise => leg.toe,
                LegPhase::Swing => {
                    start = None;
                    continue;
                }
            };
            match start {
                Some((serial, p0)) if serial == leg.phase_serial => {
                    let d = p0.distance(contact) * 1000.0;
                    if d > c.foot_skate_mm {
                        c.foot_skate_mm = d;
                        c.worst_skate = Some((f.frame, side, leg.leg_phase));
                    }
                }
                _ => start = Some((leg.phase_serial, contact)),
            }
            if !leg.reached {
                c.reach_failures += 1;
            }
        }
        for f in frames {
            if !f.legs[i].reached && f.legs[i].leg_phase == LegPhase::Swing {
                c.reach_failures += 1;
            }
        }
    }
    c.non_finite_values = frames.iter().map(non_finite_in).sum();
    c
}

/// Counts non-finite numbers in a frame.
#[must_use]
pub(crate) fn non_finite_in(f: &Frame) -> u64 {
    let mut values = vec![
        f.time_s,
        f.pelvis.x,
        f.pelvis.y,
        f.pelvis.z,
        f.pelvis_tilt_deg,
        f.pelvis_obliquity_deg,
        f.pelvis_rotation_deg,
    ];
    for l in &f.legs {
        values.extend([
            l.hip_flex_deg,
            l.hip_abd_deg,
            l.knee_flex_deg,
            l.ankle_dorsi_deg,
            l.shoulder_flex_deg,
            l.elbow_flex_deg,
        ]);
        for v in [l.hip, l.knee, l.ankle, l.heel, l.toe] {
            values.extend([v.x, v.y, v.z]);
        }
    }
    values.iter().filter(|v| !v.is_finite()).count() as u64
}

/// Figures of one gait cycle (right heel strike to right heel strike).
#[derive(Clone, Debug, PartialEq)]
pub struct CycleSummary {
    /// Cycle number (0 is start-up).
    pub cycle: usize,
    /// Duration (s).
    pub duration_s: f64,
    /// Pelvis travel over the cycle (m).
    pub stride_m: f64,
    /// Mean forward speed (m/s).
    pub speed_mps: f64,
    /// Stance share of the cycle per leg (%).
    pub stance_pct: [f64; 2],
    /// Double-support share (%).
    pub double_support_pct: f64,
    /// Pelvis vertical range (cm).
    pub pelvis_vertical_cm: f64,
    /// Pelvis lateral range (cm).
    pub pelvis_lateral_cm: f64,
    /// Knee flexion peaks per leg (deg): in stance and in swing.
    pub knee_max_stance_deg: [f64; 2],
    /// Peak knee flexion in swing.
    pub knee_max_swing_deg: [f64; 2],
    /// Hip flexion range per leg: (max extension as negative flexion, max flexion).
    pub hip_flex_deg: [(f64, f64); 2],
    /// Ankle range per leg: (max plantarflexion, max dorsiflexion).
    pub ankle_deg: [(f64, f64); 2],
    /// Lowest toe tip above the ground in mid-swing per leg (cm).
    pub min_toe_clearance_cm: [f64; 2],
}

/// Splits `frames` into cycles at right heel strikes and summarises each complete one.
#[must_use]
pub fn cycle_summaries(frames: &[Frame]) -> Vec<CycleSummary> {
    let starts: Vec<usize> = std::iter::once(0).chain(events::heel_strikes(frames, 0)).collect();
    starts.windows(2).enumerate().map(|(cycle, w)| summarise(cycle, &frames[w[0]..w[1]], &frames[w[1]])).collect()
}

fn summarise(cycle: usize, f: &[Frame], next: &Frame) -> CycleSummary {
    let n = f.len() as f64;
    let range = |it: &mut dyn Iterator<Item = f64>| {
        let (lo, hi) = it.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
        (lo, hi)
    };
    let duration_s = next.time_s - f[0].time_s;
    let stride_m = next.pelvis.x - f[0].pelvis.x;
    let per_leg = |i: usize| {
        let stance = f.iter().filter(|fr| fr.legs[i].leg_phase.is_stance()).count() as f64 / n * 100.0;
        let knee_stance = f
            .iter()
            .filter(|fr| fr.legs[i].leg_phase.is_stance())
            .map(|fr| fr.legs[i].knee_flex_deg)
            .fold(0.0, f64::max);
        let knee_swing = f
            .iter()
            .filter(|fr| !fr.legs[i].leg_phase.is_stance())
            .map(|fr| fr.legs[i].knee_flex_deg)
            .fold(0.0, f64::max);
        let hip = range(&mut f.iter().map(|fr| fr.legs[i].hip_flex_deg));
        let ankle = range(&mut f.iter().map(|fr| fr.legs[i].ankle_dorsi_deg));
        // Mid-swing: the middle half of the swing, where the foot passes the stance foot.
        let clearance = f
            .iter()
            .filter(|fr| fr.legs[i].leg_phase == LegPhase::Swing)
            .map(|fr| &fr.legs[i])
            .filter(|l| {
                let to = 1.0 - l.phase;
                to > 0.1 && to < 0.3
            })
            .map(|l| (l.toe.y - l.ground_under_toe) * 100.0)
            .fold(f64::INFINITY, f64::min);
        (stance, knee_stance, knee_swing, hip, ankle, clearance)
    };
    let (r, l) = (per_leg(0), per_leg(1));
    let vertical = range(&mut f.iter().map(|fr| fr.pelvis.y));
    let lateral = range(&mut f.iter().map(|fr| fr.pelvis.z));
    CycleSummary {
        cycle,
        duration_s,
        stride_m,
        speed_mps: stride_m / duration_s,
        stance_pct: [r.0, l.0],
        double_support_pct: f.iter().filter(|fr| fr.support == Support::Double).count() as f64 / n * 100.0,
        pelvis_vertical_cm: (vertical.1 - vertical.0) * 100.0,
        pelvis_lateral_cm: (lateral.1 - lateral.0) * 100.0,
        knee_max_stance_deg: [r.1, l.1],
        knee_max_swing_deg: [r.2, l.2],
        hip_flex_deg: [r.3, l.3],
        ankle_deg: [r.4, l.4],
        min_toe_clearance_cm: [r.5, l.5],
    }
}
