//! Config files: TOML in, validated [`WalkParams`] out, with errors that name the file, line,
//! column, key and the valid range; `--set KEY=VALUE` overrides; `gaitlab init` output.
//!
//! Parsing walks the TOML document with its spans (`toml::de::DeTable`) against the key
//! table in [`schema`], so every problem in a file is reported at once, in file order, and
//! unknown keys get a "did you mean".

pub mod edit;
pub mod presets;
pub mod render;
pub mod schema;

use crate::model::curve::Curve;
use crate::model::gait_curves::CurveName;
use crate::model::params::{TerrainChoice, WalkParams};
use schema::{GROUPS, Kind, PARAMS, ParamSpec, Value, did_you_mean, spec};
use std::collections::HashMap;
use std::fmt;
use std::path::Path;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// One problem in a config, at a place.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigError {
    /// The file (or `--set`) the problem is in.
    pub path: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column (characters).
    pub col: usize,
    /// The dotted key, or empty for a syntax error.
    pub key: String,
    /// What is wrong and what would be valid.
    pub message: String,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.key.is_empty() {
            write!(f, "{}:{}:{}: {}", self.path, self.line, self.col, self.message)
        } else {
            write!(f, "{}:{}:{}: {}: {}", self.path, self.line, self.col, self.key, self.message)
        }
    }
}

/// All problems found in one config.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigErrors(pub Vec<ConfigError>);

impl fmt::Display for ConfigErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ConfigErrors {}

/// A place in a source: (path label, line, column).
type Place = (String, usize, usize);

/// Reads TOML into parameters, remembering where each key was set.
#[derive(Debug, Default)]
pub struct Loader {
    params: WalkParams,
    places: HashMap<String, Place>,
    errors: Vec<ConfigError>,
}

