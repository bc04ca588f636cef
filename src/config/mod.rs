//! Config files: TOML in, validated [`WalkParams`] out, with errors that name the file, line,
//! column, key and the valid range; `--set KEY=VALUE` overrides; `gaitlab init` output.
//!
//! Parsing walks the TOML document with its spans (`toml::de::DeTable`) against the key
//! table in [`schema`], so every problem in a file is reported at once, in file order, and
//! unknown keys get a "did you mean".

pub mod checks;
pub mod echo;
pub mod edit;
pub mod errors;
pub mod presets;
pub mod render;
pub mod schedule;
pub mod schema;
pub mod source;

pub use checks::{check_curve, cross_check};
use errors::char_floor;
pub(crate) use errors::line_col;
pub use errors::{ConfigError, ConfigErrors};
pub use source::{MAX_CONFIG_BYTES, READ_DEADLINE, decode_source, read_source, read_text};

use crate::model::gait_curves::CurveName;
use crate::model::params::WalkParams;
use schema::{GROUPS, Kind, PARAMS, ParamSpec, Value, did_you_mean, spec};
use std::cell::Cell;
use std::collections::HashMap;
use std::path::Path;
use toml::Spanned;
use toml::de::{DeString, DeTable, DeValue};

/// A place in a source: (path label, line, column).
type Place = (String, usize, usize);

/// Most problems listed for one document; reading stops there with a line saying so (a
/// megabyte of unknown keys would otherwise print a hundred thousand lines, each with its
/// "did you mean" search).
pub const MAX_PROBLEMS: usize = 100;

/// Reads TOML into parameters, remembering where each key was set.
#[derive(Debug, Default)]
pub(crate) struct Loader {
    params: WalkParams,
    places: HashMap<String, Place>,
    errors: Vec<ConfigError>,
    /// The label of the document read, for problems no key can be blamed for.
    label: Option<String>,
}

/// [`line_col`] for many offsets of one text: line starts found once, and the column counted
/// on from the last answer when the next offset is later on the same line, so that a
/// document's problems, asked in order, cost one pass over it however many there are (a
/// megabyte of `walk = {k0 = 1, k1 = 1, ...}` on one line).
struct Locator<'t> {
    text: &'t str,
    starts: Vec<usize>,
    /// Last answer: (byte offset, line index, column).
    last: Cell<(usize, usize, usize)>,
}

impl<'t> Locator<'t> {
    fn new(text: &'t str) -> Self {
        let starts = std::iter::once(0).chain(text.match_indices('\n').map(|(i, _)| i + 1)).collect();
        Locator { text, starts, last: Cell::new((0, 0, 1)) }
    }

    fn line_col(&self, at: usize) -> (usize, usize) {
        let at = char_floor(self.text, at);
        let line = self.starts.partition_point(|&s| s <= at) - 1;
        let (from, col) = match self.last.get() {
            (off, l, col) if l == line && off <= at => (off, col),
            _ => (self.starts[line], 1),
        };
        let col = col + self.text[from..at].chars().count();
        self.last.set((at, line, col));
        (line + 1, col)
    }
}

impl Loader {
    /// Starts from the built-in defaults.
    #[must_use]
    pub fn new() -> Self {
        Loader::default()
    }

    /// Starts from given parameters (a loaded file, before `--set`).
    #[must_use]
    pub(crate) fn from_params(params: WalkParams) -> Self {
        Loader { params, ..Loader::default() }
    }

    /// Records a problem. The key may be user text (an unknown key), so it is echoed cut
    /// short and escaped; the message is held to one line of [`echo::MESSAGE_CHARS`].
    fn error(&mut self, place: &Place, key: &str, message: impl Into<String>) {
        self.errors.push(ConfigError {
            path: place.0.clone(),
            line: place.1,
            col: place.2,
            key: echo::echo(key),
            message: echo::clip(&message.into(), echo::MESSAGE_CHARS),
        });
    }

