//! The snapshot file, `NAME.snap.json` beside `NAME.toml`: JSON written by hand so that it is
//! the same bytes on every run and platform and diffs line by line — fixed key order (the
//! interface's), one value a line, each number to its kind's decimals, no timestamps, no
//! paths but the config's file name.

use super::measure::{POINTS, Snapshot, kind_of};
use crate::config::{ConfigError, ConfigErrors};
use serde_json::Value;
use std::fmt::Write as _;

/// The format's version, the file's first key.
pub const FORMAT: u64 = 1;

/// A number as stored: its kind's decimals, `null` when not finite.
#[must_use]
pub fn number_text(key: &str, x: f64) -> String {
    if x.is_finite() { format!("{:.*}", kind_of(key).decimals(), kind_of(key).round(x)) } else { "null".into() }
}

/// The snapshot's text.
#[must_use]
pub fn render(s: &Snapshot) -> String {
    let quote = |text: &str| serde_json::to_string(text).unwrap_or_else(|_| "\"\"".into());
    let mut out = String::from("{\n");
    let _ = writeln!(out, "  \"gaitlab_snapshot\": {FORMAT},");
    let _ = writeln!(out, "  \"config\": {},", quote(&s.config));
    let _ = writeln!(out, "  \"sim\": {{\n    \"cycles\": {},\n    \"fps\": {}\n  }},", s.cycles, s.fps);
    if let Some(part) = &s.steady_part {
        let _ = writeln!(out, "  \"steady_part\": {},", quote(part));
    }
    let summary: Vec<String> =
        s.summary.iter().map(|(key, x)| format!("    {}: {}", quote(key), number_text(key, *x))).collect();
    let _ = writeln!(out, "  \"summary\": {{\n{}\n  }},", summary.join(",\n"));
    let _ = writeln!(
        out,
        "  \"curves_sampled_at\": \"0 to 100 % of the right gait cycle, every {} %; mean of the steady cycles\",",
        100 / (POINTS - 1)
    );
    let curves: Vec<String> = s
        .curves
        .iter()
        .map(|(name, points)| {
            let values: Vec<String> = points.iter().map(|x| format!("      {}", number_text(name, *x))).collect();
            format!("    {}: [\n{}\n    ]", quote(name), values.join(",\n"))
        })
        .collect();
    let _ = writeln!(out, "  \"curves\": {{\n{}\n  }}", curves.join(",\n"));
    out.push_str("}\n");
    out
}

/// Reads a snapshot's text (`label` names it in problems).
pub fn parse(text: &str, label: &str) -> Result<Snapshot, ConfigErrors> {
    let problem = |line: usize, col: usize, key: &str, message: String| {
        ConfigErrors(vec![ConfigError { path: label.to_string(), line, col, key: key.to_string(), message }])
    };
    let value: Value = serde_json::from_str(text)
        .map_err(|e| problem(e.line().max(1), e.column().max(1), "", format!("not JSON: {e}")))?;
    let bad = |key: &str, what: &str| {
        problem(1, 1, key, format!("{what}; not a gaitlab snapshot of format {FORMAT} (rewrite it with --update)"))
    };
    if value["gaitlab_snapshot"].as_u64() != Some(FORMAT) {
        return Err(bad("gaitlab_snapshot", "missing or another version"));
    }
    let number = |v: &Value| if v.is_null() { Some(f64::NAN) } else { v.as_f64() };
    let summary = value["summary"].as_object().ok_or_else(|| bad("summary", "expected an object"))?;
    let summary = summary
        .iter()
        .map(|(k, v)| {
            number(v).map(|x| (k.clone(), x)).ok_or_else(|| bad(&format!("summary.{k}"), "expected a number"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let curves = value["curves"].as_object().ok_or_else(|| bad("curves", "expected an object"))?;
    let curves = curves
        .iter()
        .map(|(k, v)| {
            let points = v.as_array().and_then(|a| a.iter().map(number).collect::<Option<Vec<f64>>>());
            points.map(|p| (k.clone(), p)).ok_or_else(|| bad(&format!("curves.{k}"), "expected an array of numbers"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Snapshot {
        config: value["config"].as_str().unwrap_or_default().to_string(),
        cycles: value["sim"]["cycles"].as_u64().and_then(|c| u32::try_from(c).ok()).unwrap_or(0),
        fps: value["sim"]["fps"].as_f64().unwrap_or(f64::NAN),
        summary,
        curves,
        steady_part: value["steady_part"].as_str().map(str::to_string),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::snapshot::measure::CURVES;

    fn sample() -> Snapshot {
        Snapshot {
            config: "a \"b\".toml".into(),
            cycles: 10,
            fps: 59.94,
            summary: vec![("speed_mps".into(), 1.3), ("reach_failures".into(), 0.0), ("x_deg".into(), -0.00001)],
            curves: CURVES.iter().map(|c| ((*c).to_string(), vec![1.23456, -2.0])).collect(),
            steady_part: None,
        }
    }

    #[test]
    fn a_snapshot_reads_back_as_written_one_value_a_line() {
        let text = render(&sample());
        assert!(text.contains("\n    \"speed_mps\": 1.300000,\n    \"reach_failures\": 0,\n    \"x_deg\": 0.0000\n"));
        assert!(text.contains("\n      1.2346,\n      -2.0000\n"), "{text}");
        let back = parse(&text, "a.snap.json").unwrap();
        assert_eq!(back.fps, 59.94);
        assert_eq!(back.curves[0].1, vec![1.2346, -2.0]);
        assert_eq!(render(&back).len(), text.len());
        let e = parse("{\"gaitlab_snapshot\": 1,\n \"summary\": 3}", "a.snap.json").unwrap_err();
        assert!(e.to_string().starts_with("a.snap.json:1:1: summary: expected an object"), "{e}");
        let e = parse("{\n  oops", "a.snap.json").unwrap_err();
        assert!(e.to_string().starts_with("a.snap.json:2:3: not JSON"), "{e}");
    }
}
