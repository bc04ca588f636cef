//! The terminal lab: screens rendered into ratatui's `TestBackend` (insta snapshots of the
//! text), key scripts driven into the app, and the real binary in a pseudo-terminal.

mod lab_state;

use gaitlab::config::schema::PARAMS;
use gaitlab::model::gait_curves::CurveName;
use gaitlab::model::walk::leg::LegPhase;
use gaitlab::tui::app::{App, Overlay, Panel};
use gaitlab::tui::ui;
use lab_state::load_app;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::symbols::Marker;
use std::path::{Path, PathBuf};

/// Relative, as a user types it (tests run in the package folder), so screens that show
/// the file name are the same on every machine.
fn config(name: &str) -> PathBuf {
    Path::new("configs").join(format!("{name}.toml"))
}

/// The lab drawn into a `width` x `height` test terminal.
fn rendered(app: &App, width: u16, height: u16) -> ratatui::buffer::Buffer {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|f| ui::draw(f, app, Marker::Braille)).unwrap();
    terminal.backend().buffer().clone()
}

fn screen(app: &App, width: u16, height: u16) -> String {
    let buffer = rendered(app, width, height);
    (0..height)
        .map(|y| (0..width).map(|x| buffer[(x, y)].symbol().to_string()).collect::<String>().trim_end().to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

/// `c` until the curve chart shows `view`.
fn show_curve(app: &mut App, view: gaitlab::tui::app::CurveView) {
    let index = gaitlab::tui::app::CurveView::ALL.iter().position(|v| *v == view).unwrap();
    while app.curve != index {
        key(app, KeyCode::Char('c'));
    }
}

/// One key through the lab as its event loop does it: the state's update, then the effects
/// it asks for (saves, the report thread).
fn press(app: &mut App, key: KeyEvent) {
    gaitlab::tui::effects::step(app, gaitlab::tui::app::Msg::Key(key));
}

fn key(app: &mut App, code: KeyCode) {
    press(app, KeyEvent::new(code, KeyModifiers::NONE));
}

fn keys(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

/// The default lab walked `frames` frames of 1/60 s.
fn walked(app_config: Option<&Path>, frames: usize) -> App {
    let mut app = load_app(app_config, &[]).unwrap();
    for _ in 0..frames {
        app.tick(1.0 / 60.0);
    }
    app
}

fn select(app: &mut App, key_name: &str) {
    let target = PARAMS.iter().position(|p| p.key == key_name).unwrap();
    while app.selected != target {
        key(app, if app.selected < target { KeyCode::Down } else { KeyCode::Up });
    }
}

#[test]
fn default_screen_at_80x24() {
    let app = walked(None, 90);
    let text = screen(&app, 80, 24);
    assert!(text.contains("Walk: side view") && text.contains("Parameters") && text.contains("(embedded default)"));
    insta::assert_snapshot!(text);
}

#[test]
fn default_screen_at_160x48_shows_every_panel() {
    let app = walked(None, 150);
    let text = screen(&app, 160, 48);
    for part in
        ["Walk: side view", "Joint angles", "pelvic rotation (deg)", "Optimiser: thesis", "Parameters", "hip flexion"]
    {
        assert!(text.contains(part), "{part} missing:\n{text}");
    }
    // The curve chart names its line, its points and its cursor (red, as the right leg is).
    assert!(text.contains("x: right cycle (0-1) ─ live • points │ now"), "{text}");
    // The joint traces' time span is in their title, as the walk's clock reads it (150
    // frames at 60 fps walked: the traces end at 2.5 s).
    let span = text.split("Joint angles (deg), ").nth(1).and_then(|t| t.split(" s ").next()).expect("a time span");
    let (t0, t1) = span.split_once(" to ").expect("from and to");
    let (t0, t1): (f64, f64) = (t0.parse().unwrap(), t1.parse().unwrap());
    assert!((t1 - 2.5).abs() < 0.06 && t0 >= 0.0 && t0 < t1, "{span}");
    insta::assert_snapshot!(text);
}

#[test]
fn help_overlay_lists_every_key() {
    let mut app = walked(None, 30);
    key(&mut app, KeyCode::Char('?'));
    assert_eq!(app.overlay, Some(Overlay::Help));
    let text = screen(&app, 80, 24);
    for (actions, what) in gaitlab::tui::keys::HELP {
        let keys = app.keymap.help_keys(actions);
        assert!(text.contains(&keys) && text.contains(what), "{keys} {what}:\n{text}");
    }
    // Every action is on some line of the help.
    for action in gaitlab::tui::keys::Action::ALL {
        assert!(gaitlab::tui::keys::HELP.iter().any(|(a, _)| a.contains(&action)), "{action:?} missing from the help");
    }
    insta::assert_snapshot!(text);
    key(&mut app, KeyCode::Char('x'));
    assert_eq!(app.overlay, None);
}

#[test]
fn editor_shows_an_invalid_typed_value_inline_and_keeps_the_old_one() {
    let mut app = walked(None, 30);
    select(&mut app, "walk.speed_mps");
    key(&mut app, KeyCode::Enter);
    for _ in 0..3 {
        key(&mut app, KeyCode::Backspace);
    }
    keys(&mut app, "9.5");
    key(&mut app, KeyCode::Enter);
    let Some(Overlay::Typing { error: Some(error), .. }) = &app.overlay else { panic!("{:?}", app.overlay) };
    assert!(error.contains("walk.speed_mps") && error.contains("0.4 to 2"), "{error}");
    assert_eq!(app.params.walk.speed_mps, 1.3);
    let text = screen(&app, 80, 24);
    assert!(text.contains("9.5") && text.contains("0.4 to 2"));
    insta::assert_snapshot!(text);
    // Not a number at all.
    for _ in 0..3 {
        key(&mut app, KeyCode::Backspace);
    }
    keys(&mut app, "fast");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(&app.overlay, Some(Overlay::Typing { error: Some(_), .. })));
    key(&mut app, KeyCode::Esc);
    assert_eq!(app.overlay, None);
    assert!(!app.is_modified());
}

#[test]
fn stairs_walk_mid_swing_with_the_adapted_heel_curve() {
    let mut app = load_app(Some(&config("stairs_up")), &[]).unwrap();
    // Onto the stairs (they start at 2 m), then to the middle of a right swing.
    while app.frame.pelvis.x < 3.0
        || !(app.walker.leg(gaitlab::model::body::Side::Right).phase == LegPhase::Swing
            && app.frame.legs[0].phase > 0.8)
    {
        app.tick(1.0 / 60.0);
    }
    show_curve(&mut app, gaitlab::tui::app::CurveView::SwingHeelHeight);
    key(&mut app, KeyCode::Tab);
    assert_eq!(app.panel, Panel::Curves);
    // The swinging foot climbs from its last footfall to its next, two treads (2 × 15 cm)
    // on; the step's heel-height curve ends that far above the design's end.
    let data = gaitlab::tui::ui::curves::curve_data(&app, gaitlab::tui::app::CurveView::SwingHeelHeight);
    let (adapted, design) = (&data.lines[0].2, &data.lines[1].2);
    assert!(
        (adapted.last().unwrap().1 - design.last().unwrap().1 - 30.0).abs() < 1.0,
        "{:?} {:?}",
        adapted.last(),
        design.last()
    );
    assert!(data.cursor.is_some());
    let text = screen(&app, 100, 30);
    assert!(text.contains("swing heel height (cm)") && text.contains("this step") && text.contains("R swing"));
    // The lines are named in the bottom border, in their colours, not in a box over the
    // curve's end (ratatui's legend covered the landing at 160x48).
    assert!(text.contains("x: swing (0-1) ─ this step ─ design • points"), "{text}");
    insta::assert_snapshot!(text);
}

#[test]
fn optimiser_panel_shows_each_step_and_the_landscape() {
    let mut app = walked(Some(&config("default")), 200);
    for _ in 0..3 {
        key(&mut app, KeyCode::Tab);
    }
    assert_eq!(app.panel, Panel::Optimiser);
    let (step, landscape) = app.landscape.clone().unwrap();
    assert_eq!(landscape.len(), 41);
    assert_eq!(step, app.walker.step_plans().last().unwrap().step);
    let text = screen(&app, 80, 24);
    assert!(text.contains("Optimiser: thesis") && text.contains(&format!("step {step}")));
    // At 80 columns the title keeps both keys whole (it lost "method)" to the border), and
    // the landscape's marks are named under it (ratatui's legend box hid itself there).
    assert!(text.contains("Optimiser: thesis (o run, m method)"), "{text}");
    assert!(text.contains("• unreachable █ chosen ─ cost rad²/s³"), "{text}");
    let wide = screen(&app, 160, 48);
    assert!(wide.contains("Optimiser: thesis (o: re-run, m: method)"), "{wide}");
    insta::assert_snapshot!(text);
    // m: next method, applied as an edit and re-run on the last step at once.
    key(&mut app, KeyCode::Char('m'));
    assert_eq!(app.params.optimiser.method.name(), "golden");
    let rerun = app.rerun.clone().unwrap();
    assert_eq!(rerun.method.unwrap().name(), "golden");
    let thesis_cost = app.walker.step_plans().last().unwrap().optimisation.chosen.cost.unwrap();
    assert!(rerun.chosen.cost.unwrap() <= thesis_cost);
    assert!(screen(&app, 80, 24).contains("golden"));
    // The landscape is the re-run step's, with the re-run's choice marked and named: it had
    // stayed on whatever step the walk planned last.
    assert_eq!(app.landscape.as_ref().unwrap().0, rerun.step);
    assert!(screen(&app, 80, 24).contains("• unreachable █ chosen █ re-run ─ cost"));
}

#[test]
fn a_key_script_changes_a_parameter_the_walk_the_curve_and_the_saved_file_and_undo_restores_it() {
    let dir = std::env::temp_dir().join(format!("gaitlab-tui-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mine.toml");
    let original = "# my own walk, keep this comment\n[walk]\nspeed_mps = 1.3 # as measured\n\n[pelvis]\n# tilt from my lab\ntilt_range_deg = 3.0\n";
    std::fs::write(&path, original).unwrap();
    let mut app = load_app(Some(&path), &[]).unwrap();
    for _ in 0..60 {
        app.tick(1.0 / 60.0);
    }
    select(&mut app, "pelvis.tilt_range_deg");
    let fine = App::fine_step(gaitlab::config::schema::spec("pelvis.tilt_range_deg").unwrap());
    for _ in 0..3 {
        key(&mut app, KeyCode::Right);
    }
    press(&mut app, KeyEvent::new(KeyCode::Right, KeyModifiers::SHIFT));
    let expected = 3.0 + 13.0 * fine;
    assert!((app.params.pelvis.tilt_range_deg - expected).abs() < 1e-9, "{}", app.params.pelvis.tilt_range_deg);
    assert_eq!(app.walker.params().pelvis.tilt_range_deg, app.params.pelvis.tilt_range_deg);
    assert_eq!(app.changed_keys(), vec!["pelvis.tilt_range_deg"]);
    assert!(screen(&app, 80, 24).contains("modified (1)"));
    // After a cycle the live tilt curve has the new peak-to-peak range.
    for _ in 0..80 {
        app.tick(1.0 / 60.0);
    }
    let tilt = app.walker.live_curve(CurveName::PelvisTilt).unwrap();
    let (lo, hi) = tilt.y_range(400);
    assert!(((hi - lo).to_degrees() - expected).abs() < 0.05, "tilt range {} vs {expected}", (hi - lo).to_degrees());
    // Save: the value changes, the comments and the other keys stay.
    key(&mut app, KeyCode::Char('s'));
    let saved = std::fs::read_to_string(&path).unwrap();
    assert_eq!(saved, original.replace("tilt_range_deg = 3.0", &format!("tilt_range_deg = {expected}")));
    assert!(!app.is_modified());
    assert_eq!(gaitlab::config::load(&path, &[]).unwrap().pelvis.tilt_range_deg, expected);
    // Undo: back to 3.0 in the app and the walk; the file now differs, so it is marked.
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.params.pelvis.tilt_range_deg, 3.0);
    assert_eq!(app.walker.params().pelvis.tilt_range_deg, 3.0);
    assert!(app.is_modified());
    press(&mut app, KeyEvent::new(KeyCode::Char('r'), KeyModifiers::CONTROL));
    assert!((app.params.pelvis.tilt_range_deg - (3.0 + fine)).abs() < 1e-9);
    // Quitting now asks; esc stays, y quits.
    key(&mut app, KeyCode::Char('q'));
    assert_eq!(app.overlay, Some(Overlay::ConfirmQuit));
    assert!(!app.quit);
    assert!(screen(&app, 80, 24).contains("not saved"));
    key(&mut app, KeyCode::Esc);
    assert!(!app.quit && app.overlay.is_none());
    key(&mut app, KeyCode::Char('q'));
    key(&mut app, KeyCode::Char('y'));
    assert!(app.quit);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn quitting_without_edits_does_not_ask_and_terrain_and_presets_are_picked_from_lists() {
    let mut app = walked(None, 10);
    key(&mut app, KeyCode::Char('t'));
    key(&mut app, KeyCode::Down);
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.value_text(gaitlab::config::schema::spec("terrain.kind").unwrap()), "stairs");
    // A terrain change restarts the walk on the new ground.
    assert_eq!(app.walker.time_s(), 0.0);
    key(&mut app, KeyCode::Char('p'));
    let target = gaitlab::config::presets::PRESETS.iter().position(|(n, _)| *n == "elderly").unwrap();
    for _ in 0..target {
        key(&mut app, KeyCode::Down);
    }
    key(&mut app, KeyCode::Enter);
    let elderly = gaitlab::config::presets::params("elderly").unwrap().unwrap();
    assert_eq!(app.params, elderly);
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    assert!(!app.is_modified());
    key(&mut app, KeyCode::Char('q'));
    assert!(app.quit);
}

#[test]
fn pause_step_speed_and_restart() {
    let mut app = walked(None, 10);
    key(&mut app, KeyCode::Char(' '));
    let t = app.walker.time_s();
    assert!(!app.tick(0.5));
    assert_eq!(app.walker.time_s(), t);
    key(&mut app, KeyCode::Char('.'));
    assert!((app.walker.time_s() - t - 1.0 / 60.0).abs() < 1e-12);
    key(&mut app, KeyCode::Char(' '));
    key(&mut app, KeyCode::Char('['));
    key(&mut app, KeyCode::Char('['));
    assert_eq!(app.speed(), 0.25);
    let t = app.walker.time_s();
    app.tick(0.4);
    assert!((app.walker.time_s() - t - 0.1).abs() < 1e-9);
    key(&mut app, KeyCode::Char('r'));
    assert_eq!(app.walker.time_s(), 0.0);
    key(&mut app, KeyCode::Char('v'));
    assert!(screen(&app, 80, 24).contains("front view"));
}

#[test]
fn a_configs_keys_table_rebinds_keys_and_bad_entries_are_named() {
    let dir = std::env::temp_dir().join(format!("gaitlab-keys-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("keys.toml");
    std::fs::write(&path, "[walk]\nspeed_mps = 1.2\n\n[keys]\nquit = \"Q\"\npause = [\"p\", \"ctrl+space\"]\n")
        .unwrap();
    // The walk's own loader takes the file as it is.
    assert_eq!(gaitlab::config::load(&path, &[]).unwrap().walk.speed_mps, 1.2);
    let mut app = load_app(Some(&path), &[]).unwrap();
    key(&mut app, KeyCode::Char('q'));
    assert!(!app.quit, "q is no longer quit");
    key(&mut app, KeyCode::Char('p'));
    assert!(app.paused && app.overlay.is_none(), "p pauses now, not presets");
    press(&mut app, KeyEvent::new(KeyCode::Char(' '), KeyModifiers::CONTROL));
    assert!(!app.paused);
    assert_eq!(app.keymap.keys_of(gaitlab::tui::keys::Action::Presets), "(unbound)");
    key(&mut app, KeyCode::Char('Q'));
    assert!(app.quit);

    std::fs::write(&path, "[walk]\nspeed_mps = 1.2\n\n[keys]\npuase = \"p\"\n").unwrap();
    let err = load_app(Some(&path), &[]).err().unwrap().to_string();
    assert!(
        err.contains("keys.toml:5:") && err.contains("keys.puase") && err.contains("did you mean `pause`"),
        "{err}"
    );
    std::fs::write(&path, "[keys]\nquit = \"ctrl+\"\n").unwrap();
    let err = load_app(Some(&path), &[]).err().unwrap().to_string();
    assert!(err.contains("keys.toml:2:") && err.contains("not a key; valid:"), "{err}");
    std::fs::write(&path, "[keys]\nquit = 5\n").unwrap();
    let err = load_app(Some(&path), &[]).err().unwrap().to_string();
    assert!(err.contains("expected a key name"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn export_writes_a_report_of_the_edited_parameters_in_the_background() {
    let dir = std::env::temp_dir().join(format!("gaitlab-export-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut app = walked(Some(&config("default")), 10);
    app.export_dir = dir.clone();
    select(&mut app, "walk.speed_mps");
    for _ in 0..10 {
        key(&mut app, KeyCode::Right);
    }
    assert!((app.params.walk.speed_mps - 1.4).abs() < 1e-9);
    key(&mut app, KeyCode::Char('e'));
    assert!(app.exporting());
    // The lab keeps walking while the report is written.
    let t = app.walker.time_s();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    let mut stages = Vec::new();
    while app.exporting() {
        app.tick(1.0 / 60.0);
        if app.poll_export() {
            stages.push(app.message.clone().unwrap_or_default());
        }
        assert!(std::time::Instant::now() < deadline, "the report never finished");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    assert!(app.walker.time_s() > t);
    let last = stages.last().unwrap();
    assert!(last.starts_with("report written to"), "{stages:?}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("default/summary.json")).unwrap()).unwrap();
    assert!((json["speed_mps"].as_f64().unwrap() - 1.4).abs() < 0.02, "{}", json["speed_mps"]);
    let saved = std::fs::read_to_string(dir.join("default/config.toml")).unwrap();
    assert!(saved.contains("speed_mps = 1.4"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_ik_solver_switches_live_from_a_key_and_the_walk_shows_its_error_and_iterations() {
    let mut app = walked(None, 30);
    assert!(screen(&app, 100, 30).contains("IK analytic R 0µm 1it L 0µm 1it"));
    key(&mut app, KeyCode::Char('i'));
    assert_eq!(app.params.ik.solver.name(), "ccd");
    let time_before = app.walker.time_s();
    for _ in 0..20 {
        app.tick(1.0 / 60.0);
    }
    assert!(app.walker.time_s() > time_before, "the walk goes on without a restart");
    let ik = *app.walker.last_ik();
    assert!(ik.iter().all(|a| a.reached && a.position_error <= 1e-4 && a.iterations >= 1), "{ik:?}");
    let text = screen(&app, 100, 30);
    let expected = format!("IK ccd R {:.0}µm {}it", ik[0].position_error * 1e6, ik[0].iterations);
    assert!(text.contains(&expected), "{expected} missing:\n{text}");
    // Three more presses come round to the seed-002 gradient solver; undo goes back.
    keys(&mut app, "iii");
    assert_eq!(app.params.ik.solver.name(), "gradient");
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.params.ik.solver.name(), "jacobian_dls");
    app.tick(1.0 / 60.0);
    assert!(screen(&app, 100, 30).contains("IK jacobian_dls"));
}

#[test]
fn the_embedded_default_saves_to_a_typed_path_and_a_bad_path_is_reported_inline() {
    let dir = std::env::temp_dir().join(format!("gaitlab-saveas-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut app = walked(None, 10);
    select(&mut app, "walk.speed_mps");
    key(&mut app, KeyCode::Right);
    let edited = app.params.walk.speed_mps;
    // No file yet: `s` asks for a path, prefilled.
    key(&mut app, KeyCode::Char('s'));
    let Some(Overlay::SavePath { text, .. }) = &app.overlay else { panic!("{:?}", app.overlay) };
    assert_eq!(text, "my_walk.toml");
    // Clear it and type a path under a file (missing folders would be created, a file in
    // the way cannot be): the error stays in the box.
    for _ in 0..text.len() {
        key(&mut app, KeyCode::Backspace);
    }
    std::fs::write(dir.join("notes.txt"), "a file").unwrap();
    let bad = dir.join("notes.txt/sub/walk.toml");
    keys(&mut app, &bad.display().to_string());
    key(&mut app, KeyCode::Enter);
    let Some(Overlay::SavePath { error: Some(error), .. }) = &app.overlay else { panic!("{:?}", app.overlay) };
    assert!(error.contains("not saved") && error.contains("notes.txt is a regular file, not a folder"), "{error}");
    assert!(app.is_modified() && app.path.is_none(), "a failed save changes nothing");
    assert!(!bad.exists());
    // Now a good path.
    for _ in 0..bad.display().to_string().len() {
        key(&mut app, KeyCode::Backspace);
    }
    let good = dir.join("walk.toml");
    keys(&mut app, &good.display().to_string());
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.overlay, None, "{:?}", app.message);
    assert!(!app.is_modified());
    assert_eq!(app.path.as_deref(), Some(good.as_path()));
    // The file is a whole config (the default's comments kept) that loads to the edited walk.
    let text = std::fs::read_to_string(&good).unwrap();
    assert!(text.contains("# Walking speed"), "comments kept");
    let reloaded = gaitlab::config::parse_str(&text, "walk.toml").unwrap();
    assert_eq!(reloaded.walk.speed_mps, edited);
    assert!(!std::fs::read_dir(&dir).unwrap().any(|e| e.unwrap().file_name().to_string_lossy().contains(".tmp")));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The lab's state writes nothing and starts nothing itself: `update` returns the effects a
/// key asks for, and only running them touches the disk.
#[test]
fn the_labs_state_asks_for_effects_and_the_loop_runs_them() {
    use gaitlab::tui::app::{Effect, Msg};
    let dir = std::env::temp_dir().join(format!("gaitlab-effects-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mine.toml");
    std::fs::write(&path, "[walk]\nspeed_mps = 1.3\n").unwrap();
    let mut app = load_app(Some(&path), &[]).unwrap();
    select(&mut app, "walk.speed_mps");
    let edit = app.update(Msg::Key(KeyEvent::new(KeyCode::Right, KeyModifiers::NONE)));
    assert!(edit.is_empty(), "an edit is state only");
    let effects = app.update(Msg::Key(KeyEvent::new(KeyCode::Char('s'), KeyModifiers::NONE)));
    let [Effect::Save { path: to, text, keys: 1, .. }] = &effects[..] else { panic!("{effects:?}") };
    assert_eq!(to, &path);
    assert!(text.contains("speed_mps = 1.31"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "[walk]\nspeed_mps = 1.3\n", "nothing written yet");
    assert!(app.is_modified());
    gaitlab::tui::effects::run(&mut app, effects);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "[walk]\nspeed_mps = 1.31\n");
    assert!(!app.is_modified());
    assert_eq!(app.message.as_deref(), Some(format!("saved {} (1 key)", path.display()).as_str()));
    // The report: asked for, not started, until the effect runs.
    app.export_dir = dir.join("reports");
    let effects = app.update(Msg::Key(KeyEvent::new(KeyCode::Char('e'), KeyModifiers::NONE)));
    assert!(matches!(&effects[..], [Effect::Export { .. }]), "{effects:?}");
    assert!(!app.exporting());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A bad typed value is told as the CLI tells it (tests/cli.rs): the key, what it needs with
/// range and unit, and what was typed; the old value stays. It read "walk.speed_mps: expected
/// a number, found ...; valid: ...", or the TOML parser's words for a typo.
#[test]
fn the_editor_says_what_the_key_needs_in_the_clis_words() {
    let mut app = walked(None, 5);
    select(&mut app, "walk.speed_mps");
    let needs = "walk.speed_mps needs a number from 0.4 to 2 m/s";
    for (typed, wanted) in [
        ("abc", format!("{needs}, not \"abc\"")),
        ("1.39abc", format!("{needs}, not 1.39abc")),
        ("9.5", format!("{needs}, not 9.5")),
        ("nan", format!("{needs}, not nan")),
        ("", needs.to_string()),
    ] {
        key(&mut app, KeyCode::Enter);
        keys(&mut app, typed);
        if typed.is_empty() {
            key(&mut app, KeyCode::Backspace);
        }
        key(&mut app, KeyCode::Enter);
        let Some(Overlay::Typing { error: Some(error), .. }) = &app.overlay else { panic!("{:?}", app.overlay) };
        assert_eq!(error, &wanted);
        assert!(screen(&app, 100, 30).contains(&wanted), "{typed}: the dialog shows it whole at 100x30");
        key(&mut app, KeyCode::Esc);
    }
    assert_eq!(app.params.walk.speed_mps, 1.3);
    select(&mut app, "terrain.kind");
    key(&mut app, KeyCode::Enter);
    keys(&mut app, "stair");
    key(&mut app, KeyCode::Enter);
    let Some(Overlay::Typing { error: Some(error), .. }) = &app.overlay else { panic!("{:?}", app.overlay) };
    assert_eq!(
        error,
        "terrain.kind needs one of \"flat\", \"stairs\", \"slope\", \"random\", not \"stair\" (did you mean \"stairs\"?)"
    );
}

/// The value editor opens with the value selected: typing replaces it (no backspacing),
/// an arrow keeps it for editing.
#[test]
fn typing_in_the_editor_replaces_the_selected_value() {
    let mut app = walked(None, 5);
    select(&mut app, "walk.speed_mps");
    key(&mut app, KeyCode::Enter);
    keys(&mut app, "1.45");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.params.walk.speed_mps, 1.45);
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::End);
    key(&mut app, KeyCode::Backspace);
    keys(&mut app, "2");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.params.walk.speed_mps, 1.42);
}

/// `g` shows a grid of curves at every size the help promises it: four charts where the
/// panel holds them, two where it holds only that (it used to do nothing below 160x48).
#[test]
fn g_shows_a_grid_of_curves_at_every_common_size() {
    let titles = ["pelvic rotation", "pelvic obliquity", "pelvic tilt", "pelvis vertical"];
    for (width, height, expected) in [(160, 48, 4), (100, 30, 4), (80, 24, 2)] {
        let mut app = walked(Some(&config("default")), 30);
        let before = screen(&app, width, height);
        let shown_before = titles.iter().filter(|t| before.contains(*t)).count();
        key(&mut app, KeyCode::Char('g'));
        let after = screen(&app, width, height);
        let shown = titles.iter().filter(|t| after.contains(*t)).count();
        assert_eq!(shown, expected, "{width}x{height} after g:\n{after}");
        assert!(shown > shown_before.min(1), "{width}x{height}: g changed nothing");
        assert!(after.contains("curves in a grid"), "{width}x{height}: the status line says so");
        if width == 160 {
            // A title too long for its grid cell gives up its clause, then its unit, before
            // any of its name: it read "pelvic obliquity (deg" and "shoulder flexion, righ".
            assert!(after.contains("┌ pelvic obliquity ─"), "{after}");
            let mut app = app;
            // The shoulder's chart is the twelfth.
            for _ in 0..11 {
                key(&mut app, KeyCode::Char('c'));
            }
            let shoulders = screen(&app, width, height);
            assert!(shoulders.contains("┌ shoulder flexion (deg) "), "{shoulders}");
        }
    }
}

/// The status hint follows `[keys]`, and ctrl+c quits whatever quit is bound to, through
/// the unsaved-edits question (a second ctrl+c answers it).
#[test]
fn the_quit_hint_follows_the_bindings_and_ctrl_c_always_quits() {
    let dir = std::env::temp_dir().join(format!("gaitlab-quit-keys-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mine.toml");
    std::fs::write(&path, "[keys]\nquit = \"Q\"\nhelp = \"h\"\n").unwrap();
    let mut app = load_app(Some(&path), &[]).unwrap();
    let shown = screen(&app, 100, 30);
    assert!(shown.contains("h help  Q quit"), "{shown}");
    select(&mut app, "walk.speed_mps");
    key(&mut app, KeyCode::Right);
    press(&mut app, KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL));
    assert_eq!(app.overlay, Some(Overlay::ConfirmQuit));
    assert!(!app.quit);
    press(&mut app, KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL));
    assert!(app.quit);
    let _ = std::fs::remove_dir_all(&dir);
}

/// No parameter name runs into its value, and values stay on screen when the panel is
/// narrow (names are cut first, with an ellipsis).
#[test]
fn parameter_names_never_run_into_values_and_values_always_show() {
    let longest = PARAMS.iter().map(|p| p.name().len()).max().unwrap();
    assert!(gaitlab::tui::ui::panels::NAME_COLUMN > longest, "the name column holds {longest} characters and a space");
    let mut app = walked(Some(&config("default")), 5);
    select(&mut app, "ik.gradient_perturbations");
    for (width, height) in [(160, 48), (100, 30), (80, 24), (60, 20)] {
        let shown = screen(&app, width, height);
        let row =
            shown.lines().find(|l| l.contains("gradient_pert")).unwrap_or_else(|| panic!("{width}x{height}:\n{shown}"));
        assert!(!row.contains("perturbations5"), "{width}x{height}: {row}");
        assert!(
            row.trim_end().trim_end_matches('│').trim_end().ends_with('5'),
            "{width}x{height}: the value shows: {row}"
        );
    }
}

/// Small things a newcomer met: undo names the value now in force, the help's widest keys
/// do not run into their description, a paused lab shows no frame rate.
#[test]
fn undo_says_what_is_in_force_help_keys_fit_and_paused_shows_no_fps() {
    let mut app = walked(Some(&config("default")), 5);
    select(&mut app, "walk.speed_mps");
    key(&mut app, KeyCode::Right);
    key(&mut app, KeyCode::Char('u'));
    // The undo is a speed edit too, walked over two steps (it replaces the ramp to 1.31).
    assert_eq!(app.message.as_deref(), Some("undone: back to walk.speed_mps = 1.3, reached over two steps"));
    key(&mut app, KeyCode::Char('?'));
    let help = screen(&app, 160, 48);
    let row = help.lines().find(|l| l.contains("shift+right L")).expect("the coarse-step line");
    assert!(row.contains("shift+right L  ") || row.contains("shift+right L "), "{row}");
    assert!(!row.contains("Lchange") && !row.contains("Lby"), "{row}");
    // The original fault was a ragged description column, so the coarse step's description
    // must start in the same column as a short key's.
    let column_of = |needle: &str| {
        let line = help.lines().find(|l| l.contains(needle)).unwrap_or_else(|| panic!("{needle}:\n{help}"));
        line[..line.find(needle).expect("found")].chars().count()
    };
    assert_eq!(column_of("change it by a coarse step"), column_of("show or hide this help"), "{help}");
    key(&mut app, KeyCode::Esc);
    app.measured_fps = Some(14.0);
    key(&mut app, KeyCode::Char(' '));
    assert!(app.paused);
    assert!(!screen(&app, 100, 30).contains("14 fps"), "paused: no frame rate");
}

/// Below the documented minimum a notice says so; at the minimum every help line can be
/// reached by scrolling.
#[test]
fn small_terminals_get_a_notice_and_the_help_scrolls() {
    let (min_w, min_h) = gaitlab::tui::ui::MIN;
    let mut app = walked(Some(&config("default")), 5);
    let tiny = screen(&app, 40, 12);
    assert!(tiny.contains(&format!("needs at least {min_w}x{min_h}")) && tiny.contains("40x12"), "{tiny}");
    let at_min = screen(&app, min_w, min_h);
    assert!(!at_min.contains("needs at least"), "{at_min}");
    key(&mut app, KeyCode::Char('?'));
    let mut seen = String::new();
    for _ in 0..gaitlab::tui::keys::HELP.len() {
        seen.push_str(&screen(&app, min_w, min_h));
        key(&mut app, KeyCode::Down);
    }
    assert_eq!(app.overlay, Some(Overlay::Help), "scrolling keeps the help open");
    for (_, what) in gaitlab::tui::keys::HELP {
        let start: String = what.chars().take(20).collect();
        assert!(seen.contains(&start), "`{what}` never shown at {min_w}x{min_h}");
    }
    key(&mut app, KeyCode::Esc);
    assert_eq!(app.overlay, None);
}

/// The arm curves the config lists ([curves.shoulder], [curves.elbow]) are among the charts
/// `c` cycles through, drawn in degrees as the walk plays them.
#[test]
fn the_arm_curves_are_charted_too() {
    let mut app = walked(Some(&config("default")), 30);
    key(&mut app, KeyCode::Char('C'));
    let elbow = screen(&app, 160, 48);
    assert!(elbow.contains("elbow flexion, right (deg)"), "{elbow}");
    key(&mut app, KeyCode::Char('C'));
    let shoulder = screen(&app, 160, 48);
    assert!(shoulder.contains("shoulder flexion, right (deg)"), "{shoulder}");
    // The shoulder swings ±12.5° on the default walk: the axis, padded by 8 % of the range,
    // reads ±14 (it once passed on any "12." elsewhere on the screen).
    assert!(shoulder.contains("│14 │") && shoulder.contains("│-14│"), "{shoulder}");
}

/// At 80 columns the walk panel's status line shows the step number whole: it once cut
/// "step 10" to "step 1".
#[test]
fn the_step_number_is_never_cut_at_80_columns() {
    let app = walked(Some(&config("default")), 420);
    let step = app.walker.footfalls().last().expect("steps were taken").step;
    assert!(step >= 10, "the walk reached two-digit steps: {step}");
    let shown = screen(&app, 80, 24);
    let line = shown.lines().find(|l| l.contains("support ")).unwrap_or_else(|| panic!("{shown}"));
    assert!(line.contains(&format!("step {step} ")) || line.contains(&format!("step {step}│")), "{line}");
}

/// The optimiser table shows a column whole or not at all: at 80 columns the search time
/// (5 cells) does not fit, and a cut "162" read as "16".
#[test]
fn optimiser_columns_are_whole_or_hidden() {
    let mut app = walked(Some(&config("default")), 200);
    for _ in 0..3 {
        key(&mut app, KeyCode::Tab);
    }
    assert_eq!(app.panel, Panel::Optimiser);
    let header = |shown: &str| shown.lines().find(|l| l.contains("ratio cost")).map(str::to_string);
    // Every column fits 80 columns (the search time used to be dropped there without a word);
    // at 60 columns the last ones give way whole, never cut.
    let narrow = header(&screen(&app, 80, 24)).expect("the table's header at 80x24");
    assert!(narrow.contains("step s ratio cost   rule   feas  µs"), "{narrow}");
    let tiny = header(&screen(&app, 60, 20)).expect("the table's header at 60x20");
    assert!(tiny.contains("step s ratio cost   rule ") && !tiny.contains("fe") && !tiny.contains("µ"), "{tiny}");
    let wide = header(&screen(&app, 160, 48)).expect("the table's header at 160x48");
    assert!(wide.contains("feas  µs"), "{wide}");
}

/// A re-run of the optimiser is named in words over its row, apart from the walk's own steps:
/// it was the step number with the method's first letter ("6g"), explained nowhere.
#[test]
fn the_optimisers_rerun_row_says_what_it_is() {
    let mut app = walked(Some(&config("default")), 200);
    for _ in 0..3 {
        key(&mut app, KeyCode::Tab);
    }
    assert_eq!(app.panel, Panel::Optimiser);
    let step = app.walker.step_plans().last().unwrap().step;
    for (press, method) in [('o', "thesis"), ('m', "golden")] {
        key(&mut app, KeyCode::Char(press));
        for (width, height) in [(80, 24), (160, 48)] {
            let shown = screen(&app, width, height);
            let lines: Vec<&str> = shown.lines().collect();
            let header = lines.iter().position(|l| l.contains("ratio cost")).unwrap_or_else(|| panic!("{shown}"));
            // The table's own cells: from the header's "step" on, counted in characters
            // (the walk panel's braille to the left is three bytes a cell).
            let column = lines[header].split("step").next().unwrap().chars().count();
            let cell = |row: usize| lines[row].chars().skip(column).collect::<String>();
            assert!(cell(header + 1).starts_with(&format!("re-run with {method}:")), "{width}x{height}:\n{shown}");
            let rerun = cell(header + 2);
            assert!(rerun.starts_with(&format!("{step} ")), "the step number alone: {rerun:?}");
            assert!(cell(header + 3).starts_with("the walk's steps:"), "{width}x{height}:\n{shown}");
            assert!(cell(header + 4).starts_with(&format!("{step} ")), "{width}x{height}:\n{shown}");
        }
    }
}

/// On the wide screen the panel the keys go to has its border drawn in the focus style, and
/// only that one; `tab` moves it.
#[test]
fn the_wide_screen_marks_the_focused_panel_border() {
    let mut app = walked(None, 30);
    let focused_corners = |app: &App| {
        let buffer = rendered(app, 160, 48);
        let style = ui::FOCUS_BORDER;
        let mut corners: Vec<(u16, u16)> = Vec::new();
        for y in 0..48 {
            for x in 0..160 {
                let cell = &buffer[(x, y)];
                if cell.symbol() == "┌" && cell.fg == style.fg.unwrap() && cell.modifier.contains(style.add_modifier)
                {
                    corners.push((x, y));
                }
            }
        }
        // Every border cell of the marked panel carries the style: its top-right corner too.
        corners
    };
    assert_eq!(app.panel, Panel::Editor);
    let editor = focused_corners(&app);
    assert_eq!(editor.len(), 1, "one marked panel: {editor:?}");
    // The editor is the right-hand column.
    assert!(editor[0].0 > 100, "{editor:?}");
    key(&mut app, KeyCode::Tab);
    assert_eq!(app.panel, Panel::Curves);
    let curves = focused_corners(&app);
    assert_eq!(curves.len(), 1, "{curves:?}");
    assert!((60..110).contains(&curves[0].0) && curves[0].1 == 0, "the curve chart, middle top: {curves:?}");
    // The narrow screen has tabs instead, and no marked border.
    let buffer = rendered(&app, 80, 24);
    let marked = (0..24)
        .flat_map(|y| (0..80).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            buffer[(x, y)].modifier.contains(ratatui::style::Modifier::BOLD) && buffer[(x, y)].symbol() == "┌"
        })
        .count();
    assert_eq!(marked, 0);
}

/// The pelvis charts draw two curves each, too small a chart for ratatui's legend at the
/// lab's sizes: the title names the segments in their lines' colours instead.
#[test]
fn the_two_curve_pelvis_charts_name_their_curves_in_their_colours() {
    let mut app = walked(Some(&config("default")), 30);
    show_curve(&mut app, gaitlab::tui::app::CurveView::PelvisVertical);
    let buffer = rendered(&app, 160, 48);
    let colour_of = |word: &str| {
        (0..48u16).find_map(|y| {
            let row: String = (0..160u16).map(|x| buffer[(x, y)].symbol().to_string()).collect();
            let at = row.find(&format!("vertical {}", "ds>ms"))?;
            let offset = if word == "ds>ms" { 9 } else { 16 };
            let x = row[..at].chars().count() + offset;
            Some(buffer[(x as u16, y)].fg)
        })
    };
    let data = gaitlab::tui::ui::curves::curve_data(&app, gaitlab::tui::app::CurveView::PelvisVertical);
    assert_eq!(
        data.lines.iter().map(|l| l.0.as_str()).collect::<Vec<_>>(),
        ["pelvis_vertical_ds_ms", "pelvis_vertical"]
    );
    assert_eq!(colour_of("ds>ms"), Some(data.lines[0].1));
    assert_eq!(colour_of("ms>ds"), Some(data.lines[1].1));
    // Editing the rise keeps it in its colour: a grey "design" copy once covered it.
    let braille_in = |app: &App, colour| {
        rendered(app, 160, 48)
            .content()
            .iter()
            .filter(|c| c.fg == colour && ('\u{2801}'..='\u{28ff}').contains(&c.symbol().chars().next().unwrap()))
            .count()
    };
    let before = braille_in(&app, data.lines[0].1);
    key(&mut app, KeyCode::Char('>'));
    assert!(app.point.is_some(), "a control point is selected");
    let after = braille_in(&app, data.lines[0].1);
    assert!(after * 10 > before * 9, "the rise's own colour in {after} cells while editing, {before} before");
}

/// On the small screen the curve chart is a tab: `c` from the Parameters tab shows it (the
/// chart it turned was hidden before), the next `c` turns it; on the large screen, where the
/// chart is always in view, `c` turns it at once and the focus stays where it was.
#[test]
fn c_on_another_tab_shows_the_curves_before_turning_them() {
    let mut app = walked(Some(&config("default")), 30);
    let before = screen(&app, 80, 24);
    assert!(before.contains("Parameters") && !before.contains("pelvic obliquity"), "{before}");
    // Every tab's title whole at 80 columns.
    assert!(before.lines().next().is_some_and(|l| l.ends_with("Parameters | Curves | Joints | Optimiser")), "{before}");
    let shown = app.curve;
    key(&mut app, KeyCode::Char('c'));
    let after = screen(&app, 80, 24);
    assert_eq!(app.curve, shown, "the first c only shows the chart");
    assert!(after.contains("curves (c/C: next/previous)"), "{after}");
    key(&mut app, KeyCode::Char('c'));
    assert_ne!(app.curve, shown, "the second c turns it");

    let mut app = walked(Some(&config("default")), 30);
    let _ = screen(&app, 160, 48);
    let (shown, focus) = (app.curve, app.panel);
    key(&mut app, KeyCode::Char('c'));
    assert_ne!(app.curve, shown);
    assert_eq!(app.panel, focus);
}

/// Shift+tab goes back a panel on the small screen (terminals send it as BackTab); it did
/// nothing, so going back one tab took three presses of tab.
#[test]
fn shift_tab_goes_back_a_panel() {
    let mut app = walked(Some(&config("default")), 10);
    assert_eq!(app.panel, Panel::Editor);
    press(&mut app, KeyEvent::new(KeyCode::BackTab, KeyModifiers::SHIFT));
    assert_eq!(app.panel, Panel::Optimiser);
    press(&mut app, KeyEvent::new(KeyCode::BackTab, KeyModifiers::NONE));
    assert_eq!(app.panel, Panel::Joints);
    key(&mut app, KeyCode::Tab);
    assert_eq!(app.panel, Panel::Optimiser);
}
