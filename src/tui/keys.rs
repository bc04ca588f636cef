//! What each key does in the lab, and the list the help overlay and the README show.

use crate::config::{ConfigError, ConfigErrors};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Everything a key can ask of the lab.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, strum::IntoStaticStr, strum::EnumString, strum::VariantArray, strum::EnumCount,
)]
#[strum(serialize_all = "snake_case")]
pub enum Action {
    /// Quit (asks first when there are unsaved edits).
    Quit,
    /// Show or hide the key list.
    Help,
    /// Pause or resume the walk.
    Pause,
    /// One frame forward (pauses).
    Step,
    /// Halve the simulation speed.
    Slower,
    /// Double the simulation speed.
    Faster,
    /// Restart the walk from its first instant (mid-stride).
    Restart,
    /// Select the previous parameter.
    Up,
    /// Select the next parameter.
    Down,
    /// Previous parameter group.
    GroupUp,
    /// Next parameter group.
    GroupDown,
    /// Decrease the selected parameter by a fine step.
    Decrease,
    /// Increase it by a fine step.
    Increase,
    /// Decrease by a coarse step.
    DecreaseCoarse,
    /// Increase by a coarse step.
    IncreaseCoarse,
    /// Type an exact value.
    Edit,
    /// Back to the default (derived keys: derived again).
    Reset,
    /// Undo the last edit.
    Undo,
    /// Redo.
    Redo,
    /// Save to the config file.
    Save,
    /// Save to a new path.
    SaveAs,
    /// Pick a preset.
    Presets,
    /// Pick a terrain kind.
    Terrain,
    /// Side or frontal view.
    ToggleView,
    /// Next curve chart.
    NextCurve,
    /// Previous curve chart.
    PrevCurve,
    /// One curve or a grid of them.
    ToggleGrid,
    /// The measured adults' mean ± 1 SD behind the joint traces, or not.
    ToggleNorms,
    /// Next panel (narrow screens).
    NextPanel,
    /// Previous panel (narrow screens).
    PrevPanel,
    /// Re-run the optimiser on the last step.
    RerunOptimiser,
    /// Next optimiser method.
    NextMethod,
    /// Next leg IK solver.
    #[strum(serialize = "next_ik_solver")]
    NextSolver,
    /// Write a report of the current parameters (in the background).
    Export,
    /// Select the next control point of the curve shown (the arrows then move it).
    NextPoint,
    /// Select the previous control point.
    PrevPoint,
    /// Stop editing points: the arrows change parameters again.
    LeavePoints,
    /// Walk 0.1 m/s slower, reached over two steps (the pace schedule's ramp).
    PaceDown,
    /// Walk 0.1 m/s faster.
    PaceUp,
    /// Stop: a braking step, then the trailing foot beside the leading one.
    StopWalk,
}

crate::model::variants::named_variants!(Action);

/// The default bindings: key (as written in `[keys]`), action.
pub(crate) const DEFAULT_KEYS: &[(&str, Action)] = &[
    ("q", Action::Quit),
    ("ctrl+c", Action::Quit),
    ("?", Action::Help),
    ("space", Action::Pause),
    (".", Action::Step),
    ("[", Action::Slower),
    ("]", Action::Faster),
    ("r", Action::Restart),
    ("up", Action::Up),
    ("k", Action::Up),
    ("down", Action::Down),
    ("j", Action::Down),
    ("pageup", Action::GroupUp),
    ("pagedown", Action::GroupDown),
    ("left", Action::Decrease),
    ("h", Action::Decrease),
    ("right", Action::Increase),
    ("l", Action::Increase),
    ("shift+left", Action::DecreaseCoarse),
    ("H", Action::DecreaseCoarse),
    ("shift+right", Action::IncreaseCoarse),
    ("L", Action::IncreaseCoarse),
    ("enter", Action::Edit),
    ("x", Action::Reset),
    ("u", Action::Undo),
    ("ctrl+r", Action::Redo),
    ("s", Action::Save),
    ("S", Action::SaveAs),
    ("p", Action::Presets),
    ("t", Action::Terrain),
    ("v", Action::ToggleView),
    ("c", Action::NextCurve),
    ("C", Action::PrevCurve),
    ("g", Action::ToggleGrid),
    ("n", Action::ToggleNorms),
    ("tab", Action::NextPanel),
    ("shift+tab", Action::PrevPanel),
    ("o", Action::RerunOptimiser),
    ("m", Action::NextMethod),
    ("i", Action::NextSolver),
    ("e", Action::Export),
    (">", Action::NextPoint),
    ("<", Action::PrevPoint),
    ("esc", Action::LeavePoints),
    ("-", Action::PaceDown),
    ("+", Action::PaceUp),
    ("w", Action::StopWalk),
];

