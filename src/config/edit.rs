//! Writing parameter values into an existing config text with its comments and layout kept
//! (toml_edit): the lab's save and the report's `config.toml` after `--set`.

use crate::config::schema::{self, Value};
use crate::model::params::WalkParams;
use toml_edit::{DocumentMut, Item, Table};

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
