//! Editing parameters in the lab: the selected key stepped, typed, reset; each change an
//! undoable edit applied live to the walk where the model allows, else by a restart.

use super::app::{App, Edit};
use crate::config::render::{derived_value, toml_number};
use crate::config::schema::{Kind, PARAMS, ParamSpec, Value};
use crate::config::{self, Loader};
use crate::model::params::WalkParams;
use crate::model::walk::pace::WalkState;

impl App {
    pub(super) fn jump_group(&mut self, forward: bool) {
        let group = PARAMS[self.selected].group();
        let starts: Vec<usize> =
            (0..PARAMS.len()).filter(|&i| i == 0 || PARAMS[i].group() != PARAMS[i - 1].group()).collect();
        let here = starts.iter().rposition(|&s| PARAMS[s].group() == group).unwrap_or(0);
        let to = if forward { (here + 1) % starts.len() } else { (here + starts.len() - 1) % starts.len() };
        self.selected = starts[to];
    }

    /// The value of `spec` as the editor shows it (derived keys: their derived value).
    #[must_use]
    pub fn value_text(&self, spec: &ParamSpec) -> String {
        match (spec.get)(&self.params) {
            Value::Real(x) => toml_number(x),
            Value::Auto => {
                derived_value(spec.key, &self.params, self.walker.resolved()).map_or("auto".into(), toml_number)
            }
            Value::Int(n) => n.to_string(),
            Value::Word(w) => w.to_string(),
            Value::Bool(b) => b.to_string(),
        }
    }

    /// Fine step of a numeric key: about 1/200 of its range, rounded to 1, 2 or 5 × 10^k.
    #[must_use]
    pub fn fine_step(spec: &ParamSpec) -> f64 {
        match spec.kind {
            Kind::Real { min, max, .. } => {
                let raw = (max - min) / 200.0;
                let decade = 10f64.powf(raw.log10().floor());
                let m = raw / decade;
                decade
                    * if m < 1.5 {
                        1.0
                    } else if m < 3.5 {
                        2.0
                    } else if m < 7.5 {
                        5.0
                    } else {
                        10.0
                    }
            }
            _ => 1.0,
        }
    }

    pub(super) fn step_selected(&mut self, steps: f64) {
        let spec = &PARAMS[self.selected];
        let current = (spec.get)(&self.params);
        let new = match (spec.kind, current) {
            (Kind::Real { min, max, .. }, v) => {
                let now = match v {
                    Value::Real(x) => x,
                    _ => derived_value(spec.key, &self.params, self.walker.resolved()).unwrap_or(min),
                };
                let step = App::fine_step(spec);
                // Land on the step grid, so that repeated presses give round numbers.
                let x = ((now / step).round() + steps.signum() * steps.abs().max(1.0)) * step;
                let x = ((x.clamp(min, max)) * 1e9).round() / 1e9;
                Value::Real(x)
            }
            (Kind::Int { min, max }, Value::Int(n)) => Value::Int((n + steps as i64).clamp(min, max)),
            (Kind::Choice(words), Value::Word(w)) => {
                let i = words.iter().position(|x| *x == w).unwrap_or(0) as i64;
                let n = words.len() as i64;
                Value::Word(words[(i + steps.signum() as i64).rem_euclid(n) as usize])
            }
            (Kind::Bool, Value::Bool(b)) => Value::Bool(!b),
            _ => return,
        };
        self.set_value(spec, &new);
    }

    /// Sets a key to a value already valid for its kind, through the config's cross-checks.
    pub(super) fn set_value(&mut self, spec: &ParamSpec, value: &Value) {
        if (spec.get)(&self.params) == *value {
            return;
        }
        let mut params = self.params.clone();
        (spec.set)(&mut params, value);
        let problems = config::cross_check(&params);
        if let Some((_, message)) = problems.first() {
            self.message = Some(format!("{}: {message}", spec.key));
            return;
        }
        let what = format!("{} = {}", spec.key, crate::config::render::value_text(value).unwrap_or("(derived)".into()));
        self.apply(params, what, true);
    }

    /// Sets the selected key from typed text, validated like the config file and `--set`.
    /// Returns the error to show, if refused.
    pub(crate) fn set_typed(&mut self, text: &str) -> Result<(), String> {
        let spec = &PARAMS[self.selected];
        let text = text.trim();
        // Elsewhere, nothing typed is refused by the loader, in the key's terms.
        if (text.is_empty() || text == "auto") && matches!(spec.kind, Kind::Real { auto: true, .. }) {
            self.set_value(spec, &Value::Auto);
            return Ok(());
        }
        let mut loader = Loader::from_params(self.params.clone());
        loader.apply_set(&format!("{}={text}", spec.key), 1);
        match loader.finish() {
            Ok(params) => {
                if params != self.params {
                    self.apply(params, format!("{} = {text}", spec.key), true);
                }
                Ok(())
            }
            Err(errors) => Err(errors.0.iter().map(config::ConfigError::what).collect::<Vec<_>>().join("; ")),
        }
    }

