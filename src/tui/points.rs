//! Editing a design curve's control points in the lab: a point selected (keys `<` `>` or a
//! click), moved with the arrows or dragged with the mouse. Each move goes through
//! [`drag_control_point`] (neighbours follow, joins stay smooth) and the config's own curve
//! check, then in force like any parameter edit: a `[curves.<name>]` override, live on the
//! walk, undoable, saved by `s`.

use super::app::{App, CurveView, Edit};
use super::keys::Action;
use crate::config::checks::check_curve;
use crate::config::schema::curve_limits;
use crate::model::curve_edit::drag_control_point;
use crate::model::gait_curves::CurveName;
use crate::model::params::WalkParams;

/// A selected control point: of the curve a chart shows, by its index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PointSel {
    /// The chart.
    pub view: CurveView,
    /// The control point (0 = the curve's start).
    pub index: usize,
}

/// The design curve a chart edits, and how the chart draws its y: `shown = a * y + b` (the
/// cycle curves are unit shapes the walk scales by a range; charts show degrees and cm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EditMap {
    /// The curve.
    pub name: CurveName,
    /// Scale.
    pub a: f64,
    /// Offset.
    pub b: f64,
}

impl EditMap {
    /// Design y to chart y.
    #[must_use]
    pub fn shown(&self, y: f64) -> f64 {
        self.a * y + self.b
    }

    /// Chart y to design y (`None` when the range it is drawn at is zero).
    #[must_use]
    pub fn design(&self, shown: f64) -> Option<f64> {
        (self.a.abs() > 1e-12).then(|| (shown - self.b) / self.a)
    }
}

/// How far one arrow press moves a point: x by 1/100 of the cycle, y by 1/100 of the
/// curve's valid range (coarse: x10).
const STEPS_PER_RANGE: f64 = 100.0;

impl App {
    /// The point keys, and the arrows while a point is selected; returns whether `action`
    /// was one of them.
    pub(super) fn point_action(&mut self, action: Action) -> bool {
        match action {
            Action::NextPoint => self.select_point(1),
            Action::PrevPoint => self.select_point(-1),
            Action::LeavePoints => self.leave_points(),
            Action::Up => return self.nudge_point(0.0, 1.0),
            Action::Down => return self.nudge_point(0.0, -1.0),
            Action::Increase => return self.nudge_point(1.0, 0.0),
            Action::Decrease => return self.nudge_point(-1.0, 0.0),
            Action::IncreaseCoarse => return self.nudge_point(10.0, 0.0),
            Action::DecreaseCoarse => return self.nudge_point(-10.0, 0.0),
            _ => return false,
        }
        true
    }

    /// The curve `view` edits and its chart scale, as the walk has it now.
    #[must_use]
    pub fn edit_map(&self, view: CurveView) -> EditMap {
        let r = self.walker.resolved();
        let deg = 180.0 / std::f64::consts::PI;
        let (name, a, b) = match view {
            CurveView::PelvisRotation => (CurveName::PelvisRotation, 0.5 * r.rotation_range * deg, 0.0),
            CurveView::PelvisObliquity => (CurveName::PelvisObliquity, 0.5 * r.played_obliquity_range() * deg, 0.0),
            CurveView::PelvisTilt => (CurveName::PelvisTilt, 0.5 * r.tilt_range * deg, 0.0),
            CurveView::PelvisLateral => (CurveName::PelvisLateral, 0.5 * r.lateral_range * 100.0, 0.0),
            CurveView::Shoulder => (CurveName::Shoulder, 0.5 * r.shoulder_range * deg, 0.0),
            CurveView::Elbow => {
                (CurveName::Elbow, 0.5 * r.elbow_range * deg, (r.elbow_min_flex + 0.5 * r.elbow_range) * deg)
            }
            CurveView::PelvisVertical => (CurveName::PelvisVerticalDsMs, 1.0, 0.0),
            CurveView::PelvisForward => (CurveName::PelvisForwardDsMs, 1.0, 0.0),
            CurveView::SwingForward => (CurveName::SwingForward, 1.0, 0.0),
            CurveView::SwingLateral => (CurveName::SwingLateral, 1.0, 0.0),
            CurveView::SwingHeelHeight => (CurveName::SwingHeelHeight, 100.0, 0.0),
            CurveView::Ankle => (CurveName::SwingAnkle, 1.0, 0.0),
            CurveView::HeelRise => (CurveName::HeelRise, 1.0, 0.0),
        };
        EditMap { name, a, b }
    }

    /// The design control points of `name` in force (an override, else the default).
    #[must_use]
    pub fn design_points(&self, name: CurveName) -> Vec<(f64, f64)> {
        self.walker.design_curves().get(name).points().iter().map(|p| (p.x, p.y)).collect()
    }

