//! The lab's state and what keys do to it. No terminal here: the loop in `tui/mod.rs` feeds
//! it keys and time, the widgets in `tui/ui` draw it, and tests drive it directly.

use super::export::Export;
use super::keys::{Action, KeyMap};
pub use super::msg::{AfterSave, Effect, Msg};
use super::save;
use super::text_input::TextInput;
pub use super::views::{CurveView, Panel, PickKind, View};
use crate::config::schema::{Kind, PARAMS, Value};
use crate::config::{self, presets};
use crate::model::ik::IkSolverKind;
use crate::model::optimise::{Candidate, StepRecord};
use crate::model::params::{SearchMethod, WalkParams};
use crate::model::walk::frame::Frame;
use crate::model::walk::{ModelError, Walker};
use crate::normative::{Reference, References};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::cell::RefCell;
use std::collections::VecDeque;
use std::path::PathBuf;

/// Simulation speeds offered by `[` and `]`.
const SPEEDS: [f64; 6] = [0.125, 0.25, 0.5, 1.0, 2.0, 4.0];

/// Joint-angle samples kept for the traces: three cycles at 60 samples a second is plenty.
const TRACE_LEN: usize = 240;

/// A modal question or list on top of the screen.
#[derive(Clone, Debug, PartialEq)]
pub enum Overlay {
    /// The key list.
    Help,
    /// Typing a value for the selected key.
    Typing {
        /// The field (pre-filled with the value, selected).
        text: TextInput,
        /// Why the last Enter was refused.
        error: Option<String>,
    },
    /// Typing a path to save to.
    SavePath {
        /// The field (pre-filled, selected).
        text: TextInput,
        /// Why the last Enter was refused.
        error: Option<String>,
    },
    /// Quit with unsaved edits?
    ConfirmQuit,
    /// A lab on this config was cut off with unsaved edits: load them, or discard them?
    Recovery {
        /// The recovery file and its text.
        found: super::recovery::Found,
        /// Why loading it failed, if it did.
        error: Option<String>,
    },
    /// Choosing from a list.
    Pick {
        /// What is picked.
        what: PickKind,
        /// The choices.
        items: Vec<String>,
        /// The highlighted one.
        selected: usize,
    },
}

/// One undoable edit: the whole parameter set before and after, and what changed.
#[derive(Clone, Debug)]
pub(super) struct Edit {
    pub(super) before: WalkParams,
    pub(super) after: WalkParams,
    pub(super) what: String,
}

/// The lab.
pub struct App {
    /// The config file edits are saved to (`None`: the embedded default, saved with a path
    /// the user types).
    pub path: Option<PathBuf>,
    /// The text the saved file is built from (comments and layout kept).
    pub source_text: String,
    /// Parameters in force.
    pub params: WalkParams,
    /// Parameters as last loaded or saved (changed keys are marked against these).
    pub saved: WalkParams,
    /// The walk.
    pub walker: Walker,
    /// The latest frame of the walk.
    pub frame: Frame,
    pub(super) frame_count: u64,
    /// Joint angles of recent frames: time (s), then hip, knee, ankle right, then left (deg),
    /// then the right leg's cycle phase (0 at its heel strike), which places the norms band.
    pub(crate) traces: VecDeque<(f64, [f64; 6], f64)>,
    /// Paused.
    pub paused: bool,
    pub(super) speed_index: usize,
    /// Side or frontal view.
    pub view: View,
    /// Curve chart shown (single mode) or first in the grid.
    pub curve: usize,
    /// Several curves at once.
    pub(crate) grid: bool,
    /// The measured adults' mean ± 1 SD behind the joint traces.
    pub norms: bool,
    /// The built-in norms read at the walk's speed, and that speed (m/s): read again only when
    /// the pace changes (`refresh_norms`), not for every frame that draws the band.
    pub(super) norms_at_speed: (f64, Reference),
    /// Panel beside the walk on narrow screens.
    pub panel: Panel,
    /// The selected parameter (index into [`PARAMS`]).
    pub selected: usize,
    /// What is on top, if anything.
    pub overlay: Option<Overlay>,
    /// A line for the status bar.
    pub message: Option<String>,
    pub(super) undo: Vec<Edit>,
    pub(super) redo: Vec<Edit>,
    /// Quit requested and granted.
    pub quit: bool,
    /// Cost landscape of the last step: its step number and samples.
    pub landscape: Option<(i64, Vec<Candidate>)>,
    /// A re-run of the optimiser on the last step, with the method it used.
    pub rerun: Option<StepRecord>,
    /// Walk frames drawn per second, measured by the loop (`None` in tests: nothing to
    /// measure); redraws for keys and the mouse are not frames of the walk.
    pub measured_fps: Option<f64>,
    /// First line of the help shown (it scrolls on short terminals).
    pub(crate) help_scroll: u16,
    /// The simulation frame step (s).
    pub(crate) sim_dt: f64,
    /// Show wall-clock figures (search times); off in tests, whose screens must repeat.
    pub(crate) show_timings: bool,
    /// Key bindings (the defaults with the config's `[keys]`).
    pub keymap: KeyMap,
    /// Where exported reports go (`<export_dir>/<config stem>`).
    pub export_dir: PathBuf,
    /// A report being written in the background.
    export: Option<Export>,
    /// Effects asked for while handling the current message (taken by [`App::update`]).
    pub(super) effects: Vec<Effect>,
    /// The curve control point being edited: the arrows move it instead of changing the
    /// selected parameter.
    pub point: Option<super::points::PointSel>,
    /// A mouse drag under way: the parameters before it (the drag is one undo step).
    pub(super) drag: Option<WalkParams>,
    /// What the last frame drew where, for the mouse (written by the widgets as they draw).
    pub(crate) hits: RefCell<super::mouse::Hits>,
}

