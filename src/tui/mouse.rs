//! The mouse in the lab: what each drawn region is (recorded by the widgets as they draw a
//! frame, so a click is read against what the user sees) and what a click, a drag or the
//! wheel does there.
//!
//! A click on a parameter selects it, the wheel over the editor changes the selected value
//! by a fine step, a click on a panel focuses it (on small screens a click on a tab shows
//! that panel). In a curve chart, a press on a control point (within a cell of it) selects
//! it and starts a drag; each drag event moves the point to the cell under the pointer, read
//! back through the chart's own scale (the inverse of ratatui's canvas mapping), and the
//! drag is one undoable edit from press to release.

use super::app::{App, CurveView, Panel};
use super::points::PointSel;
use ratatui::crossterm::event::{MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::{Position, Rect};

/// A curve chart as drawn: its plotting area (inside the axes) and bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChartHit {
    /// The chart.
    pub view: CurveView,
    /// The cells the data is plotted in.
    pub graph: Rect,
    /// x bounds (left, right).
    pub x: [f64; 2],
    /// y bounds (bottom, top), in the chart's units.
    pub y: [f64; 2],
}

impl ChartHit {
    /// The cell a point (chart units) is drawn in by a one-point-a-cell marker, as ratatui's
    /// canvas rounds it; `None` outside the bounds.
    #[must_use]
    pub fn cell_of(&self, x: f64, y: f64) -> Option<Position> {
        let (w, h) = (f64::from(self.graph.width), f64::from(self.graph.height));
        let (dx, dy) = (self.x[1] - self.x[0], self.y[1] - self.y[0]);
        if x < self.x[0] || x > self.x[1] || y < self.y[0] || y > self.y[1] || dx <= 0.0 || dy <= 0.0 {
            return None;
        }
        let col = ((x - self.x[0]) * (w - 1.0) / dx).round() as u16;
        let row = ((self.y[1] - y) * (h - 1.0) / dy).round() as u16;
        Some(Position::new(self.graph.x + col, self.graph.y + row))
    }

    /// The chart coordinates of a cell's centre (the inverse of [`ChartHit::cell_of`]),
    /// clamped to the plotting area.
    #[must_use]
    pub fn coords_of(&self, cell: Position) -> (f64, f64) {
        let col = f64::from(cell.x.clamp(self.graph.x, self.graph.right().saturating_sub(1)) - self.graph.x);
        let row = f64::from(cell.y.clamp(self.graph.y, self.graph.bottom().saturating_sub(1)) - self.graph.y);
        let (w, h) = (f64::from(self.graph.width.max(2)), f64::from(self.graph.height.max(2)));
        (self.x[0] + col * (self.x[1] - self.x[0]) / (w - 1.0), self.y[1] - row * (self.y[1] - self.y[0]) / (h - 1.0))
    }
}

/// What the last frame drew where.
#[derive(Clone, Debug, Default)]
pub struct Hits {
    /// Panels and the area each covers.
    pub panels: Vec<(Rect, Panel)>,
    /// The small screen's tabs.
    pub tabs: Vec<(Rect, Panel)>,
    /// Editor rows showing a parameter (index into `PARAMS`).
    pub rows: Vec<(Rect, usize)>,
    /// Curve charts.
    pub charts: Vec<ChartHit>,
}

impl Hits {
    fn tab_at(&self, at: Position) -> Option<Panel> {
        self.tabs.iter().find(|(r, _)| r.contains(at)).map(|(_, p)| *p)
    }

    fn panel_at(&self, at: Position) -> Option<Panel> {
        self.panels.iter().find(|(r, _)| r.contains(at)).map(|(_, p)| *p)
    }

    fn row_at(&self, at: Position) -> Option<usize> {
        self.rows.iter().find(|(r, _)| r.contains(at)).map(|(_, i)| *i)
    }

    fn chart_at(&self, at: Position) -> Option<ChartHit> {
        self.charts.iter().find(|c| c.graph.contains(at)).copied()
    }
}

impl App {
    /// Where the last frame drew the chart of `view`, if it did.
    #[must_use]
    pub fn chart_drawn(&self, view: CurveView) -> Option<ChartHit> {
        self.hits.borrow().charts.iter().find(|c| c.view == view).copied()
    }

    /// Handles one mouse event (the loop ignores plain moves; none of them does anything).
    pub(super) fn on_mouse(&mut self, event: MouseEvent) {
        if self.overlay.is_some() {
            return;
        }
        let at = Position::new(event.column, event.row);
        let hits = self.hits.borrow().clone();
        match event.kind {
            MouseEventKind::Down(MouseButton::Left) => self.press(&hits, at),
            MouseEventKind::Drag(MouseButton::Left) => self.drag_to(&hits, at),
            MouseEventKind::Up(MouseButton::Left) => self.end_drag(),
            MouseEventKind::ScrollUp | MouseEventKind::ScrollDown if hits.panel_at(at) == Some(Panel::Editor) => {
                self.message = None;
                self.panel = Panel::Editor;
                self.step_selected(if event.kind == MouseEventKind::ScrollUp { 1.0 } else { -1.0 });
            }
            _ => {}
        }
    }

    fn press(&mut self, hits: &Hits, at: Position) {
        if let Some(panel) = hits.tab_at(at) {
            self.panel = panel;
            return;
        }
        if let Some(i) = hits.row_at(at) {
            self.selected = i;
            self.panel = Panel::Editor;
            self.leave_points();
            return;
        }
        if let Some(chart) = hits.chart_at(at) {
            self.panel = Panel::Curves;
            match self.point_near(&chart, at) {
                Some(index) => self.start_drag(PointSel { view: chart.view, index }),
                None => self.message = Some("press on a control point (yellow) to drag it".into()),
            }
            return;
        }
        if let Some(panel) = hits.panel_at(at) {
            self.panel = panel;
            if panel != Panel::Curves {
                self.leave_points();
            }
        }
    }

    /// The control point drawn nearest `at`, if within one cell of it (a join wins a tie
    /// with its handles, which start on it for a flat tangent only rarely).
    fn point_near(&self, chart: &ChartHit, at: Position) -> Option<usize> {
        let map = self.edit_map(chart.view);
        let points = self.design_points(map.name);
        let distance = |i: usize| {
            let (x, y) = points[i];
            chart.cell_of(x, map.shown(y)).map(|c| {
                let (dc, dr) = (i32::from(c.x) - i32::from(at.x), i32::from(c.y) - i32::from(at.y));
                (dc.abs().max(dr.abs()), !i.is_multiple_of(3))
            })
        };
        (0..points.len())
            .filter_map(|i| distance(i).map(|d| (d, i)))
            .filter(|((d, _), _)| *d <= 1)
            .min()
            .map(|(_, i)| i)
    }

    fn drag_to(&mut self, hits: &Hits, at: Position) {
        let (Some(sel), Some(_)) = (self.point, self.drag.as_ref()) else { return };
        let Some(chart) = hits.charts.iter().find(|c| c.view == sel.view) else { return };
        let map = self.edit_map(sel.view);
        let (x, shown) = chart.coords_of(at);
        let Some(y) = map.design(shown) else {
            self.message = Some(format!("refused: the chart's range is zero; set the range of {} first", map.name));
            return;
        };
        // A cell is about 1/40 of the chart: coordinates rounded to 4 decimals keep the
        // saved file readable and lose nothing the pointer could say.
        let round = |v: f64| (v * 1e4).round() / 1e4;
        self.move_point(sel, (round(x), round(y)), false);
    }
}