    /// Reads a whole TOML document.
    /// A leading byte-order mark is skipped; columns count from after it.
    pub(crate) fn read_str(&mut self, text: &str, path: &str) {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        self.label = Some(path.to_string());
        let locator = Locator::new(text);
        let place = |at: usize| {
            let (line, col) = locator.line_col(at);
            (path.to_string(), line, col)
        };
        let root = match DeTable::parse(text) {
            Ok(root) => root,
            Err(e) => {
                let at = e.span().map_or(0, |s| s.start);
                let message = echo::clip(e.message().trim(), echo::MESSAGE_CHARS - 20);
                self.error(&place(at), "", format!("TOML syntax: {message}"));
                return;
            }
        };
        // In file order (the parsed tables are sorted by key), so that problems are listed
        // as they come and the first of them are the ones kept.
        for (group_key, group_value) in in_file_order(root.get_ref()) {
            let group = group_key.get_ref().as_ref();
            let at = place(group_key.span().start);
            if self.stop_at(&at) {
                return;
            }
            // `[keys]` rebinds the terminal lab's keys; the lab reads and checks it itself
            // (key names are a terminal matter), the walk has nothing to take from it.
            if group == "keys" {
                continue;
            }
            if !GROUPS.contains(&group) {
                self.error(&at, group, unknown_group(group));
                continue;
            }
            let DeValue::Table(table) = group_value.get_ref() else {
                let found = group_value.get_ref().type_str();
                let article = echo::article(found);
                self.error(&at, group, format!("expected a table [{group}], found {article} {found}"));
                continue;
            };
            for (key, value) in in_file_order(table) {
                let name = key.get_ref().as_ref();
                let at = place(key.span().start);
                if self.stop_at(&at) {
                    return;
                }
                let value_at = place(value.span().start);
                if group == "curves" {
                    self.read_curve(name, value, &at, &place);
                } else if group == "walk" && name == "schedule" {
                    self.read_schedule(value, &at, &place);
                } else {
                    self.set_key(&format!("{group}.{name}"), value.get_ref(), &at, &value_at);
                }
            }
        }
    }

    /// Whether [`MAX_PROBLEMS`] have been found; if so, says so at `at`, where reading stops.
    fn stop_at(&mut self, at: &Place) -> bool {
        if self.errors.len() < MAX_PROBLEMS {
            return false;
        }
        self.errors.push(ConfigError {
            path: at.0.clone(),
            line: at.1,
            col: at.2,
            key: String::new(),
            message: format!("more problems from here on are not listed (the first {MAX_PROBLEMS} are)"),
        });
        true
    }

    /// Reads `[curves.<name>]`: a `points` array of `[x, y]` pairs.
    fn read_curve(&mut self, name: &str, value: &Spanned<DeValue<'_>>, at: &Place, place: &dyn Fn(usize) -> Place) {
        let key = format!("curves.{name}");
        if CurveName::from_key(name).is_none() {
            self.error(at, &key, unknown_curve(&key, name));
            return;
        }
        let DeValue::Table(table) = value.get_ref() else {
            self.error(at, &key, "expected a table with `points = [[x, y], ...]`");
            return;
        };
        for (k, v) in in_file_order(table) {
            let kname = k.get_ref().as_ref();
            let kat = place(k.span().start);
            if self.stop_at(&kat) {
                return;
            }
            if kname != "points" {
                let hint = if did_you_mean(kname, ["points"]).is_some() { "; did you mean `points`?" } else { "" };
                self.error(&kat, &format!("{key}.{kname}"), format!("unknown key{hint} (a curve takes only `points`)"));
                continue;
            }
            self.set_curve_points(name, v.get_ref(), &kat);
        }
    }

    fn set_curve_points(&mut self, name: &str, value: &DeValue<'_>, at: &Place) {
        let key = format!("curves.{name}.points");
        let shape = "expected an array of [x, y] pairs of numbers, 3n+1 of them (4, 7, 10, ...)";
        let DeValue::Array(items) = value else {
            self.error(at, &key, shape);
            return;
        };
        let mut pairs = Vec::with_capacity(items.len());
        for item in items.iter() {
            let pair = match item.get_ref() {
                DeValue::Array(xy) if xy.len() == 2 => (number(xy[0].get_ref()), number(xy[1].get_ref())),
                _ => (None, None),
            };
            match pair {
                (Some(x), Some(y)) if x.is_finite() && y.is_finite() => pairs.push((x, y)),
                _ => {
                    self.error(at, &key, shape);
                    return;
                }
            }
        }
        if let Err(message) = check_curve(name, &pairs) {
            self.error(at, &key, message);
            return;
        }
        self.params.curves.insert(name.to_string(), pairs);
        self.places.insert(format!("curves.{name}"), at.clone());
    }

    /// Sets one dotted key from a TOML value, checking type and range.
    fn set_key(&mut self, key: &str, value: &DeValue<'_>, at: &Place, value_at: &Place) {
        let Some(spec) = spec(key) else {
            self.error(at, key, unknown_key(key));
            return;
        };
        match parse_value(spec, value) {
            Ok(v) => {
                (spec.set)(&mut self.params, &v);
                self.places.insert(key.to_string(), at.clone());
            }
            Err(message) => self.error(value_at, key, message),
        }
    }

