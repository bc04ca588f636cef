//! What the view keys do: side or frontal view, the curve shown, the grid, the norms band,
//! the panel on small screens.

use super::app::{App, CurveView, Panel, View};
use super::keys::Action;
use crate::normative::{Reference, References};

impl App {
    /// What to show: the view, the curve chart, the grid, the norms band, the panel.
    pub(super) fn show(&mut self, action: Action) {
        match action {
            Action::ToggleView => self.view = if self.view == View::Side { View::Front } else { View::Side },
            // On the small screen the chart shares a tab with the other panels: from another
            // tab the first press shows it (else `c` on the Parameters tab would turn a chart
            // no one sees), the next ones turn it.
            Action::NextCurve | Action::PrevCurve if self.panel != Panel::Curves && self.tabbed() => {
                self.panel = Panel::Curves;
                self.message = Some("curves (c/C: next/previous)".into());
            }
            Action::NextCurve | Action::PrevCurve => {
                let n = CurveView::ALL.len();
                self.curve = (self.curve + if action == Action::NextCurve { 1 } else { n - 1 }) % n;
                // The point keys follow the chart shown.
                self.point = None;
            }
            Action::ToggleGrid => self.toggle_grid(),
            Action::ToggleNorms => self.toggle_norms(),
            _ => {
                let (i, n) = (Panel::ALL.iter().position(|p| *p == self.panel).unwrap_or(0), Panel::ALL.len());
                let step = if action == Action::PrevPanel { n - 1 } else { 1 };
                self.panel = Panel::ALL[(i + step) % n];
            }
        }
    }

    /// Whether the last screen drawn put the panels behind tabs (the small screen).
    fn tabbed(&self) -> bool {
        !self.hits.borrow().tabs.is_empty()
    }

    /// One curve or a grid of them; on narrow screens the curves share a tab with the other
    /// panels, so a grid switches to it.
    fn toggle_grid(&mut self) {
        self.grid = !self.grid;
        if self.grid {
            self.panel = Panel::Curves;
        }
        self.message = Some(if self.grid { "curves in a grid (c/C: next/previous)" } else { "one curve" }.into());
    }

    /// The norms band on or off; on narrow screens the joint traces share a tab with the
    /// other panels, so turning it on switches to them (else the key would look dead).
    fn toggle_norms(&mut self) {
        self.norms = !self.norms;
        if self.norms {
            self.panel = Panel::Joints;
        }
        self.message = Some(if self.norms { "adult norms band on" } else { "adult norms band off" }.into());
    }
}

impl App {
    /// The norms at the speed the walk walks now (its pace, as a schedule or an edit left
    /// it), for the joint panel's band; `None` with the band off.
    #[must_use]
    pub(crate) fn norms_band(&self) -> Option<&Reference> {
        self.norms.then_some(&self.norms_at_speed.1)
    }

    /// Reads the norms again if the walk's speed changed (a pace step, an edit, a restart).
    pub(super) fn refresh_norms(&mut self) {
        let speed = self.walk_speed_mps();
        if self.norms_at_speed.0 != speed {
            self.norms_at_speed = (speed, References::built_in().at(speed));
        }
    }

    /// The speed the walk walks now (m/s): its stride over its cycle, as a schedule or an
    /// edit left them.
    #[must_use]
    pub(crate) fn walk_speed_mps(&self) -> f64 {
        let r = self.walker.resolved();
        r.stride_m / r.cycle_s
    }
}
