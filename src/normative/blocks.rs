//! Norms tabulated in speed blocks: reading a table of them, which blocks a walk's speed falls
//! between, and how to say so. Shared by the joint-curve references, the spatiotemporal norms
//! and the pelvis norms.

use crate::error::{Error, Result};

/// Of `speeds` (rising), the two blocks around `speed_mps` and how far between them it is
/// (0 at the first): the end block twice beyond either end or for NaN.
pub(super) fn bracket(speeds: &[f64], speed_mps: f64) -> (usize, usize, f64) {
    let last = speeds.len() - 1;
    if speed_mps.is_nan() || speed_mps <= speeds[0] {
        return (0, 0, 0.0);
    }
    if speed_mps >= speeds[last] {
        return (last, last, 0.0);
    }
    let i = speeds.windows(2).position(|w| speed_mps < w[1]).unwrap_or(0);
    (i, i + 1, (speed_mps - speeds[i]) / (speeds[i + 1] - speeds[i]))
}

/// Which blocks (`from`, `to` m/s) a norm at `speed_mps` came from, in words: "the 1.232 m/s
/// block", "interpolated between the 1.232 and 1.417 m/s blocks", or "the 1.417 m/s block,
/// the fastest (the walk is faster; not extrapolated)".
pub(super) fn blocks_used(speed_mps: f64, (from, to): (f64, f64)) -> String {
    if from < to {
        return format!("interpolated between the {from:.3} and {to:.3} m/s blocks");
    }
    match beyond_blocks(speed_mps, (from, to)) {
        Some(end) => format!("the {to:.3} m/s block, the {end} (the walk is {}; not extrapolated)", walk_is(end)),
        None => format!("the {from:.3} m/s block"),
    }
}

/// "fastest" or "slowest" where a norm at `speed_mps` was read from the end block (`from` =
/// `to`) because the walk is faster or slower than every block; `None` where it was read at
/// the walk's own speed.
pub(super) fn beyond_blocks(speed_mps: f64, (from, to): (f64, f64)) -> Option<&'static str> {
    if from < to {
        None
    } else if speed_mps > to + 1e-9 {
        Some("fastest")
    } else if speed_mps < from - 1e-9 {
        Some("slowest")
    } else {
        None
    }
}

fn walk_is(end: &str) -> &'static str {
    if end == "fastest" { "faster" } else { "slower" }
}

/// Reads a table of speed blocks: `#` comments, a header, one row a block; returns the
/// `wanted` columns of each row (the first is the block's speed), every value a positive
/// number, the speeds rising, at least two rows. Errors name `label`, the line and the columns.
pub(super) fn parse_rows(text: &str, label: &str, wanted: &[&str]) -> Result<Vec<Vec<f64>>> {
    let bad = |line: usize, message: String| Error::Usage(format!("{label}:{line}: {message}"));
    let mut rows = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'));
    let (header_line, header) = rows.next().ok_or_else(|| bad(1, "no header".into()))?;
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let at: Vec<usize> = wanted
        .iter()
        .map(|w| columns.iter().position(|c| c == w).ok_or_else(|| bad(header_line + 1, format!("no column `{w}`"))))
        .collect::<Result<_>>()?;
    let mut out: Vec<Vec<f64>> = Vec::new();
    for (n, line) in rows {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        let value = |i: usize| cells.get(i).and_then(|c| c.parse::<f64>().ok()).filter(|v| v.is_finite() && *v > 0.0);
        let v: Vec<f64> = at
            .iter()
            .map(|&i| value(i))
            .collect::<Option<_>>()
            .ok_or_else(|| bad(n + 1, format!("expected positive numbers in {}", wanted.join(", "))))?;
        if out.last().is_some_and(|b| b[0] >= v[0]) {
            return Err(bad(n + 1, "speeds must rise from row to row".into()));
        }
        out.push(v);
    }
    if out.len() < 2 {
        return Err(bad(header_line + 1, format!("{} speed blocks; expected at least 2", out.len())));
    }
    Ok(out)
}