impl App {
    /// A lab on `params`, read from `source_text` (the file at `path`, or the embedded default).
    pub fn new(params: WalkParams, source_text: String, path: Option<PathBuf>) -> Result<Self, ModelError> {
        let walker = Walker::new(&params)?;
        let frame = walker.frame(0);
        let mut app = App {
            path,
            source_text,
            saved: params.clone(),
            params,
            walker,
            frame,
            frame_count: 0,
            traces: VecDeque::with_capacity(TRACE_LEN),
            paused: false,
            speed_index: 3,
            view: View::Side,
            curve: 0,
            grid: false,
            norms: false,
            norms_at_speed: (f64::NAN, References::built_in().blocks[0].clone()),
            panel: Panel::Editor,
            selected: PARAMS.iter().position(|p| p.key == "walk.speed_mps").unwrap_or(0),
            overlay: None,
            message: None,
            undo: Vec::new(),
            redo: Vec::new(),
            quit: false,
            landscape: None,
            rerun: None,
            measured_fps: None,
            help_scroll: 0,
            sim_dt: 1.0 / 60.0,
            show_timings: false,
            keymap: KeyMap::default(),
            export_dir: PathBuf::from("reports"),
            export: None,
            effects: Vec::new(),
            point: None,
            drag: None,
            hits: RefCell::default(),
        };
        app.record_trace();
        app.refresh_norms();
        Ok(app)
    }

    /// Shows wall-clock figures (search times): the walk is given a clock to time its pelvis
    /// searches with. Off in tests, whose screens must repeat.
    pub(crate) fn measure_timings(&mut self) {
        self.show_timings = true;
        self.walker.set_clock(Some(std::time::Instant::now));
    }

    /// The simulation speed factor.
    #[must_use]
    pub fn speed(&self) -> f64 {
        SPEEDS[self.speed_index]
    }

    /// The file name shown in the status bar.
    #[must_use]
    pub(crate) fn file_label(&self) -> String {
        self.path.as_ref().map_or_else(|| "(embedded default)".to_string(), |p| p.display().to_string())
    }

