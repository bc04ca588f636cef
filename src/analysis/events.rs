//! Gait events, detected in one place from the frames: every figure, plot and table that
//! splits a walk into cycles or marks its events reads them from here.
//!
//! - **heel strike**: the leg's cycle phase wraps (the walk starts each leg's cycle at its
//!   heel strike);
//! - **toe-off**: the leg enters swing.

use crate::model::walk::frame::Frame;
use crate::model::walk::leg::LegPhase;

/// Whether leg `side` (0 right, 1 left) strikes the ground between frames `a` and `b`.
#[must_use]
pub(crate) fn is_heel_strike(a: &Frame, b: &Frame, side: usize) -> bool {
    b.legs[side].phase < a.legs[side].phase
}

/// Whether leg `side` (0 right, 1 left) leaves the ground between frames `a` and `b`.
#[must_use]
pub(crate) fn is_toe_off(a: &Frame, b: &Frame, side: usize) -> bool {
    a.legs[side].leg_phase != LegPhase::Swing && b.legs[side].leg_phase == LegPhase::Swing
}

/// Indices of the frames at which leg `side` has just struck (frame 0, the start pose, never
/// counts).
#[must_use]
pub(crate) fn heel_strikes(frames: &[Frame], side: usize) -> Vec<usize> {
    (1..frames.len()).filter(|&i| is_heel_strike(&frames[i - 1], &frames[i], side)).collect()
}