    /// Applies `--set KEY=VALUE` (`index` counts the `--set`s from 1, for messages).
    pub(crate) fn apply_set(&mut self, assignment: &str, index: usize) {
        let label = format!("--set #{index}");
        let Some((key_text, value_text)) = assignment.split_once('=') else {
            self.error(
                &(label, 1, 1),
                assignment,
                "expected KEY=VALUE, like walk.speed_mps=1.4 or terrain.kind=\"stairs\"",
            );
            return;
        };
        let key = key_text.trim();
        let at = (label.clone(), 1, 1 + (key_text.len() - key_text.trim_start().len()));
        let value_col = key_text.chars().count()
            + 2
            + value_text[..value_text.len() - value_text.trim_start().len()].chars().count();
        let value_at = (label.clone(), 1, value_col);
        if key.is_empty() {
            self.error(
                &at,
                "",
                "empty key; expected KEY=VALUE with a dotted key, like walk.speed_mps=1.4 or terrain.kind=\"stairs\"",
            );
            return;
        }
        let curve = key.strip_prefix("curves.").map(|rest| rest.strip_suffix(".points").unwrap_or(rest));
        let spec = spec(key);
        if curve.is_none() && spec.is_none() {
            // Name the key's fault before looking at the value.
            let message = match key.split_once('.') {
                None if GROUPS.contains(&key) => {
                    format!("`{key}` is a group; name a key in it, like {}", example_key(key))
                }
                None => unknown_key(key),
                Some(("keys", _)) => {
                    "the lab's key bindings are set in the config file's [keys] table, not with --set".to_string()
                }
                Some((group, _)) if !GROUPS.contains(&group) => unknown_group(group),
                Some(_) => unknown_key(key),
            };
            self.error(&at, key, message);
            return;
        }
        // Plain words are forgiven their missing quotes (`terrain.kind=stairs`), except the
        // TOML words that are not strings: true and false, and nan and inf for a number key
        // (which then hears that it needs a finite number, not that "nan" is a string).
        let quoted;
        let mut text = value_text.trim();
        let numeric = spec.is_some_and(|s| matches!(s.kind, Kind::Real { .. } | Kind::Int { .. }));
        if !text.is_empty()
            && text.chars().all(|c| c.is_ascii_alphabetic() || c == '_')
            && text != "true"
            && text != "false"
            && !(numeric && (text == "nan" || text == "inf"))
        {
            quoted = format!("\"{text}\"");
            text = &quoted;
        }
        let parsed = match (DeValue::parse(text), spec) {
            (Ok(v), _) => v,
            // A typo in a key's value (`1.39abc`, nothing at all) is told in the key's terms,
            // not the TOML parser's ("invalid float, expected nothing").
            (Err(_), Some(spec)) if curve.is_none() => {
                let found = (!text.is_empty()).then(|| echo::echo(text));
                self.error(&value_at, key, needs(spec, found.as_deref()));
                return;
            }
            (Err(e), _) => {
                let message = echo::clip(e.message().trim(), echo::MESSAGE_CHARS - 20);
                self.error(&value_at, key, format!("value is not TOML: {message}"));
                return;
            }
        };
        match curve {
            Some(name) if CurveName::from_key(name).is_none() => self.error(&at, key, unknown_curve(key, name)),
            Some(name) => self.set_curve_points(name, parsed.get_ref(), &value_at),
            None => self.set_key(key, parsed.get_ref(), &at, &value_at),
        }
    }

    /// Cross-key checks on the whole parameter set, then the errors found, if any.
    pub fn finish(mut self) -> Result<WalkParams, ConfigErrors> {
        if self.errors.is_empty() {
            let problems = cross_check(&self.params);
            for (keys, message) in problems {
                let (key, place) = keys
                    .iter()
                    .find_map(|k| self.places.get(*k).map(|p| (*k, p.clone())))
                    .unwrap_or_else(|| (keys[0], self.first_place()));
                self.error(&place, key, message);
            }
        }
        if self.errors.is_empty() { Ok(self.params) } else { Err(ConfigErrors(self.errors)) }
    }

    fn first_place(&self) -> Place {
        self.places
            .values()
            .min_by_key(|p| (p.1, p.2))
            .cloned()
            .unwrap_or_else(|| (self.label.clone().unwrap_or_else(|| "config".into()), 1, 1))
    }
}

/// A parsed table's entries in the order they are written.
fn in_file_order<'a, 'i>(table: &'a DeTable<'i>) -> Vec<(&'a Spanned<DeString<'i>>, &'a Spanned<DeValue<'i>>)> {
    let mut entries: Vec<_> = table.iter().collect();
    entries.sort_by_key(|(k, _)| k.span().start);
    entries
}

