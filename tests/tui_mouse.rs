//! Curves edited by hand in the lab: control points dragged with mouse events and moved
//! with keys, the constraints kept or the move refused, the walk changed live, the curve
//! saved as a `[curves.*]` override; and the mouse on the parameter editor and the tabs.

mod lab_state;

use gaitlab::config::schema::PARAMS;
use gaitlab::model::gait_curves::CurveName;
use gaitlab::tui::app::{App, CurveView, Msg, Panel};
use gaitlab::tui::{effects, ui};
use lab_state::load_app;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::Position;
use ratatui::symbols::Marker;
use std::path::{Path, PathBuf};

/// Draws the lab into a `width` x `height` buffer (as the loop does before reading input);
/// returns the buffer's symbols by row.
fn draw(app: &App, width: u16, height: u16) -> Vec<Vec<String>> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|f| ui::draw(f, app, Marker::Braille)).unwrap();
    let buffer = terminal.backend().buffer();
    (0..height).map(|y| (0..width).map(|x| buffer[(x, y)].symbol().to_string()).collect()).collect()
}

fn key(app: &mut App, code: KeyCode) {
    effects::step(app, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn mouse(app: &mut App, kind: MouseEventKind, at: Position) {
    effects::step(app, Msg::Mouse(MouseEvent { kind, column: at.x, row: at.y, modifiers: KeyModifiers::NONE }));
}

/// A copy of the default config in a scratch folder, so that `s` has a file to write.
fn scratch_config(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-mouse-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("walk.toml");
    std::fs::copy("configs/default.toml", &path).unwrap();
    path
}

fn walked(path: &Path, frames: usize) -> App {
    let mut app = load_app(Some(path), &[]).unwrap();
    for _ in 0..frames {
        app.tick(1.0 / 60.0);
    }
    app
}

/// The lab at 160x48 with the swing heel-height chart shown.
fn on_heel_chart(path: &Path) -> App {
    let mut app = walked(path, 30);
    app.paused = true;
    while CurveView::ALL[app.curve] != CurveView::SwingHeelHeight {
        key(&mut app, KeyCode::Char('c'));
    }
    app
}

#[test]
fn dragging_a_control_point_moves_the_curve_the_walk_and_the_saved_file() {
    let path = scratch_config("drag");
    let original = std::fs::read_to_string(&path).unwrap();
    let mut app = on_heel_chart(&path);
    let mut reference = on_heel_chart(&path);
    draw(&app, 160, 48);
    let view = CurveView::SwingHeelHeight;
    let map = app.edit_map(view);
    assert_eq!(map.name, CurveName::SwingHeelHeight);
    let before = app.design_points(map.name);
    // The join at x = 0.47 (heel 14.2 cm): pressed on its cell, dragged 3 cells right and 4
    // rows up, released.
    let (x0, y0) = before[6];
    let chart = app.chart_drawn(view).unwrap();
    let start = chart.cell_of(x0, map.shown(y0)).unwrap();
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), start);
    assert_eq!(app.point.map(|p| p.index), Some(6), "{:?}", app.message);
    let mut target = start;
    for _ in 0..4 {
        target = Position::new(target.x + 1, target.y - 1);
        target.x = target.x.min(start.x + 3);
        let chart = app.chart_drawn(view).unwrap();
        mouse(&mut app, MouseEventKind::Drag(MouseButton::Left), target);
        // Each drag step lands the point in the cell under the pointer, read through the
        // chart drawn before it.
        let (x, shown) = chart.coords_of(target);
        let after = app.design_points(map.name);
        assert!((after[6].0 - x).abs() < 1e-4 && (map.shown(after[6].1) - shown).abs() < 0.01, "{:?}", after[6]);
        draw(&app, 160, 48);
    }
    mouse(&mut app, MouseEventKind::Up(MouseButton::Left), target);
    let after = app.design_points(map.name);
    let (dx, dy) = (after[6].0 - x0, after[6].1 - y0);
    assert!(dx > 0.0 && dy > 0.0, "moved right and up: {dx} {dy}");
    // Its handles came along (the join stays G1); the other points did not move.
    for i in [5, 7] {
        assert!((after[i].0 - before[i].0 - dx).abs() < 1e-9 && (after[i].1 - before[i].1 - dy).abs() < 1e-9);
    }
    assert_eq!(after[..5], before[..5]);
    assert_eq!(after[8..], before[8..]);
    assert_eq!(app.params.curves["swing_heel_height"], after);
    assert!(app.is_modified());
    // The screen shows the selected point where it now is.
    let screen = draw(&app, 160, 48);
    let chart = app.chart_drawn(view).unwrap();
    let cell = chart.cell_of(after[6].0, map.shown(after[6].1)).unwrap();
    assert_eq!(screen[usize::from(cell.y)][usize::from(cell.x)], "█");
    // The walk: the next swings lift the heel differently from the unedited lab's.
    app.paused = false;
    reference.paused = false;
    let mut most = 0.0f64;
    for _ in 0..120 {
        app.tick(1.0 / 60.0);
        reference.tick(1.0 / 60.0);
        for s in 0..2 {
            most = most.max((app.frame.legs[s].heel.y - reference.frame.legs[s].heel.y).abs());
        }
    }
    assert!(most > 0.005, "the heel heights differ by {most} m at most");
    // `s` writes the override; the file re-loads to the same curve and passes `check`.
    key(&mut app, KeyCode::Char('s'));
    assert!(app.message.as_deref().unwrap_or("").starts_with("saved"), "{:?}", app.message);
    assert!(!app.is_modified());
    let saved = std::fs::read_to_string(&path).unwrap();
    // The file's text is kept, the table appended below its closing comments on curves.
    let (kept, added) = saved.split_at(original.trim_end().len());
    assert_eq!(kept, original.trim_end());
    assert!(added.starts_with("\n\n[curves.swing_heel_height]\npoints = [[0.0, 0.2]"), "{added}");
    let back = gaitlab::config::load(&path, &[]).unwrap();
    assert_eq!(back.curves["swing_heel_height"], after);
    let check = std::process::Command::new(env!("CARGO_BIN_EXE_gaitlab")).arg("check").arg(&path).output().unwrap();
    assert!(check.status.success(), "{}", String::from_utf8_lossy(&check.stdout));
    // The drag was one edit: one undo takes the curve back to the default.
    key(&mut app, KeyCode::Char('u'));
    assert!(app.params.curves.is_empty());
    assert_eq!(app.design_points(map.name), before);
}

