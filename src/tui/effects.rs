//! Running what the lab's state asks for: file writes and the report thread happen here,
//! outside [`App::update`], and their outcomes go back in as messages.

use super::app::{App, Effect, Msg};
use super::export::Export;
use std::collections::VecDeque;

/// Runs `effects` (and any their outcomes ask for) against the world.
pub fn run(app: &mut App, effects: Vec<Effect>) {
    let mut queue: VecDeque<Effect> = effects.into();
    while let Some(effect) = queue.pop_front() {
        let more = match effect {
            Effect::Save { path, text, keys, after } => {
                let result =
                    crate::output::write_atomic(&path, |out| out.write_all(text.as_bytes())).map_err(|e| e.to_string());
                app.update(Msg::Saved { path, text, keys, after, result })
            }
            Effect::Export { out, name, params, source_text } => {
                app.update(Msg::ExportStarted(Export::start(&out, name, &params, &source_text)))
            }
            Effect::RemoveFile(path) => {
                // Already gone is as good as removed; nothing else can be done about it here.
                let _ = std::fs::remove_file(path);
                Vec::new()
            }
        };
        queue.extend(more);
    }
}

/// One message through the lab: its update, then the effects it asks for.
pub fn step(app: &mut App, msg: Msg) {
    let effects = app.update(msg);
    run(app, effects);
}
