//! Saving the lab's edits into the user's TOML: only the edited keys change, comments and
//! layout stay (toml_edit), and the file is replaced atomically (temp file + rename).

use crate::config::schema::{self, Value};
use crate::model::params::WalkParams;
use crate::output::write_atomic;
use std::path::Path;
use toml_edit::{DocumentMut, Item, Table};

/// Writes `params`' values of `keys` (and any changed curve overrides) into `source_text`
/// and saves the result at `path`. Returns the text written.
pub fn save(path: &Path, source_text: &str, params: &WalkParams, keys: &[&str]) -> Result<String, String> {
    let text = edited_text(source_text, params, keys)?;
    write_atomic(path, |out| out.write_all(text.as_bytes()))
        .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(text)
}

/// The edited document as text.
pub fn edited_text(source_text: &str, params: &WalkParams, keys: &[&str]) -> Result<String, String> {
    let mut doc: DocumentMut = source_text.parse().map_err(|e| format!("the file's TOML no longer parses: {e}"))?;
    for key in keys {
        let spec = schema::spec(key).ok_or_else(|| format!("unknown key {key}"))?;
        let (group, name) = (spec.group(), spec.name());
        if !doc.contains_key(group) {
            doc.insert(group, Item::Table(Table::new()));
        }
        let table = doc[group].as_table_mut().ok_or_else(|| format!("[{group}] is not a table in the file"))?;
        let new = match (spec.get)(params) {
            Value::Auto => {
                table.remove(name);
                continue;
            }
            Value::Real(x) => toml_edit::Value::from(x),
            Value::Int(n) => toml_edit::Value::from(n),
            Value::Word(w) => toml_edit::Value::from(w),
            Value::Bool(b) => toml_edit::Value::from(b),
        };
        match table.get_mut(name).and_then(Item::as_value_mut) {
            // Assigning a value drops its decor (the trailing comment); carry it over.
            Some(old) => {
                let decor = old.decor().clone();
                *old = new;
                *old.decor_mut() = decor;
            }
            None => {
                table.insert(name, Item::Value(new));
            }
        }
    }
    Ok(doc.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_edited_keys_change_and_comments_stay() {
        let source = "# my walk\n[walk]\n# how fast\nspeed_mps = 1.3 # brisk-ish\nsway = 1.0\n";
        let mut params = crate::config::load_text(source, "t", &[]).unwrap();
        params.walk.speed_mps = 1.45;
        params.pelvis.tilt_range_deg = 4.0;
        let text = edited_text(source, &params, &["walk.speed_mps", "pelvis.tilt_range_deg"]).unwrap();
        assert_eq!(
            text,
            "# my walk\n[walk]\n# how fast\nspeed_mps = 1.45 # brisk-ish\nsway = 1.0\n\n[pelvis]\ntilt_range_deg = 4.0\n"
        );
        let back = crate::config::load_text(&text, "t", &[]).unwrap();
        assert_eq!(back, params);
    }

    #[test]
    fn a_derived_key_set_back_to_derived_leaves_the_file() {
        let source = "[walk]\nstride_m = 1.5\nspeed_mps = 1.3\n";
        let mut params = crate::config::load_text(source, "t", &[]).unwrap();
        params.walk.stride_m = None;
        assert_eq!(edited_text(source, &params, &["walk.stride_m"]).unwrap(), "[walk]\nspeed_mps = 1.3\n");
    }
}
