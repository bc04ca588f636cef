//! Gait events, detected in one place from the frames: every figure, plot and table that
//! splits a walk into cycles or marks its events reads them from here.
//!
//! - **heel strike**: the leg's cycle phase wraps at the end of a swing (the walk starts each
//!   leg's cycle at its heel strike). A leg standing still — a stopped walk's, both feet
//!   down — keeps its phase running and wrapping while it holds midstance: that wrap ends no
//!   swing and is no heel strike, so standing has no cycles;
//! - **toe-off**: the leg enters swing.

use crate::model::walk::frame::Frame;
use crate::model::walk::leg::LegPhase;

/// Whether leg `side` (0 right, 1 left) strikes the ground between frames `a` and `b`: its
/// phase wraps and it was swinging.
#[must_use]
pub(crate) fn is_heel_strike(a: &Frame, b: &Frame, side: usize) -> bool {
    b.legs[side].phase < a.legs[side].phase && a.legs[side].leg_phase == LegPhase::Swing
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

/// Indices of the frames at which either leg has just struck, in order: the walk's steps.
#[must_use]
pub(crate) fn steps(frames: &[Frame]) -> Vec<usize> {
    (1..frames.len()).filter(|&i| (0..2).any(|side| is_heel_strike(&frames[i - 1], &frames[i], side))).collect()
}

/// Indices of the frames at which either leg has just left the ground, in order: the walk
/// plans a step at each, so the n-th is the n-th step plan's.
#[must_use]
pub(crate) fn toe_offs(frames: &[Frame]) -> Vec<usize> {
    (1..frames.len()).filter(|&i| (0..2).any(|side| is_toe_off(&frames[i - 1], &frames[i], side))).collect()
}
