//! The lab's pace keys: walk slower or faster while walking, stop, or set off again. A pace change is an
//! edit of `walk.speed_mps` like any other (undoable, saved by `s`), but the walk takes it as
//! the pace schedule does — over the next two heel strikes, never under a planted foot —
//! instead of as a live edit.

use super::app::{App, Edit};
use super::keys::Action;
use crate::config::schema::{Kind, spec};
use crate::model::walk::pace::WalkState;

/// How far one key press moves the speed (m/s).
const PACE_STEP_MPS: f64 = 0.1;

impl App {
    /// `-`, `+` and `w`: slower, faster, stop or (standing) start. False for any other action.
    pub(super) fn pace_action(&mut self, action: Action) -> bool {
        if !matches!(action, Action::PaceDown | Action::PaceUp | Action::StopWalk) {
            return false;
        }
        self.pace(action);
        true
    }

    fn pace(&mut self, action: Action) {
        match self.walker.walk_state() {
            WalkState::Walking => {}
            WalkState::Starting => {
                self.message = Some("starting: the first step is under way (w stops once walking)".into());
                return;
            }
            WalkState::Stopping => {
                self.message = Some("stopping: the walk comes to rest (w sets off again once standing)".into());
                return;
            }
            WalkState::Standing if action == Action::StopWalk => {
                self.walker.request_start();
                self.message = Some(format!(
                    "starting from standing at {:.1} m/s: a short first step, then full steps",
                    self.params.walk.speed_mps
                ));
                return;
            }
            WalkState::Standing => {}
        }
        if action == Action::StopWalk {
            self.walker.request_stop();
            self.message = Some("stopping: a braking step, then the feet side by side".into());
            return;
        }
        let Some(Kind::Real { min: low, max: high, .. }) = spec("walk.speed_mps").map(|k| k.kind) else {
            unreachable!("walk.speed_mps is a number with a range")
        };
        let sign = if action == Action::PaceUp { 1.0 } else { -1.0 };
        let speed = self.params.walk.speed_mps;
        // Rounded to the speed's own resolution (0.01 m/s) so repeated presses land on 1.3,
        // 1.4, ... not 1.4000000000000001; rounded to the 0.1 step, a press from 1.75 m/s went
        // to 1.9 and back to 1.6.
        let to = ((speed + sign * PACE_STEP_MPS) * 100.0).round() / 100.0;
        let to = to.clamp(low, high);
        if (to - speed).abs() < 1e-9 {
            self.message =
                Some(format!("walk.speed_mps is at its {} ({speed} m/s)", if sign > 0.0 { "most" } else { "least" }));
            return;
        }
        // 1.0, 1.4, 1.85: the digits the speed has, at least one after the point.
        let mut shown = format!("{to:.2}");
        if shown.ends_with('0') {
            shown.pop();
        }
        let mut params = self.params.clone();
        params.walk.speed_mps = to;
        let before = std::mem::replace(&mut self.params, params.clone());
        self.undo.push(Edit { before, after: params, what: format!("walk.speed_mps = {shown}") });
        self.redo.clear();
        self.walker.request_speed(to);
        self.message = Some(if self.walker.walk_state() == WalkState::Standing {
            format!("walk.speed_mps = {shown}: the speed w sets off at")
        } else {
            format!("walk.speed_mps = {shown}, reached over two steps")
        });
    }
}