    /// Keys whose value differs from the saved file.
    #[must_use]
    pub fn changed_keys(&self) -> Vec<&'static str> {
        PARAMS.iter().filter(|s| (s.get)(&self.params) != (s.get)(&self.saved)).map(|s| s.key).collect()
    }

    /// What `s` writes: the changed keys, then `curves.<name>` for each curve override
    /// added, changed or removed since the file was loaded or saved.
    #[must_use]
    pub fn unsaved_keys(&self) -> Vec<String> {
        let curves = crate::model::gait_curves::CurveName::ALL
            .iter()
            .map(|c| c.key())
            .filter(|k| self.params.curves.get(*k) != self.saved.curves.get(*k))
            .map(|k| format!("curves.{k}"));
        self.changed_keys().into_iter().map(String::from).chain(curves).collect()
    }

    /// Whether anything differs from the saved file (curve overrides included).
    #[must_use]
    pub fn is_modified(&self) -> bool {
        self.params != self.saved
    }

    /// Walks on by `wall_dt` seconds of real time (scaled by the speed), in frames of at most
    /// `sim_dt`; does nothing while paused. Returns whether anything moved.
    pub fn tick(&mut self, wall_dt: f64) -> bool {
        if self.paused {
            return false;
        }
        let mut left = wall_dt * self.speed();
        let mut moved = false;
        while left > 1e-9 {
            let dt = left.min(self.sim_dt);
            self.advance(dt);
            left -= dt;
            moved = true;
        }
        moved
    }

    fn advance(&mut self, dt: f64) {
        self.walker.advance(dt);
        // A lab left walking overnight would otherwise keep every step's plan (~60 000).
        self.walker.keep_recent_history(crate::model::walk::RECENT_STEPS);
        self.frame_count += 1;
        self.frame = self.walker.frame(self.frame_count);
        self.record_trace();
        self.refresh_landscape();
        self.refresh_norms();
    }

    fn record_trace(&mut self) {
        let [r, l] = &self.frame.legs;
        if self.traces.len() == TRACE_LEN {
            self.traces.pop_front();
        }
        self.traces.push_back((
            self.frame.time_s,
            [r.hip_flex_deg, r.knee_flex_deg, r.ankle_dorsi_deg, l.hip_flex_deg, l.knee_flex_deg, l.ankle_dorsi_deg],
            r.phase,
        ));
    }

    /// Recomputes the landscape when a new step has been planned (once a step: 41 costs).
    fn refresh_landscape(&mut self) {
        let Some(last) = self.walker.step_plans().last() else { return };
        if self.landscape.as_ref().is_some_and(|(step, _)| *step == last.step) {
            return;
        }
        if let Some(problem) = self.walker.last_step_problem() {
            self.landscape = Some((last.step, problem.landscape(&self.walker, 41)));
        }
    }

    /// Starts the walk again with the current parameters, from its first instant (mid-stride:
    /// the double support after a right heel strike; a start from standing is not built).
    pub fn restart(&mut self) {
        match Walker::new(&self.params) {
            Ok(mut w) => {
                if self.show_timings {
                    w.set_clock(Some(std::time::Instant::now));
                }
                self.walker = w;
                self.frame_count = 0;
                self.frame = self.walker.frame(0);
                self.traces.clear();
                self.record_trace();
                self.landscape = None;
                self.rerun = None;
            }
            Err(e) => self.message = Some(format!("cannot restart: {e}")),
        }
    }

    /// Takes one message and returns the effects it asks for (run them with
    /// `tui::effects::run`, or use `tui::effects::step`).
    #[must_use]
    pub fn update(&mut self, msg: Msg) -> Vec<Effect> {
        match msg {
            Msg::Key(key) => self.on_key(key),
            Msg::Mouse(event) => self.on_mouse(event),
            Msg::Saved { path, text, keys, after, result } => self.saved(path, text, keys, after, result),
            Msg::ExportStarted(Ok(export)) => {
                self.export = Some(export);
                self.message = Some("report: starting".into());
            }
            Msg::ExportStarted(Err(e)) => self.message = Some(format!("report not written: {e}")),
        }
        self.refresh_norms();
        std::mem::take(&mut self.effects)
    }

    /// Handles one key press.
    fn on_key(&mut self, key: KeyEvent) {
        // ctrl+c quits whatever the bindings say (a user who rebinds quit can still get out),
        // through the unsaved-edits question; pressed at that question, it quits.
        if key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL) {
            match self.overlay.take() {
                Some(Overlay::ConfirmQuit) => self.quit = true,
                _ => self.perform(Action::Quit),
            }
            return;
        }
        if let Some(overlay) = self.overlay.take() {
            self.on_overlay_key(overlay, key);
            return;
        }
        let Some(action) = self.keymap.action_of(key) else { return };
        self.perform(action);
    }

    /// Does what `action` asks.
    pub(crate) fn perform(&mut self, action: Action) {
        self.message = None;
        if self.point_action(action) || self.pace_action(action) {
            return;
        }
        match action {
            Action::Quit => {
                if self.is_modified() {
                    self.overlay = Some(Overlay::ConfirmQuit);
                } else {
                    self.quit = true;
                }
            }
            Action::Help => {
                self.help_scroll = 0;
                self.overlay = Some(Overlay::Help);
            }
            Action::Pause => self.paused = !self.paused,
            Action::Step => {
                self.paused = true;
                self.advance(self.sim_dt);
            }
            Action::Slower => self.speed_index = self.speed_index.saturating_sub(1),
            Action::Faster => self.speed_index = (self.speed_index + 1).min(SPEEDS.len() - 1),
            Action::Restart => self.restart(),
            Action::Up => self.selected = self.selected.checked_sub(1).unwrap_or(PARAMS.len() - 1),
            Action::Down => self.selected = (self.selected + 1) % PARAMS.len(),
            Action::GroupUp | Action::GroupDown => self.jump_group(action == Action::GroupDown),
            Action::Decrease => self.step_selected(-1.0),
            Action::Increase => self.step_selected(1.0),
            Action::DecreaseCoarse => self.step_selected(-10.0),
            Action::IncreaseCoarse => self.step_selected(10.0),
            Action::Edit => {
                let spec = &PARAMS[self.selected];
                let text = self.value_text(spec);
                self.overlay = Some(Overlay::Typing { text: TextInput::prefilled(text), error: None });
            }
            Action::Reset => {
                let spec = &PARAMS[self.selected];
                let default = (spec.get)(&WalkParams::default());
                self.set_value(spec, &default);
            }
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            Action::Save => match self.path.clone() {
                Some(_) => self.save(),
                None => {
                    self.overlay = Some(Overlay::SavePath { text: TextInput::prefilled("my_walk.toml"), error: None })
                }
            },
            Action::SaveAs => {
                let text = self.path.as_ref().map_or("my_walk.toml".into(), |p| p.display().to_string());
                self.overlay = Some(Overlay::SavePath { text: TextInput::prefilled(text), error: None });
            }
            Action::Presets | Action::Terrain => self.open_picker(action == Action::Terrain),
            Action::ToggleView
            | Action::NextCurve
            | Action::PrevCurve
            | Action::ToggleGrid
            | Action::ToggleNorms
            | Action::NextPanel
            | Action::PrevPanel => self.show(action),
            // Handled by `point_action` and `pace_action` above.
            Action::NextPoint | Action::PrevPoint | Action::LeavePoints => {}
            Action::PaceDown | Action::PaceUp | Action::StopWalk => {}
            Action::RerunOptimiser => self.rerun_optimiser(),
            Action::Export => self.start_export(),
            Action::NextMethod | Action::NextSolver => self.next_choice(action == Action::NextMethod),
        }
    }

    /// `m` / `i`: the next optimiser method (re-run at once) or leg IK solver, as an edit.
    fn next_choice(&mut self, method: bool) {
        if method {
            let i = SearchMethod::ALL.iter().position(|m| *m == self.params.optimiser.method).unwrap_or(0);
            let next = SearchMethod::ALL[(i + 1) % SearchMethod::ALL.len()];
            let spec = config::schema::spec("optimiser.method").expect("a key");
            self.set_value(spec, &Value::Word(next.name()));
            self.rerun_optimiser();
        } else {
            let i = IkSolverKind::ALL.iter().position(|k| *k == self.params.ik.solver).unwrap_or(0);
            let next = IkSolverKind::ALL[(i + 1) % IkSolverKind::ALL.len()];
            let spec = config::schema::spec("ik.solver").expect("a key");
            self.set_value(spec, &Value::Word(next.name()));
        }
    }

    /// Opens the preset list, or the terrain kinds with the current one highlighted.
    fn open_picker(&mut self, terrain: bool) {
        if !terrain {
            let items = presets::PRESETS.iter().map(|(n, t)| format!("{n:<12} {}", presets::description(t))).collect();
            self.overlay = Some(Overlay::Pick { what: PickKind::Preset, items, selected: 0 });
            return;
        }
        let spec = config::schema::spec("terrain.kind").expect("a key");
        let Kind::Choice(words) = spec.kind else { return };
        let current = self.value_text(spec);
        let selected = words.iter().position(|w| *w == current).unwrap_or(0);
        let items = words.iter().map(|w| (*w).to_string()).collect();
        self.overlay = Some(Overlay::Pick { what: PickKind::Terrain, items, selected });
    }

    /// Asks for the edits to be written into the config file (comments kept).
    pub fn save(&mut self) {
        self.request_save(AfterSave::Stay);
    }

    pub(super) fn request_save(&mut self, after: AfterSave) {
        let Some(path) = self.path.clone() else { return };
        let owned = self.unsaved_keys();
        let keys: Vec<&str> = owned.iter().map(String::as_str).collect();
        match save::edited_text(&self.source_text, &self.params, &keys) {
            Ok(text) => self.effects.push(Effect::Save { path, text, keys: keys.len(), after }),
            Err(e) => self.saved(path, String::new(), 0, after, Err(e)),
        }
    }

    /// A save ended.
    fn saved(&mut self, path: PathBuf, text: String, keys: usize, after: AfterSave, result: Result<(), String>) {
        match result {
            Ok(()) => {
                self.source_text = text;
                self.saved = self.params.clone();
                self.message =
                    Some(format!("saved {} ({} key{})", path.display(), keys, if keys == 1 { "" } else { "s" }));
                if after == AfterSave::Quit {
                    self.quit = true;
                }
            }
            Err(e) => {
                let e = format!("not saved: {e}");
                if let AfterSave::SaveAs { typed, old_path } = after {
                    self.path = old_path;
                    self.overlay = Some(Overlay::SavePath { text: typed, error: Some(e.clone()) });
                }
                self.message = Some(e);
            }
        }
    }

    /// What `s` would write now, if anything is unsaved: the text a recovery file keeps.
    #[must_use]
    pub(crate) fn unsaved_text(&self) -> Option<String> {
        if !self.is_modified() {
            return None;
        }
        let owned = self.unsaved_keys();
        let keys: Vec<&str> = owned.iter().map(String::as_str).collect();
        save::edited_text(&self.source_text, &self.params, &keys).ok()
    }

    /// Whether a report is being written.
    #[must_use]
    pub fn exporting(&self) -> bool {
        self.export.is_some()
    }

    /// Asks for a report of the current parameters on a worker thread; the lab stays
    /// responsive and shows the stages in the status line.
    fn start_export(&mut self) {
        if self.export.is_some() {
            self.message = Some("a report is already being written".into());
            return;
        }
        let name =
            self.path.as_ref().and_then(|p| p.file_stem()).map_or("lab".into(), |s| s.to_string_lossy().into_owned());
        self.effects.push(Effect::Export {
            out: self.export_dir.join(&name),
            name,
            params: Box::new(self.params.clone()),
            source_text: self.source_text.clone(),
        });
    }

    /// Takes what the report thread has said; returns whether anything changed on screen.
    pub fn poll_export(&mut self) -> bool {
        let Some(export) = &self.export else { return false };
        let Some(news) = export.poll() else { return false };
        if news.done {
            self.export = None;
        }
        self.message = Some(news.message);
        true
    }

    fn rerun_optimiser(&mut self) {
        let Some(problem) = self.walker.last_step_problem() else {
            self.message = Some("no step planned yet".into());
            return;
        };
        let mut problem = problem.clone();
        problem.settings = self.params.optimiser.clone();
        let started = std::time::Instant::now();
        let problem = problem.with_allowance(&self.walker);
        let candidates = problem.search(&self.walker);
        let elapsed_us = started.elapsed().as_secs_f64() * 1e6;
        let best = candidates
            .iter()
            .filter(|c| c.cost.is_some())
            .min_by(|a, b| a.cost.unwrap().total_cmp(&b.cost.unwrap()))
            .copied();
        let last = self.walker.step_plans().last().map(|p| p.optimisation.clone());
        let Some(last) = last else { return };
        let fixed = Candidate { x: problem.fixed_rule_x(), y: problem.ds.y, cost: problem.fixed_rule_cost };
        // The landscape is the re-run step's, scanned with the settings it ran with: a walk
        // that had planned on since showed its newest step's, and the re-run's choice nowhere.
        self.landscape = Some((last.step, problem.landscape(&self.walker, 41)));
        self.rerun = Some(StepRecord {
            method: Some(problem.settings.method),
            evaluations: candidates.len() as u32,
            feasible: candidates.iter().filter(|c| c.cost.is_some()).count() as u32,
            fallback: best.is_none(),
            chosen: best.unwrap_or(fixed),
            fixed_rule: fixed,
            candidates,
            elapsed_us,
            ..last
        });
        self.message = Some(format!(
            "optimiser re-run on step {} with {}",
            self.rerun.as_ref().map_or(0, |r| r.step),
            problem.settings.method.name()
        ));
    }

    pub(super) fn pick(&mut self, what: PickKind, item: &str) {
        let name = item.split_whitespace().next().unwrap_or_default();
        match what {
            PickKind::Preset => match presets::params(name) {
                Some(Ok(params)) => {
                    self.apply(params, format!("preset {name}"), true);
                }
                Some(Err(e)) => self.message = Some(e.to_string()),
                None => {}
            },
            PickKind::Terrain => {
                let spec = config::schema::spec("terrain.kind").expect("a key");
                if let Kind::Choice(words) = spec.kind
                    && let Some(w) = words.iter().find(|w| **w == name)
                {
                    self.set_value(spec, &Value::Word(w));
                }
            }
        }
    }
}
