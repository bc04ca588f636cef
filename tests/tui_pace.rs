//! The lab's pace keys (issue 14, point 4): `+` / `-` change the walking speed by 0.1 m/s over
//! the next two steps, as an undoable edit of `walk.speed_mps`; `w` stops the walk and,
//! standing, sets off; the status line says whether the walk is standing, starting, walking or
//! stopping.

mod lab_state;

use gaitlab::model::walk::pace::WalkState;
use gaitlab::tui::app::App;
use gaitlab::tui::ui;
use lab_state::load_app;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::symbols::Marker;

const FPS: f64 = 60.0;

thread_local! {
    /// Every frame each test walked, for the stance checks at its end.
    static WALKED: std::cell::RefCell<Vec<gaitlab::model::walk::frame::Frame>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// No foot slid in stance, nothing out of reach or not finite, over all the test walked.
fn assert_walked_cleanly() {
    let checks = WALKED.with(|w| gaitlab::analysis::checks(&w.borrow()));
    assert!(checks.foot_skate_mm < 1.0, "{checks:?}");
    assert_eq!((checks.reach_failures, checks.non_finite_values), (0, 0), "{checks:?}");
}

/// The lab drawn at `width` x `height`, a line a row.
fn screen(app: &App, width: u16, height: u16) -> Vec<String> {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|f| ui::draw(f, app, Marker::Braille)).unwrap();
    let buffer = terminal.backend().buffer();
    (0..height).map(|y| (0..width).map(|x| buffer[(x, y)].symbol().to_string()).collect()).collect()
}

fn status_line(app: &App) -> String {
    screen(app, 100, 30).pop().unwrap()
}

fn key(app: &mut App, c: char) {
    gaitlab::tui::effects::step(app, gaitlab::tui::app::Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE)));
}

/// Walks `seconds` and returns the pelvis's mean forward speed over them (m/s).
fn walk(app: &mut App, seconds: f64) -> f64 {
    let from = app.frame.pelvis.x;
    let frames = (seconds * FPS).round() as usize;
    for _ in 0..frames {
        app.tick(1.0 / FPS);
        WALKED.with(|w| w.borrow_mut().push(app.frame.clone()));
    }
    (app.frame.pelvis.x - from) / (frames as f64 / FPS)
}

#[test]
fn plus_and_minus_change_the_pace_over_two_steps_as_an_undoable_edit() {
    let mut app = load_app(None, &[]).unwrap();
    let cycle_s = app.params.resolve().cycle_s;
    walk(&mut app, 2.0);
    assert!(status_line(&app).contains("walking"), "{}", status_line(&app));
    key(&mut app, '+');
    key(&mut app, '+');
    assert!((app.params.walk.speed_mps - 1.5).abs() < 1e-12, "{}", app.params.walk.speed_mps);
    assert!(app.is_modified());
    assert!(app.message.as_deref().unwrap_or_default().contains("reached over two steps"), "{:?}", app.message);
    // Two steps to reach it, then a few cycles at the new pace: within 3 %.
    walk(&mut app, 2.0);
    let speed = walk(&mut app, 3.0 * cycle_s);
    assert!((speed / 1.5 - 1.0).abs() < 0.03, "walked {speed} m/s after asking 1.5");
    // `-` three times: 1.2 m/s.
    for _ in 0..3 {
        key(&mut app, '-');
    }
    walk(&mut app, 2.0);
    let speed = walk(&mut app, 3.0 * cycle_s);
    assert!((app.params.walk.speed_mps - 1.2).abs() < 1e-12);
    assert!((speed / 1.2 - 1.0).abs() < 0.03, "walked {speed} m/s after asking 1.2");
    // Each press is an edit: five undos bring back the file's 1.3 m/s, unmodified.
    for _ in 0..5 {
        key(&mut app, 'u');
    }
    assert!((app.params.walk.speed_mps - 1.3).abs() < 1e-12);
    assert!(!app.is_modified());
    walk(&mut app, 2.0);
    let speed = walk(&mut app, 3.0 * cycle_s);
    assert!((speed / 1.3 - 1.0).abs() < 0.03, "walked {speed} m/s after undoing back to 1.3");
    assert_walked_cleanly();
}