/// The help's lines: the actions each line covers, and what they do.
pub const HELP: &[(&[Action], &str)] = &[
    (&[Action::Help], "show or hide this help"),
    (&[Action::Quit], "quit (asks when edits are unsaved)"),
    (&[Action::Pause, Action::Step, Action::Restart], "pause or resume / one frame / restart"),
    (&[Action::Slower, Action::Faster], "slower / faster (0.125x to 4x)"),
    (&[Action::Up, Action::Down], "select a parameter"),
    (&[Action::GroupUp, Action::GroupDown], "previous / next group"),
    (&[Action::Decrease, Action::Increase], "change it by a fine step"),
    (&[Action::DecreaseCoarse, Action::IncreaseCoarse], "change it by a coarse step (x10)"),
    (&[Action::Edit], "type an exact value (esc cancels)"),
    (&[Action::Reset], "back to the default or derived value"),
    (&[Action::Undo, Action::Redo], "undo / redo"),
    (&[Action::Save, Action::SaveAs], "save / save as"),
    (&[Action::Presets], "load a preset's parameters"),
    (&[Action::Terrain], "pick the terrain kind"),
    (&[Action::ToggleView], "side / frontal view"),
    (&[Action::NextCurve, Action::PrevCurve], "next / previous curve"),
    // One line for both keeps the whole help on an 80x24 screen without scrolling.
    (&[Action::ToggleGrid, Action::ToggleNorms], "curve grid / adult norms band on the joints"),
    (&[Action::NextPanel, Action::PrevPanel], "next / previous panel (small screens)"),
    (&[Action::RerunOptimiser, Action::NextMethod], "re-run the optimiser / next method"),
    (&[Action::NextSolver, Action::Export], "next leg IK solver (live) / export a report"),
    (&[Action::PaceDown, Action::PaceUp, Action::StopWalk], "slower / faster (0.1 m/s) / stop, start"),
    (&[Action::NextPoint, Action::PrevPoint, Action::LeavePoints], "curve point: select (arrows move it) / done"),
];

/// A key as written in `[keys]`: `q`, `Q`, `?`, `space`, `enter`, `ctrl+r`, `shift+left`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct KeySpec {
    /// The key.
    pub code: KeyCode,
    /// With control.
    pub ctrl: bool,
    /// With shift (for keys without a shifted character).
    pub(crate) shift: bool,
}

impl KeySpec {
    /// Reads a key name; the error says what names are valid.
    pub fn parse(text: &str) -> Result<KeySpec, String> {
        let mut ctrl = false;
        let mut shift = false;
        let mut rest = text;
        loop {
            if let Some(r) = rest.strip_prefix("ctrl+") {
                ctrl = true;
                rest = r;
            } else if let Some(r) = rest.strip_prefix("shift+") {
                shift = true;
                rest = r;
            } else {
                break;
            }
        }
        let code = match rest {
            "space" => KeyCode::Char(' '),
            "enter" => KeyCode::Enter,
            "tab" => KeyCode::Tab,
            "esc" => KeyCode::Esc,
            "backspace" => KeyCode::Backspace,
            "up" => KeyCode::Up,
            "down" => KeyCode::Down,
            "left" => KeyCode::Left,
            "right" => KeyCode::Right,
            "pageup" => KeyCode::PageUp,
            "pagedown" => KeyCode::PageDown,
            "home" => KeyCode::Home,
            "end" => KeyCode::End,
            _ => {
                let mut chars = rest.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) if !c.is_control() => KeyCode::Char(c),
                    _ => {
                        return Err(format!(
                            "`{text}` is not a key; valid: one character, or space, enter, tab, esc, backspace, up, down, left, right, pageup, pagedown, home, end, each optionally after ctrl+ or shift+"
                        ));
                    }
                }
            }
        };
        Ok(KeySpec { code, ctrl, shift })
    }

    /// As the help shows it.
    #[must_use]
    pub fn label(self) -> String {
        let name = match self.code {
            KeyCode::Char(' ') => "space".to_string(),
            KeyCode::Char(c) => c.to_string(),
            KeyCode::Enter => "enter".into(),
            KeyCode::Tab => "tab".into(),
            KeyCode::Esc => "esc".into(),
            KeyCode::Backspace => "backspace".into(),
            KeyCode::Up => "up".into(),
            KeyCode::Down => "down".into(),
            KeyCode::Left => "left".into(),
            KeyCode::Right => "right".into(),
            KeyCode::PageUp => "pgup".into(),
            KeyCode::PageDown => "pgdn".into(),
            KeyCode::Home => "home".into(),
            KeyCode::End => "end".into(),
            other => format!("{other:?}"),
        };
        format!("{}{}{name}", if self.ctrl { "ctrl+" } else { "" }, if self.shift { "shift+" } else { "" })
    }

    fn matches(self, key: KeyEvent) -> bool {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        // Terminals send shift+tab as its own key, BackTab (with or without SHIFT).
        let (code, shift) = match key.code {
            KeyCode::BackTab => (KeyCode::Tab, true),
            code => (code, key.modifiers.contains(KeyModifiers::SHIFT)),
        };
        // A character carries its shift in its case: `H` arrives as Char('H') with SHIFT.
        let shift_ok = matches!(self.code, KeyCode::Char(_)) || shift == self.shift;
        self.code == code && ctrl == self.ctrl && shift_ok
    }
}

