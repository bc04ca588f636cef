//! How far a snapshotted figure may move before it counts as drift: a default per kind of
//! figure (told by its key's unit suffix), overridable per kind or per figure by a small
//! TOML file (`gaitlab snapshot --tolerance FILE`).
//!
//! | kind (file key) | figures | default | stored to |
//! |---|---|---|---|
//! | `angles_deg` | keys ending `_deg`, every joint curve | 0.05° | 1e-4° |
//! | `lengths_m` | keys ending `_m` | 0.0001 m (0.1 mm) | 1 µm |
//! | `lengths_cm` | keys ending `_cm` | 0.01 cm (0.1 mm) | 1 µm |
//! | `lengths_mm` | keys ending `_mm` | 0.1 mm | 1 µm |
//! | `percentages_pct` | keys ending `_pct` | 0.01 % | 1e-4 % |
//! | `speeds_mps` | keys ending `_mps` | 0.0001 m/s | 1 µm/s |
//! | `cadences_spm` | keys ending `_spm` | 0.01 steps/min | 1e-4 steps/min |
//! | `times_s` | keys ending `_s` | 0.0001 s | 1 µs |
//! | `counts` | reach failures, non-finite values, optimiser steps, infeasible steps, the walk's cycles and fps | exact | whole numbers |
//! | `costs_relative` | keys ending `_cost` | 1e-6 of the old value (never under 1e-6) | 1e-6 |
//!
//! "Stored to" is the rounding of the snapshot file, the report's tables' (the joint table's
//! µm and 1e-4°, `optimisation.csv`'s six decimals for costs); both sides of a comparison
//! are rounded so, and a stored step is always far under the tolerance.

use crate::config::{ConfigError, ConfigErrors, line_col, number, read_source, schema::did_you_mean};
use std::collections::BTreeMap;
use std::path::Path;
use toml::de::{DeTable, DeValue};

/// A kind of figure: its unit decides its default tolerance and its rounding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Degrees.
    Angle,
    /// Metres.
    Metres,
    /// Centimetres.
    Centimetres,
    /// Millimetres.
    Millimetres,
    /// Percent.
    Percent,
    /// Metres per second.
    Speed,
    /// Steps per minute.
    Cadence,
    /// Seconds.
    Seconds,
    /// Whole numbers, compared exactly.
    Count,
    /// Optimiser costs, compared relatively.
    Cost,
}

/// Figures counted in whole numbers (compared exactly by default).
const COUNTS: &[&str] =
    &["reach_failures", "non_finite_values", "optimiser_steps", "optimiser_infeasible_steps", "sim_cycles", "sim_fps"];

impl Kind {
    /// Every kind, in the order of the table above.
    pub const ALL: [Kind; 10] = [
        Kind::Angle,
        Kind::Metres,
        Kind::Centimetres,
        Kind::Millimetres,
        Kind::Percent,
        Kind::Speed,
        Kind::Cadence,
        Kind::Seconds,
        Kind::Count,
        Kind::Cost,
    ];

    /// The kind of the figure `key`, from its unit suffix; `None` for a key without one.
    #[must_use]
    pub fn of(key: &str) -> Option<Kind> {
        if COUNTS.contains(&key) {
            return Some(Kind::Count);
        }
        let suffixes = [
            ("_deg", Kind::Angle),
            ("_cm", Kind::Centimetres),
            ("_mm", Kind::Millimetres),
            ("_mps", Kind::Speed),
            ("_spm", Kind::Cadence),
            ("_pct", Kind::Percent),
            ("_cost", Kind::Cost),
            ("_m", Kind::Metres),
            ("_s", Kind::Seconds),
        ];
        suffixes.iter().find(|(suffix, _)| key.ends_with(suffix)).map(|&(_, kind)| kind)
    }

    /// The key that sets this kind's tolerance in a tolerance file.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Kind::Angle => "angles_deg",
            Kind::Metres => "lengths_m",
            Kind::Centimetres => "lengths_cm",
            Kind::Millimetres => "lengths_mm",
            Kind::Percent => "percentages_pct",
            Kind::Speed => "speeds_mps",
            Kind::Cadence => "cadences_spm",
            Kind::Seconds => "times_s",
            Kind::Count => "counts",
            Kind::Cost => "costs_relative",
        }
    }

    /// The default tolerance (absolute, in the figure's unit; relative for costs).
    #[must_use]
    pub fn default_tolerance(self) -> f64 {
        match self {
            Kind::Angle => 0.05,
            Kind::Metres | Kind::Speed | Kind::Seconds => 1e-4,
            Kind::Centimetres | Kind::Percent | Kind::Cadence => 0.01,
            Kind::Millimetres => 0.1,
            Kind::Count => 0.0,
            Kind::Cost => 1e-6,
        }
    }

    /// Decimals a snapshot keeps (the report's tables' rounding: µm, 1e-4°, costs to 1e-6).
    #[must_use]
    pub fn decimals(self) -> usize {
        match self {
            Kind::Angle | Kind::Centimetres | Kind::Percent | Kind::Cadence => 4,
            Kind::Metres | Kind::Speed | Kind::Seconds | Kind::Cost => 6,
            Kind::Millimetres => 3,
            Kind::Count => 0,
        }
    }

    /// `x` rounded to [`Kind::decimals`] (half away from zero; −0 becomes 0).
    #[must_use]
    pub fn round(self, x: f64) -> f64 {
        let scale = 10f64.powi(self.decimals() as i32);
        let r = (x * scale).round() / scale;
        if r == 0.0 { 0.0 } else { r }
    }
}