    /// Selects the next (`step` 1) or previous (-1) control point of the chart shown first,
    /// wrapping; the first `>` selects the first handle (a progress curve's start is pinned at
    /// 0, and a newcomer's first arrow press on it was always refused), the first `<` the last
    /// point (a cycle curve's ends move together).
    pub(super) fn select_point(&mut self, step: i64) {
        let view = self.point.map_or(CurveView::ALL[self.curve], |p| p.view);
        let n = self.design_points(self.edit_map(view).name).len() as i64;
        let index = match self.point {
            Some(p) => (p.index as i64 + step).rem_euclid(n) as usize,
            None if step > 0 => 1.min(n - 1) as usize,
            None => (n - 1) as usize,
        };
        self.point = Some(PointSel { view, index });
        self.panel = super::app::Panel::Curves;
        self.describe_point("selected");
    }

    /// Leaves point editing: the arrows select and change parameters again.
    pub(super) fn leave_points(&mut self) {
        if self.point.take().is_some() {
            self.message = Some("point editing off: the arrows change parameters".into());
        }
    }

    /// Moves the selected point by arrow steps (x, y); returns false when no point is
    /// selected (the arrows then do their parameter work).
    pub(super) fn nudge_point(&mut self, dx_steps: f64, dy_steps: f64) -> bool {
        let Some(sel) = self.point else { return false };
        let map = self.edit_map(sel.view);
        let limits = curve_limits(map.name);
        let points = self.design_points(map.name);
        let Some(&(x, y)) = points.get(sel.index) else { return false };
        let to = (x + dx_steps / STEPS_PER_RANGE, y + dy_steps * (limits.hi - limits.lo) / STEPS_PER_RANGE);
        if self.move_point(sel, to, true) {
            self.describe_point("moved");
        }
        true
    }

    /// Moves the selected point to `to` (design units), its neighbours following; refused
    /// (with the reason in the status line, the curve unchanged) when the config's rules
    /// would refuse the curve. Returns whether it moved.
    pub(super) fn move_point(&mut self, sel: PointSel, to: (f64, f64), record: bool) -> bool {
        let name = self.edit_map(sel.view).name;
        let before = self.design_points(name);
        let moved = drag_control_point(&before, sel.index, to, name.is_cyclic())
            .and_then(|points| check_curve(name.key(), &points).map(|()| points));
        match moved {
            Ok(points) if points == before => {
                if sel.index == 0 || sel.index + 1 == before.len() {
                    self.message = Some("a curve's ends stay at x = 0 and x = 1: move them up or down".into());
                }
                false
            }
            Ok(points) => {
                let mut params = self.params.clone();
                params.curves.insert(name.key().to_string(), points);
                self.apply(params, format!("curve {name}: point {} moved", sel.index), record);
                true
            }
            Err(why) => {
                self.message = Some(format!("refused: {why}"));
                false
            }
        }
    }

    /// Starts a drag of `sel`: the parameters before it are kept for its one undo step.
    pub(super) fn start_drag(&mut self, sel: PointSel) {
        // A release the terminal never reported (the button let go outside the window)
        // still closes the last drag as its own undo step.
        self.end_drag();
        self.point = Some(sel);
        self.drag = Some(self.params.clone());
        self.describe_point("dragging");
    }

    /// Ends a drag: the whole drag is one undoable edit.
    pub(super) fn end_drag(&mut self) {
        let Some(before) = self.drag.take() else { return };
        if before != self.params {
            let what = self.point.map_or("curve edit".into(), |p| {
                format!("curve {}: point {} dragged", self.edit_map(p.view).name, p.index)
            });
            self.push_edit(before, what);
            self.describe_point("dropped");
        }
    }

    fn push_edit(&mut self, before: WalkParams, what: String) {
        self.undo.push(Edit { before, after: self.params.clone(), what });
        self.redo.clear();
    }

    /// The status line for the selected point: the curve, the point, where it is (as the
    /// chart shows it) and what the keys do.
    fn describe_point(&mut self, what: &str) {
        let Some(sel) = self.point else { return };
        let map = self.edit_map(sel.view);
        let points = self.design_points(map.name);
        let Some(&(x, y)) = points.get(sel.index) else { return };
        let kind = if sel.index % 3 == 0 { "join" } else { "handle" };
        self.message = Some(format!(
            "{what} {kind} {}/{} of {}: x {x:.3}, y {:.2} (arrows move it, esc: done)",
            sel.index,
            points.len() - 1,
            map.name,
            map.shown(y)
        ));
    }
}
