//! `gaitlab optimise`: the per-step pelvis choices of a walk, as a table or JSON lines.

use super::common::{in_range, stdout_written};
use crate::config;
use crate::error::{Error, Result};
use crate::model::optimise::{Candidate, StepRecord};
use crate::model::params::WalkParams;
use crate::model::walk::Walker;
use serde_json::{Value, json};
use std::io::{self, Write};
use std::path::Path;

/// Frame rate the walk is stepped at; the choices do not depend on it beyond the frame at
/// which a toe-off is detected, and 60 fps is what the lab runs at.
const FPS: f64 = 60.0;

pub(super) fn run(path: &Path, steps: Option<u32>, json: bool, sets: &[String]) -> Result<()> {
    let params = config::load(path, sets)?;
    let steps = in_range("--steps", steps.unwrap_or(2 * params.sim.cycles), 1..=100_000, "1 to 100000")?;
    let records =
        walk_steps(&params, steps as usize).map_err(|source| Error::Walk { config: path.to_path_buf(), source })?;
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let written = if json { write_json(&mut out, &records) } else { write_table(&mut out, path, &params, &records) };
    stdout_written(written.and_then(|()| out.flush()))
}

/// Walks until `steps` pelvis choices have been made.
fn walk_steps(params: &WalkParams, steps: usize) -> Result<Vec<StepRecord>, crate::model::walk::ModelError> {
    let mut walker = Walker::new(params)?;
    // The table's time_us column: the command, not the model, reads the clock.
    walker.set_clock(Some(std::time::Instant::now));
    // A step is half a cycle; the bound only guards against a walk that stopped planning.
    let frame_limit = ((steps as f64 + 4.0) * walker.resolved().cycle_s * FPS) as u64;
    let mut frame = 0;
    let mut records = Vec::with_capacity(steps.min(4096));
    // Only the records are kept: the walker's plans are trimmed as it goes, so a long run
    // holds a record a step and nothing more.
    let mut seen = i64::MIN;
    while records.len() < steps && frame < frame_limit {
        walker.advance(1.0 / FPS);
        frame += 1;
        for plan in walker.step_plans() {
            if records.len() < steps && plan.step >= seen {
                records.push(plan.optimisation.clone());
                seen = plan.step + 1;
            }
        }
        walker.keep_recent_history(8);
    }
    Ok(records)
}

/// Summed costs over the steps, optimised and by the fixed rule.
struct Totals {
    chosen: f64,
    fixed_rule: f64,
    /// Steps where the fixed rule could not reach (its cost is not summable).
    fixed_rule_infeasible: usize,
    fallbacks: usize,
    evaluations: u64,
    median_us: f64,
}

fn totals(records: &[StepRecord]) -> Totals {
    let mut times: Vec<f64> = records.iter().filter(|r| r.method.is_some()).map(|r| r.elapsed_us).collect();
    times.sort_by(f64::total_cmp);
    Totals {
        chosen: records.iter().filter_map(|r| r.chosen.cost).sum(),
        fixed_rule: records.iter().filter_map(|r| r.fixed_rule.cost).sum(),
        fixed_rule_infeasible: records.iter().filter(|r| r.fixed_rule.cost.is_none()).count(),
        fallbacks: records.iter().filter(|r| r.fallback).count(),
        evaluations: records.iter().map(|r| u64::from(r.evaluations)).sum(),
        median_us: times.get(times.len() / 2).copied().unwrap_or(0.0),
    }
}

fn cost_text(cost: Option<f64>) -> String {
    cost.map_or_else(|| "unreachable".to_owned(), |c| format!("{c:.4}"))
}