#[test]
fn w_stops_the_walk_and_the_status_line_follows_it_to_standing() {
    let mut app = load_app(None, &[]).unwrap();
    walk(&mut app, 2.0);
    key(&mut app, 'w');
    assert_eq!(app.walker.walk_state(), WalkState::Stopping);
    assert!(status_line(&app).contains("stopping"), "{}", status_line(&app));
    walk(&mut app, 3.0);
    assert_eq!(app.walker.walk_state(), WalkState::Standing);
    assert!(status_line(&app).contains("standing"), "{}", status_line(&app));
    // The walk panel says both legs stand (no phase fraction cycling under a body at rest).
    let walk_panel = screen(&app, 100, 30).join("\n");
    assert!(walk_panel.contains("R standing  L standing"), "{walk_panel}");
    // At rest: the pelvis does not move over a second.
    assert!(walk(&mut app, 1.0).abs() < 1e-9);
    // A pace key while standing sets the speed the walk sets off at, and nothing moves.
    key(&mut app, '+');
    assert!((app.params.walk.speed_mps - 1.4).abs() < 1e-12);
    assert!((app.walker.params().walk.speed_mps - 1.4).abs() < 1e-12);
    assert!(app.message.as_deref().unwrap_or_default().contains("the speed w sets off at"), "{:?}", app.message);
    assert!(walk(&mut app, 0.5).abs() < 1e-9);
    assert_eq!(app.walker.walk_state(), WalkState::Standing);
    // `r` walks again.
    key(&mut app, 'r');
    assert_eq!(app.walker.walk_state(), WalkState::Walking);
    assert!(walk(&mut app, 2.0) > 1.0);
}

#[test]
fn w_while_standing_sets_off_and_the_status_line_says_starting_then_walking() {
    let mut app = load_app(None, &[]).unwrap();
    walk(&mut app, 2.0);
    key(&mut app, 'w');
    walk(&mut app, 3.0);
    assert_eq!(app.walker.walk_state(), WalkState::Standing);
    key(&mut app, 'w');
    assert_eq!(app.walker.walk_state(), WalkState::Starting);
    assert!(status_line(&app).contains("starting"), "{}", status_line(&app));
    assert!(app.message.as_deref().unwrap_or_default().contains("starting from standing"), "{:?}", app.message);
    // While starting, `w` and the pace keys say why they wait.
    key(&mut app, 'w');
    assert_eq!(app.walker.walk_state(), WalkState::Starting);
    assert!(app.message.as_deref().unwrap_or_default().starts_with("starting:"), "{:?}", app.message);
    walk(&mut app, 2.0);
    assert_eq!(app.walker.walk_state(), WalkState::Walking);
    assert!(status_line(&app).contains("walking"), "{}", status_line(&app));
    let cycle_s = app.walker.resolved().cycle_s;
    let speed = walk(&mut app, 3.0 * cycle_s);
    assert!((speed / 1.3 - 1.0).abs() < 0.03, "walked {speed} m/s after setting off again");
    // And it stops again.
    key(&mut app, 'w');
    walk(&mut app, 3.0);
    assert_eq!(app.walker.walk_state(), WalkState::Standing);
    assert_walked_cleanly();
}

#[test]
fn a_stopped_walk_stood_still_with_its_feet_planted() {
    let mut app = load_app(None, &[]).unwrap();
    walk(&mut app, 2.0);
    key(&mut app, 'w');
    walk(&mut app, 4.0);
    assert_walked_cleanly();
}

#[test]
fn the_optimiser_table_marks_the_starts_first_step_and_the_closing_step_as_fixed() {
    let config = std::path::Path::new("configs").join("start_stop.toml");
    let mut app = load_app(Some(&config), &[]).unwrap();
    walk(&mut app, 8.0);
    let screen = screen(&app, 160, 45);
    let rows: Vec<&String> = screen.iter().filter(|l| l.contains(" 0.500 ")).collect();
    // "fixed" under cost, "-" under the rule's cost (six cells and a space).
    let uncosted: Vec<&&String> = rows.iter().filter(|l| l.contains("fixed  -")).collect();
    // The closing step of the stop at 6 s, and the start's first step (if still in view).
    assert!(!uncosted.is_empty(), "{}", screen.join("\n"));
    assert!(rows.iter().all(|l| !l.contains("none")), "{}", screen.join("\n"));
    assert_walked_cleanly();
}

