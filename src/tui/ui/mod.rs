//! Drawing the lab: a wide layout that shows every panel, and a narrow one (80x24 and up)
//! with the walk beside one tabbed panel.

pub mod curves;
pub mod panels;
pub mod walk;

use super::app::{App, Panel};
use ratatui::prelude::*;
use ratatui::symbols::Marker;
use ratatui::widgets::Tabs;

/// Screens at least this big get every panel at once.
pub const WIDE: (u16, u16) = (140, 40);

/// Draws the whole screen.
pub fn draw(f: &mut Frame, app: &App, marker: Marker) {
    let area = f.area();
    let [main, status] = Layout::vertical([Constraint::Min(1), Constraint::Length(1)]).areas(area);
    if area.width >= WIDE.0 && area.height >= WIDE.1 {
        let [left, middle, right] =
            Layout::horizontal([Constraint::Percentage(40), Constraint::Percentage(32), Constraint::Percentage(28)])
                .areas(main);
        let [walk_area, joints] =
            Layout::vertical([Constraint::Percentage(58), Constraint::Percentage(42)]).areas(left);
        walk::draw(f, walk_area, app, marker);
        curves::draw_joints(f, joints, app, marker);
        let [curve_area, optimiser] =
            Layout::vertical([Constraint::Percentage(55), Constraint::Percentage(45)]).areas(middle);
        curves::draw_curves(f, curve_area, app, marker);
        panels::draw_optimiser(f, optimiser, app, marker);
        panels::draw_editor(f, right, app);
    } else {
        let [walk_area, side] =
            Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(main);
        walk::draw(f, walk_area, app, marker);
        let [tabs, panel] = Layout::vertical([Constraint::Length(1), Constraint::Min(1)]).areas(side);
        let selected = Panel::ALL.iter().position(|p| *p == app.panel).unwrap_or(0);
        f.render_widget(
            Tabs::new(Panel::ALL.map(Panel::title))
                .select(selected)
                .highlight_style(Style::new().reversed())
                .divider("|"),
            tabs,
        );
        match app.panel {
            Panel::Editor => panels::draw_editor(f, panel, app),
            Panel::Curves => curves::draw_curves(f, panel, app, marker),
            Panel::Joints => curves::draw_joints(f, panel, app, marker),
            Panel::Optimiser => panels::draw_optimiser(f, panel, app, marker),
        }
    }
    panels::draw_status(f, status, app);
    panels::draw_overlay(f, area, app);
}