#[test]
fn a_drag_that_would_break_x_order_or_a_fixed_end_is_refused_with_a_message() {
    let path = scratch_config("refuse");
    let mut app = on_heel_chart(&path);
    draw(&app, 160, 48);
    let view = CurveView::SwingHeelHeight;
    let map = app.edit_map(view);
    let before = app.design_points(map.name);
    let chart = app.chart_drawn(view).unwrap();
    let start = chart.cell_of(before[6].0, map.shown(before[6].1)).unwrap();
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), start);
    // Left of the previous join (x = 0.16): its handle would pass the one before it.
    let past = chart.cell_of(0.12, map.shown(before[6].1)).unwrap();
    mouse(&mut app, MouseEventKind::Drag(MouseButton::Left), past);
    let message = app.message.clone().unwrap_or_default();
    assert!(message.starts_with("refused:") && message.contains("x must increase"), "{message}");
    assert_eq!(app.design_points(map.name), before);
    assert!(app.params.curves.is_empty() && !app.is_modified());
    mouse(&mut app, MouseEventKind::Up(MouseButton::Left), past);
    assert!(app.params.curves.is_empty() && !app.is_modified());
    let text: String = draw(&app, 160, 48).iter().map(|r| r.concat()).collect::<Vec<_>>().join("\n");
    assert!(text.contains("refused: curve `swing_heel_height`"), "{text}");
    // A curve whose end is fixed (the swing ends on the footfall, progress 1) keeps it.
    while CurveView::ALL[app.curve] != CurveView::SwingForward {
        key(&mut app, KeyCode::Char('c'));
    }
    key(&mut app, KeyCode::Char('<'));
    key(&mut app, KeyCode::Down);
    let message = app.message.clone().unwrap_or_default();
    assert!(message.contains("must end at y = 1"), "{message}");
    assert!(app.params.curves.is_empty());
}

#[test]
fn keys_select_a_point_and_the_arrows_move_it_until_esc() {
    let path = scratch_config("keys");
    let mut app = on_heel_chart(&path);
    let map = app.edit_map(CurveView::SwingHeelHeight);
    let before = app.design_points(map.name);
    // The first press selects the first handle (the start point of a progress curve is
    // pinned), each next one the next point.
    key(&mut app, KeyCode::Char('>'));
    assert_eq!(app.point.map(|p| p.index), Some(1));
    for _ in 0..5 {
        key(&mut app, KeyCode::Char('>'));
    }
    assert_eq!(app.point.map(|p| p.index), Some(6));
    assert_eq!(app.panel, Panel::Curves);
    let selected = app.selected;
    key(&mut app, KeyCode::Up);
    key(&mut app, KeyCode::Right);
    let after = app.design_points(map.name);
    // y by 1/100 of the curve's valid range (0 to 0.5 m), x by 0.01.
    assert!((after[6].1 - before[6].1 - 0.005).abs() < 1e-12 && (after[6].0 - before[6].0 - 0.01).abs() < 1e-12);
    assert_eq!(app.selected, selected, "the arrows moved the point, not the parameter selection");
    assert!(app.message.as_deref().unwrap_or("").contains("join 6/15 of swing_heel_height"), "{:?}", app.message);
    // Two edits, undone one at a time.
    key(&mut app, KeyCode::Char('u'));
    assert!((app.design_points(map.name)[6].0 - before[6].0).abs() < 1e-12);
    key(&mut app, KeyCode::Esc);
    assert_eq!(app.point, None);
    key(&mut app, KeyCode::Down);
    assert_eq!(app.selected, (selected + 1) % PARAMS.len());
}

