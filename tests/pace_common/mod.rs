//! What the pace and start tests (`tests/pace.rs`, `tests/start.rs`) both walk and measure
//! with (`mod pace_common;`): a schedule entry at a time, a walk recorded frame by frame, the
//! pelvis's largest velocity change per frame, and the heel strikes.

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