/// The tolerances a comparison uses: the defaults, with a file's overrides.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tolerances {
    /// Per kind (file key `angles_deg`, ...).
    by_kind: BTreeMap<&'static str, f64>,
    /// Per figure or curve (file key `knee_flex_max_swing_deg`, `knee_flex_r_deg`, ...).
    by_key: BTreeMap<String, f64>,
}

impl Tolerances {
    /// How far figure `key` of kind `kind` may move from `old`.
    #[must_use]
    pub fn allowed(&self, key: &str, kind: Kind, old: f64) -> f64 {
        let tolerance =
            self.by_key.get(key).or_else(|| self.by_kind.get(kind.name())).copied().unwrap_or(kind.default_tolerance());
        if kind == Kind::Cost { (tolerance * old.abs()).max(1e-6) } else { tolerance }
    }

    /// Reads a tolerance file: one `[tolerance]` table of `KEY = NUMBER` (≥ 0), each key a
    /// kind (`angles_deg`, ...) or a figure (`known` lists them). Problems are located like a
    /// config's (`PATH:LINE:COL: key: message`).
    pub fn load(path: &Path, known: &[&str]) -> Result<Tolerances, ConfigErrors> {
        let text = read_source(path)?;
        Tolerances::parse(&text, &path.display().to_string(), known)
    }

    /// [`Tolerances::load`] of text labelled `label`.
    pub fn parse(text: &str, label: &str, known: &[&str]) -> Result<Tolerances, ConfigErrors> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let problem = |at: usize, key: &str, message: String| {
            let (line, col) = line_col(text, at);
            ConfigError { path: label.to_string(), line, col, key: key.to_string(), message }
        };
        let root = DeTable::parse(text).map_err(|e| {
            let at = e.span().map_or(0, |s| s.start);
            ConfigErrors(vec![problem(at, "", format!("TOML syntax: {}", e.message().trim()))])
        })?;
        let mut errors = Vec::new();
        let mut tolerances = Tolerances::default();
        let kinds: Vec<&str> = Kind::ALL.iter().map(|k| k.name()).collect();
        let mut entries: Vec<_> = root.get_ref().iter().collect();
        entries.sort_by_key(|(k, _)| k.span().start);
        for (group, value) in entries {
            let (name, at) = (group.get_ref().as_ref(), group.span().start);
            let DeValue::Table(table) = value.get_ref() else {
                errors.push(problem(at, name, "expected the table [tolerance]".into()));
                continue;
            };
            if name != "tolerance" {
                errors.push(problem(at, name, "unknown table; a tolerance file has only [tolerance]".into()));
                continue;
            }
            let mut keys: Vec<_> = table.iter().collect();
            keys.sort_by_key(|(k, _)| k.span().start);
            for (key, value) in keys {
                let (name, at) = (key.get_ref().as_ref(), key.span().start);
                let dotted = format!("tolerance.{name}");
                if !kinds.contains(&name) && !known.contains(&name) {
                    let hint = did_you_mean(name, kinds.iter().chain(known).copied())
                        .map_or(String::new(), |k| format!("did you mean `{k}`? "));
                    let message = format!("unknown key; {hint}valid: a kind ({}) or a figure's key", kinds.join(", "));
                    errors.push(problem(at, &dotted, message));
                    continue;
                }
                match number(value.get_ref()) {
                    Some(x) if x.is_finite() && x >= 0.0 => {
                        match Kind::ALL.iter().find(|k| k.name() == name) {
                            Some(kind) => tolerances.by_kind.insert(kind.name(), x),
                            None => tolerances.by_key.insert(name.to_string(), x),
                        };
                    }
                    _ => errors.push(problem(
                        value.span().start,
                        &dotted,
                        "expected a number, 0 or more (in the figure's unit; relative for costs)".into(),
                    )),
                }
            }
        }
        if errors.is_empty() { Ok(tolerances) } else { Err(ConfigErrors(errors)) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_summary_figure_has_a_kind() {
        for (key, _, _) in crate::report::metrics::LABELS {
            assert!(Kind::of(key).is_some(), "{key}");
        }
        assert_eq!(Kind::of("reach_failures"), Some(Kind::Count));
        assert_eq!(Kind::of("stride_length_m"), Some(Kind::Metres));
        assert_eq!(Kind::of("optimiser_mean_cost"), Some(Kind::Cost));
    }

    #[test]
    fn a_file_overrides_kinds_and_keys_and_locates_unknown_keys() {
        let t = Tolerances::parse("[tolerance]\nangles_deg = 0.1\nknee_deg = 2\n", "t.toml", &["knee_deg"]).unwrap();
        assert_eq!(t.allowed("knee_deg", Kind::Angle, 0.0), 2.0);
        assert_eq!(t.allowed("hip_deg", Kind::Angle, 0.0), 0.1);
        assert_eq!(t.allowed("x_m", Kind::Metres, 0.0), 1e-4);
        assert_eq!(t.allowed("c_cost", Kind::Cost, 4000.0), 4000.0 * 1e-6);
        let e = Tolerances::parse("[tolerance]\n\nangels_deg = 0.1\n", "t.toml", &[]).unwrap_err();
        assert!(
            e.to_string().starts_with("t.toml:3:1: tolerance.angels_deg: unknown key; did you mean `angles_deg`?"),
            "{e}"
        );
        let e = Tolerances::parse("[tolerance]\nangles_deg = -1\n", "t.toml", &[]).unwrap_err();
        assert!(e.to_string().starts_with("t.toml:2:14: tolerance.angles_deg: expected a number"), "{e}");
        let e = Tolerances::parse("[tolerances]\n", "t.toml", &[]).unwrap_err();
        assert!(e.to_string().starts_with("t.toml:1:2: tolerances: unknown table"), "{e}");
    }
}