#[test]
fn a_cycle_curve_s_ends_move_together() {
    let path = scratch_config("cycle");
    let mut app = walked(&path, 10);
    assert_eq!(CurveView::ALL[app.curve], CurveView::PelvisRotation);
    let start = app.design_points(CurveName::PelvisRotation)[0].1;
    key(&mut app, KeyCode::Char('<'));
    for _ in 0..3 {
        key(&mut app, KeyCode::Down);
    }
    // Three steps of 1/100 of the unit shape's range (-1 to 1) down, both ends together.
    let points = app.design_points(CurveName::PelvisRotation);
    let last = points.len() - 1;
    assert!((points[0].1 - (start - 0.06)).abs() < 1e-9 && points[last].1 == points[0].1, "{points:?}");
    assert_eq!((points[0].0, points[last].0), (0.0, 1.0));
    // Sideways, an end does not move, and the status line says why.
    key(&mut app, KeyCode::Left);
    assert_eq!(app.design_points(CurveName::PelvisRotation), points);
    assert!(app.message.as_deref().unwrap_or("").contains("ends stay at x = 0 and x = 1"), "{:?}", app.message);
}

#[test]
fn the_mouse_selects_and_scrolls_parameters_and_switches_tabs() {
    let path = scratch_config("editor");
    let mut app = walked(&path, 10);
    let screen = draw(&app, 160, 48);
    // Click on the row naming walk.cadence_spm.
    let (row, col) = screen
        .iter()
        .enumerate()
        .find_map(|(y, r)| r.concat().find(" cadence_spm").map(|x| (y, r.concat()[..x].chars().count() + 2)))
        .unwrap();
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), Position::new(col as u16, row as u16));
    mouse(&mut app, MouseEventKind::Up(MouseButton::Left), Position::new(col as u16, row as u16));
    assert_eq!(PARAMS[app.selected].key, "walk.cadence_spm");
    // The wheel over the editor steps the selected value by its fine step.
    draw(&app, 160, 48);
    let speed = PARAMS.iter().position(|p| p.key == "walk.speed_mps").unwrap();
    app.selected = speed;
    draw(&app, 160, 48);
    mouse(&mut app, MouseEventKind::ScrollUp, Position::new(col as u16, row as u16));
    assert!((app.params.walk.speed_mps - 1.31).abs() < 1e-9, "{}", app.params.walk.speed_mps);
    mouse(&mut app, MouseEventKind::ScrollDown, Position::new(col as u16, row as u16));
    mouse(&mut app, MouseEventKind::ScrollDown, Position::new(col as u16, row as u16));
    assert!((app.params.walk.speed_mps - 1.29).abs() < 1e-9);
    // On a small screen a click on a tab shows its panel; on the curve panel, it focuses it.
    let screen = draw(&app, 80, 24);
    let tabs = screen[0].concat();
    let joints = tabs.find("Joints").unwrap();
    let x = tabs[..joints].chars().count() as u16 + 1;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), Position::new(x, 0));
    assert_eq!(app.panel, Panel::Joints);
    let curves = tabs[..tabs.find("Curves").unwrap()].chars().count() as u16 + 2;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), Position::new(curves, 0));
    assert_eq!(app.panel, Panel::Curves);
    assert!(draw(&app, 80, 24).iter().any(|r| r.concat().contains("pelvic rotation (deg)")));
    // At 60x20 every tab shows, short (the optimiser's fell off the bar), and a click on the
    // short one still finds it.
    let screen = draw(&app, 60, 20);
    let tabs = screen[0].concat();
    assert!(tabs.contains("Params|Curves|Joints|Optim"), "{tabs}");
    let optim = tabs[..tabs.find("Optim").unwrap()].chars().count() as u16 + 1;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), Position::new(optim, 0));
    assert_eq!(app.panel, Panel::Optimiser);
}
