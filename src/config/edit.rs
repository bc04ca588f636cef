//! Writing parameter values into an existing config text with its comments and layout kept
//! (toml_edit): the lab's save and the report's `config.toml` after `--set`.

use crate::config::render::{derived_comment, derived_value, toml_number};
use crate::config::schema::{self, Value};
use crate::model::params::WalkParams;
use toml_edit::{DocumentMut, Item, Table};

/// The edited document as text. `keys` are dotted keys, or `curves.<name>` for a curve
/// override (written as `[curves.<name>] points = [...]`, removed when `params` has none).
pub fn edited_text(source_text: &str, params: &WalkParams, keys: &[&str]) -> Result<String, String> {
    let mut doc: DocumentMut = source_text.parse().map_err(|e| format!("the file's TOML no longer parses: {e}"))?;
    for key in keys {
        if let Some(name) = key.strip_prefix("curves.") {
            edit_curve(&mut doc, name, params.curves.get(name))?;
            continue;
        }
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
    Ok(refresh_derived(&doc.to_string(), params))
}

/// `text` with each `# name = value  # derived` comment (as `gaitlab init` writes them)
/// showing what the key derives to for `params`. Kept from the source, they showed the old
/// walk's values: a report of the default config with `--set walk.speed_mps=0.8` listed
/// `# stride_m = 1.31  # derived` for a walk whose stride was 1.03 m.
fn refresh_derived(text: &str, params: &WalkParams) -> String {
    let r = params.resolve();
    let mut group = String::new();
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        let body = line.trim_end_matches(['\n', '\r']);
        if let Some(name) = body.strip_prefix('[').and_then(|h| h.strip_suffix(']')) {
            group = name.trim_matches(['[', ']']).to_string();
        }
        let refreshed = body
            .strip_prefix("# ")
            .and_then(|rest| rest.strip_suffix("  # derived"))
            .and_then(|assignment| assignment.split_once(" = "))
            .and_then(|(name, _)| {
                let value = derived_value(&format!("{group}.{name}"), params, &r)?;
                Some(derived_comment(name, &toml_number(value)))
            });
        match refreshed {
            Some(new) => {
                out.push_str(&new);
                out.push_str(&line[body.len()..]);
            }
            None => out.push_str(line),
        }
    }
    out
}

/// Writes one curve override as `[curves.<name>] points = [[x, y], ...]` (a table appended
/// where the file has none; other keys and comments kept), or removes it (`None`).
fn edit_curve(doc: &mut DocumentMut, name: &str, points: Option<&Vec<(f64, f64)>>) -> Result<(), String> {
    let Some(points) = points else {
        if let Some(curves) = doc.get_mut("curves").and_then(Item::as_table_mut) {
            curves.remove(name);
        }
        return Ok(());
    };
    if !doc.contains_key("curves") {
        let mut curves = Table::new();
        // `[curves.<name>]` headers only, no empty `[curves]`.
        curves.set_implicit(true);
        doc.insert("curves", Item::Table(curves));
    }
    // Comments at the end of the file (the default config's note on curves) stay above a
    // table appended there, not under it.
    let trailing = doc.trailing().as_str().unwrap_or_default().to_string();
    let moved = set_points(doc, name, points, &trailing)?;
    if moved {
        doc.set_trailing("");
    }
    Ok(())
}

/// Sets `[curves.<name>] points`; a table created here takes `trailing` (the file's last
/// comments) above its header. Returns whether it did.
fn set_points(doc: &mut DocumentMut, name: &str, points: &[(f64, f64)], trailing: &str) -> Result<bool, String> {
    let curves = doc["curves"].as_table_mut().ok_or("[curves] is not a table in the file")?;
    let appended = !curves.contains_key(name);
    if appended {
        curves.insert(name, Item::Table(Table::new()));
    }
    let table = curves[name].as_table_mut().ok_or_else(|| format!("[curves.{name}] is not a table in the file"))?;
    let moved = appended && !trailing.trim().is_empty();
    if moved {
        table.decor_mut().set_prefix(format!("{}\n\n", trailing.trim_end()));
    }
    let array: toml_edit::Array =
        points.iter().map(|&(x, y)| toml_edit::Value::Array(toml_edit::Array::from_iter([x, y]))).collect();
    let new = toml_edit::Value::Array(array);
    match table.get_mut("points").and_then(Item::as_value_mut) {
        // Assigning a value drops its decor (the trailing comment); carry it over.
        Some(old) => {
            let decor = old.decor().clone();
            *old = new;
            *old.decor_mut() = decor;
        }
        None => {
            table.insert("points", Item::Value(new));
        }
    }
    Ok(moved)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_comments_show_the_edited_walks_values() {
        let source = crate::config::render::render(&WalkParams::default(), "t");
        assert!(source.contains("# stride_m = 1.31  # derived\n"), "{source}");
        let params = crate::config::load_text(&source, "t", &["walk.speed_mps=0.8".into()]).unwrap();
        let text = edited_text(&source, &params, &["walk.speed_mps"]).unwrap();
        let r = params.resolve();
        assert!(text.contains(&format!("# stride_m = {}  # derived\n", toml_number(r.stride_m))), "{text}");
        assert!(text.contains("# heel_rise = 0.33  # derived\n") && text.contains("speed_mps = 0.8\n"));
        // Only the derived comments moved: the same lines, the same count of them.
        assert_eq!(text.lines().count(), source.lines().count());
        assert_eq!(crate::config::load_text(&text, "t", &[]).unwrap(), params);
    }

    #[test]
    fn a_curve_override_is_appended_replaced_and_removed() {
        let source = "# mine\n[walk]\nspeed_mps = 1.3\n";
        let mut params = crate::config::load_text(source, "t", &[]).unwrap();
        let points = vec![(0.0, 0.0), (0.3, 0.1), (0.6, 0.9), (1.0, 1.0)];
        params.curves.insert("swing_forward".into(), points.clone());
        let text = edited_text(source, &params, &["curves.swing_forward"]).unwrap();
        assert_eq!(
            text,
            "# mine\n[walk]\nspeed_mps = 1.3\n\n[curves.swing_forward]\npoints = [[0.0, 0.0], [0.3, 0.1], [0.6, 0.9], [1.0, 1.0]]\n"
        );
        let back = crate::config::load_text(&text, "t", &[]).unwrap();
        assert_eq!(back.curves["swing_forward"], points);
        params.curves.insert("swing_forward".into(), vec![(0.0, 0.0), (0.2, 0.1), (0.6, 0.9), (1.0, 1.0)]);
        let again = edited_text(&text, &params, &["curves.swing_forward"]).unwrap();
        assert!(again.contains("points = [[0.0, 0.0], [0.2, 0.1]"), "{again}");
        params.curves.clear();
        let gone = edited_text(&again, &params, &["curves.swing_forward"]).unwrap();
        assert!(!gone.contains("swing_forward") && gone.starts_with("# mine\n[walk]"), "{gone}");
        assert!(crate::config::load_text(&gone, "t", &[]).unwrap().curves.is_empty());
    }
}
