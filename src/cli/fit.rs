//! `gaitlab fit`: a config calibrated to a normative reference, as a table (or JSON) and, with
//! `--out`, a config file.

use super::common::{in_range, stdout_written};
use crate::config::{self, schema::PARAMS};
use crate::error::{Error, Result};
use crate::fit::{self, FIT_KEYS, FitOptions, FitResult};
use crate::normative::Comparison;
use crate::output::{self, FileTarget};
use std::io::{self, IsTerminal, Write};
use std::path::Path;

/// The command's options.
pub(super) struct Args<'a> {
    pub(super) reference: Option<&'a Path>,
    pub(super) out: Option<&'a Path>,
    pub(super) evaluations: u32,
    pub(super) cycles: u32,
    pub(super) json: bool,
}

pub(super) fn run(path: &Path, args: &Args<'_>, sets: &[String]) -> Result<()> {
    let evaluations = in_range("--evaluations", args.evaluations, 10..=5000, "10 to 5000")?;
    let cycles = in_range("--cycles", args.cycles, 4..=50, "4 to 50")?;
    // Refused before any walking: a fit takes seconds.
    let target = args.out.map(FileTarget::resolve).transpose()?;
    let (text, params) = config::load_with_text(path, sets)?;
    let (reference, source) = super::common::references(args.reference)?;
    if io::stderr().is_terminal() {
        eprintln!("gaitlab fit: up to {evaluations} walks of {cycles} cycles");
    }
    let started = std::time::Instant::now();
    let result = fit::fit(path, &params, &reference, FitOptions { evaluations, cycles })?;
    let seconds = started.elapsed().as_secs_f64();
    // With the config on stdout (`--out -`), the table goes to stderr: one stream, one file.
    let config_on_stdout = matches!(target, Some(FileTarget::Stdout));
    if let Some(target) = target {
        let fitted = fitted_config(&text, &params, &result, &source)?;
        output::write_file(&target, |out: &mut dyn Write| out.write_all(fitted.as_bytes()))?;
    }
    let mut out: Box<dyn Write> = if config_on_stdout {
        Box::new(io::stderr().lock())
    } else {
        Box::new(io::BufWriter::new(io::stdout().lock()))
    };
    let written = if args.json {
        write_json(&mut out, &result, seconds)
    } else {
        write_table(&mut out, path, &source, &result, seconds, args.out)
    };
    stdout_written(written.and_then(|()| out.flush()))
}

/// The input config with the fitted keys (and any `--set` ones) written in, comments kept,
/// under a header saying what was fitted against what.
fn fitted_config(
    text: &str,
    params: &crate::model::params::WalkParams,
    result: &FitResult,
    source: &str,
) -> Result<String> {
    let read = config::load_text(text, "config", &[])?;
    let mut keys: Vec<&str> = PARAMS.iter().filter(|p| (p.get)(&read) != (p.get)(params)).map(|p| p.key).collect();
    // A key with nothing to search (the cadence of a config that sets its stride) is not
    // written: pinned beside the stride it would fix the walk's speed as well.
    let fitted: Vec<&str> =
        FIT_KEYS.iter().zip(&result.ranges).filter(|(_, (min, max))| max > min).map(|(k, _)| k.key).collect();
    keys.extend(fitted.iter().copied());
    let body = config::edit::edited_text(text, &result.params, &keys).map_err(Error::Usage)?;
    let (before, after) = (rms_line(&result.comparison.0), rms_line(&result.comparison.1));
    Ok(format!(
        "# Fitted by `gaitlab fit` against {source} at {:.3} m/s, {}.\n\
         # Hip / knee / ankle RMS difference (deg): {before} before, {after} after ({} walks).\n\
         # {}.\n\
         # Keys fitted: {}.\n\n{body}",
        result.comparison.0.reference_speed_mps,
        result.comparison.0.reference_blocks(),
        result.evaluations,
        pelvis_line(&result.comparison),
        fitted.join(", ")
    ))
}