/// Room for a list in a message about `key`, so that the whole line stays readable.
fn room(key: &str, before: &str) -> usize {
    echo::MESSAGE_CHARS.saturating_sub(key.chars().count().min(echo::ECHO_CHARS) + before.chars().count() + 1)
}

/// The message for an unknown group.
fn unknown_group(group: &str) -> String {
    let hint = did_you_mean(group, GROUPS.iter().copied()).map_or(String::new(), |g| format!("; did you mean [{g}]?"));
    let before = format!("unknown group{hint}");
    format!("{before} {}", echo::listing("groups", GROUPS, room(group, &before)))
}

/// The message for an unknown curve (`key` is `curves.<name>`).
fn unknown_curve(key: &str, name: &str) -> String {
    let names: Vec<&str> = CurveName::ALL.iter().map(|c| c.key()).collect();
    let hint = did_you_mean(name, names.iter().copied()).map_or(String::new(), |c| format!("; did you mean `{c}`?"));
    let before = format!("unknown curve{hint}");
    format!("{before} {}", echo::listing("curves", &names, room(key, &before)))
}

/// The message for an unknown dotted key (in a known group or none).
fn unknown_key(key: &str) -> String {
    let (group, name) = key.split_once('.').unwrap_or(("", key));
    let in_group: Vec<&str> = PARAMS.iter().filter(|p| p.group() == group).map(ParamSpec::name).collect();
    let hint = did_you_mean(name, in_group.iter().copied())
        .map(|n| format!("; did you mean `{n}`?"))
        .or_else(|| did_you_mean(key, PARAMS.iter().map(|p| p.key)).map(|k| format!("; did you mean `{k}`?")))
        .or_else(|| {
            // A name without its group: `speed_mps` for `walk.speed_mps`.
            PARAMS.iter().find(|p| p.name() == name).map(|p| format!("; did you mean `{}`?", p.key))
        })
        .unwrap_or_default();
    if in_group.is_empty() {
        format!("unknown key{hint} (a key is GROUP.NAME, like walk.speed_mps; groups: {})", GROUPS.join(", "))
    } else {
        let before = format!("unknown key{hint}");
        format!("{before} {}", echo::listing(&format!("keys of [{group}]"), &in_group, room(key, &before)))
    }
}

/// A key of `group` to show as an example.
fn example_key(group: &str) -> String {
    if group == "curves" {
        return "curves.heel_rise.points=[[0, 0], ...]".into();
    }
    PARAMS.iter().find(|p| p.group() == group).map_or_else(String::new, |p| format!("{}=...", p.key))
}

/// A TOML number as `f64`. An integer too large for `i64` is still a number (a large one);
/// `None` for anything not a number.
pub(crate) fn number(v: &DeValue<'_>) -> Option<f64> {
    match v {
        DeValue::Float(f) => f.as_str().replace('_', "").parse::<f64>().ok(),
        DeValue::Integer(i) => {
            let digits = i.as_str().replace('_', "");
            match i64::from_str_radix(&digits, i.radix()) {
                Ok(n) => Some(n as f64),
                // Only decimal integers carry a sign; the others are unsigned.
                Err(_) if i.radix() == 10 => digits.parse::<f64>().ok(),
                Err(_) => Some(f64::INFINITY),
            }
        }
        _ => None,
    }
}

/// A TOML value as a message shows it: literals as written (cut short), others by type.
fn describe(v: &DeValue<'_>) -> String {
    match v {
        DeValue::String(s) => echo::quoted(s),
        DeValue::Integer(i) => echo::echo(&i.to_string()),
        DeValue::Float(f) => echo::echo(f.as_str()),
        DeValue::Boolean(b) => b.to_string(),
        other => {
            let found = other.type_str();
            format!("{} {found}", echo::article(found))
        }
    }
}

/// A value's problem in the key's terms: what it needs, with its range and unit, and what it
/// got ("needs a number from 0.4 to 2 m/s, not 9.5"). The one wording for the config file,
/// `--set` and the lab's editor; [`ConfigError::what`] puts the key in front.
pub(crate) fn needs(spec: &ParamSpec, found: Option<&str>) -> String {
    let not = found.map_or(String::new(), |f| format!(", not {f}"));
    format!("{}{}{not}", errors::NEEDS, spec.needs())
}

