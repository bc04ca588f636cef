//! The terminal lab: the event loop, the terminal's set-up and its restoration.
//!
//! Over SSH every byte counts, so the loop draws only when something changed — a key, a
//! resize, or a walk frame at the capped rate (`--fps`) — writes through a buffer, and wraps
//! each frame in a synchronized update so the terminal shows it whole. Paused with no input,
//! it draws nothing and sleeps in `poll`.

pub mod app;
mod editing;
pub mod effects;
pub mod export;
mod frame_clock;
pub mod keys;
pub mod mouse;
pub mod msg;
mod overlays;
mod pace;
pub mod points;
pub mod recovery;
pub mod save;
mod showing;
pub mod text_input;
pub mod ui;
pub mod views;
pub mod watch;

use crate::config::{self, presets};
use app::App;
use frame_clock::FrameClock;
use ratatui::Terminal;
use ratatui::backend::{Backend, CrosstermBackend};
use ratatui::crossterm::event::{self, DisableMouseCapture, EnableMouseCapture, Event, KeyEventKind, MouseEventKind};
use ratatui::crossterm::terminal::{
    BeginSynchronizedUpdate, Clear, ClearType, EndSynchronizedUpdate, EnterAlternateScreen, LeaveAlternateScreen,
    disable_raw_mode, enable_raw_mode,
};
use ratatui::crossterm::{cursor, execute};
use ratatui::symbols::Marker;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How the lab is started.
#[derive(Clone, Debug)]
pub struct Options {
    /// Config file (`None`: the embedded default).
    pub config: Option<PathBuf>,
    /// `--set` overrides.
    pub sets: Vec<String>,
    /// Redraw cap while walking (frames/s).
    pub fps: f64,
    /// Canvas and chart marker.
    pub(crate) marker: Marker,
    /// Capture the mouse (clicks, drags, wheel); off with `--no-mouse`, which leaves the
    /// terminal's own selection and scrolling alone.
    pub mouse: bool,
}

/// Whether the lab turned mouse capture on: every restore path turns it off again (and
/// writes nothing about the mouse when it was never on).
pub(crate) static MOUSE_CAPTURED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// The `--marker` names.
pub(crate) const MARKERS: &[(&str, Marker)] =
    &[("braille", Marker::Braille), ("halfblock", Marker::HalfBlock), ("block", Marker::Block)];

/// Builds the lab's state from the options (no terminal needed): the config read, `--set`
/// applied, the walk started.
pub fn load_app(config: Option<&Path>, sets: &[String]) -> crate::Result<App> {
    match config {
        Some(path) => {
            // Read once: a pipe (`gaitlab <(...)`) gives its bytes only once, and the size
            // limit and deadline of `read_source` keep /dev/zero or a FIFO from hanging the lab.
            let (text, params) = config::load_with_text(path, sets)?;
            let keymap = keys::KeyMap::from_config(&text, &path.display().to_string())?;
            let mut app = App::new(params, text, Some(path.to_path_buf()))
                .map_err(|source| crate::Error::Walk { config: path.to_path_buf(), source })?;
            app.keymap = keymap;
            app.overlay = recovery::find(Some(path)).map(|found| app::Overlay::Recovery { found, error: None });
            Ok(app)
        }
        None => {
            let params = config::load_text(presets::default_text(), "(embedded default)", sets)?;
            let mut app = App::new(params, presets::default_text().to_string(), None)?;
            app.overlay = recovery::find(None).map(|found| app::Overlay::Recovery { found, error: None });
            Ok(app)
        }
    }
}

/// Puts the terminal back: mouse capture off, raw mode off, main screen, cursor shown. Safe
/// to call twice.
fn restore_terminal() {
    let mut out = io::stdout();
    if MOUSE_CAPTURED.swap(false, std::sync::atomic::Ordering::SeqCst) {
        let _ = execute!(out, DisableMouseCapture);
    }
    let _ = execute!(out, EndSynchronizedUpdate, LeaveAlternateScreen, cursor::Show);
    let _ = disable_raw_mode();
}

/// Restores the terminal when dropped, whichever way the loop ends.
struct TerminalGuard;

impl Drop for TerminalGuard {
    fn drop(&mut self) {
        restore_terminal();
    }
}

/// Runs the lab until the user quits or a signal asks it to stop. Returns the exit code.
pub fn run(options: &Options) -> i32 {
    if !(1.0..=240.0).contains(&options.fps) {
        eprintln!("gaitlab: --fps {} is out of range; valid: 1 to 240 frames/s", options.fps);
        return 2;
    }
    let mut app = match load_app(options.config.as_deref(), &options.sets) {
        Ok(app) => app,
        Err(e) => {
            eprintln!("{e}");
            return 2;
        }
    };
    app.measure_timings();
    // Checked before a single escape code is written: output redirected to a file must get
    // none of them.
    if let Some(why) = watch::terminal_error() {
        eprintln!(
            "gaitlab: the lab needs a terminal, and {why}; for output without one use `gaitlab simulate` or `gaitlab report`"
        );
        return 2;
    }
    // Signals and a lost terminal are watched on a thread of its own (see `watch`).
    let watch = match watch::Watch::start(recovery::path_for(options.config.as_deref())) {
        Ok(w) => w,
        Err(e) => {
            eprintln!("gaitlab: cannot watch the terminal and signals: {e}");
            return 1;
        }
    };
    let previous_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        restore_terminal();
        previous_hook(info);
    }));
    if let Err(e) = enable_raw_mode()
        .and_then(|()| execute!(io::stdout(), EnterAlternateScreen, cursor::Hide))
        .and_then(|()| capture_mouse(options.mouse))
    {
        restore_terminal();
        eprintln!("gaitlab: cannot set up the terminal: {e}");
        return 1;
    }
    let guard = TerminalGuard;
    let result = event_loop(&mut app, options, &watch);
    if app.quit {
        // Quit on purpose: whatever was left unsaved was the user's choice.
        watch.publish(None);
    } else if result.is_err() {
        // The terminal failed under the loop (a dropped link can end crossterm's read with
        // an error before the watch sees the hang-up): the edits go to the recovery file.
        watch.keep_unsaved();
    }
    watch.loop_done();
    drop(guard);
    // A report still being written by the export thread leaves no partial folder.
    crate::output::pending::remove_all();
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("gaitlab: {e}");
            1
        }
    }
}

