//! Measures shared by test binaries (`mod common;`): the live-change test's joint speed and
//! jerk, which the pace tests hold transitions to as well, so both judge by the same numbers.

use gaitlab::model::walk::frame::Frame;

/// Hip, knee, ankle and shoulder flexion of one leg (deg).
fn angles(f: &Frame, side: usize) -> [f64; 4] {
    let l = &f.legs[side];
    [l.hip_flex_deg, l.knee_flex_deg, l.ankle_dorsi_deg, l.shoulder_flex_deg]
}

/// The largest per-frame change of each joint (deg/frame), both legs: hip, knee, ankle,
/// shoulder.
pub fn max_steps(frames: &[Frame]) -> [f64; 4] {
    let mut out = [0.0f64; 4];
    for w in frames.windows(2) {
        for side in 0..2 {
            let (a, b) = (angles(&w[0], side), angles(&w[1], side));
            for i in 0..4 {
                out[i] = out[i].max((a[i] - b[i]).abs());
            }
        }
    }
    out
}

/// The largest change of each joint's per-frame change (deg/frame², both legs): a spike
/// here is a jerk, a jump in the joint's speed.
pub fn max_speed_changes(frames: &[Frame]) -> [f64; 4] {
    let mut out = [0.0f64; 4];
    for w in frames.windows(3) {
        for side in 0..2 {
            let (a, b, c) = (angles(&w[0], side), angles(&w[1], side), angles(&w[2], side));
            for i in 0..4 {
                out[i] = out[i].max((c[i] - 2.0 * b[i] + a[i]).abs());
            }
        }
    }
    out
}