/// The bindings in force: the defaults with a config's `[keys]` applied.
#[derive(Clone, Debug)]
pub struct KeyMap {
    bindings: Vec<(KeySpec, Action)>,
}

impl Default for KeyMap {
    fn default() -> Self {
        KeyMap {
            bindings: DEFAULT_KEYS.iter().map(|(k, a)| (KeySpec::parse(k).expect("default keys parse"), *a)).collect(),
        }
    }
}

impl KeyMap {
    /// The defaults with the `[keys]` table of a config's text applied: each named action
    /// gets exactly the keys given (a string or an array of strings), and a key given to one
    /// action is taken from any other. Errors name the file, line, key and what is valid.
    pub(crate) fn from_config(text: &str, path: &str) -> Result<KeyMap, ConfigErrors> {
        let mut map = KeyMap::default();
        let problem = |span: Option<std::ops::Range<usize>>, key: &str, message: String| {
            let (line, col) = crate::config::line_col(text, span.map_or(0, |s| s.start));
            ConfigErrors(vec![ConfigError { path: path.to_string(), line, col, key: key.to_string(), message }])
        };
        let doc: toml_edit::Document<String> =
            text.parse().map_err(|e: toml_edit::TomlError| problem(e.span(), "", e.message().trim().to_string()))?;
        let Some(table) = doc.get("keys") else { return Ok(map) };
        let Some(table) = table.as_table_like() else {
            return Err(problem(table.span(), "keys", "expected a table [keys]".into()));
        };
        for (name, item) in table.iter() {
            let at = item.span().or_else(|| table.key(name).and_then(|k| k.span()));
            let key = format!("keys.{name}");
            let Some(action) = name.parse::<Action>().ok() else {
                let hint = crate::config::schema::did_you_mean(name, Action::ALL.iter().map(|a| a.name()))
                    .map_or(String::new(), |n| format!("did you mean `{n}`? "));
                let names: Vec<&str> = Action::ALL.iter().map(|a| a.name()).collect();
                return Err(problem(at, &key, format!("unknown action; {hint}actions: {}", names.join(", "))));
            };
            let texts: Vec<&str> = match item.as_value() {
                Some(toml_edit::Value::String(s)) => vec![s.value().as_str()],
                Some(toml_edit::Value::Array(a)) if a.iter().all(|v| v.as_str().is_some()) && !a.is_empty() => {
                    a.iter().filter_map(|v| v.as_str()).collect()
                }
                _ => {
                    let message = "expected a key name or an array of them, like \"q\" or [\"q\", \"ctrl+c\"]";
                    return Err(problem(at, &key, message.into()));
                }
            };
            let mut specs = Vec::new();
            for t in texts {
                specs.push(KeySpec::parse(t).map_err(|e| problem(at.clone(), &key, e))?);
            }
            map.bindings.retain(|(k, a)| *a != action && !specs.contains(k));
            map.bindings.extend(specs.into_iter().map(|k| (k, action)));
        }
        Ok(map)
    }

    /// The action of a key press.
    #[must_use]
    pub(crate) fn action_of(&self, key: KeyEvent) -> Option<Action> {
        self.bindings.iter().find(|(k, _)| k.matches(key)).map(|(_, a)| *a)
    }

    /// The keys bound to `action`, as the help shows them.
    #[must_use]
    pub fn keys_of(&self, action: Action) -> String {
        let keys: Vec<String> = self.bindings.iter().filter(|(_, a)| *a == action).map(|(k, _)| k.label()).collect();
        if keys.is_empty() { "(unbound)".into() } else { keys.join(" ") }
    }

    /// The first key bound to `action`, as the help shows it (`None`: unbound), for hints.
    #[must_use]
    pub fn first_key_of(&self, action: Action) -> Option<String> {
        self.bindings.iter().find(|(_, a)| *a == action).map(|(k, _)| k.label())
    }

    /// The help's key column for one line.
    #[must_use]
    pub fn help_keys(&self, actions: &[Action]) -> String {
        actions.iter().map(|a| self.keys_of(*a)).collect::<Vec<_>>().join(" / ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn action_names_are_the_documented_ones_and_parse_back() {
        // The README's `[keys]` action list: the names users' configs are written in.
        let documented = "quit help pause step slower faster restart up down group_up group_down decrease increase \
            decrease_coarse increase_coarse edit reset undo redo save save_as presets terrain toggle_view next_curve \
            prev_curve toggle_grid toggle_norms next_panel prev_panel rerun_optimiser next_method next_ik_solver export next_point \
            prev_point leave_points pace_down pace_up stop_walk";
        let names: Vec<&str> = Action::ALL.iter().map(|a| a.name()).collect();
        assert_eq!(names, documented.split_whitespace().collect::<Vec<_>>());
        for a in Action::ALL {
            assert_eq!(a.name().parse::<Action>(), Ok(a));
        }
        assert!("next_solver".parse::<Action>().is_err(), "only the documented name");
    }
}
