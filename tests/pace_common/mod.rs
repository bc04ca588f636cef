//! What the pace and start tests (`tests/pace.rs`, `tests/start.rs`) both walk and measure
//! with (`mod pace_common;`): a schedule entry at a time, a walk recorded frame by frame, the
//! pelvis's largest velocity change per frame, and the heel strikes.

use crate::common::{max_speed_changes, max_steps};
use gaitlab::model::params::WalkParams;
use gaitlab::model::schedule::{PaceAction, PaceEntry, PaceTrigger};
use gaitlab::model::walk::Walker;
use gaitlab::model::walk::frame::Frame;
use gaitlab::model::walk::leg::LegPhase;

/// A schedule entry at `t` seconds.
pub fn at_time(t: f64, action: PaceAction) -> PaceEntry {
    PaceEntry { trigger: PaceTrigger::TimeS(t), action }
}

/// Walks `params` for `seconds` at `fps`, returning the frames and the walker.
pub fn walk(params: &WalkParams, seconds: f64, fps: f64) -> (Vec<Frame>, Walker) {
    let mut w = Walker::new(params).unwrap();
    let n = (seconds * fps).round() as u64;
    let mut frames = vec![w.frame(0)];
    for i in 1..=n {
        w.advance(1.0 / fps);
        frames.push(w.frame(i));
    }
    (frames, w)
}

/// The largest frame-to-frame change of the pelvis's velocity (m/s per frame, all three axes).
pub fn max_pelvis_velocity_jump(frames: &[Frame], fps: f64) -> f64 {
    frames
        .windows(3)
        .map(|w| ((w[2].pelvis - w[1].pelvis) - (w[1].pelvis - w[0].pelvis)).length() * fps)
        .fold(0.0, f64::max)
}

/// Heel strikes (frames where a leg goes from swing to loading response).
pub fn heel_strikes(frames: &[Frame]) -> Vec<&Frame> {
    frames
        .windows(2)
        .filter(|w| {
            w[1].legs
                .iter()
                .zip(&w[0].legs)
                .any(|(b, a)| b.leg_phase == LegPhase::LoadingResponse && a.leg_phase == LegPhase::Swing)
        })
        .map(|w| &w[1])
        .collect()
}

/// A steady walk's largest joint speed (deg/frame), joint jerk (deg/frame²) and pelvis
/// velocity change (m/s a frame), as `max_steps`, `max_speed_changes` and
/// [`max_pelvis_velocity_jump`] measure them.
pub struct Peaks {
    pub speed: [f64; 4],
    pub jerk: [f64; 4],
    pub pelvis: f64,
}

/// The steady walk of `params` over `seconds` at `fps`, its first second left out, measured
/// at eight sampling phases an eighth of a frame apart and the largest of each figure kept.
/// A sharp turn reads differently depending on where the frames fall (the 1.6 m/s walk's
/// hip jerk is 2.80 or 3.20°/frame² from one phase to the next), and a transition is read
/// wherever its frames fall: against one phase only, a plateau of that very walk in the
/// scheduled 0.8 -> 1.6 -> 1.0 m/s walk read 1.14x its steady walk.
pub fn steady_peaks(params: &WalkParams, seconds: f64, fps: f64) -> Peaks {
    let mut peaks = Peaks { speed: [0.0; 4], jerk: [0.0; 4], pelvis: 0.0 };
    for eighth in 0..8 {
        let mut w = Walker::new(params).unwrap();
        w.advance(f64::from(eighth) / 8.0 / fps);
        let n = (seconds * fps).round() as u64;
        let frames: Vec<Frame> = (0..n)
            .map(|i| {
                w.advance(1.0 / fps);
                w.frame(i)
            })
            .collect();
        let steady = &frames[fps.round() as usize..];
        let (speed, jerk) = (max_steps(steady), max_speed_changes(steady));
        for i in 0..4 {
            peaks.speed[i] = peaks.speed[i].max(speed[i]);
            peaks.jerk[i] = peaks.jerk[i].max(jerk[i]);
        }
        peaks.pelvis = peaks.pelvis.max(max_pelvis_velocity_jump(steady, fps));
    }
    peaks
}