#[test]
fn the_status_line_keeps_the_pace_message_whole_at_80_columns_and_cuts_it_only_when_nothing_else_can_go() {
    // A config deep in folders, as users keep them: at 80 columns its path and the rest of
    // the line used to leave the message 16 characters.
    let dir = std::env::temp_dir()
        .join(format!("gaitlab-status-{}", std::process::id()))
        .join("projects/walk-studies/2026/treadmill-sessions");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("start_stop.toml");
    std::fs::copy("configs/start_stop.toml", &path).unwrap();
    let mut app = load_app(Some(&path), &[]).unwrap();
    // Walking from 2.07 s: the start asked at 0.5 s waits for the right moment of the cycle.
    walk(&mut app, 2.5);
    let at = |app: &App, width: u16| screen(app, width, 24).pop().unwrap();
    // Wide: every part, the whole path included.
    assert!(at(&app, 160).contains(&path.display().to_string()), "{}", at(&app, 160));
    key(&mut app, '+');
    let message = "walk.speed_mps = 1.4, reached over two steps";
    let line = at(&app, 80);
    assert!(line.contains(message) && line.contains("walking") && line.contains("modified (1)"), "{line}");
    // The folders go before the message does, then (at 80 columns, until the next key clears
    // the message) the file's name; with 20 columns more the name is back.
    assert!(!line.contains("treadmill-sessions"), "{line}");
    let line = at(&app, 100);
    assert!(line.contains(" start_stop.toml ") && line.contains(message) && !line.contains("2026"), "{line}");
    // 60 columns hold the saved state, the walk's state and the message's start only.
    let line = at(&app, 60);
    assert!(line.contains("modified (1)  walking walk.speed_mps = 1.4, re") && line.ends_with('…'), "{line}");
    key(&mut app, 'w');
    let line = at(&app, 80);
    assert!(line.contains("stopping: a braking step, then the feet side by side"), "{line}");
    // Too narrow for the whole message even alone: cut with an ellipsis, the state kept.
    let line = at(&app, 60);
    assert!(line.contains("stopping stopping: a braking step") && line.ends_with('…'), "{line}");
    walk(&mut app, 4.0);
    assert_walked_cleanly();
    std::fs::remove_dir_all(std::env::temp_dir().join(format!("gaitlab-status-{}", std::process::id()))).ok();
}

/// A press moves the speed by 0.1 m/s from wherever it is: from 1.75 m/s, `+` asks 1.85 and
/// `-` then 1.75 (rounded to the 0.1 grid they asked 1.9 and 1.6).
#[test]
fn plus_and_minus_step_by_a_tenth_from_any_speed() {
    let mut app = load_app(None, &["walk.speed_mps=1.75".to_string()]).unwrap();
    walk(&mut app, 1.0);
    key(&mut app, '+');
    assert_eq!(app.params.walk.speed_mps, 1.85);
    assert!(app.message.as_deref().unwrap_or_default().contains("walk.speed_mps = 1.85"), "{:?}", app.message);
    key(&mut app, '-');
    key(&mut app, '-');
    assert_eq!(app.params.walk.speed_mps, 1.65);
    assert!(app.message.as_deref().unwrap_or_default().contains("walk.speed_mps = 1.65,"), "{:?}", app.message);
    // A whole tenth is said with its tenth: "1.0", not "1".
    let mut app = load_app(None, &[]).unwrap();
    walk(&mut app, 1.0);
    for _ in 0..3 {
        key(&mut app, '-');
    }
    assert!(app.message.as_deref().unwrap_or_default().contains("walk.speed_mps = 1.0,"), "{:?}", app.message);
}
