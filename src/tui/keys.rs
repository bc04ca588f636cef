//! What each key does in the lab, and the list the help overlay and the README show.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Everything a key can ask of the lab.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// Restart the walk from standing.
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
    /// Next panel (narrow screens).
    NextPanel,
    /// Re-run the optimiser on the last step.
    RerunOptimiser,
    /// Next optimiser method.
    NextMethod,
}

/// The default bindings, in the order the help lists them: (keys as shown, action, what).
pub const BINDINGS: &[(&str, Action, &str)] = &[
    ("?", Action::Help, "show or hide this help"),
    ("q", Action::Quit, "quit (asks when edits are unsaved)"),
    ("space", Action::Pause, "pause / resume"),
    (".", Action::Step, "one frame forward (pauses)"),
    ("[ ]", Action::Slower, "slower / faster (0.125x to 4x)"),
    ("r", Action::Restart, "restart the walk"),
    ("up down / k j", Action::Up, "select a parameter"),
    ("pgup pgdn", Action::GroupUp, "previous / next group"),
    ("left right / h l", Action::Decrease, "change it by a fine step"),
    ("shift+left right / H L", Action::DecreaseCoarse, "change it by a coarse step"),
    ("enter", Action::Edit, "type an exact value (esc cancels)"),
    ("x", Action::Reset, "back to the default or derived value"),
    ("u / ctrl+r", Action::Undo, "undo / redo"),
    ("s / S", Action::Save, "save / save as"),
    ("p", Action::Presets, "load a preset's parameters"),
    ("t", Action::Terrain, "pick the terrain kind"),
    ("v", Action::ToggleView, "side / frontal view"),
    ("c / C", Action::NextCurve, "next / previous curve"),
    ("g", Action::ToggleGrid, "one curve / grid of curves"),
    ("tab", Action::NextPanel, "next panel (small screens)"),
    ("o", Action::RerunOptimiser, "re-run the optimiser on the last step"),
    ("m", Action::NextMethod, "next optimiser method"),
];

/// The action of a key press, with the default bindings.
#[must_use]
pub fn action_of(key: KeyEvent) -> Option<Action> {
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
    Some(match key.code {
        KeyCode::Char('c') if ctrl => Action::Quit,
        KeyCode::Char('r') if ctrl => Action::Redo,
        KeyCode::Char('q') => Action::Quit,
        KeyCode::Char('?') => Action::Help,
        KeyCode::Char(' ') => Action::Pause,
        KeyCode::Char('.') => Action::Step,
        KeyCode::Char('[') => Action::Slower,
        KeyCode::Char(']') => Action::Faster,
        KeyCode::Char('r') => Action::Restart,
        KeyCode::Up | KeyCode::Char('k') => Action::Up,
        KeyCode::Down | KeyCode::Char('j') => Action::Down,
        KeyCode::PageUp => Action::GroupUp,
        KeyCode::PageDown => Action::GroupDown,
        KeyCode::Left if shift => Action::DecreaseCoarse,
        KeyCode::Right if shift => Action::IncreaseCoarse,
        KeyCode::Left | KeyCode::Char('h') => Action::Decrease,
        KeyCode::Right | KeyCode::Char('l') => Action::Increase,
        KeyCode::Char('H') => Action::DecreaseCoarse,
        KeyCode::Char('L') => Action::IncreaseCoarse,
        KeyCode::Enter => Action::Edit,
        KeyCode::Char('x') => Action::Reset,
        KeyCode::Char('u') => Action::Undo,
        KeyCode::Char('s') => Action::Save,
        KeyCode::Char('S') => Action::SaveAs,
        KeyCode::Char('p') => Action::Presets,
        KeyCode::Char('t') => Action::Terrain,
        KeyCode::Char('v') => Action::ToggleView,
        KeyCode::Char('c') => Action::NextCurve,
        KeyCode::Char('C') => Action::PrevCurve,
        KeyCode::Char('g') => Action::ToggleGrid,
        KeyCode::Tab => Action::NextPanel,
        KeyCode::Char('o') => Action::RerunOptimiser,
        KeyCode::Char('m') => Action::NextMethod,
        _ => return None,
    })
}