/// Line and column (1-based, in characters) of byte offset `at` in `text`.
#[must_use]
pub fn line_col(text: &str, at: usize) -> (usize, usize) {
    let at = at.min(text.len());
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

impl Loader {
    /// Starts from the built-in defaults.
    #[must_use]
    pub fn new() -> Self {
        Loader::default()
    }

    /// Starts from given parameters (a loaded file, before `--set`).
    #[must_use]
    pub fn from_params(params: WalkParams) -> Self {
        Loader { params, ..Loader::default() }
    }

    fn error(&mut self, place: &Place, key: &str, message: impl Into<String>) {
        self.errors.push(ConfigError {
            path: place.0.clone(),
            line: place.1,
            col: place.2,
            key: key.to_string(),
            message: message.into(),
        });
    }

    /// Reads a whole TOML document.
    pub fn read_str(&mut self, text: &str, path: &str) {
        let place = |at: usize| {
            let (line, col) = line_col(text, at);
            (path.to_string(), line, col)
        };
        let root = match DeTable::parse(text) {
            Ok(root) => root,
            Err(e) => {
                let at = e.span().map_or(0, |s| s.start);
                let message = e.message().trim().to_string();
                self.error(&place(at), "", format!("TOML syntax: {message}"));
                return;
            }
        };
        for (group_key, group_value) in root.get_ref() {
            let group = group_key.get_ref().as_ref();
            let at = place(group_key.span().start);
            // `[keys]` rebinds the terminal lab's keys; the lab reads and checks it itself
            // (key names are a terminal matter), the walk has nothing to take from it.
            if group == "keys" {
                continue;
            }
            if !GROUPS.contains(&group) {
                let hint = did_you_mean(group, GROUPS.iter().copied())
                    .map_or(String::new(), |g| format!("; did you mean [{g}]?"));
                self.error(&at, group, format!("unknown group{hint} (groups: {})", GROUPS.join(", ")));
                continue;
            }
            let DeValue::Table(table) = group_value.get_ref() else {
                let found = group_value.get_ref().type_str();
                let article = if found.starts_with(['a', 'e', 'i', 'o', 'u']) { "an" } else { "a" };
                self.error(&at, group, format!("expected a table [{group}], found {article} {found}"));
                continue;
            };
            for (key, value) in table {
                let name = key.get_ref().as_ref();
                let at = place(key.span().start);
                let value_at = place(value.span().start);
                if group == "curves" {
                    self.read_curve(name, value, &at, &place);
                } else {
                    self.set_key(&format!("{group}.{name}"), value.get_ref(), &at, &value_at);
                }
            }
        }
    }

    /// Reads `[curves.<name>]`: a `points` array of `[x, y]` pairs.
    fn read_curve(&mut self, name: &str, value: &Spanned<DeValue<'_>>, at: &Place, place: &dyn Fn(usize) -> Place) {
        let key = format!("curves.{name}");
        if CurveName::from_key(name).is_none() {
            let hint = did_you_mean(name, CurveName::ALL.iter().map(|c| c.key()))
                .map_or(String::new(), |c| format!("; did you mean `{c}`?"));
            let names: Vec<&str> = CurveName::ALL.iter().map(|c| c.key()).collect();
            self.error(at, &key, format!("unknown curve{hint} (curves: {})", names.join(", ")));
            return;
        }
        let DeValue::Table(table) = value.get_ref() else {
            self.error(at, &key, "expected a table with `points = [[x, y], ...]`");
            return;
        };
        for (k, v) in table {
            let kname = k.get_ref().as_ref();
            let kat = place(k.span().start);
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
            let (group, name) = key.split_once('.').unwrap_or((key, ""));
            let in_group: Vec<&str> = PARAMS.iter().filter(|p| p.group() == group).map(ParamSpec::name).collect();
            let hint = did_you_mean(name, in_group.iter().copied())
                .map(|n| format!("; did you mean `{n}`?"))
                .or_else(|| did_you_mean(key, PARAMS.iter().map(|p| p.key)).map(|k| format!("; did you mean `{k}`?")))
                .unwrap_or_default();
            self.error(at, key, format!("unknown key{hint} (keys of [{group}]: {})", in_group.join(", ")));
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
    pub fn apply_set(&mut self, assignment: &str, index: usize) {
        let label = format!("--set #{index}");
        let Some((key, value_text)) = assignment.split_once('=') else {
            self.error(
                &(label, 1, 1),
                assignment,
                "expected KEY=VALUE, like walk.speed_mps=1.4 or terrain.kind=\"stairs\"",
            );
            return;
        };
        let key = key.trim();
        let value_col = assignment.find('=').unwrap_or(0) + 2;
        let at = (label.clone(), 1, 1);
        let value_at = (label.clone(), 1, value_col);
        // Plain words are forgiven their missing quotes: `terrain.kind=stairs`.
        let quoted;
        let mut text = value_text.trim();
        if !text.is_empty()
            && text.chars().all(|c| c.is_ascii_alphabetic() || c == '_')
            && text != "true"
            && text != "false"
        {
            quoted = format!("\"{text}\"");
            text = &quoted;
        }
        let parsed = match DeValue::parse(text) {
            Ok(v) => v,
            Err(e) => {
                self.error(&value_at, key, format!("value is not TOML: {}", e.message().trim()));
                return;
            }
        };
        if let Some(rest) = key.strip_prefix("curves.") {
            let name = rest.strip_suffix(".points").unwrap_or(rest);
            if CurveName::from_key(name).is_none() {
                let hint = did_you_mean(name, CurveName::ALL.iter().map(|c| c.key()))
                    .map_or(String::new(), |c| format!("; did you mean `{c}`?"));
                self.error(&at, key, format!("unknown curve{hint}"));
                return;
            }
            self.set_curve_points(name, parsed.get_ref(), &value_at);
        } else {
            self.set_key(key, parsed.get_ref(), &at, &value_at);
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
        self.places.values().min_by_key(|p| (p.1, p.2)).cloned().unwrap_or(("config".into(), 1, 1))
    }

    /// Parameters read so far.
    #[must_use]
    pub fn params(&self) -> &WalkParams {
        &self.params
    }
}

fn number(v: &DeValue<'_>) -> Option<f64> {
    match v {
        DeValue::Float(f) => f.as_str().replace('_', "").parse::<f64>().ok(),
        DeValue::Integer(i) => i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok().map(|n| n as f64),
        _ => None,
    }
}

fn describe(v: &DeValue<'_>) -> String {
    match v {
        DeValue::String(s) => format!("\"{s}\""),
        DeValue::Integer(i) => i.as_str().to_string(),
        DeValue::Float(f) => f.as_str().to_string(),
        DeValue::Boolean(b) => b.to_string(),
        other => format!("a {}", other.type_str()),
    }
}

/// Checks one value against its key's kind.
fn parse_value(spec: &ParamSpec, value: &DeValue<'_>) -> Result<Value, String> {
    let valid = spec.valid_range();
    match spec.kind {
        Kind::Real { min, max, auto } => {
            if auto && matches!(value, DeValue::String(s) if s == "auto") {
                return Ok(Value::Auto);
            }
            let Some(x) = number(value) else {
                return Err(format!("expected a number, found {}; valid: {valid}", describe(value)));
            };
            if !x.is_finite() {
                return Err(format!("{} is not a finite number; valid: {valid}", describe(value)));
            }
            if x < min || x > max {
                return Err(format!("{} is out of range; valid: {valid}", describe(value)));
            }
            Ok(Value::Real(x))
        }
        Kind::Int { min, max } => {
            let n = match value {
                DeValue::Integer(i) => i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok(),
                _ => None,
            };
            let Some(n) = n else {
                return Err(format!("expected a whole number, found {}; valid: {valid}", describe(value)));
            };
            if n < min || n > max {
                return Err(format!("{n} is out of range; valid: {valid}"));
            }
            Ok(Value::Int(n))
        }
        Kind::Bool => match value {
            DeValue::Boolean(b) => Ok(Value::Bool(*b)),
            other => Err(format!("expected true or false, found {}", describe(other))),
        },
        Kind::Choice(words) => {
            let DeValue::String(s) = value else {
                return Err(format!("expected a quoted word, found {}; valid: {valid}", describe(value)));
            };
            match words.iter().find(|w| **w == s.as_ref()) {
                Some(w) => Ok(Value::Word(w)),
                None => {
                    let hint = did_you_mean(s, words.iter().copied())
                        .map_or(String::new(), |w| format!("; did you mean \"{w}\"?"));
                    Err(format!("\"{s}\" is not a choice{hint}; valid: {valid}"))
                }
            }
        }
    }
}

/// Checks control points of the named model curve: valid Bézier chain over x ∈ [0, 1], and
/// for cycle curves, ends that meet.
pub fn check_curve(name: &str, pairs: &[(f64, f64)]) -> Result<(), String> {
    let curve = Curve::from_pairs(name, pairs).map_err(|e| e.to_string())?;
    if curve.x_start() != 0.0 || curve.x_end() != 1.0 {
        return Err(format!(
            "curve `{name}` must run from x = 0 to x = 1 (it runs from {} to {})",
            curve.x_start(),
            curve.x_end()
        ));
    }
    let kind = CurveName::from_key(name).expect("checked by caller");
    if kind.is_cyclic() && (curve.eval(0.0) - curve.eval(1.0)).abs() > 1e-9 {
        return Err(format!(
            "curve `{name}` repeats every gait cycle, so its ends must meet: y(0) = {} but y(1) = {}",
            curve.eval(0.0),
            curve.eval(1.0)
        ));
    }
    Ok(())
}

/// Checks across keys; each problem names the keys to blame, the first that was set being
/// reported.
#[must_use]
pub fn cross_check(p: &WalkParams) -> Vec<(Vec<&'static str>, String)> {
    let mut out = Vec::new();
    let r = p.resolve();
    let speed_keys = |k: &'static str| vec![k, "walk.speed_mps"];
    let cadence = 120.0 / r.cycle_s;
    if !(50.0..=160.0).contains(&cadence) {
        out.push((
            speed_keys("walk.cadence_spm"),
            format!(
                "cadence resolves to {cadence:.1} steps/min (speed {} m/s, stride {:.2} m); valid: 50 to 160",
                p.walk.speed_mps, r.stride_m
            ),
        ));
    }
    if !(0.5..=2.0).contains(&r.stride_m) {
        out.push((
            speed_keys("walk.stride_m"),
            format!(
                "stride resolves to {:.2} m (speed {} m/s, cadence {cadence:.1}); valid: 0.5 to 2.0 m",
                r.stride_m, p.walk.speed_mps
            ),
        ));
    }
    if r.toe_off - 0.5 < 0.02 {
        out.push((
            speed_keys("legs.toe_off"),
            format!("toe-off at {:.3} of the cycle leaves almost no double support: that is a run, which gaitlab does not model; valid: toe_off from 0.52", r.toe_off),
        ));
    }
    if r.heel_rise - r.foot_flat < 0.05 {
        out.push((
            vec!["legs.heel_rise", "legs.foot_flat"],
            format!("heel_rise ({}) must come at least 0.05 of a cycle after foot_flat ({})", r.heel_rise, r.foot_flat),
        ));
    }
    if r.toe_off - r.heel_rise < 0.05 {
        out.push((
            vec!["legs.toe_off", "legs.heel_rise"],
            format!("toe_off ({:.3}) must come at least 0.05 of a cycle after heel_rise ({})", r.toe_off, r.heel_rise),
        ));
    }
    if 1.0 - r.toe_off < 0.25 {
        out.push((
            vec!["legs.toe_off"],
            format!("toe_off ({:.3}) leaves a swing shorter than a quarter cycle; valid: up to 0.75", r.toe_off),
        ));
    }
    if p.terrain.kind == TerrainChoice::Stairs {
        let foot = r.dims.foot_length * r.turnout.cos() + 2.0 * r.clearance + 0.01;
        if p.terrain.run_m < foot {
            out.push((
                vec!["terrain.run_m", "terrain.kind"],
                format!("a tread of {} m cannot hold a {:.3} m foot with the clearance on both sides; valid: at least {foot:.3} m", p.terrain.run_m, r.dims.foot_length),
            ));
        }
    }
    if out.is_empty()
        && let Err(e) = crate::model::walk::check(p)
    {
        out.push((vec!["walk.speed_mps"], e.0));
    }
    out
}

/// Parses a config's text.
pub fn parse_str(text: &str, path: &str) -> Result<WalkParams, ConfigErrors> {
    let mut loader = Loader::new();
    loader.read_str(text, path);
    loader.finish()
}

/// Loads a config file, then applies `--set` overrides, then checks the whole.
pub fn load(path: &Path, sets: &[String]) -> Result<WalkParams, ConfigErrors> {
    let label = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| {
        ConfigErrors(vec![ConfigError {
            path: label.clone(),
            line: 1,
            col: 1,
            key: String::new(),
            message: format!("cannot read the config: {e}"),
        }])
    })?;
    load_text(&text, &label, sets)
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
        assert!(e.to_string().starts_with("--set #1:1:16: walk.speed_mps: expected a number"), "{e}");
    }
}
