//! `gaitlab snapshot --junit FILE`: the run as JUnit XML, which CI systems show as tests —
//! one testsuite, one testcase a config, a `<failure>` listing what moved for a drifted one
//! (or saying the snapshot is missing).

use super::compare::{Moved, Outcome, Status};
use super::format::number_text;
use std::fmt::Write as _;

/// `text` with XML's special characters escaped (for attributes and text alike).
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && !matches!(c, '\n' | '\t' | '\r') => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// A moved figure as one line: `metric: old -> new (change, allowed)`.
#[must_use]
pub fn moved_line(m: &Moved) -> String {
    let value = |x: Option<f64>| x.map_or_else(|| "none".to_string(), |x| number_text(&m.key, x));
    format!(
        "{}: {} -> {} (change {}, allowed {})",
        m.metric,
        value(m.old),
        value(m.new),
        change_text(m),
        number_text(&m.key, m.allowed)
    )
}

/// A moved figure's change with its sign, to its kind's decimals (`-` when one side is missing).
#[must_use]
pub fn change_text(m: &Moved) -> String {
    let change = m.change();
    if change.is_finite() {
        let text = number_text(&m.key, change.abs());
        if change < 0.0 { format!("-{text}") } else { format!("+{text}") }
    } else {
        "-".into()
    }
}

/// The JUnit XML of a run.
#[must_use]
pub fn junit_xml(outcomes: &[Outcome]) -> String {
    let failures = outcomes.iter().filter(|o| o.failed()).count();
    let total: f64 = outcomes.iter().map(|o| o.seconds).sum();
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        xml,
        "<testsuite name=\"gaitlab snapshot\" tests=\"{}\" failures=\"{failures}\" errors=\"0\" skipped=\"0\" time=\"{total:.3}\">",
        outcomes.len()
    );
    for o in outcomes {
        let name = escape(&o.config.display().to_string());
        let _ = write!(xml, "  <testcase classname=\"gaitlab.snapshot\" name=\"{name}\" time=\"{:.3}\"", o.seconds);
        let failure = match o.status {
            Status::Drift => Some((
                format!("{} moved: {}", o.moved.len(), names(&o.moved)),
                o.moved.iter().map(moved_line).collect::<Vec<_>>().join("\n"),
            )),
            Status::Missing => Some((
                format!("no snapshot {}", o.snapshot.display()),
                "run `gaitlab snapshot --update` to write it, then review and commit it".to_string(),
            )),
            Status::Ok | Status::Updated => None,
        };
        match failure {
            Some((message, body)) => {
                let kind = o.status.name();
                let _ = writeln!(
                    xml,
                    ">\n    <failure type=\"{kind}\" message=\"{}\">{}</failure>\n  </testcase>",
                    escape(&message),
                    escape(&body)
                );
            }
            None => xml.push_str("/>\n"),
        }
    }
    xml.push_str("</testsuite>\n");
    xml
}

/// The moved figures' names, comma-separated.
fn names(moved: &[Moved]) -> String {
    moved.iter().map(|m| m.metric.as_str()).collect::<Vec<_>>().join(", ")
}