    /// Puts `params` in force: live on the walk where the model allows, else a restart; returns
    /// whether it did. A new speed is walked over [`crate::model::walk::pace::RAMP_STEPS`]
    /// steps, as the pace keys and a schedule walk it: set at once it switched cadence and
    /// forward speed within a frame (1.8 -> 0.8 m/s: the pelvis's velocity change per frame
    /// 3.4-4.9x a steady walk's, the knee 1.5x as fast). While the walk starts or stops a new
    /// speed is refused, as the pace keys refuse it (set at once there: 2.6x / 4.0x). Every
    /// other live edit keeps the speed being walked, so a ramp under way goes on.
    pub(super) fn apply(&mut self, params: WalkParams, mut what: String, record: bool) -> bool {
        let state = self.walker.walk_state();
        let new_speed = params.walk.speed_mps != self.params.walk.speed_mps;
        if new_speed && let Some(why) = speed_refused(state) {
            self.message = Some(format!("walk.speed_mps: {why}"));
            return false;
        }
        let before = std::mem::replace(&mut self.params, params.clone());
        let mut ramp = new_speed && state == WalkState::Walking;
        let live = if state == WalkState::Standing {
            self.walker.set_params(&params)
        } else {
            // Everything but the speed now, at the speed being walked; a new speed then over
            // the steps (asked again, it replaces a ramp under way, even back to the speed
            // being walked). Keys that make no walk at that speed are taken with the new one.
            let mut now = params.clone();
            now.walk.speed_mps = self.walker.params().walk.speed_mps;
            match self.walker.set_params(&now) {
                Err(_) => {
                    ramp = false;
                    self.walker.set_params(&params)
                }
                live => live,
            }
        };
        match live {
            Ok(true) if ramp => {
                self.walker.request_speed(params.walk.speed_mps);
                what.push_str(", reached over two steps");
            }
            Ok(true) => {}
            Ok(false) => self.restart(),
            Err(e) => {
                self.params = before;
                self.message = Some(format!("refused: {e}"));
                return false;
            }
        }
        if record {
            self.undo.push(Edit { before, after: params, what: what.clone() });
            self.redo.clear();
        }
        self.message = Some(what);
        true
    }

    pub(super) fn undo(&mut self) {
        match self.undo.pop() {
            Some(edit) => {
                // Say what is in force now, not what was taken back.
                let now: Vec<String> = PARAMS
                    .iter()
                    .filter(|spec| (spec.get)(&edit.before) != (spec.get)(&edit.after))
                    .take(3)
                    .map(|spec| {
                        let value = match (spec.get)(&edit.before) {
                            Value::Real(x) => toml_number(x),
                            Value::Auto => "auto".into(),
                            Value::Int(n) => n.to_string(),
                            Value::Word(w) => w.to_string(),
                            Value::Bool(b) => b.to_string(),
                        };
                        format!("{} = {value}", spec.key)
                    })
                    .collect();
                let message = if now.is_empty() {
                    format!("undone: {}", edit.what)
                } else {
                    format!("undone: back to {}", now.join(", "))
                };
                if self.apply(edit.before.clone(), message, false) {
                    self.redo.push(edit);
                } else {
                    self.undo.push(edit);
                }
            }
            None => self.message = Some("nothing to undo".into()),
        }
    }

    pub(super) fn redo(&mut self) {
        match self.redo.pop() {
            Some(edit) => {
                if self.apply(edit.after.clone(), format!("redone: {}", edit.what), false) {
                    self.undo.push(edit);
                } else {
                    self.redo.push(edit);
                }
            }
            None => self.message = Some("nothing to redo".into()),
        }
    }
}

/// Why a new speed cannot be taken in walk state `state`, if it cannot: the words the pace keys
/// use there.
fn speed_refused(state: WalkState) -> Option<&'static str> {
    match state {
        WalkState::Starting => Some("starting: the first step is under way; a new speed once walking"),
        WalkState::Stopping => Some("stopping: the walk comes to rest; a new speed once standing"),
        WalkState::Walking | WalkState::Standing => None,
    }
}
