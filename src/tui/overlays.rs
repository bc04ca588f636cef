//! The lab's dialogs: what a key does while one is open.

use super::app::{AfterSave, App, Effect, Overlay};
use super::keys::Action;
use super::text_input::TextInput;
use crate::config;
use ratatui::crossterm::event::{KeyCode, KeyEvent};
use std::path::PathBuf;

impl App {
    pub(super) fn on_overlay_key(&mut self, overlay: Overlay, key: KeyEvent) {
        match overlay {
            Overlay::Help => match key.code {
                // On a short terminal the list scrolls; any other key closes it, and `q`
                // also quits, as users expect.
                KeyCode::Down | KeyCode::Char('j') | KeyCode::PageDown => {
                    self.help_scroll =
                        self.help_scroll.saturating_add(if key.code == KeyCode::PageDown { 10 } else { 1 });
                    self.overlay = Some(Overlay::Help);
                }
                KeyCode::Up | KeyCode::Char('k') | KeyCode::PageUp => {
                    self.help_scroll =
                        self.help_scroll.saturating_sub(if key.code == KeyCode::PageUp { 10 } else { 1 });
                    self.overlay = Some(Overlay::Help);
                }
                KeyCode::Char('q') => self.perform(Action::Quit),
                _ => {}
            },
            Overlay::ConfirmQuit => match key.code {
                KeyCode::Char('y' | 'q') => self.quit = true,
                KeyCode::Char('s') => {
                    if self.path.is_some() {
                        self.request_save(AfterSave::Quit);
                    } else {
                        self.overlay =
                            Some(Overlay::SavePath { text: TextInput::prefilled("my_walk.toml"), error: None });
                    }
                }
                _ => {}
            },
            Overlay::Typing { mut text, error } => match key.code {
                KeyCode::Esc => {}
                KeyCode::Enter => match self.set_typed(text.text()) {
                    Ok(()) => {}
                    Err(e) => self.overlay = Some(Overlay::Typing { text, error: Some(e) }),
                },
                _ => {
                    text.on_key(key);
                    self.overlay = Some(Overlay::Typing { text, error });
                }
            },
            Overlay::SavePath { text, error } => self.on_save_path_key(text, error, key),
            Overlay::Recovery { found, error } => self.on_recovery_key(found, error, key),
            Overlay::Pick { what, items, mut selected } => match key.code {
                KeyCode::Esc => {}
                KeyCode::Up | KeyCode::Char('k') => {
                    selected = selected.checked_sub(1).unwrap_or(items.len() - 1);
                    self.overlay = Some(Overlay::Pick { what, items, selected });
                }
                KeyCode::Down | KeyCode::Char('j') => {
                    selected = (selected + 1) % items.len();
                    self.overlay = Some(Overlay::Pick { what, items, selected });
                }
                KeyCode::Enter => self.pick(what, &items[selected]),
                _ => self.overlay = Some(Overlay::Pick { what, items, selected }),
            },
        }
    }

    fn on_save_path_key(&mut self, mut text: TextInput, error: Option<String>, key: KeyEvent) {
        match key.code {
            KeyCode::Esc => {}
            KeyCode::Enter => {
                let typed = text.text().trim();
                if typed.is_empty() {
                    self.overlay = Some(Overlay::SavePath { text, error: Some("type a file name".into()) });
                    return;
                }
                let old_path = self.path.replace(PathBuf::from(typed));
                // A new file gets every key that differs from the text it is built from.
                self.saved = config::load_text(&self.source_text, "source", &[]).unwrap_or_default();
                self.request_save(AfterSave::SaveAs { typed: text, old_path });
            }
            _ => {
                text.on_key(key);
                self.overlay = Some(Overlay::SavePath { text, error });
            }
        }
    }

    fn on_recovery_key(&mut self, found: super::recovery::Found, error: Option<String>, key: KeyEvent) {
        match key.code {
            KeyCode::Char('l') => match config::load_text(&found.text, &found.path.display().to_string(), &[]) {
                Ok(params) => {
                    self.apply(params, format!("recovered the unsaved edits of {}", found.age), true);
                    self.effects.push(Effect::RemoveFile(found.path));
                }
                Err(e) => {
                    self.overlay = Some(Overlay::Recovery { found, error: Some(e.to_string()) });
                }
            },
            KeyCode::Char('d') => {
                self.message = Some(format!("discarded {}", found.path.display()));
                self.effects.push(Effect::RemoveFile(found.path));
            }
            KeyCode::Esc => {
                self.message = Some(format!("kept {} for later", found.path.display()));
            }
            _ => self.overlay = Some(Overlay::Recovery { found, error }),
        }
    }
}