/// Turns mouse capture on (noted first, so that a failure half-way is still undone).
fn capture_mouse(on: bool) -> io::Result<()> {
    if !on {
        return Ok(());
    }
    MOUSE_CAPTURED.store(true, std::sync::atomic::Ordering::SeqCst);
    execute!(io::stdout(), EnableMouseCapture)
}

fn draw<B: Backend + Write>(terminal: &mut Terminal<B>, app: &App, marker: Marker) -> io::Result<()>
where
    B::Error: Into<io::Error>,
{
    execute!(terminal.backend_mut(), BeginSynchronizedUpdate)?;
    terminal.draw(|f| ui::draw(f, app, marker)).map_err(Into::into)?;
    execute!(terminal.backend_mut(), EndSynchronizedUpdate)?;
    Write::flush(terminal.backend_mut())
}

/// One input event through the lab; returns whether the screen must be redrawn.
fn handle_event<B: Backend>(app: &mut App, terminal: &mut Terminal<B>, event: Event) -> io::Result<bool>
where
    B::Error: Into<io::Error>,
{
    match event {
        Event::Key(key) if key.kind != KeyEventKind::Release => effects::step(app, app::Msg::Key(key)),
        // Plain moves (any-event tracking reports them) change nothing: no redraw.
        Event::Mouse(mouse) if mouse.kind != MouseEventKind::Moved => effects::step(app, app::Msg::Mouse(mouse)),
        Event::Resize(..) => terminal.autoresize().map_err(Into::into)?,
        _ => return Ok(false),
    }
    Ok(true)
}

fn event_loop(app: &mut App, options: &Options, watch: &watch::Watch) -> io::Result<()> {
    let backend = CrosstermBackend::new(BufWriter::with_capacity(1 << 16, io::stdout()));
    // Never dropped: ratatui's Terminal shows the cursor on drop and, when that fails (the
    // link has dropped), reports it with eprintln!, which panics on the dead terminal — the
    // lab then died with exit 101 before it wrote the unsaved edits to the recovery file (a
    // third of the hang-up tests under load). TerminalGuard restores the terminal instead,
    // ignoring errors; each frame is flushed as it is drawn, so nothing is left unwritten.
    let mut terminal = std::mem::ManuallyDrop::new(Terminal::new(backend)?);
    // Not `terminal.clear()`: it asks the terminal for the cursor position first, and a
    // terminal that never answers (some web and serial consoles) would stop the lab there.
    execute!(terminal.backend_mut(), Clear(ClearType::All))?;
    let mut clock = FrameClock::new(options.fps, Instant::now());
    let mut dirty = true;
    // A way to panic on purpose, so that the restore-on-panic path can be tested through a
    // real terminal (`tests/tui_pty.rs`); nothing else sets it.
    let panic_for_test = std::env::var_os("GAITLAB_TEST_PANIC").is_some();
    // What the recovery file would hold changes with the edits and with each save.
    let mut published = (app.params.clone(), app.saved.clone());
    while !app.quit && !watch.stop_requested() {
        if dirty {
            draw(&mut terminal, app, options.marker)?;
            dirty = false;
            clock.drawn();
            assert!(!panic_for_test, "GAITLAB_TEST_PANIC is set: panicking after the first frame");
        }
        let walking = !app.paused;
        // Idle: wake once a second only to notice a signal; nothing is drawn. A report being
        // written is polled ten times a second for its progress.
        let timeout = if walking {
            clock.until_due(Instant::now())
        } else if app.exporting() {
            Duration::from_millis(100)
        } else {
            Duration::from_secs(1)
        };
        if event::poll(timeout)? {
            // Coalesce: handle everything queued before drawing once.
            loop {
                dirty |= handle_event(app, &mut terminal, event::read()?)?;
                if !event::poll(Duration::ZERO)? {
                    break;
                }
            }
        }
        if app.params != published.0 || app.saved != published.1 {
            published = (app.params.clone(), app.saved.clone());
            watch.publish(app.unsaved_text());
        }
        dirty |= app.poll_export();
        let now = Instant::now();
        if app.paused {
            clock.pause(now);
        } else if let Some(elapsed) = clock.due(now) {
            dirty |= app.tick(elapsed);
        }
        if let Some(fps) = clock.rate(now) {
            app.measured_fps = Some(fps);
        }
    }
    Ok(())
}
