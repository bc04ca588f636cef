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
pub(crate) const WIDE: (u16, u16) = (140, 40);
/// The smallest terminal the lab draws in (columns, rows); below it, a notice.
pub const MIN: (u16, u16) = (60, 20);

/// Draws a panel's border with a title at the top left and, optionally, one at the bottom
/// left — the cells `Block::bordered().title(..).title_bottom(..)` gives — and returns the
/// inner area. `Block` also restyles every cell of the area and merges each border symbol;
/// on the freshly reset buffer of a frame neither changes anything, and together they cost
/// more than the rest of a panel's frame.
pub fn panel(f: &mut Frame, area: Rect, title: Line<'_>, bottom: Option<Line<'_>>) -> Rect {
    let area = area.intersection(f.area());
    if area.width < 2 || area.height < 2 {
        return Rect { x: area.x, y: area.y, width: 0, height: 0 };
    }
    let buf = f.buffer_mut();
    let (left, top) = (area.x, area.y);
    let (right, bottom_y) = (area.right() - 1, area.bottom() - 1);
    for x in left + 1..right {
        buf[(x, top)].set_char('─');
        buf[(x, bottom_y)].set_char('─');
    }
    for y in top + 1..bottom_y {
        buf[(left, y)].set_char('│');
        buf[(right, y)].set_char('│');
    }
    buf[(left, top)].set_char('┌');
    buf[(right, top)].set_char('┐');
    buf[(left, bottom_y)].set_char('└');
    buf[(right, bottom_y)].set_char('┘');
    let width = area.width - 2;
    title.render(Rect { x: left + 1, y: top, width, height: 1 }, buf);
    if let Some(line) = bottom {
        line.render(Rect { x: left + 1, y: bottom_y, width, height: 1 }, buf);
    }
    Rect { x: left + 1, y: top + 1, width: area.width - 2, height: area.height - 2 }
}

/// Draws the whole screen.
pub fn draw(f: &mut Frame, app: &App, marker: Marker) {
    let area = f.area();
    *app.hits.borrow_mut() = super::mouse::Hits::default();
    if area.width < MIN.0 || area.height < MIN.1 {
        // Below this the panels cannot show a parameter's value or the help's keys: say so
        // instead of drawing a broken screen (keys still work: q quits, the walk goes on).
        let lines = vec![
            Line::raw(format!("gaitlab needs at least {}x{}", MIN.0, MIN.1)),
            Line::raw(format!("(this terminal is {}x{}).", area.width, area.height)),
            Line::raw("Enlarge it, or q to quit."),
        ];
        f.render_widget(ratatui::widgets::Paragraph::new(lines).wrap(ratatui::widgets::Wrap { trim: true }), area);
        return;
    }
    let [main, status] = Layout::vertical([Constraint::Min(1), Constraint::Length(1)]).areas(area);
    if area.width >= WIDE.0 && area.height >= WIDE.1 {
        let [left, middle, right] =
            Layout::horizontal([Constraint::Percentage(40), Constraint::Percentage(32), Constraint::Percentage(28)])
                .areas(main);
        let [walk_area, joints] =
            Layout::vertical([Constraint::Percentage(58), Constraint::Percentage(42)]).areas(left);
        walk::draw(f, walk_area, app, marker);
        curves::draw_joints(f, joints, app, marker);
        app.hits.borrow_mut().panels.extend([
            (joints, Panel::Joints),
            (curve_area_of(middle), Panel::Curves),
            (optimiser_area_of(middle), Panel::Optimiser),
            (right, Panel::Editor),
        ]);
        let (curve_area, optimiser) = (curve_area_of(middle), optimiser_area_of(middle));
        curves::draw_curves(f, curve_area, app, marker);
        panels::draw_optimiser(f, optimiser, app, marker);
        panels::draw_editor(f, right, app);
        let focused = match app.panel {
            Panel::Editor => right,
            Panel::Curves => curve_area,
            Panel::Joints => joints,
            Panel::Optimiser => optimiser,
        };
        mark_focus(f, focused);
    } else {
        let [walk_area, side] =
            Layout::horizontal([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(main);
        walk::draw(f, walk_area, app, marker);
        let [tabs, panel] = Layout::vertical([Constraint::Length(1), Constraint::Min(1)]).areas(side);
        let selected = Panel::ALL.iter().position(|p| *p == app.panel).unwrap_or(0);
        let (titles, divider) = tab_titles(tabs.width);
        f.render_widget(
            Tabs::new(titles)
                .select(selected)
                .highlight_style(Style::new().reversed())
                // No padding, the divider spaced: the four titles fit a 40-column half of an
                // 80-column terminal whole (padded, "Optimiser" lost its last letter).
                .padding("", "")
                .divider(divider),
            tabs,
        );
        record_tabs(app, tabs, panel);
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

/// The style of the border of the panel the keys go to.
pub const FOCUS_BORDER: Style = Style::new().fg(Color::Yellow).add_modifier(Modifier::BOLD);

/// Draws the border of `area` in [`FOCUS_BORDER`]. On the narrow screen the tab bar says
/// which panel the keys (arrows, enter, `<`/`>`) go to; on the wide one every panel is drawn
/// alike, and a newcomer pressing an arrow could not tell whether it would move a parameter
/// or a curve's point.
fn mark_focus(f: &mut Frame, area: Rect) {
    let area = area.intersection(f.area());
    if area.width < 2 || area.height < 2 {
        return;
    }
    let buf = f.buffer_mut();
    let (right, bottom) = (area.right() - 1, area.bottom() - 1);
    for x in area.left()..=right {
        for y in [area.top(), bottom] {
            buf[(x, y)].set_style(FOCUS_BORDER);
        }
    }
    for y in area.top()..=bottom {
        for x in [area.left(), right] {
            buf[(x, y)].set_style(FOCUS_BORDER);
        }
    }
}

fn curve_area_of(middle: Rect) -> Rect {
    Layout::vertical([Constraint::Percentage(55), Constraint::Percentage(45)]).areas::<2>(middle)[0]
}

fn optimiser_area_of(middle: Rect) -> Rect {
    Layout::vertical([Constraint::Percentage(55), Constraint::Percentage(45)]).areas::<2>(middle)[1]
}

/// Where each tab's title is (as `Tabs` lays them out: a space either side, `|` between),
/// and the panel under them, for the mouse.
fn record_tabs(app: &App, tabs: Rect, panel: Rect) {
    let mut hits = app.hits.borrow_mut();
    let mut x = tabs.x;
    let (titles, divider) = tab_titles(tabs.width);
    for (p, title) in Panel::ALL.into_iter().zip(titles) {
        let width = title.chars().count() as u16;
        hits.tabs.push((Rect { x, y: tabs.y, width, height: 1 }.intersection(tabs), p));
        x += width + divider.chars().count() as u16;
    }
    hits.panels.push((panel, app.panel));
}

/// The tab bar's titles and divider for a bar `width` columns wide: the panels' names, or
/// below 40 columns short ones, so that every tab shows (at 60x20 "Optimiser" fell off).
fn tab_titles(width: u16) -> ([&'static str; 4], &'static str) {
    if width >= 40 { (Panel::ALL.map(Panel::title), " | ") } else { (["Params", "Curves", "Joints", "Optim"], "|") }
}
