//! A one-line text field for the value editor and save-as: a cursor, readline's keys, and
//! the pre-filled text selected so that the first character typed replaces it (as in a
//! dialog's field), while an arrow or Home/End keeps it for editing.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// The field's text and cursor.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextInput {
    text: String,
    /// Cursor, in characters from the start.
    cursor: usize,
    /// The pre-filled text is selected: typing replaces it, Backspace/Delete clear it.
    selected: bool,
}

/// What a key did to the field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Edit {
    /// The text or cursor changed (or the key was an editing key that did nothing).
    Edited,
    /// Not an editing key: the dialog decides (Enter, Esc, …).
    Other,
}

impl TextInput {
    /// A field holding `text`, all of it selected, cursor at the end.
    #[must_use]
    pub fn prefilled(text: impl Into<String>) -> Self {
        let text = text.into();
        let cursor = text.chars().count();
        TextInput { selected: !text.is_empty(), text, cursor }
    }

    /// The text.
    #[must_use]
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Whether the whole pre-filled text is selected.
    #[must_use]
    pub(crate) fn is_selected(&self) -> bool {
        self.selected
    }

    /// The text split at the cursor (for drawing it).
    #[must_use]
    pub(crate) fn split_at_cursor(&self) -> (&str, &str) {
        self.text.split_at(self.byte_at(self.cursor))
    }

    fn byte_at(&self, chars: usize) -> usize {
        self.text.char_indices().nth(chars).map_or(self.text.len(), |(i, _)| i)
    }

    fn len(&self) -> usize {
        self.text.chars().count()
    }

    fn clear(&mut self) {
        self.text.clear();
        self.cursor = 0;
        self.selected = false;
    }

    /// Applies an editing key: characters insert at the cursor, Backspace / Delete remove,
    /// ←/→/Home/End (and ctrl+a / ctrl+e) move, ctrl+u / ctrl+k cut to the start / end,
    /// ctrl+w cuts the word before the cursor.
    pub(crate) fn on_key(&mut self, key: KeyEvent) -> Edit {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        let was_selected = std::mem::replace(&mut self.selected, false);
        match key.code {
            KeyCode::Char(c) if !ctrl => {
                if was_selected {
                    self.clear();
                }
                let at = self.byte_at(self.cursor);
                self.text.insert(at, c);
                self.cursor += 1;
            }
            KeyCode::Backspace | KeyCode::Delete if was_selected => self.clear(),
            KeyCode::Backspace if self.cursor > 0 => {
                self.cursor -= 1;
                let at = self.byte_at(self.cursor);
                self.text.remove(at);
            }
            KeyCode::Delete if self.cursor < self.len() => {
                let at = self.byte_at(self.cursor);
                self.text.remove(at);
            }
            KeyCode::Left => self.cursor = self.cursor.saturating_sub(1),
            KeyCode::Right => self.cursor = (self.cursor + 1).min(self.len()),
            KeyCode::Home => self.cursor = 0,
            KeyCode::End => self.cursor = self.len(),
            KeyCode::Char('a') if ctrl => self.cursor = 0,
            KeyCode::Char('e') if ctrl => self.cursor = self.len(),
            KeyCode::Char('u') if ctrl => {
                let at = self.byte_at(self.cursor);
                self.text.replace_range(..at, "");
                self.cursor = 0;
            }
            KeyCode::Char('k') if ctrl => {
                let at = self.byte_at(self.cursor);
                self.text.truncate(at);
            }
            KeyCode::Char('w') if ctrl => {
                let before: Vec<char> = self.text.chars().take(self.cursor).collect();
                let mut start = self.cursor;
                while start > 0 && before[start - 1] == ' ' {
                    start -= 1;
                }
                while start > 0 && before[start - 1] != ' ' {
                    start -= 1;
                }
                let (from, to) = (self.byte_at(start), self.byte_at(self.cursor));
                self.text.replace_range(from..to, "");
                self.cursor = start;
            }
            KeyCode::Backspace | KeyCode::Delete => {}
            _ => {
                self.selected = was_selected;
                return Edit::Other;
            }
        }
        Edit::Edited
    }
}

impl std::ops::Deref for TextInput {
    type Target = str;

    fn deref(&self) -> &str {
        &self.text
    }
}

impl PartialEq<&str> for &TextInput {
    fn eq(&self, other: &&str) -> bool {
        self.text == *other
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn press(input: &mut TextInput, code: KeyCode) -> Edit {
        input.on_key(KeyEvent::new(code, KeyModifiers::NONE))
    }

    fn ctrl(input: &mut TextInput, c: char) {
        input.on_key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL));
    }

    #[test]
    fn typing_replaces_the_prefilled_value_and_an_arrow_keeps_it() {
        let mut a = TextInput::prefilled("1.39");
        for c in "abc".chars() {
            press(&mut a, KeyCode::Char(c));
        }
        assert_eq!(a.text(), "abc");
        let mut b = TextInput::prefilled("1.39");
        press(&mut b, KeyCode::End);
        press(&mut b, KeyCode::Backspace);
        press(&mut b, KeyCode::Char('5'));
        assert_eq!(b.text(), "1.35");
        let mut c = TextInput::prefilled("1.39");
        press(&mut c, KeyCode::Backspace);
        assert_eq!(c.text(), "");
    }

    #[test]
    fn readline_keys_move_and_cut() {
        let mut t = TextInput::prefilled("walks/my walk.toml");
        press(&mut t, KeyCode::Left);
        for _ in 0..4 {
            press(&mut t, KeyCode::Left);
        }
        assert_eq!(t.split_at_cursor(), ("walks/my walk", ".toml"));
        ctrl(&mut t, 'w');
        assert_eq!(t.text(), "walks/my .toml");
        ctrl(&mut t, 'a');
        press(&mut t, KeyCode::Delete);
        assert_eq!(t.text(), "alks/my .toml");
        ctrl(&mut t, 'e');
        press(&mut t, KeyCode::Home);
        ctrl(&mut t, 'k');
        assert_eq!(t.text(), "");
        let mut u = TextInput::prefilled("héllo");
        press(&mut u, KeyCode::Left);
        press(&mut u, KeyCode::Left);
        press(&mut u, KeyCode::Left);
        ctrl(&mut u, 'u');
        assert_eq!(u.text(), "llo");
        assert_eq!(press(&mut u, KeyCode::Enter), Edit::Other);
    }
}