fn write_table(out: &mut dyn Write, path: &Path, params: &WalkParams, records: &[StepRecord]) -> io::Result<()> {
    let o = &params.optimiser;
    let method = if o.enabled { o.method.name() } else { "off (fixed rule)" };
    writeln!(
        out,
        "# {}: method {method}, {} + {} candidates, {} samples, {} cost, weights hip {} knee {} ankle {}, range {}% of the mid-stance gap",
        path.display(),
        o.candidates,
        o.refine,
        o.samples,
        match o.cost {
            crate::model::params::CostForm::Squared => "squared",
            crate::model::params::CostForm::Absolute => "absolute",
        },
        o.weight_hip,
        o.weight_knee,
        o.weight_ankle,
        o.range_pct,
    )?;
    writeln!(
        out,
        "# position: pelvis forward x (m) at mid double support; ratio: 0 at the stance leg's mid-stance, 1 at the landing leg's"
    )?;
    writeln!(
        out,
        "{:>5} {:>4} {:>8} {:>5} {:>5} {:>9} {:>6} {:>8} {:>12} {:>12} {:>8}  note",
        "step", "side", "phase", "evals", "feas", "x_m", "ratio", "y_m", "cost", "fixed_cost", "time_us"
    )?;
    for r in records {
        let note = if r.fallback {
            "no feasible candidate: kept the previous ratio"
        } else if r.method.is_none() {
            "optimiser off"
        } else if r.candidates.iter().any(|c| c.cost.zip(r.chosen.cost).is_some_and(|(c, chosen)| c < chosen)) {
            "fixed rule kept: the search's best is within 0.5 % of it"
        } else {
            ""
        };
        writeln!(
            out,
            "{:>5} {:>4} {:>8.4} {:>5} {:>5} {:>9.4} {:>6.3} {:>8.4} {:>12} {:>12} {:>8.1}  {note}",
            r.step,
            r.side.suffix(),
            r.phase,
            r.evaluations,
            r.feasible,
            r.chosen.x,
            r.chosen_ratio(),
            r.chosen.y,
            cost_text(r.chosen.cost),
            cost_text(r.fixed_rule.cost),
            r.elapsed_us,
        )?;
    }
    let t = totals(records);
    let gain = if t.fixed_rule > 0.0 { 100.0 * (t.chosen - t.fixed_rule) / t.fixed_rule } else { 0.0 };
    write!(
        out,
        "total {} steps: cost {:.4} chosen vs {:.4} fixed rule ({gain:+.1}%)",
        records.len(),
        t.chosen,
        t.fixed_rule
    )?;
    if t.fixed_rule_infeasible > 0 {
        write!(out, " (fixed rule unreachable on {} steps, left out of its sum)", t.fixed_rule_infeasible)?;
    }
    writeln!(
        out,
        "; {} steps without a feasible candidate; {} evaluations; median search {:.1} us",
        t.fallbacks, t.evaluations, t.median_us
    )
}

fn candidate_json(c: &Candidate) -> Value {
    json!({ "x_m": c.x, "y_m": c.y, "cost": c.cost })
}

fn write_json(out: &mut dyn Write, records: &[StepRecord]) -> io::Result<()> {
    for r in records {
        let line = json!({
            "step": r.step,
            "side": r.side.suffix(),
            "phase": r.phase,
            "method": r.method.map_or("off", |m| m.name()),
            "evaluations": r.evaluations,
            "feasible": r.feasible,
            "fallback": r.fallback,
            "chosen": candidate_json(&r.chosen),
            "chosen_ratio": r.chosen_ratio(),
            "fixed_rule": candidate_json(&r.fixed_rule),
            "window_x_m": [r.window_x.0, r.window_x.1],
            "elapsed_us": r.elapsed_us,
            "candidates": r.candidates.iter().map(candidate_json).collect::<Vec<_>>(),
        });
        writeln!(out, "{line}")?;
    }
    let t = totals(records);
    let summary = json!({
        "summary": {
            "steps": records.len(),
            "cost_chosen": t.chosen,
            "cost_fixed_rule": t.fixed_rule,
            "fixed_rule_unreachable_steps": t.fixed_rule_infeasible,
            "infeasible_steps": t.fallbacks,
            "evaluations": t.evaluations,
            "median_search_us": t.median_us,
        }
    });
    writeln!(out, "{summary}")
}