/// The walk's pelvis vertical range before and after beside people's at its speed.
fn pelvis_line((before, after): &(Comparison, Comparison)) -> String {
    let (mean, sd) = after.pelvis_norms.vertical_range_cm;
    format!(
        "Pelvis vertical range: {:.2} cm before, {:.2} after (people's {mean:.2} +- {sd:.2} cm)",
        before.pelvis_vertical_range_cm, after.pelvis_vertical_range_cm
    )
}

fn rms_line(c: &Comparison) -> String {
    c.curves.iter().take(3).map(|k| format!("{:.2}", k.rms_deg)).collect::<Vec<_>>().join(" / ")
}

fn write_table(
    out: &mut dyn Write,
    path: &Path,
    source: &str,
    r: &FitResult,
    seconds: f64,
    written: Option<&Path>,
) -> io::Result<()> {
    let (before, after) = &r.comparison;
    writeln!(
        out,
        "# {} at {:.3} m/s against {source}, {}: {} walks in {seconds:.1} s",
        path.display(),
        before.speed_mps,
        before.reference_blocks(),
        r.evaluations
    )?;
    writeln!(out, "{:<28} {:>9} {:>9}  range", "key", "start", "fitted")?;
    for (((k, start), fitted), (min, max)) in FIT_KEYS.iter().zip(&r.start).zip(&r.fitted).zip(&r.ranges) {
        writeln!(out, "{:<28} {start:>9.3} {fitted:>9.3}  {} to {}", k.key, short(*min), short(*max))?;
    }
    writeln!(
        out,
        "{:<12} {:>10} {:>9} {:>8} {:>7} {:>9} {:>8}",
        "curve", "rms_before", "rms_after", "r_before", "r_after", "out2%_bef", "out2%_aft"
    )?;
    for (b, a) in before.curves.iter().zip(&after.curves).take(3) {
        writeln!(
            out,
            "{:<12} {:>10.2} {:>9.2} {:>8.3} {:>7.3} {:>9.0} {:>8.0}",
            b.curve, b.rms_deg, a.rms_deg, b.pearson_r, a.pearson_r, b.outside_2sd_pct, a.outside_2sd_pct
        )?;
    }
    writeln!(out, "{}", pelvis_line(&r.comparison))?;
    writeln!(out, "cost (mean RMS of hip, knee and ankle, deg, + penalties): {:.3} -> {:.3}", r.cost.0, r.cost.1)?;
    match written {
        Some(p) => writeln!(out, "wrote {}", p.display()),
        None => writeln!(out, "(--out FILE writes the fitted config)"),
    }
}

fn write_json(out: &mut dyn Write, r: &FitResult, seconds: f64) -> io::Result<()> {
    let keys: Vec<serde_json::Value> = FIT_KEYS
        .iter()
        .zip(&r.start)
        .zip(&r.fitted)
        .zip(&r.ranges)
        .map(|(((k, s), f), (min, max))| serde_json::json!({"key": k.key, "start": s, "fitted": f, "min": min, "max": max}))
        .collect();
    let line = serde_json::json!({
        "keys": keys,
        "cost_before": r.cost.0,
        "cost_after": r.cost.1,
        "evaluations": r.evaluations,
        "seconds": seconds,
        "curves_before": r.comparison.0.curves,
        "curves_after": r.comparison.1.curves,
        "pelvis_vertical_range_cm_before": r.comparison.0.pelvis_vertical_range_cm,
        "pelvis_vertical_range_cm_after": r.comparison.1.pelvis_vertical_range_cm,
        "pelvis_vertical_range_norm_cm": r.comparison.1.pelvis_norms.vertical_range_cm.0,
        "pelvis_vertical_range_norm_sd_cm": r.comparison.1.pelvis_norms.vertical_range_cm.1,
    });
    writeln!(out, "{line}")
}

/// `v` with at most three decimals and no trailing zeros (a range from the speed norms is
/// not a round number).
fn short(v: f64) -> String {
    let text = format!("{v:.3}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}