/// Checks one value against its key's kind.
fn parse_value(spec: &ParamSpec, value: &DeValue<'_>) -> Result<Value, String> {
    let refused = || needs(spec, Some(&describe(value)));
    match spec.kind {
        Kind::Real { min, max, auto } => {
            if auto && matches!(value, DeValue::String(s) if s == "auto") {
                return Ok(Value::Auto);
            }
            // NaN, the infinities and literals too large for a float (1e999) fall outside
            // every range; the message shows them as written, never as a formatted NaN.
            match number(value) {
                Some(x) if (min..=max).contains(&x) => Ok(Value::Real(x)),
                _ => Err(refused()),
            }
        }
        Kind::Int { min, max } => {
            let n = match value {
                DeValue::Integer(i) => i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok(),
                _ => None,
            };
            // Out of range, too large for 64 bits, or not a whole number at all.
            n.filter(|n| (min..=max).contains(n)).map(Value::Int).ok_or_else(refused)
        }
        Kind::Bool => match value {
            DeValue::Boolean(b) => Ok(Value::Bool(*b)),
            _ => Err(refused()),
        },
        Kind::Choice(words) => {
            let DeValue::String(s) = value else {
                return Err(refused());
            };
            match words.iter().find(|w| **w == s.as_ref()) {
                Some(w) => Ok(Value::Word(w)),
                None => {
                    let hint = did_you_mean(s, words.iter().copied())
                        .map_or(String::new(), |w| format!(" (did you mean \"{w}\"?)"));
                    Err(format!("{}{hint}", refused()))
                }
            }
        }
    }
}

/// Parses a config's text.
pub fn parse_str(text: &str, path: &str) -> Result<WalkParams, ConfigErrors> {
    let mut loader = Loader::new();
    loader.read_str(text, path);
    loader.finish()
}

/// Loads a config file, then applies `--set` overrides, then checks the whole.
/// The file is read with [`read_source`]: bounded in size and time, UTF-8.
pub fn load(path: &Path, sets: &[String]) -> Result<WalkParams, ConfigErrors> {
    let text = read_source(path)?;
    load_text(&text, &path.display().to_string(), sets)
}

/// [`load`], also giving the text read: for callers that keep it (the report's `config.toml`,
/// the lab's save and key bindings). Reading once matters: a pipe (`<(...)`, a FIFO) has
/// nothing left for a second read, or blocks it.
pub fn load_with_text(path: &Path, sets: &[String]) -> Result<(String, WalkParams), ConfigErrors> {
    let text = read_source(path)?;
    let params = load_text(&text, &path.display().to_string(), sets)?;
    Ok((text, params))
}

/// Parses config text, then applies `--set` overrides, then checks the whole.
pub fn load_text(text: &str, label: &str, sets: &[String]) -> Result<WalkParams, ConfigErrors> {
    let mut loader = Loader::new();
    loader.read_str(text, label);
    for (i, s) in sets.iter().enumerate() {
        loader.apply_set(s, i + 1);
    }
    loader.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::params::TerrainChoice;

    #[test]
    fn line_and_column_count_characters() {
        assert_eq!(line_col("ab\ncdé\nx", 0), (1, 1));
        assert_eq!(line_col("ab\ncdé\nx", 3), (2, 1));
        assert_eq!(line_col("ab\ncdé\nx", 8), (3, 1));
    }

    #[test]
    fn unknown_key_gets_a_suggestion_and_place() {
        let e = parse_str("[walk]\nsped_mps = 1.2\n", "a.toml").unwrap_err();
        let text = e.to_string();
        assert!(text.starts_with("a.toml:2:1: walk.sped_mps: unknown key; did you mean `speed_mps`?"), "{text}");
    }

    #[test]
    fn out_of_range_names_the_range() {
        let e = parse_str("[walk]\nspeed_mps = 9.0\n", "b.toml").unwrap_err();
        assert_eq!(e.0[0].line, 2);
        assert_eq!(e.0[0].col, 13);
        assert!(e.0[0].message.contains("from 0.4 to 2 m/s"), "{}", e.0[0].message);
    }

    #[test]
    fn set_overrides_and_accepts_bare_words() {
        let p = load_text(
            "[walk]\nspeed_mps = 1.2\n",
            "c.toml",
            &["walk.speed_mps=1.5".into(), "terrain.kind=slope".into()],
        )
        .unwrap();
        assert_eq!(p.walk.speed_mps, 1.5);
        assert_eq!(p.terrain.kind, TerrainChoice::Slope);
        let e = load_text("", "c.toml", &["walk.speed_mps=fast".into()]).unwrap_err();
        assert_eq!(e.to_string(), "--set #1:1:16: walk.speed_mps needs a number from 0.4 to 2 m/s, not \"fast\"");
    }
}
